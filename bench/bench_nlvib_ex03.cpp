// NLvib example 03 (two masses, unilateral spring 100 behind a gap of 1, tests/unit/test_models.hpp):
// the full curve omega = 0.8 -> 0.5 at H = 21 (default N) with the stability of every point.
//   build/bin/gearhb_bench --benchmark_filter=Ex03
// Times are reported in the issue notes, never asserted in tests.
#include <benchmark/benchmark.h>

#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "../tests/unit/test_models.hpp"

using namespace gearhb;

namespace {
SweepOptions ex03_options(StabilityMethod m, bool bifurcations, double ds_max, double turn) {
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 0.8;
  o.direction = SweepDirection::down;
  o.stability = m;
  o.locate_bifurcations = bifurcations;
  o.continuation.ds_max = ds_max;
  o.continuation.target_turn_deg = turn;
  return o;
}
}  // namespace

// stability: 0 none, 1 Floquet (exact flow, corrected orbit), 2 Floquet + bifurcations located, 3 Hill.
static void BM_Ex03Curve(benchmark::State& st) {
  const HarmonicBalance hb = test_models::nlvib_ex03(int(st.range(0)));
  const int s = int(st.range(1));
  const StabilityMethod m = s == 0 ? StabilityMethod::none : s == 3 ? StabilityMethod::hill : StabilityMethod::floquet;
  const SweepOptions o = ex03_options(m, s == 2, 0.02, 0.0);
  std::size_t points = 0;
  for (auto _ : st) {
    const FrequencyCurve c = sweep_frequency(hb, o, "ex03");
    if (!c.complete) st.SkipWithError(c.failure.c_str());
    points = c.branch.points.size();
    benchmark::DoNotOptimize(c.stable.size());
  }
  st.counters["points"] = double(points);
}
BENCHMARK(BM_Ex03Curve)->ArgsProduct({{21}, {0, 1, 2, 3}})->ArgNames({"H", "stability"})
    ->Unit(benchmark::kMillisecond);

// The same with curvature step control (target 5 degrees per step, ds_max 0.1).
static void BM_Ex03CurveCurvatureSteps(benchmark::State& st) {
  const HarmonicBalance hb = test_models::nlvib_ex03(21);
  const SweepOptions o = ex03_options(st.range(0) ? StabilityMethod::floquet : StabilityMethod::none,
                                      st.range(0) != 0, 0.1, 5.0);
  std::size_t points = 0;
  for (auto _ : st) {
    const FrequencyCurve c = sweep_frequency(hb, o, "ex03");
    if (!c.complete) st.SkipWithError(c.failure.c_str());
    points = c.branch.points.size();
  }
  st.counters["points"] = double(points);
}
BENCHMARK(BM_Ex03CurveCurvatureSteps)->Arg(0)->Arg(1)->ArgNames({"floquet"})->Unit(benchmark::kMillisecond);

// Floquet multipliers of one HB point (shooting correction + matrix exponentials).
static void BM_Ex03FloquetPoint(benchmark::State& st) {
  const HarmonicBalance hb = test_models::nlvib_ex03(21);
  const FrequencyCurve c = sweep_frequency(hb, ex03_options(StabilityMethod::none, false, 0.02, 0.0), "ex03");
  const auto& p = c.branch.points[c.branch.points.size() / 2];
  for (auto _ : st) benchmark::DoNotOptimize(floquet_of_hb_orbit(hb, p.X, p.omega, c.scaling.x[0]).modulus);
}
BENCHMARK(BM_Ex03FloquetPoint)->Unit(benchmark::kMicrosecond);

// The period-2 branch of ex. 03 (hb/period_doubling.hpp) at H = 40 (H2 = 80; at H = 21 the
// period-2 model has no branch point): the switch at the first PD, the continuation to the
// second, every point's Floquet multipliers over two forcing periods and its bifurcations
// located. The period-1 sweep is computed once, outside the timing.
static void BM_Ex03Period2Branch(benchmark::State& st) {
  const HarmonicBalance hb = test_models::nlvib_ex03(40);
  SweepOptions o = ex03_options(StabilityMethod::floquet, true, 0.02, 0.0);
  const FrequencyCurve c = sweep_frequency(hb, o, "ex03");
  PeriodDoublingOptions pdo;
  pdo.fast_iterations = int(st.range(0));
  pdo.curvature_predictor = st.range(1) != 0;
  std::size_t points = 0;
  int rejected = 0, iterations = 0;
  for (auto _ : st) {
    const auto br = period_doubled_branches(hb, c, o, pdo);
    if (br.size() != 1 || br[0].end != PeriodDoubledBranch::End::merged) st.SkipWithError("no merged branch");
    points = br.empty() ? 0 : br[0].curve.branch.points.size();
    rejected = br.empty() ? 0 : br[0].curve.branch.rejected_steps;
    iterations = 0;
    for (const auto& p : br.empty() ? std::vector<BranchPoint>{} : br[0].curve.branch.points) iterations += p.iterations;
  }
  st.counters["points"] = double(points);
  st.counters["rejected"] = double(rejected);               // rejected continuation steps
  st.counters["iterations"] = double(iterations);           // corrector iterations of the accepted points
}
// fast_iterations: the branch's step-growth rule (PeriodDoublingOptions; 4, the default, lets the
// step grow after the period-2 corrector's usual 4 iterations; at 3 it grows only now and then);
// curvature: PeriodDoublingOptions::curvature_predictor (1, the default: on).
BENCHMARK(BM_Ex03Period2Branch)->ArgsProduct({{3, 4}, {0, 1}})->ArgNames({"fast_iterations", "curvature"})
    ->Unit(benchmark::kMillisecond);

// One corrector iteration of that branch at its middle point: the period-2 model's
// linearization (residual, product matrix, condensed system) and one bordered solve.
static void BM_Ex03Period2Iteration(benchmark::State& st) {
  const HarmonicBalance hb = test_models::nlvib_ex03(40);
  const SweepOptions o = ex03_options(StabilityMethod::floquet, true, 0.02, 0.0);
  const auto br = period_doubled_branches(hb, sweep_frequency(hb, o, "ex03"), o);
  if (br.empty() || br[0].curve.branch.points.size() < 3) {
    st.SkipWithError("no period-2 branch");
    return;
  }
  const HarmonicBalance& hbp = *br[0].model;
  const BranchPoint& p = br[0].curve.branch.points[br[0].curve.branch.points.size() / 2];
  const Scaling& s = br[0].curve.scaling;
  Eigen::VectorXd R, dRdomega, dy, row = Eigen::VectorXd::Zero(hbp.size() + 1), rhs = row;
  row[hbp.size()] = 1.0;
  rhs[0] = 1.0;
  for (auto _ : st) {
    const auto lin = hbp.linearize(p.X, p.omega, s, R, dRdomega);
    benchmark::DoNotOptimize(lin->solve_bordered(row, rhs, dy));
  }
}
BENCHMARK(BM_Ex03Period2Iteration)->Unit(benchmark::kMicrosecond);

