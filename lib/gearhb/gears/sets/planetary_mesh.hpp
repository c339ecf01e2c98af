#pragma once
// The meshes of a planetary set over time (gears/sets/planetary.hpp): each sun-planet and
// ring-planet mesh a unilateral contact along its line of action (contact.hpp; normal =
// sun_mesh_direction / ring_mesh_direction, no gap: the drive flank, loaded by the input
// torque; the back flank is not modelled), its stiffness a rectangular wave over the mesh
// cycle shifted by its mesh phase (Parker & Lin 2004, "Mesh phasing relationships in
// planetary and epicyclic gears", J. Mech. Des. 126:365), the whole set as one
// HarmonicBalance at the mesh frequency (theta = mesh phase of sun-planet mesh 1).
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/sets/planetary.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// The rectangular wave of a mesh's stiffness over one mesh cycle theta in [0, 2 pi):
// two pairs in contact (k_double) over the first 2 pi (eps - 1), one pair (k_single) over
// the rest; eps the contact ratio in [1, 2]. Given by its mean k and k_double / k_single.
struct RectangularMesh {
  double mean = 0.0;            // k_mean [N/m]
  double contact_ratio = 1.0;   // eps in [1, 2]
  double ratio = 1.0;           // k_double / k_single >= 1 (1: constant stiffness)
  double single() const { return mean / (1.0 + (ratio - 1.0) * (contact_ratio - 1.0)); }
  double stiffness(double theta) const;   // k(theta), 2 pi-periodic
  // The first H harmonics of k(theta) / k_mean: [1, a_1, b_1, ..., a_H, b_H].
  Eigen::VectorXd harmonics(int H) const;
};

// The mesh phases gamma in [0, 1) of mesh cycle (the mesh of planet n lags planet 1's by
// gamma_n cycles), Parker & Lin 2004 for the sun rotating counter-clockwise relative to the
// carrier: gamma_sn = z_s psi_n / (2 pi), gamma_rn = gamma_rs - z_r psi_n / (2 pi), mod 1.
// gamma_rs, the phase between the ring and sun meshes of planet 1, depends on the tooth
// thicknesses (Parker & Lin 2004 eq. (10)); it is an input here.
struct MeshPhases {
  std::vector<double> sun, ring;
};
MeshPhases mesh_phases(const PlanetaryTeeth& t, const std::vector<double>& planet_angles, double ring_sun_phase);

struct PlanetaryMeshes {
  RectangularMesh sun, ring;
  MeshPhases phases;
};

// The contacts: sun-planet meshes 1..N, then ring-planet meshes 1..N; contact i's stiffness
// k_mean s(theta - 2 pi gamma_i), s the first H harmonics of the rectangular wave / k_mean
// (the harmonic-balance basis resolves no more).
std::vector<UnilateralContact> planetary_mesh_contacts(const PlanetarySet& s, const PlanetaryMeshes& m, int H);

// Modal damping of the mean system (every mesh closed at k_mean): C = M Phi diag(2 zeta
// omega) Phi' M.
Eigen::MatrixXd planetary_modal_damping(const PlanetarySet& s, double zeta);

// The set as a harmonic-balance model at the mesh frequency: M, C (modal, zeta), the
// bearings K_b, the meshes as contacts, the static load f0 (e.g. the input torque / r_b on
// the input's u), no other forcing. The set's sun_mesh and ring_mesh are replaced by the
// meshes' mean stiffnesses.
HarmonicBalance planetary_harmonic_balance(PlanetarySet s, const PlanetaryMeshes& m, double zeta,
                                           const Eigen::VectorXd& f0, int H);

}  // namespace gearhb
