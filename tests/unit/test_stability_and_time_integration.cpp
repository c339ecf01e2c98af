// Hill stability and harmonic balance against direct time integration (GSL).
// Independent truths:
//  - a damped linear 1-DOF oscillator is stable at every forcing frequency and
//    its Floquet exponents are its eigenvalues, Re = -c/(2m) (exact);
//  - for a forced 1-DOF oscillator the middle branch between two folds of an
//    overhanging resonance is unstable (saddle-node: a real Floquet multiplier
//    crosses +1 at each fold; Nayfeh & Mook, "Nonlinear Oscillations", §4.1);
//  - the monodromy matrix from GSL integration of the variational equations
//    gives the Floquet multipliers independently of harmonic balance;
//  - GSL integration to a periodic steady state gives x_max independently.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/stability.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

Branch fig_branch(const HarmonicBalance& hb) {
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  return arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
}

bool near_fold(const Branch& b, double w, double margin) {
  for (const auto& f : b.folds)
    if (std::fabs(f.omega - w) < margin) return true;
  return false;
}

}  // namespace

TEST(Hill, LinearOscillatorExponentsAreItsEigenvalues) {
  HarmonicBalance hb = test_models::mass_wall(-10.0, 6);   // never in contact: linear
  VectorXd R;
  MatrixXd J;
  for (double w : {0.5, 1.0, 1.7}) {
    const VectorXd X = hb.open_contact_solution(w);
    hb.evaluate(X, w, R, &J, nullptr);
    const HillResult h = hill_stability(J, hb.system().M, hb.system().C, w, 6);
    EXPECT_TRUE(h.stable);
    ASSERT_EQ(h.exponents.size(), 2);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(h.exponents[i].real(), -0.005, 1e-10);   // -c/(2m)
      // imaginary part: +-w_d modulo w, w_d = sqrt(1 - 0.005^2)
      const double wd = std::sqrt(1.0 - 0.005 * 0.005);
      const double r = std::remainder(std::fabs(h.exponents[i].imag()) - wd, w);
      EXPECT_NEAR(std::min(std::fabs(r), std::fabs(std::remainder(std::fabs(h.exponents[i].imag()) + wd, w))), 0.0, 1e-9);
    }
  }
}

TEST(Hill, MiddleBranchBetweenFoldsIsUnstable) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  const Branch b = fig_branch(hb);
  ASSERT_EQ(b.folds.size(), 2u);
  const auto st = branch_stability(hb, b);
  int checked = 0;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    if (near_fold(b, b.points[i].omega, 2e-4)) continue;
    const bool middle = b.points[i].tangent_omega < 0.0;   // omega decreasing along the arc
    EXPECT_EQ(st[i], !middle) << "omega = " << b.points[i].omega;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(Hill, AgreesWithMonodromyFromTimeIntegration) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 10);
  const Branch b = fig_branch(hb);
  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  VectorXd R;
  MatrixXd J;
  int unstable_seen = 0, stable_seen = 0;
  for (std::size_t i = 0; i < b.points.size(); i += 7) {
    const auto& p = b.points[i];
    if (near_fold(b, p.omega, 1e-3)) continue;
    hb.evaluate(p.X, p.omega, R, &J, nullptr);
    const HillResult h = hill_stability(J, hb.system().M, hb.system().C, p.omega, 10);
    VectorXd x0, v0;
    hb_initial_state(hb, p.X, p.omega, x0, v0);
    const Eigen::VectorXcd mu = general_eigenvalues(ti.monodromy(x0, v0, p.omega, to), "GSL monodromy");
    const double max_mu = mu.cwiseAbs().maxCoeff();
    EXPECT_EQ(h.stable, max_mu < 1.0) << "omega = " << p.omega << ", max |mu| = " << max_mu;
    // Floquet exponent <-> multiplier: |mu| = exp(Re(lambda) T)
    const double T = 2 * M_PI / p.omega;
    EXPECT_NEAR(std::log(max_mu) / T, h.max_real, 2e-3 + 0.02 * std::fabs(h.max_real))
        << "omega = " << p.omega;
    (h.stable ? stable_seen : unstable_seen)++;
  }
  EXPECT_GT(unstable_seen, 2);
  EXPECT_GT(stable_seen, 10);
}

// Fig. 9 (g = -0.6) and Fig. 10 (g = +0.4): x_max from harmonic balance
// against GSL time integration at >= 8 stable intermittent-contact points on
// both sides of the folds. H = 10: see the H-convergence test below.
class HbVersusTimeIntegration : public ::testing::TestWithParam<double> {};

TEST_P(HbVersusTimeIntegration, XmaxWithinHalfPercent) {
  const double gap = GetParam();
  HarmonicBalance hb = test_models::mass_wall(gap, 10);
  const Branch b = fig_branch(hb);
  ASSERT_TRUE(b.complete);
  ASSERT_EQ(b.folds.size(), 2u);
  const auto st = branch_stability(hb, b);
  ResponseEvaluator ev(hb, VectorXd::Constant(1, 1.0));
  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.x_scale = hb.scaling(0.5, 2.0).x[0];
  to.periodicity_tol = 1e-10;
  // Stable points on both sides of the overhang: along the arc before the first
  // fold and after the second, near the folds, not within
  // 2e-3 rad/s of either fold (where the approach to steady state is slow).
  const double lo = std::min(b.folds[0].omega, b.folds[1].omega) - 0.3;
  const double hi = std::max(b.folds[0].omega, b.folds[1].omega) + 0.3;
  std::vector<std::size_t> before, after;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const double w = b.points[i].omega;
    if (!st[i] || near_fold(b, w, 2e-3) || w < lo || w > hi) continue;
    if (int(i) <= b.folds[0].after_point) before.push_back(i);
    if (int(i) > b.folds[1].after_point) after.push_back(i);
  }
  // keep the third of each side nearest (along the arc) to its fold
  before.erase(before.begin(), before.begin() + 2 * before.size() / 3);
  after.resize(after.size() / 3);
  ASSERT_GE(before.size(), 5u);
  ASSERT_GE(after.size(), 5u);
  int intermittent = 0;
  for (const auto* side : {&before, &after})
    for (int s = 0; s < 5; ++s) {
      const auto& p = b.points[(*side)[side->size() * s / 5]];
      VectorXd x0, v0;
      hb_initial_state(hb, p.X, p.omega, x0, v0);
      const SteadyState ss = ti.steady_state(x0, v0, p.omega, to);
      ASSERT_TRUE(ss.converged) << "omega = " << p.omega;
      const auto r = ev.summarize(p.X);
      const double ti_max = ss.x.maxCoeff();
      EXPECT_NEAR(r.x_max, ti_max, 0.005 * std::fabs(ti_max)) << "omega = " << p.omega;
      intermittent += r.contact == ContactState::intermittent;
    }
  EXPECT_GE(intermittent, 3);   // the check must exercise the contact, not only linear pieces
}

INSTANTIATE_TEST_SUITE_P(Fig9and10, HbVersusTimeIntegration, ::testing::Values(-0.6, 0.4));

TEST(HbConvergence, XmaxConvergesInHarmonics) {
  // At a fixed intermittent point of Fig. 10 (g = 0.4, omega = 1.30) the HB
  // x_max converges to the time-integration value as H grows.
  const double w = 1.30;
  double err_prev = 1e9;
  double ti_max = 0.0;
  for (int H : {1, 3, 10}) {
    HarmonicBalance hb = test_models::mass_wall(0.4, H);
    // start on the upper (intermittent) branch: continuation from the high side
    ContinuationOptions o;
    o.omega_start = 2.0;
    o.omega_end = w;
    const Branch b = arc_length_continuation(hb, hb.closed_contact_solution(2.0), hb.scaling(w, 2.0), o);
    ASSERT_TRUE(b.complete);
    const auto& p = b.points.back();
    ResponseEvaluator ev(hb, VectorXd::Constant(1, 1.0));
    if (H == 1) {
      // The reference: GSL rk8pd to the periodic steady state, its crest refined between
      // samples, at two tolerances; the reference is converged if they agree to 1e-8.
      TimeIntegrator ti(hb);
      VectorXd x0, v0;
      hb_initial_state(hb, p.X, p.omega, x0, v0);
      double crest[2];
      for (int k = 0; k < 2; ++k) {
        TimeIntegrationOptions to;
        to.rel_tol = k == 0 ? 1e-9 : 1e-11;
        to.abs_tol = to.rel_tol * 1e-2;
        const SteadyState ss = ti.steady_state(x0, v0, w, to);
        ASSERT_TRUE(ss.converged) << "rel_tol = " << to.rel_tol;
        crest[k] = ti.max_over_period(ss.x0, ss.v0, w, VectorXd::Constant(1, 1.0), to);
      }
      EXPECT_NEAR(crest[0], crest[1], 1e-8 * std::fabs(crest[1]));
      ti_max = crest[1];
    }
    const double err = std::fabs(ev.summarize(p.X).x_max - ti_max);
    EXPECT_LT(err, err_prev) << "H = " << H;
    err_prev = err;
  }
  EXPECT_LT(err_prev, 0.005 * std::fabs(ti_max));
}
