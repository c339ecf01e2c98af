// ===========================================================================
// ch05_comparin_singh: the Comparin & Singh impact pair (thesis ch. 5, Figs. 25-30)
// ===========================================================================
//
// Two masses m1, m2 joined by a linear spring k and a damper c (always acting) and a
// one-sided contact spring kc on delta = x1 - x2, contact force max(kc (g + delta), 0)
// (g < 0 a clearance, g > 0 a preload; library sign convention, README "Conventions").
// Mass 1 carries F0 + Fa_1 cos(W t), mass 2 carries -F0. Multiplying the equation of
// mass 1 by m2, that of mass 2 by m1 and subtracting (thesis §5):
//
//     M delta'' + c delta' + k delta + max(kc (g + delta), 0) = F0 + (M/m1) Fa_1 cos(W t),
//     M = m1 m2 / (m1 + m2).
//
// The regime classifier (thesis §5, rebuilt from the two linear solutions: chapter README
// "The regime classifier"): with static part dm and first-harmonic amplitude dp,
//   open:   dm_o = F0/k,                 dp_o = Fa / |k - M W^2 + i c W|
//   closed: dm_c = (F0 - kc g)/(k + kc), dp_c = Fa / |k + kc - M W^2 + i c W|,  Fa = (M/m1) Fa_1,
//   type 1 (never in contact) iff g + dm_o + dp_o <= 0, type 2 (always) iff g + dm_c - dp_c >= 0,
//   otherwise intermittent.
//
// The steps, in order (chapter README "Steps"): reduction, thesis_cases (per case: curve,
// prediction and what the case table says it measures), classifier_validation,
// describing_function_check, time_integration_check (with two_mass_check); own_case
// for --case own.
//
// Sample runs:
//   build/bin/ch05_comparin_singh                                  every figure's data and check
//   build/bin/ch05_comparin_singh --case quick --out /tmp/q        the regression subset
//   build/bin/ch05_comparin_singh --case own --set gap=-2 --set Fa_1=0.1 --out /tmp/mine
//   build/bin/ch05_comparin_singh --case fig26_g-1 --set H=20      one curve of the table
// ===========================================================================
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/hb/describing_function.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults (§5.1 table) --------
struct Pair {
  double m1 = 2.0;    // mass 1 (carries F0 + Fa_1 cos Wt) [kg]
  double m2 = 2.0;    // mass 2 (carries -F0) [kg]
  double k = 1.0;     // linear spring between the masses [N/m]
  double kc = 1.0;    // contact stiffness [N/m]
  double c = 0.01;    // viscous damper between the masses [N s/m]
  double M() const { return m1 * m2 / (m1 + m2); }
};
struct Loading {
  double F0 = 4.1;    // mean force (on mass 1, minus on mass 2) [N]
  double Fa_1 = 0.05; // harmonic force amplitude on mass 1 [N] (the thesis' Fp)
  double gap = -1.0;  // g [m]: < 0 clearance, > 0 preload
};
struct Validation {
  int grid_omegas = 25;         // frequencies per (g, F0, Fa_1) combination
  double grid_omega_min = 0.8;  // [rad/s] validation frequencies (inside the sweep range)
  double grid_omega_max = 1.6;  // [rad/s]
  int ti_points = 6;            // HB vs time integration points
};

// What a case of the table measures besides its curve and prediction.
enum class Measure {
  open_resonance,      // type 1: HB first harmonic at W = sqrt(k/M) against Fa/(c W)
  intermittent_band,   // separation on the branch, predicted band, folds, peak
};

struct Case {
  std::string label;    // file stem: frc_<label>.csv
  std::string figure;   // thesis figure
  Loading load;
  bool quick;           // part of the regression subset
  std::vector<Measure> measures;
};

// The thesis' cases (Figs. 25-30), both gaps of each figure. All are in the quick
// subset: 12 curves cost about half a second, and the state-set key number is over all.
const std::vector<Case> kCases = {
    {"fig25_g-20", "25", {4.1, 0.05, -20}, true, {Measure::open_resonance}},
    {"fig25_g-15", "25", {4.1, 0.05, -15}, true, {}},
    {"fig26_g-1", "26", {4.1, 0.05, -1}, true, {Measure::intermittent_band}},
    {"fig26_g6", "26", {4.1, 0.05, 6}, true, {}},
    {"fig27_g-20", "27", {4.1, 0.1, -20}, true, {}},
    {"fig27_g-30", "27", {4.1, 0.1, -30}, true, {}},
    {"fig28_g6", "28", {4.1, 0.1, 6}, true, {}},
    {"fig28_g20", "28", {4.1, 0.1, 20}, true, {}},
    {"fig29_g-15", "29", {2.1, 0.05, -15}, true, {}},
    {"fig29_g-8", "29", {2.1, 0.05, -8}, true, {}},
    {"fig30_g6", "30", {2.1, 0.05, 6}, true, {}},
    {"fig30_g10", "30", {2.1, 0.05, 10}, true, {}},
};
// The loading of the checks: Fig. 26, g = -1 m, full and intermittent contact.
const Loading kCheckedLoad{4.1, 0.05, -1.0};

// The classifier validation grid: F0 x Fa_1 x static penetrations s = g + F0/k spanning
// the open / closed resonance amplitudes of the two Fa_1 levels (quick: 4 of the 12).
struct Penetration {
  double s;     // [m]
  bool quick;   // in the regression subset
};
const std::vector<Penetration> kPenetrations = {
    {-8.0, true}, {-4.0, false}, {-2.0, false}, {-1.0, true}, {-0.5, false}, {0.5, false},
    {1.0, false}, {2.0, true},   {3.0, false},  {4.0, false}, {6.0, false},  {10.0, true}};
const double kGridFm[] = {2.1, 4.1};    // [N]
const double kGridFp[] = {0.05, 0.1};   // [N]
// Frequencies [rad/s] of the two-mass check (the stable branch point nearest each):
// both sides of the resonances and the intermittent band of Fig. 26.
const double kTwoMassOmegas[] = {0.9, 1.3, 1.408, 1.416, 1.6};

const VectorXd kDelta = VectorXd::Constant(1, 1.0);   // the plotted coordinate: delta itself

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// A bound in a table: the number, or "" (none) when it is infinite.
Table::Cell bound_cell(double v) { return std::isfinite(v) ? Table::Cell(v) : Table::Cell(std::string()); }

// --- the regime classifier (thesis §5, rebuilt from the two linear solutions) ---
enum class Regime { type1, type2, intermittent };
const char* regime_name(Regime r) {
  return r == Regime::type1 ? "type1_open" : r == Regime::type2 ? "type2_full" : "intermittent";
}
ContactState regime_state(Regime r) {
  return r == Regime::type1 ? ContactState::open
                            : r == Regime::type2 ? ContactState::full : ContactState::intermittent;
}

struct Classifier {
  Pair p;
  Loading l;
  double Fa() const { return p.M() / p.m1 * l.Fa_1; }
  double dm_open() const { return l.F0 / p.k; }
  double dm_closed() const { return (l.F0 - p.kc * l.gap) / (p.k + p.kc); }
  double dp(double K, double omega) const { return Fa() / std::abs(std::complex<double>(K - p.M() * omega * omega, p.c * omega)); }
  double dp_open(double omega) const { return dp(p.k, omega); }
  double dp_closed(double omega) const { return dp(p.k + p.kc, omega); }
  // Margins: type 1 holds iff open_margin >= 0, type 2 iff closed_margin >= 0.
  double open_margin(double omega) const { return -(l.gap + dm_open() + dp_open(omega)); }
  double closed_margin(double omega) const { return l.gap + dm_closed() - dp_closed(omega); }
  Regime regime(double omega) const {
    if (open_margin(omega) >= 0) return Regime::type1;
    if (closed_margin(omega) >= 0) return Regime::type2;
    return Regime::intermittent;
  }
  // Frequencies (closed form) where the linear amplitude dp with stiffness K equals A:
  // M^2 omega^4 - (2 K M - c^2) omega^2 + K^2 - (Fa/A)^2 = 0. Returns the positive roots, sorted.
  std::vector<double> amplitude_crossings(double K, double A) const {
    std::vector<double> out;
    if (A <= 0) return out;
    const double M = p.M(), a = M * M, b = -(2 * K * M - p.c * p.c), cc = K * K - std::pow(Fa() / A, 2);
    const double disc = b * b - 4 * a * cc;
    if (disc < 0) return out;
    for (double sgn : {-1.0, 1.0}) {
      const double w2 = (-b + sgn * std::sqrt(disc)) / (2 * a);
      if (w2 > 0) out.push_back(std::sqrt(w2));
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  // The predicted intermittent interval, closed form. s = g + F0/k < 0: only type 1 can
  // hold (g + dm_c has the sign of s), intermittent where dp_o > -s; s > 0: only type 2,
  // intermittent where dp_c > g + dm_c; s = 0: intermittent at every W.
  std::vector<double> intermittent_bounds() const {
    const double s = l.gap + dm_open();
    if (s < 0) return amplitude_crossings(p.k, -s);
    if (s > 0) return amplitude_crossings(p.k + p.kc, l.gap + dm_closed());
    return {0.0, INFINITY};
  }
  // One line for the figure title, over [w0, w1].
  std::string describe(double w0, double w1) const {
    const double s = l.gap + dm_open();
    const std::string base = s < 0 ? "type 1 (never in contact)" : "type 2 (always in contact)";
    const auto b = intermittent_bounds();
    std::ostringstream os;
    os.precision(4);
    if (b.size() < 2 || b[1] <= w0 || b[0] >= w1) return base + " for all W";
    os << "intermittent for " << std::max(b[0], w0) << " < W < " << std::min(b[1], w1) << " rad/s; "
       << (s < 0 ? "type 1" : "type 2") << " elsewhere";
    return os.str();
  }
};

// Which contact states (open, full, intermittent) a branch visits / the classifier predicts.
using States = std::array<bool, 3>;

States visited_states(const HarmonicBalance& hb, const FrequencyCurve& c) {
  const ResponseEvaluator ev(hb, kDelta);
  States seen{false, false, false};
  for (const auto& p : c.branch.points) seen[int(ev.summarize(p.X).contact)] = true;
  return seen;
}

States predicted_states(const Classifier& cls, const SolverSettings& s) {
  States pred{false, false, false};
  for (int i = 0; i <= 2000; ++i)
    pred[int(regime_state(cls.regime(s.omega_min + (s.omega_max - s.omega_min) * i / 2000.0)))] = true;
  return pred;
}

std::string state_list(const States& seen) {
  std::string out;
  for (int s = 0; s < 3; ++s)
    if (seen[s]) out += (out.empty() ? "" : "+") + std::string(to_string(ContactState(s)));
  return out;
}

// Every harmonic-balance solution at frequency omega on a continued branch: each crossing of
// the branch with omega, linearly interpolated and corrected by Newton at fixed omega; duplicates
// removed.
struct Crossing {
  VectorXd X;
  bool converged = false;
};
std::vector<Crossing> solutions_at(const HarmonicBalance& hb, const FrequencyCurve& c, double omega) {
  std::vector<Crossing> out;
  const auto& P = c.branch.points;
  for (std::size_t i = 1; i < P.size(); ++i) {
    const double a = P[i - 1].omega - omega, b = P[i].omega - omega;
    if (a * b > 0 || (b == 0 && i + 1 < P.size())) continue;   // count an exact hit once
    const double t = a == b ? 0.0 : a / (a - b);
    Crossing cr;
    cr.X = P[i - 1].X + t * (P[i].X - P[i - 1].X);
    cr.converged = newton_solve(hb, cr.X, omega, c.scaling).converged;
    bool dup = false;
    for (const auto& o : out)
      dup = dup || ((o.X - cr.X).cwiseQuotient(c.scaling.x).cwiseAbs().maxCoeff() < 1e-6);
    if (!dup) out.push_back(cr);
  }
  return out;
}

// Hill stability of a solution (X, omega): the flag of the nearest branch point (scaled distance).
bool stable_near(const FrequencyCurve& c, const VectorXd& X, double omega) {
  std::size_t best = 0;
  double dbest = INFINITY;
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const double d = (c.branch.points[i].X - X).cwiseQuotient(c.scaling.x).norm() +
                     std::fabs(c.branch.points[i].omega - omega) / c.scaling.omega;
    if (d < dbest) { dbest = d; best = i; }
  }
  return c.stable[best];
}

// The classifier against every HB solution at one grid frequency.
struct GridVerdict {
  long solutions = 0, newton_failures = 0;
  std::string states, stable, verdict;
};
GridVerdict judge(const HarmonicBalance& hb, const FrequencyCurve& c, double omega, ContactState predicted) {
  const ResponseEvaluator ev(hb, kDelta);
  const auto sols = solutions_at(hb, c, omega);
  GridVerdict v;
  bool has_pred = false, all_pred = true;
  for (const auto& s : sols) {
    const ContactState st = ev.summarize(s.X).contact;
    v.states += (v.states.empty() ? "" : "+") + std::string(to_string(st));
    v.stable += (v.stable.empty() ? "" : "+") + std::string(stable_near(c, s.X, omega) ? "1" : "0");
    has_pred = has_pred || st == predicted;
    all_pred = all_pred && st == predicted;
    v.newton_failures += !s.converged;
  }
  v.solutions = long(sols.size());
  v.verdict = sols.empty() ? "no_solution" : !has_pred ? "disagree" : all_pred ? "agree" : "agree_coexisting";
  return v;
}

struct GridTally {
  long points = 0, agree = 0, coexisting = 0, disagree = 0, newton_failures = 0;
  std::array<long, 3> predicted{0, 0, 0};   // by Regime
};

class ComparinSingh {
 public:
  explicit ComparinSingh(Study& study);
  void run(Run& run);

 private:
  Pair pair_;
  Loading own_;
  Validation val_;
  SolverSettings sol_;

  HarmonicBalance model(const Loading& l, int H, int N) const;
  HarmonicBalance two_mass_model(const Loading& l) const;
  void write_prediction(Run& run, const Classifier& cls, const std::string& file) const;
  void reduction(Run& run) const;
  void thesis_cases(Run& run) const;
  void measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
               const Classifier& cls) const;
  void classifier_validation(Run& run) const;
  void validate_loading(const Loading& l, Table& t, GridTally& tally) const;
  void describing_function_check(Run& run) const;
  void time_integration_check(Run& run) const;
  void two_mass_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void own_case(Run& run) const;
};

ComparinSingh::ComparinSingh(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("impact pair");
  P.add("m1", &pair_.m1, "kg", "mass 1 (carries F0 + Fa_1 cos Wt)", Range::mass());
  P.add("m2", &pair_.m2, "kg", "mass 2 (carries -F0)", Range::mass());
  P.add("k", &pair_.k, "N/m", "linear spring between the masses", Range::positive());
  P.add("kc", &pair_.kc, "N/m", "contact stiffness", Range::nonnegative());
  P.add("c", &pair_.c, "N s/m", "viscous damper between the masses", Range::positive());
  P.group("own case (--case own)", true);
  P.add("F0", &own_.F0, "N", "mean force (on mass 1, minus on mass 2; the thesis' Fm)");
  P.add("Fa_1", &own_.Fa_1, "N", "harmonic force amplitude on mass 1", Range::positive());
  P.renamed("Fm", "F0");
  P.renamed("Fp", "Fa_1");
  P.add("gap", &own_.gap, "m", "g: < 0 clearance, > 0 preload");
  add_solver_parameters(P, sol_, 1);
  P.group("checks");
  P.add("grid_omegas", &val_.grid_omegas, "-", "validation frequencies per (g, F0, Fa_1)", Range::between(1, 1000));
  P.add("grid_wmin", &val_.grid_omega_min, "rad/s", "lowest validation frequency", Range::positive());
  P.add("grid_wmax", &val_.grid_omega_max, "rad/s", "highest validation frequency", Range::positive());
  P.add("ti_points", &val_.ti_points, "-", "HB vs time-integration comparison points", Range::between(1, 50));
  register_cases(study, kCases);
  study.check([this](const Selection&) {
    check_solver_settings(sol_);
    ParameterSet::require(val_.grid_omega_min < val_.grid_omega_max, "parameter 'grid_wmin' must be < grid_wmax");
    ParameterSet::require(val_.grid_omega_min >= sol_.omega_min && val_.grid_omega_max <= sol_.omega_max,
                          "parameters 'grid_wmin'/'grid_wmax' must lie inside [omega_min, omega_max]");
  });
}

void ComparinSingh::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) reduction(run);
  thesis_cases(run);
  if (run.whole_chapter()) {
    classifier_validation(run);
    describing_function_check(run);
    time_integration_check(run);
  }
}

HarmonicBalance ComparinSingh::model(const Loading& l, int H, int N) const {
  LinearSystem sys{MatrixXd::Constant(1, 1, pair_.M()), MatrixXd::Constant(1, 1, pair_.c),
                   MatrixXd::Constant(1, 1, pair_.k)};
  UnilateralContact contact{kDelta, pair_.kc, l.gap, {}};
  Excitation f{VectorXd::Constant(1, l.F0), VectorXd::Constant(1, pair_.M() / pair_.m1 * l.Fa_1), VectorXd::Zero(1)};
  return HarmonicBalance(sys, {contact}, f, H, N, contact_quadrature(sol_));
}

// The original two-mass system (thesis §5, before the reduction), as a model the library's
// time integrator can run: M = diag(m1, m2), spring k and damper c between the masses,
// contact on x1 - x2, mean forces +F0 / -F0, Fa_1 on mass 1. (Its stiffness matrix is
// singular - a free rigid-body mode - so it is only integrated in time, never solved by HB.)
HarmonicBalance ComparinSingh::two_mass_model(const Loading& l) const {
  const Eigen::Vector2d n(1.0, -1.0);
  const MatrixXd M = Eigen::Vector2d(pair_.m1, pair_.m2).asDiagonal();
  LinearSystem sys{M, pair_.c * n * n.transpose(), pair_.k * n * n.transpose()};
  Excitation f{Eigen::Vector2d(l.F0, -l.F0), Eigen::Vector2d(l.Fa_1, 0.0), VectorXd::Zero(2)};
  return HarmonicBalance(sys, {UnilateralContact{n, pair_.kc, l.gap, {}}}, f, 1);
}

// The classifier's linear amplitudes and regime vs W over the sweep range.
void ComparinSingh::write_prediction(Run& run, const Classifier& cls, const std::string& file) const {
  Table pr({"omega", "dm_open", "dp_open", "dm_closed", "dp_closed", "regime"});
  for (int i = 0; i <= 400; ++i) {
    const double omega = sol_.omega_min + (sol_.omega_max - sol_.omega_min) * i / 400.0;
    pr.add_row({omega, cls.dm_open(), cls.dp_open(omega), cls.dm_closed(), cls.dp_closed(omega),
                std::string(regime_name(cls.regime(omega)))});
  }
  run.write(file, pr);
}

// Step 1 (thesis §5): the reduced mass and the natural frequencies of delta.
void ComparinSingh::reduction(Run& run) const {
  const double M = pair_.M();
  run.key_numbers().add("reduced_mass", M, "kg");
  run.key_numbers().add("omega_open", std::sqrt(pair_.k / M), "rad/s");
  run.key_numbers().add("omega_closed", std::sqrt((pair_.k + pair_.kc) / M), "rad/s");
}

// Step 2 (Figs. 25-30): one continuation per case of the table, the classifier's
// prediction beside it, and whether the branch visits exactly the predicted states.
void ComparinSingh::thesis_cases(Run& run) const {
  Table index({"label", "figure", "F0", "Fa_1", "gap", "static_penetration_open", "prediction", "intermittent_from",
               "intermittent_to", "hb_states", "points", "folds", "rejected_steps", "failures"});
  long failures = 0, mismatches = 0;
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const HarmonicBalance hb = model(cs.load, sol_.H, sol_.N);
    const FrequencyCurve c =
        run.timed("sweep " + cs.label, [&] { return require_complete(sweep_frequency(hb, sweep_options(sol_), cs.label), cs.label); });
    run.write("frc_" + cs.label + ".csv", frequency_response_table(hb, c, kDelta));
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c));
    const Classifier cls{pair_, cs.load};
    write_prediction(run, cls, "prediction_" + cs.label + ".csv");
    const States seen = visited_states(hb, c), pred = predicted_states(cls, sol_);
    for (int s = 0; s < 3; ++s) mismatches += seen[s] != pred[s];
    failures += long(c.branch.failures.size());
    const auto b = cls.intermittent_bounds();
    const std::string prediction = cls.describe(sol_.omega_min, sol_.omega_max);
    const Loading& l = cs.load;
    index.add_row({cs.label, cs.figure, l.F0, l.Fa_1, l.gap, l.gap + cls.dm_open(), prediction,
                   b.size() == 2 ? bound_cell(b[0]) : Table::Cell(std::string()),
                   b.size() == 2 ? bound_cell(b[1]) : Table::Cell(std::string()), state_list(seen),
                   long(c.branch.points.size()), long(c.branch.folds.size()), long(c.branch.rejected_steps),
                   long(c.branch.failures.size())});
    run.say(cs.label + ": " + c.branch.summary() + "; predicted " + prediction + "; HB states " + state_list(seen));
    measure(run, cs, hb, c, cls);
  }
  run.write("cases.csv", index);
  run.key_numbers().add("thesis_cases_corrector_failures", double(failures), "-");
  run.key_numbers().add("thesis_cases_state_set_mismatches", double(mismatches), "-");
}

// The key numbers of one case (which ones: the case table).
void ComparinSingh::measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                            const Classifier& cls) const {
  KeyNumbers& key = run.key_numbers();
  const ResponseEvaluator ev(hb, kDelta);
  if (measures(cs, Measure::open_resonance)) {   // HB (Newton) at W = sqrt(k/M); closed form Fa/(c W)
    const double wn = std::sqrt(pair_.k / pair_.M());
    VectorXd X = hb.open_contact_solution(wn);
    newton_solve(hb, X, wn, c.scaling);
    key.add("open_resonance_amplitude_" + cs.label, ev.summarize(X).x_h1, "m");
  }
  if (measures(cs, Measure::intermittent_band)) {   // closed forms in the reference
    const double sep = first_transition(hb, c, opens_somewhere(hb));
    if (std::isfinite(sep)) key.add("separation_omega_" + cs.label, sep, "rad/s");
    else run.say(cs.label + ": contact never opens in the frequency range (no separation_omega)");
    const auto b = cls.intermittent_bounds();
    if (b.size() == 2 && std::isfinite(b[1])) {
      key.add("predicted_intermittent_from_" + cs.label, b[0], "rad/s");
      key.add("predicted_intermittent_to_" + cs.label, b[1], "rad/s");
    }
    key.add("folds_" + cs.label, double(c.branch.folds.size()), "-");
    double peak = -INFINITY;
    for (const auto& p : c.branch.points) peak = std::max(peak, ev.summarize(p.X).x_max);
    key.add("delta_max_peak_" + cs.label, peak, "m");
  }
}

// Step 3: the classifier against the contact state of every HB solution on a
// (F0, Fa_1, s, W) grid.
void ComparinSingh::classifier_validation(Run& run) const {
  Table t({"F0", "Fa_1", "gap", "omega", "prediction", "n_solutions", "hb_states", "hb_stable", "verdict",
           "open_margin", "closed_margin", "newton_failures"});
  GridTally n;
  run.timed("classifier validation", [&] {
    for (double F0 : kGridFm)
      for (double Fa_1 : kGridFp)
        for (const auto& pen : kPenetrations)
          if (!run.quick() || pen.quick) validate_loading(Loading{F0, Fa_1, pen.s - F0 / pair_.k}, t, n);
  });
  run.write("classifier_validation.csv", t);
  KeyNumbers& key = run.key_numbers();
  key.add("grid_points", double(n.points), "-");
  key.add("grid_agree", double(n.agree), "-");
  key.add("grid_agree_with_coexisting_intermittent", double(n.coexisting), "-");
  key.add("grid_disagree", double(n.disagree), "-");
  key.add("grid_newton_failures", double(n.newton_failures), "-");
  key.add("grid_predicted_type1", double(n.predicted[0]), "-");
  key.add("grid_predicted_type2", double(n.predicted[1]), "-");
  key.add("grid_predicted_intermittent", double(n.predicted[2]), "-");
  run.say("classifier validation: " + std::to_string(n.points) + " grid points, " + std::to_string(n.agree) +
          " agree, " + std::to_string(n.coexisting) + " agree with a coexisting intermittent solution, " +
          std::to_string(n.disagree) + " disagree");
}

// One (F0, Fa_1, g) of the grid: continue it, then judge every grid frequency.
void ComparinSingh::validate_loading(const Loading& l, Table& t, GridTally& n) const {
  const HarmonicBalance hb = model(l, sol_.H, sol_.N);
  const std::string label = "grid_Fm" + fmt(l.F0) + "_Fp" + fmt(l.Fa_1) + "_g" + fmt(l.gap);
  const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol_), label), label);
  const Classifier cls{pair_, l};
  for (int j = 0; j < val_.grid_omegas; ++j) {
    const double omega = val_.grid_omegas == 1 ? 0.5 * (val_.grid_omega_min + val_.grid_omega_max)
                                           : val_.grid_omega_min + (val_.grid_omega_max - val_.grid_omega_min) *
                                                                       j / (val_.grid_omegas - 1);
    const Regime r = cls.regime(omega);
    const GridVerdict v = judge(hb, c, omega, regime_state(r));
    ++n.points;
    ++n.predicted[int(r)];
    n.agree += v.verdict == "agree";
    n.coexisting += v.verdict == "agree_coexisting";
    n.disagree += v.verdict == "disagree" || v.verdict == "no_solution";
    n.newton_failures += v.newton_failures;
    t.add_row({l.F0, l.Fa_1, l.gap, omega, std::string(regime_name(r)), v.solutions, v.states, v.stable, v.verdict,
               cls.open_margin(omega), cls.closed_margin(omega), v.newton_failures});
  }
}

// Step 4 (thesis §5): describing functions N_fm, N_fp by GSL quadrature against the
// H = 1 HB branch of the checked loading: dm N_fm = F0 and |N_fp - M W^2 + i c W| dp = Fa.
void ComparinSingh::describing_function_check(Run& run) const {
  const Loading& l = kCheckedLoad;
  const HarmonicBalance hb = model(l, 1, 0);
  const FrequencyCurve c = run.timed("describing functions", [&] {
    return require_complete(sweep_frequency(hb, sweep_options(sol_), "describing_function_H1"), "describing_function_H1");
  });
  const PiecewiseLinearForce f{pair_.k, pair_.kc, l.gap};
  const double M = pair_.M(), Fa = M / pair_.m1 * l.Fa_1;
  Table t({"omega", "dm", "dp", "contact_angle", "N_fm", "N_fp", "rel_err_static", "rel_err_dynamic",
           "quadrature_error", "stable"});
  double worst = 0.0, worst_intermittent = 0.0;
  long n_int = 0;
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const auto& p = c.branch.points[i];
    const double dm = p.X[hb.index(0, 0)], dp = std::hypot(p.X[hb.index(1, 0)], p.X[hb.index(2, 0)]);
    const DescribingFunction d = describing_function(f, dm, dp);
    const double e0 = std::fabs(dm * d.N_fm - l.F0) / l.F0;
    const double e1 =
        std::fabs(std::abs(std::complex<double>(d.N_fp - M * p.omega * p.omega, pair_.c * p.omega)) * dp - Fa) / Fa;
    worst = std::max({worst, e0, e1});
    if (d.contact_angle > 0 && d.contact_angle < M_PI) {
      worst_intermittent = std::max({worst_intermittent, e0, e1});
      ++n_int;
    }
    t.add_row({p.omega, dm, dp, d.contact_angle, d.N_fm, d.N_fp, e0, e1, d.abs_error, long(c.stable[i])});
  }
  run.write("describing_function_check.csv", t);
  run.key_numbers().add("describing_function_max_rel_residual_H1", worst, "-");
  run.key_numbers().add("describing_function_intermittent_points_H1", double(n_int), "-");
  run.say("describing functions vs H = 1 HB: worst relative residual " + fmt(worst) + " (" +
          std::to_string(n_int) + " intermittent points, worst there " + fmt(worst_intermittent) + ")");
}

// Step 5: HB delta_max against GSL rk8pd time integration (checked loading), then the
// reduction itself against the two-mass equations.
void ComparinSingh::time_integration_check(Run& run) const {
  const HarmonicBalance hb = model(kCheckedLoad, sol_.H, sol_.N);
  const FrequencyCurve c = timed_sweep(run, hb, sol_, "check");
  TimeIntegrationCheckOptions o;
  o.points = val_.ti_points;
  const TimeIntegrationCheck chk =
      run.timed("time integration", [&] { return compare_with_time_integration(hb, c, kDelta, o); });
  run.write("check_time_integration.csv", time_integration_table(chk));
  run.key_numbers().add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
  run.key_numbers().add("time_integration_points", double(chk.points), "-");
  run.timed("two-mass time integration", [&] { two_mass_check(run, hb, c); });
}

// The reduction: integrate the TWO-mass equations (GSL rk8pd) from the state the reduced
// HB solution implies until periodic, and compare max(x1 - x2) over the last period with
// the reduced HB x_max. The centre of mass moves as xc = -Fa_1 cos(Wt) / ((m1 + m2) W^2)
// (the mean forces cancel), so x1 = xc + m2/(m1+m2) delta, x2 = xc - m1/(m1+m2) delta.
void ComparinSingh::two_mass_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const Loading& l = kCheckedLoad;
  const ResponseEvaluator ev(hb, kDelta);
  const auto& Pts = c.branch.points;
  const HarmonicBalance two = two_mass_model(l);
  const TimeIntegrator ti2(two);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  Table t({"omega", "delta_max_hb_reduced", "delta_max_two_mass", "rel_diff", "periods", "contact"});
  double worst = 0.0;
  for (double wt : kTwoMassOmegas) {
    std::size_t best = 0;   // the stable point closest to wt on the branch
    for (std::size_t i = 0; i < Pts.size(); ++i)
      if (c.stable[i] && std::fabs(Pts[i].omega - wt) < std::fabs(Pts[best].omega - wt)) best = i;
    const double omega = Pts[best].omega, mt = pair_.m1 + pair_.m2;
    VectorXd d0, dv0;
    hb_initial_state(hb, Pts[best].X, omega, d0, dv0);
    const double xc = -l.Fa_1 / (mt * omega * omega);
    const Eigen::Vector2d x0(xc + pair_.m2 / mt * d0[0], xc - pair_.m1 / mt * d0[0]);
    const Eigen::Vector2d v0(pair_.m2 / mt * dv0[0], -pair_.m1 / mt * dv0[0]);
    const SteadyState ss = ti2.steady_state(x0, v0, omega, opt);
    if (!ss.converged)
      throw std::runtime_error("two-mass time integration did not become periodic at omega = " + fmt(omega) +
                               " (mismatch " + fmt(ss.mismatch) + " after " + std::to_string(ss.periods) + " periods)");
    const double dmax = (ss.x.col(0) - ss.x.col(1)).maxCoeff();
    const ResponseSummary rs = ev.summarize(Pts[best].X);
    const double rel = std::fabs(rs.x_max - dmax) / std::fabs(dmax);
    worst = std::max(worst, rel);
    t.add_row({omega, rs.x_max, dmax, rel, long(ss.periods), std::string(to_string(rs.contact))});
  }
  run.write("check_two_mass.csv", t);
  run.key_numbers().add("xmax_rel_diff_reduced_vs_two_mass", worst, "-");
}

// --case own: one curve with the user's loading and the classifier's prediction.
void ComparinSingh::own_case(Run& run) const {
  const HarmonicBalance hb = model(own_, sol_.H, sol_.N);
  const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  run.write("frc.csv", frequency_response_table(hb, c, s.doubled, kDelta));
  run.write("bifurcations.csv", bifurcation_table(c, s.doubled));
  const Classifier cls{pair_, own_};
  write_prediction(run, cls, "prediction.csv");
  run.say("predicted: " + cls.describe(sol_.omega_min, sol_.omega_max) + "; HB states " +
          state_list(visited_states(hb, c)));
  run.key_numbers().add("complete", c.branch.complete ? 1.0 : 0.0, "-");
  run.key_numbers().add("folds", double(c.branch.folds.size()), "-");
  run.key_numbers().add("points", double(c.branch.points.size()), "-");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch05_comparin_singh",
              "ch05_comparin_singh: the Comparin & Singh impact pair reduced to delta = x1 - x2 (thesis ch. 5, Figs. 25-30)\n"
              "  M delta'' + c delta' + k delta + max(kc (g + delta), 0) = F0 + (M/m1) Fa_1 cos(W t),  M = m1 m2/(m1 + m2)");
  ComparinSingh chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
