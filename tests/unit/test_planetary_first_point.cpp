// The first point of a planetary sweep inside a range of contact loss (hb/first_point.hpp
// step 4, the continuation in the depth of the mesh-stiffness variation): the loaded
// Lin-Parker example (programs/gearhb_planetary/examples/lin_parker_1999_loaded.json) cannot
// start at 1500 Hz from a linear guess or a contact set, and has no external forcing for the
// amplitude continuation. Its independent check is the same example's curve continued in
// frequency from 300 Hz, where the linear guess starts it: at 1500 Hz that curve has one
// point (the curve is single-valued there), and the first point found at 1500 Hz must be it.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "gearhb/hb/first_point.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/tools/planetary_file.hpp"

using namespace gearhb;

TEST(PlanetaryFirstPoint, StiffnessContinuationStartsInsideContactLossOnTheContinuedCurve) {
  const PlanetaryFile f =
      read_planetary_file(std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/lin_parker_1999_loaded.json", {});
  const HarmonicBalance hb = planetary_response_model(f);
  const double omega = 2.0 * M_PI * 1500.0;
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 300.0;
  o.omega_max = omega;
  o.stability = StabilityMethod::none;
  const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "to 1500 Hz"), "to 1500 Hz");
  ASSERT_EQ(c.first_point, FirstPointMethod::linear_guess);
  int crossings = 0;   // steps of the curve that bracket 1500 Hz: one (its end point) where single-valued
  for (std::size_t i = 1; i < c.branch.points.size(); ++i)
    crossings += (c.branch.points[i - 1].omega - omega) * (c.branch.points[i].omega - omega) <= 0.0 ? 1 : 0;
  ASSERT_EQ(crossings, 1);
  const BranchPoint& end = c.branch.points.back();
  ASSERT_DOUBLE_EQ(end.omega, omega);
  const FirstPoint fp = find_first_point(hb, omega, c.scaling);
  ASSERT_TRUE(fp.found) << fp.failure;
  EXPECT_EQ(fp.method, FirstPointMethod::stiffness_continuation);
  // the orbit loses contact there (some drive flank's penetration goes negative)
  const Aft aft(hb.harmonics());
  double lowest = INFINITY;
  for (std::size_t i = 0; i < hb.contacts().size(); ++i) lowest = std::min(lowest, aft.to_time(hb.penetration(fp.X, i)).minCoeff());
  EXPECT_LT(lowest, 0.0);
  // both converged to Newton's 1e-10: the same solution to far below its size
  EXPECT_LT((fp.X - end.X).cwiseAbs().maxCoeff(), 1e-6 * end.X.cwiseAbs().maxCoeff());
}
