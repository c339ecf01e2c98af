// Chapter 6: the Fig. 40 curve of the gear pair (kc = 5e8 N/m, Fi = 1e5 N m,
// Fa = 1e4, H = 10, 2000-62000 rad/s, ds_max 0.005 as the chapter runs it) with
// the Floquet stability of every point and the bifurcations located; and the
// Floquet multipliers of one point of it. Times go to the chapter README.
//   build/bin/gearhb_bench --benchmark_filter=ch06
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "../tests/unit/gear_pair_models.hpp"

using namespace gearhb;

namespace {
HarmonicBalance fig40_model() { return test_models::ch06_gear_pair(1e5); }
SweepOptions fig40_sweep(bool stability) {
  return test_models::ch06_sweep(stability ? StabilityMethod::floquet : StabilityMethod::none);
}
}  // namespace

// stability: 0 none, 1 Floquet of every point and the bifurcations located.
static void BM_ch06_fig40_curve(benchmark::State& state) {
  const HarmonicBalance hb = fig40_model();
  const SweepOptions o = fig40_sweep(state.range(0) != 0);
  for (auto _ : state) {
    const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
    state.counters["points"] = double(c.branch.points.size());
    state.counters["bifurcations"] = double(c.bifurcations.size());
  }
}
BENCHMARK(BM_ch06_fig40_curve)->Arg(0)->Arg(1)->ArgNames({"stability"})->Unit(benchmark::kMillisecond);

// One point near the first resonance (shooting correction + diagonalised propagators).
static void BM_ch06_floquet_point(benchmark::State& state) {
  const HarmonicBalance hb = fig40_model();
  SweepOptions o = fig40_sweep(false);
  o.omega_max = 9000.0;
  const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
  const auto& p = c.branch.points[c.branch.points.size() / 2];
  for (auto _ : state) benchmark::DoNotOptimize(floquet_of_hb_orbit(hb, p.X, p.omega, c.scaling.x[0]).modulus);
}
BENCHMARK(BM_ch06_floquet_point)->Unit(benchmark::kMicrosecond);

// One corrector step's linear algebra on the gear pair (n = 6 DOFs, one contact) against
// H: linearise and solve one bordered system, condensed (HarmonicBalance::linearize:
// an LU of 2H+2 rows) or dense (DenseLinearization: an LU of 6(2H+1)+1 rows).
static void BM_ch06_bordered_solve(benchmark::State& state) {
  const int H = int(state.range(0));
  const HarmonicBalance hb = test_models::ch06_gear_pair(1e5, H);
  const double w = 9000.0;
  const Scaling s = hb.scaling(2000.0, 62000.0);
  const Eigen::VectorXd X = 20.0 * hb.closed_contact_solution(w);   // intermittent contact
  Eigen::VectorXd row = Eigen::VectorXd::Ones(hb.size() + 1), rhs = row, dy, R, dRdomega;
  Eigen::MatrixXd J;
  for (auto _ : state) {
    if (state.range(1)) {
      const auto lin = hb.linearize(X, w, s, R, dRdomega);
      if (!lin->solve_bordered(row, rhs, dy) || !lin->last_solve_structured()) state.SkipWithError("not condensed");
    } else {
      hb.evaluate(X, w, R, &J, &dRdomega);
      DenseLinearization(J, dRdomega, s).solve_bordered(row, rhs, dy);
    }
    benchmark::DoNotOptimize(dy.data());
  }
  state.counters["unknowns"] = double(hb.size());
}
BENCHMARK(BM_ch06_bordered_solve)->ArgsProduct({{5, 10, 20, 40}, {0, 1}})->ArgNames({"H", "condensed"})
    ->Unit(benchmark::kMicrosecond);

// The bifurcation diagram by time integration (hb/bifurcation_diagram.hpp, default options)
// on Fig. 40's case over 10.0-10.8 krad/s, 6 speeds each way: chaos up to the end of the
// unstable stretch at 10.66 krad/s (the chapter's key numbers), a stable period-1 orbit at
// 10.8 krad/s. down_from_hb: 0 the down sweep from the up sweep's end (one thread), 1 from the
// HB orbit at 10.8 krad/s (the two sweeps on two threads); sequential_stop: 0 every Lyapunov
// estimate over lyapunov_periods (the default), 1 lyapunov_min_periods = 50 (as ch. 6). The HB sweep is outside
// the timing. CPU time: the process' (both threads).
static void BM_ch06_fig40_diagram(benchmark::State& state) {
  const HarmonicBalance hb = fig40_model();
  SweepOptions o = fig40_sweep(false);
  o.omega_max = 10800.0;
  const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
  const auto lowest = std::min_element(c.branch.points.begin(), c.branch.points.end(),
                                       [](const auto& a, const auto& b) { return a.omega < b.omega; });
  const auto highest = std::max_element(c.branch.points.begin(), c.branch.points.end(),
                                        [](const auto& a, const auto& b) { return a.omega < b.omega; });
  Eigen::VectorXd x0, v0;
  BifurcationDiagramOptions d;
  d.speeds = 6;
  d.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  hb_initial_state(hb, lowest->X, lowest->omega, x0, v0);
  if (state.range(0)) hb_initial_state(hb, highest->X, highest->omega, d.down_x0, d.down_v0);
  if (state.range(1)) d.lyapunov_min_periods = 50;
  long chaotic = 0, periodic = 0, lyapunov_periods = 0;
  for (auto _ : state) {
    const BifurcationDiagram b = bifurcation_diagram(hb, 10000.0, 10800.0, x0, v0, d);
    chaotic = periodic = lyapunov_periods = 0;
    for (const DiagramPoint& p : b.points)
      chaotic += p.motion == Motion::chaotic, periodic += p.motion == Motion::periodic,
          lyapunov_periods += p.lyapunov_periods;
  }
  state.counters["chaotic_speeds"] = double(chaotic);
  state.counters["periodic_speeds"] = double(periodic);
  state.counters["lyapunov_periods"] = double(lyapunov_periods);
}
BENCHMARK(BM_ch06_fig40_diagram)->ArgsProduct({{0, 1}, {0, 1}})->ArgNames({"down_from_hb", "sequential_stop"})->Unit(benchmark::kSecond)
    ->Iterations(1)->UseRealTime()->MeasureProcessCPUTime();

// What one speed of Fig. 40's diagram costs above 12 krad/s (the chapter's bands there, step 3b
// of its README): 4 speeds each way from `lo` rad/s in the band's step (12.7 krad/s: chaos, 100
// rad/s; 36 krad/s: the period-3 orbit, 200; 40 krad/s: chaos, 200; 60 krad/s: period 2, 500),
// the chapter's options there (period_tol 1e-8, lyapunov_min_periods 50, x_scale the whole
// curve's), the up sweep from the curve's orbit nearest lo, the down sweep after it (one
// thread). The curve is outside the timing. cpu_s_per_speed: the process' CPU time / 8.
static void BM_ch06_fig40_diagram_speed(benchmark::State& state) {
  static const HarmonicBalance hb = fig40_model();
  static const FrequencyCurve c = require_complete(sweep_frequency(hb, fig40_sweep(false), "bench"), "bench");
  const double lo = double(state.range(0)), step = double(state.range(1));
  const auto nearest = std::min_element(c.branch.points.begin(), c.branch.points.end(), [lo](const auto& a, const auto& b) {
    return std::abs(a.omega - lo) < std::abs(b.omega - lo);
  });
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, nearest->X, nearest->omega, x0, v0);
  BifurcationDiagramOptions d;
  d.speeds = 4;
  d.period_tol = 1e-8;
  d.lyapunov_min_periods = 50;
  d.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  long periodic = 0;
  double cpu = 0.0;
  for (auto _ : state) {
    const std::clock_t t0 = std::clock();
    const BifurcationDiagram b = bifurcation_diagram(hb, lo, lo + 3.0 * step, x0, v0, d);
    cpu = double(std::clock() - t0) / CLOCKS_PER_SEC;
    periodic = 0;
    for (const DiagramPoint& p : b.points) periodic += p.motion == Motion::periodic;
  }
  state.counters["periodic_speeds"] = double(periodic);
  state.counters["cpu_s_per_speed"] = cpu / 8.0;
}
BENCHMARK(BM_ch06_fig40_diagram_speed)->Args({12700, 100})->Args({36000, 200})->Args({40000, 200})->Args({60000, 500})
    ->ArgNames({"lo", "step"})->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime()->MeasureProcessCPUTime();
