#pragma once
// A planetary (epicyclic) gear set: the linear model of Lin & Parker (1999, "Analytical
// characterization of the unique properties of planetary gear free vibration", J. Vib.
// Acoust. 121:316), the mode classification it proves, and the mesh phases of Parker &
// Lin (2004, J. Mech. Des. 126:365).
//
// Coordinates (carrier frame, rotating with the carrier at carrier_speed): three per body,
// ordered carrier, ring, sun, planet 1..N (set_dofs = 3 (N + 3)).
//   central member j = c, r, s:  x_j, y_j (translations), u_j = r_j theta_j (rotation as the
//                                 displacement of its base circle; the carrier's r_c is the
//                                 radius of the planet centres);
//   planet n:                    zeta_n (radial), eta_n (tangential), u_n = r_p theta_n,
//                                 at the angle psi_n of its centre from the carrier's x axis.
// Mesh deflections along the lines of action (positive = teeth compressed), with
// psi_sn = psi_n - alpha_s and psi_rn = psi_n + alpha_r (LP 1999 eqs. (1)-(3)):
//   delta_sn = -x_s sin psi_sn + y_s cos psi_sn - zeta_n sin alpha_s - eta_n cos alpha_s + u_s + u_n
//   delta_rn = -x_r sin psi_rn + y_r cos psi_rn + zeta_n sin alpha_r - eta_n cos alpha_r + u_r - u_n
// (each follows from the base-circle tangent points: README of programs/gearhb_planetary),
// planet bearing n (radial and tangential, stiffness k_p):
//   x_c cos psi_n + y_c sin psi_n - zeta_n,   -x_c sin psi_n + y_c cos psi_n + u_c - eta_n,
// central bearings k_j (x_j^2 + y_j^2)/2 + k_ju u_j^2/2.
//
// Equation of motion: M q'' + Omega G q' + (K_b + K_m - Omega^2 K_Omega) q = f, with the
// gyroscopic G (blocks [0 -2m; 2m 0] on every body's translations) and the centripetal
// softening K_Omega (diag(m, m, 0)) of the rotating frame (LP 1999 eq. (4)). Default:
// carrier_speed = 0, i.e. without them, as LP's Table 1.
//
// Units SI; the rotational masses as I / r^2 [kg] and the torsional stiffnesses as
// k_u = k_theta / r^2 [N/m], so that every coordinate is a length.
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace gearhb {

struct CentralMember {
  double mass = 0.0;              // m [kg]
  double inertia_r2 = 0.0;        // I / r^2 [kg]
  double bearing = 0.0;           // radial bearing k_j [N/m] (x and y)
  double torsional = 0.0;         // torsional stiffness k_ju [N/m] (0: free to rotate)
};

struct PlanetarySet {
  CentralMember carrier, ring, sun;
  double planet_mass = 0.0, planet_inertia_r2 = 0.0;   // [kg]
  double planet_bearing = 0.0;                          // k_p [N/m], radial and tangential
  double sun_mesh = 0.0, ring_mesh = 0.0;               // k_sp, k_rp [N/m] (mean mesh stiffness)
  double sun_pressure_angle = 0.0, ring_pressure_angle = 0.0;   // alpha_s, alpha_r [rad]
  std::vector<double> planet_angles;                    // psi_n [rad], psi_1 = 0 by convention
  double carrier_speed = 0.0;                           // Omega [rad/s] (0: no gyroscopic terms)

  int planets() const { return int(planet_angles.size()); }
  int dofs() const { return 3 * (planets() + 3); }
  // Throws std::invalid_argument naming the field that is not physical.
  void check() const;
};

// psi_n = 2 pi (n - 1) / N.
std::vector<double> equally_spaced(int planets);

// Lin & Parker 1999's example set (their Table 1 data; reference/lin_parker_1999.md) with
// N equally spaced planets: sun, ring, carrier, planet masses 0.4, 2.35, 5.43, 0.66 kg,
// I / r^2 0.39, 3.0, 6.29, 0.61 kg, every bearing 1e8 N/m, ring torsion 1e9 N/m (sun and
// carrier free), k_sp = k_rp = 5e8 N/m, pressure angles 24.6 deg.
PlanetarySet lin_parker_1999_set(int planets);

// Indices of the coordinates (carrier = 0, ring = 1, sun = 2, planet n = 3 + n, n from 0).
enum class Body { carrier = 0, ring = 1, sun = 2 };
inline int coordinate(Body b, int k) { return 3 * int(b) + k; }          // k: 0 = x, 1 = y, 2 = u
inline int planet_coordinate(int n, int k) { return 3 * (3 + n) + k; }  // k: 0 = zeta, 1 = eta, 2 = u

// The mesh deflections as rows: delta_sn = sun_mesh_direction(s, n)' q (and the ring's).
// These are the contact normals of the meshes.
Eigen::VectorXd sun_mesh_direction(const PlanetarySet& s, int n);
Eigen::VectorXd ring_mesh_direction(const PlanetarySet& s, int n);

struct PlanetaryMatrices {
  Eigen::MatrixXd M;          // diag(m, m, I/r^2) per body
  Eigen::MatrixXd K_bearing;  // K_b: central bearings and the planet bearings
  Eigen::MatrixXd K_mesh;     // K_m: sum_n k_sp d_sn d_sn' + k_rp d_rn d_rn'
  Eigen::MatrixXd G;          // gyroscopic (skew), multiplies Omega q'
  Eigen::MatrixXd K_omega;    // centripetal, K - Omega^2 K_omega
  // K_b + K_m - Omega^2 K_Omega at the set's carrier_speed
  Eigen::MatrixXd stiffness(double carrier_speed) const { return K_bearing + K_mesh - carrier_speed * carrier_speed * K_omega; }
};
PlanetaryMatrices planetary_matrices(const PlanetarySet& s);

// Lin & Parker's three mode types (equally spaced planets); `mixed` where a mode is none of
// them (unequally spaced planets, or a gyroscopic set).
enum class ModeType { rotational, translational, planet, mixed };
std::string to_string(ModeType t);

struct PlanetaryMode {
  double omega = 0.0;          // natural frequency [rad/s]
  ModeType type = ModeType::mixed;
  int multiplicity = 1;        // how many modes share this frequency (relative 1e-7)
  int group = 0;               // 0-based index of the frequency group
  Eigen::VectorXd shape;       // mass-normalised
};

// The classification of one mass-normalised mode shape phi (phi' M phi = 1), by its kinetic
// energy fractions: planet mode when the central members hold less than `tol` of it;
// rotational when their translations hold less than `tol` and every planet moves as the
// first (relative difference below sqrt(tol)); translational when their rotations hold
// less than `tol`; else mixed.
ModeType classify_mode(const PlanetarySet& s, const Eigen::MatrixXd& M, const Eigen::VectorXd& phi,
                       double tol = 1e-9);

// Natural frequencies and modes at carrier_speed = 0 (K phi = omega^2 M phi, ascending):
// each mode with its type, and the modes of one frequency (within 1e-7 of the largest
// frequency of the set) grouped with their multiplicity. A group whose modes do not all
// have one type is mixed (every mode of it).
std::vector<PlanetaryMode> planetary_modes(const PlanetarySet& s);

// Natural frequencies [rad/s] of the rotating set at carrier speed Omega (the gyroscopic
// eigenproblem in first-order form; the positive imaginary parts, ascending): the
// Campbell diagram's points.
Eigen::VectorXd natural_frequencies_at_speed(const PlanetarySet& s, double carrier_speed);

// The set's drawing (standard centre distances: z_r = z_s + 2 z_p, one module, no shifts).
struct PlanetaryTeeth {
  int sun = 0, planet = 0, ring = 0;   // z_s, z_p, z_r
  double module = 0.0;                 // m [m]
  double addendum = 1.0;               // h_a* (units of m): the planets' tip circles
  double centre_distance() const { return 0.5 * (sun + planet) * module; }   // a [m]
};

// The first planet (0-based) that cannot be assembled at its angle: with sun and ring
// meshing planet 1, planet n fits where (z_s + z_r) psi_n / (2 pi) is a whole number
// (within `tol` of a tooth pitch); -1 if every planet fits. For equally spaced planets
// this is the condition that (z_s + z_r) / N is a whole number.
int planet_not_assembling(const PlanetaryTeeth& t, const std::vector<double>& planet_angles, double tol = 1e-4);

// The smallest clearance between the tip circles of neighbouring planets [m]:
// 2 a sin(dpsi / 2) - (z_p + 2 h_a*) m over each pair of neighbours (< 0: they collide).
// Infinite for one planet.
double planet_tip_clearance(const PlanetaryTeeth& t, const std::vector<double>& planet_angles);

}  // namespace gearhb
