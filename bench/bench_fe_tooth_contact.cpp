// Tooth contact by finite elements (lib/gearhb/gears/fe_tooth_contact.hpp), the issue 33
// §5 target: the FE models of a pair built and factored once (one model when both gears
// are alike), the influence coefficients of 64 mesh phases, then STE at 3 torques.
//   BM_fe_pair_build_and_ste/case   meshing, assembly, factor, influence coefficients,
//                                   STE at the file's 3 torques x 64 phases
//   BM_fe_pair_build_and_ste_knots16/case   the same with the compliances interpolated
//                                   from 17 phase knots (FePairOptions::knots_per_base_pitch)
//   BM_fe_pair_ste_only/case        the 3 x 64 contact problems alone (the model reused:
//                                   what a study of 100 tip reliefs costs per relief)
// case: 0 thesis 50/50 (m 3), 1 FZG C 16/24 (m 4.5), 2 ROSS 62/62 (m 2, bore 17.5 mm);
// default options (whole gears, default mesh density).
// Counters: nodes of each gear model, factor storage [MB] of each.
// Run: build/bin/gearhb_bench --benchmark_filter=BM_fe_pair
// Memory: /usr/bin/time -v build/bin/gearhb_bench --benchmark_filter=BM_fe_pair_build_and_ste/0
#include <benchmark/benchmark.h>

#include <array>

#include "gearhb/gears/fe_tooth_contact.hpp"

using namespace gearhb;

namespace {

GearGeometry spur(double m, int z, double x, double b) {
  GearGeometry g;
  g.module = m;
  g.teeth = z;
  g.profile_shift = x;
  g.addendum = m;
  g.dedendum = 1.25 * m;
  g.face_width = b;
  return g;
}

struct Case {
  PairSteModel pair;
  FePairOptions options;
  std::array<double, 3> torques;
};

// chapters/gearhb_gear/examples/{thesis_pair,fzg_c,ross_pair}.json
Case example(int k) {
  Case c;
  if (k == 0) {
    c.pair.gear1 = c.pair.gear2 = spur(3e-3, 50, 0, 0.02);
    c.pair.youngs_modulus1 = c.pair.youngs_modulus2 = 207e9;
    c.torques = {100, 200, 300};
  } else if (k == 1) {
    c.pair.gear1 = spur(4.5e-3, 16, 0.1817, 0.014);
    c.pair.gear2 = spur(4.5e-3, 24, 0.1715, 0.014);
    c.pair.centre_distance = 0.0915;
    c.pair.youngs_modulus1 = c.pair.youngs_modulus2 = 206e9;
    c.torques = {94.1, 183.4, 302.0};
  } else {
    c.pair.gear1 = c.pair.gear2 = spur(2e-3, 62, 0, 0.02);
    c.pair.youngs_modulus1 = c.pair.youngs_modulus2 = 206e9;
    c.options.gear1.rim_radius = c.options.gear2.rim_radius = 0.0175;
    c.torques = {50, 100, 200};
  }
  return c;
}

void counters(benchmark::State& state, const FePairModel& m) {
  state.counters["nodes1"] = m.gear1().mesh().node_count();
  state.counters["nodes2"] = m.gear2().mesh().node_count();
  state.counters["factor1_MB"] = m.gear1().factor_stats().factor_bytes / 1e6;
  state.counters["factor2_MB"] = m.gear2().factor_stats().factor_bytes / 1e6;
}

void BM_fe_pair_build_and_ste(benchmark::State& state) {
  const Case c = example(int(state.range(0)));
  for (auto _ : state) {
    const FePairModel m(c.pair, 64, c.options);
    for (double t : c.torques) benchmark::DoNotOptimize(m.ste(t));
    counters(state, m);
  }
}
BENCHMARK(BM_fe_pair_build_and_ste)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_fe_pair_build_and_ste_knots16(benchmark::State& state) {
  Case c = example(int(state.range(0)));
  c.options.knots_per_base_pitch = 16;
  for (auto _ : state) {
    const FePairModel m(c.pair, 64, c.options);
    for (double t : c.torques) benchmark::DoNotOptimize(m.ste(t));
    counters(state, m);
  }
}
BENCHMARK(BM_fe_pair_build_and_ste_knots16)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_fe_pair_ste_only(benchmark::State& state) {
  const Case c = example(int(state.range(0)));
  const FePairModel m(c.pair, 64, c.options);
  for (auto _ : state)
    for (double t : c.torques) benchmark::DoNotOptimize(m.ste(t));
  counters(state, m);
}
BENCHMARK(BM_fe_pair_ste_only)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
