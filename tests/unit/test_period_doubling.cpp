// Period-doubled branches by harmonic balance (hb/period_doubling.hpp, issue 34 §1).
//  - NLvib example 03 (test_models::nlvib_ex03) at H = 40 (H2 = 80: at H = 21 the period-2
//    model has no branch point beside the PDs, period_doubling.hpp): the period-2 branch
//    switched at one PD must end at the other, both located by Floquet on the exact flow
//    (reference/scripts/nlvib_ex03_exact.json, +-1e-11), and its stable points must be
//    period-2 orbits of the original model by GSL time integration (q1's max over two
//    periods, the orbit period-2 and not period-1).
//  - The period-2 HB of the same oscillator agrees with shooting over two forcing periods
//    on the exact flow of the ORIGINAL model (PiecewiseLinearFlow of the period-1 model:
//    no harmonic balance), a method independent of the period-2 model.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gear_pair_models.hpp"
#include "test_models.hpp"

using namespace gearhb;

namespace {
// Exact-flow period doublings of ex. 03 (test_nlvib_ex03.cpp, nlvib_ex03_exact.json).
constexpr double kPdHigh = 0.755586159356, kPdLow = 0.738783025373;

struct Ex03Pd {
  HarmonicBalance hb = test_models::nlvib_ex03(40);
  SweepOptions o = test_models::nlvib_ex03_sweep(StabilityMethod::floquet);
  FrequencyCurve c;
  std::vector<PeriodDoubledBranch> br;
  Ex03Pd() {
    c = sweep_frequency(hb, o, "ex03");
    br = period_doubled_branches(hb, c, o);
  }
};
const Ex03Pd& ex03() {
  static const Ex03Pd e;
  return e;
}
double odd_norm(const PeriodDoubledBranch& b, const BranchPoint& p) { return subharmonic_part(*b.model, 2, p.X).norm(); }
}  // namespace

TEST(PeriodDoubling, Ex03BranchJoinsTheTwoDoublings) {
  const auto& e = ex03();
  ASSERT_TRUE(e.c.complete) << e.c.failure;
  // one branch: switched at the first PD met (the sweep runs down), the second is its end
  ASSERT_EQ(e.br.size(), 1u);
  const PeriodDoubledBranch& b = e.br[0];
  EXPECT_EQ(b.end, PeriodDoubledBranch::End::merged) << b.why;
  EXPECT_NEAR(b.omega_start, kPdHigh, 1e-9);
  // the HB's own branch points beside the exact PDs (truncation at H = 40: measured 6e-7, 1.7e-6)
  EXPECT_NEAR(b.omega_branch_point, kPdHigh, 5e-6);
  EXPECT_NEAR(b.omega_end, kPdLow, 5e-6) << b.why;
  ASSERT_GE(b.to, 0);
  EXPECT_NEAR(e.c.bifurcations[std::size_t(b.to)].omega, kPdLow, 1e-9);
  // the Floquet eigen-solution and the HB null vector are one direction
  EXPECT_GT(b.direction_agreement, 0.999);
  // odd harmonics: zero at both ends, large in between
  const auto& P = b.curve.branch.points;
  double largest = 0.0;
  for (const auto& p : P) largest = std::max(largest, odd_norm(b, p));
  EXPECT_GT(largest, 0.1);
  EXPECT_EQ(odd_norm(b, P.front()), 0.0);
  // resolved up to the merge: the last point (the refined crossing, or the last point before
  // it where the refinement's corrector failed) within 2 % of the largest odd part
  EXPECT_LT(odd_norm(b, P.back()), 0.02 * largest);
}

// Near the merge the period-2 branch runs close to the period-1 branch, which solves the
// period-2 model too: a full step's corrector may converge onto it (the odd part falls from 7 %
// of the orbit to round-off in one step; seen at the default step from a branch point located
// 1e-12 away, where the round-off sign of the odd part read as a merge with no PD). At other
// step lengths the branch must still merge at the lower PD with no point on the period-1 branch.
TEST(PeriodDoubling, Ex03BranchNeverStepsOntoThePeriodOneBranch) {
  const auto& e = ex03();
  for (const double ds_max : {0.01, 0.03}) {
    SweepOptions o = e.o;
    o.continuation.ds_max = ds_max;
    const auto br = period_doubled_branches(e.hb, e.c, o);
    ASSERT_EQ(br.size(), 1u) << "ds_max " << ds_max;
    const PeriodDoubledBranch& b = br[0];
    EXPECT_EQ(b.end, PeriodDoubledBranch::End::merged) << b.why;
    EXPECT_NEAR(b.omega_end, kPdLow, 5e-6) << "ds_max " << ds_max << ": " << b.why;
    const auto& P = b.curve.branch.points;
    for (std::size_t k = 1; k + 1 < P.size(); ++k)
      EXPECT_GT(odd_norm(b, P[k]), 1e-6) << "ds_max " << ds_max << ": point " << k << " at omega "
                                         << 2.0 * P[k].omega << " lies on the period-1 branch";
  }
}

// The default step rule (PeriodDoublingOptions fast_iterations 4, curvature_predictor on;
// bench_nlvib_ex03.cpp: 34 points) against the old one (3, the tangent predictor: 87 points):
// the same branch. The default's ends against the exact-flow PDs (independent of HB), no point
// on the period-1 branch, and its own bifurcations those of the dense sampling (each located
// on the exact flow to 1e-9 of its chord, so two samplings agree to ~1e-10 in omega).
TEST(PeriodDoubling, Ex03BranchWithTheDefaultStepRuleIsTheDenselySampledBranch) {
  const auto& e = ex03();
  ASSERT_EQ(e.br.size(), 1u);
  PeriodDoublingOptions dense;
  dense.fast_iterations = 3;
  dense.curvature_predictor = false;
  const auto br = period_doubled_branches(e.hb, e.c, e.o, dense);
  ASSERT_EQ(br.size(), 1u);
  const PeriodDoubledBranch &b = e.br[0], &d = br[0];
  EXPECT_EQ(b.end, PeriodDoubledBranch::End::merged) << b.why;
  EXPECT_EQ(d.end, PeriodDoubledBranch::End::merged) << d.why;
  EXPECT_NEAR(b.omega_start, kPdHigh, 1e-9);
  EXPECT_NEAR(b.omega_end, kPdLow, 5e-6) << b.why;
  EXPECT_NEAR(d.omega_end, kPdLow, 5e-6) << d.why;
  EXPECT_LT(b.curve.branch.points.size(), d.curve.branch.points.size());
  const auto& P = b.curve.branch.points;
  for (std::size_t k = 1; k + 1 < P.size(); ++k)
    EXPECT_GT(odd_norm(b, P[k]), 1e-6) << "point " << k << " at omega " << 2.0 * P[k].omega;
  EXPECT_GE(d.curve.bifurcations.size(), 2u);   // the branch's two folds, at least
  ASSERT_EQ(b.curve.bifurcations.size(), d.curve.bifurcations.size());
  for (std::size_t k = 0; k < d.curve.bifurcations.size(); ++k) {
    EXPECT_EQ(b.curve.bifurcations[k].type, d.curve.bifurcations[k].type) << k;
    EXPECT_NEAR(b.curve.bifurcations[k].omega, d.curve.bifurcations[k].omega, 1e-8) << k;
  }
}

TEST(PeriodDoubling, Ex03StablePointsAreSeenByTimeIntegration) {
  const auto& e = ex03();
  ASSERT_EQ(e.br.size(), 1u);
  const PeriodDoubledBranch& b = e.br[0];
  const auto& P = b.curve.branch.points;
  ResponseEvaluator ev(*b.model, Eigen::Vector2d(1, 0));
  TimeIntegrator ti(e.hb);   // the ORIGINAL (period-1) model at the forcing frequency
  TimeIntegrationOptions to;
  to.x_scale = e.c.scaling.x[0];
  to.samples_per_period = 4000;
  int compared = 0, unstable = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {   // every point (34 on the branch)
    if (!b.curve.stable[i]) {
      ++unstable;
      continue;
    }
    if (b.curve.floquet[i].modulus > 0.9) continue;   // slow to settle
    Eigen::VectorXd x0, v0;
    hb_initial_state(*b.model, P[i].X, P[i].omega, x0, v0);
    const double omega = 2.0 * P[i].omega;
    // 300 transient forcing periods: |mu| <= 0.9 per two periods leaves < 1e-13 of a start error
    const Eigen::MatrixXd x = ti.sample(x0, v0, omega, 300, 4, to);
    const Eigen::Index S = to.samples_per_period;
    const double max12 = x.col(0).head(2 * S).maxCoeff(), max34 = x.col(0).tail(2 * S).maxCoeff();
    const double max1 = x.col(0).head(S).maxCoeff(), max2 = x.col(0).segment(S, S).maxCoeff();
    const double hb_max = ev.summarize(P[i].X).x_max;
    // period 2: periods 3-4 repeat 1-2, and the two forcing periods differ (by the odd part)
    EXPECT_NEAR(max34, max12, 1e-8) << omega;
    EXPECT_GT((x.block(0, 0, S, 1) - x.block(S, 0, S, 1)).cwiseAbs().maxCoeff(), 1e-3) << omega;
    // q1 max over two periods: HB (H2 = 80) against the integration. Tolerance, by the
    // triangle inequality through the exact orbit (the HB orbit corrected by shooting over
    // two periods): the HB orbit's distance to it, max |x_HB - x_exact| on 4000 samples a
    // period (FloquetResult::orbit_error), + the sampled crest of the integration (4000
    // samples a period: |x| (pi / 4000)^2 / 2 = 3.3e-7) + the integration's own error (1e-9).
    FloquetOptions dense;
    dense.steps = 8000;
    const double orbit_error = floquet_of_hb_orbit(*b.model, P[i].X, P[i].omega, e.c.scaling.x[0], dense).orbit_error;
    const double tol = orbit_error + 3.3e-7 * std::fabs(max12) + 1e-9;
    EXPECT_NEAR(hb_max, max12, tol) << "omega " << omega << " (max of one period " << max1 << ", " << max2 << ")";
    ++compared;
  }
  EXPECT_GE(compared, 4);
  EXPECT_GE(unstable, 1);   // the stretch past the fold near the upper PD
}

TEST(PeriodDoubling, Ex03PeriodTwoHbMatchesShootingOverTwoPeriods) {
  // An independent period-2 orbit: Newton on the period-2 map of the ORIGINAL model's exact
  // flow (two applications of the one-period map; no harmonic balance), started from the HB
  // state, against the HB orbit at a stable point in the middle of the branch.
  const auto& e = ex03();
  ASSERT_EQ(e.br.size(), 1u);
  const PeriodDoubledBranch& b = e.br[0];
  const auto& P = b.curve.branch.points;
  const BranchPoint& p = P[P.size() / 2];
  const double omega = 2.0 * p.omega, T = 2.0 * M_PI / omega;
  Eigen::VectorXd x0, v0;
  hb_initial_state(*b.model, p.X, p.omega, x0, v0);
  PiecewiseLinearFlow flow(e.hb);
  std::vector<double> nodes;
  for (int j = 0; j < 128; ++j) nodes.push_back(T * j / 128);
  const int n = 2;
  Eigen::VectorXd y(2 * n);
  y << x0, v0;
  const Eigen::VectorXd y_hb = y;
  double res = INFINITY;
  for (int it = 0; it < 20 && res > 1e-12; ++it) {
    Eigen::VectorXd x1, v1, x2, v2;
    Eigen::MatrixXd P1, P2;
    flow.period_map(y.head(n), y.tail(n), omega, nodes, x1, v1, P1);
    flow.period_map(x1, v1, omega, nodes, x2, v2, P2);
    Eigen::VectorXd F(2 * n);
    F << x2 - y.head(n), v2 - y.tail(n);
    res = F.cwiseAbs().maxCoeff();
    y -= (P2 * P1 - Eigen::MatrixXd::Identity(2 * n, 2 * n)).partialPivLu().solve(F);
  }
  ASSERT_LT(res, 1e-12);
  // the shot orbit is period 2, not period 1
  Eigen::VectorXd x1, v1;
  Eigen::MatrixXd P1;
  flow.period_map(y.head(n), y.tail(n), omega, nodes, x1, v1, P1);
  EXPECT_GT((x1 - y.head(n)).norm(), 1e-3);
  // HB state at phase 0 against it: within the HB orbit error of that point
  EXPECT_LT((y - y_hb).head(n).cwiseAbs().maxCoeff(), b.curve.floquet[P.size() / 2].orbit_error + 1e-9);
}

TEST(PeriodDoubling, SubharmonicModelPlacesTheForcingOnHarmonicTwo) {
  // The period-1 solution re-expressed on the period-2 basis solves the period-2 model
  // (ex. 03 at one omega: the residual of the embedded point is that of the period-1 point).
  const auto& e = ex03();
  const HarmonicBalance& hb = e.hb;
  const auto hbp = subharmonic_model(hb, 2);
  ASSERT_EQ(hbp->harmonics(), 80);
  ASSERT_EQ(hbp->excitation().harmonic, 2);
  for (std::size_t i : {std::size_t(0), e.c.branch.points.size() / 2}) {
    const BranchPoint& p = e.c.branch.points[i];
    Eigen::VectorXd R1, R;
    hb.evaluate(p.X, p.omega, R1, nullptr, nullptr);
    hbp->evaluate(to_subharmonic_basis(hb, *hbp, 2, p.X), p.omega / 2, R, nullptr, nullptr);
    EXPECT_LT(R.cwiseAbs().maxCoeff(), 1e-9 * e.c.scaling.residual + 10 * R1.cwiseAbs().maxCoeff());
    EXPECT_EQ(subharmonic_part(*hbp, 2, to_subharmonic_basis(hb, *hbp, 2, p.X)).norm(), 0.0);
  }
}

TEST(PeriodDoubling, BilinearBranchEndsAtTheOtherDoublingNotOnThePeriodOneBranch) {
  // The bilinear oscillator x'' + 0.02 x' + x + max(x, 0) = 0.01 cos(omega t) (ch. 3's mass
  // against a wall with gap 0 and c = 0.02, H = 10, omega 0.5-3.5) has four PDs of its period-1
  // orbit (Floquet on the exact flow): 0.7443 and 0.7981, 2.1212 and 2.6436 (about twice its
  // bilinear frequency 2 sqrt(2) / (1 + sqrt(2)) = 1.17). The period-2 branch switched at
  // 2.1212 runs through its subharmonic resonance to 2.6436, where the corrector turns onto the
  // period-1 branch (a solution of the period-2 model too): the branch must end there, at that
  // PD, not go on along the period-1 orbit (before: it merged at omega = 2.746 "where no PD was
  // located", its last points period-1 orbits, and 2.6436 was switched again).
  Eigen::VectorXd one = Eigen::VectorXd::Constant(1, 1.0);
  const LinearSystem s{one.asDiagonal(), 0.02 * one.asDiagonal(), one.asDiagonal()};
  const HarmonicBalance hb(s, {UnilateralContact{one, 1.0, 0.0, {}}},
                           Excitation{Eigen::VectorXd::Zero(1), 0.01 * one, Eigen::VectorXd::Zero(1)}, 10);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 3.5;
  o.stability = StabilityMethod::floquet;
  const FrequencyCurve c = sweep_frequency(hb, o, "bilinear");
  ASSERT_TRUE(c.complete) << c.failure;
  std::vector<std::size_t> pd;
  for (std::size_t k = 0; k < c.bifurcations.size(); ++k)
    if (c.bifurcations[k].type == BifurcationType::period_doubling) pd.push_back(k);
  ASSERT_EQ(pd.size(), 4u);
  const auto br = period_doubled_branches(hb, c, o);
  ASSERT_EQ(br.size(), 2u);   // each branch's end PD is not switched again
  for (const PeriodDoubledBranch& b : br) {
    ASSERT_EQ(b.end, PeriodDoubledBranch::End::merged) << b.why;
    ASSERT_GE(b.to, 0) << b.why;
    EXPECT_NEAR(b.omega_end, c.bifurcations[std::size_t(b.to)].omega, 1e-3) << b.why;
    // the two PDs of one resonance: 0.74-0.80 or 2.12-2.64
    EXPECT_LT(std::fabs(b.omega_end - b.omega_start), 0.6) << b.why;
    // every point between the ends is a period-2 orbit: its odd part well away from zero
    const auto& P = b.curve.branch.points;
    double largest = 0.0;
    for (const auto& p : P) largest = std::max(largest, odd_norm(b, p));
    for (std::size_t k = 1; k + 1 < P.size(); ++k) EXPECT_GT(odd_norm(b, P[k]), 1e-6 * largest) << b.why << ", point " << k;
  }
}

namespace {
// The bilinear oscillator of the test above at H harmonics, swept over 0.5-3.5.
struct BilinearPd {
  HarmonicBalance hb;
  SweepOptions o;
  FrequencyCurve c;
  explicit BilinearPd(int H)
      : hb(LinearSystem{Eigen::MatrixXd::Identity(1, 1), 0.02 * Eigen::MatrixXd::Identity(1, 1),
                        Eigen::MatrixXd::Identity(1, 1)},
           {UnilateralContact{Eigen::VectorXd::Ones(1), 1.0, 0.0, {}}},
           Excitation{Eigen::VectorXd::Zero(1), 0.01 * Eigen::VectorXd::Ones(1), Eigen::VectorXd::Zero(1)}, H) {
    o.omega_min = 0.5;
    o.omega_max = 3.5;
    o.stability = StabilityMethod::floquet;
    c = sweep_frequency(hb, o, "bilinear");
  }
};
}  // namespace

TEST(PeriodDoubling, BilinearBranchEndsAtTheDoublingOnItsChordAtLowHarmonics) {
  // The same oscillator at H = 3. Its PDs are those of the exact orbit (Floquet on the corrected
  // orbit: the model has no gap harmonics, so the exact flow does not depend on H): the same as at
  // H = 10 to 1e-6. The period-2 model's own branch points (where its HB branch meets the
  // period-1 branch) lie beside them by the truncation error, at H = 3 1.6e-3 and 1.4e-3
  // (relative) from 0.74434 and 0.79811: farther than the 1e-3 window the end was matched with
  // before, so the branch from 0.74434 "merged where no PD was located" and 0.79811 was switched
  // again (the same branch walked back). The end is now matched by the chord of the period-1
  // branch where the period-2 branch meets it.
  const BilinearPd ten(10), three(3);
  ASSERT_TRUE(three.c.complete) << three.c.failure;
  std::vector<double> pd3, pd10;
  for (const auto& b : three.c.bifurcations)
    if (b.type == BifurcationType::period_doubling) pd3.push_back(b.omega);
  for (const auto& b : ten.c.bifurcations)
    if (b.type == BifurcationType::period_doubling) pd10.push_back(b.omega);
  ASSERT_EQ(pd3.size(), 4u);
  ASSERT_EQ(pd10.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(pd3[k], pd10[k], 1e-6);
  const auto br = period_doubled_branches(three.hb, three.c, three.o);
  ASSERT_EQ(br.size(), 2u);   // one branch per resonance: each end's PD is not switched again
  for (const PeriodDoubledBranch& b : br) {
    ASSERT_EQ(b.end, PeriodDoubledBranch::End::merged) << b.why;
    ASSERT_GE(b.to, 0) << b.why;
    EXPECT_EQ(b.why.find("no PD"), std::string::npos) << b.why;
    const double w_to = three.c.bifurcations[std::size_t(b.to)].omega;
    EXPECT_LT(std::fabs(b.omega_end - b.omega_start), 0.6) << b.why;   // the two PDs of one resonance
    EXPECT_NEAR(b.omega_end, w_to, 2e-3 * w_to) << b.why;   // the branch point beside that PD
  }
  EXPECT_NEAR(br[0].omega_start, pd10[0], 1e-6);
  EXPECT_NEAR(three.c.bifurcations[std::size_t(br[0].to)].omega, pd10[1], 1e-6) << br[0].why;
}

TEST(PeriodDoubling, GearPairDoublingInTheStepOfANeimarkSackerIsLocatedAndEndsTheBranch) {
  // ch. 6 Fig. 40's gear pair (6 DOF, Fi = 1e5 N m, Fa = 1e4, kc = 5e8 N/m, H = 10, the chapter's
  // sweep). In one continuation step of its period-1 branch, 8959 -> 9189 rad/s, a complex pair
  // of multipliers enters the unit circle (a Neimark-Sacker point at 9072) and a real multiplier
  // leaves it through -1 (measured on the step: -0.955 at 9155, -1.017 at 9167): the number
  // outside goes 2 -> 1, and the sweep located only the first change, so the period-2 branch
  // switched at the next PD (9290) merged at 9164.7 "where no PD was located". Now the PD is
  // located (the parity of the real multipliers below -1 changes on the step), checked against
  // GSL's variational monodromy (rk8pd on the original model, independent of the exact-flow
  // exponentials), and the branch from 9290 ends at it.
  const HarmonicBalance hb = test_models::ch06_gear_pair(1e5);
  const SweepOptions o = test_models::ch06_sweep();
  const FrequencyCurve c = sweep_frequency(hb, o, "fig40");
  ASSERT_TRUE(c.complete) << c.failure;
  int found = -1, next = -1;
  for (std::size_t k = 0; k < c.bifurcations.size(); ++k) {
    const Bifurcation& b = c.bifurcations[k];
    if (b.type != BifurcationType::period_doubling) continue;
    if (b.omega > 9150 && b.omega < 9170) found = int(k);
    if (std::fabs(b.omega - 9290.07) < 0.1) next = int(k);
  }
  ASSERT_GE(found, 0) << "no PD located between 9150 and 9170 rad/s";
  ASSERT_GE(next, 0);
  const Bifurcation& pd = c.bifurcations[std::size_t(found)];
  EXPECT_TRUE(pd.smooth);
  EXPECT_NEAR(pd.multiplier.real(), -1.0, 1e-6);
  // GSL: the most negative real multiplier above -1 just below the PD, below -1 just above it
  const auto& P = c.branch.points;
  const BranchPoint &a = P[std::size_t(pd.after_point)], &z = P[std::size_t(pd.after_point) + 1];
  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.x_scale = c.scaling.x[0];
  for (const double dw : {-3.0, 3.0}) {
    const double t = (pd.omega + dw - a.omega) / (z.omega - a.omega);
    const BranchPoint q = point_on_chord(hb, a, z, c.scaling, t, 1e-9);
    const FloquetResult fl = floquet_of_hb_orbit(hb, q.X, q.omega, c.scaling.x[0]);
    ASSERT_TRUE(fl.corrected) << q.omega;
    const Eigen::VectorXcd mu = general_eigenvalues(ti.monodromy(fl.x0, fl.v0, q.omega, to), "GSL monodromy");
    double most_negative = 0.0;
    for (Eigen::Index i = 0; i < mu.size(); ++i)
      if (std::fabs(mu[i].imag()) < 1e-9) most_negative = std::min(most_negative, mu[i].real());
    if (dw < 0) EXPECT_GT(most_negative, -1.0) << "omega " << q.omega;
    else EXPECT_LT(most_negative, -1.0) << "omega " << q.omega;
  }
  // the period-2 branch switched at 9290 alone ends at the located PD
  FrequencyCurve one = c;
  one.bifurcations.clear();
  for (int k : {found, next}) one.bifurcations.push_back(c.bifurcations[std::size_t(k)]);
  std::swap(one.bifurcations[0], one.bifurcations[1]);   // switch at 9290 first
  const auto br = period_doubled_branches(hb, one, o);
  ASSERT_FALSE(br.empty());
  EXPECT_EQ(br[0].end, PeriodDoubledBranch::End::merged) << br[0].why;
  EXPECT_EQ(br[0].to, 1) << br[0].why;
  EXPECT_NEAR(br[0].omega_end, pd.omega, 5.0) << br[0].why;
}
