// The gear pair over its speed range (gears/dynamics/mesh_dynamics.hpp, gears/dynamics/dte_model.hpp with two
// flanks, the gap-amplitude start of hb/first_point.hpp). Each check names its independent truth.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;

namespace {

// The thesis pair (z 50/50, m 3 mm, 20 deg, b 20 mm, ch. 7's readings), I = 0.0158 kg m^2.
DteGear thesis_mesh(double torque, double backlash, PairSteModel m = PairSteModel{}) {
  const std::vector<MeshPhase> ph = mesh_phases(m, 64);
  return gear_pair_mesh(m, pair_ste(m, ph, torque), torque, 0.0158, 0.0158, 0.08, backlash);
}

// The thesis gears on bearings of stiffness k (masses 2.8 kg, line of action at 20 deg).
BearingSupport thesis_bearings(double k) {
  BearingSupport b;
  b.mass[0] = b.mass[1] = 2.8;
  b.stiffness[0] = b.stiffness[1] = k;
  b.pressure_angle = 20.0 * M_PI / 180.0;
  return b;
}

// The coefficients of coordinate q of the periodic orbit at f [Hz], swept from 300 Hz.
Eigen::VectorXd orbit_at(const HarmonicBalance& hb, double f, const Eigen::VectorXd& q, const char* label) {
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 300.0, o.omega_max = 2.0 * M_PI * f;
  const FrequencyCurve c = sweep_frequency(hb, o, label);
  EXPECT_TRUE(c.complete) << label << " " << f;
  return hb.project(c.branch.points.back().X, q);
}

}  // namespace

// f(psi - theta) from the reflected coefficients against the series evaluated directly.
TEST(MeshDynamics, ReflectedSeriesIsTheMirroredFunction) {
  Eigen::VectorXd c(9);
  c << 0.3, 1.0, -0.5, 0.25, 0.7, -0.1, 0.05, 0.02, -0.3;
  const double psi = 1.2345;
  const Eigen::VectorXd r = reflected_series(c, psi);
  for (double th : {0.0, 0.4, 2.0, 5.5})
    EXPECT_NEAR(trig_series(r, th), trig_series(c, psi - th), 1e-14) << th;
}

// Two identical unshifted gears: the back flank's phase psi = pi (1 + 2 eps_alpha) (mod 2 pi),
// the header's derivation specialised by hand (s_b = pb / 2 + 2 rb inv(alpha), T1T2 = 2 T1A + AE).
TEST(MeshDynamics, BackFlankPhaseOfIdenticalGears) {
  const PairSteModel m;
  const double eps = m.path().contact_ratio;
  EXPECT_NEAR(std::remainder(back_flank_phase(m) - M_PI * (1.0 + 2.0 * eps), 2.0 * M_PI), 0.0, 1e-12);
}

// The six-DOF bearing model with very stiff bearings is the one-DOF model (header): the
// transmission error p of the periodic solution equals x to O(kc / k_bearing) at a full-contact
// and at a drive-flank-loss frequency of the thesis pair at 300 N m.
TEST(MeshDynamics, StiffBearingsGiveTheOneDofModel) {
  const DteGear g = thesis_mesh(300.0, 15e-6);
  const BearingSupport b = thesis_bearings(1e15);
  const int H = 5;
  const HarmonicBalance one = gear_mesh_model(g, MeshDofs::one_dof, b, H, 0, DteModel::constant);
  const HarmonicBalance six = gear_mesh_model(g, MeshDofs::bearings, b, H, 0, DteModel::constant);
  for (double f : {1000.0, 1400.0}) {
    const Eigen::VectorXd x = orbit_at(one, f, dte_coordinate(MeshDofs::one_dof), "one");
    const Eigen::VectorXd p = orbit_at(six, f, dte_coordinate(MeshDofs::bearings), "six");
    EXPECT_LT((x - p).lpNorm<Eigen::Infinity>(), 1e-5 * x.tail(x.size() - 1).lpNorm<Eigen::Infinity>()) << f;
  }
}

// The axial DOFs of a single-helical pair (header, issue 35 c) with very stiff axial bearings
// are the six-DOF model: p equals to O(kc t^2 / ka) at a full-contact and at a drive-loss
// frequency; the closed-contact frequencies are the five of the six-DOF model and two near
// sqrt(ka / m) / 2 pi (the axial bearings, their coupling through the mesh O(kc / ka)). The static
// axial bearing force F_t tan(beta) with realistic axial bearings: gear.helical_pair_six_dof.axial_*.
TEST(MeshDynamics, StiffAxialBearingsGiveTheSixDofModel) {
  const DteGear g = thesis_mesh(300.0, 15e-6);
  const BearingSupport b = thesis_bearings(1e8);
  const int H = 5;
  const HarmonicBalance six = gear_mesh_model(g, MeshDofs::bearings, b, H, 0, DteModel::constant);
  BearingSupport a = b;
  a.helix_tan = std::tan(18.75 * M_PI / 180.0);
  a.axial_stiffness[0] = a.axial_stiffness[1] = 1e15;
  const HarmonicBalance axial = gear_mesh_model(g, MeshDofs::bearings, a, H, 0, DteModel::constant);
  ASSERT_EQ(axial.dofs(), 7);
  for (double f : {1000.0, 1400.0}) {
    const Eigen::VectorXd p6 = orbit_at(six, f, dte_coordinate(MeshDofs::bearings, b), "six");
    const Eigen::VectorXd p8 = orbit_at(axial, f, dte_coordinate(MeshDofs::bearings, a), "axial");
    EXPECT_LT((p6 - p8).lpNorm<Eigen::Infinity>(), 1e-5 * p6.tail(p6.size() - 1).lpNorm<Eigen::Infinity>()) << f;
  }
  std::vector<double> f6 = closed_contact_frequencies(g, MeshDofs::bearings, b);
  std::vector<double> f8 = closed_contact_frequencies(g, MeshDofs::bearings, a);
  ASSERT_EQ(f6.size(), 5u);
  ASSERT_EQ(f8.size(), 7u);
  std::sort(f6.begin(), f6.end());
  std::sort(f8.begin(), f8.end());
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(f8[std::size_t(k)], f6[std::size_t(k)], 1e-4 * f6[std::size_t(k)]) << k;
  const double fa = std::sqrt(1e15 / 2.8) / (2.0 * M_PI);
  for (int k = 5; k < 7; ++k) EXPECT_NEAR(f8[std::size_t(k)], fa, 1e-3 * fa) << k;
}

// The light-load relieved pair (gearhb_gear's thesis_pair_light_load.json at 20 N m, zeta 0.03,
// H = 10): at 300 Hz the 7th mesh harmonic of the relief excitation meets the mesh resonance, so
// no linear solution is near the orbit and the sweep starts by continuation in the amplitude of
// the gaps' periodic parts; the point it finds is the periodic orbit of GSL rk8pd (DTE RMS 1e-6),
// and a back-impact orbit keeps the mean mesh force at F0 (1e-9).
TEST(MeshDynamics, LightLoadReliefStartsByGapContinuationAndMatchesTimeIntegration) {
  PairSteModel m;
  m.pair_hertz = TwoPairHertz::consistent;
  m.relief1 = m.relief2 = tip_relief(m.gear1, 13.9165e-6, ReliefStart::length, 8.856394302280649e-3, ReliefShape::linear);
  const std::vector<MeshPhase> ph = mesh_phases(m, 64);
  const DteGear g = gear_pair_mesh(m, pair_ste(m, ph, 20.0), 20.0, 0.0158, 0.0158, 0.03, 15e-6);
  const HarmonicBalance hb = gear_mesh_model(g, MeshDofs::one_dof, {}, 10, 0, DteModel::constant);
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 300.0, o.omega_max = 2.0 * M_PI * 2000.0;
  const FrequencyCurve c = sweep_frequency(hb, o, "light");
  ASSERT_TRUE(c.complete) << c.failure;
  EXPECT_EQ(c.first_point, FirstPointMethod::amplitude_continuation);
  const MeshCurveSummary s = mesh_curve_summary(hb, c, g.F0, dte_coordinate(MeshDofs::one_dof));
  EXPECT_LT(s.mean_force_rel_dev, 1e-9);
  ASSERT_TRUE(std::isfinite(s.back_impact_first_omega));
  // the stable point of largest K_v with a back impact, against GSL
  std::size_t pick = c.branch.points.size();
  for (std::size_t i = 0; i < c.branch.points.size(); ++i)
    if (c.stable[i] && s.points[i].back != ContactState::open &&
        (pick == c.branch.points.size() || s.points[i].dynamic_factor > s.points[pick].dynamic_factor))
      pick = i;
  ASSERT_LT(pick, c.branch.points.size());
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, c.branch.points[pick].X, c.branch.points[pick].omega, x0, v0);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  const SteadyState st = TimeIntegrator(hb).steady_state(x0, v0, c.branch.points[pick].omega, opt);
  ASSERT_TRUE(st.converged);
  const Eigen::VectorXd x = st.x.col(0);
  const double rms = std::sqrt((x.array() - x.mean()).square().mean());
  EXPECT_NEAR(s.points[pick].dte_rms, rms, 1e-2 * rms);   // H = 10 truncation (the run's check: 0.06 %)
}
