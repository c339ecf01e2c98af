#pragma once
// What a frequency-response curve shows of one periodic solution (SPEC §2):
// for a coordinate q' x (a DOF, or a relative displacement such as x1 - x2),
//   x_max, x_min  over one period (extreme samples of the Fourier series on a fine
//                 grid, refined by Brent between neighbours: contact.hpp trig_extremes),
//   x_rms_ac      RMS of the oscillating part, sqrt(sum_k (a_k^2 + b_k^2) / 2),
//   x_h1          amplitude of the first harmonic, sqrt(a_1^2 + b_1^2),
// and the contact state over the period (open / full / intermittent), judged on
// the refined extremes of every contact penetration.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct ResponseSummary {
  double x_max = 0, x_min = 0, x_rms_ac = 0, x_h1 = 0, x_mean = 0;
  ContactState contact = ContactState::open;
};

class ResponseEvaluator {
 public:
  // q: the plotted coordinate; `fine` samples per period for max/min and contact state.
  ResponseEvaluator(const HarmonicBalance& hb, Eigen::VectorXd q, int fine = 1024);
  ResponseSummary summarize(const Eigen::VectorXd& X) const;
  // Time history of the coordinate over one period at `fine` samples (theta_j = 2 pi j / fine).
  Eigen::VectorXd history(const Eigen::VectorXd& X) const;

 private:
  const HarmonicBalance& hb_;
  Eigen::VectorXd q_;
  Aft fine_;
};

// Stability flag (Hill) of every point of a branch.
std::vector<bool> branch_stability(const HarmonicBalance& hb, const Branch& b);

}  // namespace gearhb
