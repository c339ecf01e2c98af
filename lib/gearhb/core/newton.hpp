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
#include <memory>
#include <string>

#include <Eigen/Dense>

namespace gearhb {

struct Scaling {
  Eigen::VectorXd x;     // characteristic size of each unknown
  double omega = 1.0;    // characteristic size of omega
  double residual = 1.0; // characteristic size of the residual
};

// The linearisation of a problem at one point (X, omega), able to solve the
// bordered systems of continuation (corrector and tangent), in the scaled
// variables y = [X / x_scale; omega / omega_scale]:
//
//   [ dR/dX diag(x_scale) / r_scale   dR/domega omega_scale / r_scale ] dy = [rhs_x]
//   [               row'  (n+1 entries: X part, then omega)           ]      [rhs_n]
class Linearization {
 public:
  virtual ~Linearization() = default;
  // dy (n+1), or false if the matrix is singular to working precision. A solve with the
  // row of the solve before reuses its factorization (a corrector's tangent: continuation.cpp).
  virtual bool solve_bordered(const Eigen::VectorXd& row, const Eigen::VectorXd& rhs,
                              Eigen::VectorXd& dy) const = 0;
  // Whether the last solve used a structured (not the dense) factorisation.
  virtual bool last_solve_structured() const { return false; }
  // `before`, a linearization of the same problem near this one (the iterate before in a
  // corrector, the point before on a branch), may lend its factorization to precondition
  // this one's solves (HarmonicBalance: GMRES on the condensed system in place of an LU).
  // Default: not used.
  virtual void reuse(const Linearization& /*before*/) {}
};

// The general case: the dense Jacobian, the (n+1) x (n+1) matrix factored by LU
// with partial pivoting (the factorization kept for further solves with the same row).
class DenseLinearization : public Linearization {
 public:
  DenseLinearization(Eigen::MatrixXd J, Eigen::VectorXd dRdomega, const Scaling& s);
  bool solve_bordered(const Eigen::VectorXd& row, const Eigen::VectorXd& rhs, Eigen::VectorXd& dy) const override;

 private:
  Eigen::MatrixXd A_;   // scaled, last row filled per solve
  mutable Eigen::VectorXd factored_row_;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

// A square system of equations with one parameter omega.
class ParametricProblem {
 public:
  virtual ~ParametricProblem() = default;
  virtual int size() const = 0;
  // R(X, omega); if requested also dR/dX (size x size) and dR/domega.
  virtual void evaluate(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                        Eigen::MatrixXd* dRdX, Eigen::VectorXd* dRdomega) const = 0;
  // R and dR/domega at (X, omega), and the linearisation there for the bordered
  // solves of continuation. The default is DenseLinearization of evaluate's
  // Jacobian; a problem whose Jacobian has structure may solve faster
  // (HarmonicBalance: condensation on the contact coordinates).
  virtual std::unique_ptr<Linearization> linearize(const Eigen::VectorXd& X, double omega, const Scaling& s,
                                                   Eigen::VectorXd& R, Eigen::VectorXd& dRdomega) const;
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
