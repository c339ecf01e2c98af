#include "gearhb/gears/pair/coupled_load_sharing.hpp"

#include <cmath>
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

}  // namespace gearhb
