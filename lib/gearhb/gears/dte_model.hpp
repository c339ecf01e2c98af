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
// The model has no spring to ground (the shafts are rigid in torsion). The
// harmonic-balance first guess needs a finite open-contact solution, so the
// model carries a vanishing torsional stiffness k_t = regularisation x kc
// (1e-12 by default): it shifts the mean contact force by k_t X0 ~ 1e-12 F0.
#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct DteGear {
  double me = 0.0;       // [kg]
  double kc = 0.0;       // [N/m]
  double c = 0.0;        // [N s/m]
  double F0 = 0.0;       // [N]
  Eigen::VectorXd ste;   // [e0, a1, b1, ...] [m]
  double regularisation = 1e-12;   // k_t / kc
};

double equivalent_mass(double I1, double I2, double r1, double r2);
double mesh_damping(double zeta, double kc, double me);   // 2 zeta sqrt(kc me)

// The STE coefficients cut (or zero-padded) to H harmonics.
Eigen::VectorXd ste_harmonics(const DteGear& g, int H);

// The harmonic-balance model with H harmonics (the STE truncated to H, thesis §8.2).
HarmonicBalance dte_harmonic_balance(const DteGear& g, int H, int N = 0,
                                     ContactQuadrature q = ContactQuadrature::exact);

// Closed form while the contact stays closed (linear): coefficients of x,
//   X0 = (F0 - kc e0) / (k_t + kc),  X_k = -kc E_k / (k_t + kc - (k w)^2 me + i k w c).
Eigen::VectorXd dte_closed_contact(const DteGear& g, int H, double omega);

// Penetration u = x + e (coefficients, 2H+1) of a harmonic-balance solution X.
Eigen::VectorXd dte_penetration(const DteGear& g, const Eigen::VectorXd& X);

// Mean contact force over the period, (kc / 2 pi) sum_I int_I u dtheta, integrated
// in closed form over the exact contact intervals I (hb/contact.hpp). At a
// harmonic-balance solution it must equal F0 (the static balance, thesis §8.1).
double dte_mean_contact_force(const DteGear& g, const Eigen::VectorXd& X);

// RMS of the oscillating part of a real Fourier series: sqrt(sum_k (a_k^2 + b_k^2) / 2)
// (thesis §8.2 prints sqrt(v'v)/length(v) for sqrt(v'v/length(v))).
double rms_ac(const Eigen::VectorXd& coeffs);

}  // namespace gearhb
