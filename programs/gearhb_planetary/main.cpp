// ===========================================================================
// gearhb_planetary: a planetary or star gear set from its drawing
// ===========================================================================
//
// From a planetary-set file (tools/planetary_file.hpp; README of this folder): the
// linear model of Lin & Parker (1999, J. Vib. Acoust. 121:316; gears/sets/planetary.hpp),
// three DOFs per body (sun, ring, carrier, N planets) in the carrier frame, the
// sun-planet and ring-planet meshes along their lines of action, the bearings; carrier
// speed 0 (no gyroscopic or centripetal terms, as Lin & Parker's Table 1):
//   M q'' + (K_b + K_m) q = 0.
// Its natural frequencies and modes, each classified as rotational, translational or
// planet mode with its multiplicity (1, 2 and N - 3 for equally spaced planets).
//
// With a `response` section, the set over its mesh frequency (gears/sets/planetary_mesh.hpp):
// every mesh a unilateral contact (drive flank) whose stiffness is a rectangular wave over
// the mesh cycle, shifted by its mesh phase (Parker & Lin 2004), under the input torque,
// the output held by its shaft; harmonic balance with exact contact and arc-length
// continuation over the mesh frequency, the stability of every point and the bifurcations
// between them by the pair programs' sweep (tools/planetary_sweep.hpp), per mesh its dynamic factor K_v (largest force over the static one) and its
// contact class (drive-flank loss, back-flank impact where the file gives a backlash), per
// planet its load-sharing factor (unequal with pin position errors, planet.pin_errors).
//
// With mesh.stiffness tooth_model the mesh stiffnesses come from the teeth
// (tools/planetary_stiffness.hpp): the sun-planet mesh's k(theta) by gearhb_gear's pair
// model at the mesh's static load, the ring-planet mesh's by the potential energy of an
// internal tooth (or ISO 6336-1 for internal gears: mesh.ring_planet_stiffness).
//
// At each period doubling located on the curve a period-2 branch is switched to and followed
// as the pair programs do (hb/period_doubling.hpp; tools/planetary_sweep.hpp: the meshes'
// stiffness varies, so the switch's eigen-solution and the branch's multipliers come from the
// variational equation about the HB orbit), to the file's period_doubling.depth; response.csv
// holds every branch in the one schema (app/schema.hpp), bifurcations.csv every branch's events.
//
// Where the curve has ranges with no stable period-1 orbit, the bifurcation diagram by time
// integration over each (padded: app/bifurcation_input.hpp diagram_bands with
// tools/planetary_sweep.hpp planetary_diagram_bands), as gearhb_frc and
// gearhb_gear draw theirs (hb/bifurcation_diagram.hpp; the file's bifurcation_diagram key, false:
// none): the sun's rotation u_s at phase 0 of every mesh period (bifurcation_diagram.csv) over the
// HB orbits at the same phase, period 1 and the period-2 (4) branches (bifurcation_diagram_hb.csv).
//
// Steps: read_set (in the study's checks: a bad file exits 2 before anything is
// written; it computes the stiffnesses from the teeth), natural_frequencies, mode_shapes,
// campbell, mesh_stiffness, response (loaded_model, response_curve, stability,
// doubled_branches, bifurcation_diagram, response_table, diagram_tables, bifurcations_table,
// response_key_numbers, any_motion_key_numbers), draw.
//
// Sample runs:
//   build/bin/gearhb_planetary programs/gearhb_planetary/examples/lin_parker_1999.json --out /tmp/lp
//   build/bin/gearhb_planetary programs/gearhb_planetary/examples/lin_parker_1999.json --set planets=4
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/case_table.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/fourier.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/core/units.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gearhb/gears/sets/planetary.hpp"
#include "gearhb/tools/planetary_file.hpp"
#include "gearhb/tools/planetary_stiffness.hpp"
#include "gearhb/tools/planetary_sweep.hpp"

#ifndef GEARHB_FIGURES_DIR
#define GEARHB_FIGURES_DIR ""
#endif

using namespace gearhb;

namespace {

// What each mesh and planet does over the period of one point of the curve.
struct PointMeasures {
  std::vector<PlanetaryMeshOrbit> meshes;   // 2N, mesh order (sun_1..N, ring_1..N)
  std::vector<double> load_sharing;         // N: the planet load-sharing factors
};

class PlanetarySetFromFile {
 public:
  explicit PlanetarySetFromFile(Study& study);
  void run(Run& run);

 private:
  Study& study_;
  bool plot_ = true;
  PlanetaryFile file_;

  void read_set();
  std::vector<PlanetaryMode> natural_frequencies(Run& run) const;
  void mode_shapes(Run& run, const std::vector<PlanetaryMode>& modes) const;
  void campbell(Run& run) const;
  void mesh_stiffness(Run& run) const;
  // The response: the period-1 curve and the period-doubled branches switched at its PDs.
  struct Response {
    FrequencyCurve curve;
    std::vector<PointMeasures> measures;                      // per point of curve
    std::vector<PeriodDoubledBranch> doubled;                 // period 2 (4: period_doubling.depth 2)
    std::vector<std::vector<PointMeasures>> doubled_measures; // per branch (empty: no points)
    std::vector<DiagramBand> bands;                           // of the diagram (empty: none)
    BifurcationDiagram diagram;                               // every band's, band by band
  };
  void response(Run& run) const;
  HarmonicBalance loaded_model() const;
  FrequencyCurve response_curve(Run& run, const HarmonicBalance& hb, SweepOptions& o) const;
  void stability(Run& run, const HarmonicBalance& hb, const SweepOptions& o, FrequencyCurve& c) const;
  void doubled_branches(Run& run, const HarmonicBalance& hb, SweepOptions o, const std::vector<double>& F0,
                        Response& r) const;
  void bifurcation_diagram(Run& run, const HarmonicBalance& hb, const SweepOptions& o, Response& r) const;
  void diagram_tables(Run& run, const HarmonicBalance& hb, const Response& r) const;
  std::vector<PointMeasures> measures(const HarmonicBalance& hb, const FrequencyCurve& c,
                                      const std::vector<double>& F0) const;
  Table curve_table(const HarmonicBalance& hb, const FrequencyCurve& c, const std::vector<PointMeasures>& m,
                    const BranchLabel& label) const;
  Table response_table(const HarmonicBalance& hb, const Response& r) const;
  Table bifurcations_table(const Response& r) const;
  Table sun_harmonics_table(const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void response_key_numbers(Run& run, const FrequencyCurve& c, const std::vector<PointMeasures>& m) const;
  void any_motion_key_numbers(Run& run, const HarmonicBalance& hb, const Response& r, const SweepOptions& o,
                              const std::vector<double>& F0) const;
  void draw(Run& run) const;
};

// " <head> a-b, c-d" (Hz of the mesh-frequency intervals; a one-point interval as one frequency).
std::string hz_list(const std::string& head, const Intervals& iv) {
  std::string out = head;
  char part[64];
  for (std::size_t j = 0; j < iv.size(); ++j) {
    if (iv[j].first == iv[j].second) std::snprintf(part, sizeof part, "%s %.1f", j == 0 ? "" : ",", hz(iv[j].first));
    else std::snprintf(part, sizeof part, "%s %.1f-%.1f", j == 0 ? "" : ",", hz(iv[j].first), hz(iv[j].second));
    out += part;
  }
  return out;
}

std::string mesh_name(int i, int planets) {
  return (i < planets ? "sun_" : "ring_") + std::to_string(i % planets + 1);
}

PlanetarySetFromFile::PlanetarySetFromFile(Study& study) : study_(study) {
  file_program(study, "SET.json", &plot_, [this] { read_set(); });
}

void PlanetarySetFromFile::run(Run& run) {
  run.write_text("params.json", file_.resolved.dump(2) + "\n");
  const std::vector<PlanetaryMode> modes = natural_frequencies(run);
  mode_shapes(run, modes);
  if (file_.campbell_points > 0) campbell(run);
  if (file_.tooth_model) mesh_stiffness(run);
  if (file_.response.present) response(run);
  if (plot_) draw(run);
}

// Step 1 (in the checks, before anything is written): the set file and the overrides.
void PlanetarySetFromFile::read_set() {
  file_ = read_planetary_file(study_.positional(), study_.parameters().unregistered());
}

// Step 2: the natural frequencies and their types. modes.csv: mode, frequency_hz,
// mode_type (rotational | translational | planet | mixed), multiplicity, group (the
// frequency group, from 1). Key numbers: the frequency of each group per type
// (frequency_hz_<type>_<k>, k from 1 in ascending order), the number of groups of each
// type (groups_<type>) and the planet modes' multiplicity.
std::vector<PlanetaryMode> PlanetarySetFromFile::natural_frequencies(Run& run) const {
  const std::vector<PlanetaryMode> modes = run.timed("modes", [&] { return planetary_modes(file_.set); });
  Table t({"mode", "frequency_hz", "mode_type", "multiplicity", "group"});
  std::map<ModeType, int> groups;
  int last_group = -1;
  KeyNumbers& key = run.key_numbers();
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const PlanetaryMode& m = modes[i];
    const double f = m.omega / (2.0 * M_PI);
    t.add_row({long(i + 1), f, to_string(m.type), long(m.multiplicity), long(m.group + 1)});
    if (m.group == last_group) continue;
    last_group = m.group;
    const int k = ++groups[m.type];
    key.add("frequency_hz_" + to_string(m.type) + "_" + std::to_string(k), f, "Hz");
    if (m.type == ModeType::planet) key.add("multiplicity_planet", double(m.multiplicity), "-");
  }
  run.write("modes.csv", t);
  for (ModeType type : {ModeType::rotational, ModeType::translational, ModeType::planet, ModeType::mixed})
    key.add("groups_" + to_string(type), double(groups[type]), "-");
  key.add("modes", double(modes.size()), "-");
  run.say(file_.name + ": " + std::to_string(file_.set.planets()) + " planets, " + std::to_string(modes.size()) +
          " modes: " + std::to_string(groups[ModeType::rotational]) + " rotational, " +
          std::to_string(groups[ModeType::translational]) + " translational pairs, " +
          std::to_string(groups[ModeType::planet]) + " planet groups, " + std::to_string(groups[ModeType::mixed]) +
          " mixed");
  return modes;
}

// Step 3: mode_shapes.csv, one row per mode and body: mode, body (sun | ring | carrier |
// planet_<n>), psi_deg (the planet's angle; 0 for a central member), x, y (its centre's
// displacement in the carrier frame; a planet's zeta, eta turned by psi), u (r theta),
// all of the mass-normalised shape [1/sqrt(kg)].
void PlanetarySetFromFile::mode_shapes(Run& run, const std::vector<PlanetaryMode>& modes) const {
  Table t({"mode", "body", "psi_deg", "x", "y", "u"});
  const PlanetarySet& s = file_.set;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const Eigen::VectorXd& q = modes[i].shape;
    for (auto [name, body] : {std::pair{"sun", Body::sun}, std::pair{"ring", Body::ring}, std::pair{"carrier", Body::carrier}})
      t.add_row({long(i + 1), std::string(name), 0.0, q(coordinate(body, 0)), q(coordinate(body, 1)),
                 q(coordinate(body, 2))});
    for (int n = 0; n < s.planets(); ++n) {
      const double psi = s.planet_angles[std::size_t(n)], zeta = q(planet_coordinate(n, 0)),
                   eta = q(planet_coordinate(n, 1));
      t.add_row({long(i + 1), "planet_" + std::to_string(n + 1), psi * 180.0 / M_PI,
                 zeta * std::cos(psi) - eta * std::sin(psi), zeta * std::sin(psi) + eta * std::cos(psi),
                 q(planet_coordinate(n, 2))});
    }
  }
  run.write("mode_shapes.csv", t);
}

// Step 3b (with `campbell`): campbell.csv, the natural frequencies of the rotating set
// (gyroscopic and centripetal terms, natural_frequencies_at_speed) over carrier speed:
// carrier_rpm, mode (ascending at each speed), frequency_hz (in the carrier frame).
void PlanetarySetFromFile::campbell(Run& run) const {
  Table t({"carrier_rpm", "mode", "frequency_hz"});
  const int P = file_.campbell_points;
  run.timed("campbell", [&] {
    for (int k = 0; k < P; ++k) {
      const double rpm = file_.campbell_rpm_to * k / (P - 1);
      const Eigen::VectorXd omega = natural_frequencies_at_speed(file_.set, rpm * M_PI / 30.0);
      for (Eigen::Index i = 0; i < omega.size(); ++i) t.add_row({rpm, long(i + 1), omega(i) / (2.0 * M_PI)});
    }
  });
  run.write("campbell.csv", t);
}

// Step 3c (mesh.stiffness tooth_model; tools/planetary_stiffness.hpp): mesh_stiffness.csv,
// phase (of the mesh cycle, sun-planet mesh 1's), k_sun_planet_N_per_m (the pair model's
// F / STE), k_ring_planet_N_per_m (mesh.ring_planet_stiffness: potential energy, or ISO
// 6336-1's rectangular wave); sun_planet_pair.json, the
// sun-planet pair as a gear-pair file that gearhb_gear runs (its ste_1.csv k_N_per_m is the
// same k); the key numbers of both meshes and the ring-sun phase gamma_rs (used, and from the
// teeth).
void PlanetarySetFromFile::mesh_stiffness(Run& run) const {
  const PlanetaryToothStiffness& k = file_.tooth;
  Table t({"phase", "k_sun_planet_N_per_m", "k_ring_planet_N_per_m"});
  const std::size_t J = k.sun.samples.size();
  for (std::size_t j = 0; j < J; ++j)
    t.add_row({double(j) / double(J), k.sun.samples[j], k.ring_stiffness(int(j), int(J))});
  run.write("mesh_stiffness.csv", t);
  run.write_text("sun_planet_pair.json", k.sun_planet_pair.dump(2) + "\n");
  KeyNumbers& key = run.key_numbers();
  key.add("tooth_force_N", k.tooth_force, "N");
  key.add("torque_Nm_sun_planet", k.sun_planet_torque, "N m");
  key.add("mesh_stiffness_mean_sun_planet_N_per_m", k.sun.mean(), "N/m");
  key.add("contact_ratio_sun_planet", k.sun_contact_ratio, "-");
  const bool iso = k.ring_model == RingPlanetModel::iso6336;
  const double ring_mean = iso ? k.ring.mean : k.ring_pe.mean();
  key.add("mesh_stiffness_mean_ring_planet_N_per_m", ring_mean, "N/m");
  key.add("contact_ratio_ring_planet", k.ring_contact_ratio, "-");
  key.add("ring_sun_phase", file_.ring_sun_phase, "cycles");
  key.add("ring_sun_phase_from_teeth", file_.ring_sun_phase_from_teeth, "cycles");
  key.add("back_mirror_phase_sun_planet", k.sun_back_mirror / (2.0 * M_PI), "cycles");
  key.add("back_mirror_phase_ring_planet", k.ring_back_mirror / (2.0 * M_PI), "cycles");
  key.add("back_flanks_mirrored", file_.back_phase_from_teeth ? 1.0 : 0.0, "-");
  char line[240];
  std::snprintf(line, sizeof line, "mesh stiffness from the teeth at F = %.1f N: sun-planet mean %.4g N/m (eps %.3f), "
                "ring-planet mean %.4g N/m (%s, eps %.3f)", k.tooth_force, k.sun.mean(), k.sun_contact_ratio,
                ring_mean, iso ? "ISO 6336-1" : "potential energy", k.ring_contact_ratio);
  run.say(file_.name + ": " + line);
}

// Step 4 (with `response`): the set under load over the mesh frequency, and the period-doubled
// branches switched at its period doublings.
void PlanetarySetFromFile::response(Run& run) const {
  const HarmonicBalance hb = loaded_model();
  SweepOptions o;
  Response r;
  r.curve = response_curve(run, hb, o);
  stability(run, hb, o, r.curve);
  const std::vector<double> F0 = planetary_static_mesh_forces(hb, file_.set.planets());
  r.measures = measures(hb, r.curve, F0);
  doubled_branches(run, hb, o, F0, r);
  bifurcation_diagram(run, hb, o, r);
  run.write("response.csv", response_table(hb, r));
  diagram_tables(run, hb, r);
  if (file_.response.stability) run.write("bifurcations.csv", bifurcations_table(r));
  run.write("sun_harmonics.csv", sun_harmonics_table(hb, r.curve));
  response_key_numbers(run, r.curve, r.measures);
  any_motion_key_numbers(run, hb, r, o, F0);
}

// The loaded set (planetary_file.hpp planetary_response_model): the output held by its
// shaft, the input torque, the meshes as contacts.
HarmonicBalance PlanetarySetFromFile::loaded_model() const { return planetary_response_model(file_); }

// Arc-length continuation over the mesh frequency (the sweep of the pair programs,
// hb/frequency_sweep.hpp), its stability the next step.
FrequencyCurve PlanetarySetFromFile::response_curve(Run& run, const HarmonicBalance& hb, SweepOptions& o) const {
  o = planetary_sweep_options(file_);
  report_sweep_progress(run, o, file_.name);
  FrequencyCurve c = run.timed("response", [&] { return sweep_frequency(hb, o, file_.name); });
  run.say(file_.name + ": " + c.branch.summary());
  if (!c.complete) throw std::runtime_error("the response did not reach response.f_mesh_hz.to: " + c.failure);
  return c;
}

// The Floquet multipliers of every point and the bifurcations between them, as the pair
// programs' sweep (tools/planetary_sweep.hpp: the variational multipliers about the HB
// orbit, no narrow-band search; why, and the cost). response.stability = 0 skips it (the
// curve's stability stays `none`: its stable and Floquet cells are empty).
void PlanetarySetFromFile::stability(Run& run, const HarmonicBalance& hb, const SweepOptions& o, FrequencyCurve& c) const {
  if (!file_.response.stability) return;
  c.stable.clear();
  c.floquet.clear();
  c.stability = StabilityMethod::floquet;
  run.timed("stability", [&] { analyse_stability(hb, planetary_stability_options(o), c); });
  std::map<BifurcationType, int> count;
  std::string where;
  for (const Bifurcation& b : c.bifurcations) {
    ++count[b.type];
    where += std::string(where.empty() ? ": " : ", ") + to_string(b.type) + " at " +
             std::to_string(int(std::lround(b.omega / (2.0 * M_PI)))) + " Hz";
  }
  KeyNumbers& key = run.key_numbers();
  key.add("bifurcations", double(c.bifurcations.size()), "-");
  for (BifurcationType t : {BifurcationType::fold, BifurcationType::branch_point, BifurcationType::period_doubling,
                            BifurcationType::neimark_sacker})
    key.add(std::string("bifurcations_") + to_string(t), double(count[t]), "-");
  add_unstable_period1_ranges(key, c, o.omega_min, o.omega_max);
  run.say(file_.name + ": " + std::to_string(c.bifurcations.size()) + " bifurcations" + where);
}

// Period-2 branches (and period 4 at period_doubling.depth 2) from the located period doublings
// of the curve, switched as the pair programs switch them (tools/planetary_sweep.hpp
// planetary_period_doubled_branches: hb/period_doubling.hpp over the same range, the stability of
// their points by the same variational multipliers, over two mesh periods); each says in one line
// where it starts and how it ends (a switch that fails: where and why; the rest of the run
// stands), then where it is stable and its largest stable K_v; its points' meshes measured over
// its period (F0: the period-1 set's static mesh forces). Key numbers period_doubled_branches and,
// per branch k with points, branch_points_<k>, branch_stable_points_<k>, branch_pd_f_mesh_hz_<k> (the
// PD it starts at), branch_start_f_mesh_hz_<k> (the period-2 model's branch point beside it),
// branch_end_f_mesh_hz_<k>.
void PlanetarySetFromFile::doubled_branches(Run& run, const HarmonicBalance& hb, SweepOptions o,
                                            const std::vector<double>& F0, Response& r) const {
  const auto& B = r.curve.bifurcations;
  if (file_.period_doubling_depth < 1 ||
      std::none_of(B.begin(), B.end(), [](const Bifurcation& b) { return b.type == BifurcationType::period_doubling; }))
    return;
  report_sweep_progress(run, o, file_.name + ": period 2");
  r.doubled = run.timed("period-doubled branches", [&] {
    return planetary_period_doubled_branches(hb, r.curve, o, file_.period_doubling_depth);
  });
  KeyNumbers& key = run.key_numbers();
  key.add("period_doubled_branches", double(r.doubled.size()), "-");
  for (std::size_t k = 0; k < r.doubled.size(); ++k) {
    const PeriodDoubledBranch& b = r.doubled[k];
    run.say(file_.name + ": " + b.why);
    r.doubled_measures.push_back(has_points(b) ? measures(*b.model, b.curve, F0) : std::vector<PointMeasures>{});
    if (!has_points(b)) continue;
    // branch k + 1: its points, the stable ones, where it starts (the period-2 model's branch
    // point beside the PD) and where it ends [forcing mesh frequency, Hz]
    const std::string id = std::to_string(k + 1);
    key.add("branch_points_" + id, double(b.curve.branch.points.size()), "-");
    key.add("branch_stable_points_" + id, double(std::count(b.curve.stable.begin(), b.curve.stable.end(), true)), "-");
    key.add("branch_pd_f_mesh_hz_" + id, hz(b.omega_start), "Hz");
    key.add("branch_start_f_mesh_hz_" + id, hz(b.omega_branch_point), "Hz");
    key.add("branch_end_f_mesh_hz_" + id, hz(b.omega_end), "Hz");
    char part[160];
    std::snprintf(part, sizeof part, ": period-%d branch %zu, %.1f to %.1f Hz:", b.period, k + 1, hz(b.omega_start),
                  hz(b.omega_end));
    std::string line = file_.name + part;
    // a stable stretch with no converged shooting correction listed apart (resolved_stable)
    const Intervals st = resolved_stable_intervals(b.curve, b.period);
    line += hz_list(st.empty() ? "" : " stable at", st);
    const std::vector<bool> resolved = resolved_stable(b.curve);
    double kv = 0.0;
    for (std::size_t p = 0; p < resolved.size(); ++p)
      for (const PlanetaryMeshOrbit& m : r.doubled_measures.back()[p].meshes)
        if (resolved[p]) kv = std::max(kv, m.dynamic_factor);
    std::snprintf(part, sizeof part, " Hz; largest stable K_v %.3f", kv);
    line += st.empty() ? " unstable everywhere" : part;
    const Intervals unresolved = unresolved_stable_stretches(b.curve, b.period);
    if (!unresolved.empty()) line += hz_list("; stability unresolved (shooting correction failed) at", unresolved) + " Hz";
    run.say(line);
  }
}

// The Poincare value of the diagram: the sun's rotation u_s = r_s theta_s (the response figure's
// top panel draws its AC RMS, response.csv's x), in um, at phase 0 of every mesh period.
Eigen::VectorXd poincare_coordinate(const HarmonicBalance& hb) {
  return Eigen::VectorXd::Unit(hb.dofs(), coordinate(Body::sun, 2));
}

// Step 4b (issue 34 section 3; with response.stability, unless bifurcation_diagram is false): the
// bifurcation diagram by time integration (hb/bifurcation_diagram.hpp; app/bifurcation_input.hpp
// diagram_of_curve) over each band of diagram_bands (planetary_diagram_bands: the ranges with no
// stable period-1 orbit, padded), up from the HB orbit of the curve nearest the band's start,
// down from the stable HB orbit at its end where there is one (set_down_start; else from the up
// sweep's end); speeds planetary_diagram_speeds(band width) unless the file's key gives them. Skipped with
// one line where the integration is stiff (fastest rate x period > 1e4, gearhb_frc's rule). Key
// numbers diagram_bands, diagram_<motion>_speeds, diagram_max_period; one line per band.
void PlanetarySetFromFile::bifurcation_diagram(Run& run, const HarmonicBalance& hb, const SweepOptions& o,
                                               Response& r) const {
  if (!file_.diagram_on || r.curve.stability == StabilityMethod::none) return;
  std::vector<DiagramBand> bands =
      diagram_bands(r.curve, o.omega_min, o.omega_max, hb.dofs(), planetary_diagram_bands(), 1);
  if (bands.empty()) return;
  if (const std::string stiff = diagram_stiffness(hb, bands.front().omega_lo); !stiff.empty()) {
    run.say(file_.name + ": " + stiff);
    return;
  }
  for (DiagramBand& b : bands)
    b.speeds = file_.diagram_speeds_given ? file_.diagram.speeds : planetary_diagram_speeds(hz(b.omega_hi) - hz(b.omega_lo));
  r.bands = bands;
  const auto& P = r.curve.branch.points;
  for (std::size_t k = 0; k < bands.size(); ++k) {
    const double lo = bands[k].omega_lo, hi = bands[k].omega_hi;
    BifurcationDiagramOptions opt = file_.diagram;
    opt.speeds = bands[k].speeds;
    set_down_start(hb, r.curve, hi, opt);   // the down sweep from the stable orbit at hi, if any
    const auto start = std::min_element(P.begin(), P.end(), [lo = lo](const BranchPoint& a, const BranchPoint& b) {
      return std::abs(a.omega - lo) < std::abs(b.omega - lo);
    });   // up from the point nearest lo
    const std::string id = std::to_string(k + 1);
    const BifurcationDiagram d = diagram_of_curve(run, hb, r.curve, lo, hi, opt, "bifurcation diagram " + id,
                                                  file_.name + ": ", std::size_t(start - P.begin()));
    r.diagram.points.insert(r.diagram.points.end(), d.points.begin(), d.points.end());
    char part[120];
    std::snprintf(part, sizeof part, ": band %s, %.1f to %.1f Hz: ", id.c_str(), hz(lo), hz(hi));
    run.say(file_.name + part + diagram_summary(d, [](double w) { return hz(w); }, "Hz"));
  }
  run.key_numbers().add("diagram_bands", double(bands.size()), "-");
  diagram_key_numbers(run.key_numbers(), r.diagram, "");
}

// bifurcation_diagram.csv (app/bifurcation_input.hpp's columns: f_mesh_hz, sweep, u_s_um, motion,
// n, lyapunov) and bifurcation_diagram_hb.csv (f_mesh_hz, period, branch, u_s_um, stable, point:
// the period-1 curve's rows (add_hb_section_rows), then each period-2 (4) branch's).
void PlanetarySetFromFile::diagram_tables(Run& run, const HarmonicBalance& hb, const Response& r) const {
  if (r.diagram.points.empty()) return;
  const Eigen::VectorXd q = poincare_coordinate(hb);
  Table t(bifurcation_columns({"f_mesh_hz"}, "u_s_um"));
  add_bifurcation_rows(t, r.diagram, q, 1e6, [](double w) { return std::vector<Table::Cell>{hz(w)}; });
  run.write("bifurcation_diagram.csv", t);
  Table h(hb_section_columns({"f_mesh_hz", "period", "branch"}, "u_s_um"));
  add_hb_section_rows(h, hb, r.curve, r.doubled, r.diagram, q, 1e6,
                      [](double w, int p, int b) { return std::vector<Table::Cell>{hz(w), long(p), long(b)}; });
  run.write("bifurcation_diagram_hb.csv", h);
}

// Every point's meshes over its period (planetary_mesh.hpp; hb the curve's model, of period 1 or
// 2): K_v against each mesh's static force F0, the flank states, and the planets' load-sharing factors.
std::vector<PointMeasures> PlanetarySetFromFile::measures(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                          const std::vector<double>& F0) const {
  const int N = file_.set.planets();
  const std::vector<int> back = back_flank_contacts(file_.meshes, N);
  std::vector<PointMeasures> out;
  for (const BranchPoint& p : c.branch.points) {
    PointMeasures m;
    for (int i = 0; i < 2 * N; ++i) m.meshes.push_back(planetary_mesh_orbit(hb, back, p.X, i, F0[std::size_t(i)]));
    m.load_sharing = planet_load_sharing(m.meshes, N);
    out.push_back(std::move(m));
  }
  return out;
}

// The worst contact class over the meshes (the `contact` column): drive_loss+back_impact if some
// mesh loses its drive flank and some (other) mesh's back flank hits, else whichever happens.
std::string worst_contact(const PointMeasures& m) {
  bool loss = false, impact = false;
  for (const PlanetaryMeshOrbit& o : m.meshes) {
    loss = loss || o.drive != ContactState::full;
    impact = impact || o.back != ContactState::open;
  }
  return loss && impact ? "drive_loss+back_impact" : loss ? "drive_loss" : impact ? "back_impact" : "full";
}

// The rows of one curve (app/schema.hpp): f_mesh_hz's frequency columns, the common columns of the
// sun's rotation u_s (x, m), then the set's: sun_xy_rms_um (AC RMS of the sun centre's motion),
// per planet load_sharing_planet_<n>, per mesh dynamic_factor_<mesh> and contact_<mesh>; `label`
// its period and branch (a period-2 branch: hb its period-2 model).
Table PlanetarySetFromFile::curve_table(const HarmonicBalance& hb, const FrequencyCurve& c,
                                        const std::vector<PointMeasures>& m, const BranchLabel& label) const {
  const int N = file_.set.planets(), n = hb.dofs(), H = hb.harmonics();
  std::vector<std::string> extra{"sun_xy_rms_um"};
  for (int i = 0; i < N; ++i) extra.push_back("load_sharing_planet_" + std::to_string(i + 1));
  for (int i = 0; i < 2 * N; ++i) extra.push_back("dynamic_factor_" + mesh_name(i, N));
  for (int i = 0; i < 2 * N; ++i) extra.push_back("contact_" + mesh_name(i, N));
  return frequency_response_table(
      hb, c, Eigen::VectorXd::Unit(n, coordinate(Body::sun, 2)), extra,
      [&](std::size_t p) {
        const Eigen::VectorXd& X = c.branch.points[p].X;
        double xy2 = 0.0;
        for (int k = 1; k <= 2 * H; ++k)
          xy2 += 0.5 * (std::pow(X(k * n + coordinate(Body::sun, 0)), 2) + std::pow(X(k * n + coordinate(Body::sun, 1)), 2));
        std::vector<Table::Cell> row{1e6 * std::sqrt(xy2)};
        for (double L : m[p].load_sharing) row.emplace_back(L);
        for (const PlanetaryMeshOrbit& o : m[p].meshes) row.emplace_back(o.dynamic_factor);
        for (const PlanetaryMeshOrbit& o : m[p].meshes) row.emplace_back(std::string(to_string(mesh_contact(o.drive, o.back))));
        return row;
      },
      [&](std::size_t p) { return worst_contact(m[p]); }, {}, label, {FrequencyAxis::mesh});
}

// response.csv: the period-1 curve (period 1, branch 0), then each period-doubled branch with
// points (period 2 or 4, branch k), as the pair programs write them.
Table PlanetarySetFromFile::response_table(const HarmonicBalance& hb, const Response& r) const {
  Table t = curve_table(hb, r.curve, r.measures, {});
  for (std::size_t k = 0; k < r.doubled.size(); ++k)
    if (has_points(r.doubled[k]))
      t.append(curve_table(*r.doubled[k].model, r.doubled[k].curve, r.doubled_measures[k],
                           BranchLabel{r.doubled[k].period, int(k) + 1}));
  return t;
}

// bifurcations.csv: the curve's, then each branch's (period, branch, starts_branch: app/tables.hpp).
Table PlanetarySetFromFile::bifurcations_table(const Response& r) const { return bifurcation_table(r.curve, r.doubled); }

// sun_harmonics.csv: the harmonic content of the sun's motion, one row per point and mesh
// harmonic l: f_mesh_hz, harmonic, u_um (amplitude of the rotation u_s), xy_um (of the centre,
// sqrt of the x and y amplitudes squared), and the family that mesh phasing lets harmonic l
// drive (README "Why planet phasing suppresses mesh harmonics"): phasing = rotational (l z_s
// / N whole), translational ((l z_s +- 1) / N whole) or none; empty where the set is not
// cyclically symmetric (unequal spacing, pin errors, backlashes that differ between planets).
Table PlanetarySetFromFile::sun_harmonics_table(const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const int n = hb.dofs(), N = file_.set.planets(), zs = file_.teeth.sun;
  // the rule needs the set's cyclic symmetry: equal spacing, no pin errors, one backlash per mesh kind
  bool symmetric = file_.equally_spaced;
  for (double e : file_.meshes.pin_errors) symmetric = symmetric && e == 0.0;
  const std::vector<double>& b = file_.meshes.backlash;
  for (std::size_t i = 0; i < b.size(); ++i) symmetric = symmetric && b[i] == b[i - i % std::size_t(N)];
  Table t({"f_mesh_hz", "harmonic", "u_um", "xy_um", "phasing"});
  for (const BranchPoint& p : c.branch.points)
    for (int l = 1; l <= hb.harmonics(); ++l) {
      auto amp = [&](int i) { return std::hypot(p.X((2 * l - 1) * n + i), p.X(2 * l * n + i)); };
      const int r = (l * zs) % N;
      const std::string family = !symmetric ? "" : r == 0 ? "rotational"
                                 : (r == 1 || r == N - 1) ? "translational" : "none";
      t.add_row({p.omega / (2.0 * M_PI), long(l), 1e6 * amp(coordinate(Body::sun, 2)),
                 1e6 * std::hypot(amp(coordinate(Body::sun, 0)), amp(coordinate(Body::sun, 1))), family});
    }
  return t;
}

// The curve's key numbers: points, the largest dynamic factor and where, the points with a
// drive-flank loss or a back-flank impact on some mesh and the lowest such mesh frequencies,
// the largest load-sharing factor and where, the stability evaluated.
void PlanetarySetFromFile::response_key_numbers(Run& run, const FrequencyCurve& c,
                                                const std::vector<PointMeasures>& m) const {
  KeyNumbers& key = run.key_numbers();
  const bool evaluated = c.stability != StabilityMethod::none;
  double kv_max = 0.0, kv_hz = 0.0, ls_max = 0.0, ls_hz = 0.0, first_loss = NAN, first_impact = NAN;
  int loss_points = 0, impact_points = 0, checked = 0, unstable = 0;
  for (std::size_t p = 0; p < c.branch.points.size(); ++p) {
    const double hz = c.branch.points[p].omega / (2.0 * M_PI);
    bool loss = false, impact = false;
    for (const PlanetaryMeshOrbit& o : m[p].meshes) {
      if (o.dynamic_factor > kv_max) kv_max = o.dynamic_factor, kv_hz = hz;
      loss = loss || o.drive != ContactState::full;
      impact = impact || o.back != ContactState::open;
    }
    for (double L : m[p].load_sharing)
      if (L > ls_max) ls_max = L, ls_hz = hz;
    loss_points += loss ? 1 : 0;
    impact_points += impact ? 1 : 0;
    if (loss && !(hz >= first_loss)) first_loss = hz;
    if (impact && !(hz >= first_impact)) first_impact = hz;
    checked += evaluated ? 1 : 0;
    unstable += evaluated && !c.stable[p] ? 1 : 0;
  }
  key.add("response_points", double(c.branch.points.size()), "-");
  key.add("dynamic_factor_max", kv_max, "-");
  key.add("dynamic_factor_max_f_mesh_hz", kv_hz, "Hz");
  key.add("load_sharing_max", ls_max, "-");
  key.add("load_sharing_max_f_mesh_hz", ls_hz, "Hz");
  key.add("contact_loss_points", double(loss_points), "-");
  if (std::isfinite(first_loss)) key.add("contact_loss_lowest_f_mesh_hz", first_loss, "Hz");
  key.add("back_impact_points", double(impact_points), "-");
  if (std::isfinite(first_impact)) key.add("back_impact_lowest_f_mesh_hz", first_impact, "Hz");
  key.add("stability_points", double(checked), "-");
  key.add("unstable_points", double(unstable), "-");
  auto lowest = [](double hz) { return std::isfinite(hz) ? ", the lowest at " + std::to_string(int(std::lround(hz))) + " Hz" : std::string(); };
  char line[320];
  std::snprintf(line, sizeof line,
                "largest K_v %.3f at %.1f Hz, largest load sharing %.3f at %.1f Hz; a drive flank loses contact at %d points%s; "
                "a back flank hits at %d points%s; ",
                kv_max, kv_hz, ls_max, ls_hz, loss_points, lowest(first_loss).c_str(), impact_points,
                lowest(first_impact).c_str());
  run.say(file_.name + ": " + line +
          (checked == 0 ? std::string("no stability (response.stability 0)")
                        : "Floquet at " + std::to_string(checked) + " points, " + std::to_string(unstable) + " unstable"));
}

// Issue 34 §4, as gearhb_gear's: the largest K_v of the motion that exists (max_kv_any_motion):
// over the meshes of every stable period-1 and period-2 (4) point (whose label is resolved:
// resolved_stable, hb/period_doubling.hpp) and, at the diagram's speeds in
// the ranges with no stable period-1 orbit where it is not period 1, the time-integrated motion
// (16 mesh periods from its first Poincare state, 512 samples each: planetary_sampled_dynamic_factor;
// its largest max_kv_time_integration); max_kv_any_motion_from: the orbit that gave it (1, 2, 4:
// the HB orbit of that period; 0: the time integration), absent where nothing gave one;
// any_motion_complete: 0 where a mesh frequency has neither a stable orbit of any period computed
// nor the diagram (its motion unknown, not counted). The ranges with no stable period-1 orbit are
// the stability step's unstable_period1_* keys. With stability only.
void PlanetarySetFromFile::any_motion_key_numbers(Run& run, const HarmonicBalance& hb, const Response& r,
                                                  const SweepOptions& o, const std::vector<double>& F0) const {
  if (r.curve.stability == StabilityMethod::none) return;
  double kv = 0.0;
  int from = 1;
  auto take = [&](const FrequencyCurve& c, const std::vector<PointMeasures>& m, int period) {
    const std::vector<bool> resolved = resolved_stable(c);
    for (std::size_t p = 0; p < resolved.size(); ++p)
      for (const PlanetaryMeshOrbit& mesh : m[p].meshes)
        if (resolved[p] && mesh.dynamic_factor > kv) kv = mesh.dynamic_factor, from = period;
  };
  take(r.curve, r.measures, 1);
  Intervals stable = resolved_stable_intervals(r.curve);
  const Intervals gaps = period1_ranges(o.omega_min, o.omega_max, {&r.curve}).no_stable;   // the unstable_period1_* keys'
  for (std::size_t b = 0; b < r.doubled.size(); ++b) {
    if (!has_points(r.doubled[b])) continue;
    take(r.doubled[b].curve, r.doubled_measures[b], r.doubled[b].period);
    const Intervals more = resolved_stable_intervals(r.doubled[b].curve, r.doubled[b].period);
    stable.insert(stable.end(), more.begin(), more.end());
  }
  KeyNumbers& key = run.key_numbers();
  if (!r.diagram.points.empty()) {
    const double kv_ti = run.timed("any motion", [&] {
      const std::vector<int> back = back_flank_contacts(file_.meshes, file_.set.planets());
      TimeIntegrationOptions opt;
      opt.x_scale = r.curve.scaling.x.cwiseAbs().maxCoeff();
      opt.samples_per_period = 512;
      double most = 0.0;
      for (const DiagramPoint& p : r.diagram.points) {
        const bool in_gap = std::any_of(gaps.begin(), gaps.end(), [&](auto& g) { return g.first <= p.omega && p.omega <= g.second; });
        if (!in_gap || p.motion == Motion::failed || (p.motion == Motion::periodic && p.n == 1) || p.x.rows() == 0) continue;
        const Eigen::MatrixXd xs = TimeIntegrator(hb).sample(p.x.row(0).transpose(), p.v.row(0).transpose(), p.omega, 0, 16, opt);
        most = std::max(most, planetary_sampled_dynamic_factor(hb, back, xs, 512, F0));
      }
      return most;
    });
    key.add("max_kv_time_integration", kv_ti, "-");
    if (kv_ti > kv) kv = kv_ti, from = 0;
  }
  key.add("max_kv_any_motion", kv, "-");   // 0: no stable orbit of any computed period, no diagram
  if (kv > 0.0) key.add("max_kv_any_motion_from", double(from), "-");
  const bool covered = uncovered(o.omega_min, o.omega_max, stable).empty() || (!gaps.empty() && !r.diagram.points.empty());
  key.add("any_motion_complete", covered ? 1.0 : 0.0, "-");
}

// Step 5: DIR/modes.png by figures/gearhb_planetary.py (the project's figure style).
void PlanetarySetFromFile::draw(Run& run) const {
  draw_with_script(run, std::string(GEARHB_FIGURES_DIR).empty() ? "" : std::string(GEARHB_FIGURES_DIR) + "/gearhb_planetary.py",
                   "modes.png");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("gearhb_planetary",
              "gearhb_planetary: a planetary or star gear set from its drawing (Lin & Parker 1999)\n"
              "  M q'' + (K_b + K_m) q = 0, three DOFs per body in the carrier frame\n"
              "Writes DIR/modes.csv (frequency_hz, mode_type, multiplicity), mode_shapes.csv,\n"
              "key_numbers.json, params.json (the resolved file), timings.csv and modes.png; with `response`\n"
              "response.csv (every branch: period, branch), sun_harmonics.csv, bifurcations.csv (response.stability 1:\n"
              "every point's stability; period-2 branches switched at its period doublings) and, where no\n"
              "period-1 orbit is stable, bifurcation_diagram.csv, bifurcation_diagram_hb.csv (time integration).\n\n" +
                  planetary_file_help());
  PlanetarySetFromFile program(study);
  return study.run(argc, argv, [&](Run& run) { program.run(run); });
}
