// Tooth contact by finite elements (lib/gearhb/gears/pair/fe_tooth_contact.hpp), the issue 33
// §5 target: the FE models of a pair built and factored once (one model when both gears
// are alike), the influence coefficients of 64 mesh phases, then STE at 3 torques.
//   BM_fe_pair_build_and_ste/case/knots   meshing, assembly, factor, influence
//                                   coefficients, STE at the file's 3 torques x 64 phases;
//                                   knots 0: every phase loaded (default), 16: compliances
//                                   interpolated from 17 phase knots
//                                   (FePairOptions::knots_per_base_pitch)
//   BM_fe_pair_ste_only/case        the 3 x 64 contact problems alone (the model reused:
//                                   what a study of 100 tip reliefs costs per relief)
// case: 0 thesis 50/50 (m 3), 1 FZG C 16/24 (m 4.5), 2 ROSS 62/62 (m 2, bore 17.5 mm);
// default options (whole gears, default mesh density).
// Counters: nodes of each gear model, factor storage [MB] of each.
// Run: build/bin/gearhb_bench --benchmark_filter=BM_fe_pair
// Memory: /usr/bin/time -v build/bin/gearhb_bench --benchmark_filter=BM_fe_pair_build_and_ste/0/0
#include <benchmark/benchmark.h>

#include <array>

#include "../tests/unit/fe_pair_examples.hpp"

using namespace gearhb;
using fe_pair_examples::PairCase;

namespace {

void counters(benchmark::State& state, const FePairModel& m) {
  state.counters["nodes1"] = m.gear1().mesh().node_count();
  state.counters["nodes2"] = m.gear2().mesh().node_count();
  state.counters["factor1_MB"] = m.gear1().factor_stats().factor_bytes / 1e6;
  state.counters["factor2_MB"] = m.gear2().factor_stats().factor_bytes / 1e6;
}

// range(1): FePairOptions::knots_per_base_pitch (0: every phase loaded itself, the default).
void BM_fe_pair_build_and_ste(benchmark::State& state) {
  PairCase c = fe_pair_examples::issue_pairs()[std::size_t(state.range(0))];
  c.fe.knots_per_base_pitch = int(state.range(1));
  for (auto _ : state) {
    const FePairModel m(c.pair, 64, c.fe);
    for (double t : c.torques) benchmark::DoNotOptimize(m.ste(t));
    counters(state, m);
  }
}
BENCHMARK(BM_fe_pair_build_and_ste)->ArgsProduct({{0, 1, 2}, {0, 16}})->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_fe_pair_ste_only(benchmark::State& state) {
  const PairCase c = fe_pair_examples::issue_pairs()[std::size_t(state.range(0))];
  const FePairModel m(c.pair, 64, c.fe);
  for (auto _ : state)
    for (double t : c.torques) benchmark::DoNotOptimize(m.ste(t));
  counters(state, m);
}
BENCHMARK(BM_fe_pair_ste_only)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
