#include "gearhb/experiments/parametric.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

#include "gearhb/core/fourier.hpp"

namespace gearhb {

Eigen::MatrixXd linear_periodic_jacobian(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                         const Eigen::MatrixXd& K0, const Eigen::MatrixXd& K1,
                                         const Eigen::VectorXd& kcoef, double omega, int H) {
  const int n = int(M.rows()), m = 2 * H + 1;
  if (H < 1 || kcoef.size() < 1 || kcoef.size() % 2 == 0)
    throw std::invalid_argument("linear_periodic_jacobian: H >= 1 and an odd coefficient count");
  // Moments <k cos j theta>, <k sin j theta>, j = 0..2H, of the retained harmonics.
  std::vector<double> Sc(2 * H + 1, 0.0), Ss(2 * H + 1, 0.0);
  Sc[0] = kcoef[0];
  for (int j = 1; j <= 2 * H && 2 * j < kcoef.size(); ++j) {
    Sc[j] = 0.5 * kcoef[2 * j - 1];
    Ss[j] = 0.5 * kcoef[2 * j];
  }
  const Aft aft(H);
  Eigen::MatrixXd G(m, m);
  aft.product_matrix_from_moments(Sc.data(), Ss.data(), G);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n * m, n * m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) J.block(a * n, b * n, n, n) = G(a, b) * K1;
  J.block(0, 0, n, n) += K0;
  for (int k = 1; k <= H; ++k) {
    const double kw = k * omega;
    const int ic = (2 * k - 1) * n, is = 2 * k * n;
    J.block(ic, ic, n, n) += K0 - kw * kw * M;
    J.block(is, is, n, n) += K0 - kw * kw * M;
    J.block(ic, is, n, n) += kw * C;
    J.block(is, ic, n, n) -= kw * C;
  }
  return J;
}

Eigen::VectorXd square_wave_stiffness(double a, double b, int P) {
  Eigen::VectorXd k = Eigen::VectorXd::Zero(2 * P + 1);
  k[0] = a;
  for (int m = 1; m <= P; m += 2) k[2 * m - 1] = b * 4.0 / (M_PI * m) * ((m / 2) % 2 == 0 ? 1.0 : -1.0);
  return k;
}

namespace {
// Transfer matrix of y'' + lambda y = 0 over a time tau (complex frequency for lambda < 0).
Eigen::Matrix2cd transfer(double lambda, double tau) {
  const std::complex<double> root = std::sqrt(std::complex<double>(lambda, 0.0));
  Eigen::Matrix2cd T;
  const std::complex<double> c = std::cos(root * tau);
  const std::complex<double> s_over_root = std::abs(root) < 1e-300 ? std::complex<double>(tau) : std::sin(root * tau) / root;
  T << c, s_over_root, -lambda * s_over_root, c;
  return T;
}
}  // namespace

double meissner_trace(double a, double b) {
  return (transfer(a - b, M_PI) * transfer(a + b, M_PI)).trace().real();
}

}  // namespace gearhb
