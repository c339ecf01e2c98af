#include "gearhb/core/linear_dynamics.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gearhb {

void LinearSystem::check() const {
  const auto n = M.rows();
  if (n == 0 || M.cols() != n || C.rows() != n || C.cols() != n || K.rows() != n || K.cols() != n)
    throw std::invalid_argument("LinearSystem: M, C, K must be square and of equal size");
  if (!M.isApprox(M.transpose()))
    throw std::invalid_argument("LinearSystem: M must be symmetric");
  Eigen::LLT<Eigen::MatrixXd> llt(M);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument("LinearSystem: M must be positive definite");
}

Eigen::MatrixXd rayleigh_damping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double alpha,
                                 double beta) {
  return alpha * M + beta * K;
}

Eigen::VectorXcd frequency_response(const LinearSystem& sys, const Eigen::VectorXcd& F, double omega) {
  const std::complex<double> i(0.0, 1.0);
  Eigen::MatrixXcd D = (sys.K - omega * omega * sys.M).cast<std::complex<double>>() +
                       i * omega * sys.C.cast<std::complex<double>>();
  return D.partialPivLu().solve(F);
}

Modes modal_analysis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  if (es.info() != Eigen::Success) throw std::runtime_error("modal_analysis: eigensolver failed");
  Modes m;
  m.omega = es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  m.Phi = es.eigenvectors();
  return m;
}

bool eigen_decomposition(const Eigen::MatrixXd& A, EigenDecomposition& out) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() != Eigen::Success) return false;
  out.values = es.eigenvalues();
  out.vectors = es.eigenvectors();
  out.inverse_vectors = Eigen::PartialPivLU<Eigen::MatrixXcd>(out.vectors).inverse();
  return true;
}

double smallest_singular_value(const Eigen::MatrixXcd& A) {
  return Eigen::JacobiSVD<Eigen::MatrixXcd>(A).singularValues().minCoeff();
}

Eigen::VectorXcd general_eigenvalues(const Eigen::MatrixXd& A, const std::string& where) {
  if (!A.allFinite()) throw std::runtime_error(where + ": eigensolver given a non-finite matrix");
  Eigen::EigenSolver<Eigen::MatrixXd> real_schur(A, /*computeEigenvectors=*/false);
  if (real_schur.info() == Eigen::Success) return real_schur.eigenvalues();
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> complex_schur(A.cast<std::complex<double>>(), false);
  if (complex_schur.info() == Eigen::Success) return complex_schur.eigenvalues();
  throw std::runtime_error(where + ": eigensolver failed (real and complex Schur iterations did not converge, " +
                           std::to_string(A.rows()) + " x " + std::to_string(A.cols()) + " matrix)");
}

Eigen::VectorXd balance(Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  if (!A.allFinite()) return d;
  for (int sweep = 0; sweep < 100; ++sweep) {
    bool done = true;
    for (Eigen::Index i = 0; i < n; ++i) {
      double c = A.col(i).cwiseAbs().sum() - std::fabs(A(i, i));
      double r = A.row(i).cwiseAbs().sum() - std::fabs(A(i, i));
      if (c == 0.0 || r == 0.0) continue;
      const double s = c + r;
      double f = 1.0;
      while (c < 0.5 * r) c *= 4.0, f *= 2.0;
      while (c >= 2.0 * r) c *= 0.25, f *= 0.5;
      if ((c + r) / f < 0.95 * s) {
        done = false;
        d[i] *= f;
        A.row(i) /= f;
        A.col(i) *= f;
      }
    }
    if (done) break;
  }
  return d;
}

}  // namespace gearhb
