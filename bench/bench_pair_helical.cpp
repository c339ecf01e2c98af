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
