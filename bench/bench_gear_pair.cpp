// A gear pair from its drawing (issue 20): the loaded STE of one pair, 3 torques x
// 64 phases, chapter 7's beam model (target < 50 ms on one core). Two pairs: the
// thesis gear (z 50/50) and the FZG type C pair (z 16/24, shifted, consistent Hertz).
// Times go to programs/gearhb_gear/NOTES.md. Last: one whole design with its dynamics.
#include <benchmark/benchmark.h>

#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

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

// One design, whole (issue 21 section 3): geometry and beams, the STE at 3 torques, and per
// torque the one-DOF mesh (both flanks, 15 um backlash, zeta 0.08) swept with H = 10 over
// 0.1..1.5 times its mesh natural frequency with Floquet stability of every point and located
// bifurcations (the program's defaults). Target <= 1 s on one core. The thesis gear.
static void BM_gear_pair_design_thesis_3_curves_H10(benchmark::State& state) {
  const PairSteModel m;
  std::size_t points = 0;
  for (auto _ : state) {
    const std::vector<MeshPhase> phases = mesh_phases(m, 64);
    points = 0;
    for (double T : {100.0, 200.0, 300.0}) {
      const DteGear g = gear_pair_mesh(m, pair_ste(m, phases, T), T, 0.0158, 0.0158, 0.08, 15e-6);
      const HarmonicBalance hb = gear_mesh_model(g, MeshDofs::one_dof, {}, 10, 0, DteModel::constant);
      const double wn = 2.0 * M_PI * closed_contact_frequencies(g, MeshDofs::one_dof, {}).front();
      SweepOptions o;
      o.omega_min = 0.1 * wn;
      o.omega_max = 1.5 * wn;
      o.continuation.ds_max = 0.05;
      o.narrow_bands = state.range(0) != 0 ? BandSearch::always : BandSearch::never;
      o.locate_bifurcations = state.range(1) != 0;
      const FrequencyCurve c = sweep_frequency(hb, o, "bench");
      if (!c.complete) state.SkipWithError(c.failure.c_str());
      points += c.branch.points.size();
    }
  }
  state.counters["points"] = double(points);
}
// Args: narrow-band search forced on (SweepOptions::narrow_bands = always; by default it runs
// for time-varying stiffnesses only), bifurcation location; 0, 1 is the program's sweep.
BENCHMARK(BM_gear_pair_design_thesis_3_curves_H10)
    ->ArgNames({"narrow_bands", "locate"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond);
