// Unit tests of lib/frequency_sweep: the first guess, the failure report, and the
// selection rules of the time-integration check (ch. 3 mass against a wall).
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "test_models.hpp"

using namespace gearhb;

TEST(FrequencySweep, FirstGuessIsTheExactLinearSolutionWhenOneApplies) {
  // g = +1 m (preload), F = 0.01 N at 0.5 rad/s: full contact, so the closed-contact
  // linear solution is exact (residual at round-off); g = -1.2 m: open, likewise.
  Eigen::VectorXd R;
  for (double gap : {1.0, -1.2}) {
    HarmonicBalance hb = test_models::mass_wall(gap, 5);
    const Eigen::VectorXd X = linear_first_guess(hb, 0.5);
    hb.evaluate(X, 0.5, R, nullptr, nullptr);
    EXPECT_LT(R.cwiseAbs().maxCoeff(), 1e-14) << "gap " << gap;
    const Eigen::VectorXd exact = gap > 0 ? hb.closed_contact_solution(0.5) : hb.open_contact_solution(0.5);
    EXPECT_LT((X - exact).cwiseAbs().maxCoeff(), 1e-15) << "gap " << gap;
  }
}

TEST(FrequencySweep, IncompleteBranchKeepsItsPointsAndNamesCaseAndFrequency) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 5);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 2.0;
  o.continuation.max_steps = 5;   // far too few to cross the range
  const FrequencyCurve c = sweep_frequency(hb, o, "my_case");
  EXPECT_FALSE(c.complete);
  EXPECT_EQ(c.branch.points.size(), 6u);   // the first point and the five steps
  EXPECT_EQ(c.stable.size(), c.branch.points.size());
  for (const char* part : {"my_case", "step cap", "omega =", "residual", "step", "hint"})
    EXPECT_NE(c.failure.find(part), std::string::npos) << part << " not in: " << c.failure;
  // callers that need the whole range get an error with the same information
  try {
    require_complete(c, "my_case");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), c.failure);
  }
}

TEST(FrequencySweep, DownwardSweepFindsTheSameFoldsAndReportsProgress) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 2.0;
  const FrequencyCurve up = sweep_frequency(hb, o, "up");
  o.direction = SweepDirection::down;
  std::vector<ContinuationProgress> seen;
  o.continuation.progress = [&](const ContinuationProgress& p) { seen.push_back(p); };
  const FrequencyCurve down = sweep_frequency(hb, o, "down");
  ASSERT_TRUE(up.complete && down.complete);
  EXPECT_DOUBLE_EQ(down.branch.points.front().omega, 2.0);
  EXPECT_DOUBLE_EQ(down.branch.points.back().omega, 0.5);
  ASSERT_EQ(up.branch.folds.size(), 2u);
  ASSERT_EQ(down.branch.folds.size(), 2u);
  // the same two folds, met in the opposite order (both located to round-off)
  EXPECT_NEAR(up.branch.folds[0].omega, down.branch.folds[1].omega, 1e-8);
  EXPECT_NEAR(up.branch.folds[1].omega, down.branch.folds[0].omega, 1e-8);
  // one progress report per accepted point, in order (the end point is a Newton
  // re-solve of the last accepted step and is not reported separately)
  ASSERT_GE(seen.size(), down.branch.points.size() - 1);
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].point, int(i));
}

TEST(FrequencySweep, TimeIntegrationCheckPicksStableIntermittentPointsAwayFromFolds) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 10);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 2.0;
  const FrequencyCurve c = sweep_frequency(hb, o, "g-0.6");
  ASSERT_EQ(c.branch.folds.size(), 2u);
  TimeIntegrationCheckOptions to;
  to.points = 6;
  const TimeIntegrationCheck chk = compare_with_time_integration(hb, c, Eigen::VectorXd::Constant(1, 1.0), to);
  EXPECT_EQ(chk.points, 6);
  EXPECT_EQ(chk.rows.size(), 6u);
  // The chapters' criterion (README "Reference files and tests"): x_max within 0.5 % of GSL time integration.
  EXPECT_LT(chk.worst_rel_diff, 5e-3);
}

// Every contact counts in the sweep's contact regime (issue 23: it stopped at 15 contacts,
// so a model with 16-30 lost the grazing step control on the others). One DOF against 25
// stops at 0.1, 0.2, ..., 2.5: at x = 2.05 stops 1-20 are closed, at x = 2.15 also stop 21
// (index 20); the two regimes differ only there. 31 contacts are refused.
TEST(FrequencySweep, ContactRegimeSeesEveryContact) {
  const LinearSystem s{Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Constant(1, 1, 0.01), Eigen::MatrixXd::Ones(1, 1)};
  std::vector<UnilateralContact> stops;
  for (int i = 0; i < 25; ++i) stops.push_back({Eigen::VectorXd::Ones(1), 1.0, -0.1 * (i + 1), {}, {}});
  const Excitation f{Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.1), Eigen::VectorXd::Zero(1)};
  const HarmonicBalance hb(s, stops, f, 3);
  const auto regime = contact_regime(hb);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(hb.size()), b = a;
  a[0] = 2.05;
  b[0] = 2.15;
  const std::uint64_t ra = regime(a), rb = regime(b);
  EXPECT_NE(ra, rb);
  EXPECT_EQ(ra ^ rb, std::uint64_t(1) << 40) << "only contact 20 differs: open (0) at 2.05, full (1) at 2.15";
  stops.resize(31, stops.front());
  EXPECT_THROW(HarmonicBalance(s, stops, f, 3), std::invalid_argument);
}
