// Potential-energy mesh stiffness (lib/gearhb/gears/tooth/potential_energy.hpp) of the thesis
// pair over one mesh cycle: 3 torques x 64 phases, every pair on the path of contact
// evaluated (1 or 2 pairs, each two tooth compliances + Hertz). The PE stiffness is linear
// (linear Hertz), so the three torques repeat the same work; they stand for the issue-20
// benchmark's "3 torques x 64 phases". Arg: Gauss-Legendre points per tooth piece.
#include <benchmark/benchmark.h>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"

using namespace gearhb;

static void BM_pe_mesh_cycle_3x64(benchmark::State& state) {
  PeGear g;
  g.youngs_modulus = 207e9;
  g.bore_radius = 0.025;
  PeOptions o;
  o.quadrature_points = int(state.range(0));
  const GearGeometry gg;   // the thesis gear, as g
  const PathOfContact path = path_of_contact(gg, gg);
  for (auto _ : state) {
    double sum = 0;
    for (double torque : {100.0, 200.0, 300.0}) {
      for (int i = 0; i < 64; ++i) {
        double k = 0;
        for (double s = i * path.base_pitch / 64; s <= path.AE; s += path.base_pitch) {
          const ContactRadii r = contact_radii(gg, gg, s);
          k += pe_pair_stiffness(g, g, r.r1, r.r2, true, o);
        }
        sum += torque / gg.pitch_radius() / k;   // the STE F / k of that phase
      }
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_pe_mesh_cycle_3x64)->Arg(16)->Arg(24)->Unit(benchmark::kMillisecond);
