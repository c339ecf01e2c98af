// Period-2 branches of a gear mesh (issue 34 §1-§4; gearhb_gear with hb/period_doubling.hpp)
// and what the gear does where period 1 is unstable. The light-load relieved pair of
// gearhb_gear's thesis_pair_light_load.json at 20 N m (zeta 0.03, H = 10, both flanks), over
// the speeds of its first period doublings. Each check names its independent truth:
//  - the stable period-2 HB orbits are period-2 motions of the ORIGINAL mesh model by GSL rk8pd
//    time integration at the mesh frequency (no harmonic balance): after a transient the
//    integration returns to the shooting-corrected period-2 state every two mesh periods and
//    not every one; the HB orbit's DTE RMS and K_v against the integrated ones within the bound
//    that HB's own orbit error gives (|rms_ac(a) - rms_ac(b)| <= max |a - b|; |N_a - N_b| <=
//    kc max |x_a - x_b| for the piecewise-linear flank law);
//  - stable_intervals / uncovered (the ranges with no stable period-1 orbit) against the
//    stability flags of the points themselves; resolved_stable, period1_ranges and the diagram's
//    bands over an unresolved stretch on hand-made curves (the expected ranges worked by hand);
//    so too an orbit branch's stable key numbers and the diagram's up-sweep start.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/orbit_branches.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;

namespace {

struct LightLoad {
  DteGear g;
  HarmonicBalance hb;
  SweepOptions o;
  FrequencyCurve c;
  std::vector<PeriodDoubledBranch> br;
  static DteGear mesh() {
    PairSteModel m;
    m.pair_hertz = TwoPairHertz::consistent;
    m.relief1 = m.relief2 =
        tip_relief(m.gear1, 13.9165e-6, ReliefStart::length, 8.856394302280649e-3, ReliefShape::linear);
    return gear_pair_mesh(m, pair_ste(m, mesh_phases(m, 64), 20.0), 20.0, 0.0158, 0.0158, 0.03, 15e-6);
  }
  LightLoad() : g(mesh()), hb(gear_mesh_model(g, MeshDofs::one_dof, {}, 10, 0, DteModel::constant)) {
    o.omega_min = 2.0 * M_PI * 300.0, o.omega_max = 2.0 * M_PI * 1400.0;
    o.continuation.ds_max = 0.05;
    c = sweep_frequency(hb, o, "light load");
    br = period_doubled_branches(hb, c, o);
  }
};
const LightLoad& light() {
  static const LightLoad e;
  return e;
}
// Its branches to depth 2 (period 2 and 4), computed once for the tests that use them.
const std::vector<PeriodDoubledBranch>& light_cascade() {
  static const std::vector<PeriodDoubledBranch> all = period_doubling_cascade(light().hb, light().c, light().o, 2);
  return all;
}

// The same mesh over gearhb_gear's whole speed range (thesis_pair_light_load.json: 300-5000 Hz
// mesh frequency, ds_max 0.05) and its branches to depth 2 as the program computes them
// (`--set period_doubling.depth=2`: all[k] is branch k + 1 of frc_1.csv). About 4 s.
struct LightLoadWhole {
  HarmonicBalance hb;
  SweepOptions o;
  FrequencyCurve c;
  std::vector<PeriodDoubledBranch> all;
  LightLoadWhole() : hb(gear_mesh_model(LightLoad::mesh(), MeshDofs::one_dof, {}, 10, 0, DteModel::constant)) {
    o.omega_min = 2.0 * M_PI * 300.0, o.omega_max = 2.0 * M_PI * 5000.0;
    o.continuation.ds_max = 0.05;
    c = sweep_frequency(hb, o, "light load, whole range");
    all = period_doubling_cascade(hb, c, o, 2);
  }
};

// GSL rk8pd on the ORIGINAL model at the mesh frequency from point i's HB state of branch b
// (period p mesh periods): `transient` mesh periods (a multiple of p), then p more; the state
// must be back at the shooting-corrected one after p periods and not after p / 2 (`apart`: how
// far the half-period state must lie, in x_scale). Returns the settled state (xs, vs row 0).
void expect_period_p(const TimeIntegrator& ti, const PeriodDoubledBranch& b, std::size_t i, int transient,
                     const TimeIntegrationOptions& to, double apart, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs) {
  const BranchPoint& q = b.curve.branch.points[i];
  const int p = b.period;
  const double omega = p * q.omega;   // the mesh frequency
  Eigen::VectorXd x0, v0;
  hb_initial_state(*b.model, q.X, q.omega, x0, v0);
  ti.poincare(x0, v0, omega, transient, p, to, xs, vs);
  EXPECT_LT((xs.row(0).transpose() - b.curve.floquet[i].x0).cwiseAbs().maxCoeff(), 1e-7 * to.x_scale) << omega;
  EXPECT_LT((xs.row(p) - xs.row(0)).cwiseAbs().maxCoeff(), 1e-7 * to.x_scale) << omega;
  EXPECT_GT((xs.row(p / 2) - xs.row(0)).cwiseAbs().maxCoeff(), apart * to.x_scale) << omega;
}

}  // namespace

TEST(GearPeriodDoubling, LightLoadStablePeriodTwoOrbitsAreSeenByTimeIntegration) {
  const auto& e = light();
  ASSERT_TRUE(e.c.complete) << e.c.failure;
  ASSERT_FALSE(e.br.empty());
  const Eigen::VectorXd q = dte_coordinate(MeshDofs::one_dof);
  const TimeIntegrator ti(e.hb);   // the ORIGINAL model, at the mesh frequency
  TimeIntegrationOptions to;
  to.x_scale = e.c.scaling.x[0];
  int compared = 0;
  for (const auto& b : e.br) {
    if (!has_points(b)) continue;
    const auto& P = b.curve.branch.points;
    const MeshCurveSummary s = mesh_curve_summary(*b.model, b.curve, e.g.F0, q);
    for (std::size_t i = 1; i < P.size() && compared < 6; i += std::max<std::size_t>(1, P.size() / 5)) {
      const PointFloquet& f = b.curve.floquet[i];
      if (!b.curve.stable[i] || !f.corrected || f.modulus > 0.9) continue;
      const double omega = 2.0 * P[i].omega;   // the mesh frequency
      // from the HB state, 400 mesh periods (|mu| <= 0.9 per two: < 1e-9 of a start error left);
      // back at the corrected period-2 state after two periods, not after one
      Eigen::MatrixXd xs, vs;
      expect_period_p(ti, b, i, 400, to, 1e-3, xs, vs);
      // DTE RMS and K_v of the integrated motion (two periods from the settled state), sampled
      // at two resolutions: the finer one's distance to the coarser bounds its crest deficiency
      const MeshMotionMeasures fine = mesh_motion_measures(e.hb, xs.row(0).transpose(), vs.row(0).transpose(), omega,
                                                           2, 16384, e.g.F0, q, to.x_scale);
      const MeshMotionMeasures coarse = mesh_motion_measures(e.hb, xs.row(0).transpose(), vs.row(0).transpose(),
                                                             omega, 2, 4096, e.g.F0, q, to.x_scale);
      const double err = f.orbit_error;
      EXPECT_NEAR(s.points[i].dte_rms, fine.dte_rms, err + std::fabs(fine.dte_rms - coarse.dte_rms) + 1e-12) << omega;
      EXPECT_NEAR(s.points[i].dynamic_factor, fine.dynamic_factor,
                  e.g.kc * err / e.g.F0 + std::fabs(fine.dynamic_factor - coarse.dynamic_factor) + 1e-12)
          << omega;
      ++compared;
    }
  }
  EXPECT_GE(compared, 2);
}

TEST(GearPeriodDoubling, RangesWithoutAStablePeriodOneOrbit) {
  const auto& e = light();
  const auto& P = e.c.branch.points;
  const Intervals st = stable_intervals(e.c);
  const Intervals gaps = uncovered(e.o.omega_min, e.o.omega_max, st);
  ASSERT_FALSE(gaps.empty());   // the period doublings of this range
  // every stable point lies in a stable interval and outside every gap; a speed inside a gap
  // has no stable point within the chord that brackets it
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!e.c.stable[i]) continue;
    for (const auto& [a, b] : gaps) EXPECT_FALSE(a < P[i].omega && P[i].omega < b) << P[i].omega;
  }
  for (const auto& [a, b] : gaps) {
    const double mid = 0.5 * (a + b);
    for (std::size_t k = 0; k + 1 < P.size(); ++k) {
      const double lo = std::min(P[k].omega, P[k + 1].omega), hi = std::max(P[k].omega, P[k + 1].omega);
      if (lo <= mid && mid <= hi) {
        EXPECT_FALSE(e.c.stable[k] && e.c.stable[k + 1]) << mid;
      }
    }
  }
  // each gap ends at a located bifurcation of the curve (or the range's end)
  for (const auto& [a, b] : gaps) {
    for (double w : {a, b}) {
      bool at = w == e.o.omega_min || w == e.o.omega_max;
      for (const auto& bf : e.c.bifurcations) at = at || std::fabs(bf.omega - w) <= 1e-12 * w;
      EXPECT_TRUE(at) << w;
    }
  }
}

TEST(GearPeriodDoubling, UncoveredIsTheComplement) {
  const Intervals gaps = uncovered(0.0, 10.0, {{2.0, 3.0}, {-1.0, 1.0}, {2.5, 4.0}, {9.0, 12.0}});
  ASSERT_EQ(gaps.size(), 2u);
  EXPECT_EQ(gaps[0], std::make_pair(1.0, 2.0));
  EXPECT_EQ(gaps[1], std::make_pair(4.0, 9.0));
  EXPECT_EQ(uncovered(0.0, 1.0, {}).size(), 1u);
  EXPECT_TRUE(uncovered(0.0, 1.0, {{-1.0, 2.0}}).empty());
}

TEST(GearPeriodDoubling, StableStretchWithoutACorrectedPointIsUnresolved) {
  // Seven points at omega 1..7: stable 0 1 1 0 1 1 0, corrected 1 0 1 1 0 0 1. The stretch 2-3 has
  // a corrected point (resolved, kept); the stretch 5-6 has none (unresolved: not stable, listed).
  FrequencyCurve c;
  const std::vector<bool> stable{false, true, true, false, true, true, false}, corrected{true, false, true, true,
                                                                                       false, false, true};
  for (std::size_t k = 0; k < stable.size(); ++k) {
    c.branch.points.push_back({});
    c.branch.points.back().omega = double(k + 1);
    c.floquet.push_back({});
    c.floquet.back().corrected = corrected[k];
    c.floquet.back().shooting = true;
  }
  c.stable = stable;
  EXPECT_EQ(resolved_stable(c), (std::vector<bool>{false, true, true, false, false, false, false}));
  EXPECT_EQ(unresolved_stable_stretches(c, 2), (Intervals{{10.0, 12.0}}));
  EXPECT_EQ(resolved_stable_intervals(c), (Intervals{{1.5, 3.5}}));   // to the chord midpoints (no bifurcation listed)
  EXPECT_EQ(stable_intervals(c), (Intervals{{1.5, 3.5}, {4.5, 6.5}}));
  for (auto& f : c.floquet) f.shooting = false;   // variational multipliers by choice (gearhb_planetary): no shooting tried
  EXPECT_EQ(resolved_stable(c), stable);
  c.floquet.clear();   // no Floquet data (Hill): every label as it is
  EXPECT_EQ(resolved_stable(c), stable);
}

namespace {
// A curve at omega = first, first + 1, ... with these stable labels, each point's shooting tried
// (`shooting`) and converged where `corrected` says.
FrequencyCurve labelled_curve(double first, const std::vector<bool>& stable, const std::vector<bool>& corrected,
                              bool shooting = true) {
  FrequencyCurve c;
  for (std::size_t k = 0; k < stable.size(); ++k) {
    c.branch.points.push_back({});
    c.branch.points.back().omega = first + double(k);
    c.floquet.push_back({});
    c.floquet.back().corrected = corrected[k];
    c.floquet.back().shooting = shooting;
  }
  c.stable = stable;
  return c;
}
}  // namespace

TEST(GearPeriodDoubling, Period1RangesExcludeOnlyResolvedStablePoints) {
  // Eight points at omega 1..8: stable 1 1 0 1 1 0 1 1, corrected 1 1 1 0 0 1 1 1 - the stretch at
  // 4-5 is unresolved. By hand (no bifurcation listed: a stability change ends at the chord's
  // midpoint): the labels say stable on [1, 2.5], [3.5, 5.5], [6.5, 8]; the resolved labels on
  // [1, 2.5], [6.5, 8]. So over [1, 8] no period-1 orbit is known stable on [2.5, 6.5], of which
  // [3.5, 5.5] is labelled stable but unresolved.
  const FrequencyCurve c = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                                          {true, true, true, false, false, true, true, true});
  Period1Ranges r = period1_ranges(1.0, 8.0, {&c});
  EXPECT_EQ(r.no_stable, (Intervals{{2.5, 6.5}}));
  EXPECT_EQ(r.unresolved, (Intervals{{3.5, 5.5}}));
  // A second period-1 branch resolved-stable on [4.25, 5.25] (two corrected stable points) leaves
  // [2.5, 4.25] and [5.25, 6.5], and of the unresolved stretch [3.5, 4.25] and [5.25, 5.5].
  const FrequencyCurve other = labelled_curve(4.25, {true, true}, {true, true});
  r = period1_ranges(1.0, 8.0, {&c, &other});
  EXPECT_EQ(r.no_stable, (Intervals{{2.5, 4.25}, {5.25, 6.5}}));
  EXPECT_EQ(r.unresolved, (Intervals{{3.5, 4.25}, {5.25, 5.5}}));
  // The same labels from the variational equation by choice (no shooting tried): all resolved.
  const FrequencyCurve variational = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                                                    std::vector<bool>(8, false), false);
  r = period1_ranges(1.0, 8.0, {&variational});
  EXPECT_EQ(r.no_stable, (Intervals{{2.5, 3.5}, {5.5, 6.5}}));
  EXPECT_TRUE(r.unresolved.empty());
}

TEST(GearPeriodDoubling, DiagramBandCoversAnUnresolvedStretch) {
  // The curve above: one range with no known stable period-1 orbit, [2.5, 6.5] (the unresolved
  // stretch [3.5, 5.5] in it), padded by max(0.25 x 4, 0.02 x 7) = 1 on each side: one band
  // [1.5, 7.5]. Taking the labels at face value would give two bands, [2.25, 3.75] and
  // [5.25, 6.75], and no diagram over 3.75-5.25.
  const FrequencyCurve c = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                                          {true, true, true, false, false, true, true, true});
  const std::vector<DiagramBand> bands = diagram_bands(c, 1.0, 8.0, 1);
  ASSERT_EQ(bands.size(), 1u);
  EXPECT_DOUBLE_EQ(bands[0].omega_lo, 1.5);
  EXPECT_DOUBLE_EQ(bands[0].omega_hi, 7.5);
}

TEST(GearPeriodDoubling, OrbitBranchStableKeysCountOnlyResolvedLabels) {
  // An orbit branch (period 1) on the curve above, each point's orbit x = a cos(Omega t) with a
  // = 1 at the resolved stable points (omega 1, 2, 7, 8), 3 at the unstable ones (3, 6) and 5 at
  // the unresolved stretch (4, 5): a swing of 2, 6 and 10 (256 samples hold t = 0 and pi / Omega).
  // By hand: stable (resolved) on [1, 2.5] and [6.5, 8] with the largest stable swing 2; the
  // stretch 4-5 listed apart. Taking the labels at face value gives three stable ranges
  // ([1, 2.5], [3.5, 5.5], [6.5, 8]) and a stable swing of 10.
  OrbitBranch b;
  b.omega = 4.0, b.distance = 0.0, b.bound = 1.0;   // the check's numbers: not what is tested
  b.model = std::make_shared<HarmonicBalance>(test_models::kahraman_singh(0.5, 2));
  b.curve = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                           {true, true, true, false, false, true, true, true});
  const double a[] = {1.0, 1.0, 3.0, 5.0, 5.0, 3.0, 1.0, 1.0};
  for (std::size_t k = 0; k < 8; ++k) {
    b.curve.branch.points[k].X = Eigen::VectorXd::Zero(b.model->size());
    b.curve.branch.points[k].X[b.model->index(1, 0)] = a[k];
  }
  SweepOptions o;
  o.omega_min = 0.0, o.omega_max = 10.0;
  KeyNumbers key;
  orbit_branch_numbers(key, b, 3, Eigen::VectorXd::Ones(1), "x", o, "_1");
  auto value = [&](const std::string& name) { return key.json().at(name).at("value").get<double>(); };
  EXPECT_EQ(value("orbit_branch_stable_ranges_1"), 2.0);
  EXPECT_EQ(value("orbit_branch_stable_from_omega_1_1"), 1.0);
  EXPECT_EQ(value("orbit_branch_stable_to_omega_1_1"), 2.5);
  EXPECT_EQ(value("orbit_branch_stable_from_omega_1_2"), 6.5);
  EXPECT_EQ(value("orbit_branch_stable_to_omega_1_2"), 8.0);
  EXPECT_NEAR(value("orbit_branch_stable_swing_1"), 2.0, 1e-12);
  EXPECT_NEAR(value("orbit_branch_swing_1"), 10.0, 1e-12);
  EXPECT_EQ(value("orbit_branch_unresolved_ranges_1"), 1.0);
  EXPECT_EQ(value("orbit_branch_unresolved_from_omega_1_1"), 4.0);
  EXPECT_EQ(value("orbit_branch_unresolved_to_omega_1_1"), 5.0);
}

TEST(GearPeriodDoubling, DiagramStartsOnlyOnResolvedStableOrbits) {
  // The curve above: the up sweep of a band from 4.2 starts on the nearest point stable with a
  // resolved label, omega 2 (index 1; 7 is 2.8 away), not on the unresolved point at 4 (index 3).
  const FrequencyCurve c = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                                          {true, true, true, false, false, true, true, true});
  EXPECT_EQ(diagram_start(c, 4.2), 1u);
  // Every label unresolved: the nearest point of all, omega 4 (index 3).
  const FrequencyCurve none = labelled_curve(1.0, {true, true, false, true, true, false, true, true},
                                             std::vector<bool>(8, false));
  EXPECT_EQ(diagram_start(none, 4.2), 3u);
}

TEST(GearPeriodDoubling, LightLoadStablePeriodFourOrbitsAreSeenByTimeIntegration) {
  // Depth 2: the period-4 branches from the period doublings of the period-2 branches; their
  // stable orbits against GSL rk8pd on the original model: back at the shooting-corrected
  // period-4 state every four mesh periods, not every two.
  const auto& e = light();
  const std::vector<PeriodDoubledBranch>& all = light_cascade();
  const TimeIntegrator ti(e.hb);
  TimeIntegrationOptions to;
  to.x_scale = e.c.scaling.x[0];
  int compared = 0, period4 = 0;
  for (const auto& b : all) {
    if (b.period != 4 || !has_points(b)) continue;
    ++period4;
    ASSERT_GE(b.parent, 0);
    EXPECT_EQ(all[std::size_t(b.parent)].period, 2);
    const auto& P = b.curve.branch.points;
    for (std::size_t i = 1; i < P.size() && compared < 4; i += std::max<std::size_t>(1, P.size() / 4)) {
      const PointFloquet& f = b.curve.floquet[i];
      if (!b.curve.stable[i] || !f.corrected || f.modulus > 0.9) continue;
      Eigen::MatrixXd xs, vs;
      expect_period_p(ti, b, i, 800, to, 1e-4, xs, vs);   // 800: a whole number of period-4 orbits
      ++compared;
    }
  }
  EXPECT_GE(period4, 1);
  EXPECT_GE(compared, 1);
}

TEST(GearPeriodDoubling, EverySmoothPeriodDoublingSwitchesFromACriticalMultiplier) {
  // Every located smooth PD of the period-1 curve and of the period-2 branches (depth 2) starts
  // a branch with points, and the point the switch starts from has a Floquet multiplier at -1:
  // the multipliers of the shooting-corrected orbit there (floquet_of_hb_orbit, the definition
  // of the PD, not the location's own bookkeeping). A PD point re-derived from its omega on the
  // chord (linear in omega) missed the located one where the branch turns within the chord: in
  // this range the period-2 branch's PDs at 6138 and 8068 rad/s (nearest multiplier -0.938 at
  // the re-derived point of the first: the switch failed there).
  const auto& e = light();
  const std::vector<PeriodDoubledBranch>& all = light_cascade();
  int switches = 0;
  for (const auto& b : all) {
    const FrequencyCurve& parent = b.parent < 0 ? e.c : all[std::size_t(b.parent)].curve;
    const HarmonicBalance& model = b.parent < 0 ? e.hb : *all[std::size_t(b.parent)].model;
    const Bifurcation& bf = parent.bifurcations.at(b.from);
    ASSERT_EQ(bf.type, BifurcationType::period_doubling);
    if (!bf.smooth) continue;
    ++switches;
    EXPECT_NE(b.end, PeriodDoubledBranch::End::failed) << b.why;
    EXPECT_TRUE(has_points(b)) << b.why;
    SweepOptions o = e.o;
    o.omega_min /= b.period / 2, o.omega_max /= b.period / 2;
    const SwitchPoint sp = critical_direction(model, parent, bf, o, {}, *subharmonic_model(model, 2));
    const FloquetResult fr = floquet_of_hb_orbit(model, sp.at.X, sp.at.omega, e.c.scaling.x[0], o.floquet);
    ASSERT_TRUE(fr.corrected) << b.why;
    double nearest = INFINITY;
    for (Eigen::Index k = 0; k < fr.multipliers.size(); ++k) nearest = std::min(nearest, std::abs(fr.multipliers[k] + 1.0));
    EXPECT_LT(nearest, 1e-4) << b.why;
  }
  EXPECT_GE(switches, 5);
}

TEST(GearPeriodDoubling, LightLoadNarrowStablePeriodFourStretchesAttractTheTimeIntegration) {
  // gearhb_gear's light-load example at depth 2: its period-4 branch 6 is stable on two stretches
  // near 2206 and 2262 rpm narrower than one continuation step (each holds one point, between a
  // fold and a period doubling: |mu| 0.43 and 0.44), far narrower than the bifurcation diagram's
  // speed spacing (99 rpm), so no diagram speed and no from_hb start ever reached them. At each
  // stable point of the branch between two unstable ones, the time integration of the ORIGINAL
  // mesh model (GSL rk8pd, contact switches located) started on HB's period-4 orbit:
  //  - as from_hb integrates it (diagram_point, the sweeps' options): periodic with n = 4, and
  //    each of HB's four states at phase 0 within HB's own error (hb_orbit_error) plus the
  //    classifier's resolution (period_tol x_scale) of a Poincare point;
  //  - 2000 mesh periods on: back at the shooting-corrected state (exact flow) every four mesh
  //    periods and not every two (expect_period_p).
  static const LightLoadWhole e;
  ASSERT_TRUE(e.c.complete) << e.c.failure;
  ASSERT_GE(e.all.size(), 6u);
  const PeriodDoubledBranch& b = e.all[5];   // branch 6
  ASSERT_EQ(b.period, 4);
  ASSERT_TRUE(has_points(b)) << b.why;
  const TimeIntegrator ti(e.hb);
  TimeIntegrationOptions to;
  to.x_scale = e.c.scaling.x[0];
  BifurcationDiagramOptions bo;
  bo.integration.x_scale = to.x_scale;
  const auto& P = b.curve.branch.points;
  const auto& st = b.curve.stable;
  std::vector<double> rpm;
  for (std::size_t i = 1; i + 1 < P.size(); ++i) {
    if (!st[i] || st[i - 1] || st[i + 1]) continue;
    const PointFloquet& f = b.curve.floquet[i];
    ASSERT_TRUE(f.corrected);
    const double omega = 4.0 * P[i].omega;   // the mesh frequency
    Eigen::VectorXd x0, v0;
    hb_initial_state(*b.model, P[i].X, P[i].omega, x0, v0);
    const DiagramPoint dp = diagram_point(e.hb, omega, x0, v0, bo);
    EXPECT_EQ(dp.motion, Motion::periodic) << omega;
    EXPECT_EQ(dp.n, 4) << omega;
    const Eigen::MatrixXd states = phase_states(*b.model, P[i].X, 4);
    double farthest = 0.0;
    for (int j = 0; j < 4; ++j) {
      double nearest = INFINITY;
      for (Eigen::Index r = 0; r < dp.x.rows(); ++r)
        nearest = std::min(nearest, (dp.x.row(r).transpose() - states.col(j)).cwiseAbs().maxCoeff());
      EXPECT_LE(nearest, f.orbit_error + bo.period_tol * bo.integration.x_scale) << omega << ", phase " << j;
      farthest = std::max(farthest, nearest);
    }
    Eigen::MatrixXd xs, vs;
    expect_period_p(ti, b, i, 2000, to, 1e-3, xs, vs);
    rpm.push_back(60.0 * omega / (2.0 * M_PI) / 50.0);   // z1 = 50
    std::printf("branch 6 at %.4f rpm: |mu| %.4f, %s n = %d after %d transient periods; HB's phase-0 values %.3g m "
                "from the Poincare points, hb_orbit_error %.3g m\n", rpm.back(), f.modulus, to_string(dp.motion), dp.n,
                dp.transient, farthest, f.orbit_error);
  }
  ASSERT_EQ(rpm.size(), 2u);
  for (double n : rpm) EXPECT_TRUE(std::fabs(n - 2206.0) < 2.0 || std::fabs(n - 2262.5) < 2.0) << n;
}
