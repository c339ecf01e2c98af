// The bifurcation diagram by time integration (hb/bifurcation_diagram.hpp, issue 34 §3) on
// the Kahraman & Singh (1990) clearance oscillator at F_a = 0.5 (test_clearance_oscillator.cpp
// describes the model): x'' + 0.1 x' + f(x) = 0.1 + 0.5 cos(Omega t), f the dead zone of
// half-width 1. Explored with the diagram over 0.3..2 (gearhb_frc, 35 and 100 speeds): period 1
// up to Omega = 0.85 (two coexisting orbits at 0.3..0.37), period 2 beside HB's period doublings
// (0.35..0.40, 1.78..1.92), chaos from 0.9 to 1.75 with a period-3 window at 1.25 (both
// sweeps), period 1 again from 1.95. Independent facts checked:
//  - where HB's period-1 branch is stable, the diagram says period 1 and its Poincare value is
//    the HB orbit's x at phase 0;
//  - the period-3 orbit at Omega = 1.25 is a fixed point of the three-period map, found by
//    Newton shooting from the classifier's point (a method the classifier does not use), not a
//    fixed point of the one-period map, and attracting (its multipliers inside the unit circle);
//  - the chaos at Omega = 1.0: the Lyapunov exponent is converged in the number of periods and
//    matches the growth rate of the separation of two nearby trajectories of the nonlinear flow
//    alone (no variational equations).
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gear_pair_models.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

using test_models::kahraman_singh;

// The state (x, v) after `periods` forcing periods from (x, v) at phase 0, and the product of
// the period maps' monodromy matrices (variational equations), at tight tolerances.
void map_periods(const TimeIntegrator& ti, double omega, int periods, VectorXd& x, VectorXd& v, MatrixXd& M) {
  TimeIntegrationOptions to;
  to.rel_tol = 1e-12;
  to.abs_tol = 1e-13;
  M = MatrixXd::Identity(2 * x.size(), 2 * x.size());
  for (int k = 0; k < periods; ++k) {
    VectorXd xT, vT;
    MatrixXd Phi;
    ti.period_map(x, v, omega, to, xT, vT, Phi);
    M = Phi * M;
    x = xT, v = vT;
  }
}

// HB's period-1 curve of the oscillator over Omega = 0.3 .. 2 (default sweep options).
FrequencyCurve curve_0_3_to_2(const HarmonicBalance& hb) {
  SweepOptions so;
  so.omega_min = 0.3;
  so.omega_max = 2.0;
  return sweep_frequency(hb, so, "clearance oscillator F_a 0.5");
}

}  // namespace

// HB's stable period-1 orbits (H = 20) under the Poincare points, Omega = 0.45 .. 0.85 in steps
// of 0.05, both sweeps. Tolerance 2e-4 (gap units): HB's truncation at H = 20 - over this
// stretch gearhb_frc's frc.csv of this model has hb_orbit_error up to 1.2e-4 and x_max, x_min
// within 3.7e-5 of the exact orbit's (measured differences here: up to 4.1e-5) - while a
// different orbit or a period-2 split would be off by 0.1 or more.
TEST(BifurcationDiagram, StablePeriod1HbOrbitLiesOnThePoincarePoints) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const FrequencyCurve c = curve_0_3_to_2(hb);
  ASSERT_TRUE(c.complete) << c.failure;
  // The HB orbits at omega, stable at both ends of the branch segment bracketing omega, each
  // solved at omega exactly: their x at phase 0.
  auto stable_hb = [&](double w) {
    std::vector<double> xs;
    const auto& P = c.branch.points;
    for (std::size_t i = 1; i < P.size(); ++i) {
      if ((P[i - 1].omega - w) * (P[i].omega - w) > 0 || !c.stable[i - 1] || !c.stable[i]) continue;
      VectorXd X = P[i].X;
      if (!newton_solve(hb, X, w, c.scaling).converged) continue;
      VectorXd x0, v0;
      hb_initial_state(hb, X, w, x0, v0);
      xs.push_back(x0[0]);
    }
    return xs;
  };
  const std::vector<double> start = stable_hb(0.45);
  ASSERT_EQ(start.size(), 1u);
  BifurcationDiagramOptions o;
  o.speeds = 9;
  VectorXd x0, v0;
  {
    const auto& P = c.branch.points;
    std::size_t best = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (c.stable[i] && std::fabs(P[i].omega - 0.45) < std::fabs(P[best].omega - 0.45)) best = i;
    hb_initial_state(hb, P[best].X, P[best].omega, x0, v0);
  }
  const BifurcationDiagram one_thread = bifurcation_diagram(hb, 0.45, 0.85, x0, v0, o);
  // Again with the down sweep from HB's stable orbit at 0.85 (two threads): the up sweep is the
  // one-thread run's, bit for bit (the threads share nothing), and both views agree as before.
  {
    const auto& P = c.branch.points;
    std::size_t top = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (c.stable[i] && std::fabs(P[i].omega - 0.85) < std::fabs(P[top].omega - 0.85)) top = i;
    hb_initial_state(hb, P[top].X, P[top].omega, o.down_x0, o.down_v0);
  }
  const BifurcationDiagram two_threads = bifurcation_diagram(hb, 0.45, 0.85, x0, v0, o);
  for (const BifurcationDiagram* d : {&one_thread, &two_threads}) {
    ASSERT_EQ(d->points.size(), 18u);
    int compared = 0;
    for (const DiagramPoint& p : d->points) {
      const std::vector<double> hb_x = stable_hb(p.omega);
      if (hb_x.empty()) continue;
      const std::string at = "Omega = " + std::to_string(p.omega) + (p.up ? " up" : " down");
      EXPECT_EQ(p.motion, Motion::periodic) << at;
      EXPECT_EQ(p.n, 1) << at;
      double nearest = INFINITY;
      for (double x : hb_x) nearest = std::min(nearest, std::fabs(x - p.x(0, 0)));
      EXPECT_LT(nearest, 2e-4) << at << ": Poincare x " << p.x(0, 0);
      ++compared;
    }
    EXPECT_GE(compared, 16) << "the stable period-1 branch spans the range";
  }
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_TRUE(one_thread.points[k].up && two_threads.points[k].up);
    EXPECT_EQ(one_thread.points[k].x, two_threads.points[k].x) << "up sweep, speed " << k;
  }
  for (std::size_t k = 9; k < 18; ++k) EXPECT_FALSE(two_threads.points[k].up);
  EXPECT_DOUBLE_EQ(two_threads.points[9].omega, 0.85);
}

// The period-3 window at Omega = 1.25, reached from the chaos at 1.2 (sweep up) and at 1.3
// (sweep down): the classifier's points repeat every 3 periods within period_tol = 1e-6. Newton
// shooting on the three-period map from the classifier's point converges to a fixed point within
// 1e-6 of it (to 1e-10, integration accuracy); the one-period map moves it by more than 0.1 (a
// genuine period 3) and the three-period monodromy's multipliers lie inside the unit circle.
TEST(BifurcationDiagram, KahramanSinghPeriod3IsAFixedPointOfTheThreePeriodMap) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const TimeIntegrator ti(hb);
  BifurcationDiagramOptions o;
  o.speeds = 2;
  const VectorXd rest_x = VectorXd::Constant(1, 1.1), rest_v = VectorXd::Zero(1);
  for (const auto& [lo, hi, index] : {std::make_tuple(1.2, 1.25, 1), std::make_tuple(1.25, 1.3, 3)}) {
    const BifurcationDiagram d = bifurcation_diagram(hb, lo, hi, rest_x, rest_v, o);
    const DiagramPoint& p = d.points[std::size_t(index)];
    ASSERT_NEAR(p.omega, 1.25, 1e-12);
    ASSERT_EQ(p.motion, Motion::periodic) << to_string(p.motion) << " lambda " << p.lyapunov;
    ASSERT_EQ(p.n, 3);
    const VectorXd S0 = (VectorXd(2) << p.x(0, 0), p.v(0, 0)).finished();
    VectorXd S = S0, F(2);
    MatrixXd M;
    for (int it = 0; it < 20; ++it) {
      VectorXd x = S.head(1), v = S.tail(1);
      map_periods(ti, 1.25, 3, x, v, M);
      F << x[0] - S[0], v[0] - S[1];
      if (F.norm() < 1e-10) break;
      S -= (M - MatrixXd::Identity(2, 2)).partialPivLu().solve(F);
    }
    EXPECT_LT(F.norm(), 1e-10) << "Newton shooting on the three-period map";
    EXPECT_LT((S - S0).norm(), 1e-6) << "the classifier's point is the fixed point";
    VectorXd x1 = S.head(1), v1 = S.tail(1);
    MatrixXd M1;
    map_periods(ti, 1.25, 1, x1, v1, M1);
    EXPECT_GT(std::hypot(x1[0] - S[0], v1[0] - S[1]), 0.1) << "not a fixed point of the one-period map";
    const Eigen::VectorXcd mu = M.eigenvalues();
    for (Eigen::Index k = 0; k < mu.size(); ++k) EXPECT_LT(std::abs(mu[k]), 1.0) << "multiplier " << mu[k];
  }
}

// Chaos at Omega = 1.0 (reached from rest through 0.95): the diagram says chaotic, its
// exponent (200 periods) agrees with 800 periods from the final state within 0.05 (the estimate
// over 100 .. 1600 periods was measured to scatter by 0.02 about 0.70 per period), and two
// trajectories of the flow alone, 1e-9 apart at 10 points of the attractor, separate to 1e-3 at
// a mean rate within 25 % of it (the rates scatter 0.54 .. 0.78: a perturbation takes a period
// or two to turn into the unstable direction, so the rate reads low).
TEST(BifurcationDiagram, KahramanSinghChaosHasAConvergedPositiveLyapunovExponent) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const TimeIntegrator ti(hb);
  BifurcationDiagramOptions o;
  o.speeds = 2;
  const BifurcationDiagram d = bifurcation_diagram(hb, 0.95, 1.0, VectorXd::Constant(1, 1.1), VectorXd::Zero(1), o);
  const DiagramPoint& p = d.points[1];
  ASSERT_EQ(p.motion, Motion::chaotic);
  const double lambda = p.lyapunov;
  EXPECT_GT(lambda, 0.3);
  const TimeIntegrationOptions to;
  const VectorXd x = p.x.bottomRows(1).transpose(), v = p.v.bottomRows(1).transpose();
  EXPECT_NEAR(largest_lyapunov_exponent(ti, x, v, 1.0, 800, to), lambda, 0.05);
  MatrixXd xs, vs;
  ti.poincare(x, v, 1.0, 0, 50, to, xs, vs);
  double rate_sum = 0.0;
  for (int s = 0; s < 10; ++s) {
    const VectorXd xa = xs.row(5 * s).transpose(), va = vs.row(5 * s).transpose();
    VectorXd xb = xa;
    xb[0] += 1e-9;
    MatrixXd A, Av, B, Bv;
    ti.poincare(xa, va, 1.0, 0, 60, to, A, Av);
    ti.poincare(xb, va, 1.0, 0, 60, to, B, Bv);
    int k = 1;
    double sep = 0.0;
    for (; k <= 60; ++k) {
      sep = std::max(std::fabs(A(k, 0) - B(k, 0)), std::fabs(Av(k, 0) - Bv(k, 0)));
      if (sep > 1e-3) break;
    }
    ASSERT_LE(k, 60) << "no separation to 1e-3 in 60 periods from start " << s;
    rate_sum += std::log(sep / 1e-9) / k;
  }
  EXPECT_NEAR(rate_sum / 10.0, lambda, 0.25 * lambda);
}

// The sequential stop (BifurcationDiagramOptions::lyapunov_min_periods = 50) on the chaos at
// Omega = 1.0: the estimate stops before its 200 periods, and what the stop claims holds: the
// fixed-length estimate over 800 periods from the same state is above the threshold too (the
// same class); with lyapunov_min_periods = 0 (off) it runs all 200.
TEST(BifurcationDiagram, SequentialLyapunovStopOnlyWhereClearlyChaotic) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const TimeIntegrator ti(hb);
  BifurcationDiagramOptions o;
  o.speeds = 2;
  o.lyapunov_min_periods = 50;
  const BifurcationDiagram d = bifurcation_diagram(hb, 0.95, 1.0, VectorXd::Constant(1, 1.1), VectorXd::Zero(1), o);
  const DiagramPoint& p = d.points[1];
  ASSERT_EQ(p.motion, Motion::chaotic);
  EXPECT_LT(p.lyapunov_periods, o.lyapunov_periods);
  EXPECT_GE(p.lyapunov_periods, o.lyapunov_min_periods);
  const VectorXd x = p.x.bottomRows(1).transpose(), v = p.v.bottomRows(1).transpose();
  EXPECT_GT(p.lyapunov, o.lyapunov_threshold);
  EXPECT_GT(largest_lyapunov_exponent(ti, x, v, 1.0, 800, TimeIntegrationOptions{}), o.lyapunov_threshold);
  o.lyapunov_min_periods = 0;
  const BifurcationDiagram full = bifurcation_diagram(hb, 0.95, 1.0, VectorXd::Constant(1, 1.1), VectorXd::Zero(1), o);
  EXPECT_EQ(full.points[1].lyapunov_periods, o.lyapunov_periods);
}

// The exponents by re-orthonormalisation (lyapunov_exponents) against Liouville's formula: the
// contact force depends on x alone and is continuous, so the divergence of the flow is
// -tr(M^-1 C) in every contact state and det Phi = exp(-tr(M^-1 C) T) over each period, exactly;
// the sum of all 2n exponents per period (the log of the volume growth) must be -tr(M^-1 C) T
// whatever the orbit (here chaotic, Kahraman-Singh at Omega = 1.0: -0.1 x 2 pi). The second
// is below the first.
TEST(BifurcationDiagram, LyapunovExponentsSumToTheVolumeContraction) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const TimeIntegrator ti(hb);
  const TimeIntegrationOptions to;
  const VectorXd x0 = VectorXd::Constant(1, 1.1), v0 = VectorXd::Zero(1);
  VectorXd x, v;
  largest_lyapunov_exponent(ti, x0, v0, 1.0, 100, to, &x, &v);   // onto the chaotic attractor
  const std::vector<double> l = lyapunov_exponents(ti, x, v, 1.0, 200, 2, to);
  EXPECT_NEAR(l[0] + l[1], -0.1 * 2.0 * M_PI, 1e-6);
  // The largest alone (one tangent vector) is another integration: the tangent columns enter
  // GSL's step control, so its orbit parts from this one at round-off and its finite-time
  // estimate is another sample of the same exponent; both must say chaos.
  EXPECT_GT(largest_lyapunov_exponent(ti, x, v, 1.0, 200, to), 0.3);
  EXPECT_GT(l[0], 0.3);
  EXPECT_LT(l[1], l[0]);
}

// The classifier's period test on made-up Poincare sequences: a 2-cycle is period 2 (not 1),
// a sequence that never repeats (an irrational rotation) is period 0.
TEST(BifurcationDiagram, PoincarePeriodOfKnownSequences) {
  MatrixXd x(17, 1), v = MatrixXd::Zero(17, 1), r(17, 1);
  for (int j = 0; j < 17; ++j) x(j, 0) = j % 2 ? 1.0 : -1.0, r(j, 0) = std::cos(j * std::sqrt(2.0));
  EXPECT_EQ(poincare_period(x, v, 1.0, 8, 1e-6), 2);
  EXPECT_EQ(poincare_period(r, v, 1.0, 8, 1e-6), 0);
  x(16, 0) += 1e-3;   // the last point off the cycle
  EXPECT_EQ(poincare_period(x, v, 1.0, 8, 1e-6), 0);
}

// Ch. 6 draws Fig. 45's diagram as Fig. 43's times 100 (the pair with zero gap is homogeneous
// in the loads: (Fi, Fa) x c gives every orbit x c). Checked by integrating both: Fig. 43's
// and Fig. 45's loads over 10.0-10.4 krad/s (HB's period-1 orbit stable there, chapter key
// numbers), from rest and from the closed-mesh static deflection times the ratio: every speed
// of both sweeps is period 1 in both, with the Poincare states 100 times apart within
// period_tol (1e-6 of x_scale, the classifier's own resolution).
TEST(BifurcationDiagram, GearPairDiagramScalesWithTheLoads) {
  const GearPairParameters g;
  auto model = [&](double c) {
    Eigen::VectorXd F(6);
    F << 1e4, 0.0, 1e4, 1e4, 0.0, 1e4;
    return HarmonicBalance(gear_pair_system(g), {gear_pair_mesh(g)},
                           Excitation{gear_pair_static_torque(g, -1e6 * c), c * F, VectorXd::Zero(6)}, 10);
  };
  const HarmonicBalance hb1 = model(1.0), hb100 = model(100.0);
  const MatrixXd Kc = gear_pair_support_stiffness(g) + gear_pair_mesh_stiffness(g);
  const VectorXd x1 = Kc.ldlt().solve(gear_pair_static_torque(g, -1e6)), v = VectorXd::Zero(6);
  BifurcationDiagramOptions o;
  o.speeds = 2;
  o.integration.x_scale = 1e-5;   // the order of Fig. 43's Delta
  const BifurcationDiagram d1 = bifurcation_diagram(hb1, 10000.0, 10400.0, x1, v, o);
  o.integration.x_scale *= 100.0;
  const BifurcationDiagram d100 = bifurcation_diagram(hb100, 10000.0, 10400.0, 100.0 * x1, v, o);
  ASSERT_EQ(d1.points.size(), d100.points.size());
  for (std::size_t k = 0; k < d1.points.size(); ++k) {
    const DiagramPoint &a = d1.points[k], &b = d100.points[k];
    ASSERT_EQ(a.motion, Motion::periodic) << k;
    ASSERT_EQ(b.motion, Motion::periodic) << k;
    EXPECT_EQ(a.n, 1);
    EXPECT_EQ(b.n, 1);
    EXPECT_LE((b.x.row(0) - 100.0 * a.x.row(0)).cwiseAbs().maxCoeff(), o.period_tol * o.integration.x_scale) << k;
    EXPECT_LE((b.v.row(0) - 100.0 * a.v.row(0)).cwiseAbs().maxCoeff() / a.omega, o.period_tol * o.integration.x_scale) << k;
  }
}

// What Fig. 41's diagram found (ch. 6 README): over 13.6-13.85 krad/s the time integration sits
// on a period-1 orbit far larger than any point of the continued curve (Delta_min about -2.9 mm;
// the continued period-1 curve reaches -0.95 mm at most, its period-2 branches -1.28 mm,
// frc_fig41.csv). Is it an orbit of the harmonic balance that the continuation missed? At 13.70
// krad/s, from the closed-mesh linear orbit, GSL rk8pd settles (3000 periods) on a period-1 orbit
// (it repeats after one period to 1e-9 of the amplitude) with Delta_min below -2.5 mm; Newton on
// the H = 10 model started from its Fourier coefficients (hb_unknowns_of_samples) converges to an
// HB orbit that matches it within the HB orbit's own distance to the exact flow (hb_orbit_error x
// sum |T2_i|) and is stable (Floquet): a coexisting stable branch the continuation does not reach
// (a probe run found the same at 13.65 krad/s; at 13.80 the integration from that start is not
// period 1).
TEST(BifurcationDiagram, Fig41IntegratedLargeOrbitIsAStableHbOrbit) {
  const HarmonicBalance hb = test_models::ch06_gear_pair(1e7);
  const double w = 13700.0;
  const VectorXd T2 = gear_pair_T2(GearPairParameters{});
  TimeIntegrationOptions o;
  o.x_scale = 1e-3;
  o.samples_per_period = 256;
  VectorXd x0, v0;
  hb_initial_state(hb, hb.closed_contact_solution(w), w, x0, v0);
  const MatrixXd q = TimeIntegrator(hb).sample(x0, v0, w, 3000, 2, o);
  const VectorXd d = q.topRows(256) * T2;
  const double amplitude = d.maxCoeff() - d.minCoeff();
  ASSERT_LE((q.topRows(256) - q.bottomRows(256)).cwiseAbs().maxCoeff(), 1e-9 * amplitude);   // period 1
  EXPECT_LT(d.minCoeff(), -2.5e-3);
  VectorXd X = hb_unknowns_of_samples(hb, q.topRows(256));
  const Scaling s = hb.scaling(0.99 * w, 1.01 * w);
  ASSERT_TRUE(newton_solve(hb, X, w, s, {1e-9, 30}).converged);
  const FloquetResult fr = floquet_of_hb_orbit(hb, X, w, s.x[0]);
  EXPECT_LT(fr.modulus, 1.0);
  const VectorXd dh = ResponseEvaluator(hb, T2, 256).history(X);
  EXPECT_LE((dh - d).cwiseAbs().maxCoeff(), T2.cwiseAbs().sum() * fr.orbit_error);
}

// The down sweep's start (app/bifurcation_input.hpp set_down_start) on the same oscillator: at a
// band end where HB's period-1 orbit is stable (Omega = 1.98, period 1 again from 1.95) it is a
// periodic orbit of the equations, checked by time integration (one period at tight tolerances
// returns to it within 2e-4 gap units, HB's truncation at H = 20 as above (measured 2.9e-7 in x,
// 3.6e-6 in v / Omega), while the chaos or a period-2 orbit nearby is off by 0.1 or more) and
// attracting (the period map's multipliers inside the unit circle; measured largest 0.85); where no stable orbit brackets the end (Omega = 1.25, the chaotic stretch)
// it sets none and clears a start given before.
TEST(BifurcationDiagram, DownSweepStartIsTheStableOrbitAtTheBandEnd) {
  const HarmonicBalance hb = kahraman_singh(0.5);
  const FrequencyCurve c = curve_0_3_to_2(hb);
  ASSERT_TRUE(c.complete) << c.failure;
  BifurcationDiagramOptions o;
  const double w = 1.98;
  ASSERT_TRUE(set_down_start(hb, c, w, o));
  ASSERT_EQ(o.down_x0.size(), 1);
  ASSERT_EQ(o.down_v0.size(), 1);
  VectorXd x = o.down_x0, v = o.down_v0;
  MatrixXd M;
  map_periods(TimeIntegrator(hb), w, 1, x, v, M);
  EXPECT_LT(std::abs(x[0] - o.down_x0[0]), 2e-4);
  EXPECT_LT(std::abs(v[0] - o.down_v0[0]) / w, 2e-4);
  Eigen::EigenSolver<MatrixXd> es(M);
  EXPECT_LT(es.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
  EXPECT_FALSE(set_down_start(hb, c, 1.25, o));
  EXPECT_EQ(o.down_x0.size(), 0);
  EXPECT_EQ(o.down_v0.size(), 0);
  // The same curve with every stable label on a shooting correction that failed (hand-made: each
  // point's shooting tried, none converged): no label is resolved, so no orbit at 1.98 is known
  // to attract and the down sweep follows the up sweep (hb/period_doubling.hpp resolved_stable).
  FrequencyCurve unresolved = c;
  for (PointFloquet& f : unresolved.floquet) f.shooting = true, f.corrected = false;
  EXPECT_FALSE(set_down_start(hb, unresolved, w, o));
  EXPECT_EQ(o.down_x0.size(), 0);
}

// The speeds a grid misses (hb/bifurcation_diagram.hpp speeds_missed, sweep_speeds), by hand: the
// grid 0, 0.1, ..., 1 misses [0.52, 0.58] (its middle 0.55 is added) but holds 0.3 in [0.29,
// 0.31] and 1 in [0.95, 1.2] (clipped to [0.95, 1]). On the oscillator (period 1 up to 0.85 by
// the header) a two-speed grid over [0.5, 0.6] with 0.55 added visits 0.5, 0.55, 0.6 up and down,
// and the added speed is classified as the others: period 1 in both sweeps.
TEST(BifurcationDiagram, SpeedsTheGridMissesAreAdded) {
  const std::vector<double> added = speeds_missed(0.0, 1.0, 11, {{0.52, 0.58}, {0.29, 0.31}, {0.95, 1.2}});
  ASSERT_EQ(added.size(), 1u);
  EXPECT_DOUBLE_EQ(added[0], 0.55);
  const std::vector<double> w = sweep_speeds(0.0, 1.0, 11, {0.55, 2.0, NAN});
  ASSERT_EQ(w.size(), 12u);
  EXPECT_DOUBLE_EQ(w[6], 0.55);
  EXPECT_TRUE(std::is_sorted(w.begin(), w.end()));
  const HarmonicBalance hb = kahraman_singh(0.5);
  BifurcationDiagramOptions o;
  o.speeds = 2;
  o.added_speeds = {0.55};
  o.integration.x_scale = 1.0;
  const BifurcationDiagram d = bifurcation_diagram(hb, 0.5, 0.6, VectorXd::Zero(1), VectorXd::Zero(1), o);
  ASSERT_EQ(d.points.size(), 6u);
  const double omegas[] = {0.5, 0.55, 0.6, 0.6, 0.55, 0.5};
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(d.points[k].omega, omegas[k]);
    EXPECT_EQ(d.points[k].up, k < 3);
    EXPECT_EQ(d.points[k].added, k == 1 || k == 4);
  }
  for (std::size_t k : {std::size_t(1), std::size_t(4)}) {
    EXPECT_EQ(d.points[k].motion, Motion::periodic) << d.points[k].failure;
    EXPECT_EQ(d.points[k].n, 1);
  }
}
