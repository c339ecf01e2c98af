#pragma once
// Helpers for a chapter's case table (README "Running a chapter"): the cases are a
// const table of structs, each with at least
//   std::string label;               // --case LABEL, file stems
//   bool quick;                      // part of the regression subset (--case quick)
//   std::vector<Measure> measures;   // what the case measures besides its curve
// and the chapter's steps ask the table, never compare labels or parameters.
#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"

namespace gearhb {

// Register the table's labels, and which of them form the quick subset, with the study.
template <class Case>
void register_cases(Study& study, const std::vector<Case>& table) {
  std::vector<std::string> labels, quick;
  for (const auto& c : table) {
    labels.push_back(c.label);
    if (c.quick) quick.push_back(c.label);
  }
  study.cases(labels, quick);
}

// Whether the case measures m (m is in its list `measures`).
template <class Case, class Measure>
bool measures(const Case& c, Measure m) {
  return std::find(c.measures.begin(), c.measures.end(), m) != c.measures.end();
}

// A sweep's progress on stderr (Run::progress): its continuation as `label`, the steps after
// it as "<label>: stability", "<label>: bifurcations", "<label>: narrow bands".
inline void report_sweep_progress(Run& run, SweepOptions& o, const std::string& label) {
  o.continuation.progress = run.progress_of(label);
  o.step_progress = [&run, label](const std::string& step, const ContinuationProgress& p) {
    run.progress(label + ": " + step, p.point, p.omega, p.ds);
  };
}

// The progress of a curve's tables on stderr (Run::progress) as "<label>: tables".
inline RowProgress table_progress(Run& run, const FrequencyCurve& c, const std::string& label) {
  return [&run, &c, label](std::size_t i) {
    run.progress(label + ": tables", long(i), c.branch.points[i].omega, c.branch.points[i].ds);
  };
}

// One frequency sweep, its wall time recorded in timings.csv as "sweep <label>",
// its progress on stderr and its summary said on stdout. Throws if incomplete.
inline FrequencyCurve timed_sweep(Run& run, const HarmonicBalance& hb, SweepOptions o, const std::string& label) {
  report_sweep_progress(run, o, label);
  FrequencyCurve c = run.timed("sweep " + label, [&] { return require_complete(sweep_frequency(hb, o, label), label); });
  run.say(label + ": " + c.branch.summary());
  return c;
}

// Key numbers of frequency ranges: <what>_ranges<suffix> and, for each range k,
// <what>_from_<unit><suffix>_k, <what>_to_<unit><suffix>_k, each end speed(omega) [unit_name]
// (default: omega itself, rad/s).
inline void add_range_key_numbers(KeyNumbers& key, const std::string& what, const Intervals& ranges,
                                  const std::string& suffix, const std::string& unit = "omega",
                                  const std::function<double(double)>& speed = {},
                                  const std::string& unit_name = "rad/s") {
  key.add(what + "_ranges" + suffix, double(ranges.size()), "-");
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const std::string tag = suffix + "_" + std::to_string(k + 1);
    key.add(what + "_from_" + unit + tag, speed ? speed(ranges[k].first) : ranges[k].first, unit_name);
    key.add(what + "_to_" + unit + tag, speed ? speed(ranges[k].second) : ranges[k].second, unit_name);
  }
}
// The period-1 ranges (period1_ranges: of one curve, or of several period-1 branches together):
// unstable_period1_ranges<suffix> and each range's unstable_period1_from_omega<suffix>_k,
// unstable_period1_to_omega<suffix>_k, where no period-1 orbit is stable with a resolved label;
// unresolved_period1_ranges<suffix>, unresolved_period1_from_omega<suffix>_k,
// unresolved_period1_to_omega<suffix>_k, the parts of those ranges whose labels say stable but
// rest on no converged shooting correction (resolved_stable).
inline void add_unstable_period1_ranges(KeyNumbers& key, const Period1Ranges& r, const std::string& suffix) {
  add_range_key_numbers(key, "unstable_period1", r.no_stable, suffix);
  add_range_key_numbers(key, "unresolved_period1", r.unresolved, suffix);
}
// The same for the curve c on [omega_min, omega_max] (issue 34 §4; the figures shade them).
inline void add_unstable_period1_ranges(KeyNumbers& key, const FrequencyCurve& c, double omega_min, double omega_max,
                                        const std::string& suffix = "") {
  add_unstable_period1_ranges(key, period1_ranges(omega_min, omega_max, {&c}), suffix);
}

// The unresolved stretches of the period-doubled branches pd with points (unresolved_stable_stretches:
// the first to the last point of a run of stable points none of whose shooting corrections
// converged, in forcing omega), per period p of the branches, of all its branches together (merged):
// unresolved_period<p>_ranges<suffix>, unresolved_period<p>_from_omega<suffix>_k,
// unresolved_period<p>_to_omega<suffix>_k (0 ranges: every stable label of that period resolved).
inline void add_unresolved_branch_ranges(KeyNumbers& key, const std::vector<PeriodDoubledBranch>& pd,
                                         const std::string& suffix) {
  std::map<int, Intervals> of_period;
  for (const PeriodDoubledBranch& b : pd) {
    if (!has_points(b)) continue;
    const Intervals u = unresolved_stable_stretches(b.curve, b.period);
    Intervals& all = of_period[b.period];
    all.insert(all.end(), u.begin(), u.end());
  }
  for (const auto& [p, u] : of_period)   // merged where they overlap (a branch with folds passes an omega again)
    add_range_key_numbers(key, "unresolved_period" + std::to_string(p), merged(u), suffix);
}

// A frequency-response curve and the period-doubled branches switched at its period doublings.
struct SweptCurve {
  FrequencyCurve curve;
  std::vector<PeriodDoubledBranch> doubled;   // period_doubling_cascade (empty: depth 0 or no PD)
};

// timed_sweep (throws if incomplete), then, at depth >= 1 where the curve has a period doubling,
// its period-doubled branches over the same range (timings.csv "period-doubled branches
// <label>"), each saying in one line where it starts and how it ends (a switch that fails: at
// which PD and why; the rest of the run stands), with the key numbers of their unresolved
// stretches (add_unresolved_branch_ranges), and the key numbers of the ranges with no stable
// period-1 orbit and of their unresolved stretches (add_unstable_period1_ranges; suffix "_<label>").
inline SweptCurve timed_sweep_with_branches(Run& run, const HarmonicBalance& hb, SweepOptions o,
                                            const std::string& label, int depth) {
  SweptCurve s{timed_sweep(run, hb, o, label), {}};
  const auto& B = s.curve.bifurcations;
  if (depth >= 1 && std::any_of(B.begin(), B.end(), [](const Bifurcation& b) { return b.type == BifurcationType::period_doubling; })) {
    report_sweep_progress(run, o, label + ": period 2");
    s.doubled = run.timed("period-doubled branches " + label, [&] { return period_doubling_cascade(hb, s.curve, o, depth); });
    for (const auto& b : s.doubled) run.say(label + ": " + b.why);
    add_unresolved_branch_ranges(run.key_numbers(), s.doubled, "_" + label);
  }
  add_unstable_period1_ranges(run.key_numbers(), s.curve, o.omega_min, o.omega_max, "_" + label);
  return s;
}

// The same with the shared solver settings.
inline FrequencyCurve timed_sweep(Run& run, const HarmonicBalance& hb, const SolverSettings& s,
                                  const std::string& label) {
  return timed_sweep(run, hb, sweep_options(s), label);
}

}  // namespace gearhb
