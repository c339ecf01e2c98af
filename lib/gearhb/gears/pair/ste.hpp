#pragma once
// Static transmission error (STE) of a spur-gear pair over one mesh cycle,
// from the beam tooth model of thesis ch. 7.
//
// Model (thesis §7.1-7.6):
//  * each tooth is a cantilever from the root circle (radius rf) to the tip,
//    n_e equal elements of length h / n_e (h = ha + hf), nodes k = 0..n_e
//    counted from the root; bending stiffness E b s^3 / 12 with s either a
//    constant (6 mm in §7.4) or the involute thickness s(r) at a radius of the
//    element chosen by `ThicknessAt` (the text does not say which);
//  * the path of contact is cut into P positions per base pitch; at position
//    j = 0..P-1 the first pair touches at node k = j + 1 of the driving tooth
//    and node n_e + 1 - k of the driven one (so 2-22, 3-21, ... for n_e = 10),
//    and a second pair touches at k + P / n_e + 1 - k - P when k + P <= n_e
//    (30-38, 31-37, ... for P = 6). Thesis: P = 6, n_e = 10 (Figs. 46, 60) and
//    P = 8, n_e = 14 (Figs. 62-64); default n_e = floor(P * contact ratio);
//  * one pair: both roots clamped, the tooth force F on both contact nodes,
//    STE_elastic = sum of the two contact-node deflections (§7.4);
//  * two pairs: the driving roots are guided (rotation fixed) and moved by the
//    same X, the driven roots clamped, the contact nodes fused (translation
//    and rotation, §7.2); by linearity X = F / (k_A + k_B) with k_i the
//    reaction per unit X of pair i, and F_i = k_i X (§7.1);
//  * Hertz: Palmgren approach (hertz.hpp) added per contact or per tooth
//    (`HertzCount`), in the two-pair case at the force given by `TwoPairHertz`;
//  * tooth force F = T / r (thesis, pitch radius) or T / rb (normal force on
//    the line of action).
//
// The mean mesh stiffness is the mean over the cycle of F / STE (thesis §8.1,
// whose printed k = (T/r) V should read (T/r) / V: chapters/ch07_ste/README.md,
// "Thesis errors").
//
// Size bound. The four-beam model has 8 (n_e + 1) <= 16 P DOFs and is solved densely
// (the assembled K, the reduced T'KT and its LDLT factor: three matrices of
// (16 P)^2 doubles); P <= max_positions_per_base_pitch = 128 keeps that below
// 3 x 32 MiB and one mesh cycle below a few minutes (P solves of O((16 P)^3)).
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/tooth_fe.hpp"

namespace gearhb {

constexpr int max_positions_per_base_pitch = 128;

enum class ThicknessAt : int {
  element_root_node = 0,   // s at the node of the element nearer the root
  element_midpoint = 1,    // s at the element's mid radius
  element_tip_node = 2     // s at the node nearer the tip
};
enum class HertzCount : int { none = 0, per_contact = 1, per_tooth = 2 };
enum class TwoPairHertz : int {
  equal_split = 0,   // each contact at F / 2 (as in the constant-thickness case)
  fe_split_mean = 1, // mean of the approaches at the FE forces F_A, F_B
  consistent = 2     // force split solved so both pairs close the same X (nonlinear)
};
enum class ToothForce : int { over_pitch_radius = 0, over_base_radius = 1 };

struct SteModel {
  GearGeometry gear;
  double youngs_modulus = 207e9;          // E [Pa]
  bool constant_thickness = false;        // §7.4 model
  double constant_thickness_value = 6e-3; // [m]
  int positions_per_base_pitch = 8;       // P
  int tooth_elements = 0;                 // n_e; 0 = floor(P * contact ratio)
  ThicknessAt thickness_at = ThicknessAt::element_root_node;
  HertzCount hertz = HertzCount::per_tooth;
  TwoPairHertz two_pair_hertz = TwoPairHertz::equal_split;
  ToothForce tooth_force = ToothForce::over_pitch_radius;

  int elements() const;                   // n_e actually used
  double force(double torque) const;      // F [N] for torque T [N m]
};

// The tooth as a beam: node heights above the root circle and element EI.
struct ToothBeam {
  std::vector<double> x;    // [m], x[0] = 0 at the root circle
  std::vector<double> EI;   // [N m^2], one per element
  std::vector<double> s;    // thickness used per element [m]
};
ToothBeam tooth_beam(const SteModel& m);
// The same beam for any gear (each gear of a pair its own, issue 20): n_e equal
// elements from the root circle rf to the tip circle ra, element thickness s(r)
// (gear_geometry.hpp, with the profile shift) at the radius `at` picks, EI = E b s^3/12.
// Below the base circle (rf < rb, small or shifted-in gears) the involute and
// s(r) do not exist: there the beam keeps s(rb) (a constant-thickness root part,
// the straight-flank simplification of the potential-energy literature, e.g. Tian
// 2004 / Wan et al. 2014: the flank between root and base circle drawn as a
// straight line). constant_thickness > 0 replaces s(r) by that value (§7.4).
ToothBeam tooth_beam(const GearGeometry& g, double youngs_modulus, int elements, ThicknessAt at,
                     double constant_thickness = 0.0);

// One pair in contact at driving node k1, driven node k2 (counted from the
// roots): the 2-beam model of §7.4 with force F.
struct SinglePairSolve {
  BeamModel model;             // beams 0 (driving) and 1 (driven)
  BeamModel::Solution solution;
  double ste_elastic = 0.0;    // sum of the contact-node deflections [m]
};
SinglePairSolve solve_single_pair(const ToothBeam& tooth, int k1, int k2, double F);

// Two pairs (kA1, kA2) and (kB1, kB2): the 4-beam fused model of §7.2.
struct TwoPairSolve {
  BeamModel model;             // beams 0,1 (pair A) and 2,3 (pair B)
  BeamModel::Solution solution;  // for the X that carries the total force F
  double X = 0.0;              // elastic STE [m]
  double force_A = 0.0, force_B = 0.0;   // pair forces [N]
  double stiffness_A = 0.0, stiffness_B = 0.0;   // k_i [N/m]
};
TwoPairSolve solve_two_pairs(const ToothBeam& tooth, int kA1, int kA2, int kB1, int kB2, double F);

struct MeshPosition {
  double phase = 0.0;           // j / P in [0, 1)
  int pairs = 1;
  int kA1 = 0, kA2 = 0, kB1 = -1, kB2 = -1;   // contact nodes from the roots
  double force_A = 0.0, force_B = 0.0;        // [N]
  double elastic = 0.0, hertz = 0.0, ste = 0.0;   // [m]
  double elastic_linear = 0.0;      // FE elastic STE with the linear force split [m]
  double elastic_closed_form = 0.0; // the same from the stepped-beam formulas [m]
};
// The P positions of one mesh cycle with their contact nodes and pair count
// (phase, pairs, kA1, kA2, kB1, kB2; nothing solved yet). Throws if P is outside
// [2, max_positions_per_base_pitch] or n_e is not in [P, 2P).
std::vector<MeshPosition> mesh_positions(const SteModel& m);
// The STE at every position of mesh_positions(m) for torque T [N m].
std::vector<MeshPosition> ste_over_mesh_cycle(const SteModel& m, double torque);

// Mean of F / STE over the positions [N/m].
double mean_mesh_stiffness(const std::vector<MeshPosition>& cycle, double F);

// Fourier coefficients [a0, a1, b1, ..., aH, bH] of the sampled STE period (via
// the FFTW-based Aft), ste(phase) = a0 + sum a_k cos(2 pi k phase) + b_k sin(...),
// H = the largest the P samples carry (N >= 2H + 2).
Eigen::VectorXd ste_fourier(const std::vector<MeshPosition>& cycle, int* H_out = nullptr);

}  // namespace gearhb
