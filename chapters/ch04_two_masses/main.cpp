// ===========================================================================
// ch04_two_masses: two masses that can touch each other (thesis ch. 4, Figs. 20-23)
// ===========================================================================
//
//     m x1'' + c11 x1' + k x1 + Fc = F0_1 + Fa_1 cos(omega t)
//     m x2'' + c22 x2' + k x2 - Fc = F0_2 + Fa_2 cos(omega t)     Fc = max( kc (g + x1 - x2), 0 )
//
// i.e. M x'' + C x' + K x + n Fc = f0 + f cos(omega t) with the contact normal n = [1, -1]:
// the masses touch when the relative displacement d = x1 - x2 exceeds -g (g < 0 a
// clearance, g > 0 a preload); the contact pushes mass 1 back (-x) and mass 2 forward
// (+x) (library sign convention, README "Conventions"). Each mass is tied to ground by
// k; Rayleigh damping C = alpha M + beta K with K the support springs (thesis §4).
// With equal masses and supports s = (x1 + x2)/2 never strains the contact and d obeys
// the mass-against-wall oscillator of ch. 3 (contact 2 kc, force Fa_1 - Fa_2): chapter README.
//
// The steps, in order (chapter README "Steps"): normal_modes, frequency_responses (per
// case: its curves and what the case table says it measures: deviation_from_linear,
// onset_and_peak, time_integration_check); own_case for --case own.
//
// Sample runs:
//   build/bin/ch04_two_masses                                  every figure's data
//   build/bin/ch04_two_masses --case quick --out /tmp/q        the regression subset
//   build/bin/ch04_two_masses --case own --set gap=-0.02 --set Fa_1=0.05 --out /tmp/mine
//   build/bin/ch04_two_masses --case g-0.005 --set H=20        one curve of the table
// ===========================================================================
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults (§4, §4.3) ---------
struct TwoMasses {
  double m = 1.0;       // each mass [kg]
  double k = 5.0;       // each support spring to ground [N/m]
  double kc = 2.0;      // contact stiffness on x1 - x2 [N/m]
  double alpha = 0.0;   // Rayleigh, mass-proportional [1/s]
  double beta = 0.01;   // Rayleigh, stiffness-proportional [s]
};
struct Loading {
  double gap = -0.005;  // g [m]: < 0 clearance, > 0 preload
  double Fa_1 = 0.025;  // harmonic force amplitude on mass 1 [N] (the thesis' F1)
  double Fa_2 = 0.02;   // harmonic force amplitude on mass 2 [N] (the thesis' F2)
  double F0_1 = 0.0;    // static force on mass 1 [N]
  double F0_2 = 0.0;    // static force on mass 2 [N]
};
struct Checks {
  int check_points = 8; // HB vs time-integration comparisons
};

// What a case of the table measures besides its curve, its contact-state counts and folds.
enum class Measure {
  open_linear,       // never touches: the curve must be the open linear response
  closed_linear,     // never separates: the curve must be the closed linear response
  onset_and_peak,    // contact onset, peak of d_max, upper fold
  time_integration,  // HB d_max against GSL time integration
};

struct Case {
  std::string label;    // file stem: frc_<label>.csv
  std::string figure;   // thesis figure
  Loading load;
  bool quick;           // part of the regression subset
  std::vector<Measure> measures;
};

// The thesis' cases (Figs. 20-23): Fa_1 = 0.025 N, Fa_2 = 0.02 N (its F1, F2), four gaps.
const std::vector<Case> kCases = {
    {"g-0.5", "20", {-0.5, 0.025, 0.02, 0.0, 0.0}, true, {Measure::open_linear}},
    {"g-0.005", "21", {-0.005, 0.025, 0.02, 0.0, 0.0}, true, {Measure::onset_and_peak, Measure::time_integration}},
    {"g0.15", "22", {0.15, 0.025, 0.02, 0.0, 0.0}, true, {Measure::closed_linear}},
    {"g0.6", "23", {0.6, 0.025, 0.02, 0.0, 0.0}, true, {Measure::closed_linear}},
};

const Vector2d kNormal(1.0, -1.0);   // d = x1 - x2 = n' x, the plotted coordinate

struct ContactCounts {
  long intermittent = 0, full = 0;
};

class TwoMassesChapter {
 public:
  explicit TwoMassesChapter(Study& study);
  void run(Run& run);

 private:
  TwoMasses sys_;
  Loading own_;
  Checks checks_;
  SolverSettings sol_;

  LinearSystem open_system() const;
  HarmonicBalance model(const Loading& l) const;
  void write_curves(Run& run, const HarmonicBalance& hb, const SweptCurve& s, const std::string& label) const;
  void normal_modes(Run& run) const;
  void frequency_responses(Run& run) const;
  void measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
               const ContactCounts& n) const;
  double deviation_from_linear(const HarmonicBalance& hb, const FrequencyCurve& c, bool closed) const;
  void onset_and_peak(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void time_integration_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void own_case(Run& run) const;
};

TwoMassesChapter::TwoMassesChapter(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("two masses");
  P.add("m", &sys_.m, "kg", "each mass", Range::mass());
  P.add("k", &sys_.k, "N/m", "each support spring to ground", Range::positive());
  P.add("kc", &sys_.kc, "N/m", "contact stiffness on x1 - x2", Range::nonnegative());
  P.add("rayleigh_alpha", &sys_.alpha, "1/s", "Rayleigh damping C = alpha M + beta K, mass-proportional",
        Range::nonnegative());
  P.add("rayleigh_beta", &sys_.beta, "s", "Rayleigh damping C = alpha M + beta K, stiffness-proportional",
        Range::nonnegative());
  P.renamed("alpha", "rayleigh_alpha");
  P.renamed("beta", "rayleigh_beta");
  P.group("own case (--case own)", true);
  P.add("gap", &own_.gap, "m", "g: < 0 clearance, > 0 preload");
  P.add("Fa_1", &own_.Fa_1, "N", "harmonic force amplitude on mass 1 (the thesis' F1)");
  P.add("Fa_2", &own_.Fa_2, "N", "harmonic force amplitude on mass 2 (the thesis' F2)");
  P.add("F0_1", &own_.F0_1, "N", "static force on mass 1");
  P.add("F0_2", &own_.F0_2, "N", "static force on mass 2");
  P.renamed("F1", "Fa_1");
  P.renamed("F2", "Fa_2");
  P.renamed("F01", "F0_1");
  P.renamed("F02", "F0_2");
  sol_.omega_min = 1.0;   // the thesis gives no range: 1-4 rad/s holds both natural frequencies
  sol_.omega_max = 4.0;
  add_solver_parameters(P, sol_, 2);
  P.group("checks");
  P.add("check_points", &checks_.check_points, "-", "HB vs time-integration comparisons", Range::between(1, 50));
  register_cases(study, kCases);
  study.check([this](const Selection&) { check_solver_settings(sol_); });
}

void TwoMassesChapter::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) normal_modes(run);
  frequency_responses(run);
}

LinearSystem TwoMassesChapter::open_system() const {
  const MatrixXd M = sys_.m * MatrixXd::Identity(2, 2), K = sys_.k * MatrixXd::Identity(2, 2);
  return {M, rayleigh_damping(M, K, sys_.alpha, sys_.beta), K};
}

HarmonicBalance TwoMassesChapter::model(const Loading& l) const {
  UnilateralContact contact{kNormal, sys_.kc, l.gap, {}};
  Excitation f{Vector2d(l.F0_1, l.F0_2), Vector2d(l.Fa_1, l.Fa_2), VectorXd::Zero(2)};
  return HarmonicBalance(open_system(), {contact}, f, sol_.H, sol_.N, contact_quadrature(sol_));
}

// One curve and its period-doubled branches as three tables, d = x1 - x2 (frc<label>.csv) and
// each mass (frc<label>_x1/_x2.csv), and its bifurcations (bifurcations<label>.csv); label ""
// or "_<case>".
void TwoMassesChapter::write_curves(Run& run, const HarmonicBalance& hb, const SweptCurve& s,
                                    const std::string& label) const {
  const std::string stem = "frc" + label;
  run.write(stem + ".csv", frequency_response_table(hb, s.curve, s.doubled, kNormal));
  run.write("bifurcations" + label + ".csv", bifurcation_table(s.curve, s.doubled));
  run.write(stem + "_x1.csv", frequency_response_table(hb, s.curve, s.doubled, Vector2d(1, 0)));
  run.write(stem + "_x2.csv", frequency_response_table(hb, s.curve, s.doubled, Vector2d(0, 1)));
}

// Step 1 (thesis §4.1): natural frequencies and mass-normalised shapes, contact open and
// closed; Phi' M Phi = I and Phi' K Phi = diag(omega_i^2) are checked rather than assumed.
void TwoMassesChapter::normal_modes(Run& run) const {
  const LinearSystem open = open_system();
  const MatrixXd Kc = sys_.kc * kNormal * kNormal.transpose();
  Table t({"state", "mode", "omega", "phi_x1", "phi_x2"});
  for (bool closed : {false, true}) {
    const MatrixXd K = closed ? MatrixXd(open.K + Kc) : open.K;
    const Modes md = modal_analysis(open.M, K);
    const std::string st = closed ? "closed" : "open";
    const MatrixXd PMP = md.Phi.transpose() * open.M * md.Phi;
    const MatrixXd PKP = md.Phi.transpose() * K * md.Phi;
    const MatrixXd W2 = md.omega.cwiseProduct(md.omega).asDiagonal();
    run.key_numbers().add("mass_normalisation_error_" + st, (PMP - MatrixXd::Identity(2, 2)).cwiseAbs().maxCoeff(), "-");
    run.key_numbers().add("stiffness_diagonalisation_error_" + st, (PKP - W2).cwiseAbs().maxCoeff() / W2.maxCoeff(), "-");
    for (int j = 0; j < 2; ++j) {
      run.key_numbers().add("omega_" + st + "_" + std::to_string(j + 1), md.omega[j], "rad/s");
      t.add_row({st, long(j + 1), md.omega[j], md.Phi(0, j), md.Phi(1, j)});
    }
  }
  run.write("modes.csv", t);
}

// Step 2 (Figs. 20-23): one continuation per case of the table, its contact-state
// counts, and what the case measures.
void TwoMassesChapter::frequency_responses(Run& run) const {
  Table index({"label", "figure", "gap", "Fa_1", "Fa_2", "F0_1", "F0_2", "points", "folds", "rejected_steps",
               "intermittent_points", "full_points"});
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const HarmonicBalance hb = model(cs.load);
    const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), cs.label, sol_.period_doubling_depth);
    const FrequencyCurve& c = s.curve;
    write_curves(run, hb, s, "_" + cs.label);
    const ResponseEvaluator ev(hb, kNormal);
    ContactCounts n;
    for (const auto& pt : c.branch.points) {
      const ContactState s = ev.summarize(pt.X).contact;
      n.intermittent += s == ContactState::intermittent;
      n.full += s == ContactState::full;
    }
    const Loading& l = cs.load;
    index.add_row({cs.label, cs.figure, l.gap, l.Fa_1, l.Fa_2, l.F0_1, l.F0_2, long(c.branch.points.size()),
                   long(c.branch.folds.size()), long(c.branch.rejected_steps), n.intermittent, n.full});
    measure(run, cs, hb, c, n);
  }
  run.write("cases.csv", index);
}

// The key numbers of one case (which ones: the case table).
void TwoMassesChapter::measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                               const ContactCounts& n) const {
  KeyNumbers& key = run.key_numbers();
  key.add("intermittent_points_" + cs.label, double(n.intermittent), "-");
  key.add("folds_" + cs.label, double(c.branch.folds.size()), "-");
  if (measures(cs, Measure::open_linear))
    key.add("deviation_from_open_linear_" + cs.label, deviation_from_linear(hb, c, false), "-");
  if (measures(cs, Measure::closed_linear)) {
    key.add("deviation_from_closed_linear_" + cs.label, deviation_from_linear(hb, c, true), "-");
    key.add("full_points_fraction_" + cs.label, double(n.full) / double(c.branch.points.size()), "-");
  }
  if (measures(cs, Measure::onset_and_peak)) onset_and_peak(run, cs, hb, c);
  if (measures(cs, Measure::time_integration)) time_integration_check(run, hb, c);
}

// Largest deviation of the branch's d = x1 - x2 from the linear response of the system
// with the contact open (closed = false) or permanently closed: static part (K^-1 f0)
// and first harmonic (closed-form FRF) must match, every higher harmonic must vanish;
// relative to the first-harmonic amplitude. With H = 1 the model has no higher
// harmonics, so the deviation is measured on the static part and the first harmonic.
double TwoMassesChapter::deviation_from_linear(const HarmonicBalance& hb, const FrequencyCurve& c,
                                               bool closed) const {
  LinearSystem sys = hb.system();
  VectorXd f0 = hb.excitation().f0;
  if (closed) {
    sys.K += sys_.kc * kNormal * kNormal.transpose();
    f0 -= sys_.kc * hb.contacts()[0].gap * kNormal;
  }
  const Eigen::VectorXcd F = hb.excitation().fc.cast<std::complex<double>>();
  const double d0 = kNormal.dot(sys.K.partialPivLu().solve(f0));
  double worst = 0.0;
  for (const auto& pt : c.branch.points) {
    const std::complex<double> d1 = kNormal.cast<std::complex<double>>().dot(frequency_response(sys, F, pt.omega));
    const VectorXd dc = hb.project(pt.X, kNormal);
    // X = [a0, a1, b1, a2, b2, ...]: a1 = Re(Z), b1 = -Im(Z) for the response Re(Z e^{i omega t}).
    const double higher = dc.size() > 3 ? dc.tail(dc.size() - 3).cwiseAbs().maxCoeff() : 0.0;
    const double err =
        std::max({std::fabs(dc[0] - d0), std::fabs(dc[1] - d1.real()), std::fabs(dc[2] + d1.imag()), higher});
    worst = std::max(worst, err / std::abs(d1));
  }
  return worst;
}

// Contact onset on the rising branch (closed form in the reference), the peak of d_max
// and the first fold met along the branch (the upper end of the hardening overhang).
void TwoMassesChapter::onset_and_peak(Run& run, const Case& cs, const HarmonicBalance& hb,
                                      const FrequencyCurve& c) const {
  KeyNumbers& key = run.key_numbers();
  const double onset = first_transition(hb, c, touches_somewhere(hb));
  if (std::isfinite(onset)) key.add("onset_omega_" + cs.label, onset, "rad/s");
  else run.say(cs.label + ": the masses never touch in the frequency range (no onset_omega)");
  const ResponseEvaluator ev(hb, kNormal);
  double peak = -INFINITY, w_peak = 0;
  for (const auto& pt : c.branch.points) {
    const double xm = ev.summarize(pt.X).x_max;
    if (xm > peak) { peak = xm; w_peak = pt.omega; }
  }
  key.add("d_max_peak_" + cs.label, peak, "m");
  key.add("d_max_peak_omega_" + cs.label, w_peak, "rad/s");
  if (!c.branch.folds.empty()) key.add("upper_fold_omega_" + cs.label, c.branch.folds.front().omega, "rad/s");
}

// HB d_max against GSL rk8pd time integration at stable intermittent points.
void TwoMassesChapter::time_integration_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  TimeIntegrationCheckOptions to;
  to.points = checks_.check_points;
  const TimeIntegrationCheck chk =
      run.timed("time integration", [&] { return compare_with_time_integration(hb, c, kNormal, to); });
  run.write("check_time_integration.csv", time_integration_table(chk));
  run.key_numbers().add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
  run.key_numbers().add("time_integration_points", double(chk.points), "-");
}

// --case own: one curve (d and each mass) with the user's loading.
void TwoMassesChapter::own_case(Run& run) const {
  const HarmonicBalance hb = model(own_);
  const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  write_curves(run, hb, s, "");
  run.key_numbers().add("complete", c.branch.complete ? 1.0 : 0.0, "-");
  run.key_numbers().add("folds", double(c.branch.folds.size()), "-");
  run.key_numbers().add("points", double(c.branch.points.size()), "-");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch04_two_masses",
              "ch04_two_masses: two masses that can touch (thesis ch. 4, Figs. 20-23)\n"
              "  m xi'' + C x' + k xi +- max(kc (g + x1 - x2), 0) = F0_i + Fa_i cos(omega t),  g < 0 clearance, g > 0 preload");
  TwoMassesChapter chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
