#pragma once
// Stability of a periodic solution by Hill's method.
//
// A perturbation p(t) = e^{lambda t} sum_k (pc_k cos k theta + ps_k sin k theta)
// of the harmonic-balance solution satisfies, to the order kept,
//
//   ( lambda^2 D2 + lambda D1 + D0 ) P = 0,
//   D2 = I (x) M,   D1 = 2 (Nabla (x) M) + I (x) C,   D0 = dR/dX  (the HB Jacobian),
//
// where Nabla is the time derivative in the real Fourier basis
// (d/dt of a cos + b sin = k omega (b cos - a sin)). The 2 n (2H+1) eigenvalues of
// this quadratic problem approximate the Floquet exponents, each repeated with
// shifts i k omega. Selection criterion: keep the 2n eigenvalues with the smallest
// |Im lambda| (those whose eigenvectors are dominated by the retained
// low harmonics; Lazarus & Thomas, C. R. Mecanique 338 (2010) 510-517;
// Moore, "Floquet theory as a computational tool", SIAM J. Numer. Anal. 2005),
// plus every eigenvalue with |Im lambda| <= 0.51 omega: at a period doubling the
// multipliers are real negative, their exponents sit at Im = +-omega/2 (shifted by
// the truncation error either way) and there are more of them than slots;
// without this Hill called period-doubled orbits stable (ch. 6, against GSL
// Floquet multipliers).
// The eigenproblem is solved for mu = lambda / omega (time in radians of forcing
// phase), which keeps the companion matrix balanced for stiff gear models.
// The solution is stable when every selected exponent has Re(lambda) < 0
// (within a tolerance relative to omega).
#include <complex>

#include <Eigen/Dense>

namespace gearhb {

struct HillResult {
  Eigen::VectorXcd exponents;   // the 2n selected Floquet exponents (more if tied)
  double max_real = 0.0;        // largest real part among them
  bool stable = true;
};

// JX: HB Jacobian dR/dX (harmonic-major layout, see harmonic_balance.hpp).
HillResult hill_stability(const Eigen::MatrixXd& JX, const Eigen::MatrixXd& M,
                          const Eigen::MatrixXd& C, double omega, int H,
                          double relative_tolerance = 1e-7);

}  // namespace gearhb
