#pragma once
// Newton-Raphson for a residual R(X, omega) = 0 at fixed omega (thesis §2.1),
// and the interface every continuation-ready problem implements.
//
// Scaling. Gear problems mix micrometre displacements with 1e8 N/m stiffnesses;
// an unscaled Newton/arc-length then mixes numbers 14 orders apart (the thesis
// multiplied by 1e6 by hand). Every problem supplies a characteristic size of
// its unknowns, of omega and of its residual, derived from its own data (see
// HarmonicBalance::scaling); the solvers work in the scaled variables
// x/x_scale, omega/omega_scale, R/r_scale. No factor is tuned by hand.
#include <string>

#include <Eigen/Dense>

namespace gearhb {

struct Scaling {
  Eigen::VectorXd x;     // characteristic size of each unknown
  double omega = 1.0;    // characteristic size of omega
  double residual = 1.0; // characteristic size of the residual
};

// A square system of equations with one parameter omega.
class ParametricProblem {
 public:
  virtual ~ParametricProblem() = default;
  virtual int size() const = 0;
  // R(X, omega); if requested also dR/dX (size x size) and dR/domega.
  virtual void evaluate(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                        Eigen::MatrixXd* dRdX, Eigen::VectorXd* dRdw) const = 0;
};

struct NewtonOptions {
  double tolerance = 1e-10;   // on max|R|/r_scale and on max|dX|/x_scale
  int max_iterations = 30;
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;      // max|R| / r_scale at exit
  double step = 0.0;          // max|dX| / x_scale of the last update
  std::string message;        // why it stopped (human readable)
};

// Solve R(X, omega) = 0 for X, starting from X (updated in place).
NewtonReport newton_solve(const ParametricProblem& p, Eigen::VectorXd& X, double omega,
                          const Scaling& s, const NewtonOptions& opt = {});

}  // namespace gearhb
