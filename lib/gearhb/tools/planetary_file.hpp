#pragma once
// A planetary-set file for gearhb_planetary (programs/gearhb_planetary/README.md): the
// set's drawing and the lumped parameters of Lin & Parker's model (gears/sets/planetary.hpp),
// SI units, in the frame of the gear-pair file.
//
//   {
//     "name": "Lin & Parker 1999 example set",
//     "planets": 3,                                N, equally spaced unless
//     "planet_angles_deg": [0, 120, 240],          optional: psi_n [deg], N entries, the first 0
//     "teeth": {"sun": 27, "planet": 33, "ring": 93},   z_s, z_p, z_r = z_s + 2 z_p
//     "module": 0.0032,                            m [m]
//     "addendum": 1.0,                             optional h_a* (units of m), the tip circles
//     "pressure_angle_deg": 24.6,                  operating pressure angle of both meshes
//     "sun":     {"mass": 0.4,  "inertia_r2": 0.39, "bearing": 1e8, "torsional": 0},
//     "ring":    {"mass": 2.35, "inertia_r2": 3.0,  "bearing": 1e8, "torsional": 1e9},
//     "carrier": {"mass": 5.43, "inertia_r2": 6.29, "bearing": 1e8, "torsional": 0},
//                                                  m [kg], I / r^2 [kg] (r: base radius, the
//                                                  carrier's: the planet-centre radius), radial
//                                                  bearing [N/m], torsional k_theta / r^2 [N/m]
//     "planet":  {"mass": 0.66, "inertia_r2": 0.61, "bearing": 1e8},   bearing: radial and tangential
//     "mesh":    {"sun_planet": 5e8, "ring_planet": 5e8,              mean mesh stiffness [N/m]
//                 "sun_contact_ratio": 1.6, "ring_contact_ratio": 1.8, optional (default 1.6, 1.8)
//                 "stiffness_ratio": 1.5,                              optional k_double / k_single (1)
//                 "ring_sun_phase": 0},                                optional gamma_rs [mesh cycles] (0)
//   or, the stiffnesses computed from the teeth (tools/planetary_stiffness.hpp; needs `response`):
//     "mesh":    {"stiffness": "tooth_model",                          (default "rectangular")
//                 "sun_planet_pair": {"basic_rack": {...}, "gears": [{sun}, {planet}], "model": {...}},
//                                     the sun-planet pair in the gear-pair file's keys (gear_file.hpp)
//                                     without z, module, pressure angle, addendum (the set's), x = 0
//                 "ring_planet_stiffness": "potential_energy",        or "iso6336"
//                 "ring_sun_phase": optional, default from the teeth (ring_sun_phase_from_teeth)
//                 "back_phase": optional; absent: each back flank's wave the mirror image of its
//                               drive flank's (planetary_mesh.hpp sun_back_mirror, ring_back_mirror)
//                 "ring_sun_phase": 0, ...backlash keys as above}
//     "response": {"input": "sun", "torque": 100,                      optional: the response over
//                  "output": "carrier", "output_shaft": 1e8,           mesh frequency; torque [N m] on the
//                  "f_mesh_hz": {"from": 300, "to": 3000},             input, the output member held by a
//                  "zeta": 0.02, "harmonics": 8, "stability": 1}        shaft of k_theta / r^2 [N/m]
//     "campbell": {"carrier_rpm_to": 6000, "points": 31}   optional: the natural frequencies over
//                                                  carrier speed 0..carrier_rpm_to (gyroscopic)
//   }
//
// Checks, each a UsageError naming the key: the ranges of every number, z_r = z_s + 2 z_p
// (teeth.ring: profile shifts are not modelled), the assembly condition ((z_s + z_r) / N
// whole for equally spaced planets: key planets; (z_s + z_r) psi_n / 360 whole for given
// angles: key planet_angles_deg.n), planets whose tip circles overlap (key planets or
// planet_angles_deg).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "gearhb/gears/sets/planetary.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/tools/planetary_stiffness.hpp"

namespace gearhb {

// The response over mesh frequency (`response`; programs/gearhb_planetary/README.md).
struct PlanetaryResponseInput {
  bool present = false;
  Body input = Body::sun, output = Body::carrier;
  double torque = 0.0;           // on the input [N m], > 0: loads the drive flanks
  double output_shaft = 0.0;     // torsional stiffness added to the output [N/m] (k_theta / r^2)
  double f_mesh_hz_from = 0.0, f_mesh_hz_to = 0.0;   // [Hz]
  double zeta = 0.02;            // modal damping ratio of the mean system
  int harmonics = 8;             // H
  bool stability = true;          // every point's Floquet multipliers and the bifurcations (tools/planetary_sweep.hpp)
};

struct PlanetaryFile {
  std::string name;
  PlanetaryTeeth teeth;
  PlanetarySet set;
  bool equally_spaced = true;   // no planet_angles_deg in the file
  PlanetaryMeshes meshes;       // the stiffness waves and mesh phases (planetary_mesh.hpp)
  bool tooth_model = false;     // mesh.stiffness tooth_model (tools/planetary_stiffness.hpp)
  nlohmann::json sun_planet_pair;   // mesh.sun_planet_pair as the file gives it
  RingPlanetModel ring_planet_model = RingPlanetModel::potential_energy;   // mesh.ring_planet_stiffness
  double ring_sun_phase = 0.0;            // tooth_model: gamma_rs used (the file's, or from the teeth)
  double ring_sun_phase_from_teeth = 0.0; // tooth_model: ring_sun_phase_from_teeth
  bool back_phase_from_teeth = false;     // tooth_model without mesh.back_phase: mirrored back flanks
  PlanetaryToothStiffness tooth;    // what the tooth model gave (tooth_model only)
  PlanetaryResponseInput response;
  double campbell_rpm_to = 0.0;   // campbell.carrier_rpm_to (0: no Campbell diagram)
  int campbell_points = 0;
  // period_doubling.depth (app/bifurcation_input.hpp, as gearhb_gear): the period-2 (and 4)
  // branches switched at the located period doublings of the response (tools/planetary_sweep.hpp)
  int period_doubling_depth = 1;
  // bifurcation_diagram (app/bifurcation_input.hpp's key, as gearhb_frc and gearhb_gear read it):
  // absent or true, the diagram by time integration over each range of the response with no
  // stable period-1 orbit (programs/gearhb_planetary: diagram_bands), its options the library's
  // with `speeds` from the band's width (planetary_diagram_speeds); an object overrides options
  // (its `speeds`: per band and sweep); false, none.
  bool diagram_on = true;
  bool diagram_speeds_given = false;
  BifurcationDiagramOptions diagram;
  nlohmann::json resolved;      // the file after overrides (params.json)
};

// The set's defaults of the diagram's options, chosen for its cost (24 DOFs for five planets: a
// speed that is not periodic integrates lyapunov_periods mesh periods with one tangent vector,
// 2n + 2n = 96 equations, and, where not chaotic, shoots on the max_period-period map with the
// 2n + 4n^2 = 2352 of the monodromy: most of the diagram's time, bench/bench_planetary.cpp
// BM_planetary_diagram_*): the library's
// (hb/bifurcation_diagram.hpp) but transient_periods 200 (a mode of damping ratio 0.02 at the mesh
// frequency decays by exp(-2 pi 0.02 200) ~ 1e-11 after a jump), periods 16 (a period up to 4
// repeating 4 times), max_period 4 (period 2 and the period-4 branches of period_doubling.depth 2),
// lyapunov_periods 20 (a finite-time estimate scattering by O(1/20) about a torus' 0: a point whose
// lambda lies within it of lyapunov_threshold is not settled by it).
BifurcationDiagramOptions planetary_diagram_defaults();

PlanetaryFile read_planetary_file(const std::string& path,
                                  const std::vector<std::pair<std::string, std::string>>& overrides);

// The radius r of a member's rotational coordinate u = r theta [m]: the base radius of the
// sun and the ring, the planet-centre radius of the carrier.
double member_radius(const PlanetaryTeeth& t, double pressure_angle, Body b);

// The loaded set of the file's `response` as a harmonic-balance model: the output's shaft
// added to its torsional stiffness, the input torque T / r on the input's u (r:
// member_radius; on the carrier -T / r: the direction that loads the drive flanks), the
// meshes as contacts (planetary_harmonic_balance).
HarmonicBalance planetary_response_model(const PlanetaryFile& f);

// Text for --help: every key, its unit and meaning.
std::string planetary_file_help();

}  // namespace gearhb
