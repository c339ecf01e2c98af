// Plane-strain P2 elasticity (lib/gearhb/fe): Lame's quarter ring (a = 50 mm, b = 100 mm)
// meshed by Gmsh at h = (b - a) / k, k = 32, 64, 128 (about 1.2e4, 4.5e4, 1.8e5 nodes).
//   BM_fe_mesh/k                 Gmsh meshing (P2)
//   BM_fe_assemble/k             the stiffness matrix
//   BM_fe_factor/k/backend       split by the constraints + symbolic + numeric Cholesky
//   BM_fe_solve/k/backend        one right-hand side on the factor
//   BM_fe_solve_many/k/backend   256 right-hand sides at once (influence coefficients)
// backend: 0 CHOLMOD supernodal, 1 Eigen SimplicialLDLT, 2 Eigen SimplicialLLT.
// Counters: nodes, nonzeros of L, factor storage [MB], CHOLMOD's peak memory [MB].
// Run: build/bin/gearhb_bench --benchmark_filter=BM_fe
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "gearhb/fe/elasticity.hpp"
#include "gearhb/fe/gmsh_mesher.hpp"
#include "gearhb/fe/linear_solver.hpp"

using namespace gearhb::fe;

namespace {

MeshSpec quarter_ring(int k) {
  const double a = 0.05, b = 0.1;
  const Eigen::Vector2d o(0, 0);
  MeshSpec s;
  s.loops = {{{CurveKind::polyline, {Eigen::Vector2d(a, 0), Eigen::Vector2d(b, 0)}, 1},
              {CurveKind::circle_arc, {Eigen::Vector2d(b, 0), o, Eigen::Vector2d(0, b)}, 2},
              {CurveKind::polyline, {Eigen::Vector2d(0, b), Eigen::Vector2d(0, a)}, 3},
              {CurveKind::circle_arc, {Eigen::Vector2d(0, a), o, Eigen::Vector2d(a, 0)}, 4}}};
  s.size = (b - a) / k;
  return s;
}

struct Problem {
  P2Mesh mesh;
  Material material;
  Eigen::SparseMatrix<double> k;
  Eigen::VectorXd f;
  Constraints fix;
};

// One problem per mesh level, built once for all benchmarks.
const Problem& problem(int level) {
  static std::map<int, std::unique_ptr<Problem>> cache;
  auto& p = cache[level];
  if (!p) {
    p = std::make_unique<Problem>();
    p->mesh = mesh_with_gmsh(quarter_ring(level));
    p->k = assemble_stiffness(p->mesh, p->material);
    p->f = Eigen::VectorXd::Zero(p->mesh.dof_count());
    add_pressure(p->mesh, p->material, 4, 100e6, p->f);
    fix_tagged(p->mesh, 1, 1, 0.0, p->fix);
    fix_tagged(p->mesh, 3, 0, 0.0, p->fix);
  }
  return *p;
}

void size_counters(benchmark::State& state, const Problem& p, const ElasticSolver* s) {
  state.counters["nodes"] = p.mesh.node_count();
  if (!s) return;
  state.counters["L_nnz"] = double(s->stats().factor_nonzeros);
  state.counters["L_MB"] = s->stats().factor_bytes / 1e6;
  state.counters["peak_MB"] = s->stats().peak_bytes / 1e6;
}

CholeskyBackend backend(int i) { return static_cast<CholeskyBackend>(i); }

void BM_fe_mesh(benchmark::State& state) {
  const MeshSpec spec = quarter_ring(int(state.range(0)));
  int nodes = 0;
  for (auto _ : state) nodes = mesh_with_gmsh(spec).node_count();
  state.counters["nodes"] = nodes;
}

void BM_fe_assemble(benchmark::State& state) {
  const Problem& p = problem(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(assemble_stiffness(p.mesh, p.material).nonZeros());
  size_counters(state, p, nullptr);
}

void BM_fe_factor(benchmark::State& state) {
  const Problem& p = problem(int(state.range(0)));
  std::unique_ptr<ElasticSolver> s;
  for (auto _ : state) s = std::make_unique<ElasticSolver>(p.k, p.fix.dofs(), backend(int(state.range(1))));
  size_counters(state, p, s.get());
}

void BM_fe_solve(benchmark::State& state) {
  const Problem& p = problem(int(state.range(0)));
  const ElasticSolver s(p.k, p.fix.dofs(), backend(int(state.range(1))));
  for (auto _ : state) benchmark::DoNotOptimize(s.solve(p.f).data());
  size_counters(state, p, &s);
}

void BM_fe_solve_many(benchmark::State& state) {
  const Problem& p = problem(int(state.range(0)));
  const ElasticSolver s(p.k, p.fix.dofs(), backend(int(state.range(1))));
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(p.mesh.dof_count(), 256);
  for (int j = 0; j < 256; ++j) loads.col(j) = p.f * (1.0 + j);
  for (auto _ : state) benchmark::DoNotOptimize(s.solve(loads).data());
  size_counters(state, p, &s);
}

}  // namespace

BENCHMARK(BM_fe_mesh)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_fe_assemble)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_fe_factor)->ArgsProduct({{32, 64, 128}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_fe_solve)->ArgsProduct({{32, 64, 128}, {0, 1, 2}})->Unit(benchmark::kMillisecond);
// 256 columns of 1.8e5 nodes hold 0.7 GB each (loads, reduced loads, solution): the
// largest level only with the default backend (Eigen's LDLT took 46 s CPU there).
BENCHMARK(BM_fe_solve_many)->ArgsProduct({{32, 64}, {0, 1}})->Args({128, 0})->Unit(benchmark::kMillisecond);
