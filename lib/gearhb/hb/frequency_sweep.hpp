#pragma once
// A frequency sweep as every chapter runs it (thesis ch. 3-6, 8-9): the
// continuation of one harmonic-balance model over [omega_min, omega_max],
// Hill stability of every point, the frequencies where the contact state
// changes, and the independent check against direct time integration.
//
//  - sweep_frequency: pseudo-arc-length continuation (or natural continuation
//    for teaching) from the better of the open- and closed-contact linear
//    solutions at omega_min. An incomplete arc-length branch is an error that
//    names the case, the frequency, the residual and the step (never a
//    silently truncated curve); a natural branch stops at its first fold, as
//    the method does, and the stop is reported.
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

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct SweepOptions {
  double omega_min = 0.0, omega_max = 1.0;   // [rad/s]; the sweep runs upward
  bool natural = false;                      // natural continuation (stops at a fold)
  ContinuationOptions continuation;          // omega_start / omega_end are overwritten
};

struct FrequencyCurve {
  Branch branch;
  std::vector<bool> stable;   // Hill, one flag per point
  Scaling scaling;            // the scaling the branch was computed with
};

// Linear first guess at omega: the open- or closed-contact solution, whichever
// has the smaller residual.
Eigen::VectorXd linear_first_guess(const HarmonicBalance& hb, double omega);

// Continue `hb` over the range; `label` names the case in error messages.
FrequencyCurve sweep_frequency(const HarmonicBalance& hb, const SweepOptions& opt,
                               const std::string& label);

// Contact predicates (on the penetration of every contact over a period).
std::function<bool(const Eigen::VectorXd&)> touches_somewhere(const HarmonicBalance& hb);
std::function<bool(const Eigen::VectorXd&)> opens_somewhere(const HarmonicBalance& hb);

// First omega along the branch where `state` switches from false to true; NaN if never.
double first_transition(const HarmonicBalance& hb, const FrequencyCurve& c,
                        const std::function<bool(const Eigen::VectorXd&)>& state);

struct TimeIntegrationCheckOptions {
  int points = 8;                                  // at most this many comparisons
  ContactState state = ContactState::intermittent; // compare points in this state only
  double fold_margin = 2e-3;                       // skip points within fold_margin*omega of a fold
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
