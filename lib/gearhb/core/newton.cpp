#include "gearhb/core/newton.hpp"

#include <cmath>
#include <sstream>

namespace gearhb {

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
