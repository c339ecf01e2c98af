// ===========================================================================
// gearhb_gear: a spur gear pair from its drawing
// ===========================================================================
//
// From a gear-pair file (gear_file.hpp; README "A gear pair from its drawing"):
// the involute geometry of the pair (shifted gears at any centre distance, path of
// contact A-B-C-D-E, contact ratio, undercut), the loaded static transmission
// error STE(theta) over the mesh cycle for each torque with chapter 7's beam
// model generalised to two different teeth and tip relief (ste_continuous.hpp
// PairSteModel; the load shared between the pairs by the exact contact problem of
// load_sharing.hpp), the mesh stiffness k = F / STE, the load share of each pair,
// the loaded contact ratio, the STE spectrum per mesh order, the Harris map (STE
// peak-to-peak against torque with and without the file's relief), and ISO 6336-1
// method B's c'_th, c' and c_gamma_alpha for the same pair (and, with a speed range, its
// dynamic factor K_v over the range, beside the computed one). model.method chooses the
// tooth model of the pair stiffness (loaded_pair.hpp): the beams (default), the
// potential-energy method, or tooth contact by finite elements on the generated tooth
// form (fe_tooth_contact.hpp), built once and reused for every torque. A helical pair
// (helix_angle_deg, or a lead modification) is its transverse section with the face in slices
// (pair_helical.hpp; README "Helical pairs").
//
// With `speed` and `dynamics` in the file, the pair over its speed range
// (mesh_dynamics.hpp; README "The pair over its speed range"): per torque, the mesh
//   m_e x'' + c x' + N(x, theta) = F0,   theta = 2 pi f_mesh t,
// N the drive flank (penetration u = x + e(theta) > 0, constant kc, or the parametric
// k(theta)) minus the back flank (penetration -u - b_n - g_b(theta) > 0: the same pairs
// mirrored, phase psi - theta; dte_model.hpp), free flight between; harmonic balance
// with arc-length continuation over f_mesh, Floquet
// stability of the corrected orbit, bifurcations, DTE RMS, dynamic factor K_v and the
// contact of each flank at every point, checked against GSL time integration; from each
// located period doubling a period-2 branch (hb/period_doubling.hpp, as gearhb_frc), and
// the speed ranges with no stable period-1 orbit with the K_v of the motion that exists there.
// Or the six-DOF model (bearings, mesh along the line of action), from the same file.
//
// Steps: read_gear (in the study's checks: a bad file exits 2 before anything is
// written), geometry, helix_key_numbers, tooth_model, transmission_error, iso6336, harris_map, dynamics (response,
// response_tables, response_key_numbers, spectrum_and_history,
// time_integration_check per torque), iso_dynamic_factor, draw.
//
// Sample runs:
//   build/bin/gearhb_gear programs/gearhb_gear/examples/thesis_pair.json --out /tmp/thesis
//   build/bin/gearhb_gear programs/gearhb_gear/examples/fzg_c.json --set torques.0=150 --out /tmp/fzg
//   build/bin/gearhb_gear programs/gearhb_gear/examples/thesis_pair_light_load.json --out /tmp/rattle
//   build/bin/gearhb_gear programs/gearhb_gear/examples/fzg_c_fe.json --out /tmp/fzg_fe
// ===========================================================================
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "gearhb/app/case_table.hpp"
#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/orbit_branches.hpp"
#include "gearhb/tools/gear_file.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/rating/iso6336.hpp"
#include "gearhb/gears/rating/iso6336_root.hpp"
#include "gearhb/gears/pair/loaded_pair.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/pair/pair_helical.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

#ifndef GEARHB_FIGURES_DIR
#define GEARHB_FIGURES_DIR ""
#endif

using namespace gearhb;

namespace {

constexpr int kMaxOrders = 20;   // mesh orders written to spectrum.csv (at most what the phases carry)

double peak_to_peak(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

// ste_<i>.csv: phase, STE, F / STE, the share of each pair (0 for a pair not on the
// path at this phase), the count of loaded pairs, the separations (empty for a pair
// not on the path).
Table ste_table(const std::vector<PairStePoint>& c, std::size_t pairs, double F) {
  std::vector<std::string> columns{"phase", "ste_um", "k_N_per_m"};
  for (std::size_t k = 0; k < pairs; ++k) columns.push_back("share_pair_" + std::to_string(k + 1));
  columns.push_back("loaded_pairs");
  for (std::size_t k = 0; k < pairs; ++k) columns.push_back("separation_um_" + std::to_string(k + 1));
  Table t(columns);
  for (const auto& p : c) {
    std::vector<Table::Cell> row(columns.size(), Table::Cell(0.0));
    row[0] = p.mesh.phase;
    row[1] = p.ste * 1e6;
    row[2] = F / p.ste;
    row[3 + pairs] = long(p.loaded);
    for (std::size_t k = 0; k < pairs; ++k) {
      const bool on = k < p.mesh.pairs.size();
      if (on) row[3 + k] = p.mesh.pairs[k].force / F;
      row[4 + pairs + k] = cell(on, on ? p.mesh.pairs[k].separation * 1e6 : 0.0);
    }
    t.add_row(row);
  }
  return t;
}

// ste_<i>.csv of a face in slices: phase, STE, F / STE, the share of each tooth pair (its
// contacts over all slices; 0 when off the path), the tooth pairs and the slice contacts loaded.
Table sliced_ste_table(const std::vector<PairStePoint>& c, double F) {
  int lo = 0, hi = 0;
  for (const auto& p : c)
    for (const auto& k : p.mesh.pairs) lo = std::min(lo, k.tooth), hi = std::max(hi, k.tooth);
  const std::size_t pairs = std::size_t(hi - lo + 1);
  std::vector<std::string> columns{"phase", "ste_um", "k_N_per_m"};
  for (std::size_t k = 0; k < pairs; ++k) columns.push_back("share_pair_" + std::to_string(k + 1));
  columns.push_back("loaded_pairs");
  columns.push_back("loaded_contacts");
  Table t(columns);
  for (const auto& p : c) {
    std::vector<double> share(pairs, 0.0);
    for (const auto& k : p.mesh.pairs) share[std::size_t(k.tooth - lo)] += k.force / F;
    std::vector<Table::Cell> row(columns.size(), Table::Cell(0.0));
    row[0] = p.mesh.phase;
    row[1] = p.ste * 1e6;
    row[2] = F / p.ste;
    for (std::size_t k = 0; k < pairs; ++k) row[3 + k] = share[k];
    row[3 + pairs] = long(std::count_if(share.begin(), share.end(), [](double v) { return v > 0.0; }));
    row[4 + pairs] = long(p.loaded);
    t.add_row(row);
  }
  return t;
}

// load_map_<i>.csv: the line load of every loaded slice contact over the mesh cycle.
Table load_map_table(const std::vector<PairStePoint>& c, const PairSteModel& m, int slices) {
  Table t({"phase", "slice", "y_m", "s_from_A_m", "roll_angle_deg", "line_load_N_per_mm"});
  const double b = m.contact_length(), rb1 = m.gear1.base_radius(), T1A = m.path().T1A;
  for (const auto& p : c)
    for (const auto& k : p.mesh.pairs)
      t.add_row({p.mesh.phase, long(k.slice), (k.slice + 0.5) / slices * b, k.s, (T1A + k.s) / rb1 * 180.0 / M_PI,
                 k.force / (b / slices) * 1e-3});
  return t;
}

// spectrum.csv: the amplitude per mesh order k (order 0: the mean), sqrt(a_k^2 + b_k^2).
Table spectrum_table(const std::vector<std::string>& columns, const std::vector<Eigen::VectorXd>& spectra, int H) {
  Table s(columns);
  for (int k = 0; k <= H; ++k) {
    std::vector<Table::Cell> row(spectra.size() + 1, Table::Cell(long(k)));
    for (std::size_t i = 0; i < spectra.size(); ++i) {
      const Eigen::VectorXd& c = spectra[i];
      row[i + 1] = 1e6 * (k == 0 ? c[0] : std::hypot(c[2 * k - 1], c[2 * k]));
    }
    s.add_row(row);
  }
  return s;
}

class GearPairFromFile {
 public:
  explicit GearPairFromFile(Study& study);
  void run(Run& run);

 private:
  Study& study_;
  bool plot_ = true;
  GearFile file_;
  std::unique_ptr<LoadedPair> loaded_;   // the tooth model of model.method, built once

  void read_gear();
  void geometry(Run& run) const;
  void helix_key_numbers(Run& run) const;
  int slices() const { return file_.helical.sliced() ? file_.helical.slices : 1; }
  void tooth_model(Run& run);
  void transmission_error(Run& run) const;
  void root_stress_and_contact(Run& run) const;
  void iso6336(Run& run) const;
  void harris_map(Run& run) const;
  void dynamics(Run& run) const;
  void iso_dynamic_factor(Run& run) const;
  void draw(Run& run) const;

  // The dynamics, per torque (README "The pair over its speed range").
  // One mesh model per torque: built once, its sweep's options, curve, summary and closed-contact
  // frequency; the period-doubled branches from its period doublings (hb/period_doubling.hpp), then
  // those continued from the diagram's orbits off every branch (orbit_branches), and theirs.
  struct Response {
    DteGear mesh;
    SweepOptions o;
    FrequencyCurve curve;
    MeshCurveSummary summary;
    double f_natural = 0.0;   // the one-DOF closed-contact mesh frequency [Hz]
    std::vector<PeriodDoubledBranch> doubled;   // period 2 (and 4: period_doubling.depth 2), then the orbit branches
    std::vector<MeshCurveSummary> doubled_summary;   // per branch (empty for one without points)
  };
  BearingSupport bearings() const;
  DteGear mesh_at(std::size_t i) const;
  Response response(Run& run, std::size_t i, const DteGear& mesh, const HarmonicBalance& hb) const;
  void doubled_branches(Run& run, std::size_t i, const HarmonicBalance& hb, SweepOptions o, Response& r) const;
  void say_branch(Run& run, std::size_t i, std::size_t k, const PeriodDoubledBranch& b, const MeshCurveSummary& m) const;
  std::string rpm_list(const std::string& head, const Intervals& iv) const;
  Table mesh_table(const HarmonicBalance& hb, const FrequencyCurve& c, const MeshCurveSummary& s,
                   const BranchLabel& label, const RowProgress& progress) const;
  void response_tables(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const;
  void any_motion_key_numbers(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r,
                              const BifurcationDiagram* d) const;
  void response_key_numbers(Run& run, std::size_t i, const Response& r) const;
  void axial_key_numbers(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const;
  void time_integration_check(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const;
  bool bifurcation_diagram(Run& run, std::size_t i, const HarmonicBalance& hb, Response& r, BifurcationDiagram& d,
                           Table& t, Table& hb_section) const;
  void orbit_branches(Run& run, std::size_t i, const HarmonicBalance& hb, Response& r, const std::vector<DiagramPoint>& off) const;
  void spectrum_and_history(const HarmonicBalance& hb, std::size_t i, const Response& r, Table& spectrum,
                            Table& history, double& history_kv) const;
  double speed_rpm(double omega) const { return 60.0 * hz(omega) / file_.pair.gear1.teeth; }
  std::string torque_label(std::size_t i) const;   // "T1 = 100 N m": names torque i's curve in progress lines
};

GearPairFromFile::GearPairFromFile(Study& study) : study_(study) {
  file_program(study, "GEAR.json", &plot_, [this] { read_gear(); });
}

void GearPairFromFile::run(Run& run) {
  run.write_text("params.json", file_.resolved.dump(2) + "\n");
  geometry(run);
  helix_key_numbers(run);
  tooth_model(run);
  transmission_error(run);
  if (loaded_->fe_model() && !file_.helical.sliced()) root_stress_and_contact(run);   // a spur section only
  iso6336(run);
  harris_map(run);
  if (file_.dynamics.present) dynamics(run), iso_dynamic_factor(run);
  if (plot_) draw(run);
}

// Step 1 (in the checks, before anything is written): the file, the overrides, every check.
void GearPairFromFile::read_gear() {
  file_ = read_gear_file(study_.positional(), study_.parameters().unregistered());
}


// Step 2: the involute geometry of the pair (of a helical pair's transverse section);
// path_of_contact.csv, key numbers.
void GearPairFromFile::geometry(Run& run) const {
  const PairSteModel& m = file_.pair;
  const PathOfContact p = m.path();
  KeyNumbers& key = run.key_numbers();
  key.add("centre_distance_m", p.mesh.centre_distance, "m");
  key.add("operating_pressure_angle_deg", p.mesh.pressure_angle * 180.0 / M_PI, "deg");
  key.add("contact_ratio", p.contact_ratio, "-");
  key.add("path_of_contact_m", p.AE, "m");
  key.add("base_pitch_m", p.base_pitch, "m");
  const GearGeometry* g[2] = {&m.gear1, &m.gear2};
  int undercut = 0;
  const double c = std::cos(file_.helical.helix_angle);   // a helical rack's coefficients in m_t: times cos(beta)
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i + 1);
    key.add("base_radius_" + n + "_m", g[i]->base_radius(), "m");
    key.add("tip_radius_" + n + "_m", g[i]->tip_radius(), "m");
    key.add("root_radius_" + n + "_m", g[i]->root_radius(), "m");
    key.add("operating_pitch_radius_" + n + "_m", i == 0 ? p.mesh.pitch_radius1 : p.mesh.pitch_radius2, "m");
    key.add("tip_thickness_" + n + "_m", tooth_thickness(*g[i], g[i]->tip_radius()), "m");
    const double z_min = undercut_limit_teeth(file_.dedendum_coefficient * c, file_.root_radius_coefficient * c,
                                              g[i]->profile_shift, g[i]->pressure_angle_deg);
    key.add("undercut_z_min_" + n, z_min, "-");
    if (g[i]->teeth < z_min) {
      undercut = 1;
      run.say("WARNING gear " + n + ": z = " + std::to_string(g[i]->teeth) + " < z_min = " + std::to_string(z_min) +
              ": the involute is undercut near the root (the beam model keeps the full involute)");
    }
  }
  key.add("undercut", undercut, "-");
  key.add("method_potential_energy", file_.method == ToothModel::potential_energy ? 1 : 0, "-");
  key.add("method_fe", file_.method == ToothModel::fe ? 1 : 0, "-");
  if (file_.method == ToothModel::potential_energy) {
    // Sainsot's fillet fit holds for 1.4 <= h_f = rf / r_int <= 7, 0.01 <= theta_f <= 0.12 rad.
    for (int i = 0; i < 2; ++i) {
      const PeToothGeometry t = pe_tooth_geometry(file_.pe[i]);
      const bool in = pe_fillet_in_range(t.h_f, t.theta_f);
      const std::string n = std::to_string(i + 1);
      key.add("pe_fillet_h_f_" + n, t.h_f, "-");
      key.add("pe_fillet_in_range_" + n, in ? 1 : 0, "-");
      if (!in)
        run.say("WARNING gear " + n + ": h_f = rf / rim_radius = " + std::to_string(t.h_f) + ", theta_f = " +
                std::to_string(t.theta_f) + " rad lie outside Sainsot's fitted range (1.4..7, 0.01..0.12): the " +
                "fillet-foundation term is extrapolated");
    }
  }
  key.add("normal_backlash_m", file_.backlash, "m");
  key.add("tooth_elements", m.elements(), "-");
  // The points of the path: distance from T1 and the radius on each gear.
  Table t({"point", "T1_distance_m", "s_from_A_m", "r1_m", "r2_m"});
  const std::pair<const char*, double> points[] = {
      {"A", p.T1A}, {"B", p.T1B}, {"C", p.T1C}, {"D", p.T1D}, {"E", p.T1E}};
  for (const auto& [name, T1P] : points) {
    const ContactRadii r = contact_radii(m.gear1, m.gear2, p, T1P - p.T1A);
    t.add_row({std::string(name), T1P, T1P - p.T1A, r.r1, r.r2});
  }
  run.write("path_of_contact.csv", t);
  const char* method[] = {" [beam model]", " [potential-energy method]", " [finite elements]"};
  run.say(file_.name + method[int(file_.method)] + ": a = " + std::to_string(p.mesh.centre_distance * 1e3) + " mm, alpha_w = " +
          std::to_string(p.mesh.pressure_angle * 180 / M_PI) + " deg, eps_alpha = " + std::to_string(p.contact_ratio));
}

// The helix (pair_helical.hpp; 0 and the spur values for a spur pair): transverse section,
// overlap and total contact ratio, the slices.
void GearPairFromFile::helix_key_numbers(Run& run) const {
  const HelicalPair& h = file_.helical;
  const PairSteModel& m = file_.pair;
  KeyNumbers& key = run.key_numbers();
  const double eps_beta = overlap_ratio(m, h);
  key.add("helix_angle_deg", h.helix_angle * 180.0 / M_PI, "deg");
  key.add("base_helix_angle_deg", h.base_helix_angle() * 180.0 / M_PI, "deg");
  key.add("helix_left_hand", h.left_hand ? 1 : 0, "-");
  key.add("double_helical", h.double_helical ? 1 : 0, "-");
  key.add("transverse_module_m", m.gear1.module, "m");
  key.add("transverse_pressure_angle_deg", m.gear1.pressure_angle_deg, "deg");
  key.add("overlap_ratio", eps_beta, "-");
  key.add("total_contact_ratio", m.path().contact_ratio + eps_beta, "-");
  key.add("slices", slices(), "-");
}

// Step 3: the tooth model of model.method, built once (the FE: both gears meshed and
// factored, the influence coefficients of every phase); for the FE its mesh and the
// torsional compliance of each gear body between bore and teeth (inside its STE: a dynamic
// model with its own shafts and bodies must not count it twice).
void GearPairFromFile::tooth_model(Run& run) {
  if (file_.method == ToothModel::potential_energy)
    run.key_numbers().add("pe_coupling_m_per_N", gear_file_pe_coupling(file_), "m/N");
  loaded_ = run.timed(file_.method == ToothModel::fe ? "fe_model" : "mesh_phases", [&] { return gear_file_loaded_pair(file_); });
  const FePairModel* fe = loaded_->fe_model();
  if (!fe) return;
  KeyNumbers& key = run.key_numbers();
  const FeGearModel* g[2] = {&fe->gear1(), &fe->gear2()};
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i + 1);
    const double c = run.timed("fe_body_torsion_" + n, [&] { return g[i]->body_torsion_compliance(); });
    const double rb = g[i]->gear().base_radius();
    key.add("fe_nodes_" + n, double(g[i]->mesh().nodes.size()), "-");
    key.add("fe_bore_radius_" + n + "_m", g[i]->bore_radius(), "m");
    key.add("fe_body_torsion_compliance_" + n + "_rad_per_Nm", c, "rad/(N m)");
    key.add("fe_body_stiffness_" + n + "_N_per_m", 1.0 / (c * rb * rb), "N/m");
  }
}

// Step 4: STE(theta), k(theta) and the load shares per torque; the spectrum.
void GearPairFromFile::transmission_error(Run& run) const {
  const PairSteModel& m = file_.pair;
  std::size_t pairs = 0;
  for (const auto& ph : loaded_->ste(file_.torques.front())) pairs = std::max(pairs, ph.mesh.pairs.size());
  const int H = std::min(kMaxOrders, (file_.phases - 2) / 2);
  std::vector<std::string> spectrum_columns{"order"};
  std::vector<Eigen::VectorXd> spectra;
  KeyNumbers& key = run.key_numbers();
  const PathOfContact path = m.path();
  for (std::size_t i = 0; i < file_.torques.size(); ++i) {
    const double T = file_.torques[i], F = loaded_->force(T);
    const std::string n = std::to_string(i + 1);
    const std::vector<PairStePoint> c = run.timed("ste_" + n, [&] { return loaded_->ste(T); });
    run.write("ste_" + n + ".csv", slices() > 1 ? sliced_ste_table(c, F) : ste_table(c, pairs, F));
    if (slices() > 1) run.write("load_map_" + n + ".csv", load_map_table(c, m, slices()));
    std::vector<double> ste;
    for (const auto& p : c) ste.push_back(p.ste);
    const double mean = std::accumulate(ste.begin(), ste.end(), 0.0) / double(ste.size());
    key.add("torque_Nm_" + n, T, "N m");
    key.add("tooth_force_N_" + n, F, "N");
    key.add("ste_max_um_" + n, *std::max_element(ste.begin(), ste.end()) * 1e6, "um");
    key.add("ste_ptp_um_" + n, peak_to_peak(ste) * 1e6, "um");
    key.add("ste_mean_um_" + n, mean * 1e6, "um");
    key.add("mesh_stiffness_mean_N_per_m_" + n, mean_stiffness(ste, F), "N/m");
    key.add("loaded_contact_ratio_" + n, sliced_loaded_contact_ratio(c, path, slices()), "-");
    key.add("axial_force_N_" + n, axial_force(m, file_.helical, T), "N");
    key.add("single_pair_deflection_um_" + n, loaded_->single_pair_ste(path.AC, T) * 1e6, "um");
    spectrum_columns.push_back("amplitude_um_" + n);
    spectra.push_back(periodic_fourier(ste, H));
    char line[160];
    std::snprintf(line, sizeof line, "T1 = %g N m: max STE %.4f um, peak-to-peak %.4f um, mean k %.2f MN/m, loaded contact ratio %.4f",
                  T, *std::max_element(ste.begin(), ste.end()) * 1e6, peak_to_peak(ste) * 1e6,
                  mean_stiffness(ste, F) / 1e6, sliced_loaded_contact_ratio(c, path, slices()));
    run.say(line);
  }
  run.write("spectrum.csv", spectrum_table(spectrum_columns, spectra, H));
}

// fillet_stress_<i>.csv: along both fillets of each gear's tooth at the contact position of
// its peak root stress.
Table fillet_stress_table(const FePairModel& fe, const std::vector<FeRootStressPoint> (&r)[2]) {
  Table along({"gear", "s_from_A_m", "side", "radius_m", "tangent_deg", "stress_MPa"});
  for (int j = 0; j < 2; ++j) {
    const auto peak = std::max_element(r[j].begin(), r[j].end(), [](auto& x, auto& y) { return x.stress < y.stress; });
    const auto& stations = (j == 0 ? fe.gear1() : fe.gear2()).fillet_stations();
    // Per side, ordered from the root up; a node shared by two fillet edges is read in both
    // triangles: the mean of the two (their difference is the discretisation's).
    std::map<std::pair<bool, double>, std::array<double, 3>> rows;   // (other side, radius) -> tangent, sum, count
    for (const auto& [station, sigma] : peak->fillet) {
      const FilletStation& st = stations[std::size_t(station)];
      auto& row = rows[{!st.loaded_side, st.radius}];
      row[0] = st.tangent_deg, row[1] += sigma, row[2] += 1;
    }
    for (const auto& [where, row] : rows)
      along.add_row({long(j + 1), peak->s, std::string(where.first ? "other" : "loaded"), where.second, row[0],
                     row[1] / row[2] / 1e6});
  }
  return along;
}

// Step 4b (method fe): the root stress of each gear's teeth over the path of contact
// (root_stress_<i>.csv: the largest tensile stress on the fillet below the loaded flank,
// where it sits; fillet_stress_<i>.csv: along both fillets at the peak) beside ISO 6336-3
// method B's nominal sigma_F0 = F_t / (b m) Y_F Y_S with
// F_t = T1 / r1 (a comparison, not a fit: ISO's critical section is where the fillet's
// tangent makes 30 degrees with the centre line), and Hertz's contact of every loaded pair
// for the FE's forces (contact_<i>.csv).
void GearPairFromFile::root_stress_and_contact(Run& run) const {
  const FePairModel& fe = *loaded_->fe_model();
  const PairSteModel& m = file_.pair;
  KeyNumbers& key = run.key_numbers();
  const GearGeometry* g[2] = {&m.gear1, &m.gear2};
  Iso6336ToothRoot iso[2];
  for (int j = 0; j < 2; ++j) iso[j] = iso6336_tooth_root(*g[j], file_.root_radius_coefficient, *g[1 - j], m.centre_distance);
  for (std::size_t i = 0; i < file_.torques.size(); ++i) {
    const double T = file_.torques[i];
    const std::string n = std::to_string(i + 1);
    const std::vector<FeRootStressPoint> r[2] = {run.timed("root_stress_1_" + n, [&] { return fe.root_stress(T, 1); }),
                                                 run.timed("root_stress_2_" + n, [&] { return fe.root_stress(T, 2); })};
    Table t({"s_from_A_m", "root_stress_MPa_1", "radius_m_1", "tangent_deg_1", "root_stress_MPa_2", "radius_m_2",
             "tangent_deg_2"});
    for (std::size_t k = 0; k < r[0].size() && k < r[1].size(); ++k) {
      const FilletStation& a = fe.gear1().fillet_stations()[std::size_t(r[0][k].station)];
      const FilletStation& b = fe.gear2().fillet_stations()[std::size_t(r[1][k].station)];
      t.add_row({r[0][k].s, r[0][k].stress / 1e6, a.radius, a.tangent_deg, r[1][k].stress / 1e6, b.radius, b.tangent_deg});
    }
    run.write("root_stress_" + n + ".csv", t);
    run.write("fillet_stress_" + n + ".csv", fillet_stress_table(fe, r));
    for (int j = 0; j < 2; ++j) {
      const std::string gj = std::to_string(j + 1) + "_" + n;
      const auto peak = std::max_element(r[j].begin(), r[j].end(), [](auto& x, auto& y) { return x.stress < y.stress; });
      const FilletStation& st = (j == 0 ? fe.gear1() : fe.gear2()).fillet_stations()[std::size_t(peak->station)];
      const double Ft = T / m.gear1.pitch_radius();
      key.add("fe_root_stress_max_MPa_" + gj, peak->stress / 1e6, "MPa");
      key.add("fe_root_stress_max_s_m_" + gj, peak->s, "m");
      key.add("fe_root_stress_max_radius_m_" + gj, st.radius, "m");
      key.add("fe_root_stress_max_tangent_deg_" + gj, st.tangent_deg, "deg");
      key.add("iso6336_root_stress_MPa_" + gj,
              iso6336_nominal_root_stress(Ft, g[j]->face_width, g[j]->module, iso[j].Y_F, iso[j].Y_S) / 1e6, "MPa");
    }
    const std::vector<FeContactPressure> c = fe.contact_pressure(T);
    Table p({"s_from_A_m", "force_N", "half_width_um", "peak_pressure_MPa"});
    double p_max = 0.0;
    for (const auto& q : c) {
      p.add_row({q.s, q.force, q.half_width * 1e6, q.peak_pressure / 1e6});
      p_max = std::max(p_max, q.peak_pressure);
    }
    run.write("contact_" + n + ".csv", p);
    key.add("fe_contact_pressure_max_MPa_" + n, p_max / 1e6, "MPa");
  }
}

// Step 5: ISO 6336-1 method B for the same pair, at the file's largest torque.
void GearPairFromFile::iso6336(Run& run) const {
  const PairSteModel& m = file_.pair;
  const double T = *std::max_element(file_.torques.begin(), file_.torques.end());
  const double b = m.contact_length();
  // F_t = 2000 T1 / d1 (ISO 6336-1, d1 the reference diameter), line load F_t / b [N/mm].
  const double line_load = T / m.gear1.pitch_radius() / (b * 1e3);
  const Iso6336Stiffness s =
      iso6336_mesh_stiffness(pair_iso6336_input(m, file_.helical, file_.dedendum_coefficient, line_load));
  KeyNumbers& key = run.key_numbers();
  key.add("iso6336_c_prime_th", s.c_th, "N/(mm um)");
  key.add("iso6336_c_prime", s.c_single, "N/(mm um)");
  key.add("iso6336_c_gamma_alpha", s.c_gamma_alpha, "N/(mm um)");
  key.add("iso6336_c_gamma_beta", s.c_gamma_beta, "N/(mm um)");
  key.add("iso6336_c_gamma_alpha_N_per_m", s.c_gamma_alpha_total, "N/m");
  key.add("iso6336_line_load_N_per_mm", line_load, "N/mm");
}

// Step 6: the Harris map, STE peak-to-peak against torque with and without the relief
// (the same tooth model: the reliefs are separations of its contact problem).
void GearPairFromFile::harris_map(Run& run) const {
  Table t({"torque_Nm", "ste_ptp_um", "ste_ptp_um_unmodified", "loaded_contact_ratio"});
  double best = 1e300, at = 0.0;
  for (int j = 0; j < file_.harris_points; ++j) {
    const double T = file_.harris_from + (file_.harris_to - file_.harris_from) * j / (file_.harris_points - 1);
    const auto c = loaded_->ste(T);
    std::vector<double> v;
    for (const auto& p : c) v.push_back(p.ste);
    const double ptp = peak_to_peak(v);
    v.clear();
    for (const auto& p : loaded_->ste(T, false)) v.push_back(p.ste);
    t.add_row({T, ptp * 1e6, peak_to_peak(v) * 1e6, sliced_loaded_contact_ratio(c, file_.pair.path(), slices())});
    if (ptp < best) best = ptp, at = T;
  }
  run.write("harris.csv", t);
  run.key_numbers().add("harris_min_ptp_torque_Nm", at, "N m");
  run.key_numbers().add("harris_min_ptp_um", best * 1e6, "um");
}

// Step 7: the response over the speed range for every torque, both flanks, with Floquet
// stability and bifurcations (frc_<i>.csv, bifurcations_<i>.csv), GSL time integration at
// stable points (check_time_integration_<i>.csv), the closed-contact modes (modes.csv).
void GearPairFromFile::dynamics(Run& run) const {
  const GearDynamicsInput& d = file_.dynamics;
  Table modes({"torque_index", "torque_Nm", "mode", "f_hz", "speed_rpm_mesh_order_1"});
  Table spectrum({"torque_index", "f_mesh_hz", "order", "amplitude_um"});
  Table history({"torque_index", "f_mesh_hz", "phase", "t_ms", "dte_um", "mesh_force_N", "drive_force_N", "back_force_N"});
  double history_kv = 0.0;
  const std::vector<std::string> lead{"torque_index", "torque_Nm", "f_mesh_hz", "speed_rpm"};
  std::vector<std::string> banded = lead, branched = lead;
  banded.emplace_back("band");
  branched.insert(branched.end(), {"period", "branch"});
  Table diagram(bifurcation_columns(banded, "dte_um")), diagram_hb(hb_section_columns(branched, "dte_um"));
  bool drawn = false;
  for (std::size_t i = 0; i < file_.torques.size(); ++i) {
    const DteGear mesh = mesh_at(i);
    const HarmonicBalance hb = gear_mesh_model(mesh, d.dofs, bearings(), d.harmonics, 0, d.mesh);
    Response r = response(run, i, mesh, hb);
    response_key_numbers(run, i, r);
    axial_key_numbers(run, i, hb, r);
    spectrum_and_history(hb, i, r, spectrum, history, history_kv);
    if (d.time_check_points > 0) time_integration_check(run, i, hb, r);
    BifurcationDiagram bd;
    const bool has = bifurcation_diagram(run, i, hb, r, bd, diagram, diagram_hb);   // and the orbit branches
    drawn = drawn || has;
    response_tables(run, i, hb, r);
    any_motion_key_numbers(run, i, hb, r, has ? &bd : nullptr);
    const std::vector<double> f = closed_contact_frequencies(r.mesh, d.dofs, bearings());
    for (std::size_t k = 0; k < f.size(); ++k)
      modes.add_row({long(i + 1), file_.torques[i], long(k + 1), f[k], speed_rpm(2.0 * M_PI * f[k])});
  }
  run.write("modes.csv", modes);
  run.write("dte_spectrum.csv", spectrum);
  if (history.rows() > 0) run.write("time_history.csv", history);
  if (drawn) {
    run.write("bifurcation_diagram.csv", diagram);
    run.write("bifurcation_diagram_hb.csv", diagram_hb);
  }
}

// The diagram by time integration of torque i (app/bifurcation_input.hpp) into d, up then down
// over each band of the file's bifurcation_diagram key (down from the stable HB orbit at the
// band's upper end where there is one, on a second thread: set_down_start) - by default each speed range with no
// stable period-1 orbit, padded to show period 1 on both sides; false (said in one line) where
// there is none (every range stable, the key false) or the integration is stiff. Rows of
// bifurcation_diagram.csv: the DTE at phase 0 of each mesh period, um, and the band (1, 2, ...);
// bifurcation_diagram_hb.csv: the HB branches' (period 1 and the period-doubled ones, period and branch
// columns); key numbers diagram_off_branch_period1_<i>, _period2_<i>: its orbits on no HB branch of
// their period (off_branch_key_numbers).
bool GearPairFromFile::bifurcation_diagram(Run& run, std::size_t i, const HarmonicBalance& hb, Response& r,
                                           BifurcationDiagram& d, Table& t, Table& hb_section) const {
  if (!file_.diagram.on) return false;
  const std::string n = std::to_string(i + 1);
  const double lo = 2.0 * M_PI * file_.dynamics.f_min_hz, hi = 2.0 * M_PI * file_.dynamics.f_max_hz;
  const std::vector<DiagramBand> bands = input_bands(file_.diagram, r.curve, lo, hi, hb.dofs());
  const std::string stiff = bands.empty() ? "" : diagram_stiffness(hb, bands.front().omega_lo);
  if (bands.empty() || !stiff.empty()) {
    run.say(torque_label(i) + ": " + (bands.empty() ? "no bifurcation diagram: a stable period-1 orbit over the whole speed range" : stiff));
    return false;
  }
  auto rpm = [&](double w) { return speed_rpm(w); };
  run.say(torque_label(i) + ": " + diagram_bands_text(bands, rpm, "rpm"));
  d = diagram_of_bands(run, hb, r.curve, bands, file_.diagram.options, "bifurcation_diagram_" + n, torque_label(i) + ": ");
  diagram_key_numbers(run.key_numbers(), d, "_" + n);
  run.key_numbers().add("diagram_bands_" + n, double(bands.size()), "-");
  const std::vector<DiagramPoint> off = diagram_off_branch_orbits(hb, r.curve, r.doubled, d, file_.diagram.options.period_tol);
  off_branch_key_numbers(run.key_numbers(), off, "_" + n);
  run.say(torque_label(i) + ": " + diagram_summary(d, rpm, "rpm"));
  orbit_branches(run, i, hb, r, off);
  auto lead = [&](double w) {
    return std::vector<Table::Cell>{long(i + 1), file_.torques[i], hz(w), speed_rpm(w)};
  };
  const Eigen::VectorXd q = dte_coordinate(file_.dynamics.dofs, bearings());
  const BifurcationDiagram& sweeps = d;
  const SectionOrbits orbits = run.timed("HB orbits at the diagram's speeds " + n, [&] {
    return section_orbits(hb, r.curve, r.doubled, d);
  });
  const BifurcationDiagram from_hb = diagram_from_hb_orbits(run, hb, r.curve, r.doubled, orbits, d, file_.diagram.options);
  for (const BifurcationDiagram* e : {&sweeps, &from_hb})
    add_bifurcation_rows(t, *e, q, 1e6, [&](double w) {
      std::vector<Table::Cell> row = lead(w);
      row.emplace_back(band_of(bands, w));
      return row;
    });
  add_hb_section_rows(hb_section, hb, r.curve, r.doubled, orbits, q, 1e6, [&](double w, int p, int b) {
    std::vector<Table::Cell> row = lead(w);
    row.emplace_back(long(p));
    row.emplace_back(long(b));
    return row;
  });
  return true;
}

// Torque i's HB branches through the diagram's orbits of period 1 or 2 that lie on none of its
// branches (`off`: those diagram_off_branch_period1_<i>, _period2_<i> count, found and polished
// once by bifurcation_diagram: diagram_off_branch_orbits; app/orbit_branches.hpp orbit_branches_of_diagram, as gearhb_frc's step 4b): each
// continued over the speed range with the curve's sweep options, appended to r.doubled (the next
// branch id in frc_<i>.csv, bifurcations_<i>.csv and bifurcation_diagram_hb.csv) with its gear
// measures, and said in one line as the period-2 branches are. Key numbers with the suffix _<i>
// (orbit_branches_<i>, off_curve_orbits_left_<i>, off_curve_orbits_on_known_<i>,
// orbit_branch_*_<i>_<k>: "dte", the DTE) and the speed ranges with no stable period-1 orbit on
// any period-1 branch, unstable_period1_ranges_all_branches_<i> with each range k as
// unstable_period1_from_rpm_all_branches_<i>_<k>, unstable_period1_to_rpm_all_branches_<i>_<k>,
// and their unresolved stretches, unresolved_period1_*_all_branches_<i> (period1_ranges).
void GearPairFromFile::orbit_branches(Run& run, std::size_t i, const HarmonicBalance& hb, Response& r,
                                      const std::vector<DiagramPoint>& off) const {
  const std::string n = std::to_string(i + 1);
  const Eigen::VectorXd q = dte_coordinate(file_.dynamics.dofs, bearings());
  const std::size_t first = r.doubled.size();
  const std::vector<OrbitBranch> found = orbit_branches_of_diagram(run, torque_label(i), hb, r.curve, r.doubled, off, r.o,
                                                                   file_.diagram.options.period_tol, q, "dte", "_" + n);
  for (std::size_t k = first; k < r.doubled.size(); ++k) {
    const PeriodDoubledBranch& b = r.doubled[k];
    r.doubled_summary.push_back(mesh_curve_summary(*b.model, b.curve, r.mesh.F0, q));
    say_branch(run, i, k, b, r.doubled_summary.back());
  }
  if (found.empty()) return;
  const Period1Ranges p1 = period1_ranges(r.o.omega_min, r.o.omega_max, period1_curves(r.curve, found));
  const auto rpm = [this](double w) { return speed_rpm(w); };
  add_range_key_numbers(run.key_numbers(), "unstable_period1", p1.no_stable, "_all_branches_" + n, "rpm", rpm, "rpm");
  add_range_key_numbers(run.key_numbers(), "unresolved_period1", p1.unresolved, "_all_branches_" + n, "rpm", rpm, "rpm");
}

// Step 8: ISO 6336-1 method B's K_v over the same speed range, per torque (iso_kv.csv, the
// dotted curves of response.png), with ISO 1328-1 grade dynamics.iso_quality_grade.
void GearPairFromFile::iso_dynamic_factor(Run& run) const {
  constexpr int kSpeeds = 801;
  const GearDynamicsInput& d = file_.dynamics;
  KeyNumbers& key = run.key_numbers();
  std::vector<std::string> columns{"speed_rpm"};
  std::vector<Iso6336KvInput> inputs;
  for (std::size_t i = 0; i < file_.torques.size(); ++i) {
    PairIsoKv k;
    try {
      k = pair_iso6336_kv(file_.pair, file_.dedendum_coefficient, file_.torques[i], file_.gear[0].inertia,
                          file_.gear[1].inertia, d.iso_quality_grade, file_.helical);
    } catch (const std::domain_error& e) {
      run.say(std::string("no ISO 6336-1 K_v: ") + e.what());
      return;
    }
    const std::string n = std::to_string(i + 1);
    if (i == 0) {
      key.add("iso_quality_grade", d.iso_quality_grade, "-");
      key.add("iso_f_pb_um", k.f_pb, "um");
      key.add("iso_f_f_alpha_um", k.f_f_alpha, "um");
      key.add("iso_tip_relief_um", k.input.C_a, "um");
      key.add("iso_tip_relief_from_running_in", k.relief_from_running_in ? 1 : 0, "-");
    }
    const Iso6336Kv at0 = iso6336_dynamic_factor(k.input, 0.0);
    key.add("iso_kv_resonance_speed_rpm_" + n, at0.n_E1_rpm, "rpm");
    columns.push_back("K_v_" + n);
    inputs.push_back(k.input);
  }
  Table t(columns);
  std::vector<double> peak(inputs.size(), 0.0);
  const double z1 = file_.pair.gear1.teeth, from = 60.0 * d.f_min_hz / z1, to = 60.0 * d.f_max_hz / z1;
  for (int j = 0; j < kSpeeds; ++j) {
    const double n1 = from + (to - from) * j / (kSpeeds - 1);
    std::vector<double> row{n1};
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const double kv = iso6336_dynamic_factor(inputs[i], n1).K_v;
      row.push_back(kv);
      peak[i] = std::max(peak[i], kv);
    }
    t.add_row(std::vector<Table::Cell>(row.begin(), row.end()));
  }
  run.write("iso_kv.csv", t);
  for (std::size_t i = 0; i < peak.size(); ++i) key.add("iso_kv_peak_" + std::to_string(i + 1), peak[i], "-");
}

// dte_spectrum.csv: the DTE per mesh order at the stable points nearest 0.5 f_n, the DTE RMS
// peak and 1.5 f_n (f_n the closed-contact mesh frequency); time_history.csv: two mesh
// periods of the DTE and the flank forces at the stable point of largest K_v with a back
// impact (else with a drive loss) over all torques.
void GearPairFromFile::spectrum_and_history(const HarmonicBalance& hb, std::size_t i, const Response& r, Table& spectrum,
                                            Table& history, double& history_kv) const {
  const auto& P = r.curve.branch.points;
  const Eigen::VectorXd q = dte_coordinate(file_.dynamics.dofs, bearings());
  const double wn = 2.0 * M_PI * r.f_natural;
  for (double omega : {0.5 * wn, r.summary.dte_rms_peak_omega, 1.5 * wn}) {
    std::size_t best = P.size();
    for (std::size_t k = 0; k < P.size(); ++k)
      if (r.curve.stable[k] && (best == P.size() || std::fabs(P[k].omega - omega) < std::fabs(P[best].omega - omega))) best = k;
    if (best == P.size()) continue;
    const Eigen::VectorXd c = hb.project(P[best].X, q);
    for (int k = 1; k <= hb.harmonics(); ++k)
      spectrum.add_row({long(i + 1), hz(P[best].omega), long(k), 1e6 * std::hypot(c[2 * k - 1], c[2 * k])});
  }
  std::size_t pick = P.size();
  auto rank = [&](std::size_t k) {   // back impacts first, then drive losses, then K_v
    const MeshContact c = r.summary.points[k].contact;
    return (c == MeshContact::full ? 0.0 : c == MeshContact::drive_loss ? 1e3 : 2e3) + r.summary.points[k].dynamic_factor;
  };
  for (std::size_t k = 0; k < P.size(); ++k)
    if (r.curve.stable[k] && r.summary.points[k].contact != MeshContact::full && (pick == P.size() || rank(k) > rank(pick)))
      pick = k;
  if (pick == P.size() || rank(pick) <= history_kv) return;
  history_kv = rank(pick);
  history = Table({"torque_index", "f_mesh_hz", "phase", "t_ms", "dte_um", "mesh_force_N", "drive_force_N", "back_force_N"});
  const ResponseEvaluator ev(hb, q, 512);
  const Eigen::VectorXd x = ev.history(P[pick].X), fd = ev.contact_force_history(P[pick].X, 0);
  const Eigen::VectorXd fb = hb.contacts().size() > 1 ? ev.contact_force_history(P[pick].X, 1) : Eigen::VectorXd::Zero(x.size());
  const double T = 2.0 * M_PI / P[pick].omega;
  for (int period = 0; period < 2; ++period)
    for (Eigen::Index j = 0; j < x.size(); ++j) {
      const double ph = period + double(j) / double(x.size());
      history.add_row({long(i + 1), hz(P[pick].omega), ph, 1e3 * T * ph, 1e6 * x[j], fd[j] - fb[j], fd[j], fb[j]});
    }
}

BearingSupport GearPairFromFile::bearings() const { return gear_file_bearings(file_); }

std::string GearPairFromFile::torque_label(std::size_t i) const {
  char label[48];
  std::snprintf(label, sizeof label, "T1 = %g N m", file_.torques[i]);
  return label;
}

// The mesh at torque i (its STE from the tooth model, its equivalent mass and damping).
DteGear GearPairFromFile::mesh_at(std::size_t i) const {
  const GearDynamicsInput& d = file_.dynamics;
  const double T = file_.torques[i];
  return gear_pair_mesh(file_.pair, loaded_->ste(T), T, file_.gear[0].inertia, file_.gear[1].inertia, d.zeta,
                        d.back_flank ? file_.backlash : INFINITY);
}

// The frequency curve of torque i's mesh model over the speed range.
GearPairFromFile::Response GearPairFromFile::response(Run& run, std::size_t i, const DteGear& mesh,
                                                      const HarmonicBalance& hb) const {
  const GearDynamicsInput& d = file_.dynamics;
  Response r;
  r.mesh = mesh;
  r.f_natural = closed_contact_frequencies(mesh, MeshDofs::one_dof, {}).front();
  SweepOptions& o = r.o;
  o.omega_min = 2.0 * M_PI * d.f_min_hz;
  o.omega_max = 2.0 * M_PI * d.f_max_hz;
  o.direction = d.direction;
  o.continuation.ds_max = 0.05;
  r.curve = timed_sweep(run, hb, o, torque_label(i));
  r.summary = mesh_curve_summary(hb, r.curve, r.mesh.F0, dte_coordinate(d.dofs, bearings()));
  if (file_.period_doubling_depth >= 1) doubled_branches(run, i, hb, o, r);
  return r;
}

// Period-2 branches (and period 4 at depth 2) from the located period doublings of torque i's curve, switched as
// gearhb_frc switches them (period_doubled_branches, over the same speed range); each says in
// one line where it starts and how it ends (a switch that fails: where and why; the rest of
// the run stands), and the gear's measures of its points (over two mesh periods).
void GearPairFromFile::doubled_branches(Run& run, std::size_t i, const HarmonicBalance& hb, SweepOptions o,
                                        Response& r) const {
  const auto& B = r.curve.bifurcations;
  if (std::none_of(B.begin(), B.end(), [](const Bifurcation& b) { return b.type == BifurcationType::period_doubling; }))
    return;
  report_sweep_progress(run, o, torque_label(i) + ": period 2");
  r.doubled = run.timed("period-doubled branches T" + std::to_string(i + 1), [&] {
    return period_doubling_cascade(hb, r.curve, o, file_.period_doubling_depth);
  });
  for (std::size_t k = 0; k < r.doubled.size(); ++k) {
    const PeriodDoubledBranch& b = r.doubled[k];
    run.say(torque_label(i) + ": " + b.why);
    r.doubled_summary.push_back(has_points(b) ? mesh_curve_summary(*b.model, b.curve, r.mesh.F0,
                                                                   dte_coordinate(file_.dynamics.dofs, bearings()))
                                              : MeshCurveSummary{});
    if (has_points(b)) say_branch(run, i, k, b, r.doubled_summary.back());
  }
}

// One line for branch k of torque i (a period-doubled one, or one continued from a diagram orbit):
// its speeds, where it is stable, and its largest stable K_v and DTE RMS (over its period); a
// stable stretch with no converged shooting correction is listed apart (resolved_stable).
void GearPairFromFile::say_branch(Run& run, std::size_t i, std::size_t k, const PeriodDoubledBranch& b,
                                  const MeshCurveSummary& m) const {
  double lo = INFINITY, hi = -INFINITY;   // its span in forcing omega
  for (const auto& p : b.curve.branch.points) lo = std::min(lo, b.period * p.omega), hi = std::max(hi, b.period * p.omega);
  const bool doubled = b.from != std::size_t(-1);   // a period-doubled branch: from its PD to where it ends
  char part[120];
  std::snprintf(part, sizeof part, ": period-%d branch %zu, %.0f to %.0f rpm:", b.period, k + 1,
                speed_rpm(doubled ? b.omega_start : lo), speed_rpm(doubled ? b.omega_end : hi));
  const Intervals st = resolved_stable_intervals(b.curve, b.period);
  std::string line = torque_label(i) + part + rpm_list(st.empty() ? "" : " stable at", st);
  std::snprintf(part, sizeof part, " rpm; largest stable K_v %.2f, DTE RMS %.2f um", m.dynamic_factor_peak,
                m.dte_rms_peak * 1e6);
  line += st.empty() ? " unstable everywhere" : part;
  const Intervals unresolved = unresolved_stable_stretches(b.curve, b.period);
  if (!unresolved.empty())
    line += rpm_list("; stability unresolved (shooting correction failed) at", unresolved) + " rpm";
  run.say(line);
}

// " <head> a-b, c-d" (rpm of the forcing-frequency intervals; a one-point interval as one speed).
std::string GearPairFromFile::rpm_list(const std::string& head, const Intervals& iv) const {
  std::string out = head;
  char part[64];
  for (std::size_t j = 0; j < iv.size(); ++j) {
    const double a = speed_rpm(iv[j].first), b = speed_rpm(iv[j].second);
    if (a == b) std::snprintf(part, sizeof part, "%s %.0f", j == 0 ? "" : ",", a);
    else std::snprintf(part, sizeof part, "%s %.0f-%.0f", j == 0 ? "" : ",", a, b);
    out += part;
  }
  return out;
}

// The rows of one curve of a torque (the common columns, then the gear's); `label` its period
// and branch (a period-2 branch: hb its period-2 model, its omegas half the mesh frequency).
Table GearPairFromFile::mesh_table(const HarmonicBalance& hb, const FrequencyCurve& c, const MeshCurveSummary& s,
                                   const BranchLabel& label, const RowProgress& progress) const {
  const auto& m = s.points;
  return frequency_response_table(
      hb, c, dte_coordinate(file_.dynamics.dofs, bearings()),
      {"dte_ptp_um", "mesh_force_max_N", "mesh_force_min_N", "dynamic_factor", "contact_drive", "contact_back"},
      [&](std::size_t k) -> std::vector<Table::Cell> {
        return {m[k].dte_ptp * 1e6, m[k].force_max, m[k].force_min, m[k].dynamic_factor,
                std::string(to_string(m[k].drive)), std::string(to_string(m[k].back))};
      },
      [&](std::size_t k) { return std::string(to_string(m[k].contact)); }, progress, label,
      {FrequencyAxis::gear, double(file_.pair.gear1.teeth)});
}

// frc_<i>.csv and bifurcations_<i>.csv: the period-1 curve (period 1, branch 0), then each
// period-2 branch with points (period 2, branch k), as gearhb_frc writes them.
void GearPairFromFile::response_tables(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const {
  const std::string n = std::to_string(i + 1);
  Table frc = mesh_table(hb, r.curve, r.summary, {}, table_progress(run, r.curve, torque_label(i)));
  Table bif = bifurcation_table(r.curve, {}, branch_starts(r.curve, r.doubled));
  for (std::size_t k = 0; k < r.doubled.size(); ++k) {
    if (!has_points(r.doubled[k])) continue;
    const BranchLabel label{r.doubled[k].period, int(k) + 1};
    frc.append(mesh_table(*r.doubled[k].model, r.doubled[k].curve, r.doubled_summary[k], label, {}));
    bif.append(bifurcation_table(r.doubled[k].curve, label, branch_starts(r.doubled[k].curve, r.doubled, int(k))));
  }
  run.write("frc_" + n + ".csv", frc);
  run.write("bifurcations_" + n + ".csv", bif);
}

// The key numbers of torque i (file order, 1-based); a transition that never happens is absent,
// and so are the peaks (over stable points) where no point of the period-1 curve is stable.
void GearPairFromFile::response_key_numbers(Run& run, std::size_t i, const Response& r) const {
  KeyNumbers& key = run.key_numbers();
  const std::string n = std::to_string(i + 1);
  const MeshCurveSummary& s = r.summary;
  const double fn = r.f_natural;
  if (i == 0) key.add("f_mesh_natural_hz", fn, "Hz");
  key.add("f_mesh_natural_hz_" + n, fn, "Hz");
  key.add("mesh_stiffness_kc_N_per_m_" + n, r.mesh.kc, "N/m");
  key.add("equivalent_mass_kg_" + n, r.mesh.me, "kg");
  const bool stable_point = std::isfinite(s.dte_rms_peak_omega);   // the peaks are over stable points
  if (stable_point) {
    key.add("dte_rms_peak_um_" + n, s.dte_rms_peak * 1e6, "um");
    key.add("dte_rms_peak_f_mesh_hz_" + n, hz(s.dte_rms_peak_omega), "Hz");
    key.add("dynamic_factor_peak_" + n, s.dynamic_factor_peak, "-");
    key.add("dynamic_factor_peak_speed_rpm_" + n, speed_rpm(s.dynamic_factor_peak_omega), "rpm");
  }
  if (std::isfinite(s.drive_loss_first_omega))
    key.add("drive_loss_first_f_mesh_hz_" + n, hz(s.drive_loss_first_omega), "Hz");
  if (std::isfinite(s.back_impact_first_omega))
    key.add("back_impact_first_f_mesh_hz_" + n, hz(s.back_impact_first_omega), "Hz");
  key.add("mean_force_rel_dev_" + n, s.mean_force_rel_dev, "-");
  long unstable = 0;
  for (bool st : r.curve.stable) unstable += st ? 0 : 1;
  key.add("points_" + n, double(r.curve.branch.points.size()), "-");
  key.add("unstable_points_" + n, double(unstable), "-");
  key.add("bifurcations_" + n, double(r.curve.bifurcations.size()), "-");
  char line[200];
  if (stable_point)
    std::snprintf(line, sizeof line, "T1 = %g N m: peak DTE RMS %.4f um at %.1f Hz, peak K_v %.4f at %.0f rpm, %zu points",
                  file_.torques[i], s.dte_rms_peak * 1e6, hz(s.dte_rms_peak_omega), s.dynamic_factor_peak,
                  speed_rpm(s.dynamic_factor_peak_omega), r.curve.branch.points.size());
  else
    std::snprintf(line, sizeof line, "T1 = %g N m: no stable period-1 point over the speed range (no peak DTE RMS, K_v), %zu points",
                  file_.torques[i], r.curve.branch.points.size());
  run.say(line);
}

// Six DOFs with a helix (mesh_dynamics.hpp, BearingSupport: one axial DOF per gear): the mean
// axial bearing force of each gear at the curve's first point, axial_bearing_force_N_<gear>_<i>
// (its static closed form F0 tan(beta_b) = F_t tan(beta) is axial_force_N_<i>).
void GearPairFromFile::axial_key_numbers(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const {
  const BearingSupport b = bearings();
  if (file_.dynamics.dofs != MeshDofs::bearings || !b.axial() || r.curve.branch.points.empty()) return;
  for (int g = 0; g < 2; ++g)
    run.key_numbers().add("axial_bearing_force_N_" + std::to_string(g + 1) + "_" + std::to_string(i + 1),
                          mean_axial_bearing_force(hb, b, r.curve.branch.points.front().X, g), "N");
}

// Issue 34 §4, torque i: the speed ranges with no stable period-1 orbit (period1_ranges: the gaps
// of the period-1 curve's resolved-stable intervals; unstable_period1_ranges_<i>, each
// unstable_period1_from_rpm_<i>_<k>, unstable_period1_to_rpm_<i>_<k>), of them the stretches whose
// stable label is unresolved (unresolved_period1_ranges_<i>, unresolved_period1_from_rpm_<i>_<k>,
// unresolved_period1_to_rpm_<i>_<k>), and the largest K_v and DTE RMS of the motion that exists
// (max_kv_any_motion_<i>, max_dte_rms_any_motion_um_<i>): every stable period-1 and period-2 orbit
// (period 2: where its label is resolved, resolved_stable)
// and, at the diagram's speeds in those ranges where it is not period 1, the time-integrated motion
// (16 mesh periods from its first Poincare state, 512 samples each: mesh_motion_measures);
// max_kv_any_motion_from_<i>: which gave the largest K_v (1, 2: the HB orbit of that period; 0: the
// time integration); any_motion_complete_<i>: 0 where a range has neither a resolved stable
// period-2 orbit nor the diagram (its motion unknown, not counted).
void GearPairFromFile::any_motion_key_numbers(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r,
                                              const BifurcationDiagram* d) const {
  KeyNumbers& key = run.key_numbers();
  const std::string n = std::to_string(i + 1);
  const double lo = 2.0 * M_PI * file_.dynamics.f_min_hz, hi = 2.0 * M_PI * file_.dynamics.f_max_hz;
  const Period1Ranges p1 = period1_ranges(lo, hi, {&r.curve});
  const Intervals& gaps = p1.no_stable;
  const auto rpm = [this](double w) { return speed_rpm(w); };
  add_range_key_numbers(key, "unstable_period1", gaps, "_" + n, "rpm", rpm, "rpm");
  add_range_key_numbers(key, "unresolved_period1", p1.unresolved, "_" + n, "rpm", rpm, "rpm");
  Intervals stable = resolved_stable_intervals(r.curve);
  double kv = r.summary.dynamic_factor_peak, rms = r.summary.dte_rms_peak;
  int from = 1;
  for (std::size_t b = 0; b < r.doubled.size(); ++b) {
    if (!has_points(r.doubled[b])) continue;
    const Intervals more = resolved_stable_intervals(r.doubled[b].curve, r.doubled[b].period);
    stable.insert(stable.end(), more.begin(), more.end());
    const std::vector<bool> resolved = resolved_stable(r.doubled[b].curve);
    for (std::size_t k = 0; k < resolved.size(); ++k) {
      if (!resolved[k]) continue;
      const MeshOrbitMeasures& m = r.doubled_summary[b].points[k];
      if (m.dynamic_factor > kv) kv = m.dynamic_factor, from = r.doubled[b].period;
      rms = std::max(rms, m.dte_rms);
    }
  }
  const bool p1_everywhere = gaps.empty();
  double kv_ti = 0.0;
  if (d && !gaps.empty()) run.timed("any motion T" + n, [&] {
    for (const DiagramPoint& p : d->points) {
      const bool in_gap = std::any_of(gaps.begin(), gaps.end(), [&](auto& g) { return g.first <= p.omega && p.omega <= g.second; });
      if (!in_gap || p.motion == Motion::failed || (p.motion == Motion::periodic && p.n == 1) || p.x.rows() == 0) continue;
      const MeshMotionMeasures m = mesh_motion_measures(hb, p.x.row(0).transpose(), p.v.row(0).transpose(), p.omega, 16,
                                                        512, r.mesh.F0, dte_coordinate(file_.dynamics.dofs, bearings()),
                                                        r.curve.scaling.x.cwiseAbs().maxCoeff());
      kv_ti = std::max(kv_ti, m.dynamic_factor);
      rms = std::max(rms, m.dte_rms);
    }
    return 0;
  });
  if (kv_ti > kv) kv = kv_ti, from = 0;
  if (d && !gaps.empty()) key.add("max_kv_time_integration_" + n, kv_ti, "-");
  key.add("max_kv_any_motion_" + n, kv, "-");
  key.add("max_kv_any_motion_from_" + n, from, "-");
  key.add("max_dte_rms_any_motion_um_" + n, rms * 1e6, "um");
  key.add("any_motion_complete_" + n, p1_everywhere || d || uncovered(lo, hi, stable).empty() ? 1 : 0, "-");
}

// HB against GSL time integration of the same model at stable points (mesh_time_integration_check).
void GearPairFromFile::time_integration_check(Run& run, std::size_t i, const HarmonicBalance& hb, const Response& r) const {
  const std::string n = std::to_string(i + 1);
  const auto& P = r.curve.branch.points;
  auto progress = [&](std::size_t k, int period, double mismatch) {
    char what[160];
    std::snprintf(what, sizeof what, "%s: time integration, period %d, mismatch %.3g", torque_label(i).c_str(), period,
                  mismatch);
    run.progress(what, long(k), P[k].omega, P[k].ds);
  };
  const auto rows = run.timed("time integration T" + n, [&] {
    return mesh_time_integration_check(hb, r.curve, r.summary, r.mesh.F0, dte_coordinate(file_.dynamics.dofs, bearings()),
                                       file_.dynamics.time_check_points, progress);
  });
  Table t(check_columns(FrequencyAxis::gear, {"x_rms_ac", "dynamic_factor"}));
  double worst = 0.0;
  long impacts = 0, losses = 0;
  for (const auto& c : rows) {
    std::vector<Table::Cell> row = frequency_cells(FrequencyAxis::gear, c.omega, file_.pair.gear1.teeth);
    row.insert(row.end(), {std::string(to_string(c.contact)), c.dte_rms_hb, c.dte_rms_ti, c.dynamic_factor_hb,
                           c.dynamic_factor_ti, c.rel_diff, long(c.periods)});
    t.add_row(std::move(row));
    worst = std::max(worst, c.rel_diff);
    impacts += (c.contact == MeshContact::back_impact || c.contact == MeshContact::drive_loss_back_impact) ? 1 : 0;
    losses += c.contact == MeshContact::drive_loss ? 1 : 0;
  }
  run.write("check_time_integration_" + n + ".csv", t);
  KeyNumbers& key = run.key_numbers();
  key.add("time_integration_points_" + n, double(rows.size()), "-");
  key.add("time_integration_back_impact_points_" + n, double(impacts), "-");
  key.add("time_integration_drive_loss_points_" + n, double(losses), "-");
  key.add("time_integration_rel_diff_max_" + n, worst, "-");
}

// Step 9: DIR/*.png by figures/gearhb_gear.py (the project's figure style).
void GearPairFromFile::draw(Run& run) const {
  draw_with_script(run, std::string(GEARHB_FIGURES_DIR).empty() ? "" : std::string(GEARHB_FIGURES_DIR) + "/gearhb_gear.py",
                   "figures");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("gearhb_gear",
              "gearhb_gear: a spur or helical gear pair from its drawing - geometry, loaded static transmission error,\n"
              "mesh stiffness k = F / STE over the mesh cycle, load shares, Harris map, ISO 6336-1 stiffness;\n"
              "with a speed range the response over speed (both flanks, Floquet, K_v) and ISO 6336-1's K_v.\n"
              "Writes DIR/path_of_contact.csv, ste_<i>.csv (one per torque), spectrum.csv, harris.csv,\n"
              "key_numbers.json, params.json (the resolved file), timings.csv, *.png; with a speed range\n"
              "also frc_<i>.csv (with the period-2 and period-4 branches: columns period, branch), bifurcations_<i>.csv,\n"
              "check_time_integration_<i>.csv, modes.csv,\n"
              "dte_spectrum.csv, time_history.csv, iso_kv.csv; where a torque has a speed range with no stable\n"
              "period-1 orbit (or with bifurcation_diagram.range whole) bifurcation_diagram.csv, bifurcation_diagram_hb.csv;\n"
              "with model.method fe also root_stress_<i>.csv,\n"
              "fillet_stress_<i>.csv, contact_<i>.csv; a helical or lead-modified face also load_map_<i>.csv.\n\n" +
                  gear_file_help());
  GearPairFromFile program(study);
  return study.run(argc, argv, [&](Run& run) { program.run(run); });
}
