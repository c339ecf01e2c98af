#include "gearhb/core/newton.hpp"

#include <cmath>
#include <sstream>

namespace gearhb {

DenseLinearization::DenseLinearization(Eigen::MatrixXd J, Eigen::VectorXd dRdomega, const Scaling& s) {
  const Eigen::Index n = J.rows();
  A_.resize(n + 1, n + 1);
  A_.topLeftCorner(n, n) = (J * s.x.asDiagonal()) / s.residual;
  A_.block(0, n, n, 1) = dRdomega * (s.omega / s.residual);
  A_.row(n).setZero();
}

bool DenseLinearization::solve_bordered(const Eigen::VectorXd& row, const Eigen::VectorXd& rhs,
                                        Eigen::VectorXd& dy) const {
  if (!(row.size() == factored_row_.size() && row == factored_row_)) {
    Eigen::MatrixXd A = A_;
    A.row(A.rows() - 1) = row.transpose();
    lu_.compute(A);
    factored_row_ = row;
  }
  dy = lu_.solve(rhs);
  return dy.allFinite();
}

std::unique_ptr<Linearization> ParametricProblem::linearize(const Eigen::VectorXd& X, double omega,
                                                            const Scaling& s, Eigen::VectorXd& R,
                                                            Eigen::VectorXd& dRdomega) const {
  Eigen::MatrixXd J;
  evaluate(X, omega, R, &J, &dRdomega);
  return std::make_unique<DenseLinearization>(std::move(J), dRdomega, s);
}

NewtonReport newton_solve(const ParametricProblem& p, Eigen::VectorXd& X, double omega,
                          const Scaling& s, const NewtonOptions& opt) {
  NewtonReport rep;
  const int n = p.size();
  Eigen::VectorXd R(n);
  Eigen::MatrixXd J(n, n);
  for (int it = 0; it <= opt.max_iterations; ++it) {
    p.evaluate(X, omega, R, &J, nullptr);
    rep.residual = R.cwiseAbs().maxCoeff() / s.residual;
    rep.iterations = it;
    if (!std::isfinite(rep.residual)) {
      rep.message = "residual is not finite";
      return rep;
    }
    if (rep.residual < opt.tolerance && it > 0 && rep.step < opt.tolerance) {
      rep.converged = true;
      rep.message = "converged";
      return rep;
    }
    if (it == opt.max_iterations) break;
    // Scaled system: (J diag(x) / r) dy = -R / r, dX = diag(x) dy.
    const Eigen::MatrixXd Js = (J * s.x.asDiagonal()) / s.residual;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(Js);
    const Eigen::VectorXd dy = lu.solve(-R / s.residual);
    if (!dy.allFinite()) {
      rep.message = "singular Jacobian";
      return rep;
    }
    rep.step = dy.cwiseAbs().maxCoeff();
    X += s.x.cwiseProduct(dy);
    // An exact linear problem converges in one step; accept a tiny residual at once.
    if (rep.step < opt.tolerance && rep.residual < opt.tolerance) {
      rep.converged = true;
      rep.iterations = it + 1;
      rep.message = "converged";
      return rep;
    }
  }
  std::ostringstream os;
  os << "no convergence in " << opt.max_iterations << " iterations (residual " << rep.residual
     << ", last step " << rep.step << ")";
  rep.message = os.str();
  return rep;
}

}  // namespace gearhb
