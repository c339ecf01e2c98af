#include "gearhb/gears/pair/ste_file.hpp"

#include "gearhb/core/text_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace gearhb {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& why) {
  throw SteFileError("STE file " + path + (line > 0 ? " line " + std::to_string(line) : std::string()) + ": " + why);
}

double number(const std::string& path, int line, const std::string& field, const char* column) {
  const std::string t = trim(field);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v))
    fail(path, line, std::string(column) + " '" + t + "' is not a finite number");
  return v;
}

}  // namespace

SteFile read_ste_file(const std::string& path, int min_rows, bool require_positive) {
  std::vector<std::string> text_lines;
  try {
    text_lines = read_text_lines(path);
  } catch (const TextFileError& e) {
    fail(path, 0, e.what());
  }
  SteFile f;
  std::vector<int> lines;
  bool header = false;
  for (int line = 1; line <= int(text_lines.size()); ++line) {
    const std::string& text = text_lines[std::size_t(line - 1)];
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream ss(t);
    for (std::string fld; std::getline(ss, fld, ',');) fields.push_back(fld);
    if (!header) {
      if (fields.size() != 2 || trim(fields[0]) != "phase" || trim(fields[1]) != "ste_um")
        fail(path, line, "is not an STE file: its first line must be the header 'phase,ste_um'");
      header = true;
      continue;
    }
    if (fields.size() != 2) fail(path, line, "expected 2 columns (phase,ste_um), got " + std::to_string(fields.size()));
    const double ph = number(path, line, fields[0], "phase"), um = number(path, line, fields[1], "ste_um");
    if (ph < 0.0 || ph >= 1.0) fail(path, line, "phase " + trim(fields[0]) + " is not in [0, 1)");
    if (require_positive && !(um > 0.0))
      fail(path, line, "ste_um " + trim(fields[1]) + " must be > 0 (the mesh stiffness is F / STE)");
    f.phase.push_back(ph);
    f.ste.push_back(um * 1e-6);
    lines.push_back(line);
  }
  if (!header) fail(path, 0, "is empty (header 'phase,ste_um' expected)");
  const int n = int(f.phase.size());
  if (n < min_rows)
    fail(path, 0, std::to_string(n) + " rows, at least " + std::to_string(min_rows) + " needed (2H+1)");
  for (int j = 0; j < n; ++j)
    if (std::fabs(f.phase[j] - double(j) / n) > 1e-6) {
      std::ostringstream os;
      os << "phase " << f.phase[j] << " is not uniform: expected " << double(j) / n << " (row " << j + 1
         << " of " << n << ")";
      fail(path, lines[j], os.str());
    }
  return f;
}

}  // namespace gearhb
