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

TEST(FrequencySweep, IncompleteBranchIsAnErrorNamingCaseAndFrequency) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 5);
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 2.0;
  o.continuation.max_steps = 5;   // far too few to cross the range
  try {
    sweep_frequency(hb, o, "my_case");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("my_case"), std::string::npos) << m;
    EXPECT_NE(m.find("step cap"), std::string::npos) << m;
    EXPECT_NE(m.find("omega ="), std::string::npos) << m;
  }
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
  // issue #3 criterion: x_max within 0.5 % of GSL time integration.
  EXPECT_LT(chk.worst_rel_diff, 5e-3);
}
