// ===========================================================================
// ch02_methods: the method, speed against accuracy, and where each method fails
// (thesis ch. 2: harmonic balance §2.1, continuation §2.2, contact and AFT §2.3)
// ===========================================================================
//
//     M x'' + C x' + K x + n max( kc (g(theta) + n' x), 0 ) = f0 + f cos(theta),  theta = omega t
//
// Three scenes (the cases of this chapter):
//   mass_wall   thesis ch. 3, g = -0.6 m, Fa = 0.01 N, omega = 0.5 ... 2 rad/s (contact, two folds)
//   nlvib_ex03  NLvib's example 03: two unit masses, chain springs [0 1 1], damping 0.03 K,
//               0.1 cos on DOF 2, spring 100 behind a gap of 1 on DOF 1, omega = 0.5 ... 0.8
//   gear_300Nm  thesis ch. 8: the 1-DOF gear mesh at 300 N m driven by its STE (5 harmonics)
// Each is solved on a fixed frequency grid by harmonic balance (exact contact, H = 1 ... 60;
// sampled AFT, N = 2 ... 32 (2H+1)) and by direct time integration stepped up and down
// (GSL rk8pd and rkf45, tolerance 1e-3 ... 1e-11), each timed in CPU seconds and compared
// with a reference (HB at high H for which solutions exist and are stable, their
// values from tight GSL time integration started on them, the two cross-checked). Then one study
// per failure of a method. The steps, in order (README of this chapter): references,
// accuracy_against_cost, speed_ups, cost_growth, natural_vs_arclength, hill_vs_floquet,
// unscaled_newton, grazing.
//
// Sample runs:
//   build/bin/ch02_methods                            every figure's data (< 1 min)
//   build/bin/ch02_methods --case quick --out /tmp/q  the regression subset (seconds)
//   build/bin/ch02_methods --case nlvib_ex03          one scene's accuracy/cost chart
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/hb/exact_orbit.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/experiments/method_comparison.hpp"
#include "gearhb/experiments/parametric.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/stability.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern ---------------------------------------
struct Comparison {
  int grid_points = 16;        // frequencies of the comparison grid per scene
  double ti_ref_tol = 1e-12;   // GSL tolerance of the reference time integration
  int max_periods = 1500;      // per frequency of a time-integration sweep
};
struct Charts {
  int a_points = 61, q_points = 26;   // Mathieu / Meissner stability charts
  int newton_frequencies = 40;        // unscaled-Newton study (gear scene)
  int grazing_points = 31;            // grazing study (mass against wall)
};
struct GearSettings {
  double torque = 300.0;   // [N m]
  int ste_harmonics = 5;   // STE components kept (thesis §8.2)
  double zeta = 0.08;      // mesh damping ratio
};

class Methods;
using ModelBuilder = HarmonicBalance (Methods::*)(int H, int N, ContactQuadrature q) const;

// A scene: one model, its frequency range and plotted coordinate.
struct Scene {
  std::string label;
  std::string what;
  ModelBuilder model;
  double omega_min, omega_max;   // [rad/s] the whole curve
  double grid_min, grid_max;     // [rad/s] the comparison grid (where contact acts)
  double ds_max;                 // arc-length step cap (scaled)
  int H_ref;                     // harmonics of the reference HB branch
  int max_H;                     // largest H of the accuracy/cost settings run on it
  std::vector<double> q;         // plotted coordinate q' x
  bool quick;
};

// A method and its accuracy knob.
enum class Family { hb_exact, hb_sampled, hb_stepped, ti_rk8pd, ti_rkf45, hb_corrected };
struct Setting {
  Family family;
  int H;             // HB harmonics
  int N_per;         // sampled AFT: N = N_per (2H+1)
  double tol;        // time integration: GSL tolerance and periodicity tolerance
  bool quick;
  bool curve;        // write the whole curve / both sweeps (failure figures)
};
const char* family_name(Family f) {
  const char* names[] = {"hb_exact", "hb_sampled", "hb_stepped", "ti_rk8pd", "ti_rkf45", "hb_corrected"};
  return names[int(f)];
}

const std::vector<Setting> kSettings = {
    {Family::hb_exact, 1, 0, 0, true, true},     {Family::hb_exact, 2, 0, 0, false, false},
    {Family::hb_exact, 3, 0, 0, true, true},     {Family::hb_exact, 5, 0, 0, false, true},
    {Family::hb_exact, 8, 0, 0, true, false},    {Family::hb_exact, 10, 0, 0, false, true},
    {Family::hb_exact, 12, 0, 0, false, false},
    {Family::hb_exact, 20, 0, 0, true, true},    {Family::hb_exact, 30, 0, 0, false, false},
    {Family::hb_exact, 40, 0, 0, false, false},
    {Family::hb_sampled, 10, 2, 0, true, true},  {Family::hb_sampled, 10, 4, 0, false, true},
    {Family::hb_sampled, 10, 8, 0, false, true}, {Family::hb_sampled, 10, 16, 0, false, false},
    {Family::hb_sampled, 10, 32, 0, false, true},
    {Family::hb_stepped, 3, 0, 0, true, false},  {Family::hb_stepped, 5, 0, 0, false, false},
    {Family::hb_stepped, 8, 0, 0, true, false},  {Family::hb_stepped, 12, 0, 0, false, false},
    {Family::hb_stepped, 20, 0, 0, true, false}, {Family::hb_stepped, 30, 0, 0, false, false},
    {Family::hb_stepped, 40, 0, 0, false, false},
    {Family::ti_rk8pd, 0, 0, 1e-3, true, false}, {Family::ti_rk8pd, 0, 0, 1e-5, true, false},
    {Family::ti_rk8pd, 0, 0, 1e-7, true, true},  {Family::ti_rk8pd, 0, 0, 1e-9, false, false},
    {Family::ti_rkf45, 0, 0, 1e-3, false, false}, {Family::ti_rkf45, 0, 0, 1e-5, false, false},
    {Family::hb_corrected, 1, 0, 0, false, false}, {Family::hb_corrected, 3, 0, 0, true, false},
    {Family::hb_corrected, 5, 0, 0, false, false}, {Family::hb_corrected, 8, 0, 0, true, false},
    {Family::hb_corrected, 12, 0, 0, false, false}, {Family::hb_corrected, 20, 0, 0, false, false},
};
bool hb_setting(Family f) { return f == Family::hb_exact || f == Family::hb_stepped || f == Family::hb_corrected; }

// What one method setting produced on a scene's grid.
struct GridRun {
  GridSolutions grid;
  double cpu_s = 0.0;
  FrequencyCurve curve;                                 // harmonic balance
  double cpu_correction_s = 0.0;                        // of cpu_s: the exact-flow correction
  int corrected = 0, not_corrected = 0;                 // grid solutions
  std::vector<std::vector<SteppedSweepPoint>> sweeps;   // time integration: up, down
};

// One row of accuracy_cost.csv.
struct CostRow {
  std::string scene;
  Family family;
  std::string setting;
  double cpu_s, error, error_h1;
  int missed, compared;
  double cpu_correction_s = NAN;   // hb_corrected: the correction's share of cpu_s
  int not_corrected = 0;           // hb_corrected: grid solutions whose correction failed
  int corrected = 0;
};

// A scene's reference: the grid solutions and their checks.
struct Reference {
  std::vector<double> omegas;
  GridSolutions grid;
  Scaling scaling;
};

std::string setting_label(const Setting& s) {
  char buf[64];
  if (hb_setting(s.family)) std::snprintf(buf, sizeof buf, "H=%d", s.H);
  else if (s.family == Family::hb_sampled) std::snprintf(buf, sizeof buf, "H=%d N=%d(2H+1)", s.H, s.N_per);
  else std::snprintf(buf, sizeof buf, "tol=%.0e", s.tol);
  return buf;
}
std::string file_tag(const Setting& s) {
  char buf[64];
  if (hb_setting(s.family)) std::snprintf(buf, sizeof buf, "%s_H%d", family_name(s.family), s.H);
  else if (s.family == Family::hb_sampled) std::snprintf(buf, sizeof buf, "hb_sampled_H%d_N%d", s.H, s.N_per);
  else std::snprintf(buf, sizeof buf, "%s_tol%.0e", family_name(s.family), s.tol);
  return buf;
}
std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}
VectorXd vec(const std::vector<double>& v) { return Eigen::Map<const VectorXd>(v.data(), Eigen::Index(v.size())); }

class Methods {
 public:
  explicit Methods(Study& study);
  void run(Run& run);

  HarmonicBalance mass_wall(int H, int N, ContactQuadrature q) const;
  HarmonicBalance nlvib_ex03(int H, int N, ContactQuadrature q) const;
  HarmonicBalance gear(int H, int N, ContactQuadrature q) const;
  HarmonicBalance wall(double F, int H, int N, ContactQuadrature q) const;   // ch. 3, g = -0.6 m
  // The method families, each timed on a scene's grid (kRunners).
  GridRun harmonic_balance(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const;
  GridRun harmonic_balance_stepped(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const;
  GridRun harmonic_balance_corrected(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const;
  GridRun time_integration(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const;

 private:
  Comparison cmp_;
  Charts charts_;
  GearSettings gear_;
  DteGear mesh_;   // the gear scene's model (STE of ch. 7 at gear_.torque)

  std::vector<double> grid(const Scene& sc) const;
  SweepOptions hb_sweep(const Scene& sc) const;
  Reference reference(Run& run, const Scene& sc) const;
  Reference time_integration_reference(Run& run, const Scene& sc, Reference ref) const;
  void write_curves(Run& run, const Scene& sc, const Setting& s, const GridRun& g) const;
  void accuracy_against_cost(Run& run, const Scene& sc, const Reference& ref, std::vector<CostRow>& rows) const;
  void speed_ups(Run& run, const std::vector<CostRow>& rows) const;
  void convergence(Run& run, const std::vector<CostRow>& rows) const;
  void cost_growth(Run& run) const;
  void natural_vs_arclength(Run& run) const;
  void hill_vs_floquet(Run& run) const;
  void unscaled_newton(Run& run) const;
  void grazing(Run& run) const;
};


// The scenes (cases of this chapter).
const std::vector<Scene> kScenes = {
    {"mass_wall", "thesis ch. 3, g = -0.6 m, F = 0.01 N", &Methods::mass_wall, 0.5, 2.0, 0.9, 1.2, 0.02, 100, 40, {1.0}, true},
    {"nlvib_ex03", "NLvib example 03, x1", &Methods::nlvib_ex03, 0.5, 0.8, 0.5, 0.8, 0.02, 30, 30, {1.0, 0.0}, false},
    {"gear_300Nm", "thesis ch. 8 gear at 300 N m, DTE", &Methods::gear, 2 * M_PI * 300, 2 * M_PI * 5000,
     2 * M_PI * 2000, 2 * M_PI * 3600, 0.05, 100, 40, {1.0}, false},
};

Methods::Methods(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("accuracy against cost");
  P.add("grid_points", &cmp_.grid_points, "-", "frequencies of the comparison grid per scene", Range::between(3, 400));
  P.add("ti_ref_tol", &cmp_.ti_ref_tol, "-", "GSL tolerance of the reference time integration", Range::between(1e-14, 1e-6));
  P.add("max_periods", &cmp_.max_periods, "-", "periods per frequency of a time-integration sweep", Range::between(10, 1000000));
  P.group("failure studies");
  P.add("a_points", &charts_.a_points, "-", "Mathieu/Meissner chart: values of a", Range::between(3, 2000));
  P.add("q_points", &charts_.q_points, "-", "Mathieu/Meissner chart: values of q (b)", Range::between(3, 2000));
  P.add("newton_frequencies", &charts_.newton_frequencies, "-", "unscaled Newton: frequencies tried", Range::between(2, 10000));
  P.add("grazing_points", &charts_.grazing_points, "-", "grazing study: force amplitudes", Range::between(3, 10000));
  P.group("gear scene (thesis ch. 8)");
  P.add("torque", &gear_.torque, "N m", "transmitted torque", Range::between(10.0, 1000.0));
  P.add("ste_harmonics", &gear_.ste_harmonics, "-", "STE harmonics kept in the model", Range::between(1, 20));
  P.add("zeta", &gear_.zeta, "-", "mesh damping ratio", Range::between(1e-3, 1.0));
  register_cases(study, kScenes);
}

void Methods::run(Run& run) {
  const SteModel thesis_gear;
  const std::vector<double> e = ste_values(ste_continuous(thesis_gear, gear_.torque, 64));
  const double r = thesis_gear.gear.pitch_radius();
  mesh_.F0 = gear_.torque / r;
  mesh_.me = equivalent_mass(0.0158, 0.0158, r, r);
  mesh_.kc = mean_stiffness(e, mesh_.F0);
  mesh_.c = mesh_damping(gear_.zeta, mesh_.kc, mesh_.me);
  mesh_.ste = periodic_fourier(e, gear_.ste_harmonics);
  std::vector<CostRow> rows;
  for (const auto& sc : kScenes) {
    if (!run.wants(sc.label, sc.quick)) continue;
    const Reference ref = run.timed("reference " + sc.label, [&] {
      return time_integration_reference(run, sc, reference(run, sc));
    });
    accuracy_against_cost(run, sc, ref, rows);
  }
  speed_ups(run, rows);
  convergence(run, rows);
  if (!run.whole_chapter()) return;
  run.timed("cost growth", [&] { cost_growth(run); return 0; });
  run.timed("natural vs arc length", [&] { natural_vs_arclength(run); return 0; });
  run.timed("hill vs floquet", [&] { hill_vs_floquet(run); return 0; });
  run.timed("unscaled newton", [&] { unscaled_newton(run); return 0; });
  run.timed("grazing", [&] { grazing(run); return 0; });
}

// --- the three models ---------------------------------------------------------
HarmonicBalance Methods::mass_wall(int H, int N, ContactQuadrature q) const { return wall(0.01, H, N, q); }

HarmonicBalance Methods::nlvib_ex03(int H, int N, ContactQuadrature q) const {
  MatrixXd K(2, 2);
  K << 1, -1, -1, 2;
  LinearSystem sys{MatrixXd::Identity(2, 2), 0.03 * K, K};
  UnilateralContact spring{vec({1.0, 0.0}), 100.0, -1.0, {}};
  Excitation f{VectorXd::Zero(2), vec({0.0, 0.1}), VectorXd::Zero(2)};
  return HarmonicBalance(sys, {spring}, f, H, N, q);
}

HarmonicBalance Methods::gear(int H, int N, ContactQuadrature q) const {
  return dte_harmonic_balance(mesh_, H, N, q);
}

// --- step 1: the reference of a scene ------------------------------------------
std::vector<double> Methods::grid(const Scene& sc) const {
  std::vector<double> omegas;
  for (int i = 0; i < cmp_.grid_points; ++i)
    omegas.push_back(sc.grid_min + (sc.grid_max - sc.grid_min) * (i + 0.5) / cmp_.grid_points);
  return omegas;
}

SweepOptions Methods::hb_sweep(const Scene& sc) const {
  SweepOptions o;
  o.omega_min = sc.omega_min;
  o.omega_max = sc.omega_max;
  o.stability = StabilityMethod::none;
  o.locate_bifurcations = false;
  o.continuation.ds_max = sc.ds_max;
  return o;
}

// HB at the scene's H_ref with exact contact over the whole range, its solutions
// on the grid, each with the Floquet stability of its corrected orbit (the
// trusted label): which solutions exist and which are stable.
Reference Methods::reference(Run& run, const Scene& sc) const {
  const HarmonicBalance hb = (this->*sc.model)(sc.H_ref, 0, ContactQuadrature::exact);
  const FrequencyCurve c = require_complete(sweep_frequency(hb, hb_sweep(sc), sc.label + " reference"), sc.label);
  Reference ref;
  ref.omegas = grid(sc);
  ref.scaling = c.scaling;
  ref.grid = branch_on_grid(hb, c.branch, c.scaling, ref.omegas, vec(sc.q), StabilityMethod::floquet).solutions;
  long stable = 0;
  for (const auto& at : ref.grid)
    for (const auto& s : at) stable += s.stable;
  run.say(sc.label + ": reference HB H = " + std::to_string(sc.H_ref) + ", " + c.branch.summary() + ", " +
          std::to_string(stable) + " stable grid solutions");
  return ref;
}

// The values of the reference: GSL rk8pd at ti_ref_tol started on every stable HB
// solution and integrated until the state repeats to 10 ti_ref_tol. Checked two
// ways: against the same integration at 10x the tolerance (the error of the
// reference itself) and against HB at H_ref (HB's truncation error, or a bound on
// both where they agree).
Reference Methods::time_integration_reference(Run& run, const Scene& sc, Reference ref) const {
  const HarmonicBalance hb = (this->*sc.model)(sc.H_ref, 0, ContactQuadrature::exact);
  TimeIntegrationOptions tight, looser;
  tight.rel_tol = tight.abs_tol = cmp_.ti_ref_tol;
  tight.periodicity_tol = 10 * cmp_.ti_ref_tol;
  looser.rel_tol = looser.abs_tol = 10 * cmp_.ti_ref_tol;
  looser.periodicity_tol = 100 * cmp_.ti_ref_tol;
  Table t({"omega", "x_max_hb", "x_max_ti", "x_max_ti_looser", "x_h1_hb", "x_h1_ti", "periods"});
  double hb_diff = 0.0, self_diff = 0.0;
  for (std::size_t i = 0; i < ref.omegas.size(); ++i)
    for (auto& s : ref.grid[i]) {
      if (!s.stable) continue;
      VectorXd x0, v0;
      hb_initial_state(hb, s.X, ref.omegas[i], x0, v0);
      const SteppedSweepPoint p = stepped_sweep(hb, {ref.omegas[i]}, vec(sc.q), tight, x0, v0).front();
      const SteppedSweepPoint l = stepped_sweep(hb, {ref.omegas[i]}, vec(sc.q), looser, x0, v0).front();
      if (!p.periodic || !l.periodic)
        throw std::runtime_error(sc.label + ": reference time integration not periodic at omega = " +
                                 std::to_string(ref.omegas[i]) + " after " + std::to_string(p.periods) + " periods");
      hb_diff = std::max(hb_diff, std::fabs(p.x_max - s.x_max) / std::fabs(p.x_max));
      self_diff = std::max(self_diff, std::fabs(p.x_max - l.x_max) / std::fabs(p.x_max));
      t.add_row({ref.omegas[i], s.x_max, p.x_max, l.x_max, s.x_h1, p.x_h1, long(p.periods)});
      s.x_max = p.x_max;
      s.x_h1 = p.x_h1;
    }
  run.write("reference_" + sc.label + ".csv", t);
  KeyNumbers& key = run.key_numbers();
  key.add("ref_ti_self_x_max_" + sc.label, self_diff, "-");
  key.add("ref_hb_vs_ti_x_max_" + sc.label, hb_diff, "-");
  key.add("ref_stable_points_" + sc.label, double(t.rows()), "-");
  run.say(sc.label + ": reference rk8pd tol " + sci(cmp_.ti_ref_tol) + " vs 10x looser: " + sci(self_diff) +
          "; HB H = " + std::to_string(sc.H_ref) + " vs it: " + sci(hb_diff));
  return ref;
}

// --- step 2: every method setting on the scene's grid, timed ---------------------
GridRun Methods::harmonic_balance(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const {
  const ContactQuadrature quad = s.family == Family::hb_sampled ? ContactQuadrature::sampled : ContactQuadrature::exact;
  const HarmonicBalance hb = (this->*sc.model)(s.H, s.N_per * (2 * s.H + 1), quad);
  GridRun g;
  const double t0 = cpu_seconds();
  g.curve = sweep_frequency(hb, hb_sweep(sc), sc.label + " " + setting_label(s));
  g.grid = branch_on_grid(hb, g.curve.branch, g.curve.scaling, omegas, vec(sc.q), StabilityMethod::hill).solutions;
  g.cpu_s = cpu_seconds() - t0;
  return g;
}

// HB at H by arc length, then every grid solution corrected on the exact piecewise-linear
// flow (method_comparison.hpp correct_on_exact_flow): its values and Floquet label are
// those of the exact orbit. The CPU time includes both; the correction's share is kept.
GridRun Methods::harmonic_balance_corrected(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const {
  const HarmonicBalance hb = (this->*sc.model)(s.H, 0, ContactQuadrature::exact);
  GridRun g;
  const double t0 = cpu_seconds();
  g.curve = sweep_frequency(hb, hb_sweep(sc), sc.label + " " + setting_label(s));
  g.grid = branch_on_grid(hb, g.curve.branch, g.curve.scaling, omegas, vec(sc.q), StabilityMethod::none).solutions;
  const double t1 = cpu_seconds();
  g.not_corrected = correct_on_exact_flow(hb, omegas, vec(sc.q), g.curve.scaling, g.grid);
  g.cpu_s = cpu_seconds() - t0;
  g.cpu_correction_s = cpu_seconds() - t1;
  for (const auto& at : g.grid) g.corrected += int(at.size());
  return g;
}

// HB stepped up and down the grid like the time-integration sweeps (same output, no curve).
GridRun Methods::harmonic_balance_stepped(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const {
  const HarmonicBalance hb = (this->*sc.model)(s.H, 0, ContactQuadrature::exact);
  GridRun g;
  const std::vector<double> down(omegas.rbegin(), omegas.rend());
  const double t0 = cpu_seconds();
  const Scaling sc_ = hb.scaling(sc.omega_min, sc.omega_max);
  GridSolutions dn = newton_stepped_sweep(hb, down, vec(sc.q), sc_);
  std::reverse(dn.begin(), dn.end());
  g.grid = merge_grid({newton_stepped_sweep(hb, omegas, vec(sc.q), sc_), dn}, sc_);
  g.cpu_s = cpu_seconds() - t0;
  return g;
}

GridRun Methods::time_integration(const Scene& sc, const Setting& s, const std::vector<double>& omegas) const {
  const HarmonicBalance hb = (this->*sc.model)(sc.H_ref, 0, ContactQuadrature::exact);   // H unused by TI
  TimeIntegrationOptions o;
  o.stepper = s.family == Family::ti_rkf45 ? OdeStepper::rkf45 : OdeStepper::rk8pd;
  o.rel_tol = s.tol;
  o.abs_tol = s.tol;
  o.periodicity_tol = s.tol;
  o.max_periods = cmp_.max_periods;
  o.x_scale = hb.scaling(sc.omega_min, sc.omega_max).x[0];
  GridRun g;
  const std::vector<double> down(omegas.rbegin(), omegas.rend());
  const double t0 = cpu_seconds();
  g.sweeps.push_back(stepped_sweep(hb, omegas, vec(sc.q), o));
  g.sweeps.push_back(stepped_sweep(hb, down, vec(sc.q), o));
  g.grid = sweep_on_grid(omegas, g.sweeps);
  g.cpu_s = cpu_seconds() - t0;
  return g;
}

// The failure figures' data: the whole HB curve (Hill stability), or both sweeps.
void Methods::write_curves(Run& run, const Scene& sc, const Setting& s, const GridRun& g) const {
  const std::string stem = sc.label + "_" + file_tag(s);
  if (!g.sweeps.empty()) {
    Table t({"direction", "omega", "x_max", "x_h1", "periodic", "periods"});
    const char* dir[] = {"up", "down"};
    for (std::size_t d = 0; d < g.sweeps.size(); ++d)
      for (const auto& p : g.sweeps[d])
        t.add_row({std::string(dir[d]), p.omega, p.x_max, p.x_h1, long(p.periodic), long(p.periods)});
    run.write("sweep_" + stem + ".csv", t);
    return;
  }
  const ContactQuadrature quad = s.family == Family::hb_sampled ? ContactQuadrature::sampled : ContactQuadrature::exact;
  const HarmonicBalance hb = (this->*sc.model)(s.H, s.N_per * (2 * s.H + 1), quad);
  const ResponseEvaluator ev(hb, vec(sc.q));
  const std::vector<bool> st = branch_stability(hb, g.curve.branch);
  Table t({"omega", "x_max", "x_h1", "stable"});
  for (std::size_t i = 0; i < g.curve.branch.points.size(); ++i) {
    const auto& p = g.curve.branch.points[i];
    const ResponseSummary r = ev.summarize(p.X);
    t.add_row({p.omega, r.x_max, r.x_h1, long(st[i])});
  }
  run.write("curve_" + stem + ".csv", t);
}

// The runner of each family (indexed by Family).
using Runner = GridRun (Methods::*)(const Scene&, const Setting&, const std::vector<double>&) const;
const Runner kRunners[] = {&Methods::harmonic_balance, &Methods::harmonic_balance, &Methods::harmonic_balance_stepped,
                           &Methods::time_integration, &Methods::time_integration, &Methods::harmonic_balance_corrected};

void Methods::accuracy_against_cost(Run& run, const Scene& sc, const Reference& ref, std::vector<CostRow>& rows) const {
  Table folds({"setting", "points", "folds", "complete"});
  for (const auto& s : kSettings) {
    if ((run.quick() && !s.quick) || s.H > sc.max_H) continue;
    const bool hb = s.family == Family::hb_exact || s.family == Family::hb_sampled;
    const GridRun g = run.timed(sc.label + " " + file_tag(s), [&] {
      return (this->*kRunners[int(s.family)])(sc, s, ref.omegas);
    });
    const GridError e = grid_error(ref.grid, g.grid);
    rows.push_back({sc.label, s.family, setting_label(s), g.cpu_s, e.x_max, e.x_h1, e.missed, e.compared,
                    s.family == Family::hb_corrected ? g.cpu_correction_s : NAN, g.not_corrected, g.corrected});
    if (hb) folds.add_row({file_tag(s), long(g.curve.branch.points.size()), long(g.curve.branch.folds.size()),
                           long(g.curve.complete)});
    if (s.curve) write_curves(run, sc, s, g);
  }
  run.write("folds_" + sc.label + ".csv", folds);
  Table t({"scene", "method", "setting", "cpu_s", "error", "error_h1", "missed", "compared", "cpu_s_correction",
           "corrected", "not_corrected"});
  for (const auto& r : rows) {
    const bool c = r.family == Family::hb_corrected;
    t.add_row({r.scene, std::string(family_name(r.family)), r.setting, r.cpu_s, r.error, r.error_h1, long(r.missed),
               long(r.compared), cell(c, r.cpu_correction_s), c ? Table::Cell(long(r.corrected)) : Table::Cell(std::string()),
               c ? Table::Cell(long(r.not_corrected)) : Table::Cell(std::string())});
  }
  run.write("accuracy_cost.csv", t);
}

// --- step 3b: what the accuracy/cost table shows without a clock -------------------
// The CPU times of step 3 are measurements (they vary run to run); the errors are not.
// Checked here: HB converges in H (its error against the reference falls with every
// H of the table), time integration converges in its tolerance, and HB stepped on the
// grid finds the same orbits as HB continued by arc length (equal errors at equal H).
void Methods::convergence(Run& run, const std::vector<CostRow>& rows) const {
  auto errors = [&](const std::string& scene, Family f) {
    std::vector<std::pair<std::string, double>> e;
    for (const auto& r : rows)
      if (r.scene == scene && r.family == f) e.emplace_back(r.setting, r.error);
    return e;
  };
  auto decreasing = [](const std::vector<std::pair<std::string, double>>& e) {
    for (std::size_t i = 1; i < e.size(); ++i)
      if (!(e[i].second < e[i - 1].second)) return 0.0;
    return e.size() >= 2 ? 1.0 : 0.0;
  };
  for (const auto& sc : kScenes) {
    if (!run.wants(sc.label, sc.quick)) continue;
    const auto hb = errors(sc.label, Family::hb_exact), stepped = errors(sc.label, Family::hb_stepped),
               ti = errors(sc.label, Family::ti_rk8pd);
    run.key_numbers().add("hb_error_decreasing_in_H_" + sc.label, decreasing(hb), "-");
    run.key_numbers().add("ti_error_decreasing_in_tol_" + sc.label, decreasing(ti), "-");
    if (!hb.empty()) run.key_numbers().add("hb_error_at_largest_H_" + sc.label, hb.back().second, "-");
    double gap = 0.0;
    for (const auto& [setting, e] : stepped)
      for (const auto& [setting_c, e_c] : hb)
        if (setting == setting_c) gap = std::max(gap, std::fabs(e - e_c));
    run.key_numbers().add("hb_stepped_vs_curve_error_gap_" + sc.label, gap, "-");
    // HB at any H of the table corrected on the exact flow: its largest error against the reference
    const auto corrected = errors(sc.label, Family::hb_corrected);
    double worst = 0.0;
    for (const auto& [setting, e] : corrected) worst = std::max(worst, e);
    if (!corrected.empty()) run.key_numbers().add("hb_corrected_error_" + sc.label, worst, "-");
  }
}

// --- step 3: speed-up of HB over time integration at equal accuracy ---------------
// Cost to reach an accuracy: the cheapest setting of the family whose error is at
// or below it (no interpolation between settings).
void Methods::speed_ups(Run& run, const std::vector<CostRow>& rows) const {
  auto cheapest = [&](const std::string& scene, Family f, double target) {
    double best = INFINITY;
    for (const auto& r : rows)
      if (r.scene == scene && r.family == f && r.error <= target) best = std::min(best, r.cpu_s);
    return best;
  };
  // HB stepped on the grid (the same output as the time-integration sweeps) and HB
  // over the whole curve by arc length (more output: unstable branch, folds).
  // HB at H corrected on the exact flow (the curve, then the exact orbits on the grid).
  const std::pair<Family, std::string> hb_kinds[] = {
      {Family::hb_stepped, "grid"}, {Family::hb_exact, "curve"}, {Family::hb_corrected, "corrected"}};
  for (const auto& sc : kScenes) {
    if (!run.wants(sc.label, sc.quick)) continue;
    for (double target : {1e-3, 1e-6}) {
      const double ti = std::min(cheapest(sc.label, Family::ti_rk8pd, target), cheapest(sc.label, Family::ti_rkf45, target));
      for (const auto& [family, kind] : hb_kinds) {
        const double hb = cheapest(sc.label, family, target);
        const std::string tag = sci(target).substr(0, 1) + sci(target).substr(4);   // "1e-03"
        if (!std::isfinite(hb) || !std::isfinite(ti)) {
          run.say(sc.label + ": error " + tag + " not reached by " + (std::isfinite(hb) ? "time integration" : "HB " + kind));
          continue;
        }
        run.key_numbers().add("speedup_" + kind + "_" + tag + "_" + sc.label, ti / hb, "-");
        run.say(sc.label + ": at error " + tag + " HB (" + kind + ") " + sci(hb) + " s, time integration " + sci(ti) +
                " s CPU: speed-up " + sci(ti / hb));
      }
    }
  }
}

// --- step 4: cost of one Newton step against H and n --------------------------------
// A chain of n unit masses (springs 1 between neighbours and to the walls, damping
// 0.02 K, force on the last, a contact on the first), each step repeated until 0.02 s
// of CPU time:
//  - dense: one residual + Jacobian evaluation and one LU solve of n(2H+1) unknowns;
//  - condensed: one linearisation and one bordered solve as the continuation's
//    corrector does it (HarmonicBalance::linearize: an LU of 2H+2 rows, one contact).
void Methods::cost_growth(Run& run) const {
  Table t({"n", "H", "unknowns", "cpu_s_per_step", "cpu_s_condensed"});
  auto seconds_per_call = [](const std::function<void()>& step) {
    const double t0 = cpu_seconds();
    int reps = 0;
    do {
      step();
      ++reps;
    } while (cpu_seconds() - t0 < 0.02 || reps < 3);
    return (cpu_seconds() - t0) / reps;
  };
  for (int n : {1, 2, 4, 8, 16})
    for (int H : {1, 2, 4, 8, 16, 32, 64}) {
      const int unknowns = n * (2 * H + 1);
      if (unknowns > (run.quick() ? 200 : 800)) continue;
      MatrixXd K = MatrixXd::Zero(n, n);
      for (int i = 0; i < n; ++i) {
        K(i, i) = 2.0;
        if (i > 0) K(i, i - 1) = K(i - 1, i) = -1.0;
      }
      VectorXd e1 = VectorXd::Zero(n), fc = VectorXd::Zero(n);
      e1[0] = 1.0;
      fc[n - 1] = 0.1;
      const HarmonicBalance hb(LinearSystem{MatrixXd::Identity(n, n), 0.02 * K, K}, {UnilateralContact{e1, 10.0, -0.5, {}}},
                               Excitation{VectorXd::Zero(n), fc, VectorXd::Zero(n)}, H);
      const double omega = 0.3;
      const Scaling sc = hb.scaling(0.5 * omega, 2.0 * omega);
      const VectorXd X = hb.open_contact_solution(omega) * 3.0;
      const VectorXd border = VectorXd::Ones(hb.size() + 1);
      VectorXd R, dX, dRdomega;
      MatrixXd J;
      const double dense = seconds_per_call([&] {
        hb.evaluate(X, omega, R, &J, nullptr);
        dX = J.partialPivLu().solve(R);
      });
      const double condensed = seconds_per_call([&] {
        const auto lin = hb.linearize(X, omega, sc, R, dRdomega);
        lin->solve_bordered(border, border, dX);
      });
      t.add_row({long(n), long(H), long(unknowns), dense, condensed});
    }
  run.write("cost_per_point.csv", t);
}

// --- failure 1: natural continuation stops at the first fold ----------------------
void Methods::natural_vs_arclength(Run& run) const {
  const Scene& sc = kScenes.front();   // the mass against the wall
  const HarmonicBalance hb = mass_wall(10, 0, ContactQuadrature::exact);
  SweepOptions o = hb_sweep(sc);
  o.stability = StabilityMethod::floquet;
  const FrequencyCurve arc = sweep_frequency(hb, o, "arc length");
  o.natural = true;
  o.continuation.natural_points = 300;
  const FrequencyCurve nat = sweep_frequency(hb, o, "natural");
  const ResponseEvaluator ev(hb, vec(sc.q));
  Table t({"method", "omega", "x_max", "stable"});
  for (const auto* c : {&arc, &nat})
    for (std::size_t i = 0; i < c->branch.points.size(); ++i)
      t.add_row({std::string(c == &arc ? "arc_length" : "natural"), c->branch.points[i].omega,
                 ev.summarize(c->branch.points[i].X).x_max, long(c->stable[i])});
  run.write("natural_vs_arclength.csv", t);
  const double stop = nat.branch.points.back().omega;
  run.key_numbers().add("natural_stop_omega", stop, "rad/s");
  run.key_numbers().add("arclength_first_fold_omega", arc.branch.folds.front().omega, "rad/s");
  run.say("natural continuation stops at omega = " + std::to_string(stop) + " rad/s; arc length passes " +
          std::to_string(arc.branch.folds.size()) + " folds, the first at " + std::to_string(arc.branch.folds.front().omega));
}

// --- failure 5: Hill's truncated selection against Floquet on known charts --------
// Mathieu y'' + (a - 2q cos 2t) y = 0 (omega = 2, k = a - 2q cos theta) and
// Meissner y'' + (a + b sgn(cos t)) y = 0 (omega = 1, b written q in the tables):
// Floquet by GSL rk8pd on the variational equation (Meissner also in closed form);
// Hill at H = 1, 2, 4, 8 (the square wave enters Hill through its harmonics <= 2H).
struct ParametricEquation {
  std::string name;
  double omega, a_lo, a_hi, q_hi;
  double (*k)(double a, double q, double theta);
  VectorXd (*coefficients)(double a, double q, int H);
  std::vector<double> breakpoints;              // phases where k jumps
  double (*exact_trace)(double a, double q);    // closed form, if known
};
double mathieu_k(double a, double q, double th) { return a - 2 * q * std::cos(th); }
VectorXd mathieu_coefficients(double a, double q, int) { return vec({a, -2 * q, 0.0}); }
double meissner_k(double a, double b, double th) { return a + b * (std::cos(th) > 0 ? 1.0 : -1.0); }
VectorXd meissner_coefficients(double a, double b, int H) { return square_wave_stiffness(a, b, 2 * H); }
const ParametricEquation kEquations[] = {
    {"mathieu", 2.0, -1.5, 10.0, 5.0, mathieu_k, mathieu_coefficients, {}, nullptr},
    {"meissner", 1.0, -1.5, 10.0, 5.0, meissner_k, meissner_coefficients, {M_PI / 2, 3 * M_PI / 2}, meissner_trace},
};
const int kHillH[] = {1, 2, 4, 8};

// Trace of the monodromy matrix of y'' + k(theta) y = 0 over one period (GSL rk8pd).
double monodromy_trace(const ParametricEquation& eq, double a, double q, double tol) {
  auto A = [&](double t, MatrixXd& out) { out << 0, 1, -eq.k(a, q, eq.omega * t), 0; };
  std::vector<double> breaks;
  for (double b : eq.breakpoints) breaks.push_back(b / eq.omega);
  return monodromy_linear_periodic(A, 2, 2 * M_PI / eq.omega, breaks, tol).trace();
}

void Methods::hill_vs_floquet(Run& run) const {
  const MatrixXd one = MatrixXd::Identity(1, 1), zero = MatrixXd::Zero(1, 1);
  for (const auto& eq : kEquations) {
    Table t({"a", "q", "trace", "floquet_stable", "exact_trace", "hill_H1", "hill_H2", "hill_H4", "hill_H8"});
    long disagree[4] = {0, 0, 0, 0}, points = 0;
    double worst_trace = 0.0;
    for (int i = 0; i < charts_.a_points; ++i)
      for (int j = 0; j < charts_.q_points; ++j) {
        const double a = eq.a_lo + (eq.a_hi - eq.a_lo) * i / (charts_.a_points - 1);
        const double q = eq.q_hi * j / (charts_.q_points - 1);
        const double tr = monodromy_trace(eq, a, q, 1e-11);
        const bool fl = std::fabs(tr) < 2.0;
        const double exact = eq.exact_trace ? eq.exact_trace(a, q) : tr;
        worst_trace = std::max(worst_trace, std::fabs(tr - exact) / std::max(1.0, std::fabs(exact)));
        std::vector<Table::Cell> row{a, q, tr, long(fl), exact};
        for (int h = 0; h < 4; ++h) {
          const MatrixXd J = linear_periodic_jacobian(one, zero, zero, one, eq.coefficients(a, q, kHillH[h]), eq.omega, kHillH[h]);
          const bool hs = hill_stability(J, one, zero, eq.omega, kHillH[h]).stable;
          disagree[h] += hs != fl;
          row.emplace_back(std::in_place_type<long>, long(hs));
        }
        ++points;
        t.add_row(row);
      }
    run.write(eq.name + "_chart.csv", t);
    for (int h = 0; h < 4; ++h)
      run.key_numbers().add(eq.name + "_hill_H" + std::to_string(kHillH[h]) + "_disagreement", double(disagree[h]) / points, "-");
    if (eq.exact_trace) run.key_numbers().add(eq.name + "_trace_gsl_vs_exact", worst_trace, "-");
  }
  // Edges of Mathieu's first tongue at q = 0.1 (trace = -2), by bisection on Floquet's trace.
  struct Edge { const char* name; double lo, hi; };
  for (const Edge& e : {Edge{"mathieu_b1_q0.1", 0.5, 1.0}, Edge{"mathieu_a1_q0.1", 1.0, 1.5}}) {
    double lo = e.lo, hi = e.hi;
    auto f = [&](double a) { return monodromy_trace(kEquations[0], a, 0.1, 1e-13) + 2.0; };
    const bool flo = f(lo) > 0;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((f(mid) > 0) == flo ? lo : hi) = mid;
    }
    run.key_numbers().add(e.name, 0.5 * (lo + hi), "-");
  }
}

// --- failure 6: Newton without scaling on the micrometre gear problem ---------------
// At each of newton_frequencies frequencies, Newton from the linear first guess, with
// the automatic scaling (HarmonicBalance::scaling) and with none (x, omega and the
// residual in SI units, as an unscaled code would); then a whole arc-length branch
// unscaled.
void Methods::unscaled_newton(Run& run) const {
  const Scene& sc = kScenes.back();   // the gear
  const HarmonicBalance hb = gear(5, 0, ContactQuadrature::exact);
  const Scaling scaled = hb.scaling(sc.omega_min, sc.omega_max);
  Scaling unit;
  unit.x = VectorXd::Ones(hb.size());
  const Scaling& none = unit;   // x, omega and residual in SI units
  Table t({"omega", "scaled_converged", "scaled_iterations", "unscaled_converged", "unscaled_iterations",
           "unscaled_residual_N", "solution_rel_diff"});
  long fail_scaled = 0, fail_unscaled = 0;
  for (int i = 0; i < charts_.newton_frequencies; ++i) {
    const double omega = sc.omega_min + (sc.omega_max - sc.omega_min) * (i + 0.5) / charts_.newton_frequencies;
    VectorXd Xs = linear_first_guess(hb, omega), Xu = Xs;
    const NewtonReport rs = newton_solve(hb, Xs, omega, scaled), ru = newton_solve(hb, Xu, omega, none);
    fail_scaled += !rs.converged;
    fail_unscaled += !ru.converged;
    const double diff = (Xu - Xs).lpNorm<Eigen::Infinity>() / Xs.lpNorm<Eigen::Infinity>();
    t.add_row({omega, long(rs.converged), long(rs.iterations), long(ru.converged), long(ru.iterations), ru.residual, diff});
  }
  run.write("unscaled_newton.csv", t);
  KeyNumbers& key = run.key_numbers();
  key.add("newton_failure_rate_scaled", double(fail_scaled) / charts_.newton_frequencies, "-");
  key.add("newton_failure_rate_unscaled", double(fail_unscaled) / charts_.newton_frequencies, "-");
  ContinuationOptions co;
  co.omega_start = sc.omega_min;
  co.omega_end = sc.omega_max;
  co.ds_max = sc.ds_max;
  co.max_steps = 3000;
  Table b({"scaling", "omega", "x_max"});
  const ResponseEvaluator ev(hb, vec(sc.q));
  for (const auto* s : {&scaled, &none}) {
    const Branch br = arc_length_continuation(hb, linear_first_guess(hb, sc.omega_min), *s, co);
    for (const auto& p : br.points) b.add_row({std::string(s == &scaled ? "automatic" : "none"), p.omega, ev.summarize(p.X).x_max});
    key.add(std::string("arclength_complete_") + (s == &scaled ? "scaled" : "unscaled"), br.complete ? 1.0 : 0.0, "-");
    key.add(std::string("arclength_reached_hz_") + (s == &scaled ? "scaled" : "unscaled"),
            br.points.empty() ? 0.0 : hz(br.points.back().omega), "Hz");
    run.say(std::string("gear arc length, ") + (s == &scaled ? "automatic scaling: " : "no scaling: ") + br.summary());
  }
  run.write("unscaled_arclength.csv", b);
  run.say("Newton failures at " + std::to_string(charts_.newton_frequencies) + " frequencies: scaled " +
          std::to_string(fail_scaled) + ", unscaled " + std::to_string(fail_unscaled));
}

// --- failure 7: grazing -------------------------------------------------------------
// Mass against the wall at omega = 0.8 rad/s (below resonance, one solution), force
// amplitude F stepped through the value where the crest just touches the wall
// (F_graze = |1 - omega^2 + i 0.01 omega| 0.6 for the linear open response). Reference:
// GSL rk8pd at ti_ref_tol. Errors of x_max: HB exact (H = 10), HB sampled (H = 10,
// N = 4(2H+1)), time integration (rk8pd 1e-6); the contact duration and the Floquet
// multiplier of the reference orbit.
void Methods::grazing(Run& run) const {
  const double omega = 0.8, F_graze = 0.6 * std::abs(std::complex<double>(1 - omega * omega, 0.01 * omega));
  Table t({"Fa", "contact_rad", "x_max_ref", "err_hb_exact", "err_hb_sampled", "err_ti", "floquet_modulus",
           "err_hb_corrected"});
  TimeIntegrationOptions tight, loose;
  tight.rel_tol = tight.abs_tol = cmp_.ti_ref_tol;
  tight.periodicity_tol = 10 * cmp_.ti_ref_tol;
  loose.rel_tol = loose.abs_tol = loose.periodicity_tol = 1e-6;
  for (int i = 0; i < charts_.grazing_points; ++i) {
    const double F = F_graze * (0.97 + 0.06 * i / (charts_.grazing_points - 1));
    const HarmonicBalance ex = wall(F, 10, 0, ContactQuadrature::exact), sa = wall(F, 10, 84, ContactQuadrature::sampled);
    const Scaling s = ex.scaling(0.5, 2.0);
    VectorXd Xe = linear_first_guess(ex, omega), Xs = Xe;
    if (!newton_solve(ex, Xe, omega, s).converged || !newton_solve(sa, Xs, omega, s).converged)
      throw std::runtime_error("grazing: Newton failed at F = " + std::to_string(F));
    VectorXd x0, v0;
    hb_initial_state(ex, Xe, omega, x0, v0);
    tight.x_scale = loose.x_scale = s.x[0];
    const auto ref = stepped_sweep(ex, {omega}, vec({1.0}), tight, x0, v0).front();
    const auto ti = stepped_sweep(ex, {omega}, vec({1.0}), loose).front();
    const ResponseEvaluator ev(ex, vec({1.0})), evs(sa, vec({1.0}));
    const VectorXd uc = ex.penetration(Xe, 0);
    double width = 0.0;
    for (const auto& [lo, hi] : contact_intervals(uc, Aft(ex.harmonics()).to_time(uc))) width += hi - lo;
    const FloquetResult fr = floquet_of_hb_orbit(ex, Xe, omega, s.x[0]);
    auto err = [&](double x) { return std::fabs(x - ref.x_max) / std::fabs(ref.x_max); };
    // HB H = 10 corrected on the exact flow: empty where the correction fails or is inconsistent
    double corrected = NAN;
    if (fr.corrected) {
      const ExactOrbit o(ex, Xe, omega, fr.x0, fr.v0);
      if (o.consistent()) corrected = err(o.measures(vec({1.0})).x_max);
    }
    t.add_row({F, width, ref.x_max, err(ev.summarize(Xe).x_max), err(evs.summarize(Xs).x_max), err(ti.x_max),
               fr.modulus, cell(std::isfinite(corrected), corrected)});
  }
  run.write("grazing.csv", t);
  run.key_numbers().add("grazing_force", F_graze, "N");
}

HarmonicBalance Methods::wall(double F, int H, int N, ContactQuadrature q) const {
  LinearSystem sys{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.01), MatrixXd::Constant(1, 1, 1.0)};
  UnilateralContact c{VectorXd::Constant(1, 1.0), 1.0, -0.6, {}};
  Excitation f{VectorXd::Zero(1), VectorXd::Constant(1, F), VectorXd::Zero(1)};
  return HarmonicBalance(sys, {c}, f, H, N, q);
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch02_methods",
              "ch02_methods: the method, speed against accuracy, and where each method fails (thesis ch. 2)\n"
              "  M x'' + C x' + K x + n max(kc (g + n'x), 0) = f0 + f cos(omega t): harmonic balance, continuation,\n"
              "  time integration and stability on three scenes (mass against wall, NLvib ex. 03, gear at 300 N m)");
  Methods chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
