// Benchmarks of the harmonic-balance engine (thesis ch. 3 model, Fig. 9 g = -0.6).
//   build/bin/gearhb_bench        (or `make bench`)
// Times are reported in the issue notes, never asserted in tests.
#include <benchmark/benchmark.h>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;

namespace {
HarmonicBalance fig9(int H, ContactQuadrature q) {
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  LinearSystem s{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.01), MatrixXd::Constant(1, 1, 1.0)};
  UnilateralContact c{VectorXd::Constant(1, 1.0), 1.0, -0.6, {}};
  Excitation f{VectorXd::Zero(1), VectorXd::Constant(1, 0.01), VectorXd::Zero(1)};
  return HarmonicBalance(s, {c}, f, H, 0, q);
}
ContactQuadrature quad(int64_t i) { return i ? ContactQuadrature::exact : ContactQuadrature::sampled; }
}  // namespace

// One residual + analytic Jacobian (+ dR/domega) in intermittent contact.
static void BM_ResidualJacobian(benchmark::State& st) {
  HarmonicBalance hb = fig9(int(st.range(0)), quad(st.range(1)));
  Eigen::VectorXd X = Eigen::VectorXd::Zero(hb.size()), R, dw;
  X[1] = 0.9;
  X[2] = 0.2;
  Eigen::MatrixXd J;
  for (auto _ : st) {
    hb.evaluate(X, 1.04, R, &J, &dw);
    benchmark::DoNotOptimize(R.data());
  }
}
BENCHMARK(BM_ResidualJacobian)->ArgsProduct({{1, 5, 10, 20}, {0, 1}})->ArgNames({"H", "exact"})
    ->Unit(benchmark::kMicrosecond);

// A full Fig. 9 curve (0.5 -> 2 rad/s) by pseudo-arc-length continuation.
static void BM_Fig9Curve(benchmark::State& st) {
  HarmonicBalance hb = fig9(int(st.range(0)), ContactQuadrature::exact);
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  const Scaling sc = hb.scaling(0.5, 2.0);
  std::size_t pts = 0;
  for (auto _ : st) {
    Branch b = arc_length_continuation(hb, hb.open_contact_solution(0.5), sc, o);
    pts = b.points.size();
    benchmark::DoNotOptimize(b.points.data());
  }
  st.counters["points"] = double(pts);
}
BENCHMARK(BM_Fig9Curve)->Arg(1)->Arg(5)->Arg(10)->Arg(20)->ArgName("H")->Unit(benchmark::kMillisecond);

// Hill stability of every point of that curve (separate: O((2H+1)^3) per point).
static void BM_Fig9Stability(benchmark::State& st) {
  HarmonicBalance hb = fig9(int(st.range(0)), ContactQuadrature::exact);
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  const Branch b = arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
  for (auto _ : st) benchmark::DoNotOptimize(branch_stability(hb, b));
}
BENCHMARK(BM_Fig9Stability)->Arg(1)->Arg(5)->Arg(10)->Arg(20)->ArgName("H")->Unit(benchmark::kMillisecond);
