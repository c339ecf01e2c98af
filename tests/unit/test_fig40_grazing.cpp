// Ch. 6 Fig. 40's grazing region (issue 34 §3): where its bifurcation diagram by time
// integration and the H = 10 harmonic balance disagree, which is right? (The probe over every
// speed: tests/scratch/fig40_probe.cpp; the chapter README, step 3b, says what it found.) The
// model is Fig. 40's gear pair (Fi = 1e5 N m, Fa = 1e4), its H = 10 branch continued as the
// chapter does (2-62 krad/s, ds_max 0.005); the HB orbits at a speed are Newton's solutions
// there from the ends of every branch segment that brackets it. Independent of the HB view:
// the shooting on the exact piecewise-linear flow (floquet.hpp), HB with more harmonics, and
// GSL rk8pd started on the orbit.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/core/newton.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gear_pair_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

const GearPairParameters kGear;
constexpr double kXScale = 1e-5;   // the order of Fig. 40's Delta in this band [m]

HarmonicBalance fig40(int H) { return test_models::ch06_gear_pair(1e5, H); }

// The chapter's H = 10 branch (its continuation settings; no stability: the tests take the
// multipliers themselves).
const FrequencyCurve& fig40_curve() {
  static const HarmonicBalance hb = fig40(10);
  static const FrequencyCurve c = sweep_frequency(hb, test_models::ch06_sweep(StabilityMethod::none), "fig40");
  return c;
}

// Every distinct H = 10 orbit at w (Newton from the ends of each segment bracketing w).
std::vector<VectorXd> hb_orbits_at(const HarmonicBalance& hb, double w) {
  const FrequencyCurve& c = fig40_curve();
  const auto& P = c.branch.points;
  std::vector<VectorXd> out;
  for (std::size_t i = 1; i < P.size(); ++i) {
    if ((P[i - 1].omega - w) * (P[i].omega - w) > 0) continue;
    for (const VectorXd* start : {&P[i].X, &P[i - 1].X}) {
      VectorXd X = *start;
      if (!newton_solve(hb, X, w, c.scaling, {1e-9, 30}).converged) continue;
      bool seen = false;
      for (const VectorXd& Y : out) seen = seen || (Y - X).cwiseAbs().maxCoeff() < 1e-6 * c.scaling.x.maxCoeff();
      if (!seen) out.push_back(X);
      break;
    }
  }
  return out;
}

// The Poincare states (x, v / w rows) of 64 periods after `transient` from (x0, v0).
MatrixXd poincare_states(const HarmonicBalance& hb, const VectorXd& x0, const VectorXd& v0, double w, int transient) {
  TimeIntegrationOptions o;
  o.x_scale = kXScale;
  MatrixXd xs, vs;
  TimeIntegrator(hb).poincare(x0, v0, w, transient, 64, o, xs, vs);
  MatrixXd s(xs.rows(), 12);
  s << xs, vs / w;
  return s;
}

// The orbit's state at phase 0 on the exact flow as rows (x, v / w), for comparisons with poincare_states.
Eigen::RowVectorXd state(const VectorXd& x0, const VectorXd& v0, double w) {
  Eigen::RowVectorXd s(12);
  s << x0.transpose(), v0.transpose() / w;
  return s;
}

// HB with H harmonics from the exact orbit through (x0, v0) (its 256 samples over a period):
// Newton, then its own shooting on the exact flow.
FloquetResult higher_h(int H, const VectorXd& x0, const VectorXd& v0, double w) {
  const HarmonicBalance hb = fig40(H);
  TimeIntegrationOptions o;
  o.x_scale = kXScale;
  o.rel_tol = 1e-12;
  o.abs_tol = 1e-13;
  o.samples_per_period = 256;
  VectorXd X = hb_unknowns_of_samples(hb, TimeIntegrator(hb).sample(x0, v0, w, 0, 1, o));
  const Scaling s = hb.scaling(2000.0, 62000.0);
  EXPECT_TRUE(newton_solve(hb, X, w, s, {1e-9, 40}).converged) << "H = " << H;
  return floquet_of_hb_orbit(hb, X, w, s.x[0]);
}

}  // namespace

// At 8250 rad/s both sweeps of Fig. 40's diagram are chaotic where HB has a stable orbit. Both
// are right: two attractors coexist. The H = 10 orbit's shooting converges to an exact orbit
// with multipliers inside the circle; HB with H = 30 from that exact orbit corrects to the same
// orbit with the same critical multiplier (H = 10's stability is resolved there); GSL rk8pd
// started on the H = 10 orbit stays on the exact orbit (64 Poincare points after 400 periods,
// all within the classifier's 1e-6 of the typical displacement). The integration started on the
// coexisting unstable H = 10 orbit (a Neimark-Sacker-unstable one, |mu| about 1.02) does not
// settle on any period <= 8 within the same periods: the sweeps' attractor, beside the stable
// orbit. (The same holds at 9300 rad/s: tests/scratch/fig40_probe.cpp.)
TEST(Fig40Grazing, StableHbOrbitCoexistsWithTheSweepsNonPeriodicAttractor) {
  const double w = 8250.0;
  const HarmonicBalance hb = fig40(10);
  const double xs = fig40_curve().scaling.x[0];
  int stable = 0, unstable = 0;
  for (const VectorXd& X : hb_orbits_at(hb, w)) {
    const FloquetResult f = floquet_of_hb_orbit(hb, X, w, xs);
    ASSERT_TRUE(f.corrected);
    VectorXd x0, v0;
    hb_initial_state(hb, X, w, x0, v0);
    if (f.modulus < 1.0) {
      ++stable;
      const FloquetResult f30 = higher_h(30, f.x0, f.v0, w);
      ASSERT_TRUE(f30.corrected);
      EXPECT_LE((state(f30.x0, f30.v0, w) - state(f.x0, f.v0, w)).cwiseAbs().maxCoeff(), 1e-9 * kXScale);
      EXPECT_NEAR(f30.modulus, f.modulus, 1e-6);
      const MatrixXd p = poincare_states(hb, x0, v0, w, 400);
      for (int j = 0; j < p.rows(); ++j)
        EXPECT_LE((p.row(j) - state(f.x0, f.v0, w)).cwiseAbs().maxCoeff(), 1e-6 * kXScale) << j;
    } else if (f.modulus < 1.1 && std::abs(f.angle) > 0.1) {   // the Neimark-Sacker-unstable orbit
      ++unstable;
      const MatrixXd p = poincare_states(hb, x0, v0, w, 400);
      EXPECT_EQ(poincare_period(p.leftCols(6), p.rightCols(6) * w, w, 8, 1e-6 * kXScale), 0);
      EXPECT_GT((p.rowwise() - state(f.x0, f.v0, w)).cwiseAbs().maxCoeff(), 1e-3 * kXScale);
    }
  }
  EXPECT_EQ(stable, 1);
  EXPECT_EQ(unstable, 1);
}

// At 7800 rad/s the H = 10 branch is drawn unstable (both ends of its segment flagged so) and
// the diagram's sweeps are period 1 there. The H = 10 flag is not resolved: the shooting from
// the H = 10 orbit does not converge (its multipliers are those of a failed correction). HB
// with H = 14 from the padded H = 10 orbit corrects to an exact orbit with multipliers inside
// the circle, and GSL rk8pd started on the H = 10 orbit settles on that exact orbit (period 1 within
// 1e-6 of the typical displacement after 400 periods): H = 10 is too few harmonics at this
// grazing orbit, and the diagram is right.
TEST(Fig40Grazing, H10InstabilityIsAFailedCorrectionTheOrbitIsStable) {
  const double w = 7800.0;
  const HarmonicBalance hb = fig40(10);
  const std::vector<VectorXd> orbits = hb_orbits_at(hb, w);
  ASSERT_EQ(orbits.size(), 1u);
  const FloquetResult f10 = floquet_of_hb_orbit(hb, orbits[0], w, fig40_curve().scaling.x[0]);
  EXPECT_FALSE(f10.corrected);
  const HarmonicBalance hb14 = fig40(14);
  VectorXd X14 = VectorXd::Zero(hb14.size());
  X14.head(orbits[0].size()) = orbits[0];
  const Scaling s14 = hb14.scaling(2000.0, 62000.0);
  ASSERT_TRUE(newton_solve(hb14, X14, w, s14, {1e-9, 40}).converged);
  const FloquetResult f14 = floquet_of_hb_orbit(hb14, X14, w, s14.x[0]);
  ASSERT_TRUE(f14.corrected);
  EXPECT_LT(f14.modulus, 1.0);
  VectorXd x0, v0;
  hb_initial_state(hb, orbits[0], w, x0, v0);
  const MatrixXd p = poincare_states(hb, x0, v0, w, 400);
  for (int j = 0; j < p.rows(); ++j)
    EXPECT_LE((p.row(j) - state(f14.x0, f14.v0, w)).cwiseAbs().maxCoeff(), 1e-6 * kXScale) << j;
}
