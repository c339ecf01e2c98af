#include "gearhb/app/json_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "gearhb/app/cli.hpp"

namespace gearhb {

using nlohmann::json;

json load_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError(path + ": cannot be opened");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw UsageError(path + ": not valid JSON (" + std::string(e.what()) + ")");
  }
}

void fail_key(const std::string& file, const std::string& key, const std::string& why) {
  throw UsageError(file + ": '" + key + "' " + why);
}

void apply_override(json& root, const std::string& file, const std::string& path, const std::string& text) {
  json* node = &root;
  std::stringstream ss(path);
  std::string part;
  while (std::getline(ss, part, '.')) {
    if (node->is_object() && node->contains(part)) {
      node = &(*node)[part];
    } else if (node->is_array() && !part.empty() && part.find_first_not_of("0123456789") == std::string::npos &&
               part.size() < 9 && std::stoul(part) < node->size()) {
      node = &(*node)[std::stoul(part)];
    } else {
      fail_key(file, path, "is not in the model (--set overrides a number that the file has)");
    }
  }
  if (!node->is_number()) fail_key(file, path, "is not a number (--set overrides numbers only)");
  *node = parse_decimal(text, "--set " + path);
}

double json_number(const json& j, const std::string& file, const std::string& key) {
  if (!j.is_number()) fail_key(file, key, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail_key(file, key, "must be finite");
  return v;
}

int json_whole(const json& j, const std::string& file, const std::string& key, int lo, int hi) {
  const double v = json_number(j, file, key);
  if (v != std::floor(v) || v < lo || v > hi)
    fail_key(file, key, "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(v);
}

void only_keys(const json& j, const std::string& file, const std::string& where,
               const std::vector<std::string>& allowed) {
  if (!j.is_object()) fail_key(file, where, "must be an object");
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const auto& a : allowed) ok = ok || item.key() == a;
    if (!ok) fail_key(file, (where.empty() ? "" : where + ".") + item.key(), "is not a model key (see --help)");
  }
}

}  // namespace gearhb
