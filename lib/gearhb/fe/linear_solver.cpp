#include "gearhb/fe/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gearhb::fe {

using SparseMatrix = Eigen::SparseMatrix<double>;

void Constraints::fix(int dof, double value) {
  if (dof < 0) throw std::invalid_argument("Constraints::fix: negative DOF");
  const auto it = std::lower_bound(dofs_.begin(), dofs_.end(), dof);
  const auto i = it - dofs_.begin();
  if (it != dofs_.end() && *it == dof) {
    if (std::abs(values_[i] - value) > 1e-14 * std::max(1.0, std::abs(value)))
      throw std::invalid_argument("Constraints::fix: DOF " + std::to_string(dof) + " prescribed twice, to " +
                                  std::to_string(values_[i]) + " and " + std::to_string(value));
    return;
  }
  dofs_.insert(it, dof);
  values_.insert(values_.begin() + i, value);
}

void fix_tagged(const P2Mesh& mesh, int tag, int component, const std::function<double(const Eigen::Vector2d&)>& value,
                Constraints& c) {
  if (component != 0 && component != 1) throw std::invalid_argument("fix_tagged: component must be 0 (x) or 1 (y)");
  const std::vector<int> nodes = tagged_nodes(mesh, tag);
  if (nodes.empty()) throw std::invalid_argument("fix_tagged: no boundary edge has tag " + std::to_string(tag));
  for (int n : nodes) c.fix(2 * n + component, value(mesh.nodes[n]));
}

void fix_tagged(const P2Mesh& mesh, int tag, int component, double value, Constraints& c) {
  fix_tagged(mesh, tag, component, [value](const Eigen::Vector2d&) { return value; }, c);
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Eigen's CHOLMOD wrapper with access to the symbolic factor (its size before the
// numeric factorisation).
class Cholmod : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* factor() const { return m_cholmodFactor; }
};

// Storage of the factor [bytes] after the symbolic analysis: supernodal values and
// row indices, or (simplicial) one value and one index per nonzero.
double cholmod_factor_bytes(const cholmod_factor* l, cholmod_common& common, long long& nonzeros) {
  nonzeros = (long long)common.lnz;
  if (l->is_super) return double(l->xsize) * sizeof(double) + double(l->ssize) * sizeof(int);
  return common.lnz * (sizeof(double) + sizeof(int));
}

// The fill of Eigen's simplicial factorisations: CHOLMOD's symbolic analysis with the
// same ordering (AMD; Eigen's AMD is a port of SuiteSparse's), without a numeric step.
double amd_factor_bytes(const SparseMatrix& a, long long& nonzeros) {
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  SparseMatrix lower = a.triangularView<Eigen::Lower>();
  cholmod_sparse view = Eigen::viewAsCholmod(lower);
  view.stype = -1;
  cholmod_factor* l = cholmod_analyze(&view, &common);
  const double bytes = l ? cholmod_factor_bytes(l, common, nonzeros) : 0.0;
  cholmod_free_factor(&l, &common);
  cholmod_finish(&common);
  return bytes;
}

void check_factor_size(double bytes, const SolverLimits& limits) {
  if (bytes > limits.max_factor_bytes)
    throw std::invalid_argument("finite-element model too large: its Cholesky factor would need " +
                                std::to_string(bytes / (1 << 20)) + " MiB, above the limit of " +
                                std::to_string(limits.max_factor_bytes / (1 << 20)) +
                                " MiB (SolverLimits::max_factor_bytes); use a coarser mesh");
}

const std::string not_definite =
    "the stiffness of the free DOFs is not positive definite: the constraints do not stop every rigid motion";

}  // namespace

struct ElasticSolver::Impl {
  SparseMatrix k;                // the whole K
  SparseMatrix kff, kfc;         // free-free, free-prescribed
  std::vector<int> free, fixed;  // DOF numbers
  CholeskyBackend backend;
  Cholmod cholmod;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
  Eigen::SimplicialLLT<SparseMatrix> llt;

  // K_ff^-1 b for one or many columns.
  Eigen::MatrixXd solve_free(const Eigen::MatrixXd& b) const {
    switch (backend) {
      case CholeskyBackend::cholmod_supernodal: return cholmod.solve(b);
      case CholeskyBackend::eigen_ldlt: return ldlt.solve(b);
      case CholeskyBackend::eigen_llt: return llt.solve(b);
    }
    return {};
  }
};

namespace {

// The partition of K: rows and columns of `rows`/`cols` (index maps: DOF -> position or -1).
SparseMatrix block(const SparseMatrix& k, const std::vector<int>& row_of, int rows, const std::vector<int>& col_of,
                   int cols) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < k.outerSize(); ++j) {
    if (col_of[j] < 0) continue;
    for (SparseMatrix::InnerIterator it(k, j); it; ++it)
      if (row_of[it.row()] >= 0) t.emplace_back(row_of[it.row()], col_of[j], it.value());
  }
  SparseMatrix b(rows, cols);
  b.setFromTriplets(t.begin(), t.end());
  return b;
}

}  // namespace

ElasticSolver::ElasticSolver(const SparseMatrix& stiffness, const std::vector<int>& fixed_dofs, CholeskyBackend backend,
                             SolverLimits limits)
    : impl_(std::make_unique<Impl>()) {
  const int n = int(stiffness.rows());
  if (stiffness.cols() != n) throw std::invalid_argument("ElasticSolver: K is not square");
  Impl& s = *impl_;
  s.k = stiffness;
  s.backend = backend;
  std::vector<int> free_of(n, -1), fixed_of(n, -1);
  for (int d : fixed_dofs) {
    if (d < 0 || d >= n) throw std::invalid_argument("ElasticSolver: prescribed DOF " + std::to_string(d) + " outside K");
    if (fixed_of[d] >= 0) throw std::invalid_argument("ElasticSolver: DOF " + std::to_string(d) + " prescribed twice");
    fixed_of[d] = int(s.fixed.size());
    s.fixed.push_back(d);
  }
  for (int d = 0; d < n; ++d)
    if (fixed_of[d] < 0) {
      free_of[d] = int(s.free.size());
      s.free.push_back(d);
    }
  const int nf = int(s.free.size());
  s.kff = block(stiffness, free_of, nf, free_of, nf);
  s.kfc = block(stiffness, free_of, nf, fixed_of, int(s.fixed.size()));
  stats_.free_dofs = nf;
  stats_.stiffness_nonzeros = s.kff.nonZeros();

  auto t0 = std::chrono::steady_clock::now();
  if (backend == CholeskyBackend::cholmod_supernodal) {
    s.cholmod.analyzePattern(s.kff);
    stats_.factor_bytes = cholmod_factor_bytes(s.cholmod.factor(), s.cholmod.cholmod(), stats_.factor_nonzeros);
  } else {
    stats_.factor_bytes = amd_factor_bytes(s.kff, stats_.factor_nonzeros);
  }
  check_factor_size(stats_.factor_bytes, limits);
  if (backend == CholeskyBackend::eigen_ldlt) s.ldlt.analyzePattern(s.kff);
  if (backend == CholeskyBackend::eigen_llt) s.llt.analyzePattern(s.kff);
  stats_.analyse_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  bool ok = false;
  switch (backend) {
    case CholeskyBackend::cholmod_supernodal:
      s.cholmod.factorize(s.kff);
      ok = s.cholmod.info() == Eigen::Success;
      stats_.peak_bytes = double(s.cholmod.cholmod().memory_usage);
      break;
    case CholeskyBackend::eigen_ldlt:
      s.ldlt.factorize(s.kff);
      ok = s.ldlt.info() == Eigen::Success && (nf == 0 || s.ldlt.vectorD().minCoeff() > 0);
      break;
    case CholeskyBackend::eigen_llt:
      s.llt.factorize(s.kff);
      ok = s.llt.info() == Eigen::Success;
      break;
  }
  stats_.factor_seconds = seconds_since(t0);
  if (!ok) throw std::invalid_argument("ElasticSolver: " + not_definite);
}

ElasticSolver::~ElasticSolver() = default;
ElasticSolver::ElasticSolver(ElasticSolver&&) noexcept = default;
ElasticSolver& ElasticSolver::operator=(ElasticSolver&&) noexcept = default;

int ElasticSolver::dofs() const { return int(impl_->k.rows()); }

Eigen::VectorXd ElasticSolver::solve(const Eigen::VectorXd& f, const std::vector<double>& prescribed) const {
  const Impl& s = *impl_;
  if (f.size() != dofs()) throw std::invalid_argument("ElasticSolver::solve: load of the wrong size");
  if (!prescribed.empty() && prescribed.size() != s.fixed.size())
    throw std::invalid_argument("ElasticSolver::solve: " + std::to_string(prescribed.size()) + " prescribed values for " +
                                std::to_string(s.fixed.size()) + " prescribed DOFs");
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(Eigen::Index(s.fixed.size()));
  for (std::size_t i = 0; i < prescribed.size(); ++i) uc(Eigen::Index(i)) = prescribed[i];
  Eigen::VectorXd b(s.free.size());
  for (std::size_t i = 0; i < s.free.size(); ++i) b(Eigen::Index(i)) = f(s.free[i]);
  if (!s.fixed.empty()) b -= s.kfc * uc;
  const Eigen::VectorXd uf = s.solve_free(b);
  Eigen::VectorXd u(dofs());
  for (std::size_t i = 0; i < s.free.size(); ++i) u(s.free[i]) = uf(Eigen::Index(i));
  for (std::size_t i = 0; i < s.fixed.size(); ++i) u(s.fixed[i]) = uc(Eigen::Index(i));
  return u;
}

Eigen::MatrixXd ElasticSolver::solve(const Eigen::MatrixXd& f) const {
  const Impl& s = *impl_;
  if (f.rows() != dofs()) throw std::invalid_argument("ElasticSolver::solve: loads of the wrong size");
  Eigen::MatrixXd b(s.free.size(), f.cols());
  for (std::size_t i = 0; i < s.free.size(); ++i) b.row(Eigen::Index(i)) = f.row(s.free[i]);
  const Eigen::MatrixXd uf = s.solve_free(b);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(dofs(), f.cols());
  for (std::size_t i = 0; i < s.free.size(); ++i) u.row(s.free[i]) = uf.row(Eigen::Index(i));
  return u;
}

Eigen::VectorXd ElasticSolver::reactions(const Eigen::VectorXd& u, const Eigen::VectorXd& f) const {
  return impl_->k * u - f;
}

Eigen::VectorXd solve_elastic(const SparseMatrix& stiffness, const Eigen::VectorXd& f, const Constraints& constraints,
                              CholeskyBackend backend) {
  const ElasticSolver solver(stiffness, constraints.dofs(), backend);
  return solver.solve(f, constraints.values());
}

}  // namespace gearhb::fe
