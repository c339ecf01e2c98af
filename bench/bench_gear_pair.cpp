// A gear pair from its drawing (issue 20): the loaded STE of one pair, 3 torques x
// 64 phases, chapter 7's beam model (target < 50 ms on one core). Two pairs: the
// thesis gear (z 50/50) and the FZG type C pair (z 16/24, shifted, consistent Hertz).
// Times go to chapters/gearhb_gear/README.md.
#include <benchmark/benchmark.h>

#include "gearhb/gears/ste_continuous.hpp"

using namespace gearhb;

namespace {
PairSteModel fzg_c() {
  PairSteModel m;
  for (GearGeometry* g : {&m.gear1, &m.gear2}) {
    g->module = 4.5e-3;
    g->addendum = 4.5e-3;
    g->dedendum = 1.25 * 4.5e-3;
    g->face_width = 14e-3;
  }
  m.gear1.teeth = 16;
  m.gear1.profile_shift = 0.1817;
  m.gear2.teeth = 24;
  m.gear2.profile_shift = 0.1715;
  m.centre_distance = 91.5e-3;
  m.youngs_modulus1 = m.youngs_modulus2 = 206e9;
  m.hertz = HertzCount::per_contact;
  m.pair_hertz = TwoPairHertz::consistent;
  m.pair_stiffness = PairStiffness::cantilevers;
  m.tooth_force = ToothForce::over_base_radius;
  return m;
}

void run(benchmark::State& state, const PairSteModel& m, const double (&torques)[3]) {
  for (auto _ : state) {
    const std::vector<MeshPhase> phases = mesh_phases(m, 64);   // beams, contact points, stiffnesses
    double sum = 0.0;
    for (double T : torques)
      for (const PairStePoint& p : pair_ste(m, phases, T)) sum += p.ste;
    benchmark::DoNotOptimize(sum);
  }
}
}  // namespace

static void BM_gear_pair_thesis_3_torques_64_phases(benchmark::State& state) {
  const double torques[3] = {100, 200, 300};
  run(state, PairSteModel(), torques);
}
BENCHMARK(BM_gear_pair_thesis_3_torques_64_phases)->Unit(benchmark::kMillisecond);

static void BM_gear_pair_fzg_c_3_torques_64_phases(benchmark::State& state) {
  const double torques[3] = {94.1, 183.4, 302.0};
  run(state, fzg_c(), torques);
}
BENCHMARK(BM_gear_pair_fzg_c_3_torques_64_phases)->Unit(benchmark::kMillisecond);
