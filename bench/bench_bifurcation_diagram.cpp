// The bifurcation diagram by time integration (issue 34 §3): the light-load gear
// (programs/gearhb_gear/examples/thesis_pair_light_load.json, read as gearhb_gear reads it) at
// its 20 N m torque, 400 speeds swept up and down over 300 .. 5000 Hz mesh frequency with the
// library's default options, from the HB orbit at the lowest speed (the HB sweep outside the
// timing). Target <= 30 s on 2 cores. Times go to programs/gearhb_gear/NOTES.md.
#include <algorithm>
#include <string>

#include <benchmark/benchmark.h>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/tools/gear_file.hpp"
#include "gearhb/gears/pair/loaded_pair.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"

#ifndef GEARHB_SOURCE_DIR
#define GEARHB_SOURCE_DIR "."
#endif

using namespace gearhb;

static void BM_bifurcation_diagram_light_load_gear_400_speeds(benchmark::State& state) {
  const GearFile f = read_gear_file(std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_gear/examples/thesis_pair_light_load.json", {});
  const auto loaded = phase_loaded_pair(f.pair, f.phases);
  const double T = 20.0;
  const DteGear g = gear_pair_mesh(f.pair, loaded->ste(T), T, f.gear[0].inertia, f.gear[1].inertia, f.dynamics.zeta,
                                   f.backlash);
  const HarmonicBalance hb = gear_mesh_model(g, MeshDofs::one_dof, {}, f.dynamics.harmonics, 0, f.dynamics.mesh);
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * f.dynamics.f_min_hz;
  o.omega_max = 2.0 * M_PI * f.dynamics.f_max_hz;
  o.continuation.ds_max = 0.05;
  const FrequencyCurve c = sweep_frequency(hb, o, "bench");
  if (!c.complete) state.SkipWithError(c.failure.c_str());
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, c.branch.points.front().X, c.branch.points.front().omega, x0, v0);
  BifurcationDiagramOptions d;
  d.speeds = 400;
  d.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  long chaotic = 0, periodic = 0;
  for (auto _ : state) {
    const BifurcationDiagram b = bifurcation_diagram(hb, o.omega_min, o.omega_max, x0, v0, d);
    chaotic = periodic = 0;
    for (const DiagramPoint& p : b.points) chaotic += p.motion == Motion::chaotic, periodic += p.motion == Motion::periodic;
  }
  state.counters["chaotic_speeds"] = double(chaotic);
  state.counters["periodic_speeds"] = double(periodic);
}
BENCHMARK(BM_bifurcation_diagram_light_load_gear_400_speeds)->Unit(benchmark::kSecond)->Iterations(1);

// What one speed of a default diagram costs (the band rule's cap, app/bifurcation_input.hpp
// DiagramBandOptions): the light-load gear at 20 N m, one DOF (Arg 0, thesis_pair_light_load.json)
// or six (Arg 1, thesis_pair_light_load_six_dof.json), over the six-DOF run's upper band (2468-6000
// rpm, mesh 2056.7-5000 Hz: period 1 unstable over most of it), 8 speeds a sweep, the library's
// default options, as the programs run it: up from the HB orbit at the band's lower end, down
// from the stable HB orbit at its upper end on a second thread (set_down_start). The HB sweep
// with Floquet stability outside the timing. Counter s_per_speed: wall seconds per speed of one
// sweep (the two sweeps run at once, so also per speed of the band).
static void BM_bifurcation_diagram_speed_cost(benchmark::State& state) {
  const char* file = state.range(0) ? "thesis_pair_light_load_six_dof.json" : "thesis_pair_light_load.json";
  const GearFile f = read_gear_file(std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_gear/examples/" + file, {});
  const auto loaded = phase_loaded_pair(f.pair, f.phases);
  const double T = 20.0;
  const DteGear g = gear_pair_mesh(f.pair, loaded->ste(T), T, f.gear[0].inertia, f.gear[1].inertia, f.dynamics.zeta,
                                   f.backlash);
  const HarmonicBalance hb =
      gear_mesh_model(g, f.dynamics.dofs, gear_file_bearings(f), f.dynamics.harmonics, 0, f.dynamics.mesh);
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * f.dynamics.f_min_hz;
  o.omega_max = 2.0 * M_PI * f.dynamics.f_max_hz;
  o.continuation.ds_max = 0.05;
  const FrequencyCurve c = sweep_frequency(hb, o, "bench");
  if (!c.complete) return state.SkipWithError(c.failure.c_str());
  const double lo = 2.0 * M_PI * 2468.0 * 50.0 / 60.0;
  const auto& P = c.branch.points;
  const auto start = std::min_element(P.begin(), P.end(), [lo](const BranchPoint& a, const BranchPoint& b) {
    return std::abs(a.omega - lo) < std::abs(b.omega - lo);
  });
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, start->X, start->omega, x0, v0);
  BifurcationDiagramOptions d;
  d.speeds = 8;
  d.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  state.counters["down_from_hb"] = set_down_start(hb, c, o.omega_max, d) ? 1.0 : 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(bifurcation_diagram(hb, lo, o.omega_max, x0, v0, d));
  state.counters["dofs"] = double(hb.dofs());
  state.counters["s_per_speed"] = benchmark::Counter(double(d.speeds), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_bifurcation_diagram_speed_cost)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
