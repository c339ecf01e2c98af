// The step "orbit -> HB branch" (hb/orbit_branch.hpp) on a small system with two coexisting
// stable period-1 orbits known independently: the one-sided clearance oscillator
//   x'' + 0.1 x' + x + 4 max(x - 1, 0) = 0.5 cos(omega t)
// (a hardening contact: its resonance leans right between two folds). At omega = OMEGA the time
// integration (GSL rk8pd, contact switches located) settles from rest on one orbit and from
// x = 4 on another (their swings checked apart here: from rest the large one). The step, started from either orbit:
//  - its HB point matches the integrated orbit within HB's own error bound (checked inside the
//    step, and here again against integrations at two other speeds on the branch);
//  - its Floquet stability at the start agrees with the integration (both orbits attract);
//  - the branch from the large orbit, continued through the folds, passes the small orbit too
//    (distance_to_branch within the bound): one S-shaped curve, as the sweep finds it, whose
//    folds it reproduces (the full sweep_frequency curve, a second continuation from the
//    linear guess);
//  - off_every_branch: against the natural continuation down from omega_max (it stops at the
//    lower fold, so it holds the small orbit only) the large orbit is off every branch and the
//    small one is not.
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/orbit_branch.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

const double OMEGA = 1.26;

HarmonicBalance one_sided(int H = 12) { return test_models::one_sided_clearance(H); }

SweepOptions range() { return test_models::one_sided_clearance_range(); }

// The periodic orbit reached from x(0) = x_start, v(0) = 0 (its state at phase 0).
SteadyState settle(const HarmonicBalance& hb, double x_start, double omega) {
  TimeIntegrationOptions to;
  to.x_scale = 1.0;
  return TimeIntegrator(hb).steady_state(VectorXd::Constant(1, x_start), VectorXd::Zero(1), omega, to);
}

double swing(const SteadyState& s) { return s.x.maxCoeff() - s.x.minCoeff(); }

// The two orbits at OMEGA, the small one first.
std::pair<SteadyState, SteadyState> two_orbits(const HarmonicBalance& hb) {
  SteadyState a = settle(hb, 0.0, OMEGA), b = settle(hb, 4.0, OMEGA);
  if (swing(a) > swing(b)) std::swap(a, b);
  return {a, b};
}

}  // namespace

TEST(OrbitBranch, TwoCoexistingOrbitsOfAClearanceOscillator) {
  const HarmonicBalance hb = one_sided();
  const auto [low, high] = two_orbits(hb);
  ASSERT_TRUE(low.converged && high.converged);
  ASSERT_GT(swing(high), 1.5 * swing(low));   // two orbits, not one
  const SweepOptions opt = range();
  const OrbitBranch bh = branch_from_orbit(hb, high.x0, high.v0, OMEGA, 1, opt);
  const OrbitBranch bl = branch_from_orbit(hb, low.x0, low.v0, OMEGA, 1, opt);
  ASSERT_TRUE(bh.ok) << bh.why;
  ASSERT_TRUE(bl.ok) << bl.why;
  EXPECT_LE(bh.distance, bh.bound);
  EXPECT_TRUE(bh.curve.stable[std::size_t(bh.start)]);
  EXPECT_TRUE(bl.curve.stable[std::size_t(bl.start)]);
  EXPECT_TRUE(bh.curve.complete) << bh.why;
  // the branch from the large orbit passes the small one
  const BranchView vh{bh.model.get(), &bh.curve, 1};
  MatrixXd xs = low.x0.transpose();
  const BranchDistance d = distance_to_branch(vh, xs, 1, OMEGA);
  EXPECT_LE(d.distance, d.bound + 1e-6) << d.distance << " " << d.bound;
  // its folds are the sweep's
  const FrequencyCurve full = sweep_frequency(hb, opt, "one-sided");
  ASSERT_EQ(full.branch.folds.size(), 2u);
  ASSERT_EQ(bh.curve.branch.folds.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    double nearest = INFINITY;
    for (const Fold& f : bh.curve.branch.folds) nearest = std::min(nearest, std::fabs(f.omega - full.branch.folds[std::size_t(k)].omega));
    EXPECT_LT(nearest, 1e-6) << k;
  }
}

TEST(OrbitBranch, BranchPointsAgreeWithTimeIntegrationAtAnotherSpeed) {
  const HarmonicBalance hb = one_sided();
  const SteadyState high = two_orbits(hb).second;
  const OrbitBranch b = branch_from_orbit(hb, high.x0, high.v0, OMEGA, 1, range());
  ASSERT_TRUE(b.ok) << b.why;
  // a stable point of the upper stretch at another speed: integrate from its own HB state
  const auto& P = b.curve.branch.points;
  int checked = 0;
  for (std::size_t i = 0; i < P.size() && checked < 2; ++i) {
    if (!b.curve.stable[i] || std::fabs(P[i].omega - OMEGA) < 0.05 || P[i].omega > OMEGA + 0.15 || P[i].omega < OMEGA - 0.3) continue;
    VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const SteadyState s = TimeIntegrator(hb).steady_state(x0 * 1.01, v0, P[i].omega, TimeIntegrationOptions{});
    ASSERT_TRUE(s.converged);
    // the integration settles on the branch point's orbit: on its shooting-corrected state, and on
    // the HB state within HB's own error there
    const double hb_error = std::fabs(b.curve.floquet[i].x0[0] - x0[0]);
    EXPECT_LE(std::fabs(s.x0[0] - b.curve.floquet[i].x0[0]), 1e-6) << P[i].omega;
    EXPECT_LE(std::fabs(s.x0[0] - x0[0]), hb_error + 1e-6) << P[i].omega;
    EXPECT_LT(hb_error, 1e-2) << P[i].omega;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(OrbitBranch, OffEveryBranchAgainstTheNaturalCurveDown) {
  const HarmonicBalance hb = one_sided();
  SweepOptions o = range();
  o.natural = true;
  o.direction = SweepDirection::down;
  o.continuation.natural_points = 250;
  const FrequencyCurve down = sweep_frequency(hb, o, "down");
  ASSERT_GT(down.branch.points.back().omega, 1.0);
  ASSERT_LT(down.branch.points.back().omega, OMEGA);   // stopped at the lower fold, below OMEGA
  const std::vector<BranchView> views{{&hb, &down, 1}};
  auto point = [&](const SteadyState& s) {
    DiagramPoint p;
    p.omega = OMEGA;
    p.motion = Motion::periodic;
    p.n = 1;
    p.x = s.x0.transpose();
    p.v = s.v0.transpose();
    return p;
  };
  const auto [low, high] = two_orbits(hb);
  EXPECT_TRUE(off_every_branch(point(high), views, 1e-6));
  EXPECT_FALSE(off_every_branch(point(low), views, 1e-6));
}

TEST(OrbitBranch, FailureSaysWhy) {
  const HarmonicBalance hb = one_sided();
  const OrbitBranch b = branch_from_orbit(hb, VectorXd::Zero(1), VectorXd::Zero(1), OMEGA, 3, range());
  EXPECT_FALSE(b.ok);
  EXPECT_NE(b.why.find("period must be 1 or 2"), std::string::npos) << b.why;
  // a state not on a periodic orbit (a transient): Newton fails or lands off it, said at omega
  const OrbitBranch c = branch_from_orbit(hb, VectorXd::Constant(1, 4.0), VectorXd::Zero(1), OMEGA, 1, range());
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.why.find("at omega = 1.26: failed: "), std::string::npos) << c.why;
}

// Period 2: the Kahraman & Singh clearance oscillator at F_a = 0.5 (test_bifurcation_diagram.cpp),
// x'' + 0.1 x' + f(x) = 0.1 + 0.5 cos(Omega t), f the dead zone of half-width 1. At Omega = OMEGA2
// the time integration settles on a period-2 orbit (its Poincare points repeat after two forcing
// periods, not one: checked here); the step on the period-2 model (H2 = 40) matches it within
// HB's own error, finds it stable, and continues a branch of period 2 through it that, going up,
// meets the period-1 branch within 1e-3 of the period doubling the period-1 sweep locates there
// (measured 1.6e-4: the end is the first point past the crossing, not refined).
TEST(OrbitBranch, PeriodTwoOrbitOfTheKahramanSinghOscillator) {
  const double OMEGA2 = 1.85;
  const HarmonicBalance hb = test_models::kahraman_singh(0.5);
  MatrixXd xs, vs;
  TimeIntegrationOptions to;
  to.rel_tol = 1e-12;
  to.abs_tol = 1e-13;
  TimeIntegrator(hb).poincare(VectorXd::Constant(1, 0.9), VectorXd::Zero(1), OMEGA2, 2000, 4, to, xs, vs);
  ASSERT_LT(std::fabs(xs(2, 0) - xs(0, 0)) + std::fabs(xs(4, 0) - xs(2, 0)), 1e-7);   // period 2 ...
  ASSERT_GT(std::fabs(xs(1, 0) - xs(0, 0)), 1e-3);                                       // ... not 1
  SweepOptions o;
  o.omega_min = 1.7;
  o.omega_max = 2.0;
  const OrbitBranch b = branch_from_orbit(hb, xs.row(0).transpose(), vs.row(0).transpose(), OMEGA2, 2, o);
  ASSERT_TRUE(b.ok) << b.why;
  EXPECT_EQ(b.period, 2);
  EXPECT_LE(b.distance, b.bound);
  EXPECT_TRUE(b.curve.stable[std::size_t(b.start)]);
  EXPECT_GT(b.curve.branch.points.size(), 10u) << b.why;
  // up, it meets the period-1 branch at its period doubling (the period-1 sweep's, located by Floquet)
  ASSERT_NE(b.why.find("up: meets the period-1 branch"), std::string::npos) << b.why;
  const FrequencyCurve c = sweep_frequency(hb, o, "Kahraman-Singh");
  double nearest = INFINITY;
  const double met = 2.0 * b.curve.branch.points.back().omega;
  for (const Bifurcation& f : c.bifurcations)
    if (f.type == BifurcationType::period_doubling) nearest = std::min(nearest, std::fabs(f.omega - met));
  EXPECT_LT(nearest, 1e-3) << met;
}
