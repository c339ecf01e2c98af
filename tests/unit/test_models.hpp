#pragma once
// Small models shared by the unit tests.
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace test_models {

// Thesis ch. 3 mass against a wall: m = 1 kg, c = 0.01 N s/m, k = 1 N/m,
// kc = 1 N/m, F = 0.01 N, gap g, static force F0.
inline gearhb::HarmonicBalance mass_wall(double gap, int H, double F0 = 0.0, double F = 0.01,
                                         int N = 0) {
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  gearhb::LinearSystem s{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.01),
                         MatrixXd::Constant(1, 1, 1.0)};
  gearhb::UnilateralContact c{VectorXd::Constant(1, 1.0), 1.0, gap, {}};
  gearhb::Excitation f{VectorXd::Constant(1, F0), VectorXd::Constant(1, F), VectorXd::Zero(1)};
  return gearhb::HarmonicBalance(s, {c}, f, H, N);
}

}  // namespace test_models

namespace test_models {

// NLvib example 03 (Krack & Gross, "Harmonic Balance for Nonlinear Vibration
// Problems", Springer 2019, and the NLvib toolbox): two unit masses in a chain,
// ChainOfOscillators with ki = [k1 k2 k3] = [0 1 1] (k1 ground-mass 1, k2 mass 1-mass 2,
// k3 mass 2-ground): K = [[k1+k2, -k2], [-k2, k2+k3]] = [[1, -1], [-1, 2]], D = 0.03 K,
// force 0.1 cos(omega t) on DOF 2, unilateral spring 100 max(x1 - 1, 0) on DOF 1.
inline gearhb::HarmonicBalance nlvib_ex03(int H, int N = 0) {
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  MatrixXd K(2, 2);
  K << 1, -1, -1, 2;
  gearhb::LinearSystem s{MatrixXd::Identity(2, 2), 0.03 * K, K};
  VectorXd e1 = VectorXd::Zero(2);
  e1[0] = 1.0;
  gearhb::UnilateralContact c{e1, 100.0, -1.0, {}};
  VectorXd fc = VectorXd::Zero(2);
  fc[1] = 0.1;
  gearhb::Excitation f{VectorXd::Zero(2), fc, VectorXd::Zero(2)};
  return gearhb::HarmonicBalance(s, {c}, f, H, N);
}

// The same two masses with twice the damping (C = 0.06 K) and forcing 0.06: a
// Neimark-Sacker point at omega = 0.61471 where a torus is born, another at 0.59939
// (programs/gearhb_frc/examples/nlvib_ex03_torus.json); its sweep: 0.59 up to 0.63.
inline gearhb::HarmonicBalance nlvib_ex03_torus(int H) {
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  MatrixXd K(2, 2);
  K << 1, -1, -1, 2;
  gearhb::LinearSystem s{MatrixXd::Identity(2, 2), 0.06 * K, K};
  VectorXd e1 = VectorXd::Zero(2);
  e1[0] = 1.0;
  gearhb::UnilateralContact c{e1, 100.0, -1.0, {}};
  VectorXd fc = VectorXd::Zero(2);
  fc[1] = 0.06;
  gearhb::Excitation f{VectorXd::Zero(2), fc, VectorXd::Zero(2)};
  return gearhb::HarmonicBalance(s, {c}, f, H);
}
inline gearhb::SweepOptions nlvib_ex03_torus_sweep() {
  gearhb::SweepOptions o;
  o.omega_min = 0.59;
  o.omega_max = 0.63;
  o.direction = gearhb::SweepDirection::up;
  return o;
}

// NLvib example 03's sweep: omega from 0.8 down to 0.5.
inline gearhb::SweepOptions nlvib_ex03_sweep(gearhb::StabilityMethod stability) {
  gearhb::SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 0.8;
  o.direction = gearhb::SweepDirection::down;
  o.stability = stability;
  return o;
}

}  // namespace test_models

namespace test_models {

// A unit mass with damping c and stiffness k.
inline gearhb::LinearSystem unit_oscillator(double c, double k) {
  return {Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Constant(1, 1, c), Eigen::MatrixXd::Constant(1, 1, k)};
}

// The Kahraman & Singh (1990) clearance oscillator, scaled: x'' + 0.1 x' + f(x) = 0.1 + Fa
// cos(Omega t), f the dead zone of half-width 1 (two contacts of unit stiffness).
inline gearhb::HarmonicBalance kahraman_singh(double Fa, int H = 20) {
  using Eigen::VectorXd;
  const gearhb::LinearSystem s = unit_oscillator(0.1, 0.0);
  gearhb::UnilateralContact drive{VectorXd::Ones(1), 1.0, -1.0, VectorXd::Zero(2 * H + 1)};
  gearhb::UnilateralContact back = drive;
  back.normal = -drive.normal;
  return gearhb::HarmonicBalance(
      s, {drive, back}, gearhb::Excitation{VectorXd::Constant(1, 0.1), VectorXd::Constant(1, Fa), VectorXd::Zero(1)}, H);
}

}  // namespace test_models

namespace test_models {

// The one-sided clearance oscillator x'' + 0.1 x' + x + 4 max(x - 1, 0) = 0.5 cos(omega t): a
// hardening contact whose resonance leans right between two folds, two stable orbits coexisting
// at omega = 1.26 (tests/unit/test_orbit_branch.cpp); its range 0.5-3 rad/s.
inline gearhb::HarmonicBalance one_sided_clearance(int H = 12) {
  using Eigen::VectorXd;
  const gearhb::LinearSystem s = unit_oscillator(0.1, 1.0);
  gearhb::UnilateralContact c{VectorXd::Ones(1), 4.0, -1.0, VectorXd::Zero(2 * H + 1)};
  return gearhb::HarmonicBalance(s, {c}, gearhb::Excitation{VectorXd::Zero(1), VectorXd::Constant(1, 0.5),
                                                            VectorXd::Zero(1)}, H);
}
inline gearhb::SweepOptions one_sided_clearance_range() {
  gearhb::SweepOptions o;
  o.omega_min = 0.5, o.omega_max = 3.0;
  return o;
}

}  // namespace test_models
