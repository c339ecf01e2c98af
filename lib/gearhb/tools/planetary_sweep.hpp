#pragma once
// The sweep of a planetary-set file's `response` (programs/gearhb_planetary), shared by the
// program and its benchmark so that both time the same computation.
//
// The stability of every point as the pair programs' sweep computes it (hb/frequency_sweep.hpp
// analyse_stability: Floquet multipliers at every point, each change of the count outside the
// unit circle located on the chord and classified as fold, period doubling or Neimark-Sacker),
// with two choices made for the set's size (24 DOFs for five planets), both measured on the
// five-planet star set (examples/gtf_star_five_planets.json, 134 points; gearhb_bench
// --benchmark_filter=planetary):
//  - the multipliers of the variational equation about the HB orbit (FloquetOptions::
//    correct_orbit = false; floquet.hpp floquet_of_hb_variational), not those of the orbit
//    corrected by shooting: the meshes' stiffness varies with the mesh phase, so the
//    corrected orbit needs GSL's period map with 2n + 4n^2 = 2352 equations, about 3 s a point
//    (446 s for the curve) against 0.065 s (8.7 s);
//  - no search for instability bands narrower than a step between two stable points
//    (BandSearch::never; frequency_sweep.hpp add_narrow_bands): it cost 58 s more on the star
//    set (12-40 Floquet points for each interval whose critical multiplier lies near the real
//    axis beyond 0.75, which a lightly damped set has everywhere) and found none there.
#include <algorithm>
#include <cmath>

#include <string>
#include <vector>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/tools/planetary_file.hpp"

namespace gearhb {

// The continuation over the file's mesh-frequency range (no stability: the program times it
// as its own step, planetary_stability_options).
inline SweepOptions planetary_sweep_options(const PlanetaryFile& f) {
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * f.response.f_mesh_hz_from;
  o.omega_max = 2.0 * M_PI * f.response.f_mesh_hz_to;
  o.stability = StabilityMethod::none;
  return o;
}

// The same options for analyse_stability (see above).
inline SweepOptions planetary_stability_options(SweepOptions o) {
  o.stability = StabilityMethod::floquet;
  o.locate_bifurcations = true;
  o.floquet.correct_orbit = false;
  o.narrow_bands = BandSearch::never;
  return o;
}

// The curve over the range of o (planetary_sweep_options) and the stability of every point with
// its bifurcations: the program's two steps in one, for its benchmark and tests (throws if the
// curve is incomplete).
inline FrequencyCurve planetary_response_with_stability(const HarmonicBalance& hb, const SweepOptions& o,
                                                        const std::string& label) {
  FrequencyCurve c = require_complete(sweep_frequency(hb, o, label), label);
  c.stable.clear();
  c.floquet.clear();
  analyse_stability(hb, planetary_stability_options(o), c);
  return c;
}

// The period-doubled branches from the located period doublings of the response c (o: the
// sweep's options, whose range bounds them), as the pair programs switch them
// (hb/period_doubling.hpp period_doubling_cascade, to period 2^depth) with the stability options
// above: the switch's eigen-solution and the branches' multipliers from the variational equation
// about the HB orbit (the meshes' stiffness varies: no exact flow), over two mesh periods.
inline std::vector<PeriodDoubledBranch> planetary_period_doubled_branches(const HarmonicBalance& hb,
                                                                          const FrequencyCurve& c,
                                                                          const SweepOptions& o, int depth) {
  return period_doubling_cascade(hb, c, planetary_stability_options(o), depth);
}

// The bifurcation diagram of a set (issue 34 section 3; programs/gearhb_planetary): its bands are
// app/bifurcation_input.hpp diagram_bands with these options: each range with no stable period-1
// orbit padded on both sides by its own width (margin 1, no least margin), so that the diagram
// starts and ends on the stable period-1 orbit beside the range where there is one (the agreement
// with HB is checked there). A whole width because the curve's points are sparse (14 over the
// Lin & Parker set's 1494-1530 Hz): half a width ended the test's band between the range and the
// curve's first stable point, where HB has no segment stable at both ends to solve an orbit on.
inline DiagramBandOptions planetary_diagram_bands() {
  DiagramBandOptions o;
  o.margin = 1.0;
  o.min_margin = 0.0;
  return o;
}

// Speeds of each sweep over a band width_hz wide: kDiagramSpeedsPerHz a hertz (both ends
// included), at least kDiagramSpeedsMin, at most kDiagramSpeedsMax (the cost: each speed
// integrates up to transient_periods + periods mesh periods of the 2n equations, and a speed
// that is not periodic lyapunov_periods more with one tangent vector (4n), and shoots with the
// monodromy's 2n + 4n^2 if it is not chaotic; bench/bench_planetary.cpp BM_planetary_diagram_*
// measures it).
constexpr double kDiagramSpeedsPerHz = 0.1;
constexpr int kDiagramSpeedsMin = 3, kDiagramSpeedsMax = 6;
inline int planetary_diagram_speeds(double width_hz) {
  return std::clamp(int(std::ceil(kDiagramSpeedsPerHz * width_hz)) + 1, kDiagramSpeedsMin, kDiagramSpeedsMax);
}

}  // namespace gearhb
