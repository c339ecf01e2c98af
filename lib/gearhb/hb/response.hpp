#pragma once
// What a frequency-response curve shows of one periodic solution (README "Output files"):
// for a coordinate q' x (a DOF, or a relative displacement such as x1 - x2),
//   x_max, x_min  over one period (extreme samples of the Fourier series on a fine
//                 grid, refined by Brent between neighbours: contact.hpp trig_extremes),
//   x_rms_ac      RMS of the oscillating part, sqrt(sum_k (a_k^2 + b_k^2) / 2),
//   x_h1          amplitude of the first harmonic, sqrt(a_1^2 + b_1^2),
// and the contact state over the period (open / full / intermittent), judged on
// the refined extremes of every contact penetration.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct ResponseSummary {
  double x_max = 0, x_min = 0, x_rms_ac = 0, x_h1 = 0, x_mean = 0;
  // The summary over all contacts: open (none ever touches), full (every contact closed
  // all period), intermittent otherwise. With two flanks (a clearance on both sides) a
  // state that stays on one flank all period reads intermittent: contact_states says
  // which flank does what.
  ContactState contact = ContactState::open;
  std::vector<ContactState> contact_states;   // per contact (hb.contacts() order)
  // Distance from grazing: over the contacts, the smallest |max u| or |min u| of the
  // penetration u = g + n'x over its half peak-to-peak (0 at a grazing orbit, where
  // the contact state changes; infinite without contacts or oscillation).
  double grazing_distance = INFINITY;
};

class ResponseEvaluator {
 public:
  // q: the plotted coordinate; `fine` samples per period for max/min and contact state
  // (raised to 2H + 2 if smaller: the grid must carry the H harmonics).
  ResponseEvaluator(const HarmonicBalance& hb, Eigen::VectorXd q, int fine = 1024);
  ResponseSummary summarize(const Eigen::VectorXd& X) const;
  // Time history of the coordinate over one period at `fine` samples (theta_j = 2 pi j / fine).
  Eigen::VectorXd history(const Eigen::VectorXd& X) const;
  // The force max(k(theta) u(theta), 0) of contact `i` on the same samples, with the
  // contact's own law: penetration u = g(theta) + n'x(theta) and stiffness k(theta)
  // (constant kc, or kc s(theta) for a time-varying stiffness).
  Eigen::VectorXd contact_force_history(const Eigen::VectorXd& X, std::size_t i) const;

 private:
  const HarmonicBalance& hb_;
  Eigen::VectorXd q_;
  Aft fine_;
};

// Mean over the period of contact i's force max(k(theta) u(theta), 0): over the exact contact
// intervals of u (contact.hpp contact_intervals), in closed form for a constant kc, by
// Gauss-Legendre quadrature between the exact crossings for a stiffness profile
// (weighted_indicator_moments).
double mean_contact_force(const HarmonicBalance& hb, const Eigen::VectorXd& X, std::size_t i);

// The contact states met along a branch, in continuation order, for the
// coordinate q' x (a chapter's contact summary of one curve).
struct ContactHistory {
  int transitions = 0;                         // changes of state between consecutive points
  ContactState start = ContactState::open;     // state at the first point
  ContactState end = ContactState::open;       // state at the last point
  double changed_lo = NAN, changed_hi = NAN;   // omega span of the points not in the start state
  double x_max = NAN, x_min = NAN;             // extremes of q' x over the whole branch
  long points[3] = {0, 0, 0};                  // points per state, indexed by ContactState (open, full, intermittent)
};
ContactHistory contact_history(const HarmonicBalance& hb, const Branch& b, const Eigen::VectorXd& q);

// Stability flag (Hill) of every point of a branch.
std::vector<bool> branch_stability(const HarmonicBalance& hb, const Branch& b);

}  // namespace gearhb
