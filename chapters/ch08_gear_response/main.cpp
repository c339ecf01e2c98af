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
// (lib/gearhb/gears/dynamics/dte_model.hpp). Harmonic balance with the static term, exact
// projection of the contact law, one arc-length continuation per curve,
// Floquet stability of every point (lib/gearhb/hb). The steps, in order (README
// of this chapter): mesh_stiffness, gear_constants, frequency_responses (per
// case: the linear closed-contact curve, measure, the time-integration check, time_history,
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
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/tools/gear_tables.hpp"
#include "gearhb/tools/gear_mesh_parameters.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/dynamics/dte_response.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/gears/pair/ste_file.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;
using Eigen::VectorXd;

namespace {

constexpr double kUm = 1e6;   // m -> um

// --- parameters: one struct per concern, thesis defaults (§8.1) ------------
// (the gear pair, the STE, the mesh model (constant | parametric) and the frequency
// range: GearMeshParameters, tools/gear_mesh_parameters.hpp, shared with chapter 9)
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

std::string torque_tag(double T) { return "T" + std::to_string(long(std::lround(T))); }

// The worst values of the chapter's own checks over every point computed.
struct Worst {
  double mean_force = 0.0, closed_form = 0.0;
  long closed_points = 0;
  void add(const DteCurveReport& r) {
    mean_force = std::max(mean_force, r.mean_force_rel_dev);
    closed_form = std::max(closed_form, r.closed_form_rel_diff);
    closed_points += r.closed_points;
  }
};

class GearResponse {
 public:
  explicit GearResponse(Study& study);
  void run(Run& run);

 private:
  GearMeshParameters gear_;
  OwnCase own_;
  SolverSettings sol_;
  SteModel thesis_gear_;   // ch. 7's STE model, thesis defaults

  std::vector<double> ste_samples(double torque) const;
  DteGear mesh(double torque) const;
  void mesh_stiffness(Run& run) const;
  void gear_constants(Run& run) const;
  void frequency_responses(Run& run) const;
  DteCurveReport measure(Run& run, const std::string& label, const DteGear& g, DteModel model,
                         const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void time_history(Run& run, const DteGear& g, DteModel model, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void peak_check(Run& run, const Case& cs, const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void floquet_check(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  DteModel model_of(const Case& cs) const { return cs.parametric ? DteModel::parametric : mesh_model(gear_); }
  void own_case(Run& run) const;
  void check(const Selection& sel);
};

GearResponse::GearResponse(Study& study) {
  ParameterSet& P = study.parameters();
  add_gear_mesh_parameters(P, gear_);
  P.group("own case (--case own)", true);
  P.add("torque", &own_.torque, "N m", "transmitted torque T", Range::between(1e-3, 1e5));
  P.add("pitch_radius", &own_.pitch_radius, "m", "pitch radius r of both wheels", Range::between(1e-3, 10.0));
  P.add("me", &own_.me, "kg", "equivalent mass (0 = from I1, I2, r)", Range::between(0.0, 1e6));
  P.add("kc", &own_.kc, "N/m", "mesh stiffness (0 = mean of F0/e(t))", Range::between(0.0, 1e13));
  P.add("ste_file", &own_.ste_file, "path", "STE as CSV 'phase,ste_um' (empty = ch. 7's STE)");
  sol_.H = 5;
  sol_.omega_min = 2 * M_PI * gear_.f_min_hz;
  sol_.omega_max = 2 * M_PI * gear_.f_max_hz;
  sol_.ds_max = 0.05;
  add_solver_parameters(P, sol_, 1);
  register_cases(study, kCases);
  study.check([this, &P](const Selection& sel) {
    ParameterSet::require(sel.kind == Selection::Kind::own || !P.was_set("H"),
                          "parameter 'H' is fixed by the case table (H = 1, 5, 10, 20); set it with --case own");
    apply_gear_mesh_parameters(P, gear_, sol_);
    check(sel);
  });
}

void GearResponse::check(const Selection& sel) {
  if (sel.kind != Selection::Kind::own) return;
  ParameterSet::require(own_.ste_file.empty() || gear_.ste_reading == 0,
                        "ste_reading applies to ch. 7's STE, not to an ste_file");
  if (!own_.ste_file.empty()) {
    const bool parametric = mesh_model(gear_) == DteModel::parametric;
    try {
      const std::vector<double> e = read_ste_file(own_.ste_file, 2 * sol_.H + 1, own_.kc == 0.0 || parametric).ste;
      // the parametric stiffness F0 / e needs the STE cut to H harmonics positive
      const VectorXd eh = Aft(sol_.H, 64 * (2 * sol_.H + 1)).to_time(periodic_fourier(e, sol_.H));
      ParameterSet::require(!parametric || eh.minCoeff() > 0.0,
                            own_.ste_file + ": model=parametric needs the STE cut to H harmonics > 0 over the cycle");
    } catch (const SteFileError& e) {
      throw UsageError("parameter 'ste_file': " + std::string(e.what()));
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
  if (gear_.ste_reading == 1) return ste_values(ste_over_mesh_cycle(thesis_gear_, torque));
  return ste_values(ste_continuous(thesis_gear_, torque, gear_.ste_samples));
}

// The 1-DOF model of the thesis' gear pair at torque T (§8.1), STE harmonics up to 20.
DteGear GearResponse::mesh(double torque) const {
  return dte_gear(ste_samples(torque), torque, thesis_gear_.gear.pitch_radius(), gear_.I1, gear_.I2, gear_.zeta);
}

// Step 1 (Fig. 67): the STE and k(t) = F0 / e(t) over one mesh cycle, both readings.
void GearResponse::mesh_stiffness(Run& run) const {
  Table spectrum({"torque", "k", "amplitude_um", "amplitude_p8_um"});
  for (double T : kTorques) {
    const double F = T / thesis_gear_.gear.pitch_radius();
    const std::vector<double> ec = ste_values(ste_continuous(thesis_gear_, T, gear_.ste_samples));
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
  key.add("fn_T300", hz(std::sqrt(g.kc / g.me)), "Hz");
  run.say("me = " + std::to_string(g.me) + " kg, kc(300 N m) = " + std::to_string(g.kc * 1e-6) +
          " MN/m, c = " + std::to_string(g.c) + " N s/m, fn = " +
          std::to_string(hz(std::sqrt(g.kc / g.me))) + " Hz");
}

// Step 3 (Figs. 69-70, H-convergence): one continuation per case of the table.
void GearResponse::frequency_responses(Run& run) const {
  Table index({"label", "figure", "model", "torque", "H", "F0", "me", "kc", "c", "points", "folds", "bifurcations",
               "peak_rms_um", "peak_f_hz"});
  std::vector<std::pair<std::string, DteCurveReport>> reports;
  std::vector<std::pair<std::string, DteTimeCheck>> checks;
  Worst worst;
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const DteGear g = mesh(cs.torque);
    const DteModel model = model_of(cs);
    const HarmonicBalance hb = dte_harmonic_balance(g, cs.H, sol_.N, contact_quadrature(sol_), model);
    const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), cs.label, sol_.period_doubling_depth);
    const FrequencyCurve& c = s.curve;
    run.write("frc_" + cs.label + ".csv", mesh_response_table(hb, c, s.doubled));
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c, s.doubled));
    run.write("linear_" + cs.label + ".csv", linear_mesh_table(g, cs.H, sol_.omega_min, sol_.omega_max));
    const DteCurveReport rep = measure(run, cs.label, g, model, hb, c);
    worst.add(rep);
    reports.push_back({cs.label, rep});
    index.add_row({cs.label, cs.figure, std::string(to_string(model)), cs.torque, long(cs.H), g.F0, g.me, g.kc, g.c,
                   long(c.branch.points.size()), long(c.branch.folds.size()), long(c.bifurcations.size()),
                   rep.peak_rms * kUm, hz(rep.peak_omega)});
    if (measures(cs, Measure::time_check)) checks.push_back({cs.label, timed_dte_time_check(run, cs.label, hb, c)});
    if (measures(cs, Measure::time_history)) time_history(run, g, model, hb, c);
    if (measures(cs, Measure::peak)) peak_check(run, cs, g, hb, c);
    if (measures(cs, Measure::floquet)) floquet_check(run, cs, hb, c);
  }
  run.write("cases.csv", index);
  run.write("loss_bands.csv", loss_band_table(reports));
  if (!checks.empty()) run.write("check_time_integration.csv", dte_time_integration_table(checks));
  if (worst.closed_points > 0) run.key_numbers().add("closed_form_rel_diff", worst.closed_form, "-");
  run.key_numbers().add("mean_force_rel_dev", worst.mean_force, "-");
}

// Contact-loss bands, the first loss refined on the branch, the peak, the mean
// contact force (either model) and, constant model, the closed form at every
// full-contact point (dte_response.hpp).
DteCurveReport GearResponse::measure(Run& run, const std::string& label, const DteGear& g, DteModel model,
                                     const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const DteCurveReport r = dte_curve_report(g, hb, c, model);
  KeyNumbers& key = run.key_numbers();
  key.add("loss_bands_" + label, double(r.loss_bands.size()), "-");
  key.add("contact_loss_" + label, r.loss_bands.empty() ? 0.0 : 1.0, "-");
  if (std::isfinite(r.first_loss_omega)) key.add("loss_onset_hz_" + label, hz(r.first_loss_omega), "Hz");
  key.add("peak_rms_um_" + label, r.peak_rms * kUm, "um");
  return r;
}

// Supplement: x(t), e(t) and the contact force over two mesh periods at the
// stable contact-loss point of largest RMS. The parametric model's unknown is the
// mesh deflection d: its dynamic transmission error is x = d - e.
void GearResponse::time_history(Run& run, const DteGear& g, DteModel model, const HarmonicBalance& hb,
                                const FrequencyCurve& c) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  std::size_t pick = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (c.stable[i] && ev.summarize(P[i].X).contact != ContactState::full &&
        (pick == P.size() || rms_ac(P[i].X) > rms_ac(P[pick].X)))
      pick = i;
  if (pick == P.size()) throw std::runtime_error("time_history: no stable contact-loss point on the curve");
  const VectorXd x = ev.history(P[pick].X);
  const VectorXd force = ev.contact_force_history(P[pick].X, 0);   // the model's own law (constant or parametric)
  const Aft fine(hb.harmonics(), int(x.size()));
  const VectorXd e = fine.to_time(ste_harmonics(g, hb.harmonics()));
  const double T = 2 * M_PI / P[pick].omega;
  Table t({"t_ms", "x_um", "e_um", "contact_force"});
  for (int period = 0; period < 2; ++period)
    for (int j = 0; j < x.size(); ++j)
      t.add_row({1e3 * T * (period + double(j) / x.size()),
                 (model == DteModel::parametric ? x[j] - e[j] : x[j]) * kUm, e[j] * kUm, force[j]});
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
  const std::size_t pick = dte_peak_below_fold_point(c);
  if (pick == c.branch.points.size())
    throw std::runtime_error(cs.label + ": no stable point below the first fold for the peak check");
  const HarmonicBalance full = dte_harmonic_balance(g, kFullSte, 0, ContactQuadrature::exact, model_of(cs));
  const DteTimeComparison r = run.timed("peak check " + cs.label, [&] {
    try {
      return dte_time_integration_point(hb, c, pick, full);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(cs.label + ": peak check: " + e.what());
    }
  });
  KeyNumbers& key = run.key_numbers();
  key.add("peak_check_f_hz_" + cs.label, hz(r.omega), "Hz");
  key.add("peak_check_rms_hb_um_" + cs.label, r.rms_hb * kUm, "um");
  key.add("peak_check_rms_ti_um_" + cs.label, r.rms_time_integration * kUm, "um");
  key.add("peak_check_rel_diff_" + cs.label, r.rel_diff, "-");
}

// Floquet multipliers of the parametric model (variational equation about the HB
// orbit, hb/floquet.hpp) against GSL's variational equation integrated along the
// orbit itself (TimeIntegrator::monodromy, from the HB state): at the stable
// full-contact point of largest RMS, the stable contact-loss point of largest RMS
// and the unstable point of largest |mu| (where present), all 1 % away from folds.
void GearResponse::floquet_check(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const DteFloquetCheck chk = run.timed("floquet check " + cs.label, [&] { return dte_floquet_check(hb, c); });
  run.write("check_floquet_" + cs.label + ".csv", dte_floquet_table(cs.label, chk));
  run.key_numbers().add("floquet_check_points_" + cs.label, double(chk.rows.size()), "-");
  run.key_numbers().add("floquet_check_abs_diff_" + cs.label, chk.worst_abs_diff, "-");
  run.key_numbers().add("unstable_points_" + cs.label, double(chk.unstable_points), "-");
}

// --case own: one curve with the user's gear.
void GearResponse::own_case(Run& run) const {
  const double F0 = own_.torque / own_.pitch_radius;
  std::vector<double> e;
  if (own_.ste_file.empty()) {
    e = ste_samples(F0 * thesis_gear_.gear.pitch_radius());   // ch. 7's gear at the same tooth force
  } else {
    e = read_ste_file(own_.ste_file, 2 * sol_.H + 1, own_.kc == 0.0 || mesh_model(gear_) == DteModel::parametric).ste;
  }
  DteGear g;
  g.F0 = F0;
  g.me = own_.me > 0 ? own_.me : equivalent_mass(gear_.I1, gear_.I2, own_.pitch_radius, own_.pitch_radius);
  g.kc = own_.kc > 0 ? own_.kc : mean_stiffness(e, F0);
  g.c = mesh_damping(gear_.zeta, g.kc, g.me);
  g.ste = periodic_fourier(e, sol_.H);
  const HarmonicBalance hb = dte_harmonic_balance(g, sol_.H, sol_.N, contact_quadrature(sol_), mesh_model(gear_));
  const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  run.write("frc.csv", mesh_response_table(hb, c, s.doubled));
  run.write("bifurcations.csv", bifurcation_table(c, s.doubled));
  run.write("linear_own.csv", linear_mesh_table(g, sol_.H, sol_.omega_min, sol_.omega_max));
  const DteCurveReport rep = measure(run, "own", g, mesh_model(gear_), hb, c);
  run.write("loss_bands.csv", loss_band_table({{"own", rep}}));
  KeyNumbers& key = run.key_numbers();
  key.add("me", g.me, "kg");
  key.add("kc", g.kc, "N/m");
  key.add("c", g.c, "N s/m");
  key.add("fn", hz(std::sqrt(g.kc / g.me)), "Hz");
  key.add("mean_force_rel_dev", rep.mean_force_rel_dev, "-");
  key.add("points", double(c.branch.points.size()), "-");
  key.add("folds", double(c.branch.folds.size()), "-");
  key.add("bifurcations", double(c.bifurcations.size()), "-");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch08_gear_response",
              "ch08_gear_response: the gear mesh driven by its own static transmission error (thesis ch. 8, Figs. 67, 69-70)\n"
              "  me x'' + c x' + max(kc (x + e(t)), 0) = F0,  x the dynamic transmission error, e(t) the STE");
  GearResponse chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
