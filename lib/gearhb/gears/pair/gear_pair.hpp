#pragma once
// A spur-gear pair with 6 DOFs and an external-forcing mesh (thesis ch. 6, §6.1-6.2).
//
// DOFs q = [x1, y1, th1, x2, y2, th2]: translation of each gear centre on its
// shaft springs (kx, ky) and rotation on a torsional spring (kth). The mesh
// deflection along the line of action (thesis §6.1)
//
//     Delta = T2 q,   T2 = [cos a, -sin a, rb1, -cos a, sin a, -rb2]
//
// (Delta > 0: the teeth are pressed together; rigid rolling rb1 th1 = rb2 th2
// gives Delta = 0, i.e. th2 is measured in the sense opposite to th1). The
// mesh force N = max(kc Delta, 0) acts on the gears as the generalised force
// T1 N with T1 = [-cos a, sin a, -rb1, cos a, -sin a, rb2]' = -T2', so
//
//     M q'' + C q' + K q = F(t) + T1 max(kc T2 q, 0),
//
// and while the teeth stay in contact the stiffness is K + Kc with
// Kc = -T1 kc T2 = kc T2' T2 (symmetric, rank one). In the library's contact
// convention (harmonic_balance.hpp: + n max(kc (g + n'x), 0) on the left) this
// is UnilateralContact{normal = T2', kc, gap = 0}.
#include <Eigen/Dense>

#include "gearhb/hb/contact.hpp"
#include "gearhb/core/linear_dynamics.hpp"

namespace gearhb {

struct GearPairParameters {
  double pressure_angle_deg = 24.6;       // pressure angle [deg]
  double I1 = 0.39, m1 = 0.4, rb1 = 0.0774;   // gear 1: [kg m^2], [kg], base radius [m]
  double I2 = 0.61, m2 = 0.66, rb2 = 0.1003;  // gear 2
  double kx1 = 1e8, ky1 = 1e8, kth1 = 1e9;    // supports of gear 1 [N/m], [N/m], [N m/rad]
  double kx2 = 1e8, ky2 = 1e8, kth2 = 1e9;    // supports of gear 2
  double kc = 5e8;                        // mesh (contact) stiffness [N/m]
  double rayleigh_alpha = 0.0;            // C = alpha M + beta K [1/s]
  double rayleigh_beta = 1e-6;            // [s]
  bool damping_on_mesh = false;           // true: C = alpha M + beta (K + Kc)
};

// Row vector T2 (returned as a column) and T1 = -T2'.
Eigen::VectorXd gear_pair_T2(const GearPairParameters& p);
Eigen::VectorXd gear_pair_T1(const GearPairParameters& p);
// Diagonal mass and support-stiffness matrices, 6 x 6.
Eigen::MatrixXd gear_pair_mass(const GearPairParameters& p);
Eigen::MatrixXd gear_pair_support_stiffness(const GearPairParameters& p);
// Kc = -T1 kc T2 (closed-mesh stiffness to add to K).
Eigen::MatrixXd gear_pair_mesh_stiffness(const GearPairParameters& p);
// {M, C, K} with K the support stiffness only (the mesh is the contact).
LinearSystem gear_pair_system(const GearPairParameters& p);
// The mesh as a unilateral contact: normal = T2', kc, gap 0.
UnilateralContact gear_pair_mesh(const GearPairParameters& p);
// Static torque pair F0 = [0, 0, Fi, 0, 0, -Fi rb2/rb1] (power-conserving).
Eigen::VectorXd gear_pair_static_torque(const GearPairParameters& p, double Fi);

}  // namespace gearhb
