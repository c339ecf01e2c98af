#include "gearhb/gears/pair/coupled_load_sharing.hpp"

#include <cmath>
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace gearhb {

namespace {

// The solution with the contacts of `mask` loaded and the others at zero force.
CoupledShare solve_loaded_set(const Eigen::MatrixXd& C, const Eigen::VectorXd& g, double F, unsigned mask) {
  std::vector<int> set;
  for (int i = 0; i < int(g.size()); ++i)
    if (mask & (1u << i)) set.push_back(i);
  const int m = int(set.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m + 1, m + 1);
  Eigen::VectorXd b(m + 1);
  for (int a = 0; a < m; ++a) {
    for (int c = 0; c < m; ++c) A(a, c) = C(set[a], set[c]);
    A(a, m) = -1.0;
    A(m, a) = 1.0;
    b(a) = -g(set[a]);
  }
  b(m) = F;
  const Eigen::VectorXd x = A.fullPivLu().solve(b);
  CoupledShare s;
  s.force = Eigen::VectorXd::Zero(g.size());
  for (int a = 0; a < m; ++a) s.force(set[a]) = x(a);
  s.approach = x(m);
  s.loaded = m;
  return s;
}

// KKT conditions up to round-off: forces of the set >= 0, gaps off the set >= 0.
bool satisfies_kkt(const Eigen::MatrixXd& C, const Eigen::VectorXd& g, double F, unsigned mask,
                   const CoupledShare& s) {
  const Eigen::VectorXd w = C * s.force + g - Eigen::VectorXd::Constant(g.size(), s.approach);
  const double force_tol = 1e-12 * F;
  const double gap_tol = 1e-12 * (std::abs(s.approach) + g.cwiseAbs().maxCoeff() + C.cwiseAbs().maxCoeff() * F);
  for (int i = 0; i < int(g.size()); ++i) {
    const bool in_set = mask & (1u << i);
    if (in_set && !(s.force(i) >= -force_tol)) return false;
    if (!in_set && !(w(i) >= -gap_tol)) return false;
  }
  return true;
}

}  // namespace

CoupledShare share_load_coupled(const Eigen::MatrixXd& compliance, const Eigen::VectorXd& separation,
                                double force) {
  const int n = int(separation.size());
  if (n == 0 || n > 12) throw std::invalid_argument("share_load_coupled: 1 to 12 contacts");
  if (compliance.rows() != n || compliance.cols() != n)
    throw std::invalid_argument("share_load_coupled: compliance and separations differ in size");
  if (!(force > 0)) throw std::invalid_argument("share_load_coupled: the tooth force must be > 0");
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    CoupledShare s = solve_loaded_set(compliance, separation, force, mask);
    if (!s.force.allFinite() || !satisfies_kkt(compliance, separation, force, mask, s)) continue;
    s.force = s.force.cwiseMax(0.0);   // round-off below zero on a tie
    s.loaded = int((s.force.array() > 0).count());
    return s;
  }
  throw std::invalid_argument("share_load_coupled: no loaded set satisfies the contact conditions "
                              "(compliance not positive definite?)");
}

namespace {

// One block at approach X: its loaded set (a mask) and forces, by enumeration.
struct BlockState {
  unsigned mask = 0;
  Eigen::VectorXd force;
};

BlockState block_at(const Eigen::MatrixXd& C, const Eigen::VectorXd& g, double X) {
  const int n = int(g.size());
  const double scale = std::abs(X) + g.cwiseAbs().maxCoeff();
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<int> set;
    for (int i = 0; i < n; ++i)
      if (mask & (1u << i)) set.push_back(i);
    const int m = int(set.size());
    Eigen::MatrixXd A(m, m);
    Eigen::VectorXd b(m);
    for (int a = 0; a < m; ++a) {
      for (int c = 0; c < m; ++c) A(a, c) = C(set[a], set[c]);
      b(a) = X - g(set[a]);
    }
    BlockState s{mask, Eigen::VectorXd::Zero(n)};
    const Eigen::VectorXd f = m ? Eigen::VectorXd(A.ldlt().solve(b)) : Eigen::VectorXd();
    for (int a = 0; a < m; ++a) s.force(set[a]) = f(a);
    const Eigen::VectorXd w = C * s.force + g - Eigen::VectorXd::Constant(n, X);
    const double force_tol = 1e-12 * (s.force.cwiseAbs().maxCoeff() + 1e-300);
    bool ok = f.allFinite();
    for (int i = 0; i < n && ok; ++i)
      ok = (mask & (1u << i)) ? s.force(i) >= -force_tol : w(i) >= -1e-12 * scale;
    if (ok) {
      s.force = s.force.cwiseMax(0.0);
      return s;
    }
  }
  throw std::invalid_argument("share_load_blocks: no loaded set satisfies the contact conditions "
                              "(compliance not positive definite?)");
}

// sum_b 1^T C_SS^-1 1 and sum_b 1^T C_SS^-1 g_S over the blocks' loaded sets.
std::pair<double, double> linear_piece(const std::vector<Eigen::MatrixXd>& C, const std::vector<Eigen::VectorXd>& g,
                                       const std::vector<BlockState>& state) {
  double a = 0.0, c = 0.0;
  for (std::size_t b = 0; b < C.size(); ++b) {
    std::vector<int> set;
    for (int i = 0; i < int(g[b].size()); ++i)
      if (state[b].mask & (1u << i)) set.push_back(i);
    const int m = int(set.size());
    if (m == 0) continue;
    Eigen::MatrixXd A(m, m);
    Eigen::VectorXd gs(m);
    for (int p = 0; p < m; ++p) {
      for (int q = 0; q < m; ++q) A(p, q) = C[b](set[p], set[q]);
      gs(p) = g[b](set[p]);
    }
    const auto ldlt = A.ldlt();
    a += ldlt.solve(Eigen::VectorXd::Ones(m)).sum();
    c += ldlt.solve(gs).sum();
  }
  return {a, c};
}

}  // namespace

CoupledShare share_load_blocks(const std::vector<Eigen::MatrixXd>& compliance,
                               const std::vector<Eigen::VectorXd>& separation, double force) {
  const std::size_t nb = compliance.size();
  if (nb == 0 || separation.size() != nb) throw std::invalid_argument("share_load_blocks: no block, or sizes that differ");
  if (!(force > 0)) throw std::invalid_argument("share_load_blocks: the tooth force must be > 0");
  double g_min = 1e300, c_max = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    const int n = int(separation[b].size());
    if (n == 0 || n > 12) throw std::invalid_argument("share_load_blocks: 1 to 12 contacts a block");
    if (compliance[b].rows() != n || compliance[b].cols() != n)
      throw std::invalid_argument("share_load_blocks: compliance and separations differ in size");
    g_min = std::min(g_min, separation[b].minCoeff());
    c_max = std::max(c_max, compliance[b].diagonal().maxCoeff());
  }
  std::vector<BlockState> state(nb);
  auto total_at = [&](double X) {
    double t = 0.0;
    for (std::size_t b = 0; b < nb; ++b) state[b] = block_at(compliance[b], separation[b], X), t += state[b].force.sum();
    return t;
  };
  double lo = g_min, hi = g_min + force * c_max;   // total(lo) = 0 < F
  for (int k = 0; total_at(hi) < force; ++k) {
    if (k == 200) throw std::invalid_argument("share_load_blocks: the total force does not reach F");
    lo = hi, hi = g_min + 2.0 * (hi - g_min);
  }
  double X = hi, t = total_at(X);
  for (int it = 0;; ++it) {
    if (it == 200) throw std::runtime_error("share_load_blocks: the loaded sets did not settle");
    (t < force ? lo : hi) = X;
    const std::vector<BlockState> from = state;
    const auto [a, c] = linear_piece(compliance, separation, from);
    if (a > 0.0) {   // the root of this piece; exact where the sets there are the same
      const double next = (force + c) / a;
      const double t_next = total_at(next);
      bool same = true;
      for (std::size_t b = 0; b < nb && same; ++b) same = state[b].mask == from[b].mask;
      if (same) {
        X = next;
        break;
      }
      if (next > lo && next < hi) {
        X = next, t = t_next;
        continue;
      }
    }
    X = 0.5 * (lo + hi);
    t = total_at(X);
  }
  CoupledShare out;
  long n = 0;
  for (const auto& s : state) n += s.force.size();
  out.force.resize(n);
  n = 0;
  for (const auto& s : state) out.force.segment(n, s.force.size()) = s.force, n += s.force.size();
  out.approach = X;
  out.loaded = int((out.force.array() > 0).count());
  return out;
}

}  // namespace gearhb
