#pragma once
// Linear systems with a periodic stiffness, the test bench of stability methods
// (thesis ch. 2; chapter 2's program, "Hill against Floquet"):
//
//     M x'' + C x' + (K0 + k(theta) K1) x = 0,      theta = omega t,
//     k(theta) = k0 + sum_m (a_m cos m theta + b_m sin m theta).
//
// Mathieu's equation y'' + (a - 2 q cos 2t) y = 0 is n = 1, omega = 2,
// k = a - 2 q cos theta; Meissner's y'' + (a + b sgn(cos t)) y = 0 is omega = 1
// with the square wave k = a + b sgn(cos theta).
//
//  - linear_periodic_jacobian: the harmonic-balance Jacobian of the system at H
//    harmonics (what Hill's method sees: k enters only through its harmonics up
//    to 2H, by the product matrix of fourier.hpp). hill_stability (stability.hpp)
//    takes it as it takes a contact problem's.
//  - meissner_trace: the exact trace of Meissner's monodromy matrix (two
//    constant-stiffness half periods, each a closed-form transfer matrix);
//    stable iff |trace| < 2 (det = 1 without damping).
#include <Eigen/Dense>

namespace gearhb {

// kcoef = [k0, a1, b1, ..., aP, bP] (any P; harmonics above 2H are not seen).
Eigen::MatrixXd linear_periodic_jacobian(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                         const Eigen::MatrixXd& K0, const Eigen::MatrixXd& K1,
                                         const Eigen::VectorXd& kcoef, double omega, int H);

// Fourier coefficients [k0, a1, b1, ..., aP, bP] of a + b sgn(cos theta).
Eigen::VectorXd square_wave_stiffness(double a, double b, int P);

// Trace of the monodromy matrix of y'' + (a + b sgn(cos t)) y = 0 over 2 pi.
double meissner_trace(double a, double b);

}  // namespace gearhb
