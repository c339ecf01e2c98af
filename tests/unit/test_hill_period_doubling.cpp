// Hill's method at a period doubling: the damped Mathieu equation
//     x'' + c x' + (1 + eps cos(w t)) x = 0,  w = 2,
// sits in the centre of its first instability tongue. Its Floquet multipliers are
// real and negative (exponents at Im = w/2) and for small eps the growth rate is
//     sigma = eps/4 - c/2   (first-order averaging; e.g. Nayfeh & Mook,
//                            Nonlinear Oscillations, 1979, §5.3: the tongue
//                            boundary w = 2 (1 +- eps/4) and growth eps/4 at its centre).
// Four Hill eigenvalues share |Im| ~ w/2 for the two slots of a 1-DOF system, so a
// selection by count alone may keep the decaying pair and miss the instability.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/hb/stability.hpp"

using namespace gearhb;

namespace {
// HB Jacobian of x'' + c x' + s(theta) x = 0 in the real basis (harmonic_balance.hpp layout, n = 1).
Eigen::MatrixXd mathieu_jacobian(double c, double eps, double w, int H) {
  Aft aft(H);
  Eigen::VectorXd s(aft.samples());
  for (int j = 0; j < s.size(); ++j) s[j] = 1.0 + eps * std::cos(aft.theta(j));
  Eigen::MatrixXd J(2 * H + 1, 2 * H + 1);
  aft.product_matrix(s.data(), J);
  for (int k = 1; k <= H; ++k) {
    const int ic = 2 * k - 1, is = 2 * k;
    J(ic, ic) -= (k * w) * (k * w);
    J(is, is) -= (k * w) * (k * w);
    J(ic, is) += k * w * c;
    J(is, ic) -= k * w * c;
  }
  return J;
}
}  // namespace

TEST(Hill, FindsThePeriodDoublingOfTheMathieuEquation) {
  const double c = 0.01, w = 2.0;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(1, 1), C = c * M;
  for (double eps : {0.1, 0.2}) {
    const HillResult r = hill_stability(mathieu_jacobian(c, eps, w, 8), M, C, w, 8);
    EXPECT_FALSE(r.stable) << "eps = " << eps;
    const double sigma = eps / 4 - c / 2;
    // tolerance: the averaging formula is first order in eps (error O(eps^2) ~ 0.1 sigma)
    EXPECT_NEAR(r.max_real, sigma, 0.15 * sigma) << "eps = " << eps;
  }
  // Across the tongue and for several truncations (where the truncation error
  // puts the growing exponent's Im just outside w/2, a count-only selection fails).
  for (int H : {3, 5, 8, 12})
    for (double wi : {1.97, 1.99, 2.0, 2.01, 2.03}) {
      const HillResult r = hill_stability(mathieu_jacobian(c, 0.2, wi, H), M, C, wi, H);
      EXPECT_FALSE(r.stable) << "H = " << H << ", w = " << wi;
    }
  // Outside the tongue (w = 2.6: |w/2 - 1| = 0.3 > eps/4) the same equation is stable.
  const HillResult s = hill_stability(mathieu_jacobian(c, 0.2, 2.6, 8), M, C, 2.6, 8);
  EXPECT_TRUE(s.stable);
  EXPECT_NEAR(s.max_real, -c / 2, 1e-3);
}
