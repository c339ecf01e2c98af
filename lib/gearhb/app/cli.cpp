#include "gearhb/app/cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace gearhb {

std::string Range::violation(double v) const {
  std::ostringstream os;
  if (!std::isfinite(v)) return "must be a finite number";
  switch (kind) {
    case Kind::any: return "";
    case Kind::positive:
      if (v <= 0.0) return "must be > 0";
      return "";
    case Kind::nonnegative:
      if (v < 0.0) return "must be >= 0";
      return "";
    case Kind::at_least:
      if (v < lo) { os << "must be >= " << lo; return os.str(); }
      return "";
    case Kind::between:
      if (v < lo || v > hi) { os << "must be in [" << lo << ", " << hi << "]"; return os.str(); }
      return "";
  }
  return "";
}

void ParameterSet::add(const std::string& name, double* value, const std::string& unit,
                       const std::string& help, Range range) {
  entries_.push_back({name, unit, help, value, nullptr, *value, range});
}

void ParameterSet::add(const std::string& name, int* value, const std::string& unit,
                       const std::string& help, Range range) {
  entries_.push_back({name, unit, help, nullptr, value, double(*value), range});
}

const ParameterSet::Entry* ParameterSet::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

void ParameterSet::set(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UsageError("--set expects key=value, got '" + assignment + "'");
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const Entry* e = find(key);
  if (!e) throw UsageError("unknown parameter '" + key + "' (see --help)");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw UsageError("parameter '" + key + "': '" + text + "' is not a number");
  if (e->i) {
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      throw UsageError("parameter '" + key + "': '" + text + "' is not a whole number");
    *e->i = int(v);
  } else {
    *e->d = v;
  }
  overridden_.push_back(key);
}

void ParameterSet::validate() const {
  for (const auto& e : entries_) {
    const double v = e.d ? *e.d : double(*e.i);
    const std::string why = e.range.violation(v);
    if (!why.empty()) {
      std::ostringstream os;
      os << "parameter '" << e.name << "' = " << v << " " << why;
      throw UsageError(os.str());
    }
  }
}

void ParameterSet::require(bool ok, const std::string& message) {
  if (!ok) throw UsageError(message);
}

bool ParameterSet::was_set(const std::string& name) const {
  for (const auto& k : overridden_)
    if (k == name) return true;
  return false;
}

std::string ParameterSet::help_text() const {
  std::ostringstream os;
  os << "Parameters (--set key=value):\n";
  for (const auto& e : entries_) {
    std::ostringstream def;
    def << e.default_value;
    os << "  " << std::left << std::setw(14) << e.name << std::setw(12) << def.str()
       << std::setw(10) << (e.unit.empty() ? "-" : e.unit) << e.help << "\n";
  }
  return os.str();
}

nlohmann::json ParameterSet::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& e : entries_) {
    if (e.d) j[e.name] = {{"value", *e.d}, {"unit", e.unit}};
    else j[e.name] = {{"value", *e.i}, {"unit", e.unit}};
  }
  return j;
}

CommandLine parse_command_line(int argc, char** argv, ParameterSet& params,
                               const std::string& default_out_dir) {
  CommandLine cl;
  cl.out_dir = default_out_dir;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    auto next = [&](const char* what) -> std::string {
      if (a + 1 >= argc) throw UsageError(arg + " expects " + what);
      return argv[++a];
    };
    if (arg == "--help" || arg == "-h") cl.help = true;
    else if (arg == "--out") cl.out_dir = next("a directory");
    else if (arg == "--set") params.set(next("key=value"));
    else if (arg.rfind("--set=", 0) == 0) params.set(arg.substr(6));
    else if (arg.rfind("--out=", 0) == 0) cl.out_dir = arg.substr(6);
    else throw UsageError("unknown argument '" + arg + "' (see --help)");
  }
  if (cl.out_dir.empty()) throw UsageError("--out needs a non-empty directory");
  params.validate();
  return cl;
}

int run_chapter(const std::string& program, const std::string& usage, int argc, char** argv,
                ParameterSet& params, const std::string& default_out_dir,
                const std::function<void(const CommandLine&)>& body) {
  CommandLine cl;
  try {
    cl = parse_command_line(argc, argv, params, default_out_dir);
  } catch (const UsageError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 2;
  }
  if (cl.help) {
    std::cout << usage << "\n"
              << "Options:\n  --out DIR        output folder (default " << default_out_dir << ")\n"
              << "  --set key=value  override one parameter (repeatable)\n"
              << "  --help           this text\n\n"
              << params.help_text();
    return 0;
  }
  try {
    body(cl);
  } catch (const UsageError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace gearhb
