#include "gearhb/app/cli.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace gearhb {

std::string Range::violation(double v) const {
  std::ostringstream os;
  os << std::setprecision(12);
  if (!std::isfinite(v)) return "must be a finite number";
  switch (kind) {
    case Kind::any: return "";
    case Kind::positive:
      if (v <= 0.0) return "must be > 0";
      return "";
    case Kind::nonnegative:
      if (v < 0.0) return "must be >= 0";
      return "";
    case Kind::between:
      if (v < lo || v > hi) { os << "must be in [" << lo << ", " << hi << "]"; return os.str(); }
      return "";
  }
  return "";
}

void ParameterSet::group(const std::string& title, bool own_case) {
  group_ = title;
  group_own_ = own_case;
}

void ParameterSet::add(const std::string& name, double* value, const std::string& unit,
                       const std::string& help, Range range) {
  entries_.push_back({name, unit, help, value, nullptr, nullptr, *value, "", range, group_, group_own_});
}

void ParameterSet::add(const std::string& name, int* value, const std::string& unit,
                       const std::string& help, Range range) {
  entries_.push_back({name, unit, help, nullptr, value, nullptr, double(*value), "", range, group_, group_own_});
}

void ParameterSet::add(const std::string& name, bool* value, const std::string& unit, const std::string& help) {
  Entry e{name, unit, help, nullptr, nullptr, nullptr, *value ? 1.0 : 0.0, "", Range::between(0, 1), group_, group_own_};
  e.b = value;
  entries_.push_back(e);
}

void ParameterSet::add(const std::string& name, std::string* value, const std::string& unit,
                       const std::string& help) {
  Entry e{name, unit, help, nullptr, nullptr, value, 0.0, *value, Range::any(), group_, group_own_};
  entries_.push_back(e);
}

std::vector<std::string> ParameterSet::overridden_own_case() const {
  std::vector<std::string> out;
  for (const auto& k : overridden_)
    if (const Entry* e = find(k); e && e->own_case) out.push_back(k);
  return out;
}

double parse_decimal(const std::string& text, const std::string& what) {
  // Decimal syntax only: [+-] digits [. digits] [(e|E) [+-] digits], at least one digit.
  std::size_t i = 0, n = text.size(), digits = 0;
  if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
  while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) { ++i; ++digits; }
  if (i < n && text[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) { ++i; ++digits; }
  }
  bool ok = digits > 0;
  if (ok && i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exp_digits = 0;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) { ++i; ++exp_digits; }
    ok = exp_digits > 0;
  }
  if (!ok || i != n) throw UsageError(what + ": '" + text + "' is not a decimal number");
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  // ERANGE with a finite result is underflow (denormal or zero): a valid value.
  if (!std::isfinite(v)) throw UsageError(what + ": '" + text + "' is out of the range of a double");
  return v;
}

const ParameterSet::Entry* ParameterSet::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

void ParameterSet::renamed(const std::string& old_name, const std::string& new_name) {
  renamed_.emplace_back(old_name, new_name);
}

void ParameterSet::set(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UsageError("--set expects key=value, got '" + assignment + "'");
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const Entry* e = find(key);
  for (const auto& [old_name, new_name] : renamed_)
    if (!e && key == old_name) throw UsageError("parameter '" + key + "' was renamed to '" + new_name + "'");
  if (!e && keep_unregistered_) {
    unregistered_.emplace_back(key, text);
    return;
  }
  if (!e) throw UsageError("unknown parameter '" + key + "' (see --help)");
  if (e->s) {
    *e->s = text;
    overridden_.push_back(key);
    return;
  }
  if (e->b) {   // true | false, or a number equal to 1 or 0 (a study writes 0.0)
    const bool word = text == "true" || text == "false";
    const double v = word ? (text == "true" ? 1.0 : 0.0) : parse_decimal(text, "parameter '" + key + "'");
    if (v != 0.0 && v != 1.0)
      throw UsageError("parameter '" + key + "': '" + text + "' is not a flag (1, 0, true or false)");
    *e->b = v == 1.0;
    overridden_.push_back(key);
    return;
  }
  const double v = parse_decimal(text, "parameter '" + key + "'");
  if (e->i) {
    if (v != std::floor(v)) throw UsageError("parameter '" + key + "': '" + text + "' is not a whole number");
    if (std::fabs(v) > 2e9) throw UsageError("parameter '" + key + "': '" + text + "' is too large");
    *e->i = int(v);
  } else {
    *e->d = v;
  }
  overridden_.push_back(key);
}

void ParameterSet::validate() const {
  for (const auto& e : entries_) {
    if (e.s || e.b) continue;   // strings are checked by the chapter; a flag is 0 or 1 by construction
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
  // Column widths from the longest entry, so long names never collide.
  std::size_t wn = 4, wd = 7, wu = 4;
  std::vector<std::string> defaults;
  for (const auto& e : entries_) {
    std::ostringstream def;
    if (e.s) def << (e.default_text.empty() ? "\"\"" : e.default_text);
    else def << e.default_value;
    defaults.push_back(def.str());
    wn = std::max(wn, e.name.size());
    wd = std::max(wd, defaults.back().size());
    wu = std::max(wu, e.unit.size());
  }
  std::ostringstream os;
  os << "Parameters (--set key=value):\n";
  os << "  " << std::left << std::setw(int(wn) + 2) << "name" << std::setw(int(wd) + 2) << "default"
     << std::setw(int(wu) + 2) << "unit" << "meaning\n";
  std::string current = "\x01";
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const auto& e = entries_[i];
    if (e.group != current) {
      current = e.group;
      if (!current.empty()) os << " " << current << ":\n";
    }
    os << "  " << std::left << std::setw(int(wn) + 2) << e.name << std::setw(int(wd) + 2) << defaults[i]
       << std::setw(int(wu) + 2) << (e.unit.empty() ? "-" : e.unit) << e.help;
    if (e.b) {
      os << " (flag: 1 or 0)";
    } else if (e.range.kind != Range::Kind::any) {
      std::ostringstream r;
      r << std::setprecision(12);
      switch (e.range.kind) {
        case Range::Kind::positive: r << " (> 0)"; break;
        case Range::Kind::nonnegative: r << " (>= 0)"; break;
        case Range::Kind::between: r << " (" << e.range.lo << " to " << e.range.hi << ")"; break;
        default: break;
      }
      os << r.str();
    }
    os << "\n";
  }
  return os.str();
}

nlohmann::json ParameterSet::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& e : entries_) {
    if (e.s) j[e.name] = {{"value", *e.s}, {"unit", e.unit}};
    else if (e.b) j[e.name] = {{"value", *e.b}, {"unit", e.unit}};
    else if (e.d) j[e.name] = {{"value", *e.d}, {"unit", e.unit}};
    else j[e.name] = {{"value", *e.i}, {"unit", e.unit}};
  }
  return j;
}

}  // namespace gearhb
