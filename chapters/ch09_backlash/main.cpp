// ===========================================================================
// ch09_backlash: backlash limits the static transmission error at high torque
// (thesis ch. 9, Figs. 77-82)
// ===========================================================================
//
// Chapter 8's gear mesh, me x'' + c x' + max(kc (x + e(t)), 0) = F0, with the STE
// e(t) of ch. 7 changed in the single-pair zone A'E' where it reaches the local
// normal backlash b_n = b cos(mu) (b = 15 um nominal; lib/gearhb/gears/pair/backlash.hpp):
//   clip     e = min(e, b_n)                        (the thesis' reading, §9)
//   contact  F0 = k1 e + k2 max(e - b_n, 0)          (the adjacent pair as a unilateral
//            spring of the beam model's stiffness: the physical reading)
// kc = mean of F0 / e is recomputed from the new STE. With --set model=parametric
// every curve runs ch. 8's parametric model, me d'' + c d' + max(k(t) d, 0) = F0 with
// k(t) = F0 / e(t) on the same limited STE (where e is limited, the adjacent pair
// stiffens the mesh). The steps, in order (README
// of this chapter): normal_backlash_geometry, limited_ste, frequency_responses
// (per case: the linear closed-contact curve, measure, the time-integration check),
// backlash_effect;
// own_case for --case own.
//
// Sample runs:
//   build/bin/ch09_backlash                                    every figure's data
//   build/bin/ch09_backlash --case quick --out /tmp/q          the regression subset
//   build/bin/ch09_backlash --set backlash_model=contact       the physical reading
//   build/bin/ch09_backlash --set model=parametric             ch. 8's parametric mesh model
//   build/bin/ch09_backlash --case own --set torque=250 --set H=3 --set backlash_um=12
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/tools/gear_tables.hpp"
#include "gearhb/tools/gear_mesh_parameters.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/pair/backlash.hpp"
#include "gearhb/gears/dynamics/dte_response.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

using namespace gearhb;

namespace {

constexpr double kUm = 1e6, kDeg = 180.0 / M_PI;

// --- parameters: one struct per concern, thesis defaults (§9) --------------
// (the gear pair, the STE, the mesh model and the frequency range: GearMeshParameters, as chapter 8)
struct BacklashParameters {
  double backlash_um = 15.0;             // nominal (circumferential) backlash [um]
  std::string model = "clip";            // clip (thesis) | contact (adjacent pair as a spring)
  std::string angle = "roll";            // roll (thesis' C and E' values) | involute (b cos alpha)
  std::string values = "thesis";         // thesis (printed eps, eps') | exact (T2C = rb tan alpha)
};
struct OwnCase {
  double torque = 300.0;   // [N m]
};

// Which STE a case runs on: none = ch. 8's, chosen = the backlash_model parameter,
// other = the reading not chosen (Fig. 82 shows both).
enum class Reading { none, chosen, other };
enum class Measure { time_check };

struct Case {
  std::string label;   // file stem: frc_<label>.csv
  std::string figure;  // thesis figure
  double torque;       // [N m]
  int H;               // harmonics (and STE components kept, thesis §8.2)
  Reading reading;
  bool quick;          // part of the regression subset
  std::vector<Measure> measures;
};

const std::vector<Case> kCases = {
    {"B100_H1", "80", 100, 1, Reading::chosen, false, {}},
    {"B200_H1", "80", 200, 1, Reading::chosen, false, {}},
    {"B300_H1", "80", 300, 1, Reading::chosen, true, {}},
    {"B100_H5", "81", 100, 5, Reading::chosen, false, {}},
    {"B200_H5", "81", 200, 5, Reading::chosen, false, {}},
    {"B300_H5", "81", 300, 5, Reading::chosen, true, {Measure::time_check}},
    {"N300_H1", "82", 300, 1, Reading::none, true, {}},
    {"N300_H5", "82", 300, 5, Reading::none, true, {}},
    {"X300_H1", "82", 300, 1, Reading::other, false, {}},
    {"X300_H5", "82", 300, 5, Reading::other, false, {}},
};
const double kTorques[] = {100, 200, 300};   // Fig. 77
const std::map<std::string, BacklashModel> kModels = {{"clip", BacklashModel::clip},
                                                       {"contact", BacklashModel::contact}};
const std::map<std::string, BacklashAngle> kAngles = {{"roll", BacklashAngle::roll},
                                                       {"involute", BacklashAngle::involute}};
const std::map<std::string, BacklashValues> kValues = {{"thesis", BacklashValues::thesis_printed},
                                                        {"exact", BacklashValues::exact}};

std::string torque_tag(double T) { return "T" + std::to_string(long(std::lround(T))); }

template <class E>
E lookup(const std::map<std::string, E>& m, const std::string& key, const std::string& name) {
  const auto it = m.find(key);
  if (it != m.end()) return it->second;
  std::string all;
  for (const auto& [k, v] : m) all += (all.empty() ? "" : "|") + k;
  throw UsageError("parameter '" + name + "' must be one of " + all + ", not '" + key + "'");
}

// One curve's result, kept for the comparison of step 4.
struct CurveResult {
  const Case* cs;
  DteGear gear;
  FrequencyCurve curve;
  DteCurveReport report;
};

class BacklashChapter {
 public:
  explicit BacklashChapter(Study& study);
  void run(Run& run);

 private:
  GearMeshParameters gear_;
  BacklashParameters bl_;
  OwnCase own_;
  SolverSettings sol_;
  SteModel thesis_gear_;   // ch. 7's STE model, thesis defaults

  BacklashSettings settings(Reading r) const;
  std::string reading_name(Reading r) const;
  std::vector<BacklashPoint> cycle(double torque, const BacklashSettings& s) const;
  DteGear mesh(double torque, Reading r) const;
  void normal_backlash_geometry(Run& run) const;
  void limited_ste(Run& run) const;
  void ste_table(Run& run, double torque) const;
  std::vector<CurveResult> frequency_responses(Run& run) const;
  DteCurveReport measure(Run& run, const std::string& label, const DteGear& g, const HarmonicBalance& hb,
                         const FrequencyCurve& c) const;
  HarmonicBalance balance(const DteGear& g, int H) const;
  void backlash_effect(Run& run, const std::vector<CurveResult>& curves) const;
  DteTimeCheck peak_change(Run& run, const CurveResult& with, const CurveResult& without) const;
  void own_case(Run& run) const;
};

BacklashChapter::BacklashChapter(Study& study) {
  ParameterSet& P = study.parameters();
  add_gear_mesh_parameters(P, gear_);
  P.group("backlash (thesis §9)");
  P.add("backlash_um", &bl_.backlash_um, "um", "nominal (circumferential) backlash b", Range::between(0.0, 1000.0));
  P.add("backlash_model", &bl_.model, "-", "clip (thesis: STE = min(STE, b_n)) | contact (adjacent pair engages)");
  P.add("backlash_mu", &bl_.angle, "-", "roll (mu from alpha at C to the thesis' value at E') | involute (mu = alpha)");
  P.add("backlash_values", &bl_.values, "-", "thesis (printed eps = 4.35 deg, eps') | exact (T2C = rb tan alpha)");
  P.group("own case (--case own)", true);
  P.add("torque", &own_.torque, "N m", "transmitted torque T (ch. 7's gear)", Range::between(1e-3, 1e4));
  sol_.H = 5;
  sol_.ds_max = 0.05;
  add_solver_parameters(P, sol_, 1);
  register_cases(study, kCases);
  study.check([this, &P](const Selection& sel) {
    ParameterSet::require(sel.kind == Selection::Kind::own || !P.was_set("H"),
                          "parameter 'H' is fixed by the case table (H = 1, 5); set it with --case own");
    apply_gear_mesh_parameters(P, gear_, sol_);
    lookup(kModels, bl_.model, "backlash_model");
    lookup(kAngles, bl_.angle, "backlash_mu");
    lookup(kValues, bl_.values, "backlash_values");
  });
}

void BacklashChapter::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) {
    normal_backlash_geometry(run);
    limited_ste(run);
  }
  backlash_effect(run, frequency_responses(run));
}

// The backlash settings of a reading (none: b = infinity is not needed, see cycle()).
BacklashSettings BacklashChapter::settings(Reading r) const {
  BacklashSettings s;
  s.b = bl_.backlash_um / kUm;
  s.model = lookup(kModels, bl_.model, "backlash_model");
  if (r == Reading::other) s.model = s.model == BacklashModel::clip ? BacklashModel::contact : BacklashModel::clip;
  s.angle = lookup(kAngles, bl_.angle, "backlash_mu");
  s.values = lookup(kValues, bl_.values, "backlash_values");
  return s;
}

// The STE of ch. 7's gear at torque T with backlash (continuous, or the 8 positions).
std::vector<BacklashPoint> BacklashChapter::cycle(double torque, const BacklashSettings& s) const {
  if (gear_.ste_reading == 1) return ste_with_backlash(thesis_gear_, torque, ste_over_mesh_cycle(thesis_gear_, torque), s);
  return ste_with_backlash(thesis_gear_, torque, ste_continuous(thesis_gear_, torque, gear_.ste_samples), s);
}

// "none", or the name of the backlash model a reading runs ("clip", "contact").
std::string BacklashChapter::reading_name(Reading r) const {
  if (r == Reading::none) return "none";
  const BacklashModel m = settings(r).model;
  for (const auto& [name, v] : kModels)
    if (v == m) return name;
  return "";
}

// The 1-DOF model of the thesis' gear pair at torque T on the STE of reading r.
DteGear BacklashChapter::mesh(double torque, Reading r) const {
  const std::vector<BacklashPoint> p = cycle(torque, settings(r));
  std::vector<double> e;
  for (const auto& q : p) e.push_back(r == Reading::none ? q.ste_free : q.ste);
  return dte_gear(e, torque, thesis_gear_.gear.pitch_radius(), gear_.I1, gear_.I2, gear_.zeta);
}

// Step 1 (§9): b_n at C and at E' (A'), eps and eps', with the printed and the exact geometry.
void BacklashChapter::normal_backlash_geometry(Run& run) const {
  Table t({"values", "b_um", "alpha_deg", "rb_mm", "pb_mm", "AC_mm", "CE_prime_mm", "epsilon_deg",
           "epsilon_prime_deg", "mu_C_deg", "mu_E_prime_deg", "bn_C_um", "bn_E_prime_um", "bn_A_prime_um"});
  for (const auto& [name, v] : kValues) {
    const BacklashGeometry g = backlash_geometry(thesis_gear_.gear, bl_.backlash_um / kUm, v);
    t.add_row({name, g.b * kUm, g.alpha * kDeg, g.rb * 1e3, g.pb * 1e3, g.AC * 1e3, g.CE_prime * 1e3,
               g.epsilon * kDeg, g.epsilon_prime * kDeg, g.mu_C * kDeg, g.mu_E_prime * kDeg, g.bn_C * kUm,
               g.bn_E_prime * kUm, g.bn_A_prime * kUm});
    KeyNumbers& key = run.key_numbers();
    key.add("bn_C_um", g.bn_C * kUm, "um");
    key.add("epsilon_deg_" + name, g.epsilon * kDeg, "deg");
    key.add("epsilon_prime_deg_" + name, g.epsilon_prime * kDeg, "deg");
    key.add("CE_prime_mm_" + name, g.CE_prime * 1e3, "mm");
    key.add("mu_E_prime_deg_" + name, g.mu_E_prime * kDeg, "deg");
    key.add("bn_E_prime_um_" + name, g.bn_E_prime * kUm, "um");
  }
  run.write("backlash_geometry.csv", t);
}

// Step 2 (Figs. 77-79): the STE with and without backlash, both readings, per torque.
void BacklashChapter::limited_ste(Run& run) const {
  Table spectrum({"torque", "k", "free_um", "clip_um", "contact_um"});
  for (double T : kTorques) {
    ste_table(run, T);
    BacklashSettings s = settings(Reading::chosen);
    s.model = BacklashModel::clip;
    const std::vector<BacklashPoint> clip = cycle(T, s);
    s.model = BacklashModel::contact;
    const std::vector<BacklashPoint> contact = cycle(T, s);
    std::vector<double> free;
    for (const auto& p : clip) free.push_back(p.ste_free);
    const Eigen::VectorXd A0 = periodic_fourier(free, 20), Ac = periodic_fourier(ste_values(clip), 20),
                          Ak = periodic_fourier(ste_values(contact), 20);
    for (int k = 1; k <= 20; ++k)
      spectrum.add_row({T, long(k), std::hypot(A0[2 * k - 1], A0[2 * k]) * kUm,
                        std::hypot(Ac[2 * k - 1], Ac[2 * k]) * kUm, std::hypot(Ak[2 * k - 1], Ak[2 * k]) * kUm});
    const double F = T / thesis_gear_.gear.pitch_radius();
    KeyNumbers& key = run.key_numbers();
    const std::string tag = torque_tag(T);
    key.add("kc_free_" + tag, mean_stiffness(free, F), "N/m");
    key.add("kc_clip_" + tag, mean_stiffness(ste_values(clip), F), "N/m");
    key.add("kc_contact_" + tag, mean_stiffness(ste_values(contact), F), "N/m");
    const auto n_limited = std::count_if(clip.begin(), clip.end(), [](const auto& p) { return p.limited; });
    key.add("limited_samples_clip_" + tag, double(n_limited), "-");
    key.add("limited_" + tag, n_limited > 0 ? 1.0 : 0.0, "-");
    key.add("max_ste_free_um_" + tag, *std::max_element(free.begin(), free.end()) * kUm, "um");
    const std::vector<double> ec = ste_values(clip), ek = ste_values(contact);
    key.add("max_ste_clip_um_" + tag, *std::max_element(ec.begin(), ec.end()) * kUm, "um");
    key.add("max_ste_contact_um_" + tag, *std::max_element(ek.begin(), ek.end()) * kUm, "um");
  }
  run.write("fig78_spectrum.csv", spectrum);
  BacklashSettings s = settings(Reading::chosen);
  s.model = BacklashModel::clip;   // the thesis' own STE: 8 positions, clipped
  const auto p8 = ste_with_backlash(thesis_gear_, 300.0, ste_over_mesh_cycle(thesis_gear_, 300.0), s);
  run.key_numbers().add("kc_p8_clip_T300", mean_stiffness(ste_values(p8), 300.0 / thesis_gear_.gear.pitch_radius()), "N/m");
}

// One torque's STE over the mesh cycle: without backlash, b_n, clip and contact readings.
void BacklashChapter::ste_table(Run& run, double torque) const {
  BacklashSettings s = settings(Reading::chosen);
  s.model = BacklashModel::clip;
  const std::vector<BacklashPoint> clip = cycle(torque, s);
  s.model = BacklashModel::contact;
  const std::vector<BacklashPoint> contact = cycle(torque, s);
  Table t({"phase", "s_mm", "pairs", "ste_um", "bn_um", "ste_clip_um", "ste_contact_um", "adjacent_force"});
  for (std::size_t j = 0; j < clip.size(); ++j) {
    const BacklashPoint& p = clip[j];
    t.add_row({p.phase, p.s * 1e3, long(p.pairs), p.ste_free * kUm,
               p.pairs == 1 ? Table::Cell(p.bn * kUm) : Table::Cell(std::string()), p.ste * kUm,
               contact[j].ste * kUm, contact[j].adjacent_force});
  }
  run.write("fig77_" + torque_tag(torque) + ".csv", t);
}

// The harmonic balance of the mesh with H harmonics, the run's mesh model.
HarmonicBalance BacklashChapter::balance(const DteGear& g, int H) const {
  return dte_harmonic_balance(g, H, sol_.N, contact_quadrature(sol_), mesh_model(gear_));
}

// Step 3 (Figs. 80-82): one continuation per case of the table.
std::vector<CurveResult> BacklashChapter::frequency_responses(Run& run) const {
  Table index({"label", "figure", "model", "torque", "H", "reading", "F0", "me", "kc", "c", "points", "folds", "bifurcations",
               "peak_rms_um", "peak_f_hz"});
  std::vector<std::pair<std::string, DteCurveReport>> reports;
  std::vector<std::pair<std::string, DteTimeCheck>> checks;
  std::vector<CurveResult> out;
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const DteGear g = mesh(cs.torque, cs.reading);
    const HarmonicBalance hb = balance(g, cs.H);
    const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), cs.label, sol_.period_doubling_depth);
    const FrequencyCurve& c = s.curve;
    run.write("frc_" + cs.label + ".csv", mesh_response_table(hb, c, s.doubled));
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c, s.doubled));
    run.write("linear_" + cs.label + ".csv", linear_mesh_table(g, cs.H, sol_.omega_min, sol_.omega_max));
    const DteCurveReport rep = measure(run, cs.label, g, hb, c);
    reports.push_back({cs.label, rep});
    out.push_back({&cs, g, c, rep});
    index.add_row({cs.label, cs.figure, std::string(to_string(mesh_model(gear_))), cs.torque, long(cs.H),
                   reading_name(cs.reading), g.F0, g.me, g.kc, g.c, long(c.branch.points.size()),
                   long(c.branch.folds.size()), long(c.bifurcations.size()), rep.peak_rms * kUm, hz(rep.peak_omega)});
    if (measures(cs, Measure::time_check)) checks.push_back({cs.label, timed_dte_time_check(run, cs.label, hb, c)});
  }
  run.write("cases.csv", index);
  run.write("loss_bands.csv", loss_band_table(reports));
  if (!checks.empty()) run.write("check_time_integration.csv", dte_time_integration_table(checks));
  return out;
}

// Contact-loss bands, first loss, peak, and ch. 8's two checks at every point
// (the closed form for the constant model only).
DteCurveReport BacklashChapter::measure(Run& run, const std::string& label, const DteGear& g,
                                        const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const DteCurveReport r = dte_curve_report(g, hb, c, mesh_model(gear_));
  KeyNumbers& key = run.key_numbers();
  key.add("kc_" + label, g.kc, "N/m");
  key.add("peak_rms_um_" + label, r.peak_rms * kUm, "um");
  key.add("peak_f_hz_" + label, hz(r.peak_omega), "Hz");
  key.add("loss_bands_" + label, double(r.loss_bands.size()), "-");
  if (std::isfinite(r.first_loss_omega)) key.add("loss_onset_hz_" + label, hz(r.first_loss_omega), "Hz");
  key.add("mean_force_rel_dev_" + label, r.mean_force_rel_dev, "-");
  if (r.closed_points > 0) key.add("closed_form_rel_diff_" + label, r.closed_form_rel_diff, "-");
  return r;
}

// Step 4 (§9: "the 300 N m peak drops and moves closer to 200 N m"): each curve with
// backlash against the curve without it (same torque and H), and against the next
// lower torque with backlash (the gap between the peaks).
void BacklashChapter::backlash_effect(Run& run, const std::vector<CurveResult>& curves) const {
  std::vector<std::pair<std::string, DteTimeCheck>> near;
  for (const auto& a : curves) {
    if (a.cs->reading != Reading::chosen) continue;
    for (const auto& b : curves) {
      if (b.cs->H != a.cs->H) continue;
      if (b.cs->torque == a.cs->torque && b.cs->reading == Reading::none) {
        const DteTimeCheck chk = peak_change(run, a, b);
        near.push_back({a.cs->label, {{chk.rows[0]}, chk.rows[0].rel_diff}});
        near.push_back({b.cs->label, {{chk.rows[1]}, chk.rows[1].rel_diff}});
      }
      if (b.cs->reading == Reading::chosen && b.cs->torque < a.cs->torque && b.cs->torque >= a.cs->torque - 100.0)
        run.key_numbers().add("peak_gap_um_" + a.cs->label + "_vs_" + b.cs->label,
                              (a.report.peak_rms - b.report.peak_rms) * kUm, "um");
    }
  }
  if (!near.empty()) run.write("check_near_peak_time_integration.csv", dte_time_integration_table(near));
}

// The change of the peak by harmonic balance, and its check: the highest stable
// points away from the folds of both curves integrated in time (GSL rk8pd); the
// change between them by HB and by time integration must agree.
DteTimeCheck BacklashChapter::peak_change(Run& run, const CurveResult& with, const CurveResult& without) const {
  KeyNumbers& key = run.key_numbers();
  const std::string tag = with.cs->label + "_vs_" + without.cs->label;
  key.add("peak_change_um_" + tag, (with.report.peak_rms - without.report.peak_rms) * kUm, "um");
  key.add("peak_lower_" + tag, with.report.peak_rms < without.report.peak_rms ? 1.0 : 0.0, "-");
  key.add("peak_shift_hz_" + tag, hz(with.report.peak_omega - without.report.peak_omega), "Hz");
  DteTimeComparison near[2];
  run.timed("time integration near the peaks " + tag, [&] {
    for (int k = 0; k < 2; ++k) {
      const CurveResult& r = k == 0 ? with : without;
      const HarmonicBalance hb = balance(r.gear, r.cs->H);
      const std::size_t i = dte_near_peak_point(r.curve);
      if (i == r.curve.branch.points.size()) throw std::runtime_error(r.cs->label + ": no stable point near the peak");
      near[k] = dte_time_integration_point(hb, r.curve, i);
    }
    return 0;
  });
  const double hb = near[0].rms_hb - near[1].rms_hb, ti = near[0].rms_time_integration - near[1].rms_time_integration;
  key.add("near_peak_change_hb_um_" + tag, hb * kUm, "um");
  key.add("near_peak_change_ti_um_" + tag, ti * kUm, "um");
  key.add("near_peak_change_diff_um_" + tag, std::fabs(hb - ti) * kUm, "um");
  return {{near[0], near[1]}, std::max(near[0].rel_diff, near[1].rel_diff)};
}

// --case own: one curve of ch. 7's gear at the user's torque with the chosen reading.
void BacklashChapter::own_case(Run& run) const {
  const DteGear g = mesh(own_.torque, Reading::chosen);
  const HarmonicBalance hb = balance(g, sol_.H);
  const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  run.write("frc.csv", mesh_response_table(hb, c, s.doubled));
  run.write("bifurcations.csv", bifurcation_table(c, s.doubled));
  run.write("linear_own.csv", linear_mesh_table(g, sol_.H, sol_.omega_min, sol_.omega_max));
  const DteCurveReport rep = measure(run, "own", g, hb, c);
  run.write("loss_bands.csv", loss_band_table({{"own", rep}}));
  KeyNumbers& key = run.key_numbers();
  key.add("fn", hz(std::sqrt(g.kc / g.me)), "Hz");
  key.add("folds", double(c.branch.folds.size()), "-");
  key.add("bifurcations", double(c.bifurcations.size()), "-");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch09_backlash",
              "ch09_backlash: backlash limits the static transmission error at high torque (thesis ch. 9, Figs. 77-82)\n"
              "  me x'' + c x' + max(kc (x + e(t)), 0) = F0 with e(t) limited by the normal backlash b cos(mu)");
  BacklashChapter chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
