#pragma once
// Reading a JSON input file (a gearhb_frc model file, a gearhb_gear gear-pair file)
// so that every error is one line naming the file and the key: the typed readers
// and the --set overrides both model files share. Every function throws
// UsageError("<file>: '<key>' <why>").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gearhb {

// A JSON input file (a model file, a gear file): a regular text file (no NUL byte) of
// at most 16 MiB with lines of at most 4096 characters (core/text_file.hpp), nested at
// most max_json_depth levels, no key twice in one object. Throws UsageError naming the
// path and what is wrong (a parse error by line and column, never quoting the file).
constexpr int max_json_depth = 32;
nlohmann::json read_json_file(const std::string& path);

[[noreturn]] void fail_key(const std::string& file, const std::string& key, const std::string& why);

// --set PATH=VALUE: replace the number at the dotted path (objects by key, lists by
// index: `contacts.0.kc`, `gears.1.tip_relief.amount`); only numbers the file has.
void apply_override(nlohmann::json& root, const std::string& file, const std::string& path, const std::string& text);

// A finite number, 0 or of magnitude in [1e-150, 1e150] (beyond it products of two
// entries leave double precision).
double json_number(const nlohmann::json& j, const std::string& file, const std::string& key);
// A whole number in [lo, hi].
int json_whole(const nlohmann::json& j, const std::string& file, const std::string& key, int lo, int hi);
// A name that figures put in their titles: a text of 1..max_name_chars characters
// without control characters (`fallback` where the key is absent).
constexpr int max_name_chars = 120;
std::string json_name(const nlohmann::json& root, const std::string& file, const std::string& key,
                      const std::string& fallback);
// An on/off flag: true / false, or 1 / 0.
bool json_flag(const nlohmann::json& j, const std::string& file, const std::string& key);
// An object whose keys are all in `allowed` (`where` is its dotted path, "" the root).
void only_keys(const nlohmann::json& j, const std::string& file, const std::string& where,
               const std::vector<std::string>& allowed);

}  // namespace gearhb
