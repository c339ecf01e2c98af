// Uses the installed library: the first natural frequency of a 1-DOF oscillator
// (k = 4 N/m, m = 1 kg: exactly 2 rad/s). Exit 0 when it is right.
#include <cmath>
#include <cstdio>

#include <gearhb/core/linear_dynamics.hpp>

int main() {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Constant(1, 1, 1.0), K = Eigen::MatrixXd::Constant(1, 1, 4.0);
  const double w = gearhb::modal_analysis(M, K).omega[0];
  std::printf("omega_1 = %.15g rad/s (exact 2)\n", w);
  return std::fabs(w - 2.0) < 1e-12 ? 0 : 1;
}
