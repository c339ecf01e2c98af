// The bifurcation diagram by time integration (issue 34 §3): the light-load gear
// (programs/gearhb_gear/examples/thesis_pair_light_load.json, read as gearhb_gear reads it) at
// its 20 N m torque, 400 speeds swept up and down over 300 .. 5000 Hz mesh frequency with the
// library's default options, from the HB orbit at the lowest speed (the HB sweep outside the
// timing). Target <= 30 s on 2 cores. Times go to programs/gearhb_gear/NOTES.md.
#include <algorithm>
#include <string>

#include <benchmark/benchmark.h>

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
