#pragma once
// The meshes of a planetary set over time (gears/sets/planetary.hpp): each sun-planet and
// ring-planet mesh a unilateral contact along its line of action (contact.hpp; normal =
// sun_mesh_direction / ring_mesh_direction: the drive flank, loaded by the input torque),
// with a back flank at the mesh's backlash where one is given, its stiffness a rectangular
// wave over the mesh cycle shifted by its mesh phase (Parker & Lin 2004, "Mesh phasing relationships in
// planetary and epicyclic gears", J. Mech. Des. 126:365), the whole set as one
// HarmonicBalance at the mesh frequency (theta = mesh phase of sun-planet mesh 1).
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/sets/planetary.hpp"
#include "gearhb/hb/contact.hpp"
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

// A mesh kind's stiffness computed by a tooth model: k(theta) sampled at J >= 4 equal phases
// theta_j = 2 pi j / J of the mesh cycle [N/m] (the pair model's STE at the mesh's static
// force F: k_j = F / STE_j, as gearhb_gear's ste_<i>.csv). Its first H harmonics / k_mean,
// [1, a_1, b_1, ..., a_H, b_H] (H <= (J - 2) / 2; core/fourier.hpp periodic_fourier), k_mean
// the samples' mean.
struct SampledMesh {
  std::vector<double> samples;
  double mean() const;
  Eigen::VectorXd harmonics(int H) const;
};

// The meshes of the set. Mesh i = 0..2N-1: sun-planet meshes 1..N, then ring-planet meshes
// 1..N (the order of every per-mesh list and table).
struct PlanetaryMeshes {
  RectangularMesh sun, ring;
  // A mesh kind's computed stiffness replaces its rectangular wave where it has samples
  // (its mean is then also sun.mean / ring.mean).
  SampledMesh sun_computed, ring_computed;
  // The first H harmonics / k_mean of the stiffness of the sun (ring = false) or ring meshes.
  Eigen::VectorXd harmonics(bool ring, int H) const;
  MeshPhases phases;
  // Normal backlash b of each mesh along its line of action [m], 2N entries in mesh order;
  // infinite: no back flank (empty: none anywhere, the drive flanks only).
  std::vector<double> backlash;
  // The back flank's stiffness is the drive flank's wave lagging by back_phase mesh cycles
  // (it depends on the tooth thicknesses, as gamma_rs; an input).
  double back_phase = 0.0;
  // Or, from the teeth, per mesh kind: the back flank's wave is the mirror image of the drive
  // flank's, k_back(theta_i) = k(psi - theta_i) in the mesh's own phase theta_i = theta - 2 pi
  // gamma_i (the back pairs sit on the line of action mirrored about the line of centres,
  // met in the opposite order; mesh_dynamics.hpp back_flank_phase). psi [rad]; NaN: back_phase.
  double sun_back_mirror = NAN, ring_back_mirror = NAN;
  // Tangential position error e_n of planet n's pin on the carrier [m] (N entries, or empty:
  // none): the planet's centre sits displaced by e_n along eta_n, which opens both of its
  // meshes by e_n cos(alpha) (the eta_n terms of delta_sn and delta_rn): a constant gap
  // -e_n cos(alpha) in each.
  std::vector<double> pin_errors;
};

// The contacts: the drive flanks of meshes 0..2N-1 (contact i = mesh i), then the back
// flank of every mesh with a finite backlash, in mesh order. Drive flank of mesh i:
// normal d_i (its deflection direction), gap g_i = -e_n cos(alpha) (pin error), stiffness
// k_mean s(theta - 2 pi gamma_i), s the first H harmonics of the rectangular wave / k_mean
// (the harmonic-balance basis resolves no more). Back flank: normal -d_i, gap -b_i - g_i
// (it touches where the deflection d_i'q + g_i < -b_i), stiffness k_mean s(theta - 2 pi
// (gamma_i + back_phase)), or k_mean s(psi - theta + 2 pi gamma_i) with a mirror phase psi. Throws std::invalid_argument on more than kMaxContacts contacts.
std::vector<UnilateralContact> planetary_mesh_contacts(const PlanetarySet& s, const PlanetaryMeshes& m, int H);

// The contact index of each mesh's back flank (2N entries, -1: none), as planetary_mesh_contacts orders them.
std::vector<int> back_flank_contacts(const PlanetaryMeshes& m, int planets);

// What a mesh does over one period of an orbit X of the set's harmonic balance:
struct PlanetaryMeshOrbit {
  double force_max = 0.0;        // largest drive-flank force [N]
  double dynamic_factor = 0.0;   // K_v = max |N| / F0, N = drive force - back force over the period
  ContactState drive = ContactState::full, back = ContactState::open;
};
// Mesh i's orbit; F0 its static force. Sampled on 32 (2H + 1) phases (the stiffness varies);
// the flank states from the exact crossings (contact.hpp contact_state).
PlanetaryMeshOrbit planetary_mesh_orbit(const HarmonicBalance& hb, const std::vector<int>& back, const Eigen::VectorXd& X,
                                        int mesh, double F0);

// The largest dynamic factor over the meshes of a motion sampled in time (xs: the states, rows,
// `per_period` uniform samples a mesh period from phase 0, as TimeIntegrator::sample gives them):
// each mesh's N = drive-flank force - back-flank force by the model's contact law at each sample
// (back: back_flank_contacts), max over the meshes i and samples of |N| / F0[i]. The time
// integration's counterpart of planetary_mesh_orbit's dynamic_factor (a motion HB has no orbit of).
double planetary_sampled_dynamic_factor(const HarmonicBalance& hb, const std::vector<int>& back, const Eigen::MatrixXd& xs,
                                        int per_period, const std::vector<double>& F0);

// The static force of each mesh (2N, mesh order): the drive flanks closed at their mean
// stiffnesses, the back flanks open (the static part of that linear solution), averaged over
// the planets per mesh kind (sun, ring): the nominal share of the load, which the pin errors
// redistribute but do not change (the torque on the input is the sum of its meshes').
std::vector<double> planetary_static_mesh_forces(const HarmonicBalance& hb, int planets);

// The planet load-sharing factor of each planet n over a period: L_n = N F_n / sum_m F_m,
// F_n the largest drive-flank force of its sun-planet mesh (meshes[n].force_max). 1 for every
// planet where the load is shared equally.
std::vector<double> planet_load_sharing(const std::vector<PlanetaryMeshOrbit>& meshes, int planets);

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
