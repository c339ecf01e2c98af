// Unit tests of harmonic balance, Newton and continuation (lib/harmonic_balance,
// lib/newton, lib/continuation). Independent truths: the closed-form FRF of a
// linear system, X = (K - w^2 M + i w C)^{-1} F (any vibration text, e.g.
// Géradin & Rixen, "Mechanical Vibrations", 3rd ed., §2.3); finite differences
// for the Jacobian.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Two masses on springs, coupled, Rayleigh damped, no contact.
HarmonicBalance two_dof_linear(int H) {
  MatrixXd M(2, 2), K(2, 2);
  M << 1.0, 0.0, 0.0, 2.0;
  K << 5.0, -2.0, -2.0, 3.0;
  LinearSystem s{M, rayleigh_damping(M, K, 0.05, 0.01), K};
  Excitation f{VectorXd::Zero(2), VectorXd::Zero(2), VectorXd::Zero(2)};
  f.f0 << 0.3, -0.1;
  f.fc << 1.0, 0.0;
  f.fs << 0.0, 0.5;
  return HarmonicBalance(s, {}, f, H);
}

}  // namespace

TEST(HarmonicBalance, LinearSystemEqualsClosedFormFrf) {
  HarmonicBalance hb = two_dof_linear(3);
  const auto sc = hb.scaling(0.1, 3.0);
  for (double w : {0.3, 1.1, 1.7, 2.5}) {
    VectorXd X = VectorXd::Zero(hb.size());
    const NewtonReport r = newton_solve(hb, X, w, sc);
    ASSERT_TRUE(r.converged) << r.message;
    // closed form: static K^{-1} f0, first harmonic from the complex FRF of (fc - i fs)
    const VectorXd xs = hb.system().K.partialPivLu().solve(hb.excitation().f0);
    const Eigen::VectorXcd F = hb.excitation().fc.cast<std::complex<double>>() -
                               std::complex<double>(0, 1) * hb.excitation().fs.cast<std::complex<double>>();
    const Eigen::VectorXcd Z = frequency_response(hb.system(), F, w);
    for (int d = 0; d < 2; ++d) {
      EXPECT_NEAR(X[hb.index(0, d)], xs[d], 1e-12);
      EXPECT_NEAR(X[hb.index(1, d)], Z[d].real(), 1e-12);
      EXPECT_NEAR(X[hb.index(2, d)], -Z[d].imag(), 1e-12);
      for (int a = 3; a < 7; ++a) EXPECT_NEAR(X[hb.index(a, d)], 0.0, 1e-12);  // no higher harmonics
    }
  }
}

TEST(HarmonicBalance, OpenContactEqualsLinearSolution) {
  // g = -10 m: the response (amplitude <= 1 m) never reaches the wall.
  HarmonicBalance hb = test_models::mass_wall(-10.0, 5);
  const auto sc = hb.scaling(0.5, 2.0);
  for (double w : {0.5, 0.9, 1.0, 1.3}) {
    VectorXd X = VectorXd::Zero(hb.size());
    ASSERT_TRUE(newton_solve(hb, X, w, sc).converged);
    EXPECT_LT((X - hb.open_contact_solution(w)).cwiseAbs().maxCoeff(), 1e-12) << "w = " << w;
  }
}

TEST(HarmonicBalance, FullContactEqualsClosedLinearSolution) {
  // g = +5 m preload: the spring kc never opens; x = closed-contact linear solution,
  // static offset -kc g / (k + kc) = -2.5 m.
  HarmonicBalance hb = test_models::mass_wall(5.0, 5);
  const auto sc = hb.scaling(0.5, 2.0);
  for (double w : {0.7, 1.414, 1.8}) {
    VectorXd X = VectorXd::Zero(hb.size());
    ASSERT_TRUE(newton_solve(hb, X, w, sc).converged);
    EXPECT_LT((X - hb.closed_contact_solution(w)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(X[0], -2.5, 1e-12);
  }
}

TEST(HarmonicBalance, OpenResonanceAmplitudeIsFOverCOmega) {
  // k = m = 1: at w = 1, |X| = F / (c w) = 0.01 / 0.01 = 1.0 m exactly.
  HarmonicBalance hb = test_models::mass_wall(-10.0, 3);
  VectorXd X = VectorXd::Zero(hb.size());
  ASSERT_TRUE(newton_solve(hb, X, 1.0, hb.scaling(0.5, 2.0)).converged);
  EXPECT_NEAR(std::hypot(X[1], X[2]), 1.0, 1e-12);
}

TEST(HarmonicBalance, JacobianMatchesFiniteDifferences) {
  // An intermittent-contact state: g = -0.6, amplitude ~0.9 with harmonics.
  HarmonicBalance hb = test_models::mass_wall(-0.6, 4, 0.05);
  VectorXd X = VectorXd::Zero(hb.size());
  X << 0.05, 0.9, 0.2, 0.03, -0.02, 0.01, 0.004, -0.003, 0.002;
  const double w = 1.04;
  VectorXd R, dRdomega;
  MatrixXd J;
  hb.evaluate(X, w, R, &J, &dRdomega);
  const double h = 1e-7;   // central differences: error O(h^2) away from kinks
  VectorXd Rp, Rm;
  for (int j = 0; j < hb.size(); ++j) {
    VectorXd Xp = X, Xm = X;
    Xp[j] += h;
    Xm[j] -= h;
    hb.evaluate(Xp, w, Rp, nullptr, nullptr);
    hb.evaluate(Xm, w, Rm, nullptr, nullptr);
    const VectorXd col = (Rp - Rm) / (2 * h);
    EXPECT_LT((col - J.col(j)).cwiseAbs().maxCoeff(), 1e-6) << "column " << j;
  }
  hb.evaluate(X, w + h, Rp, nullptr, nullptr);
  hb.evaluate(X, w - h, Rm, nullptr, nullptr);
  EXPECT_LT(((Rp - Rm) / (2 * h) - dRdomega).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(Continuation, ContactBranchHasExactlyTwoFoldsAndIsComplete) {
  // Fig. 9, g = -0.6: hardening contact resonance with one overhang: two folds.
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  const Branch b = arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
  ASSERT_TRUE(b.complete) << b.summary();
  EXPECT_TRUE(b.failures.empty());
  ASSERT_EQ(b.folds.size(), 2u) << b.summary();
  EXPECT_GT(b.folds[0].omega, b.folds[1].omega);   // upper fold first, then back down
  EXPECT_GT(b.folds[1].omega, 1.0);                // both above the open resonance
  EXPECT_LT(b.folds[0].omega, std::sqrt(2.0));     // and below the closed one
}

TEST(Continuation, DescendingSweepFindsTheSameFolds) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  ContinuationOptions up, down;
  up.omega_start = down.omega_end = 0.5;
  up.omega_end = down.omega_start = 2.0;
  const auto sc = hb.scaling(0.5, 2.0);
  const Branch bu = arc_length_continuation(hb, hb.open_contact_solution(0.5), sc, up);
  const Branch bd = arc_length_continuation(hb, hb.open_contact_solution(2.0), sc, down);
  ASSERT_TRUE(bu.complete && bd.complete);
  ASSERT_EQ(bd.folds.size(), 2u);
  EXPECT_NEAR(bd.folds[1].omega, bu.folds[0].omega, 1e-8);  // folds refined by bisection (continuation.hpp)
  EXPECT_NEAR(bd.folds[0].omega, bu.folds[1].omega, 1e-8);  // folds refined by bisection (continuation.hpp)
}

TEST(Continuation, NaturalContinuationStopsAtTheFold) {
  // Teaching case (thesis §2.2): marching omega upward follows the upper branch
  // to the fold and fails just past it; arc-length continuation goes round it.
  HarmonicBalance hb = test_models::mass_wall(-0.6, 5);
  ContinuationOptions o;
  o.omega_start = 0.9;
  o.omega_end = 1.2;
  o.natural_points = 600;   // d omega = 5e-4
  const auto sc = hb.scaling(0.9, 1.2);
  const Branch nat = natural_continuation(hb, hb.open_contact_solution(0.9), sc, o);
  const Branch arc = arc_length_continuation(hb, hb.open_contact_solution(0.9), sc, o);
  ASSERT_EQ(arc.folds.size(), 2u);
  EXPECT_FALSE(nat.complete);
  ASSERT_EQ(nat.failures.size(), 1u);
  const double fold = arc.folds[0].omega, dw = 0.3 / 600;
  EXPECT_GT(nat.failures[0].omega, fold);            // it failed past the fold ...
  EXPECT_LT(nat.failures[0].omega, fold + dw + 1e-12); // ... at the first step beyond it
  const auto& last = nat.points.back();
  EXPECT_GT(std::hypot(last.X[1], last.X[2]), 0.85);  // still on the upper branch
}

TEST(Continuation, ReportsFailureInsteadOfTruncating) {
  // A step cap that is too small must surface as a reported failure.
  HarmonicBalance hb = test_models::mass_wall(-0.6, 3);
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  o.max_steps = 10;
  const Branch b = arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
  EXPECT_FALSE(b.complete);
  ASSERT_EQ(b.failures.size(), 1u);
  EXPECT_NE(b.failures[0].what.find("step cap"), std::string::npos);
  EXPECT_GT(b.failures[0].omega, 0.5);
}

TEST(Continuation, MicrometreScaleProblemConvergesWithoutHandScaling) {
  // The same physics in gear-like units: stiffness x 1e8, forces x 1e2 -> x ~ 1e-6 m.
  // Automatic scaling must give the same branch, scaled, with no tuning.
  using Eigen::MatrixXd;
  const double ks = 1e8, fs = 1e2, xs = fs / ks;
  LinearSystem s{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.01 * 1e4),
                 MatrixXd::Constant(1, 1, ks)};   // w scales by 1e4
  UnilateralContact c{VectorXd::Constant(1, 1.0), ks, -0.6 * xs, {}};
  Excitation f{VectorXd::Zero(1), VectorXd::Constant(1, 0.01 * fs), VectorXd::Zero(1)};
  HarmonicBalance hb(s, {c}, f, 5);
  ContinuationOptions o;
  o.omega_start = 0.5e4;
  o.omega_end = 2.0e4;
  const Branch b = arc_length_continuation(hb, hb.open_contact_solution(o.omega_start),
                                           hb.scaling(o.omega_start, o.omega_end), o);
  HarmonicBalance ref = test_models::mass_wall(-0.6, 5);
  ContinuationOptions oref;
  oref.omega_start = 0.5;
  oref.omega_end = 2.0;
  const Branch br = arc_length_continuation(ref, ref.open_contact_solution(0.5), ref.scaling(0.5, 2.0), oref);
  ASSERT_TRUE(b.complete) << b.summary();
  ASSERT_EQ(b.folds.size(), br.folds.size());
  for (std::size_t i = 0; i < b.folds.size(); ++i)
    EXPECT_NEAR(b.folds[i].omega / 1e4, br.folds[i].omega, 1e-6);
}
