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

// The same with the shared solver settings.
inline FrequencyCurve timed_sweep(Run& run, const HarmonicBalance& hb, const SolverSettings& s,
                                  const std::string& label) {
  return timed_sweep(run, hb, sweep_options(s), label);
}

}  // namespace gearhb
