#pragma once
// Small models shared by the unit tests.
#include "gearhb/hb/harmonic_balance.hpp"

namespace test_models {

// Thesis ch. 3 mass against a wall: m = 1 kg, c = 0.01 N s/m, k = 1 N/m,
// kc = 1 N/m, F = 0.01 N, gap g, static force F0.
inline gearhb::HarmonicBalance mass_wall(double gap, int H, double F0 = 0.0, double F = 0.01,
                                         int N = 0) {
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  gearhb::LinearSystem s{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.01),
                         MatrixXd::Constant(1, 1, 1.0)};
  gearhb::UnilateralContact c{VectorXd::Constant(1, 1.0), 1.0, gap, {}};
  gearhb::Excitation f{VectorXd::Constant(1, F0), VectorXd::Constant(1, F), VectorXd::Zero(1)};
  return gearhb::HarmonicBalance(s, {c}, f, H, N);
}

}  // namespace test_models
