#pragma once
// Reading a JSON input file (a gearhb_frc model file, a gearhb_gear gear-pair file)
// so that every error is one line naming the file and the key: the typed readers
// and the --set overrides both model files share. Every function throws
// UsageError("<file>: '<key>' <why>").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gearhb {

// Parse the file; "cannot be opened" / "not valid JSON" as a UsageError.
nlohmann::json load_json_file(const std::string& path);

[[noreturn]] void fail_key(const std::string& file, const std::string& key, const std::string& why);

// --set PATH=VALUE: replace the number at the dotted path (objects by key, lists by
// index: `contacts.0.kc`, `gears.1.tip_relief.amount`); only numbers the file has.
void apply_override(nlohmann::json& root, const std::string& file, const std::string& path, const std::string& text);

// A finite number.
double json_number(const nlohmann::json& j, const std::string& file, const std::string& key);
// A whole number in [lo, hi].
int json_whole(const nlohmann::json& j, const std::string& file, const std::string& key, int lo, int hi);
// An object whose keys are all in `allowed` (`where` is its dotted path, "" the root).
void only_keys(const nlohmann::json& j, const std::string& file, const std::string& where,
               const std::vector<std::string>& allowed);

}  // namespace gearhb
