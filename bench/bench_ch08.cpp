// Chapter 8: one full 300 N m DTE curve (300-5000 Hz, Floquet stability of every
// point, bifurcations located) at H = 5 and H = 20. Times go to the chapter README.
#include <benchmark/benchmark.h>

#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

using namespace gearhb;

static void BM_ch08_curve_300Nm(benchmark::State& state) {
  const int H = int(state.range(0));
  SteModel m;
  const std::vector<double> e = ste_values(ste_continuous(m, 300.0, 64));
  DteGear g;
  g.F0 = 300.0 / m.gear.pitch_radius();
  g.me = equivalent_mass(0.0158, 0.0158, m.gear.pitch_radius(), m.gear.pitch_radius());
  g.kc = mean_stiffness(e, g.F0);
  g.c = mesh_damping(0.08, g.kc, g.me);
  g.ste = periodic_fourier(e, H);
  const HarmonicBalance hb = dte_harmonic_balance(g, H);
  SweepOptions o;
  o.omega_min = 2 * M_PI * 300;
  o.omega_max = 2 * M_PI * 5000;
  o.continuation.ds_max = 0.05;
  for (auto _ : state) {
    const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
    benchmark::DoNotOptimize(c.stable.size());
    state.counters["points"] = double(c.branch.points.size());
  }
}
BENCHMARK(BM_ch08_curve_300Nm)->Arg(5)->Arg(20)->Unit(benchmark::kMillisecond);
