#pragma once
// The 1-DOF gear mesh driven by its own static transmission error (thesis §8.1,
// Ozguven & Houser, J. Sound Vib. 121 (1988)):
//
//     me x'' + c x' + max( kc (x + e(t)), 0 ) = F0
//
// x   dynamic transmission error along the line of action [m] (x = r1 th1 - r2 th2
//     measured from the rigid-body position; the mesh deflection is x + e);
// e   the loaded STE, periodic with the mesh period, given by its real Fourier
//     coefficients [e0, a1, b1, ..., aH, bH] in the mesh phase theta = omega t
//     (omega = 2 pi f_mesh);
// me  = I1 I2 / (I1 r2^2 + I2 r1^2);   F0 = T / r;
// kc  = mean over the cycle of F0 / e(t) (thesis prints (T/r) V for (T/r)/V);
// c   = 2 zeta sqrt(kc me) (thesis prints zeta 2 sqrt(kc/me), which is not a damping).
//
// In the library's contact law (hb/contact.hpp) this is one DOF, normal 1,
// gap e0 and gap harmonics [0, a1, b1, ...]: penetration u = e(theta) + x.
// The model has no spring to ground (the shafts are rigid in torsion): K = 0,
// the open-contact linear solution does not exist and the sweep starts from the
// closed one (hb/first_point.hpp linear_first_guess).
//
// The parametric model it approximates (Ozguven & Houser; README of chapter 8):
//
//     me d'' + c d' + max( k(t) d, 0 ) = F0,      k(theta) = F0 / e(theta)
//
// d   the total mesh deflection along the line of action [m] (d -> e at low speed:
//     the static deflection under F0 is the STE). The stiffness varies with the
//     mesh phase; since k > 0 the teeth are in contact exactly where d > 0. In the
//     library: one contact, normal 1, no gap, stiffness kc s(theta) with the
//     profile s = F0 / (kc e(theta)) (hb/contact.hpp stiffness_profile), e the STE
//     truncated to the H harmonics of the balance as in the constant model.
//
// Both flanks (gearhb_gear; README of programs/gearhb_gear "Both flanks"). With a finite
// normal backlash b_n the back flanks touch where the drive-flank mesh deflection u (u = x + e
// for the constant model, u = d for the parametric one) falls below -(b_n + g_b(theta)):
//
//     back-flank penetration  -u - b_n - g_b(theta),   force along -u.
//
// Why u and not x: the drive and back flanks sit on the same two gear bodies, so whatever
// brings the bodies together along the drive line of action (the mesh deflection u) opens the
// back-flank clearance by the same amount; a rigid, unmodified back flank therefore closes at
// u = -b_n (the dead zone of Kahraman & Singh, J. Sound Vib. 142 (1990), in the deflection
// coordinate). g_b is the no-load separation of the back flanks (their tip relief), the drive
// flanks' no-load transmission error g (`nlte`) read at the mirrored mesh phase psi - theta:
// the back flanks mesh on the second line of action, as the drive flanks do in reverse, so the
// back contact passes the same configurations in the opposite order (phase psi - theta; psi from
// the tooth geometry, gears/dynamics/mesh_dynamics.hpp back_flank_phase). The parametric model's back
// stiffness is the drive one at that phase, k(psi - theta).
//
// Tip relief (`nlte`, empty = none): the parametric model then reads the elastic stiffness
// k_el(theta) = F0 / (e - g) and closes the drive flank where d > g(theta) (the relieved pair
// touches only once the bodies have approached by its relief), so d = e statically as before.
#include <cmath>

#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct DteGear {
  double me = 0.0;       // [kg]
  double kc = 0.0;       // [N/m]
  double c = 0.0;        // [N s/m]
  double F0 = 0.0;       // [N]
  Eigen::VectorXd ste;   // [e0, a1, b1, ...] [m]
  Eigen::VectorXd nlte;  // no-load transmission error g [g0, a1, b1, ...] [m] (tip relief); empty = 0
  double backlash = INFINITY;   // normal backlash b_n along the line of action [m]; infinite: no back flank
  double back_phase = 0.0;      // psi [rad]: the back flanks meet as the drive flanks do at phase psi - theta
};

inline bool has_back_flank(const DteGear& g) { return std::isfinite(g.backlash); }

// Which of the two models: the thesis' constant kc with the STE as excitation, or
// the parametric one with k(t) = F0 / e(t).
enum class DteModel { constant, parametric };
const char* to_string(DteModel m);   // "constant" | "parametric"

double equivalent_mass(double I1, double I2, double r1, double r2);
double mesh_damping(double zeta, double kc, double me);   // 2 zeta sqrt(kc me)

// The STE coefficients cut (or zero-padded) to H harmonics.
Eigen::VectorXd ste_harmonics(const DteGear& g, int H);

// The harmonic-balance model with H harmonics (the STE truncated to H, thesis §8.2),
// constant (unknown x) or parametric (unknown d). The parametric model needs the
// truncated STE positive over the whole cycle (std::invalid_argument otherwise).
HarmonicBalance dte_harmonic_balance(const DteGear& g, int H, int N = 0,
                                     ContactQuadrature q = ContactQuadrature::exact,
                                     DteModel model = DteModel::constant);

// The parametric mesh stiffness k(theta) = F0 / (e_H - g_H)(theta), e_H and g_H the STE and
// the no-load transmission error cut to H harmonics (g = 0 without tip relief).
double dte_parametric_stiffness(const DteGear& g, int H, double theta);

// The mesh as the library's contacts along the coordinate n' x (n = [1] for the 1-DOF model):
// the drive flank, then the back flank if the backlash is finite (see above), with the STE
// (constant model) or the no-load transmission error (parametric) cut to H harmonics.
std::vector<UnilateralContact> dte_mesh_contacts(const DteGear& g, int H, DteModel model, const Eigen::VectorXd& n);

// Closed form while the contact stays closed (linear, constant model): coefficients of x,
//   X0 = F0 / kc - e0,  X_k = -kc E_k / (kc - (k omega)^2 me + i k omega c).
Eigen::VectorXd dte_closed_contact(const DteGear& g, int H, double omega);

// Penetration u = x + e (coefficients, 2H+1) of a harmonic-balance solution X.
Eigen::VectorXd dte_penetration(const DteGear& g, const Eigen::VectorXd& X);

// Mean mesh force over the period: the drive flank's mean contact force minus the back
// flank's (contacts 0 and 1 of dte_harmonic_balance; hb/response.hpp mean_contact_force:
// closed form over the exact contact intervals for a constant kc, Gauss-Legendre between the
// exact crossings for the parametric k(theta)). At a harmonic-balance solution it must equal
// F0 (the static balance, thesis §8.1).
double dte_mean_contact_force(const HarmonicBalance& hb, const Eigen::VectorXd& X);

// RMS of the oscillating part of a real Fourier series: sqrt(sum_k (a_k^2 + b_k^2) / 2)
// (thesis §8.2 prints sqrt(v'v)/length(v) for sqrt(v'v/length(v))).
double rms_ac(const Eigen::VectorXd& coeffs);

}  // namespace gearhb
