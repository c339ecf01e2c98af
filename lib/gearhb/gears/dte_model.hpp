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
// closed one (hb/frequency_sweep.hpp linear_first_guess).
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
#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct DteGear {
  double me = 0.0;       // [kg]
  double kc = 0.0;       // [N/m]
  double c = 0.0;        // [N s/m]
  double F0 = 0.0;       // [N]
  Eigen::VectorXd ste;   // [e0, a1, b1, ...] [m]
};

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

// The parametric mesh stiffness k(theta) = F0 / e_H(theta), e_H the STE cut to H harmonics.
double dte_parametric_stiffness(const DteGear& g, int H, double theta);

// Closed form while the contact stays closed (linear, constant model): coefficients of x,
//   X0 = F0 / kc - e0,  X_k = -kc E_k / (kc - (k w)^2 me + i k w c).
Eigen::VectorXd dte_closed_contact(const DteGear& g, int H, double omega);

// Penetration u = x + e (coefficients, 2H+1) of a harmonic-balance solution X.
Eigen::VectorXd dte_penetration(const DteGear& g, const Eigen::VectorXd& X);

// Mean contact force over the period, (kc / 2 pi) sum_I int_I u dtheta, integrated
// in closed form over the exact contact intervals I (hb/contact.hpp); for the
// parametric model (1 / 2 pi) sum_I int_I k(theta) d dtheta by Gauss-Legendre
// quadrature between the exact crossings. At a harmonic-balance solution it must
// equal F0 (the static balance, thesis §8.1).
double dte_mean_contact_force(const DteGear& g, const Eigen::VectorXd& X, DteModel model = DteModel::constant);

// RMS of the oscillating part of a real Fourier series: sqrt(sum_k (a_k^2 + b_k^2) / 2)
// (thesis §8.2 prints sqrt(v'v)/length(v) for sqrt(v'v/length(v))).
double rms_ac(const Eigen::VectorXd& coeffs);

}  // namespace gearhb
