#include "gearhb/hb/stability.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/core/linear_dynamics.hpp"

namespace gearhb {

HillResult hill_stability(const Eigen::MatrixXd& JX, const Eigen::MatrixXd& M,
                          const Eigen::MatrixXd& C, double omega, int H, double rtol) {
  const int n = int(M.rows()), m = 2 * H + 1, N = n * m;
  if (JX.rows() != N || JX.cols() != N) throw std::invalid_argument("hill_stability: Jacobian size");
  // D1 = 2 Nabla(x)M + I(x)C, block by block (harmonic-major).
  Eigen::MatrixXd D1 = Eigen::MatrixXd::Zero(N, N);
  for (int a = 0; a < m; ++a) D1.block(a * n, a * n, n, n) = C;
  for (int k = 1; k <= H; ++k) {
    const int ic = (2 * k - 1) * n, is = 2 * k * n;
    // (d/dt p)_c = k omega p_s, (d/dt p)_s = -k omega p_c
    D1.block(ic, is, n, n) += 2.0 * k * omega * M;
    D1.block(is, ic, n, n) -= 2.0 * k * omega * M;
  }
  // First-order companion form in the scaled exponent mu = lambda / omega (time measured
  // in radians of forcing phase), with D2^{-1} = I (x) M^{-1}:
  //   [ 0                I             ]
  //   [ -D2^-1 D0 / omega^2  -D2^-1 D1 / omega ]
  // Without the scaling the entries range from 1 to K/M (1e9 1/s^2 for a gear
  // pair) and the unbalanced QR iteration may not converge.
  const Eigen::MatrixXd Minv = M.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * N, 2 * N);
  A.topRightCorner(N, N).setIdentity();
  for (int a = 0; a < m; ++a) {
    A.block(N + a * n, 0, n, N) = -Minv * JX.middleRows(a * n, n) / (omega * omega);
    A.block(N + a * n, N, n, N) = -Minv * D1.middleRows(a * n, n) / omega;
  }
  const Eigen::VectorXcd ev = general_eigenvalues(A, "hill_stability at omega = " + std::to_string(omega)) * omega;
  std::vector<int> idx(ev.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(),
            [&](int i, int j) { return std::fabs(ev[i].imag()) < std::fabs(ev[j].imag()); });
  // The 2n smallest |Im|, extended by every eigenvalue of the band |Im| <= omega/2
  // (plus a 1 % margin for the truncation error of Im): at a period doubling two
  // real multipliers put four eigenvalues at Im ~ +-omega/2 for two slots, and the
  // truncation shifts their Im by ~1e-5 omega in either direction, so a count alone
  // may keep the stable pair and drop the unstable one (ch. 6, Fig. 43 at
  // 10.85 krad/s: Hill exponent 0.0521 omega + 0.500328 i omega vs Floquet 0.0526 omega + 0.5 i omega).
  // Any extra eigenvalue kept is a copy (shift i k omega) of a true exponent with the
  // same real part, so widening the selection cannot create a false instability.
  std::size_t count = std::min<std::size_t>(2 * n, idx.size());
  while (count < idx.size() && std::fabs(ev[idx[count]].imag()) <= 0.51 * std::fabs(omega)) ++count;
  HillResult r;
  r.exponents.resize(Eigen::Index(count));
  r.max_real = -INFINITY;
  for (std::size_t i = 0; i < count; ++i) {
    r.exponents[Eigen::Index(i)] = ev[idx[i]];
    r.max_real = std::max(r.max_real, ev[idx[i]].real());
  }
  r.stable = r.max_real < rtol * std::fabs(omega);
  return r;
}

}  // namespace gearhb
