#pragma once
// A frequency sweep as every chapter runs it (thesis ch. 3-6, 8-9): the
// continuation of one harmonic-balance model over [omega_min, omega_max],
// the stability of every point (Floquet multipliers of the corrected orbit by
// default, floquet.hpp; Hill's method as an option and a cross-check), the
// bifurcations along the branch, the frequencies where the contact state
// changes, and the independent check against direct time integration.
//
//  - sweep_frequency: pseudo-arc-length continuation (or natural continuation
//    for teaching), upward from omega_min or downward from omega_max, from the
//    better of the open- and closed-contact linear solutions there, or, where
//    Newton fails from both (K = 0 with clearances on both sides), from the point
//    find_first_point finds (first_point.hpp); a sweep that cannot start returns
//    no points, complete = false and the reason. It returns
//    the points it has: an incomplete branch has complete = false and a
//    `failure` that names the case, the frequency, the residual, the step and a
//    hint; callers that need the whole range call require_complete.
//  - bifurcations (Floquet stability): between consecutive points where the
//    number of multipliers outside the unit circle changes, the change is
//    located by bisection on the chord with the corrector and classified: a real
//    multiplier through +1 (fold; branch point if the tangent does not turn),
//    through -1 (period doubling), a complex pair (Neimark-Sacker).
//  - first_transition: the first frequency along the branch where a contact
//    predicate switches on, refined by bisection on the branch.
//  - compare_with_time_integration: x_max of a coordinate q' x from harmonic
//    balance against GSL rk8pd integrated to a periodic steady state, at up to
//    `points` stable points in the requested contact state, spread evenly over
//    the branch and away from folds (where the solution is slow to attract).
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <complex>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/first_point.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

enum class SweepDirection { up, down };
enum class StabilityMethod { floquet, hill, none };

// The contact regime of a solution X (two bits per contact: its ContactState over the
// period), the sweep's ContinuationOptions::regime: every contact counts, up to kMaxContacts.
std::function<std::uint64_t(const Eigen::VectorXd&)> contact_regime(const HarmonicBalance& hb);

enum class BandSearch { parametric, always, never };

struct SweepOptions {
  double omega_min = 0.0, omega_max = 1.0;   // [rad/s]
  SweepDirection direction = SweepDirection::up;   // up: from omega_min; down: from omega_max
  bool natural = false;                      // natural continuation (stops at a fold)
  StabilityMethod stability = StabilityMethod::floquet;
  bool hill_cross_check = false;             // also Hill at every point (FrequencyCurve::hill_stable)
  bool locate_bifurcations = true;           // Floquet only
  // A band of instability narrower than a step (a Mathieu tongue of a time-varying
  // stiffness crossed in one step) between two stable points: see add_narrow_bands in
  // frequency_sweep.cpp (criterion and cost). Its two crossings are listed in
  // FrequencyCurve::bifurcations (after_point the interval); the band has no point of its
  // own. parametric: searched only for a model with a time-varying contact stiffness (where
  // the tongues are; the search doubles the cost of a constant-stiffness gear sweep).
  BandSearch narrow_bands = BandSearch::parametric;   // Floquet and locate_bifurcations only
  FloquetOptions floquet;
  ContinuationOptions continuation;          // omega_start / omega_end are overwritten
  // Called before every Floquet computation of the steps after the continuation
  // (continuation.progress reports the continuation itself; e.g. to show progress, the
  // numerics never print), with the step's name and the point: "stability" (the point's
  // multipliers), "bifurcations" (a trial on the chord from the point before, at the trial's
  // omega, locating a crossing), "narrow bands" (the same, searching for a band).
  std::function<void(const std::string& step, const ContinuationProgress& point)> step_progress;
};

enum class BifurcationType { fold, branch_point, period_doubling, neimark_sacker };
const char* to_string(BifurcationType t);

struct Bifurcation {
  BifurcationType type = BifurcationType::fold;
  double omega = 0.0;
  std::complex<double> multiplier;   // the critical multiplier at the located point
  int after_point = 0;               // between points after_point and after_point + 1
  // Located on the chord between the two points; false if a corrector failed there (the
  // multiplier is then that of point after_point + 1 and omega is that point's).
  bool located = true;
  // The crossing multiplier is within 1e-2 of the unit circle at the located point. False:
  // the multipliers jump across the circle inside the located bracket (chord fraction
  // 1e-9), as they may where the corrected orbit grazes a contact or where the shooting
  // correction lands on a coexisting orbit next to a fold; the type is then that of the
  // kind whose count changed, not of a smooth crossing.
  bool smooth = true;
  // The located point's coefficients (the branch at `omega`: the trial point of the location,
  // or the fold's turning point); empty where a corrector failed on the chord. The branch switch at a period
  // doubling starts from it (period_doubling.hpp): re-deriving it from `omega` misses it where
  // the branch turns within the chord.
  Eigen::VectorXd X;
};

// Floquet data of one point (the stable flag is FrequencyCurve::stable).
struct PointFloquet {
  double modulus = 0.0, angle = 0.0;   // critical multiplier: |mu|, arg(mu)
  double orbit_error = 0.0;            // max |x_HB - x_exact| over the period (floquet.hpp)
  bool corrected = false;              // shooting correction converged
  bool shooting = false;               // one was tried (FloquetResult::shooting)
  Eigen::VectorXd x0, v0;              // the corrected state at phase 0 (FloquetResult::x0, v0; exact_orbit.hpp)
  bool lower_period = false;           // FloquetResult::lower_period
  int outside_real_positive = 0, outside_real_negative = 0, outside_complex = 0;
};

struct FrequencyCurve {
  Branch branch;
  std::vector<bool> stable;      // one flag per point (the `stability` method; all true for none)
  StabilityMethod stability = StabilityMethod::floquet;
  std::vector<PointFloquet> floquet;   // per point, Floquet method only
  std::vector<bool> hill_stable;       // per point, Hill method or hill_cross_check
  std::vector<Bifurcation> bifurcations;   // Floquet only, in continuation order
  Scaling scaling;               // the scaling the branch was computed with
  bool natural = false;
  // How the first point was found: linear_guess (Newton from the better of the open and
  // all-closed linear solutions, as always), or find_first_point's contact_set or
  // amplitude_continuation (first_point.hpp) where that failed.
  FirstPointMethod first_point = FirstPointMethod::linear_guess;
  bool complete = false;         // the branch reached the end of the range
  std::string failure;           // why not (omega, residual, step, hint); empty if complete
};

// Throws std::runtime_error("case <label>: <failure>") for an incomplete
// arc-length branch (a natural branch that stopped at a fold is returned as it is).
FrequencyCurve require_complete(FrequencyCurve c, const std::string& label);

// Continue `hb` over the range; `label` names the case in the failure report.
FrequencyCurve sweep_frequency(const HarmonicBalance& hb, const SweepOptions& opt,
                               const std::string& label);

// The steps of sweep_frequency after the continuation, on a traced branch (c.branch,
// c.scaling, c.natural set): the stability of every point by opt.stability and, for
// Floquet, the bifurcations located between the points (opt.locate_bifurcations).
void analyse_stability(const HarmonicBalance& hb, const SweepOptions& opt, FrequencyCurve& c);

// Contact predicates on the penetration over a period: of every contact together (contact
// = -1: the summary state, ResponseSummary::contact) or of contact `contact` alone (e.g. one
// flank of a gear mesh with backlash).
std::function<bool(const Eigen::VectorXd&)> touches_somewhere(const HarmonicBalance& hb, int contact = -1);
std::function<bool(const Eigen::VectorXd&)> opens_somewhere(const HarmonicBalance& hb, int contact = -1);

// First omega along the branch where `state` switches from false to true; NaN if never.
double first_transition(const HarmonicBalance& hb, const FrequencyCurve& c,
                        const std::function<bool(const Eigen::VectorXd&)>& state,
                        const TransitionOptions& opt = {});

struct TimeIntegrationCheckOptions {
  int points = 8;                                  // at most this many comparisons
  ContactState state = ContactState::intermittent; // compare points in this state only
  double fold_margin = 2e-3;                       // skip points within fold_margin*omega of a fold
  // Skip points whose largest Floquet multiplier (if computed) exceeds this modulus: a
  // perturbation decays like |mu|^periods, so |mu| = 0.999 needs ~20000 periods to settle
  // to 1e-9 (beside a period doubling or a Neimark-Sacker point).
  double max_multiplier = 0.99;
  // Skip points closer to grazing than this (ResponseSummary::grazing_distance): with a
  // contact interval that barely opens, the integrator's error at the switches (where
  // the force has a kink) stalls the periodicity test above its tolerance.
  double min_grazing_distance = 1e-3;
  // Skip points whose crest x_max is below this fraction of the half peak-to-peak
  // (a crest grazing 0 makes a relative error of x_max meaningless).
  double min_crest_fraction = 0.0;
  // Further filter on the branch point index, applied last (e.g. an independent
  // stability test that is too costly to run on every point); empty = accept all.
  std::function<bool(std::size_t)> accept;
  double omega_factor = 1.0;   // omega written to the table = omega x this (scaled-time models)
};

// One compared point: x_max by harmonic balance and by time integration.
struct TimeIntegrationComparison {
  double omega = 0.0;            // [rad/s] (x omega_factor)
  double x_max_hb = 0.0, x_max_time_integration = 0.0, rel_diff = 0.0;
  int periods = 0;               // forcing periods integrated to the periodic state
  ContactState contact = ContactState::open;
};

struct TimeIntegrationCheck {
  std::vector<TimeIntegrationComparison> rows;
  double worst_rel_diff = 0.0;   // max |x_max_hb - x_max_ti| / |x_max_ti|
  int points = 0;
};

// Throws if the time integration does not reach a periodic state.
TimeIntegrationCheck compare_with_time_integration(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                   const Eigen::VectorXd& q,
                                                   const TimeIntegrationCheckOptions& opt = {});

}  // namespace gearhb
