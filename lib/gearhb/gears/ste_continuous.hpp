#pragma once
// Static transmission error with the load moving continuously along the teeth
// (thesis ch. 7 beam model, refined for the dynamics of ch. 8).
//
// Chapter 7 reads the STE at P positions per base pitch, the load sitting on a
// beam node at each (8 positions, 14 elements: 8 samples of the mesh cycle, so
// at most 3 harmonics). The dynamics of ch. 8 with H = 5 harmonics needs more.
// Here the same beams (tooth_beam: root circle to tip, one EI per element) carry
// the load anywhere along the tooth:
//
//  * kinematics: the contact point runs along the line of action A -> E at
//    constant speed (rb omega), one base pitch pb per mesh cycle. At mesh phase
//    phi in [0, 1) pair A touches at s = phi pb from A, pair B (if s + pb <= AE)
//    at s + pb. Each contact point meets the driving tooth at radius r1(s) and
//    the driven one at r2(s) (gear_geometry.hpp contact_radii); the load height
//    on the beam is r - rf.
//  * a load between nodes: the point force F at height a inside element e
//    (xi = (a - x_e)/L_e) enters as the consistent nodal loads N(xi)^T F, with the
//    cubic Hermite shape functions of the beam element
//        N1 = 1 - 3 xi^2 + 2 xi^3,  N2 = L (xi - 2 xi^2 + xi^3),
//        N3 = 3 xi^2 - 2 xi^3,      N4 = L (xi^3 - xi^2),
//    (a moment M as N'(xi)^T M) and the deflection and rotation at the load
//    point are read the same way, w(a) = N(xi) q_e, theta(a) = N'(xi) q_e.
//    The nodal values are exact for a stepped Euler-Bernoulli beam; inside the
//    loaded element the cubic misses the exact elastic line by O((L_e/a)^3).
//  * each tooth is summarised by its 2x2 flexibility at the load point
//    (w, theta per unit force and moment), root clamped;
//  * one pair: STE_elastic = F (G1_ww + G2_ww), the two deflections (ch. 7 §7.4);
//  * two pairs: each pair is the fused beam of §7.2 (driving root guided,
//    driven root clamped, translation and rotation continuous through the
//    contact, the driven tooth's frame turned by 180 deg: w -> -w, theta -> theta).
//    Cutting at the contact, the interface force and moment v = (V, M) obey
//    (G1 + D G2 D) v = (X, 0), D = diag(1, -1), so the pair stiffness is
//    k = [(G1 + D G2 D)^-1]_00; the pairs share F as k_A : k_B, X = F/(k_A + k_B);
//  * Hertz: as in ch. 7 (SteModel::hertz, two_pair_hertz equal_split or
//    fe_split_mean; the consistent split is not offered here).
// At loads on nodes the result equals ch. 7's FE exactly (unit tests).
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/ste.hpp"

namespace gearhb {

// Flexibility of a tooth (root clamped) at height a above the root circle:
// [[w/F, w/M], [theta/F, theta/M]] by the FE with Hermite shape functions.
Eigen::Matrix2d tooth_flexibility(const ToothBeam& tooth, double a);

// Stiffness V/X of the fused pair (driving tooth loaded at a1, driven at a2).
double fused_pair_stiffness(const ToothBeam& tooth, double a1, double a2);

// One pair alone touching at the point s from A of the path of contact (0 <= s <= AE):
// the deflections of both teeth (roots clamped) at their load heights under F [m],
// and that plus Hertz (SteModel::hertz contacts at F) [m].
double single_pair_elastic(const SteModel& m, const ToothBeam& tooth, double s, double F);
double single_pair_ste(const SteModel& m, const ToothBeam& tooth, double s, double F);

struct StePoint {
  double phase = 0.0;              // mesh phase in [0, 1)
  int pairs = 1;
  double a1A = 0, a2A = 0;         // load heights of pair A on driving / driven tooth [m]
  double a1B = -1, a2B = -1;       // pair B (-1 when one pair)
  double force_A = 0, force_B = 0; // [N]
  double elastic = 0, hertz = 0, ste = 0;   // [m]
};

// STE at `samples` uniform phases of one mesh cycle for torque T [N m].
std::vector<StePoint> ste_continuous(const SteModel& m, double torque, int samples);

// The STE values of a cycle (ch. 7's positions or the continuous points) [m].
std::vector<double> ste_values(const std::vector<MeshPosition>& cycle);
std::vector<double> ste_values(const std::vector<StePoint>& cycle);

// Real Fourier coefficients [a0, a1, b1, ..., aH, bH] of one uniformly sampled
// period, e(phase) = a0 + sum a_k cos(2 pi k phase) + b_k sin(2 pi k phase); the
// harmonics above what the samples carry (N < 2H + 2) are zero.
Eigen::VectorXd periodic_fourier(const std::vector<double>& samples, int H);

// Mean over the samples of F / e [N/m] (thesis §8.1: k = (T/r)/V, misprinted (T/r) V).
double mean_stiffness(const std::vector<double>& ste, double F);

}  // namespace gearhb
