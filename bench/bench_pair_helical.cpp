// A helical pair by slices (issue 35): ISO/TR 6336-30 Example 01 (m_n 8 mm, beta 15.8 deg,
// z 17/103, b 100 mm, a_w 500 mm), beam model, the default 20 slices, 3 torques x 64 phases:
// the slices' sections and stiffnesses built, then the load shared over slices x pairs per
// torque (target <= 50 ms on one core). Two readings: Hertz inside the sharing (the example
// file's: a nested Brent over about 50 contacts per phase) and no Hertz (the linear active set,
// the potential-energy method's path). Times go to programs/gearhb_gear/NOTES.md.
#include <benchmark/benchmark.h>

#include "gearhb/gears/pair/pair_helical.hpp"

using namespace gearhb;

namespace {

PairSteModel example01(HelicalPair& h, HertzCount hertz) {
  h.helix_angle = 15.8 * M_PI / 180.0;
  h.normal_module = 8e-3;
  h.shift1 = 0.145;
  h.slices = 20;
  PairSteModel m;
  GearGeometry* g[2] = {&m.gear1, &m.gear2};
  const int z[2] = {17, 103};
  const double x[2] = {0.145, 0.0};
  for (int i = 0; i < 2; ++i) {
    GearGeometry n;
    n.module = 8e-3;
    n.teeth = z[i];
    n.addendum = 8e-3;
    n.dedendum = 1.4 * 8e-3;
    n.face_width = 0.1;
    n.profile_shift = x[i];
    *g[i] = transverse_section(n, h.helix_angle);
  }
  m.centre_distance = 0.5;
  m.youngs_modulus1 = m.youngs_modulus2 = 206e9;
  m.hertz = hertz;
  m.pair_hertz = TwoPairHertz::consistent;
  m.pair_stiffness = PairStiffness::cantilevers;
  m.tooth_force = ToothForce::over_base_radius;
  return m;
}

void run(benchmark::State& state, HertzCount hertz) {
  HelicalPair h;
  const PairSteModel m = example01(h, hertz);
  for (auto _ : state) {
    const auto pair = sliced_loaded_pair(m, h, 64);
    double sum = 0.0;
    for (double T : {4500.0, 9000.0, 13500.0})
      for (const PairStePoint& p : pair->ste(T)) sum += p.ste;
    benchmark::DoNotOptimize(sum);
  }
}

}  // namespace

static void BM_helical_pair_ex01_20_slices_3_torques_64_phases_hertz(benchmark::State& state) {
  run(state, HertzCount::per_contact);
}
BENCHMARK(BM_helical_pair_ex01_20_slices_3_torques_64_phases_hertz)->Unit(benchmark::kMillisecond);

static void BM_helical_pair_ex01_20_slices_3_torques_64_phases_linear(benchmark::State& state) {
  run(state, HertzCount::none);
}
BENCHMARK(BM_helical_pair_ex01_20_slices_3_torques_64_phases_linear)->Unit(benchmark::kMillisecond);

// Method fe by slices (issue 35 a): programs/gearhb_gear/examples/helical_pair_fe.json (the thesis
// pair made helical, m_n 3 mm, beta 20 deg, b 20 mm, bores 25 mm), 20 slices x 64 phases.
// build: meshing, assembly, factor and the influence coefficients of every slice contact (one
// FE solve per distinct point per gear); ste: the 3 torques' block contact problems alone.
namespace {

PairSteModel helical_thesis_pair(HelicalPair& h, FePairOptions& o) {
  const double beta = 20.0 * M_PI / 180.0;
  GearGeometry g;   // the thesis gear: z 50, m 3 mm, 20 deg, b 20 mm
  h.helix_angle = beta;
  h.normal_module = g.module;
  h.slices = 20;
  PairSteModel m;
  m.gear1 = m.gear2 = transverse_section(g, beta);
  m.youngs_modulus1 = m.youngs_modulus2 = 207e9;
  m.hertz = HertzCount::none;
  m.tooth_force = ToothForce::over_base_radius;
  o.gear1.rim_radius = o.gear2.rim_radius = 0.025;
  return m;
}

}  // namespace

static void BM_helical_pair_fe_20_slices_64_phases_build(benchmark::State& state) {
  HelicalPair h;
  FePairOptions o;
  const PairSteModel m = helical_thesis_pair(h, o);
  for (auto _ : state) benchmark::DoNotOptimize(sliced_fe_loaded_pair(m, h, 64, o));
}
BENCHMARK(BM_helical_pair_fe_20_slices_64_phases_build)->Unit(benchmark::kMillisecond)->Iterations(1);

static void BM_helical_pair_fe_20_slices_3_torques_64_phases_ste(benchmark::State& state) {
  HelicalPair h;
  FePairOptions o;
  const PairSteModel m = helical_thesis_pair(h, o);
  const auto pair = sliced_fe_loaded_pair(m, h, 64, o);
  for (auto _ : state) {
    double sum = 0.0;
    for (double T : {100.0, 200.0, 300.0})
      for (const PairStePoint& p : pair->ste(T)) sum += p.ste;
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_helical_pair_fe_20_slices_3_torques_64_phases_ste)->Unit(benchmark::kMillisecond);
