#include "gearhb/app/json_file.hpp"

#include <cmath>
#include <sstream>

#include "gearhb/app/cli.hpp"
#include "gearhb/core/text_file.hpp"

namespace gearhb {

using nlohmann::json;

namespace {

// nlohmann's parse error without its "; last read: '...'" tail, which quotes the file's
// text: the error names the line and column, never the content of a file that may not
// be a model at all (a password file given by mistake).
std::string parse_error_without_text(std::string what) {
  if (const auto tail = what.find("; last read:"); tail != std::string::npos) what.erase(tail);
  if (const auto id = what.find("] "); what.rfind("[json.exception.", 0) == 0 && id != std::string::npos)
    what.erase(0, id + 2);
  return what;
}

}  // namespace

json read_json_file(const std::string& path) {
  std::string text;
  try {
    text = read_text_file(path);
    check_line_lengths(text);
  } catch (const TextFileError& e) {
    throw UsageError(path + ": " + e.what());
  }
  // Refuse deep nesting while parsing (the parser itself is iterative, but copying or
  // destroying a deeply nested value recurses) and duplicate keys (the last would win).
  std::vector<std::vector<std::string>> keys;   // the keys of each open object
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    if ((event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) &&
        depth >= max_json_depth)
      throw UsageError(path + ": nested deeper than " + std::to_string(max_json_depth) + " levels");
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.empty()) {
      const std::string k = parsed.get<std::string>();
      for (const auto& seen : keys.back())
        if (seen == k) throw UsageError(path + ": key '" + k + "' appears twice in one object");
      keys.back().push_back(k);
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::exception& e) {
    throw UsageError(path + ": not valid JSON (" + parse_error_without_text(e.what()) + ")");
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
  // Every quantity of a model in any consistent units lies far inside this; beyond
  // it products of two entries leave double precision and the solver sees inf or 0.
  if (v != 0.0 && (std::fabs(v) < 1e-150 || std::fabs(v) > 1e150))
    fail_key(file, key, "must be 0 or of magnitude between 1e-150 and 1e150");
  return v;
}

int json_whole(const json& j, const std::string& file, const std::string& key, int lo, int hi) {
  const double v = json_number(j, file, key);
  if (v != std::floor(v) || v < lo || v > hi)
    fail_key(file, key, "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(v);
}

std::string json_name(const json& root, const std::string& file, const std::string& key,
                      const std::string& fallback) {
  if (!root.contains(key)) return fallback;
  const json& j = root[key];
  if (!j.is_string()) fail_key(file, key, "must be a text in quotes");
  const std::string name = j.get<std::string>();
  int chars = 0;   // UTF-8 code points (the parser has checked the encoding)
  bool control = false;
  for (const unsigned char c : name) {
    chars += (c & 0xc0) != 0x80;
    control = control || c < 0x20 || c == 0x7f;
  }
  if (chars < 1 || chars > max_name_chars || control)
    fail_key(file, key, "must be 1 to " + std::to_string(max_name_chars) +
                            " characters without control characters (it titles the figures)");
  return name;
}

bool json_flag(const json& j, const std::string& file, const std::string& key) {
  if (j.is_boolean()) return j.get<bool>();
  if (!j.is_number() || !(j.get<double>() == 0.0 || j.get<double>() == 1.0))
    fail_key(file, key, "must be a flag: true, false, 1 or 0");
  return j.get<double>() == 1.0;
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
