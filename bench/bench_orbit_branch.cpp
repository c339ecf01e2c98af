// The step "orbit -> HB branch" (hb/orbit_branch.hpp): from a time-integrated periodic orbit,
// HB by Newton from its Fourier coefficients, checked against it, continued both ways with
// Floquet stability and the bifurcations located. Two cases:
//  - ch. 6 Fig. 41's isola (kc = 5e8 N/m, Fi = 1e7 N m, Fa = 1e4, H = 10, range 2000-62000
//    rad/s, ds_max 0.005 as the chapter runs it), from the orbit GSL rk8pd settles on at 13700
//    rad/s from the closed-mesh linear orbit (3000 periods, outside the timing);
//  - the one-sided clearance oscillator of tests/unit/test_orbit_branch.cpp (H = 12) from its
//    large orbit at omega = 1.26.
//   build/bin/gearhb_bench --benchmark_filter=orbit_branch
#include <benchmark/benchmark.h>

#include "gearhb/hb/orbit_branch.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "../tests/unit/gear_pair_models.hpp"
#include "../tests/unit/test_models.hpp"

using namespace gearhb;

static void BM_orbit_branch_fig41_isola(benchmark::State& state) {
  const HarmonicBalance hb = test_models::ch06_gear_pair(1e7);
  const double w = 13700.0;
  TimeIntegrationOptions to;
  to.x_scale = 1e-3;
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, hb.closed_contact_solution(w), w, x0, v0);
  const SteadyState s = TimeIntegrator(hb).steady_state(x0, v0, w, to);
  const SweepOptions o = test_models::ch06_sweep();
  for (auto _ : state) {
    const OrbitBranch b = branch_from_orbit(hb, s.x0, s.v0, w, 1, o);
    state.counters["ok"] = b.ok ? 1.0 : 0.0;
    state.counters["points"] = double(b.curve.branch.points.size());
    state.counters["isola"] = b.isola ? 1.0 : 0.0;
  }
}
BENCHMARK(BM_orbit_branch_fig41_isola)->Unit(benchmark::kMillisecond);

static void BM_orbit_branch_one_sided(benchmark::State& state) {
  const HarmonicBalance hb = test_models::one_sided_clearance();
  const SteadyState s = TimeIntegrator(hb).steady_state(Eigen::VectorXd::Constant(1, 4.0), Eigen::VectorXd::Zero(1),
                                                        1.26, TimeIntegrationOptions{});
  const SweepOptions o = test_models::one_sided_clearance_range();
  for (auto _ : state) {
    const OrbitBranch b = branch_from_orbit(hb, s.x0, s.v0, 1.26, 1, o);
    state.counters["ok"] = b.ok ? 1.0 : 0.0;
    state.counters["points"] = double(b.curve.branch.points.size());
  }
}
BENCHMARK(BM_orbit_branch_one_sided)->Unit(benchmark::kMillisecond);
