#pragma once
// Parameters of a program's command line (README "Running a chapter"):
//
//   --set key=value   (repeatable)
//
// Each chapter keeps its parameters in plain structs (one per concern) whose
// member initialisers are the thesis defaults. It binds every member to a name
// in a ParameterSet, which then prints --help, applies --set overrides, checks
// ranges, and echoes the values used into the output folder.
//
// Bad input (unknown key, malformed number, value out of its physical range)
// raises UsageError; the Study (study.hpp) prints its one line and exits with 2
// before anything is written.
#include <functional>
#include <map>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gearhb {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Admissible range of a parameter.
struct Range {
  enum class Kind { any, positive, nonnegative, between } kind = Kind::any;
  double lo = 0.0, hi = 0.0;
  static Range any() { return {}; }
  static Range positive() { return {Kind::positive}; }
  static Range nonnegative() { return {Kind::nonnegative}; }
  static Range between(double a, double b) { return {Kind::between, a, b}; }
  // A mass [kg] or polar inertia [kg m^2]: 1e-9 ... 1e9 holds every machine part and
  // keeps a model's natural frequencies inside double precision (a denormal mass
  // would make them inf).
  static Range mass() { return between(1e-9, 1e9); }
  // Empty string when v is admissible, otherwise what is wrong ("must be > 0").
  std::string violation(double v) const;
};

class ParameterSet {
 public:
  // Bind a double (or an int: whole numbers only) to a command-line name.
  void add(const std::string& name, double* value, const std::string& unit,
           const std::string& help, Range range = Range::any());
  void add(const std::string& name, int* value, const std::string& unit,
           const std::string& help, Range range = Range::any());
  // Bind an on/off flag: --set name=1 | 0 | true | false (echoed as true / false).
  void add(const std::string& name, bool* value, const std::string& unit, const std::string& help);
  // Bind a string (e.g. a file path): any text is accepted by --set, empty
  // included; checking it (does the file exist, is it valid) is the chapter's
  // cross-parameter check.
  void add(const std::string& name, std::string* value, const std::string& unit, const std::string& help);

  // A parameter's former name (README glossary: one name per quantity): --set of it is
  // refused with "'old' was renamed to 'new'".
  void renamed(const std::string& old_name, const std::string& new_name);

  // Parameters added after this call are listed under `title` in --help. An
  // own-case group holds the parameters of the user's own case (--case own):
  // setting one of them for another selection is a usage error.
  void group(const std::string& title, bool own_case = false);
  // The overridden parameters that belong to an own-case group.
  std::vector<std::string> overridden_own_case() const;

  // Apply one "key=value" override. Throws UsageError naming the key. The value
  // must be a decimal floating-point number (no hex, no blanks, no inf/nan).
  void set(const std::string& assignment);
  // Check every parameter against its range. Throws UsageError naming the first bad one.
  void validate() const;
  // Cross-parameter condition: throws UsageError(message) unless ok.
  static void require(bool ok, const std::string& message);

  // Keys that name no registered parameter are kept (key, value text) instead of
  // refused, for a program whose parameters come from a file (gearhb_frc).
  void keep_unregistered() { keep_unregistered_ = true; }
  const std::vector<std::pair<std::string, std::string>>& unregistered() const { return unregistered_; }

  bool was_set(const std::string& name) const;
  std::string help_text() const;     // one line per parameter: name, default, unit, meaning
  nlohmann::json to_json() const;    // {"name": {"value": v, "unit": u}}

 private:
  struct Entry {
    std::string name, unit, help;
    double* d = nullptr;
    int* i = nullptr;
    std::string* s = nullptr;
    double default_value = 0.0;
    std::string default_text;
    Range range;
    std::string group;
    bool own_case = false;
    bool* b = nullptr;   // a flag (set after the aggregate initialisation)
  };
  const Entry* find(const std::string& name) const;
  std::vector<Entry> entries_;
  std::vector<std::string> overridden_;
  std::string group_;
  bool group_own_ = false;
  bool keep_unregistered_ = false;
  std::vector<std::pair<std::string, std::string>> unregistered_;
  std::vector<std::pair<std::string, std::string>> renamed_;   // (old, new)
};

// Parse a decimal floating-point number (digits, one optional point, optional
// exponent; denormals accepted). Throws UsageError naming `what` otherwise.
double parse_decimal(const std::string& text, const std::string& what);

}  // namespace gearhb
