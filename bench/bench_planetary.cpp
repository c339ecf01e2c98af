// Planetary sets (gears/sets/planetary.hpp, planetary_mesh.hpp): the natural frequencies
// and mode types of Lin & Parker's set, and the loaded five-planet set's response over
// 300-3000 Hz mesh frequency (H = 8, no stability) and the Floquet multipliers of the
// variational equation at one point of it, as gearhb_planetary runs them
// (programs/gearhb_planetary/examples/lin_parker_1999_loaded.json); and the five-planet star
// set of geared-turbofan proportions (examples/gtf_star_five_planets.json: both flanks on
// every mesh, 20 contacts) over its speed range with the stability of every point and the
// bifurcations, as the program computes them. Times go to the report.
// The example at its period doubling: the whole run with the switch, and the switch alone.
//   build/bin/gearhb_bench --benchmark_filter=planetary
#include <algorithm>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gearhb/tools/planetary_file.hpp"
#include "gearhb/tools/planetary_sweep.hpp"

using namespace gearhb;

namespace {
PlanetarySet lin_parker(int planets, double carrier_shaft) {
  PlanetarySet s = lin_parker_1999_set(planets);
  s.carrier.torsional = carrier_shaft;
  return s;
}
HarmonicBalance loaded(int planets) {
  const PlanetarySet s = lin_parker(planets, 1e8);
  PlanetaryMeshes m;
  m.sun = {5e8, 1.6, 1.5};
  m.ring = {5e8, 1.8, 1.5};
  m.phases = mesh_phases(PlanetaryTeeth{27, 33, 93, 0.0032, 1.0}, s.planet_angles, 0.0);
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
  f0(coordinate(Body::sun, 2)) = 100.0 / (0.5 * 27 * 0.0032 * std::cos(s.sun_pressure_angle));
  return planetary_harmonic_balance(s, m, 0.02, f0, 8);
}
SweepOptions range() {
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 300.0;
  o.omega_max = 2.0 * M_PI * 3000.0;
  o.stability = StabilityMethod::none;
  return o;
}
}  // namespace

static void BM_planetary_modes(benchmark::State& state) {
  const PlanetarySet s = lin_parker(int(state.range(0)), 0.0);
  for (auto _ : state) benchmark::DoNotOptimize(planetary_modes(s));
}
BENCHMARK(BM_planetary_modes)->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

static void BM_planetary_response(benchmark::State& state) {
  const HarmonicBalance hb = loaded(int(state.range(0)));
  for (auto _ : state) {
    const FrequencyCurve c = require_complete(sweep_frequency(hb, range(), "bench"), "bench");
    state.counters["points"] = double(c.branch.points.size());
  }
}
BENCHMARK(BM_planetary_response)->Arg(3)->Arg(5)->Unit(benchmark::kSecond)->Iterations(1);

static void BM_planetary_floquet_point(benchmark::State& state) {
  const HarmonicBalance hb = loaded(int(state.range(0)));
  SweepOptions o = range();
  o.omega_max = o.omega_min * 1.01;
  const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
  const BranchPoint& p = c.branch.points.back();
  for (auto _ : state) benchmark::DoNotOptimize(floquet_of_hb_variational(hb, p.X, p.omega));
}
BENCHMARK(BM_planetary_floquet_point)->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);

// The star set from its example file, as gearhb_planetary loads it (the ring held by the
// output shaft, the torque on the sun): the sweep, then the stability of every point and the
// bifurcations between them (tools/planetary_sweep.hpp, as the program runs them).
static void BM_planetary_star_response_with_stability(benchmark::State& state) {
  const PlanetaryFile f =
      read_planetary_file(std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/gtf_star_five_planets.json", {});
  const HarmonicBalance hb = planetary_response_model(f);
  const SweepOptions o = planetary_sweep_options(f);
  for (auto _ : state) {
    const FrequencyCurve c = planetary_response_with_stability(hb, o, "bench");
    state.counters["points"] = double(c.branch.points.size());
    state.counters["unstable"] = double(std::count(c.stable.begin(), c.stable.end(), false));
    state.counters["bifurcations"] = double(c.bifurcations.size());
  }
}
BENCHMARK(BM_planetary_star_response_with_stability)->Unit(benchmark::kSecond)->Iterations(1);

// The example at the loaded Lin-Parker set's period doubling (examples/lin_parker_1999_loaded_pd.json)
// as gearhb_planetary runs it: the sweep over its band, the stability of every point and the
// bifurcations, then the period-2 branch switched at the period doubling with its own stability
// (tools/planetary_sweep.hpp planetary_period_doubled_branches); then the switch and the branch
// alone.
namespace {
PlanetaryFile pd_example() {
  return read_planetary_file(
      std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/lin_parker_1999_loaded_pd.json", {});
}
}  // namespace

static void BM_planetary_period_doubling_example(benchmark::State& state) {
  const PlanetaryFile f = pd_example();
  const HarmonicBalance hb = planetary_response_model(f);
  const SweepOptions o = planetary_sweep_options(f);
  for (auto _ : state) {
    const FrequencyCurve c = planetary_response_with_stability(hb, o, "bench");
    const std::vector<PeriodDoubledBranch> br = planetary_period_doubled_branches(hb, c, o, f.period_doubling_depth);
    state.counters["points"] = double(c.branch.points.size());
    state.counters["branches"] = double(br.size());
    state.counters["period2_points"] = br.empty() ? 0.0 : double(br.front().curve.branch.points.size());
  }
}
BENCHMARK(BM_planetary_period_doubling_example)->Unit(benchmark::kSecond)->Iterations(1);

static void BM_planetary_period_doubling_switch(benchmark::State& state) {
  const PlanetaryFile f = pd_example();
  const HarmonicBalance hb = planetary_response_model(f);
  const SweepOptions o = planetary_sweep_options(f);
  const FrequencyCurve c = planetary_response_with_stability(hb, o, "bench");
  for (auto _ : state) benchmark::DoNotOptimize(planetary_period_doubled_branches(hb, c, o, f.period_doubling_depth));
}
BENCHMARK(BM_planetary_period_doubling_switch)->Unit(benchmark::kSecond)->Iterations(1);

// The Floquet multipliers of one point of the star set with its meshes from the teeth
// (examples/gtf_star_five_planets_teeth.json: 24 DOFs, 20 contacts whose stiffness is a
// Fourier series of the loaded teeth): the variational equation about the HB orbit, as the
// program's stability step runs it at each of its points (Arg: the mesh frequency, Hz).
static void BM_planetary_teeth_floquet_point(benchmark::State& state) {
  const PlanetaryFile f = read_planetary_file(
      std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/gtf_star_five_planets_teeth.json", {});
  const HarmonicBalance hb = planetary_response_model(f);
  SweepOptions o = planetary_sweep_options(f);
  o.omega_max = 2.0 * M_PI * double(state.range(0));
  o.omega_min = 0.99 * o.omega_max;
  const FrequencyCurve c = require_complete(sweep_frequency(hb, o, "bench"), "bench");
  const BranchPoint& p = c.branch.points.back();
  for (auto _ : state) benchmark::DoNotOptimize(floquet_of_hb_variational(hb, p.X, p.omega));
}
BENCHMARK(BM_planetary_teeth_floquet_point)->Arg(1310)->Arg(1400)->Arg(1490)->Unit(benchmark::kMillisecond);

// A planetary file's diagram as gearhb_planetary's step sets it up: the model, its curve with
// the stability, the first band (the range with no stable period-1 orbit padded and clipped,
// diagram_bands), the file's diagram options (x_scale the curve's) and the HB orbit at the
// curve's first point, the up sweep's start.
struct DiagramCase {
  explicit DiagramCase(const PlanetaryFile& file)
      : f(file), hb(planetary_response_model(f)), o(planetary_sweep_options(f)),
        c(planetary_response_with_stability(hb, o, "bench")),
        bands(diagram_bands(c, o.omega_min, o.omega_max, hb.dofs(), planetary_diagram_bands(), 1)), opt(f.diagram) {
    opt.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
    hb_initial_state(hb, c.branch.points.front().X, c.branch.points.front().omega, x0, v0);
  }
  BifurcationDiagram run() const { return bifurcation_diagram(hb, bands[0].omega_lo, bands[0].omega_hi, x0, v0, opt); }
  PlanetaryFile f;
  HarmonicBalance hb;
  SweepOptions o;
  FrequencyCurve c;
  std::vector<DiagramBand> bands;
  BifurcationDiagramOptions opt;
  Eigen::VectorXd x0, v0;
};

// The example's bifurcation diagram by time integration (the example file's options, 2 speeds a
// sweep) from the HB orbit at the band's start: the cost of the step; and the set's defaults
// (planetary_diagram_defaults, planetary_diagram_speeds) over the same band.
static void planetary_diagram(benchmark::State& state, bool file_options) {
  DiagramCase d(pd_example());
  if (d.bands.empty()) return state.SkipWithError("no band");
  if (!file_options) {
    const double x_scale = d.opt.integration.x_scale;
    d.opt = planetary_diagram_defaults();
    d.opt.integration.x_scale = x_scale;
    d.opt.speeds = planetary_diagram_speeds((d.bands[0].omega_hi - d.bands[0].omega_lo) / (2.0 * M_PI));
  }
  for (auto _ : state) state.counters["speeds"] = double(d.run().points.size());
}
static void BM_planetary_diagram_example(benchmark::State& state) { planetary_diagram(state, true); }
BENCHMARK(BM_planetary_diagram_example)->Unit(benchmark::kSecond)->Iterations(1);
static void BM_planetary_diagram_defaults(benchmark::State& state) { planetary_diagram(state, false); }
BENCHMARK(BM_planetary_diagram_defaults)->Unit(benchmark::kSecond)->Iterations(1);

// The diagram of CTest planetary.diagram.run (tests/data/planetary_diagram/: one band, 2 speeds
// a sweep, the file's options) as gearhb_planetary runs it: up from the HB orbit nearest the
// band's start, down from the stable HB orbit at its end on a second thread (set_down_start).
// Counters per speed (u0 u1 up, d0 d1 down, in sweep order): the transient periods discarded
// (t_), 1 where periodic by shooting (s_), the Lyapunov periods (l_); Arg: transient_periods.
static void BM_planetary_diagram_check_case(benchmark::State& state) {
  DiagramCase c(read_planetary_file(
      std::string(GEARHB_SOURCE_DIR) + "/tests/data/planetary_diagram/lin_parker_1999_loaded_above_pd.json", {}));
  if (c.bands.empty()) return state.SkipWithError("no band");
  c.opt.transient_periods = int(state.range(0));
  set_down_start(c.hb, c.c, c.bands[0].omega_hi, c.opt);
  for (auto _ : state) {
    const BifurcationDiagram d = c.run();
    for (std::size_t k = 0; k < d.points.size(); ++k) {
      const DiagramPoint& p = d.points[k];
      const std::string id = (p.up ? "u" : "d") + std::to_string(p.up ? k : k - d.points.size() / 2);
      state.counters["t_" + id] = p.transient;
      state.counters["s_" + id] = p.by_shooting ? 1.0 : 0.0;
      state.counters["l_" + id] = p.lyapunov_periods;
    }
  }
}
BENCHMARK(BM_planetary_diagram_check_case)->Arg(300)->Unit(benchmark::kSecond)->Iterations(1);
