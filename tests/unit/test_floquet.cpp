// Floquet multipliers on the exact piecewise-linear flow (lib/gearhb/hb/floquet.hpp),
// against independent truths:
//  - linear oscillator (contact never or always closed): multipliers exp(lambda T),
//    lambda the eigenvalues of [0 1; -k/m -c/m] (exact);
//  - Meissner equation x'' + (a + b sgn cos t) x = 0: exact trace of the monodromy
//    2 cos(p1 t1) cos(p2 t2) - (p1/p2 + p2/p1) sin(p1 t1) sin(p2 t2) (closed form);
//  - Mathieu equation x'' + (d + e cos t) x = 0: transition curves of the first
//    tongue d = 1/4 -+ e/2 - e^2/8 + O(e^3) (Nayfeh & Mook, Nonlinear Oscillations, §5.2.2)
//    and Liouville's det = exp(-int trace) = 1;
//  - GSL monodromy (variational equations, rk8pd) about the orbit after GSL
//    integration to a periodic steady state;
//  - the middle branch between two folds of chapter 3's mass against a wall is unstable.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(Floquet, LinearOscillatorMultipliersAreExpLambdaT) {
  for (double gap : {-10.0, 10.0}) {   // open (k = 1) and always closed (k = 1 + kc = 2)
    HarmonicBalance hb = test_models::mass_wall(gap, 5);
    const double k = gap < 0 ? 1.0 : 2.0, c = 0.01;
    for (double w : {0.5, 1.3}) {
      const VectorXd X = gap < 0 ? hb.open_contact_solution(w) : hb.closed_contact_solution(w);
      const FloquetResult r = floquet_of_hb_orbit(hb, X, w, 1.0);
      const std::complex<double> lambda(-c / 2, std::sqrt(k - c * c / 4));
      const std::complex<double> mu = std::exp(lambda * (2 * M_PI / w));
      ASSERT_EQ(r.multipliers.size(), 2);
      for (int i = 0; i < 2; ++i)
        EXPECT_NEAR(std::min(std::abs(r.multipliers[i] - mu), std::abs(r.multipliers[i] - std::conj(mu))), 0.0, 1e-11)
            << "gap " << gap << ", w " << w;
      EXPECT_TRUE(r.stable);
      EXPECT_TRUE(r.corrected);
      EXPECT_LT(r.orbit_error, 1e-12);   // the HB solution of a linear system is exact
    }
  }
}

namespace {
double meissner_trace(double a, double b, double T) {
  // x'' + (a + b) x = 0 on [0, T/4) and [3T/4, T), x'' + (a - b) x = 0 on [T/4, 3T/4) (sgn cos)
  const double p1 = std::sqrt(a + b), p2 = std::sqrt(a - b), t1 = T / 2, t2 = T / 2;
  return 2 * std::cos(p1 * t1) * std::cos(p2 * t2) - (p1 / p2 + p2 / p1) * std::sin(p1 * t1) * std::sin(p2 * t2);
}
}  // namespace

TEST(Floquet, MeissnerSquareWaveStiffnessMatchesTheClosedFormTrace) {
  const double T = 2 * M_PI;
  for (double a : {0.2, 0.3, 0.9, 1.1, 2.0}) {
    const double b = 0.1;
    auto A = [&](double t, MatrixXd& out) {
      out.resize(2, 2);
      const double q = a + (std::cos(t) >= 0 ? b : -b);
      out << 0, 1, -q, 0;
    };
    const MatrixXd Phi = monodromy_linear_periodic(A, 2, T, {T / 4, 3 * T / 4});
    EXPECT_NEAR(Phi.trace(), meissner_trace(a, b, T), 1e-10) << "a = " << a;
    EXPECT_NEAR(Phi.determinant(), 1.0, 1e-10);
    // stability from the trace: |tr| < 2 <=> stable (a test that can fail both ways)
    const bool stable = std::fabs(meissner_trace(a, b, T)) < 2.0;
    const double mu = Phi.eigenvalues().cwiseAbs().maxCoeff();
    EXPECT_EQ(mu < 1.0 + 1e-8, stable) << "a = " << a;
  }
}

TEST(Floquet, MathieuFirstTongueFromTheVariationalEquation) {
  const double e = 0.1;
  const double lower = 0.25 - e / 2 - e * e / 8, upper = 0.25 + e / 2 - e * e / 8;   // +O(e^3) ~ 3e-5
  for (double d : {lower - 0.01, 0.25, upper + 0.01, lower + 0.01, upper - 0.01}) {
    auto A = [&](double t, MatrixXd& out) {
      out.resize(2, 2);
      out << 0, 1, -(d + e * std::cos(t)), 0;
    };
    const MatrixXd Phi = monodromy_linear_periodic(A, 2, 2 * M_PI);
    EXPECT_NEAR(Phi.determinant(), 1.0, 1e-10);
    const bool inside = d > lower && d < upper;
    EXPECT_EQ(std::fabs(Phi.trace()) > 2.0, inside) << "d = " << d << ", trace " << Phi.trace();
    if (inside) {
      EXPECT_LT(Phi.trace(), -2.0);   // the first tongue is a period doubling (multiplier -1)
    }
  }
}

namespace {
Branch ch3_branch(const HarmonicBalance& hb) {
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  return arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
}
}  // namespace

TEST(Floquet, AgreesWithGslMonodromyOfTheConvergedTimeIntegration) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 10);
  for (double w : {1.05, 1.2, 1.5}) {
    // a stable intermittent orbit: Newton from the open solution, then the exact-flow multipliers
    VectorXd X = hb.open_contact_solution(w);
    const Branch b = ch3_branch(hb);
    // the point of the upper (resonant) part nearest to w
    std::size_t best = 0;
    for (std::size_t i = 0; i < b.points.size(); ++i)
      if (std::fabs(b.points[i].omega - w) < std::fabs(b.points[best].omega - w)) best = i;
    X = b.points[best].X;
    const double wb = b.points[best].omega;
    const FloquetResult r = floquet_of_hb_orbit(hb, X, wb, 0.6);
    ASSERT_TRUE(r.corrected) << "w = " << wb;
    TimeIntegrator ti(hb);
    TimeIntegrationOptions o;
    o.x_scale = 0.6;
    VectorXd x0, v0;
    hb_initial_state(hb, X, wb, x0, v0);
    const SteadyState ss = ti.steady_state(x0, v0, wb, o);
    ASSERT_TRUE(ss.converged);
    // the same periodic state (up to the GSL tolerance) and the same multipliers
    EXPECT_LT((ss.x0 - r.x0).cwiseAbs().maxCoeff(), 1e-7) << "w = " << wb;
    const MatrixXd Pg = ti.monodromy(ss.x0, ss.v0, wb, o);
    Eigen::VectorXcd mg = Pg.eigenvalues();
    for (int i = 0; i < 2; ++i) {
      double dmin = INFINITY;
      for (int j = 0; j < 2; ++j) dmin = std::min(dmin, std::abs(mg[j] - r.multipliers[i]));
      EXPECT_LT(dmin, 1e-6) << "w = " << wb << ", multiplier " << r.multipliers[i];
    }
  }
}

TEST(Floquet, MiddleBranchOfChapter3IsUnstableWithAMultiplierAboveOne) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  const Branch b = ch3_branch(hb);
  ASSERT_EQ(b.folds.size(), 2u);
  int middle = 0, outer = 0;
  for (const auto& p : b.points) {
    bool near = false;
    for (const auto& f : b.folds) near = near || std::fabs(f.omega - p.omega) < 2e-4;
    if (near) continue;
    const FloquetResult r = floquet_of_hb_orbit(hb, p.X, p.omega, 0.6);
    if (p.tangent_omega < 0.0) {
      EXPECT_FALSE(r.stable) << "omega = " << p.omega;
      EXPECT_GT(r.critical.real(), 1.0);            // real, above +1 (saddle)
      EXPECT_NEAR(r.critical.imag(), 0.0, 1e-12);
      ++middle;
    } else {
      EXPECT_TRUE(r.stable) << "omega = " << p.omega;
      ++outer;
    }
  }
  EXPECT_GT(middle, 5);
  EXPECT_GT(outer, 50);
}
