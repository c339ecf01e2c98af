// ===========================================================================
// ch08_gear_response: the gear mesh driven by its own static transmission error
// (thesis ch. 8, Figs. 67, 69-70)
// ===========================================================================
//
//     me x'' + c x' + max( kc (x + e(t)), 0 ) = F0,      F0 = T / r
//
// and, beyond the thesis (--set model=parametric, README "Beyond the thesis"),
// the parametric model it approximates, d the total mesh deflection:
//
//     me d'' + c d' + max( k(t) d, 0 ) = F0,             k(t) = F0 / e(t)
//
// x is the dynamic transmission error along the line of action, e(t) the loaded
// STE of ch. 7 (periodic with the mesh period, theta = omega t = 2 pi f_mesh t),
// me = I1 I2 / (I1 r2^2 + I2 r1^2), kc = mean of F0 / e(t), c = 2 zeta sqrt(kc me)
// (lib/gearhb/gears/dte_model.hpp). Harmonic balance with the static term, exact
// projection of the contact law, one arc-length continuation per curve,
// Floquet stability of every point (lib/gearhb/hb). The steps, in order (README
// of this chapter): mesh_stiffness, gear_constants, frequency_responses (per
// case: linear_reference, measure, time_integration_check, time_history,
// peak_check, floquet_check); own_case for --case own.
//
// Sample runs:
//   build/bin/ch08_gear_response                                  every figure's data
//   build/bin/ch08_gear_response --case quick --out /tmp/q        the regression subset
//   build/bin/ch08_gear_response --case own --set torque=150 --set H=8 --out /tmp/mine
//   build/bin/ch08_gear_response --case own --set ste_file=my_ste.csv --out /tmp/mine
//   build/bin/ch08_gear_response --set model=parametric --out /tmp/par  Figs. 69-70 parametric
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/dte_model.hpp"
#include "gearhb/gears/ste.hpp"
#include "gearhb/gears/ste_continuous.hpp"
#include "gearhb/gears/ste_file.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::VectorXd;

namespace {

constexpr double kUm = 1e6;   // m -> um

// --- parameters: one struct per concern, thesis defaults (§8.1) ------------
struct GearPair {
  double I1 = 0.0158, I2 = 0.0158;   // wheel inertias [kg m^2]
  double zeta = 0.08;                // damping ratio of the mesh
};
struct SteSettings {
  int samples = 64;   // phases per mesh cycle of the continuous STE
  int reading = 0;    // 0 load moving continuously, 1 ch. 7's 8 positions per base pitch
};
struct FrequencyRange {
  double f_min_hz = 300.0, f_max_hz = 5000.0;   // mesh frequency [Hz]
};
struct MeshModel {
  std::string name = "constant";   // constant (thesis §8.1) | parametric (k(t) = F0 / e(t))
  DteModel model() const { return name == "parametric" ? DteModel::parametric : DteModel::constant; }
};
struct OwnCase {
  double torque = 300.0;         // [N m]
  double pitch_radius = 0.075;   // r1 = r2 [m]
  double me = 0.0;               // [kg], 0 = from I1, I2, r
  double kc = 0.0;               // [N/m], 0 = mean of F0 / e(t)
  std::string ste_file;          // CSV phase,ste_um; empty = ch. 7's STE
};

// What a case measures besides its curve.
//  time_check    HB against GSL time integration at 8 stable points
//  time_history  x(t) and the contact force at a contact-loss point
//  peak          the near-peak point against GSL time integration of the full-STE model
//  floquet       the multipliers against GSL's variational equation on the integrated orbit
enum class Measure { time_check, time_history, peak, floquet };

struct Case {
  std::string label;   // file stem: frc_<label>.csv
  std::string figure;  // thesis figure
  double torque;       // [N m]
  int H;               // harmonics (and STE components kept, thesis §8.2)
  bool quick;          // part of the regression subset
  bool parametric;     // always the parametric model (else the run's `model`)
  std::vector<Measure> measures;
};

const std::vector<Case> kCases = {
    {"T100_H1", "69", 100, 1, false, false, {}},
    {"T200_H1", "69", 200, 1, false, false, {}},
    {"T300_H1", "69", 300, 1, false, false, {Measure::peak}},
    {"T100_H5", "70", 100, 5, true, false, {Measure::time_check}},
    {"T200_H5", "70", 200, 5, true, false, {Measure::time_check}},
    {"T300_H5", "70", 300, 5, true, false, {Measure::time_check, Measure::time_history, Measure::peak}},
    {"T300_H10", "H-convergence", 300, 10, false, false, {Measure::peak}},
    {"T300_H20", "H-convergence", 300, 20, false, false, {Measure::peak}},
    {"T300_H5_param", "parametric model", 300, 5, true, true, {Measure::time_check, Measure::floquet}},
};
constexpr int kFullSte = 20;   // STE harmonics of the "full" model (peak check)
const double kTorques[] = {100, 200, 300};   // Fig. 67
const VectorXd kX = VectorXd::Constant(1, 1.0);

bool has(const Case& c, Measure m) { return std::find(c.measures.begin(), c.measures.end(), m) != c.measures.end(); }
std::string torque_tag(double T) { return "T" + std::to_string(long(std::lround(T))); }
double hz(double omega) { return omega / (2 * M_PI); }

// The worst values of the chapter's own checks over every point computed.
struct Worst {
  double mean_force = 0.0, closed_form = 0.0;
  long closed_points = 0;
};

class GearResponse {
 public:
  explicit GearResponse(Study& study);
  void run(Run& run);

 private:
  GearPair gear_;
  SteSettings ste_;
  FrequencyRange range_;
  MeshModel model_;
  OwnCase own_;
  SolverSettings sol_;
  SteModel thesis_gear_;   // ch. 7's STE model, thesis defaults

  std::vector<double> ste_samples(double torque) const;
  DteGear mesh(double torque) const;
  SweepOptions sweep_settings() const;
  FrequencyCurve sweep(Run& run, const HarmonicBalance& hb, const std::string& label) const;
  void mesh_stiffness(Run& run) const;
  void gear_constants(Run& run) const;
  void frequency_responses(Run& run) const;
  Table response_table(const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void linear_reference(Run& run, const DteGear& g, int H, const std::string& label) const;
  void measure(Run& run, const std::string& label, const DteGear& g, DteModel model, const HarmonicBalance& hb,
               const FrequencyCurve& c, Worst& worst, Table& bands) const;
  void time_integration_check(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                              Table& rows) const;
  void time_history(Run& run, const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void peak_check(Run& run, const Case& cs, const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void floquet_check(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  DteModel model_of(const Case& cs) const { return cs.parametric ? DteModel::parametric : model_.model(); }
  void own_case(Run& run) const;
  void check(const Selection& sel);
};

GearResponse::GearResponse(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("gear pair (thesis §8.1)");
  P.add("I1", &gear_.I1, "kg m^2", "inertia of wheel 1", Range::positive());
  P.add("I2", &gear_.I2, "kg m^2", "inertia of wheel 2", Range::positive());
  P.add("zeta", &gear_.zeta, "-", "damping ratio, c = 2 zeta sqrt(kc me)", Range::between(1e-4, 1.0));
  P.group("static transmission error (thesis ch. 7 model)");
  P.add("ste_samples", &ste_.samples, "-", "phases per mesh cycle of the continuous STE", Range::between(16, 4096));
  P.add("ste_reading", &ste_.reading, "-", "0 load moving continuously, 1 ch. 7's 8 positions per base pitch",
        Range::between(0, 1));
  P.group("mesh model");
  P.add("model", &model_.name, "-", "constant (thesis §8.1: kc, STE as excitation) or parametric (k(t) = F0/e(t))");
  P.group("mesh frequency range");
  P.add("f_min_hz", &range_.f_min_hz, "Hz", "start of the sweep", Range::between(1.0, 1e6));
  P.add("f_max_hz", &range_.f_max_hz, "Hz", "end of the sweep", Range::between(1.0, 1e6));
  P.group("own case (--case own)", true);
  P.add("torque", &own_.torque, "N m", "transmitted torque T", Range::between(1e-3, 1e5));
  P.add("pitch_radius", &own_.pitch_radius, "m", "pitch radius r of both wheels", Range::between(1e-3, 10.0));
  P.add("me", &own_.me, "kg", "equivalent mass (0 = from I1, I2, r)", Range::between(0.0, 1e6));
  P.add("kc", &own_.kc, "N/m", "mesh stiffness (0 = mean of F0/e(t))", Range::between(0.0, 1e13));
  P.add("ste_file", &own_.ste_file, "path", "STE as CSV 'phase,ste_um' (empty = ch. 7's STE)");
  sol_.H = 5;
  sol_.omega_min = 2 * M_PI * range_.f_min_hz;
  sol_.omega_max = 2 * M_PI * range_.f_max_hz;
  sol_.ds_max = 0.05;
  add_solver_parameters(P, sol_, 1);
  std::vector<std::string> labels, quick;
  for (const auto& c : kCases) {
    labels.push_back(c.label);
    if (c.quick) quick.push_back(c.label);
  }
  study.cases(labels, quick);
  study.check([this, &P](const Selection& sel) {
    ParameterSet::require(!P.was_set("omega_min") && !P.was_set("omega_max"),
                          "set the mesh-frequency range with f_min_hz / f_max_hz [Hz], not omega_min / omega_max");
    ParameterSet::require(sel.kind == Selection::Kind::own || !P.was_set("H"),
                          "parameter 'H' is fixed by the case table (H = 1, 5, 10, 20); set it with --case own");
    check(sel);
  });
}

void GearResponse::check(const Selection& sel) {
  sol_.omega_min = 2 * M_PI * range_.f_min_hz;
  sol_.omega_max = 2 * M_PI * range_.f_max_hz;
  ParameterSet::require(range_.f_min_hz < range_.f_max_hz, "parameter 'f_min_hz' must be < f_max_hz");
  ParameterSet::require(model_.name == "constant" || model_.name == "parametric",
                        "parameter 'model' must be 'constant' or 'parametric'");
  check_solver_settings(sol_);
  if (sel.kind != Selection::Kind::own) return;
  ParameterSet::require(own_.ste_file.empty() || ste_.reading == 0,
                        "ste_reading applies to ch. 7's STE, not to an ste_file");
  if (!own_.ste_file.empty()) {
    const bool parametric = model_.model() == DteModel::parametric;
    try {
      const std::vector<double> e = read_ste_file(own_.ste_file, 2 * sol_.H + 1, own_.kc == 0.0 || parametric).ste;
      // the parametric stiffness F0 / e needs the STE cut to H harmonics positive
      const VectorXd eh = Aft(sol_.H, 64 * (2 * sol_.H + 1)).to_time(periodic_fourier(e, sol_.H));
      ParameterSet::require(!parametric || eh.minCoeff() > 0.0,
                            own_.ste_file + ": model=parametric needs the STE cut to H harmonics > 0 over the cycle");
    } catch (const SteFileError& e) {
      throw UsageError(e.what());
    }
  }
}

void GearResponse::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) {
    mesh_stiffness(run);
    gear_constants(run);
  }
  frequency_responses(run);
}

// The STE of ch. 7's gear at torque T (continuous, or the 8-position reading) [m].
std::vector<double> GearResponse::ste_samples(double torque) const {
  if (ste_.reading == 1) return ste_values(ste_over_mesh_cycle(thesis_gear_, torque));
  return ste_values(ste_continuous(thesis_gear_, torque, ste_.samples));
}

// The 1-DOF model of the thesis' gear pair at torque T (§8.1), STE harmonics up to 20.
DteGear GearResponse::mesh(double torque) const {
  const std::vector<double> e = ste_samples(torque);
  const double r = thesis_gear_.gear.pitch_radius();
  DteGear g;
  g.F0 = torque / r;
  g.me = equivalent_mass(gear_.I1, gear_.I2, r, r);
  g.kc = mean_stiffness(e, g.F0);
  g.c = mesh_damping(gear_.zeta, g.kc, g.me);
  g.ste = periodic_fourier(e, 20);
  return g;
}

SweepOptions GearResponse::sweep_settings() const {
  SweepOptions o = sweep_options(sol_);
  o.stability = StabilityMethod::floquet;
  return o;
}

FrequencyCurve GearResponse::sweep(Run& run, const HarmonicBalance& hb, const std::string& label) const {
  FrequencyCurve c = run.timed("sweep " + label, [&] {
    return require_complete(sweep_frequency(hb, sweep_settings(), label), label);
  });
  run.say(label + ": " + c.branch.summary());
  return c;
}

// Step 1 (Fig. 67): the STE and k(t) = F0 / e(t) over one mesh cycle, both readings.
void GearResponse::mesh_stiffness(Run& run) const {
  Table spectrum({"torque", "k", "amplitude_um", "amplitude_p8_um"});
  for (double T : kTorques) {
    const double F = T / thesis_gear_.gear.pitch_radius();
    const std::vector<double> ec = ste_values(ste_continuous(thesis_gear_, T, ste_.samples));
    const std::vector<double> e8 = ste_values(ste_over_mesh_cycle(thesis_gear_, T));
    for (const auto& [name, e] : {std::pair<std::string, const std::vector<double>&>{"", ec}, {"_p8", e8}}) {
      Table t({"phase", "ste_um", "k"});
      for (std::size_t j = 0; j < e.size(); ++j) t.add_row({double(j) / e.size(), e[j] * kUm, F / e[j]});
      run.write("fig67" + name + "_" + torque_tag(T) + ".csv", t);
      run.key_numbers().add("kc" + name + "_" + torque_tag(T), mean_stiffness(e, F), "N/m");
      run.key_numbers().add("max_ste" + name + "_" + torque_tag(T), *std::max_element(e.begin(), e.end()) * kUm, "um");
    }
    const VectorXd Ac = periodic_fourier(ec, 20), A8 = periodic_fourier(e8, 20);
    for (int k = 1; k <= 20; ++k)
      spectrum.add_row({T, long(k), std::hypot(Ac[2 * k - 1], Ac[2 * k]) * kUm, std::hypot(A8[2 * k - 1], A8[2 * k]) * kUm});
  }
  run.write("ste_spectrum.csv", spectrum);
}

// Step 2: me, kc, c and the closed-contact natural frequency at 300 N m.
void GearResponse::gear_constants(Run& run) const {
  const DteGear g = mesh(300.0);
  KeyNumbers& key = run.key_numbers();
  key.add("me", g.me, "kg");
  key.add("kc_used_T300", g.kc, "N/m");
  key.add("c_T300", g.c, "N s/m");
  key.add("fn_T300", std::sqrt(g.kc / g.me) / (2 * M_PI), "Hz");
  run.say("me = " + std::to_string(g.me) + " kg, kc(300 N m) = " + std::to_string(g.kc * 1e-6) +
          " MN/m, c = " + std::to_string(g.c) + " N s/m, fn = " +
          std::to_string(std::sqrt(g.kc / g.me) / (2 * M_PI)) + " Hz");
}

// Step 3 (Figs. 69-70, H-convergence): one continuation per case of the table.
void GearResponse::frequency_responses(Run& run) const {
  Table index({"label", "figure", "model", "torque", "H", "F0", "me", "kc", "c", "points", "folds", "bifurcations",
               "peak_rms_um", "peak_f_hz"});
  Table bands({"label", "band", "f_lo_hz", "f_hi_hz"});
  Table ti({"label", "f_mesh_hz", "contact", "x_rms_ac_hb", "x_rms_ac_ti", "rel_diff", "periods"});
  Worst worst;
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const DteGear g = mesh(cs.torque);
    const DteModel model = model_of(cs);
    const HarmonicBalance hb = dte_harmonic_balance(g, cs.H, sol_.N, contact_quadrature(sol_), model);
    const FrequencyCurve c = sweep(run, hb, cs.label);
    const Table frc = response_table(g, hb, c);
    run.write("frc_" + cs.label + ".csv", frc);
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c));
    linear_reference(run, g, cs.H, cs.label);
    measure(run, cs.label, g, model, hb, c, worst, bands);
    std::size_t peak = 0;
    for (std::size_t i = 0; i < c.branch.points.size(); ++i)
      if (rms_ac(c.branch.points[i].X) > rms_ac(c.branch.points[peak].X)) peak = i;
    index.add_row({cs.label, cs.figure, std::string(model == DteModel::parametric ? "parametric" : "constant"), cs.torque, long(cs.H), g.F0, g.me, g.kc, g.c, long(c.branch.points.size()),
                   long(c.branch.folds.size()), long(c.bifurcations.size()), rms_ac(c.branch.points[peak].X) * kUm,
                   hz(c.branch.points[peak].omega)});
    if (has(cs, Measure::time_check)) time_integration_check(run, cs, hb, c, ti);
    if (has(cs, Measure::time_history)) time_history(run, g, hb, c);
    if (has(cs, Measure::peak)) peak_check(run, cs, g, hb, c);
    if (has(cs, Measure::floquet)) floquet_check(run, cs, hb, c);
  }
  run.write("cases.csv", index);
  run.write("loss_bands.csv", bands);
  if (ti.rows() > 0) run.write("check_time_integration.csv", ti);
  if (worst.closed_points > 0) run.key_numbers().add("closed_form_rel_diff", worst.closed_form, "-");
  run.key_numbers().add("mean_force_rel_dev", worst.mean_force, "-");
}

// One row per continuation point: f_mesh_hz, omega, x_max, x_min, x_rms_ac, x_h1, stable, contact [m].
Table GearResponse::response_table(const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  (void)g;
  const ResponseEvaluator ev(hb, kX);
  Table t({"f_mesh_hz", "omega", "x_max", "x_min", "x_rms_ac", "x_h1", "stable", "contact"});
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const auto& p = c.branch.points[i];
    const ResponseSummary r = ev.summarize(p.X);
    t.add_row({hz(p.omega), p.omega, r.x_max, r.x_min, r.x_rms_ac, r.x_h1, long(c.stable[i] ? 1 : 0),
               std::string(to_string(r.contact))});
  }
  return t;
}

// The linear closed-contact curve (closed form from the STE harmonics kept).
void GearResponse::linear_reference(Run& run, const DteGear& g, int H, const std::string& label) const {
  Table t({"f_mesh_hz", "x_rms_ac"});
  for (int i = 0; i <= 800; ++i) {
    const double w = sol_.omega_min + (sol_.omega_max - sol_.omega_min) * i / 800.0;
    t.add_row({hz(w), rms_ac(dte_closed_contact(g, H, w))});
  }
  run.write("linear_" + label + ".csv", t);
}

// Contact-loss bands (runs of points not in full contact), the first loss
// frequency refined on the branch, the mean contact force and (constant model)
// the closed form at every full-contact point.
void GearResponse::measure(Run& run, const std::string& label, const DteGear& g, DteModel model,
                           const HarmonicBalance& hb, const FrequencyCurve& c, Worst& worst, Table& bands) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  long band = 0;
  double lo = 0.0, hi = 0.0;
  bool in_band = false;
  for (std::size_t i = 0; i <= P.size(); ++i) {
    const bool lost = i < P.size() && ev.summarize(P[i].X).contact != ContactState::full;
    if (lost) {
      const double f = hz(P[i].omega);
      lo = in_band ? std::min(lo, f) : f;
      hi = in_band ? std::max(hi, f) : f;
    } else if (in_band) {
      bands.add_row({label, ++band, lo, hi});
    }
    in_band = lost;
    if (i == P.size()) break;
    const double F = dte_mean_contact_force(g, P[i].X, model);
    worst.mean_force = std::max(worst.mean_force, std::fabs(F - g.F0) / g.F0);
    if (!lost && model == DteModel::constant) {
      const VectorXd Xc = dte_closed_contact(g, hb.harmonics(), P[i].omega);
      worst.closed_form = std::max(worst.closed_form, (P[i].X - Xc).lpNorm<Eigen::Infinity>() /
                                                          Xc.tail(Xc.size() - 1).lpNorm<Eigen::Infinity>());
      ++worst.closed_points;
    }
  }
  KeyNumbers& key = run.key_numbers();
  key.add("loss_bands_" + label, double(band), "-");
  key.add("contact_loss_" + label, band > 0 ? 1.0 : 0.0, "-");
  const double f_loss = first_transition(hb, c, opens_somewhere(hb));
  if (std::isfinite(f_loss)) key.add("loss_onset_hz_" + label, hz(f_loss), "Hz");
  double peak = 0.0;
  for (const auto& p : P) peak = std::max(peak, rms_ac(p.X));
  key.add("peak_rms_um_" + label, peak * kUm, "um");
}

// Step 4 (§5 of the chapter README): x_rms_ac by HB against GSL rk8pd at up to 8
// stable points away from folds, contact-loss points first, spread over the branch.
void GearResponse::time_integration_check(Run& run, const Case& cs, const HarmonicBalance& hb,
                                          const FrequencyCurve& c, Table& rows) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  std::vector<std::size_t> lost, full;
  for (std::size_t i = 0; i < P.size(); ++i) {
    bool near = false;
    for (const auto& f : c.branch.folds) near = near || std::fabs(f.omega - P[i].omega) < 5e-3 * f.omega;
    if (!c.stable[i] || near) continue;
    (ev.summarize(P[i].X).contact == ContactState::full ? full : lost).push_back(i);
  }
  std::vector<std::size_t> chosen;
  auto spread = [&](const std::vector<std::size_t>& v, std::size_t n) {
    for (std::size_t k = 0; k < n && !v.empty(); ++k) chosen.push_back(v[(2 * k + 1) * v.size() / (2 * n)]);
  };
  spread(lost, std::min<std::size_t>(5, lost.size()));
  spread(full, 8 - std::min<std::size_t>(5, lost.size()));
  const TimeIntegrator ti(hb);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  double worst = 0.0;
  run.timed("time integration " + cs.label, [&] {
    for (std::size_t i : chosen) {
      VectorXd x0, v0;
      hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
      const SteadyState s = ti.steady_state(x0, v0, P[i].omega, opt);
      if (!s.converged)
        throw std::runtime_error(cs.label + ": time integration not periodic at f_mesh = " + std::to_string(hz(P[i].omega)) + " Hz");
      const VectorXd x = s.x.col(0);
      const double rms_ti = std::sqrt((x.array() - x.mean()).square().mean());
      const double rms_hb = ev.summarize(P[i].X).x_rms_ac, d = std::fabs(rms_hb - rms_ti) / rms_ti;
      worst = std::max(worst, d);
      rows.add_row({cs.label, hz(P[i].omega), std::string(to_string(ev.summarize(P[i].X).contact)), rms_hb, rms_ti, d,
                    long(s.periods)});
    }
    return 0;
  });
  run.key_numbers().add("ti_points_" + cs.label, double(chosen.size()), "-");
  run.key_numbers().add("ti_rms_rel_diff_" + cs.label, worst, "-");
}

// Supplement: x(t), e(t) and the contact force over two mesh periods at the
// stable contact-loss point of largest RMS.
void GearResponse::time_history(Run& run, const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  std::size_t pick = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (c.stable[i] && ev.summarize(P[i].X).contact != ContactState::full &&
        (pick == P.size() || rms_ac(P[i].X) > rms_ac(P[pick].X)))
      pick = i;
  if (pick == P.size()) throw std::runtime_error("time_history: no stable contact-loss point on the curve");
  const VectorXd x = ev.history(P[pick].X);
  const Aft fine(hb.harmonics(), int(x.size()));
  const VectorXd e = fine.to_time(ste_harmonics(g, hb.harmonics()));
  const double T = 2 * M_PI / P[pick].omega;
  Table t({"t_ms", "x_um", "e_um", "contact_force"});
  for (int period = 0; period < 2; ++period)
    for (int j = 0; j < x.size(); ++j)
      t.add_row({1e3 * T * (period + double(j) / x.size()), x[j] * kUm, e[j] * kUm,
                 std::max(g.kc * (x[j] + e[j]), 0.0)});
  run.write("time_history.csv", t);
  run.key_numbers().add("time_history_f_hz", hz(P[pick].omega), "Hz");
}

// The near-peak point of a curve against GSL time integration of the model with
// the STE's first 20 harmonics (the "full" STE): the stable point of largest
// x_rms_ac at least 0.3 % in frequency below the first fold (the peak of the
// softening overhang; at the fold itself the orbit attracts too slowly), from
// its HB state to the periodic state. For H = 20 it checks the HB solution; for
// H < 20 it measures the truncation error of the curve at its peak (STE and
// response harmonics together).
void GearResponse::peak_check(Run& run, const Case& cs, const DteGear& g, const HarmonicBalance& hb,
                              const FrequencyCurve& c) const {
  const auto& P = c.branch.points;
  const double w_fold = c.branch.folds.empty() ? INFINITY : c.branch.folds.front().omega;
  std::size_t pick = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (c.stable[i] && P[i].omega < (1.0 - 3e-3) * w_fold && (pick == P.size() || rms_ac(P[i].X) > rms_ac(P[pick].X)))
      pick = i;
  if (pick == P.size()) throw std::runtime_error(cs.label + ": no stable point below the first fold for the peak check");
  const HarmonicBalance full = dte_harmonic_balance(g, kFullSte, 0, ContactQuadrature::exact, model_of(cs));
  VectorXd x0, v0;
  hb_initial_state(hb, P[pick].X, P[pick].omega, x0, v0);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  const SteadyState s = run.timed("peak check " + cs.label, [&] {
    return TimeIntegrator(full).steady_state(x0, v0, P[pick].omega, opt);
  });
  if (!s.converged)
    throw std::runtime_error(cs.label + ": peak check: time integration not periodic at f_mesh = " +
                             std::to_string(hz(P[pick].omega)) + " Hz");
  const VectorXd x = s.x.col(0);
  const double rms_ti = std::sqrt((x.array() - x.mean()).square().mean()), rms_hb = rms_ac(P[pick].X);
  KeyNumbers& key = run.key_numbers();
  key.add("peak_check_f_hz_" + cs.label, hz(P[pick].omega), "Hz");
  key.add("peak_check_rms_hb_um_" + cs.label, rms_hb * kUm, "um");
  key.add("peak_check_rms_ti_um_" + cs.label, rms_ti * kUm, "um");
  key.add("peak_check_rel_diff_" + cs.label, std::fabs(rms_hb - rms_ti) / rms_ti, "-");
}

// Floquet multipliers of the parametric model (variational equation about the HB
// orbit, hb/floquet.hpp) against GSL's variational equation integrated along the
// orbit itself (TimeIntegrator::monodromy, from the HB state): at the stable
// full-contact point of largest RMS, the stable contact-loss point of largest RMS
// and the unstable point of largest |mu| (where present), all 1 % away from folds.
void GearResponse::floquet_check(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  // the point of largest value(i) among those with ok(i)
  auto pick = [&](const std::function<bool(std::size_t)>& ok, const std::function<double(std::size_t)>& value) {
    std::size_t best = P.size();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (ok(i) && (best == P.size() || value(i) > value(best))) best = i;
    return best;
  };
  auto closed = [&](std::size_t i) { return ev.summarize(P[i].X).contact == ContactState::full; };
  auto rms = [&](std::size_t i) { return rms_ac(P[i].X); };
  auto away = [&](std::size_t i) {   // 1 % from every fold (a multiplier near +1 there is slow to resolve)
    for (const auto& f : c.branch.folds)
      if (std::fabs(f.omega - P[i].omega) < 1e-2 * f.omega) return false;
    return true;
  };
  const std::size_t full = pick([&](std::size_t i) { return c.stable[i] && closed(i) && away(i); }, rms);
  const std::size_t lost = pick([&](std::size_t i) { return c.stable[i] && !closed(i) && away(i); }, rms);
  const std::size_t unstable = pick([&](std::size_t i) { return !c.stable[i] && away(i); },
                                    [&](std::size_t i) { return c.floquet[i].modulus; });
  Table t({"label", "f_mesh_hz", "contact", "stable", "modulus_variational", "modulus_time_integration", "abs_diff"});
  const TimeIntegrator ti(hb);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  double worst = 0.0;
  for (std::size_t i : {full, lost, unstable}) {
    if (i == P.size()) continue;
    VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const Eigen::VectorXcd mu = Eigen::EigenSolver<Eigen::MatrixXd>(ti.monodromy(x0, v0, P[i].omega, opt), false).eigenvalues();
    const double m_ti = mu.cwiseAbs().maxCoeff(), d = std::fabs(m_ti - c.floquet[i].modulus);
    worst = std::max(worst, d);
    t.add_row({cs.label, hz(P[i].omega), std::string(to_string(ev.summarize(P[i].X).contact)), long(c.stable[i] ? 1 : 0),
               c.floquet[i].modulus, m_ti, d});
  }
  run.write("check_floquet_" + cs.label + ".csv", t);
  run.key_numbers().add("floquet_check_points_" + cs.label, double(t.rows()), "-");
  run.key_numbers().add("floquet_check_abs_diff_" + cs.label, worst, "-");
  long n_unstable = 0;
  for (bool st : c.stable) n_unstable += st ? 0 : 1;
  run.key_numbers().add("unstable_points_" + cs.label, double(n_unstable), "-");
}

// --case own: one curve with the user's gear.
void GearResponse::own_case(Run& run) const {
  const double F0 = own_.torque / own_.pitch_radius;
  std::vector<double> e;
  if (own_.ste_file.empty()) {
    e = ste_samples(F0 * thesis_gear_.gear.pitch_radius());   // ch. 7's gear at the same tooth force
  } else {
    e = read_ste_file(own_.ste_file, 2 * sol_.H + 1, own_.kc == 0.0 || model_.model() == DteModel::parametric).ste;
  }
  DteGear g;
  g.F0 = F0;
  g.me = own_.me > 0 ? own_.me : equivalent_mass(gear_.I1, gear_.I2, own_.pitch_radius, own_.pitch_radius);
  g.kc = own_.kc > 0 ? own_.kc : mean_stiffness(e, F0);
  g.c = mesh_damping(gear_.zeta, g.kc, g.me);
  g.ste = periodic_fourier(e, sol_.H);
  const HarmonicBalance hb = dte_harmonic_balance(g, sol_.H, sol_.N, contact_quadrature(sol_), model_.model());
  const FrequencyCurve c = sweep(run, hb, "own");
  run.write("frc.csv", response_table(g, hb, c));
  linear_reference(run, g, sol_.H, "own");
  Worst worst;
  Table bands({"label", "band", "f_lo_hz", "f_hi_hz"});
  measure(run, "own", g, model_.model(), hb, c, worst, bands);
  run.write("loss_bands.csv", bands);
  KeyNumbers& key = run.key_numbers();
  key.add("me", g.me, "kg");
  key.add("kc", g.kc, "N/m");
  key.add("c", g.c, "N s/m");
  key.add("fn", std::sqrt(g.kc / g.me) / (2 * M_PI), "Hz");
  key.add("mean_force_rel_dev", worst.mean_force, "-");
  key.add("points", double(c.branch.points.size()), "-");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch08_gear_response",
              "ch08_gear_response: the gear mesh driven by its own static transmission error (thesis ch. 8, Figs. 67, 69-70)\n"
              "  me x'' + c x' + max(kc (x + e(t)), 0) = F0,  x the dynamic transmission error, e(t) the STE");
  GearResponse chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
