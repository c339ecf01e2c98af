#include "gearhb/stability.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace gearhb {

HillResult hill_stability(const Eigen::MatrixXd& JX, const Eigen::MatrixXd& M,
                          const Eigen::MatrixXd& C, double w, int H, double rtol) {
  const int n = int(M.rows()), m = 2 * H + 1, N = n * m;
  if (JX.rows() != N || JX.cols() != N) throw std::invalid_argument("hill_stability: Jacobian size");
  // D1 = 2 Nabla(x)M + I(x)C, block by block (harmonic-major).
  Eigen::MatrixXd D1 = Eigen::MatrixXd::Zero(N, N);
  for (int a = 0; a < m; ++a) D1.block(a * n, a * n, n, n) = C;
  for (int k = 1; k <= H; ++k) {
    const int ic = (2 * k - 1) * n, is = 2 * k * n;
    // (d/dt p)_c = k w p_s, (d/dt p)_s = -k w p_c
    D1.block(ic, is, n, n) += 2.0 * k * w * M;
    D1.block(is, ic, n, n) -= 2.0 * k * w * M;
  }
  // First-order companion form with D2^{-1} = I (x) M^{-1}:
  //   [ 0        I        ]
  //   [ -D2^-1 D0  -D2^-1 D1 ]
  const Eigen::MatrixXd Minv = M.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * N, 2 * N);
  A.topRightCorner(N, N).setIdentity();
  for (int a = 0; a < m; ++a) {
    A.block(N + a * n, 0, n, N) = -Minv * JX.middleRows(a * n, n);
    A.block(N + a * n, N, n, N) = -Minv * D1.middleRows(a * n, n);
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, /*computeEigenvectors=*/false);
  if (es.info() != Eigen::Success) throw std::runtime_error("hill_stability: eigensolver failed");
  const Eigen::VectorXcd ev = es.eigenvalues();
  std::vector<int> idx(ev.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::partial_sort(idx.begin(), idx.begin() + 2 * n, idx.end(),
                    [&](int i, int j) { return std::fabs(ev[i].imag()) < std::fabs(ev[j].imag()); });
  HillResult r;
  r.exponents.resize(2 * n);
  r.max_real = -INFINITY;
  for (int i = 0; i < 2 * n; ++i) {
    r.exponents[i] = ev[idx[i]];
    r.max_real = std::max(r.max_real, ev[idx[i]].real());
  }
  r.stable = r.max_real < rtol * std::fabs(w);
  return r;
}

}  // namespace gearhb
