#pragma once
// Solving K u = f with prescribed displacements, one factorisation for many loads.
//
// Dirichlet conditions by elimination (Zienkiewicz, Taylor & Zhu, 7th ed., vol. 1,
// §1.4): with the DOFs split into free (f) and prescribed (c), u_c given,
//     K_ff u_f = f_f - K_fc u_c,
// and the reactions at the prescribed DOFs are r_c = K_cf u_f + K_cc u_c - f_c.
// K_ff is symmetric positive definite when the prescribed DOFs stop the rigid motions,
// and is factored once by a sparse Cholesky factorisation (fill-reducing ordering);
// each load then costs a forward and a back substitution. The influence coefficients of
// many contact points are many right-hand sides of one factorisation: solve(F) with one
// column per load.
//
// Backends (each with a fill-reducing ordering chosen by the library):
//   cholmod_supernodal (default): SuiteSparse CHOLMOD's supernodal LL^T through Eigen's
//     CholmodSupernodalLLT (CHOLMOD picks AMD or METIS); dense BLAS kernels on the
//     supernodes. Chosen by measurement (bench/bench_fe_elasticity.cpp, Lame quarter
//     ring, CPU times on a loaded 2-core machine): factor 134 / 966 / 8024 ms at 1.2e4 /
//     4.5e4 / 1.8e5 nodes against Eigen's SimplicialLDLT 160 / 1431 / 12952 ms; 256
//     right-hand sides 864 / 3892 / 18481 ms against 869 / 6910 / 45906 ms; factor
//     storage 342 MB against 483 MB at 1.8e5 nodes; one solve the same (3 / 37 / 156 ms).
//   eigen_ldlt / eigen_llt: Eigen's SimplicialLDLT / SimplicialLLT, AMD ordering; no
//     external library, slower on large meshes.
//
// Size guard: the factor's size is known before it is computed (the symbolic analysis
// counts its nonzeros), and a factor of more than SolverLimits::max_factor_bytes is
// refused with std::invalid_argument before any numeric work.
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "gearhb/fe/mesh.hpp"

namespace gearhb::fe {

enum class CholeskyBackend { cholmod_supernodal, eigen_ldlt, eigen_llt };

struct SolverLimits {
  // Bytes of the Cholesky factor (values and row indices) at the most. 4 GiB: a plane
  // mesh of about 2 million P2 nodes (a gear sector needs < 0.2 million), and room for
  // two such models in the 16-32 GB of a workstation.
  double max_factor_bytes = 4.0 * (1ull << 30);
};

// Prescribed displacements: DOF -> value. fix() the same DOF twice with different values
// is an error (std::invalid_argument): two conditions that contradict each other.
class Constraints {
 public:
  void fix(int dof, double value = 0.0);
  const std::vector<int>& dofs() const { return dofs_; }          // sorted
  const std::vector<double>& values() const { return values_; }   // same order
  std::size_t size() const { return dofs_.size(); }

 private:
  std::vector<int> dofs_;
  std::vector<double> values_;
};

// Helpers: fix component (0: x, 1: y) of every node of the boundary edges with this tag,
// to a constant or to a function of the node's position.
void fix_tagged(const P2Mesh& mesh, int tag, int component, double value, Constraints& c);
void fix_tagged(const P2Mesh& mesh, int tag, int component,
                const std::function<double(const Eigen::Vector2d&)>& value, Constraints& c);

struct FactorStats {
  int free_dofs = 0;
  long long stiffness_nonzeros = 0;   // of K_ff (both triangles)
  long long factor_nonzeros = 0;      // of L
  double factor_bytes = 0;            // storage of L (values and indices) [bytes]
  double peak_bytes = 0;              // CHOLMOD's peak workspace + factor (0 for Eigen)
  double analyse_seconds = 0, factor_seconds = 0;
};

class ElasticSolver {
 public:
  // Splits K (n x n, symmetric) by the constraints' DOFs and factors K_ff.
  // Throws std::invalid_argument for a constraint outside 0..n-1, a factor above the
  // limit, or a K_ff that is not positive definite (rigid motions not stopped).
  ElasticSolver(const Eigen::SparseMatrix<double>& stiffness, const std::vector<int>& fixed_dofs,
                CholeskyBackend backend = CholeskyBackend::cholmod_supernodal, SolverLimits limits = {});
  ~ElasticSolver();
  ElasticSolver(ElasticSolver&&) noexcept;
  ElasticSolver& operator=(ElasticSolver&&) noexcept;

  // The whole displacement u (n) for the load f (n) and the prescribed values (same
  // order as fixed_dofs; empty = all zero).
  Eigen::VectorXd solve(const Eigen::VectorXd& f, const std::vector<double>& prescribed = {}) const;
  // Many loads at once, prescribed displacements zero: column j of the result is the
  // displacement of column j of F (n x m).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& f) const;
  // r = K u - f: the reactions (nonzero at the prescribed DOFs, ~0 elsewhere).
  Eigen::VectorXd reactions(const Eigen::VectorXd& u, const Eigen::VectorXd& f) const;

  const FactorStats& stats() const { return stats_; }
  int dofs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  FactorStats stats_;
};

// Convenience: factor and solve once.
Eigen::VectorXd solve_elastic(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& f,
                              const Constraints& constraints,
                              CholeskyBackend backend = CholeskyBackend::cholmod_supernodal);

}  // namespace gearhb::fe
