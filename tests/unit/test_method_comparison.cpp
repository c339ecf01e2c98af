// lib/gearhb/experiments/parametric.hpp and method_comparison.hpp against closed forms.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/hb/floquet.hpp"
#include "gearhb/experiments/method_comparison.hpp"
#include "gearhb/experiments/parametric.hpp"
#include "gearhb/hb/stability.hpp"
#include "test_models.hpp"

using namespace gearhb;

// b = 0: y'' + a y = 0 over 2 pi, trace = 2 cos(2 pi sqrt(a)) (closed form), 2 cosh(2 pi sqrt(-a)) for a < 0.
TEST(Parametric, MeissnerTraceWithoutModulationIsTheHarmonicOscillator) {
  EXPECT_NEAR(meissner_trace(0.3, 0.0), 2 * std::cos(2 * M_PI * std::sqrt(0.3)), 1e-12);
  EXPECT_NEAR(meissner_trace(-0.2, 0.0), 2 * std::cosh(2 * M_PI * std::sqrt(0.2)), 1e-10);
}

// Meissner's trace against GSL rk8pd on the variational equation (tol 1e-12), a = 2, b = 1.
TEST(Parametric, MeissnerTraceMatchesGslMonodromy) {
  const double a = 2.0, b = 1.0;
  auto A = [&](double t, Eigen::MatrixXd& out) { out << 0, 1, -(a + b * (std::cos(t) > 0 ? 1.0 : -1.0)), 0; };
  const double tr = monodromy_linear_periodic(A, 2, 2 * M_PI, {M_PI / 2, 3 * M_PI / 2}, 1e-12).trace();
  EXPECT_NEAR(meissner_trace(a, b), tr, 1e-8);
}

// Square wave a + b sgn(cos): a1 = 4b/pi, a3 = -4b/(3 pi), even harmonics 0 (Fourier series).
TEST(Parametric, SquareWaveCoefficients) {
  const Eigen::VectorXd k = square_wave_stiffness(1.0, 2.0, 4);
  EXPECT_DOUBLE_EQ(k[0], 1.0);
  EXPECT_NEAR(k[1], 8 / M_PI, 1e-15);
  EXPECT_NEAR(k[3], 0.0, 1e-15);
  EXPECT_NEAR(k[5], -8 / (3 * M_PI), 1e-15);
}

// Mathieu at q = 0: stable for a > 0 away from a = k^2 (Hill and Floquet agree), unstable for a < 0.
TEST(Parametric, HillOnMathieuWithoutModulation) {
  const Eigen::MatrixXd one = Eigen::MatrixXd::Identity(1, 1), zero = Eigen::MatrixXd::Zero(1, 1);
  for (double a : {-0.5, 0.5, 2.5}) {
    const Eigen::VectorXd k = (Eigen::VectorXd(3) << a, 0.0, 0.0).finished();
    const Eigen::MatrixXd J = linear_periodic_jacobian(one, zero, zero, one, k, 2.0, 4);
    EXPECT_EQ(hill_stability(J, one, zero, 2.0, 4).stable, a > 0) << "a = " << a;
  }
}

// A stable open-contact point of the mass against the wall is the linear response:
// x_max = F/|k - w^2 m + i w c| (closed form) from a stepped sweep started on it.
TEST(MethodComparison, SteppedSweepOnTheLinearResponse) {
  const HarmonicBalance hb = test_models::mass_wall(-0.6, 5);
  const double w = 0.7, amp = 0.01 / std::abs(std::complex<double>(1 - w * w, 0.01 * w));
  TimeIntegrationOptions o;
  o.rel_tol = o.abs_tol = 1e-12;
  o.periodicity_tol = 1e-11;
  const auto p = stepped_sweep(hb, {w}, Eigen::VectorXd::Constant(1, 1.0), o).front();
  ASSERT_TRUE(p.periodic);
  EXPECT_NEAR(p.x_max, amp, 1e-9 * amp);
  EXPECT_NEAR(p.x_h1, amp, 1e-9 * amp);
}

// Error measure: nearest solution, misses counted (defined in method_comparison.hpp).
TEST(MethodComparison, GridErrorTakesTheNearestSolutionAndCountsMisses) {
  GridSolutions ref(2), m(2);
  ref[0] = {{1.0, 1.0, true, {}}, {2.0, 2.0, true, {}}};
  ref[1] = {{1.0, 1.0, false, {}}};
  m[0] = {{1.001, 1.0, true, {}}};
  const GridError e = grid_error(ref, m);
  EXPECT_EQ(e.compared, 2);
  EXPECT_EQ(e.missed, 1);                  // 2.0 has no solution within 5 %
  EXPECT_NEAR(e.x_max, 0.4995, 1e-12);     // |1.001 - 2| / 2
}
