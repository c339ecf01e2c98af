// ===========================================================================
// ch03_mass_wall: a mass against a wall (thesis ch. 3, Figs. 7-18)
// ===========================================================================
//
//     m x'' + c x' + k x + max( kc (g + x), 0 ) = F0 + Fa cos(omega t)
//
// g < 0 is a clearance (the mass touches the wall when x > -g), g > 0 a preload
// (pressed against the wall at x = 0); the contact law and its sign convention
// are those of the library (README "Conventions"). Harmonic balance with the
// static term kept, exact projection of the contact law, pseudo-arc-length
// continuation, stability of every point (lib/). The steps, in order (README of
// this chapter): natural_frequencies, contact_force_law, frequency_responses,
// time_histories, time_integration_check, sample_study; own_case for --case own.
//
// Sample runs:
//   build/bin/ch03_mass_wall                                    every figure's data
//   build/bin/ch03_mass_wall --case quick --out /tmp/q          the regression subset
//   build/bin/ch03_mass_wall --case own --set gap=-0.8 --set Fa=0.02 --out /tmp/mine
//   build/bin/ch03_mass_wall --case g-0.6_F0.01 --set H=20      one curve of the table
// ===========================================================================
#include <cmath>
#include <string>
#include <vector>

#include "gearhb/app/case_table.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults (§3.1) ------------
struct Oscillator {
  double m = 1.0;     // mass [kg]
  double c = 0.01;    // viscous damping [N s/m]
  double k = 1.0;     // spring to ground [N/m]
  double kc = 1.0;    // contact stiffness [N/m]
};
struct Loading {
  double gap = -0.6;  // g [m]: < 0 clearance, > 0 preload
  double Fa = 0.01;   // harmonic force amplitude [N] (the thesis' F)
  double F0 = 0.0;    // static force [N]
};

// What a case of the table measures besides its curve (its key numbers).
enum class Measure { onset, separation, fold_count, open_resonance, time_marks };

struct Case {
  std::string label;             // file stem: frc_<label>.csv
  std::string figure;            // thesis figure(s)
  Loading load;
  bool quick;                    // part of the regression subset
  std::vector<Measure> measures;
};

// The thesis' cases (Figs. 9-18).
const std::vector<Case> kCases = {
    {"g-1.2_F0.01", "9+12", {-1.2, 0.01, 0.0}, true, {Measure::open_resonance}},
    {"g-0.6_F0.01", "9+11", {-0.6, 0.01, 0.0}, true, {Measure::onset, Measure::fold_count}},
    {"g1_F0.01", "10", {1.0, 0.01, 0.0}, false, {}},
    {"g0.4_F0.01", "10", {0.4, 0.01, 0.0}, true, {Measure::separation}},
    {"g-0.6_F0.001", "11", {-0.6, 0.001, 0.0}, false, {}},
    {"g-1.2_F0.03", "12", {-1.2, 0.03, 0.0}, false, {}},
    {"g-1.5_F0.01_F01", "13-15", {-1.5, 0.01, 1.0}, true, {Measure::onset, Measure::time_marks}},
    {"g-0.5_F0.01_F01", "16-18", {-0.5, 0.01, 1.0}, true, {Measure::separation, Measure::time_marks}},
};
// The curve checked against time integration and used for the sample study.
const Loading kCheckedLoad{-0.6, 0.01, 0.0};

const VectorXd kX = VectorXd::Constant(1, 1.0);   // the plotted coordinate: x itself

class MassAgainstWall {
 public:
  explicit MassAgainstWall(Study& study);
  void run(Run& run);

 private:
  Oscillator osc_;
  Loading own_;
  SolverSettings sol_;

  HarmonicBalance model(const Loading& l, const SolverSettings& s) const;
  void natural_frequencies(Run& run) const;
  void contact_force_law(Run& run) const;
  void frequency_responses(Run& run) const;
  void measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void time_histories(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                      Table& marks) const;
  void time_integration_check(Run& run) const;
  void sample_study(Run& run) const;
  void own_case(Run& run) const;
};

MassAgainstWall::MassAgainstWall(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("oscillator");
  P.add("m", &osc_.m, "kg", "mass", Range::mass());
  P.add("c", &osc_.c, "N s/m", "viscous damping", Range::nonnegative());
  P.add("k", &osc_.k, "N/m", "spring to ground", Range::positive());
  P.add("kc", &osc_.kc, "N/m", "contact stiffness", Range::nonnegative());
  P.group("own case (--case own)", true);
  P.add("gap", &own_.gap, "m", "g: < 0 clearance, > 0 preload", Range::between(-1e6, 1e6));
  P.add("Fa", &own_.Fa, "N", "harmonic force amplitude (the thesis' F)", Range::between(-1e12, 1e12));
  P.renamed("F", "Fa");
  P.add("F0", &own_.F0, "N", "static force", Range::between(-1e12, 1e12));
  add_solver_parameters(P, sol_, 1);
  register_cases(study, kCases);
  study.check([this](const Selection&) { check_solver_settings(sol_); });
}

void MassAgainstWall::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) {
    natural_frequencies(run);
    contact_force_law(run);
  }
  frequency_responses(run);
  if (run.whole_chapter()) {
    time_integration_check(run);
    sample_study(run);
  }
}

HarmonicBalance MassAgainstWall::model(const Loading& l, const SolverSettings& s) const {
  LinearSystem sys{MatrixXd::Constant(1, 1, osc_.m), MatrixXd::Constant(1, 1, osc_.c),
                   MatrixXd::Constant(1, 1, osc_.k)};
  UnilateralContact wall{kX, osc_.kc, l.gap, {}};
  Excitation f{VectorXd::Constant(1, l.F0), VectorXd::Constant(1, l.Fa), VectorXd::Zero(1)};
  return HarmonicBalance(sys, {wall}, f, s.H, s.N, contact_quadrature(s));
}

// Step 1 (Fig. 7): the linear references, open (k) and full contact (k + kc).
void MassAgainstWall::natural_frequencies(Run& run) const {
  LinearSystem open{MatrixXd::Constant(1, 1, osc_.m), MatrixXd::Constant(1, 1, osc_.c),
                    MatrixXd::Constant(1, 1, osc_.k)};
  LinearSystem full = open;
  full.K(0, 0) += osc_.kc;
  Table t({"omega", "x_open", "x_full"});
  const Eigen::VectorXcd F = Eigen::VectorXcd::Constant(1, kCases.front().load.Fa);
  for (int i = 0; i <= 600; ++i) {
    const double omega = sol_.omega_min + (sol_.omega_max - sol_.omega_min) * i / 600.0;
    t.add_row({omega, std::abs(frequency_response(open, F, omega)[0]), std::abs(frequency_response(full, F, omega)[0])});
  }
  run.write("fig07_linear.csv", t);
  run.key_numbers().add("omega_open", modal_analysis(open.M, open.K).omega[0], "rad/s");
  run.key_numbers().add("omega_closed", modal_analysis(full.M, full.K).omega[0], "rad/s");
}

// Step 2 (Fig. 8): the contact law on an oscillation x0 = 1 m with three preloads N0.
void MassAgainstWall::contact_force_law(Run& run) const {
  Table t({"theta", "F_full", "F_intermittent", "F_open"});
  for (int i = 0; i <= 360; ++i) {
    const double th = 2 * M_PI * i / 360.0, x = std::cos(th);
    t.add_row({th, contact_force(osc_.kc, 1.5 + x), contact_force(osc_.kc, 0.5 + x),
               contact_force(osc_.kc, -1.5 + x)});
  }
  run.write("fig08_contact_force.csv", t);
}

// Step 3 (Figs. 9-18): one continuation per case of the table.
void MassAgainstWall::frequency_responses(Run& run) const {
  Table index({"label", "figure", "gap", "Fa", "F0", "points", "folds", "rejected_steps", "complete"});
  Table marks({"label", "mark", "omega", "x_max", "contact"});
  for (const auto& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const HarmonicBalance hb = model(cs.load, sol_);
    const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), cs.label, sol_.period_doubling_depth);
    const FrequencyCurve& c = s.curve;
    run.write("frc_" + cs.label + ".csv", frequency_response_table(hb, c, s.doubled, kX));
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c, s.doubled));
    index.add_row({cs.label, cs.figure, cs.load.gap, cs.load.Fa, cs.load.F0, long(c.branch.points.size()),
                   long(c.branch.folds.size()), long(c.branch.rejected_steps), long(c.branch.complete)});
    measure(run, cs, hb, c);
    if (measures(cs, Measure::time_marks)) time_histories(run, cs, hb, c, marks);
  }
  run.write("cases.csv", index);
  run.write("marks.csv", marks);
}

// The key numbers a case measures: contact onset / separation along the rising
// branch (checked against the closed-form linear FRF), the fold count, and the
// open resonance amplitude Fa/(c omega) at omega = sqrt(k/m) by Newton at that omega.
void MassAgainstWall::measure(Run& run, const Case& cs, const HarmonicBalance& hb,
                              const FrequencyCurve& c) const {
  KeyNumbers& key = run.key_numbers();
  if (measures(cs, Measure::onset))
    key.add("onset_omega_" + cs.label, first_transition(hb, c, touches_somewhere(hb)), "rad/s");
  if (measures(cs, Measure::separation))
    key.add("separation_omega_" + cs.label, first_transition(hb, c, opens_somewhere(hb)), "rad/s");
  if (measures(cs, Measure::fold_count)) key.add("folds_" + cs.label, double(c.branch.folds.size()), "-");
  if (measures(cs, Measure::open_resonance)) {
    const double wn = std::sqrt(osc_.k / osc_.m);
    VectorXd X = hb.open_contact_solution(wn);
    newton_solve(hb, X, wn, c.scaling);
    key.add("open_resonance_amplitude", std::hypot(X[hb.index(1, 0)], X[hb.index(2, 0)]), "m");
  }
}

// Figs. 13-18: x(t) over two periods at three points of the curve, chosen by a
// stated rule: A 0.02 rad/s before the contact state first changes, B the largest
// response, C 0.05 rad/s after the last change.
void MassAgainstWall::time_histories(Run& run, const Case& cs, const HarmonicBalance& hb,
                                     const FrequencyCurve& c, Table& marks) const {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  std::vector<ResponseSummary> r;
  for (const auto& p : P) r.push_back(ev.summarize(p.X));
  std::size_t first = P.size(), last = 0, peak = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (r[i].contact != r.front().contact) { first = std::min(first, i); last = i; }
    if (r[i].x_max - r[i].x_min > r[peak].x_max - r[peak].x_min) peak = i;
  }
  if (first == P.size()) throw std::runtime_error(cs.label + ": no contact change along the branch");
  std::size_t a = first, after = last;
  while (a > 0 && P[a].omega > P[first].omega - 0.02) --a;
  while (after + 1 < P.size() && P[after].omega < P[last].omega + 0.05) ++after;
  const std::pair<const char*, std::size_t> chosen[] = {{"A", a}, {"B", peak}, {"C", after}};
  for (const auto& [name, i] : chosen) {
    marks.add_row({cs.label, std::string(name), P[i].omega, r[i].x_max, std::string(to_string(r[i].contact))});
    const VectorXd x = ev.history(P[i].X);
    const double T = 2 * M_PI / P[i].omega;
    Table th({"t", "x"});
    for (int period = 0; period < 2; ++period)
      for (int j = 0; j < x.size(); ++j) th.add_row({T * (period + double(j) / x.size()), x[j]});
    run.write("time_" + cs.label + "_" + name + ".csv", th);
  }
}

// Step 4: x_max by harmonic balance against GSL time integration (g = -0.6).
void MassAgainstWall::time_integration_check(Run& run) const {
  const HarmonicBalance hb = model(kCheckedLoad, sol_);
  const FrequencyCurve c = timed_sweep(run, hb, sol_, "check");
  const TimeIntegrationCheck chk =
      run.timed("time integration", [&] { return compare_with_time_integration(hb, c, kX); });
  run.write("check_time_integration.csv", time_integration_table(chk));
  run.key_numbers().add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
  run.key_numbers().add("time_integration_points", double(chk.points), "-");
}

// Step 5 (figS1): folds found with sampled AFT against the number of samples N,
// and with the exact projection (which needs N only to evaluate the series).
void MassAgainstWall::sample_study(Run& run) const {
  struct Setting { ContactQuadrature quadrature; int N; };
  const std::vector<Setting> settings = {
      {ContactQuadrature::sampled, 42},  {ContactQuadrature::sampled, 84},  {ContactQuadrature::sampled, 168},
      {ContactQuadrature::sampled, 336}, {ContactQuadrature::sampled, 672}, {ContactQuadrature::sampled, 1344},
      {ContactQuadrature::exact, 84}};
  Table t({"quadrature", "H", "N", "points", "folds", "upper_fold_omega"});
  for (const auto& s : settings) {
    SolverSettings ss = sol_;
    ss.H = 10;
    ss.N = s.N;
    ss.exact_contact = s.quadrature == ContactQuadrature::exact;
    const HarmonicBalance hb = model(kCheckedLoad, ss);
    ContinuationOptions opt;
    opt.omega_start = sol_.omega_min;
    opt.omega_end = sol_.omega_max;
    const std::string name = std::string(ss.exact_contact ? "exact" : "sampled");
    const Branch b = run.timed("sample study " + name + " N=" + std::to_string(s.N), [&] {
      return arc_length_continuation(hb, hb.open_contact_solution(sol_.omega_min),
                                     hb.scaling(sol_.omega_min, sol_.omega_max), opt);
    });
    double upper = -INFINITY;
    for (const auto& f : b.folds) upper = std::max(upper, f.omega);
    t.add_row({name, long(10), long(s.N), long(b.points.size()), long(b.folds.size()),
               b.folds.empty() ? Table::Cell(std::string()) : Table::Cell(upper)});
  }
  run.write("sample_study.csv", t);
}

// --case own: one curve with the user's parameters.
void MassAgainstWall::own_case(Run& run) const {
  const HarmonicBalance hb = model(own_, sol_);
  const SweptCurve s = timed_sweep_with_branches(run, hb, sweep_options(sol_), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  run.write("frc.csv", frequency_response_table(hb, c, s.doubled, kX));
  run.write("bifurcations.csv", bifurcation_table(c, s.doubled));
  const ResponseEvaluator ev(hb, kX);
  double peak = -INFINITY;
  for (const auto& p : c.branch.points) peak = std::max(peak, ev.summarize(p.X).x_max);
  run.key_numbers().add("complete", c.branch.complete ? 1.0 : 0.0, "-");
  run.key_numbers().add("folds", double(c.branch.folds.size()), "-");
  run.key_numbers().add("points", double(c.branch.points.size()), "-");
  run.key_numbers().add("x_max_peak", peak, "m");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch03_mass_wall",
              "ch03_mass_wall: a mass against a wall (thesis ch. 3, Figs. 7-18)\n"
              "  m x'' + c x' + k x + max(kc (g + x), 0) = F0 + Fa cos(omega t),  g < 0 clearance, g > 0 preload");
  MassAgainstWall chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
