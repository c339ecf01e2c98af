#pragma once
// Helpers for a chapter's case table (README "Running a chapter"): the cases are a
// const table of structs, each with at least
//   std::string label;               // --case LABEL, file stems
//   bool quick;                      // part of the regression subset (--case quick)
//   std::vector<Measure> measures;   // what the case measures besides its curve
// and the chapter's steps ask the table, never compare labels or parameters.
#include <algorithm>
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

// Ranges with no stable period-1 orbit (`gaps`, e.g. of the stable intervals of several period-1
// branches together): key numbers unstable_period1_ranges<suffix> and, for each range k,
// unstable_period1_from_omega<suffix>_k, unstable_period1_to_omega<suffix>_k.
inline void add_unstable_period1_ranges(KeyNumbers& key, const Intervals& gaps, const std::string& suffix) {
  key.add("unstable_period1_ranges" + suffix, double(gaps.size()), "-");
  for (std::size_t k = 0; k < gaps.size(); ++k) {
    key.add("unstable_period1_from_omega" + suffix + "_" + std::to_string(k + 1), gaps[k].first, "rad/s");
    key.add("unstable_period1_to_omega" + suffix + "_" + std::to_string(k + 1), gaps[k].second, "rad/s");
  }
}
// The ranges of [omega_min, omega_max] with no stable period-1 orbit on c (issue 34 §4; the
// figures shade them), as above.
inline void add_unstable_period1_ranges(KeyNumbers& key, const FrequencyCurve& c, double omega_min, double omega_max,
                                        const std::string& suffix = "") {
  add_unstable_period1_ranges(key, uncovered(omega_min, omega_max, stable_intervals(c)), suffix);
}

// A frequency-response curve and the period-doubled branches switched at its period doublings.
struct SweptCurve {
  FrequencyCurve curve;
  std::vector<PeriodDoubledBranch> doubled;   // period_doubling_cascade (empty: depth 0 or no PD)
};

// timed_sweep (throws if incomplete), then, at depth >= 1 where the curve has a period doubling,
// its period-doubled branches over the same range (timings.csv "period-doubled branches
// <label>"), each saying in one line where it starts and how it ends (a switch that fails: at
// which PD and why; the rest of the run stands), and the key numbers of the ranges with no
// stable period-1 orbit (suffix "_<label>").
inline SweptCurve timed_sweep_with_branches(Run& run, const HarmonicBalance& hb, SweepOptions o,
                                            const std::string& label, int depth) {
  SweptCurve s{timed_sweep(run, hb, o, label), {}};
  const auto& B = s.curve.bifurcations;
  if (depth >= 1 && std::any_of(B.begin(), B.end(), [](const Bifurcation& b) { return b.type == BifurcationType::period_doubling; })) {
    report_sweep_progress(run, o, label + ": period 2");
    s.doubled = run.timed("period-doubled branches " + label, [&] { return period_doubling_cascade(hb, s.curve, o, depth); });
    for (const auto& b : s.doubled) run.say(label + ": " + b.why);
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
