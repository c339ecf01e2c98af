// 6-DOF spur-gear pair (thesis ch. 6): see gear_pair.hpp.
#include "gearhb/gears/pair/gear_pair.hpp"

#include <cmath>

namespace gearhb {

Eigen::VectorXd gear_pair_T2(const GearPairParameters& p) {
  const double a = p.pressure_angle_deg * M_PI / 180.0;
  Eigen::VectorXd t(6);
  t << std::cos(a), -std::sin(a), p.rb1, -std::cos(a), std::sin(a), -p.rb2;
  return t;
}

Eigen::VectorXd gear_pair_T1(const GearPairParameters& p) {
  const double a = p.pressure_angle_deg * M_PI / 180.0;
  Eigen::VectorXd t(6);   // thesis §6.1, written out (not derived from T2)
  t << -std::cos(a), std::sin(a), -p.rb1, std::cos(a), -std::sin(a), p.rb2;
  return t;
}

Eigen::MatrixXd gear_pair_mass(const GearPairParameters& p) {
  Eigen::VectorXd d(6);
  d << p.m1, p.m1, p.I1, p.m2, p.m2, p.I2;
  return d.asDiagonal();
}

Eigen::MatrixXd gear_pair_support_stiffness(const GearPairParameters& p) {
  Eigen::VectorXd d(6);
  d << p.kx1, p.ky1, p.kth1, p.kx2, p.ky2, p.kth2;
  return d.asDiagonal();
}

Eigen::MatrixXd gear_pair_mesh_stiffness(const GearPairParameters& p) {
  return -gear_pair_T1(p) * p.kc * gear_pair_T2(p).transpose();
}

LinearSystem gear_pair_system(const GearPairParameters& p) {
  const Eigen::MatrixXd M = gear_pair_mass(p), K = gear_pair_support_stiffness(p);
  const Eigen::MatrixXd Kd = p.damping_on_mesh ? Eigen::MatrixXd(K + gear_pair_mesh_stiffness(p)) : K;
  return {M, rayleigh_damping(M, Kd, p.rayleigh_alpha, p.rayleigh_beta), K};
}

UnilateralContact gear_pair_mesh(const GearPairParameters& p) {
  return {gear_pair_T2(p), p.kc, 0.0, {}};
}

Eigen::VectorXd gear_pair_static_torque(const GearPairParameters& p, double Fi) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  f[2] = Fi;
  f[5] = -Fi * p.rb2 / p.rb1;
  return f;
}

}  // namespace gearhb
