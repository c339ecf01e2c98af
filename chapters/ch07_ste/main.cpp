// ===========================================================================
// ch07_ste: static transmission error of a spur-gear pair (thesis ch. 7, Figs. 48-64)
// ===========================================================================
//
// Each tooth is an Euler-Bernoulli cantilever from the root circle to the tip,
// n_e equal elements, EI = E b s^3 / 12 with s a constant (6 mm, thesis §7.4) or
// the involute thickness s(r) = r s0/r0 + 2 r (inv a0 - inv a(r)) (§7.5);
//   one pair in contact:  STE = w1 + w2 (+ Hertz), both roots clamped, -F on the contact nodes;
//   two pairs:            X with k_A X + k_B X = F (fused contact nodes, guided driving roots);
//   Hertz (Palmgren):     delta[mm] = 3.84e-5 F[N]^0.9 / L[mm]^0.8;
//   mesh stiffness:       k = mean over the cycle of F / STE (thesis §8.1 corrected, README).
// The library (lib/gearhb/gears: gear_geometry, tooth_fe, hertz, ste, iso6336) does the
// numerics; this program only chooses the cases and writes them. The steps, in
// order (README of this chapter): gear_geometry, tooth_axis_angles,
// constant_thickness_checks, tooth_deflections, exact_elastic_lines, fused_moment,
// tooth_profile, ste_cycles (measure, mesh_scheme, iso6336_comparison), readings,
// convergence; own_case for --case own.
//
// Sample runs:
//   build/bin/ch07_ste                                          every figure's data
//   build/bin/ch07_ste --case quick --out /tmp/q                the regression subset
//   build/bin/ch07_ste --case refined_T3 --set torque_3=400     one STE of the case table
//   build/bin/ch07_ste --case own --set teeth=60 --set own_torque=150 --out /tmp/mine
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gearhb/app/study.hpp"
#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/hertz.hpp"
#include "gearhb/gears/rating/iso6336.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/tooth/tooth_fe.hpp"

using namespace gearhb;

namespace {

constexpr double um = 1e6, mm = 1e3;   // SI -> micrometres, millimetres
constexpr double kMaxRootStrain = 0.01;  // linear elastic, small-deflection limit of the beams

// --- parameters: one struct per concern, thesis defaults (§7.4) -------------
// The gear is lib's GearGeometry itself (both gears identical).
struct Material {
  double youngs_modulus = 207e9;   // E [Pa]
  double poisson_ratio = 0.3;      // listed by the thesis; unused by Euler-Bernoulli beams
};
struct Loads {
  double torque_1 = 100, torque_2 = 200, torque_3 = 300;   // [N m], Fig. 60
};
struct Models {
  double constant_thickness = 6e-3;         // [m], §7.4
  int first_positions_per_base_pitch = 6;   // first model: 10 elements (Fig. 46)
  int positions_per_base_pitch = 8;         // refined model: 14 elements (Fig. 62)
  int convergence_max_positions = 64;       // P = 8, 16, ... up to this
};
struct Readings {   // the modelling choices the text leaves open (README "Readings")
  int thickness_at = 0, hertz_count = 2, two_pair_hertz = 0, tooth_force = 0;
};
struct OwnCase {
  double torque = 300;           // [N m]
  int positions_per_base_pitch = 8;
};

// The gear parameters, their ranges, and how to write one into a GearGeometry
// (used to bind them and to tell the user which values of the one they set work).
struct GearField {
  std::string name;
  double lo, hi;
  bool integer;
  void (*set)(GearGeometry&, double);
  double (*get)(const GearGeometry&);
};
const std::vector<GearField> kGearFields = {
    {"teeth", 3, 10000, true,
     [](GearGeometry& g, double v) { g.teeth = int(v); }, [](const GearGeometry& g) { return double(g.teeth); }},
    {"pressure_angle_deg", 10, 35, false,
     [](GearGeometry& g, double v) { g.pressure_angle_deg = v; }, [](const GearGeometry& g) { return g.pressure_angle_deg; }},
    {"module", 1e-4, 0.1, false,
     [](GearGeometry& g, double v) { g.module = v; }, [](const GearGeometry& g) { return g.module; }},
    {"addendum", 1e-6, 0.1, false,
     [](GearGeometry& g, double v) { g.addendum = v; }, [](const GearGeometry& g) { return g.addendum; }},
    {"dedendum", 1e-6, 0.1, false,
     [](GearGeometry& g, double v) { g.dedendum = v; }, [](const GearGeometry& g) { return g.dedendum; }},
};

const GearField& gear_field(const std::string& name) {
  for (const GearField& f : kGearFields)
    if (f.name == name) return f;
  throw std::logic_error("no gear field " + name);
}

// The two mesh models of the thesis (positions per base pitch from Models).
enum class Mesh { first, refined };
struct MeshModel {
  Mesh mesh;
  std::string name, parameter;
  int Models::*positions;
};
const std::vector<MeshModel> kMeshes = {
    {Mesh::first, "first", "first_positions_per_base_pitch", &Models::first_positions_per_base_pitch},
    {Mesh::refined, "refined", "positions_per_base_pitch", &Models::positions_per_base_pitch}};

// The torques of Fig. 60.
struct Torque {
  std::string name;
  double Loads::*value;
};
const std::vector<Torque> kTorques = {{"torque_1", &Loads::torque_1}, {"torque_2", &Loads::torque_2},
                                      {"torque_3", &Loads::torque_3}};

// What an STE case measures besides its curve.
enum class Measure { max_ste, mean_stiffness, mesh_scheme, iso6336 };
struct KeyOf {
  Measure what;
  std::string key;
};
struct SteCase {
  std::string label;    // file stems ste_<label>.csv, ste_fourier_<label>.csv
  std::string figure;   // thesis figures
  Mesh mesh;
  int torque;           // index into kTorques
  bool quick;           // part of the regression subset
  std::vector<KeyOf> measures;
};
const std::vector<SteCase> kSteCases = {
    {"first_T1", "60-61", Mesh::first, 0, false, {}},
    {"first_T2", "60-61", Mesh::first, 1, false, {}},
    {"first_T3", "60-61", Mesh::first, 2, true,
     {{Measure::max_ste, "ste_max_first_model_T3_um"}, {Measure::mean_stiffness, "mean_stiffness_first_model_T3_MN_per_m"}}},
    {"refined_T1", "63-64", Mesh::refined, 0, false, {}},
    {"refined_T2", "63-64", Mesh::refined, 1, false, {}},
    {"refined_T3", "62-64", Mesh::refined, 2, true,
     {{Measure::max_ste, "ste_max_T3_um"}, {Measure::mean_stiffness, "mean_stiffness_T3_MN_per_m"},
      {Measure::mesh_scheme, ""}, {Measure::iso6336, "iso6336_c_gamma_alpha_MN_per_m"}}},
};

// The tooth-deflection figures: the n-th position with one or two pairs in contact
// of the first model's cycle, at torque_3 (Figs. 48-49 and 52-55 constant 6 mm,
// 58-59 involute thickness).
struct DeflectionCase {
  std::string figure;
  bool constant;
  int pairs;
  int nth;
};
const std::vector<DeflectionCase> kDeflections = {
    {"48", true, 1, 0}, {"49", true, 1, 1}, {"52", true, 2, 0}, {"53", true, 2, 1},
    {"54", true, 2, 2}, {"55", true, 2, 3}, {"58", false, 1, 0}, {"59", false, 2, 0}};
// Figs. 50-51: the exact elastic line for the force on the driving contact node
// of the n-th one-pair position (node 7, then node 6).
const std::vector<DeflectionCase> kElasticLines = {{"50", true, 1, 1}, {"51", true, 1, 0}};
// Fig. 56: the moment along the fused beam of the first two-pair position.
const DeflectionCase kMomentCase{"56", true, 2, 0};

// §7.7: the three readings of T2C, and the key numbers each gives.
struct AngleKey {
  std::string key;
  double ToothAxisAngles::*value;
  double scale;
  std::string unit;
};
struct AngleVariant {
  std::string name;
  T2CFormula formula;
  bool round_like_thesis;
  std::vector<AngleKey> keys;
};
const double kDeg = 180 / M_PI;
const std::vector<AngleVariant> kAngleVariants = {
    {"thesis_printed_values", T2CFormula::thesis_rb_sin, true,
     {{"beta_deg", &ToothAxisAngles::beta, kDeg, "deg"}, {"epsilon_deg", &ToothAxisAngles::epsilon, kDeg, "deg"},
      {"force_variation_percent", &ToothAxisAngles::force_variation, 100, "%"}}},
    {"thesis_formula_unrounded", T2CFormula::thesis_rb_sin, false, {}},
    {"corrected_rb_tan", T2CFormula::rb_tan, false, {{"corrected_T2C_mm", &ToothAxisAngles::T2C, mm, "mm"}}},
};

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// --- writers ------------------------------------------------------------------
// Nodal deflections of every beam (thesis global node numbers, 1-based) and the
// element thickness at each node (for drawing the deformed teeth).
Table deflection_table(const BeamModel& m, const BeamModel::Solution& s, const ToothBeam& tooth) {
  Table t({"beam", "node", "x_mm", "w_um", "theta_rad", "thickness_mm"});
  for (int b = 0; b < m.beams(); ++b)
    for (int i = 0; i < m.beam_nodes(b); ++i) {
      const int n = m.node(b, i);
      const double th = tooth.s[std::min<std::size_t>(i, tooth.s.size() - 1)];
      t.add_row({long(b + 1), long(n + 1), m.beam_x(b)[i] * mm, s.Q[BeamModel::w_dof(n)] * um,
                 s.Q[BeamModel::theta_dof(n)], th * mm});
    }
  return t;
}

std::string pair_label(const BeamModel& m, int beam_a, int ka, int beam_b, int kb) {
  return std::to_string(m.node(beam_a, ka) + 1) + "-" + std::to_string(m.node(beam_b, kb) + 1);
}

Table cycle_table(const std::vector<MeshPosition>& c, double F) {
  Table t({"phase", "ste_um", "pairs_in_contact", "elastic_um", "hertz_um", "elastic_closed_form_um",
           "force_A_N", "force_B_N", "stiffness_N_per_m", "kA1", "kA2", "kB1", "kB2"});
  for (const auto& p : c)
    t.add_row({p.phase, p.ste * um, long(p.pairs), p.elastic * um, p.hertz * um, p.elastic_closed_form * um,
               p.force_A, p.force_B, F / p.ste, long(p.kA1), long(p.kA2), long(p.kB1), long(p.kB2)});
  return t;
}

// Amplitude of harmonic k of the cycle (k <= H).
double amplitude(const Eigen::VectorXd& a, int k) { return k == 0 ? std::fabs(a[0]) : std::hypot(a[2 * k - 1], a[2 * k]); }

Table fourier_table(const std::vector<MeshPosition>& c) {
  int H = 0;
  const Eigen::VectorXd a = ste_fourier(c, &H);
  Table t({"harmonic", "a_um", "b_um", "amplitude_um"});
  t.add_row({0L, a[0] * um, 0.0, amplitude(a, 0) * um});
  for (int k = 1; k <= H; ++k) t.add_row({long(k), a[2 * k - 1] * um, a[2 * k] * um, amplitude(a, k) * um});
  return t;
}

double max_ste(const std::vector<MeshPosition>& c) {
  double v = 0;
  for (const auto& p : c) v = std::max(v, p.ste);
  return v;
}

double min_ste(const std::vector<MeshPosition>& c) {
  double v = INFINITY;
  for (const auto& p : c) v = std::min(v, p.ste);
  return v;
}

double max_rel_fe_vs_closed_form(const std::vector<MeshPosition>& c) {
  double e = 0;
  for (const auto& p : c)
    e = std::max(e, std::fabs(p.elastic_linear - p.elastic_closed_form) / p.elastic_closed_form);
  return e;
}

// The n-th position of the cycle with `pairs` pairs in contact, or nullptr.
const MeshPosition* nth_position(const std::vector<MeshPosition>& cycle, int pairs, int nth) {
  for (const auto& p : cycle)
    if (p.pairs == pairs && nth-- == 0) return &p;
  return nullptr;
}

// One position of the cycle solved with force F: the model, its solution and the
// contact nodes in thesis numbering ("6-18", "2-22_30-38").
struct Solved {
  BeamModel model;
  BeamModel::Solution solution;
  std::string nodes;
};
Solved solve_position(const ToothBeam& tooth, const MeshPosition& p, double F) {
  if (p.pairs == 1) {
    const SinglePairSolve s = solve_single_pair(tooth, p.kA1, p.kA2, F);
    return {s.model, s.solution, pair_label(s.model, 0, p.kA1, 1, p.kA2)};
  }
  const TwoPairSolve s = solve_two_pairs(tooth, p.kA1, p.kA2, p.kB1, p.kB2, F);
  return {s.model, s.solution, pair_label(s.model, 0, p.kA1, 1, p.kA2) + "_" + pair_label(s.model, 2, p.kB1, 3, p.kB2)};
}

// Internal bending moment along the fused beam of pair A (driving root -> contact
// -> driven root), from the element end forces [V1 M1 V2 M2] = K^(e) q^(e):
// internal moment -M1 at an element's first node, +M2 at its second. The driven
// tooth's frame is turned by 180 deg, so its moments change sign in the driving frame.
Table fused_moment_table(const TwoPairSolve& s, int k1, int k2) {
  Table t({"s_mm", "moment_N_m", "tooth"});
  const BeamModel& m = s.model;
  const std::vector<double>& x = m.beam_x(0);
  for (int e = 0; e < k1; ++e) {
    const Eigen::Vector4d f = m.element_end_forces(s.solution, 0, e);
    t.add_row({x[e] * mm, -f[1], std::string("driving")});
    t.add_row({x[e + 1] * mm, f[3], std::string("driving")});
  }
  const double xc = x[k1];
  for (int e = k2 - 1; e >= 0; --e) {   // driven tooth, from the contact towards its root
    const Eigen::Vector4d f = m.element_end_forces(s.solution, 1, e);
    t.add_row({(xc + x[k2] - x[e + 1]) * mm, -f[3], std::string("driven")});
    t.add_row({(xc + x[k2] - x[e]) * mm, f[1], std::string("driven")});
  }
  return t;
}

// --- the chapter ------------------------------------------------------------------
class StaticTransmissionError {
 public:
  explicit StaticTransmissionError(Study& study);
  void run(Run& run) const;

 private:
  GearGeometry gear_;
  Material mat_;
  Loads loads_;
  Models models_;
  Readings read_;
  OwnCase own_;
  const ParameterSet* params_ = nullptr;

  void check(const Selection& s) const;
  void check_gear() const;
  void check_positions(const std::string& name, int P) const;
  void check_torque(const std::string& name, double T, bool constant_model_too) const;
  SteModel model(int P, bool constant, const Readings& r) const;
  SteModel model(int P, bool constant) const { return model(P, constant, read_); }
  const MeshModel& mesh_model(Mesh mesh) const;
  double torque(int i) const { return loads_.*kTorques.at(i).value; }
  void gear_geometry(Run& run) const;
  void axis_angles(Run& run) const;
  void constant_thickness_checks(Run& run) const;
  void tooth_deflections(Run& run, Table& index) const;
  void exact_elastic_lines(Run& run, Table& index) const;
  void fused_moment(Run& run, Table& index) const;
  void tooth_profile(Run& run) const;
  void ste_cycles(Run& run) const;
  void measure(Run& run, const SteCase& cs, const SteModel& m, const std::vector<MeshPosition>& c) const;
  void mesh_scheme(Run& run, const SteModel& m, const std::vector<MeshPosition>& c) const;
  void iso6336_comparison(Run& run, const SteModel& m, const std::vector<MeshPosition>& c, const KeyOf& k) const;
  void readings(Run& run) const;
  void convergence(Run& run) const;
  void own_case(Run& run) const;
};

StaticTransmissionError::StaticTransmissionError(Study& study) {
  ParameterSet& P = study.parameters();
  params_ = &P;
  P.group("gear pair (both gears identical, thesis §7.4)");
  auto gear = [&](const char* name, auto* value, const char* unit, const std::string& help) {
    const GearField& f = gear_field(name);
    P.add(name, value, unit, help + " [" + number(f.lo) + ", " + number(f.hi) + "]", Range::between(f.lo, f.hi));
  };
  gear("teeth", &gear_.teeth, "-", "number of teeth z (both gears)");
  gear("pressure_angle_deg", &gear_.pressure_angle_deg, "deg", "pressure angle alpha0");
  gear("module", &gear_.module, "m", "module m");
  gear("addendum", &gear_.addendum, "m", "addendum ha");
  gear("dedendum", &gear_.dedendum, "m", "dedendum hf");
  P.add("face_width", &gear_.face_width, "m", "face width b (beam width, Hertz contact length) [1e-4, 1]",
        Range::between(1e-4, 1));
  P.add("youngs_modulus", &mat_.youngs_modulus, "Pa", "Young's modulus E [1e8 (polymers), 2e12 (diamond)]",
        Range::between(1e8, 2e12));
  P.add("poisson_ratio", &mat_.poisson_ratio, "-", "Poisson's ratio (thesis table; unused by Euler-Bernoulli beams)",
        Range::between(0, 0.5));
  P.group("loads (Fig. 60; each <= the torque that strains the tooth root by 1 %)");
  P.add("torque_1", &loads_.torque_1, "N m", "first torque", Range::between(1e-3, 1e9));
  P.add("torque_2", &loads_.torque_2, "N m", "second torque", Range::between(1e-3, 1e9));
  P.add("torque_3", &loads_.torque_3, "N m", "third torque: also the deflection figures, max STE, mean stiffness",
        Range::between(1e-3, 1e9));
  const std::string Pmax = std::to_string(max_positions_per_base_pitch);
  P.group("tooth models (P <= " + Pmax + ": the dense 16P-DOF model needs 3 x (16P)^2 doubles, <= 100 MiB)");
  P.add("constant_thickness", &models_.constant_thickness, "m", "tooth thickness of the §7.4 model [1e-5, 1]",
        Range::between(1e-5, 1));
  P.add("first_positions_per_base_pitch", &models_.first_positions_per_base_pitch, "-",
        "positions per base pitch P of the first model (Figs. 46-61; the whole run takes ~10 s at P = 6, ~95 s at 32)",
        Range::between(4, max_positions_per_base_pitch));
  P.add("positions_per_base_pitch", &models_.positions_per_base_pitch, "-",
        "P of the refined model (Figs. 62-64)", Range::between(4, max_positions_per_base_pitch));
  P.add("convergence_max_positions", &models_.convergence_max_positions, "-",
        "largest P of the convergence study (P doubles from positions_per_base_pitch)",
        Range::between(4, max_positions_per_base_pitch));
  P.group("modelling readings (README \"Readings\")");
  P.add("thickness_at", &read_.thickness_at, "-", "element thickness at 0 root-side node, 1 midpoint, 2 tip-side node",
        Range::between(0, 2));
  P.add("hertz_count", &read_.hertz_count, "-", "Palmgren approach added 0 never, 1 per contact, 2 per tooth",
        Range::between(0, 2));
  P.add("two_pair_hertz", &read_.two_pair_hertz, "-", "two pairs: Hertz at 0 F/2, 1 mean at FE forces, 2 consistent split",
        Range::between(0, 2));
  P.add("tooth_force", &read_.tooth_force, "-", "tooth force 0 T/r (thesis), 1 T/rb", Range::between(0, 1));
  P.group("own case (--case own: one STE over the mesh cycle of the gear above)", true);
  P.add("own_torque", &own_.torque, "N m", "torque", Range::between(1e-3, 1e9));
  P.add("own_positions_per_base_pitch", &own_.positions_per_base_pitch, "-", "positions per base pitch P",
        Range::between(4, max_positions_per_base_pitch));
  std::vector<std::string> labels, quick;
  for (const auto& c : kSteCases) {
    labels.push_back(c.label);
    if (c.quick) quick.push_back(c.label);
  }
  study.cases(labels, quick);
  study.check([this](const Selection& s) { check(s); });
}

// Every cross-parameter check, before anything is written: each message names the
// parameter the user set and the values of it that work.
void StaticTransmissionError::check(const Selection& s) const {
  check_gear();
  if (s.kind == Selection::Kind::own) {
    check_positions("own_positions_per_base_pitch", own_.positions_per_base_pitch);
    check_torque("own_torque", own_.torque, false);
    return;
  }
  for (bool set : {true, false})   // the ones the user set first
    for (const MeshModel& mesh : kMeshes)
      if (params_->was_set(mesh.parameter) == set) check_positions(mesh.parameter, models_.*mesh.positions);
  ParameterSet::require(models_.convergence_max_positions >= models_.positions_per_base_pitch,
                        "convergence_max_positions = " + std::to_string(models_.convergence_max_positions) +
                            ": must be >= positions_per_base_pitch = " + std::to_string(models_.positions_per_base_pitch));
  for (std::size_t i = 1; i < kTorques.size(); ++i) {   // blame the one the user set
    const std::size_t j = params_->was_set(kTorques[i - 1].name) && !params_->was_set(kTorques[i].name) ? i - 1 : i;
    const std::size_t other = j == i ? i - 1 : i;
    ParameterSet::require(torque(int(i - 1)) < torque(int(i)),
                          kTorques[j].name + " = " + number(torque(int(j))) + " N m: the torques must increase, need " +
                              kTorques[j].name + (j < other ? " < " : " > ") + kTorques[other].name + " = " +
                              number(torque(int(other))) + " N m");
  }
  check_torque(kTorques.back().name, torque(int(kTorques.size()) - 1), true);   // the largest
}

// The gear must suit the involute beam model (lib involute_tooth_model_problem);
// the message blames the gear parameter the user set (the first in kGearFields).
void StaticTransmissionError::check_gear() const {
  const std::string problem = involute_tooth_model_problem(gear_);
  if (problem.empty()) return;
  const GearField* blamed = &kGearFields.front();
  for (const GearField& f : kGearFields)
    if (params_->was_set(f.name)) {
      blamed = &f;
      break;
    }
  double from = 0, to = 0;
  const bool any = admissible_interval(gear_, blamed->set, blamed->lo, blamed->hi, blamed->integer, &from, &to);
  const std::string head = blamed->name + " = " + number(blamed->get(gear_)) + ": " + problem;
  ParameterSet::require(false, any ? head + "; with the other gear parameters as set, need " + number(from) +
                                         " <= " + blamed->name + " <= " + number(to)
                                   : head + "; no " + blamed->name + " in [" + number(blamed->lo) + ", " +
                                         number(blamed->hi) + "] works with the other gear parameters as set");
}

// P positions per base pitch need n_e = floor(P eps) tooth elements with P < n_e < 2P:
// at least one position with two pairs in contact.
void StaticTransmissionError::check_positions(const std::string& name, int P) const {
  const SteModel m = model(P, false);
  if (m.elements() > P) return;
  int need = P;
  while (need < max_positions_per_base_pitch && model(need, false).elements() <= need) ++need;
  const double eps = path_of_contact(gear_, gear_).contact_ratio;
  ParameterSet::require(false, name + " = " + std::to_string(P) + ": floor(P x contact ratio " + number(eps) +
                                   ") = " + std::to_string(m.elements()) +
                                   " tooth elements leave no position with two pairs in contact; need " + name +
                                   " >= " + std::to_string(need) + " (at most " +
                                   std::to_string(max_positions_per_base_pitch) + ")");
}

// The beams are linear and small-deflection: the root bending strain
// 6 F h / (E b s^2) (cantilever of height h loaded at its tip, s the thinner of the
// involute root thickness and, for the chapter's cases, constant_thickness) must stay
// below 1 % at the largest torque. The message blames the parameter the user set.
void StaticTransmissionError::check_torque(const std::string& name, double T, bool constant_model_too) const {
  const SteModel m = model(models_.positions_per_base_pitch, false);
  const double s_root = tooth_thickness(gear_, gear_.root_radius());
  const bool thin = constant_model_too && models_.constant_thickness < s_root;
  const double s = thin ? models_.constant_thickness : s_root;
  const double h = gear_.tooth_height(), b = gear_.face_width, E = mat_.youngs_modulus;
  const double strain = 6 * m.force(T) * h / (E * b * s * s), over = strain / kMaxRootStrain;
  if (over <= 1) return;
  const std::string at = " at " + name + " = " + number(T) + " N m the tooth-root bending strain 6 F h/(E b s^2) would be " +
                         number(strain) + ", beyond the linear small-deflection beam model (1 %); need ";
  std::string msg = name + " = " + number(T) + " N m:" + at.substr(at.find(" the tooth")) + name + " <= " + number(T / over) + " N m";
  if (!params_->was_set(name)) {
    if (thin && params_->was_set("constant_thickness"))
      msg = "constant_thickness = " + number(s) + " m:" + at + "constant_thickness >= " + number(s * std::sqrt(over)) + " m";
    else if (params_->was_set("youngs_modulus"))
      msg = "youngs_modulus = " + number(E) + " Pa:" + at + "youngs_modulus >= " + number(E * over) + " Pa";
    else if (params_->was_set("face_width"))
      msg = "face_width = " + number(b) + " m:" + at + "face_width >= " + number(b * over) + " m";
  }
  ParameterSet::require(false, msg);
}

SteModel StaticTransmissionError::model(int P, bool constant, const Readings& r) const {
  SteModel m;
  m.gear = gear_;
  m.youngs_modulus = mat_.youngs_modulus;
  m.constant_thickness = constant;
  m.constant_thickness_value = models_.constant_thickness;
  m.positions_per_base_pitch = P;
  m.thickness_at = ThicknessAt(r.thickness_at);
  m.hertz = HertzCount(r.hertz_count);
  m.two_pair_hertz = TwoPairHertz(r.two_pair_hertz);
  m.tooth_force = ToothForce(r.tooth_force);
  return m;
}

const MeshModel& StaticTransmissionError::mesh_model(Mesh mesh) const {
  for (const MeshModel& m : kMeshes)
    if (m.mesh == mesh) return m;
  throw std::logic_error("unknown mesh model");
}

void StaticTransmissionError::run(Run& run) const {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) {
    gear_geometry(run);
    axis_angles(run);
    constant_thickness_checks(run);
    Table index({"figure", "file", "thickness", "constant_thickness_mm", "pairs", "nodes", "torque_N_m", "force_N",
                 "node_of_force", "a_mm"});
    tooth_deflections(run, index);
    exact_elastic_lines(run, index);
    fused_moment(run, index);
    run.write("deflection_cases.csv", index);
    tooth_profile(run);
  }
  ste_cycles(run);
  if (run.whole_chapter() && !run.quick()) {
    readings(run);
    convergence(run);
  }
}

// Step 1: radii, path of contact and contact ratio (thesis §7.6-7.7).
void StaticTransmissionError::gear_geometry(Run& run) const {
  const PathOfContact path = path_of_contact(gear_, gear_);
  const ContactRadii rA = contact_radii(gear_, gear_, 0.0), rE = contact_radii(gear_, gear_, path.AE);
  const std::vector<std::pair<std::string, double>> rows = {
      {"pitch_radius", gear_.pitch_radius()}, {"base_radius", gear_.base_radius()}, {"tip_radius", gear_.tip_radius()},
      {"root_radius", gear_.root_radius()},   {"base_pitch", gear_.base_pitch()},   {"T1C", path.T1C},
      {"AC", path.AC},                        {"CE", path.CE},                      {"AE", path.AE},
      {"driver_radius_at_A", rA.r1},          {"driver_radius_at_E", rE.r1}};
  Table t({"quantity", "value", "unit"});
  for (const auto& [name, v] : rows) t.add_row({name, v, std::string("m")});
  t.add_row({std::string("contact_ratio"), path.contact_ratio, std::string("-")});
  run.write("geometry.csv", t);
  run.key_numbers().add("contact_ratio", path.contact_ratio, "-");
  run.key_numbers().add("AC_mm", path.AC * mm, "mm");
  run.key_numbers().add("CE_mm", path.CE * mm, "mm");
}

// Step 2 (§7.7): angles of the tooth axis with the normal to the path of contact.
void StaticTransmissionError::axis_angles(Run& run) const {
  const PathOfContact path = path_of_contact(gear_, gear_);
  Table t({"variant", "rb_m", "AC_m", "CE_m", "T2C_m", "T2E_m", "beta_deg", "epsilon_deg", "cos_alpha_minus_beta",
           "cos_alpha_plus_epsilon", "force_variation_percent"});
  for (const AngleVariant& v : kAngleVariants) {
    const ToothAxisAngles a = tooth_axis_angles(gear_, path, v.formula, v.round_like_thesis);
    t.add_row({v.name, a.rb, a.AC, a.CE, a.T2C, a.T2E, a.beta * kDeg, a.epsilon * kDeg, a.cos_alpha_minus_beta,
               a.cos_alpha_plus_epsilon, a.force_variation * 100});
    for (const AngleKey& k : v.keys) run.key_numbers().add(k.key, a.*k.value * k.scale, k.unit);
  }
  run.write("tooth_axis_angles.csv", t);
}

// Step 3 (§7.4, Figs. 48-56): constant thickness, first model, torque_3: every
// position against the exact beam formulas, and the reactions {R_V} of the two-pair cases.
void StaticTransmissionError::constant_thickness_checks(Run& run) const {
  const SteModel m = model(models_.first_positions_per_base_pitch, true);
  const ToothBeam tooth = tooth_beam(m);
  const double F = m.force(loads_.torque_3), EI = tooth.EI[0], ne = m.elements();
  Table reactions({"pair_nodes", "X_um", "dof", "reaction", "unit"});
  double worst_single = 0, worst_two = 0;
  KeyNumbers& key = run.key_numbers();
  const std::vector<MeshPosition> cycle = mesh_positions(m);
  const MeshPosition *first_one = nth_position(cycle, 1, 0), *first_two = nth_position(cycle, 2, 0);
  for (const MeshPosition& p : cycle) {
    if (p.pairs == 1) {
      const SinglePairSolve s = solve_single_pair(tooth, p.kA1, p.kA2, F);
      const double a1 = tooth.x[p.kA1], a2 = tooth.x[p.kA2];   // exact: F (a1^3 + a2^3) / (3 EI)
      const double exact = F * (a1 * a1 * a1 + a2 * a2 * a2) / (3 * EI);
      worst_single = std::max(worst_single, std::fabs(s.ste_elastic - exact) / exact);
      if (&p == first_one) key.add("ste_single_pair_const_um", s.ste_elastic * um, "um");
      continue;
    }
    const TwoPairSolve s = solve_two_pairs(tooth, p.kA1, p.kA2, p.kB1, p.kB2, F);
    // Each fused pair is a clamped-guided beam of n_e + 1 elements carrying F/2: X = (F/2) L^3 / (12 EI).
    const double L = tooth.x[1] * (ne + 1), X_exact = 0.5 * F * L * L * L / (12 * EI);
    worst_two = std::max(worst_two, std::fabs(s.X - X_exact) / X_exact);
    // The six constrained DOFs of {R_V}: rotation of the guided roots (beams 1, 3),
    // translation and rotation of the clamped roots (beams 2, 4).
    const BeamModel& b = s.model;
    const int dofs[6] = {BeamModel::theta_dof(b.node(0, 0)), BeamModel::w_dof(b.node(1, 0)),
                         BeamModel::theta_dof(b.node(1, 0)), BeamModel::theta_dof(b.node(2, 0)),
                         BeamModel::w_dof(b.node(3, 0)),     BeamModel::theta_dof(b.node(3, 0))};
    const std::string label = pair_label(b, 0, p.kA1, 1, p.kA2) + "_" + pair_label(b, 2, p.kB1, 3, p.kB2);
    for (int d : dofs)
      reactions.add_row({label, s.X * um, std::string(d % 2 ? "theta_node_" : "w_node_") + std::to_string(d / 2 + 1),
                         s.solution.reactions[d], std::string(d % 2 ? "N m" : "N")});
    if (&p == first_two) {
      key.add("ste_two_pairs_const_um", s.X * um, "um");
      key.add("reaction_moment_guided_root_N_m", s.solution.reactions[dofs[0]], "N m");
      key.add("reaction_force_clamped_root_N", s.solution.reactions[dofs[1]], "N");
      key.add("reaction_moment_clamped_root_N_m", s.solution.reactions[dofs[2]], "N m");
    }
  }
  key.add("ste_single_pair_const_fe_vs_exact_rel", worst_single, "-");
  key.add("ste_two_pairs_const_fe_vs_exact_rel", worst_two, "-");
  run.write("reactions_const_two_pairs.csv", reactions);
}

// Step 4 (Figs. 48-49, 52-55, 58-59): nodal deflections of the positions of kDeflections.
void StaticTransmissionError::tooth_deflections(Run& run, Table& index) const {
  for (const DeflectionCase& dc : kDeflections) {
    const SteModel m = model(models_.first_positions_per_base_pitch, dc.constant);
    const std::vector<MeshPosition> cycle = mesh_positions(m);
    const MeshPosition* p = nth_position(cycle, dc.pairs, dc.nth);
    if (!p) {
      run.say("Fig. " + dc.figure + ": the first model has no such position (first_positions_per_base_pitch)");
      continue;
    }
    const ToothBeam tooth = tooth_beam(m);
    const double F = m.force(loads_.torque_3);
    const Solved s = solve_position(tooth, *p, F);
    const std::string file = "deflection_fig" + dc.figure + ".csv";
    run.write(file, deflection_table(s.model, s.solution, tooth));
    index.add_row({dc.figure, file, std::string(dc.constant ? "constant" : "involute"),
                   dc.constant ? Table::Cell(models_.constant_thickness * mm) : Table::Cell(std::string()),
                   long(dc.pairs), s.nodes, loads_.torque_3, F, std::string(), std::string()});
  }
}

// Step 5 (Figs. 50-51): the exact elastic line of a cantilever with the force on
// the driving contact node of a one-pair position, and the FE nodes of that beam.
void StaticTransmissionError::exact_elastic_lines(Run& run, Table& index) const {
  const SteModel m = model(models_.first_positions_per_base_pitch, true);
  const ToothBeam tooth = tooth_beam(m);
  const std::vector<MeshPosition> cycle = mesh_positions(m);
  const double F = m.force(loads_.torque_3), EI = tooth.EI[0], Ltot = tooth.x.back();
  for (const DeflectionCase& dc : kElasticLines) {
    const MeshPosition* p = nth_position(cycle, dc.pairs, dc.nth);
    if (!p) continue;
    const Solved s = solve_position(tooth, *p, F);
    const double a = tooth.x[p->kA1];
    Table t({"kind", "x_mm", "y_um"});
    for (int i = 0; i <= 200; ++i) {
      const double x = Ltot * i / 200.0;
      t.add_row({std::string("exact"), x * mm, -cantilever_point_load_deflection(F, a, x, EI) * um});
    }
    for (int i = 0; i < s.model.beam_nodes(0); ++i)
      t.add_row({std::string("fe"), tooth.x[i] * mm, s.solution.Q[BeamModel::w_dof(s.model.node(0, i))] * um});
    const std::string file = "elastic_line_fig" + dc.figure + ".csv";
    run.write(file, t);
    index.add_row({dc.figure, file, std::string("constant"), models_.constant_thickness * mm, 1L, s.nodes,
                   loads_.torque_3, F, long(s.model.node(0, p->kA1) + 1), a * mm});
  }
}

// Step 6 (Fig. 56): bending moment along the fused beam of the first two-pair position.
void StaticTransmissionError::fused_moment(Run& run, Table& index) const {
  const SteModel m = model(models_.first_positions_per_base_pitch, kMomentCase.constant);
  const ToothBeam tooth = tooth_beam(m);
  const std::vector<MeshPosition> cycle = mesh_positions(m);
  const MeshPosition* p = nth_position(cycle, kMomentCase.pairs, kMomentCase.nth);
  if (!p) return;
  const double F = m.force(loads_.torque_3);
  const TwoPairSolve s = solve_two_pairs(tooth, p->kA1, p->kA2, p->kB1, p->kB2, F);
  const std::string file = "moment_fig" + kMomentCase.figure + ".csv";
  run.write(file, fused_moment_table(s, p->kA1, p->kA2));
  index.add_row({kMomentCase.figure, file, std::string("constant"), models_.constant_thickness * mm, 2L,
                 pair_label(s.model, 0, p->kA1, 1, p->kA2), loads_.torque_3, F, std::string(), std::string()});
}

// Step 7 (Fig. 57): the involute thickness s(r) and the stepped beams of both models.
void StaticTransmissionError::tooth_profile(Run& run) const {
  Table t({"r_mm", "height_mm", "thickness_mm"});
  const double rf = gear_.root_radius(), ra = gear_.tip_radius();
  for (int i = 0; i <= 200; ++i) {
    const double r = rf + (ra - rf) * i / 200.0;
    t.add_row({r * mm, (r - rf) * mm, tooth_thickness(gear_, r) * mm});
  }
  run.write("tooth_profile.csv", t);
  for (const MeshModel& mesh : kMeshes) {
    const ToothBeam tb = tooth_beam(model(models_.*mesh.positions, false));
    Table b({"element", "x_start_mm", "x_end_mm", "thickness_mm", "EI_N_m2"});
    for (std::size_t e = 0; e < tb.EI.size(); ++e)
      b.add_row({long(e + 1), tb.x[e] * mm, tb.x[e + 1] * mm, tb.s[e] * mm, tb.EI[e]});
    run.write("beam_thickness_" + mesh.name + ".csv", b);
  }
}

// Step 8 (Figs. 60-64): the STE over one mesh cycle for each case of kSteCases.
void StaticTransmissionError::ste_cycles(Run& run) const {
  Table index({"label", "figure", "model", "positions_per_base_pitch", "tooth_elements", "torque_name", "torque_N_m",
               "force_N", "file", "fourier_file", "ste_max_um", "ste_min_um", "mean_stiffness_MN_per_m"});
  double worst = 0;
  for (const SteCase& cs : kSteCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const MeshModel& mesh = mesh_model(cs.mesh);
    const SteModel m = model(models_.*mesh.positions, false);
    const double T = torque(cs.torque), F = m.force(T);
    const std::vector<MeshPosition> c = run.timed("ste " + cs.label, [&] { return ste_over_mesh_cycle(m, T); });
    const std::string file = "ste_" + cs.label + ".csv", fourier = "ste_fourier_" + cs.label + ".csv";
    run.write(file, cycle_table(c, F));
    run.write(fourier, fourier_table(c));
    worst = std::max(worst, max_rel_fe_vs_closed_form(c));
    const double k = mean_mesh_stiffness(c, F);
    index.add_row({cs.label, cs.figure, mesh.name, long(m.positions_per_base_pitch), long(m.elements()),
                   kTorques[cs.torque].name, T, F, file, fourier, max_ste(c) * um, min_ste(c) * um, k / 1e6});
    run.say(cs.label + ": " + std::to_string(m.elements()) + " elements, T = " + number(T) + " N m, max STE " +
            number(max_ste(c) * um) + " um, mean F/STE " + number(k / 1e6) + " MN/m");
    measure(run, cs, m, c);
  }
  run.write("cases.csv", index);
  run.key_numbers().add("ste_fe_vs_closed_form_max_rel", worst, "-");
}

// The key numbers and extra tables a case of kSteCases asks for.
void StaticTransmissionError::measure(Run& run, const SteCase& cs, const SteModel& m,
                                      const std::vector<MeshPosition>& c) const {
  const double F = m.force(torque(cs.torque));
  for (const KeyOf& k : cs.measures) switch (k.what) {
      case Measure::max_ste: run.key_numbers().add(k.key, max_ste(c) * um, "um"); break;
      case Measure::mean_stiffness: run.key_numbers().add(k.key, mean_mesh_stiffness(c, F) / 1e6, "MN/m"); break;
      case Measure::mesh_scheme: mesh_scheme(run, m, c); break;
      case Measure::iso6336: iso6336_comparison(run, m, c, k); break;
    }
}

// Fig. 62: the contact nodes at each position (thesis global numbers: beams of n_e + 1 nodes).
void StaticTransmissionError::mesh_scheme(Run& run, const SteModel& m, const std::vector<MeshPosition>& c) const {
  Table t({"position", "phase", "pairs_in_contact", "driving_node_A", "driven_node_A", "driving_node_B",
           "driven_node_B", "tooth_elements", "positions_per_base_pitch"});
  const int ne = m.elements(), nn = ne + 1;
  const Table::Cell none = std::string();
  for (std::size_t j = 0; j < c.size(); ++j) {
    const MeshPosition& q = c[j];
    t.add_row({long(j + 1), q.phase, long(q.pairs), long(q.kA1 + 1), long(nn + q.kA2 + 1),
               q.pairs == 2 ? Table::Cell(long(2 * nn + q.kB1 + 1)) : none,
               q.pairs == 2 ? Table::Cell(long(3 * nn + q.kB2 + 1)) : none, long(ne), long(m.positions_per_base_pitch)});
  }
  run.write("mesh_scheme.csv", t);
}

// The beam model's mean stiffness beside ISO 6336-1 Method B at the same line load.
void StaticTransmissionError::iso6336_comparison(Run& run, const SteModel& m, const std::vector<MeshPosition>& c,
                                                 const KeyOf& k) const {
  const double F = m.force(loads_.torque_3), b = gear_.face_width;
  const double eps = path_of_contact(gear_, gear_).contact_ratio;
  const Iso6336Stiffness iso = iso6336_mesh_stiffness(gear_.teeth, gear_.teeth, 0.0, 0.0, gear_.pressure_angle_deg,
                                                      gear_.dedendum / gear_.module, eps, b, F / (b * mm));
  double mean_ste = 0;
  for (const auto& q : c) mean_ste += q.ste / double(c.size());
  Table t({"quantity", "value", "unit"});
  const std::vector<std::tuple<std::string, double, std::string>> rows = {
      {"mean_F_over_STE", mean_mesh_stiffness(c, F), "N/m"}, {"F_over_mean_STE", F / mean_ste, "N/m"},
      {"iso6336_q_prime", iso.q_prime, "mm um/N"},          {"iso6336_c_th", iso.c_th, "N/(mm um)"},
      {"iso6336_C_B", iso.C_B, "-"},                         {"iso6336_c_single", iso.c_single_total, "N/m"},
      {"iso6336_c_gamma_alpha", iso.c_gamma_alpha_total, "N/m"}};
  for (const auto& [name, v, unit] : rows) t.add_row({name, v, unit});
  run.write("stiffness.csv", t);
  run.key_numbers().add(k.key, iso.c_gamma_alpha_total / 1e6, "MN/m");
}

// Step 9: every combination of the open modelling choices, both models, all torques.
void StaticTransmissionError::readings(Run& run) const {
  Table t({"thickness_at", "hertz_count", "two_pair_hertz", "tooth_force", "positions_per_base_pitch",
           "tooth_elements", "ste_max_T1_um", "ste_max_T2_um", "ste_max_T3_um", "mean_stiffness_T3_MN_per_m"});
  std::vector<Readings> all;
  for (int th = 0; th <= 2; ++th)
    for (int hc = 1; hc <= 2; ++hc)
      for (int tp = 0; tp <= 2; ++tp)
        for (int tf = 0; tf <= 1; ++tf) all.push_back({th, hc, tp, tf});
  run.timed("readings", [&] {
    for (const MeshModel& mesh : kMeshes)
      for (const Readings& r : all) {
        const SteModel m = model(models_.*mesh.positions, false, r);
        std::vector<Table::Cell> row = {long(r.thickness_at), long(r.hertz_count), long(r.two_pair_hertz),
                                        long(r.tooth_force), long(m.positions_per_base_pitch), long(m.elements())};
        std::vector<MeshPosition> c;
        for (std::size_t i = 0; i < kTorques.size(); ++i) {
          c = ste_over_mesh_cycle(m, torque(int(i)));
          row.emplace_back(std::in_place_type<double>, max_ste(c) * um);
        }
        row.emplace_back(std::in_place_type<double>, mean_mesh_stiffness(c, m.force(loads_.torque_3)) / 1e6);   // c: the last torque, torque_3
        t.add_row(row);
      }
  });
  run.write("readings.csv", t);
}

// Step 10: convergence in the number of positions per base pitch (P doubles).
void StaticTransmissionError::convergence(Run& run) const {
  Table t({"positions_per_base_pitch", "tooth_elements", "dofs", "ste_max_T3_um", "ste_min_T3_um",
           "mean_stiffness_T3_MN_per_m", "harmonic_1_um", "harmonic_2_um", "harmonic_3_um"});
  for (int P = models_.positions_per_base_pitch; P <= models_.convergence_max_positions; P *= 2) {
    const SteModel m = model(P, false);
    const auto c = run.timed("convergence P=" + std::to_string(P), [&] { return ste_over_mesh_cycle(m, loads_.torque_3); });
    int H = 0;
    const Eigen::VectorXd a = ste_fourier(c, &H);
    std::vector<Table::Cell> row = {long(P), long(m.elements()), long(8 * (m.elements() + 1)), max_ste(c) * um,
                                    min_ste(c) * um, mean_mesh_stiffness(c, m.force(loads_.torque_3)) / 1e6};
    for (int k = 1; k <= 3; ++k) row.push_back(k <= H ? Table::Cell(amplitude(a, k) * um) : Table::Cell(std::string()));
    t.add_row(row);
  }
  run.write("convergence.csv", t);
}

// --case own: one STE over the mesh cycle of the gear as set, at own_torque.
void StaticTransmissionError::own_case(Run& run) const {
  gear_geometry(run);
  const SteModel m = model(own_.positions_per_base_pitch, false);
  const double F = m.force(own_.torque);
  const auto c = run.timed("ste own", [&] { return ste_over_mesh_cycle(m, own_.torque); });
  run.write("ste.csv", cycle_table(c, F));
  run.write("ste_fourier.csv", fourier_table(c));
  KeyNumbers& key = run.key_numbers();
  key.add("tooth_elements", double(m.elements()), "-");
  key.add("ste_max_um", max_ste(c) * um, "um");
  key.add("ste_min_um", min_ste(c) * um, "um");
  key.add("mean_stiffness_MN_per_m", mean_mesh_stiffness(c, F) / 1e6, "MN/m");
  key.add("ste_fe_vs_closed_form_max_rel", max_rel_fe_vs_closed_form(c), "-");
  run.say("own: " + std::to_string(m.elements()) + " elements, max STE " + number(max_ste(c) * um) + " um");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch07_ste",
              "ch07_ste: static transmission error of a spur-gear pair from a beam FE tooth model plus Hertzian\n"
              "  contact (thesis ch. 7, Figs. 48-64): STE = elastic deflections + Palmgren approach, k = mean F/STE");
  StaticTransmissionError chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
