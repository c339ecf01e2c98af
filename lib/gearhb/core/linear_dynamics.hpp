#pragma once
// Linear structural dynamics: M x'' + C x' + K x = f(t).
//  - Rayleigh damping C = alpha M + beta K;
//  - frequency response X(w) = (K - w^2 M + i w C)^{-1} F (thesis §3, Fig. 7);
//  - modal analysis: K phi = w^2 M phi with mass-normalised modes,
//    Phi' M Phi = I and Phi' K Phi = diag(w^2) (thesis §4.1).
#include <complex>
#include <string>

#include <Eigen/Dense>

namespace gearhb {

struct LinearSystem {
  Eigen::MatrixXd M, C, K;   // mass [kg], damping [N s/m], stiffness [N/m] (or rotational)
  int dofs() const { return int(M.rows()); }
  // Throws std::invalid_argument unless M, C, K are square, of equal size, M
  // symmetric positive definite.
  void check() const;
};

// C = alpha M + beta K  (alpha [1/s], beta [s]).
Eigen::MatrixXd rayleigh_damping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double alpha,
                                 double beta);

// Complex amplitude X of the steady response to Re(F e^{i w t}).
Eigen::VectorXcd frequency_response(const LinearSystem& sys, const Eigen::VectorXcd& F, double omega);

struct Modes {
  Eigen::VectorXd omega;   // natural frequencies [rad/s], ascending
  Eigen::MatrixXd Phi;     // mass-normalised mode shapes, one per column
};
// Generalised symmetric eigenproblem K phi = w^2 M phi (Eigen's
// GeneralizedSelfAdjointEigenSolver, whose eigenvectors are M-normalised).
Modes modal_analysis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

// Eigenvalues of a general real square matrix: Eigen's real Schur iteration
// (EigenSolver), and if it does not converge (it can on a matrix with repeated
// complex pairs, e.g. the monodromy matrix of a gear pair whose two supports have
// the same natural frequency) the complex Schur iteration (ComplexEigenSolver).
// Throws std::runtime_error("<where>: eigensolver failed ...") if both fail.
Eigen::VectorXcd general_eigenvalues(const Eigen::MatrixXd& A, const std::string& where);

// Eigen-decomposition A = V diag(lambda) V^-1 of a general real matrix (EigenSolver with
// eigenvectors; V^-1 by partial-pivoting LU). False, and `out` untouched, when the real
// Schur iteration does not converge.
struct EigenDecomposition {
  Eigen::VectorXcd values;          // lambda
  Eigen::MatrixXcd vectors;         // V (columns)
  Eigen::MatrixXcd inverse_vectors; // V^-1
};
bool eigen_decomposition(const Eigen::MatrixXd& A, EigenDecomposition& out);

// The smallest singular value of a complex matrix (Jacobi SVD): sigma_min(A - mu I) is
// how far mu is from being an eigenvalue of A (the check of an eigensolver's output).
// One compiled instance, so that tests do not each instantiate the SVD.
double smallest_singular_value(const Eigen::MatrixXcd& A);

// Balancing (Parlett & Reinsch 1969, as LAPACK's dgebal without permutation):
// replaces A by D^-1 A D, D = diag(d) with powers of 2, so that the off-diagonal
// norms of every row and its column are within a factor 2; returns d. Eigenvalues
// are unchanged and the eigenvectors of a matrix that mixes units (metres beside
// metres per second beside unit oscillators) are well scaled.
Eigen::VectorXd balance(Eigen::MatrixXd& A);

}  // namespace gearhb
