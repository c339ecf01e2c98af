// ===========================================================================
// ch05_comparin_singh: the Comparin & Singh impact pair (thesis ch. 5, Figs. 25-30)
// ===========================================================================
//
// Two masses m1, m2 joined by a linear spring k and a damper c (always acting)
// and a one-sided contact spring kc acting on delta = x1 - x2 with the contact
// law of ch. 3-4 (contact.hpp): force max(kc (g + delta), 0), g < 0 a clearance,
// g > 0 a preload. Mass 1 carries Fm + Fp cos(W t), mass 2 carries -Fm.
// Multiplying the equation of mass 1 by m2, that of mass 2 by m1 and subtracting
// (thesis §5) gives one equation on delta:
//
//     M delta'' + c delta' + k delta + max(kc (g + delta), 0) = Fm + (M/m1) Fp cos(W t),
//     M = m1 m2 / (m1 + m2).
//
// Thesis defaults m1 = m2 = 2 kg (M = 1 kg), k = kc = 1 N/m, c = 0.01 N s/m:
// open natural frequency sqrt(k/M) = 1 rad/s, closed sqrt((k + kc)/M) = 1.414 rad/s.
//
// The regime classifier (thesis §5, rebuilt; README): with the two linear
// solutions (static part dm, first-harmonic amplitude dp)
//   open:   dm_o = Fm/k,                 dp_o = Fa / |k - M W^2 + i c W|
//   closed: dm_c = (Fm - kc g)/(k + kc), dp_c = Fa / |k + kc - M W^2 + i c W|,  Fa = (M/m1) Fp,
//   type 1 (never in contact)  iff  g + dm_o + dp_o <= 0,
//   type 2 (always in contact) iff  g + dm_c - dp_c >= 0,
//   otherwise no linear solution is self-consistent: intermittent contact.
//
// What it makes (data in --out, default build/data/ch05_comparin_singh; figures by
// figures/ch05_comparin_singh.py, all through `make figures`):
//   Figs. 25-30  frc_<label>.csv (delta: x_max, x_min, ...), cases.csv (index with the
//                classifier's prediction), prediction_<label>.csv (the linear amplitudes
//                and the regime vs W)
//   classifier_validation.csv   prediction vs every HB solution on the validation grid
//   describing_function_check.csv  N_fm, N_fp by GSL quadrature vs the H = 1 HB branch
//   check_time_integration.csv  HB vs GSL rk8pd (g = -1 m, Fig. 26)
//   check_two_mass.csv          the reduced equation vs the two-mass equations (GSL)
//   key_numbers.json, params.json
//   (figS2 classifier map drawn from classifier_validation.csv)
//
// Exact commands:
//   build/bin/ch05_comparin_singh --out build/data/ch05_comparin_singh        (everything)
//   build/bin/ch05_comparin_singh --out DIR --set gap=-2 --set Fp=0.1        (one curve: DIR/frc.csv)
// ===========================================================================
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gearhb/app/tables.hpp"
#include "gearhb/app/cli.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/describing_function.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults -------------------
struct Pair {
  double m1 = 2.0;    // mass 1 (carries Fm + Fp cos Wt) [kg]
  double m2 = 2.0;    // mass 2 (carries -Fm) [kg]
  double k = 1.0;     // linear spring between the masses [N/m]
  double kc = 1.0;    // contact stiffness [N/m]
  double c = 0.01;    // viscous damper between the masses [N s/m]
  double M() const { return m1 * m2 / (m1 + m2); }
};
struct Loading {
  double Fm = 4.1;    // mean force (on mass 1, minus on mass 2) [N]
  double Fp = 0.05;   // harmonic force amplitude on mass 1 [N]
  double gap = -1.0;  // g [m]: < 0 clearance, > 0 preload
};
struct Solver {
  int H = 10;                 // harmonics
  int N = 0;                  // AFT samples per period (0 = 4 (2H+1))
  double omega_min = 0.5;     // [rad/s]
  double omega_max = 2.0;     // [rad/s]
};
struct Validation {
  int grid_omegas = 25;         // frequencies per (g, Fm, Fp) combination
  double grid_omega_min = 0.8;  // [rad/s] validation frequencies (inside the sweep range)
  double grid_omega_max = 1.6;  // [rad/s]
  int grid_gaps = 12;           // number of static penetrations s = g + Fm/k used (<= 12)
  int ti_points = 6;            // HB vs time integration points
};

struct Case {
  std::string label;   // file stem
  std::string figure;  // thesis figure
  Loading load;
};

HarmonicBalance make_model(const Pair& p, const Loading& l, int H, int N) {
  LinearSystem sys{MatrixXd::Constant(1, 1, p.M()), MatrixXd::Constant(1, 1, p.c),
                   MatrixXd::Constant(1, 1, p.k)};
  UnilateralContact contact{VectorXd::Constant(1, 1.0), p.kc, l.gap, {}};
  Excitation f{VectorXd::Constant(1, l.Fm), VectorXd::Constant(1, p.M() / p.m1 * l.Fp), VectorXd::Zero(1)};
  return HarmonicBalance(sys, {contact}, f, H, N, ContactQuadrature::exact);
}

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
  double Fa() const { return p.M() / p.m1 * l.Fp; }
  double dm_open() const { return l.Fm / p.k; }
  double dm_closed() const { return (l.Fm - p.kc * l.gap) / (p.k + p.kc); }
  double dp(double K, double w) const { return Fa() / std::abs(std::complex<double>(K - p.M() * w * w, p.c * w)); }
  double dp_open(double w) const { return dp(p.k, w); }
  double dp_closed(double w) const { return dp(p.k + p.kc, w); }
  // Margins: type 1 holds iff open_margin >= 0, type 2 iff closed_margin >= 0.
  double open_margin(double w) const { return -(l.gap + dm_open() + dp_open(w)); }
  double closed_margin(double w) const { return l.gap + dm_closed() - dp_closed(w); }
  Regime regime(double w) const {
    if (open_margin(w) >= 0) return Regime::type1;
    if (closed_margin(w) >= 0) return Regime::type2;
    return Regime::intermittent;
  }
  // Frequencies (closed form) where the linear amplitude dp with stiffness K equals A:
  // M^2 w^4 - (2 K M - c^2) w^2 + K^2 - (Fa/A)^2 = 0. Returns the positive roots, sorted.
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
  // The predicted intermittent interval(s), closed form. s = g + Fm/k < 0: only
  // type 1 can hold (g + dm_c has the sign of s), intermittent where dp_o > -s;
  // s > 0: only type 2, intermittent where dp_c > g + dm_c.
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

// The classifier's linear amplitudes and regime vs W over the sweep range.
void write_prediction(const Classifier& cls, const Solver& sol, const std::string& path) {
  Table pr({"omega", "dm_open", "dp_open", "dm_closed", "dp_closed", "regime"});
  for (int i = 0; i <= 400; ++i) {
    const double w = sol.omega_min + (sol.omega_max - sol.omega_min) * i / 400.0;
    pr.add_row({w, cls.dm_open(), cls.dp_open(w), cls.dm_closed(), cls.dp_closed(w),
                std::string(regime_name(cls.regime(w)))});
  }
  pr.write(path);
}

SweepOptions sweep_options(const Solver& s) {
  SweepOptions o;
  o.omega_min = s.omega_min;
  o.omega_max = s.omega_max;
  return o;
}

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// Every harmonic-balance solution at frequency w on a continued branch: each
// crossing of the branch with w, linearly interpolated and corrected by Newton
// at fixed w; duplicates removed.
struct Crossing {
  VectorXd X;
  bool converged = false;
};
std::vector<Crossing> solutions_at(const HarmonicBalance& hb, const FrequencyCurve& c, double w) {
  std::vector<Crossing> out;
  const auto& P = c.branch.points;
  for (std::size_t i = 1; i < P.size(); ++i) {
    const double a = P[i - 1].omega - w, b = P[i].omega - w;
    if (a * b > 0 || (b == 0 && i + 1 < P.size())) continue;   // count an exact hit once
    const double t = a == b ? 0.0 : a / (a - b);
    Crossing cr;
    cr.X = P[i - 1].X + t * (P[i].X - P[i - 1].X);
    cr.converged = newton_solve(hb, cr.X, w, c.scaling).converged;
    bool dup = false;
    for (const auto& o : out)
      dup = dup || ((o.X - cr.X).cwiseQuotient(c.scaling.x).cwiseAbs().maxCoeff() < 1e-6);
    if (!dup) out.push_back(cr);
  }
  return out;
}

// The original two-mass system (thesis §5, before the reduction), as a model the
// library's time integrator can run: M = diag(m1, m2), spring k and damper c
// between the masses, contact on x1 - x2, mean forces +Fm / -Fm, Fp on mass 1.
// (Its stiffness matrix is singular - a free rigid-body mode - so it is only
// integrated in time, never solved by harmonic balance.)
HarmonicBalance two_mass_model(const Pair& p, const Loading& l) {
  const Eigen::Vector2d w(1.0, -1.0);
  const MatrixXd M = Eigen::Vector2d(p.m1, p.m2).asDiagonal();
  LinearSystem sys{M, p.c * w * w.transpose(), p.k * w * w.transpose()};
  Excitation f{Eigen::Vector2d(l.Fm, -l.Fm), Eigen::Vector2d(l.Fp, 0.0), VectorXd::Zero(2)};
  return HarmonicBalance(sys, {UnilateralContact{w, p.kc, l.gap, {}}}, f, 1);
}

}  // namespace

int main(int argc, char** argv) {
  Pair pair;
  Loading load;
  Solver sol;
  Validation val;
  ParameterSet P;
  P.add("m1", &pair.m1, "kg", "mass 1 (carries Fm + Fp cos Wt)", Range::positive());
  P.add("m2", &pair.m2, "kg", "mass 2 (carries -Fm)", Range::positive());
  P.add("k", &pair.k, "N/m", "linear spring between the masses", Range::positive());
  P.add("kc", &pair.kc, "N/m", "contact stiffness", Range::nonnegative());
  P.add("c", &pair.c, "N s/m", "viscous damper between the masses", Range::positive());
  P.add("Fm", &load.Fm, "N", "mean force (single-case run)");
  P.add("Fp", &load.Fp, "N", "harmonic force amplitude on mass 1 (single-case run)", Range::positive());
  P.add("gap", &load.gap, "m", "g: < 0 clearance, > 0 preload (single-case run)");
  P.add("H", &sol.H, "-", "number of harmonics", Range::at_least(1));
  P.add("N", &sol.N, "-", "AFT time samples per period (0 = 4(2H+1))", Range::nonnegative());
  P.add("omega_min", &sol.omega_min, "rad/s", "start of the frequency range", Range::positive());
  P.add("omega_max", &sol.omega_max, "rad/s", "end of the frequency range", Range::positive());
  P.add("grid_omegas", &val.grid_omegas, "-", "validation frequencies per (g, Fm, Fp)", Range::at_least(1));
  P.add("grid_wmin", &val.grid_omega_min, "rad/s", "lowest validation frequency", Range::positive());
  P.add("grid_wmax", &val.grid_omega_max, "rad/s", "highest validation frequency", Range::positive());
  P.add("grid_gaps", &val.grid_gaps, "-", "static penetrations s = g + Fm/k on the grid (1-12)", Range::between(1, 12));
  P.add("ti_points", &val.ti_points, "-", "HB vs time-integration comparison points", Range::between(1, 50));

  const std::string usage =
      "ch05_comparin_singh: Comparin & Singh impact pair reduced to one DOF on delta = x1 - x2,\n"
      "M delta'' + c delta' + k delta + max(kc (g + delta), 0) = Fm + (M/m1) Fp cos(W t), M = m1 m2/(m1+m2)\n"
      "(thesis ch. 5). Without --set of Fm, Fp or gap: Figs. 25-30 and all checks.\n"
      "With any of them: one curve in DIR/frc.csv with the classifier's prediction.";
  return run_chapter("ch05_comparin_singh", usage, argc, argv, P, "build/data/ch05_comparin_singh",
                     [&](const CommandLine& cl) {
    ParameterSet::require(sol.omega_min < sol.omega_max, "parameter 'omega_min' must be < omega_max");
    ParameterSet::require(sol.N == 0 || sol.N >= 4 * sol.H + 2,
                          "parameter 'N' must be 0 or >= 4H+2 (" + std::to_string(4 * sol.H + 2) + ")");
    ParameterSet::require(val.grid_omega_min < val.grid_omega_max,
                          "parameter 'grid_wmin' must be < grid_wmax");
    ParameterSet::require(val.grid_omega_min >= sol.omega_min && val.grid_omega_max <= sol.omega_max,
                          "parameters 'grid_wmin'/'grid_wmax' must lie inside [omega_min, omega_max]");
    const std::string out = cl.out_dir + "/";
    const VectorXd q = VectorXd::Constant(1, 1.0);   // the plotted coordinate: delta itself
    KeyNumbers key;
    const auto t_start = std::chrono::steady_clock::now();
    auto lap = [t_start](const std::string& what) {
      std::cout << "ch05_comparin_singh: [" << std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count()
                << " s] " << what << "\n";
    };

    // ---- Single case: the user's own loading --------------------------------
    if (P.was_set("Fm") || P.was_set("Fp") || P.was_set("gap")) {
      write_file_atomic(out + "params.json", P.to_json().dump(2) + "\n");
      HarmonicBalance hb = make_model(pair, load, sol.H, sol.N);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol), "frc"), "frc");
      frequency_response_table(hb, c, q).write(out + "frc.csv");
      const Classifier cls{pair, load};
      write_prediction(cls, sol, out + "prediction.csv");
      key.add("folds", double(c.branch.folds.size()), "-");
      key.add("points", double(c.branch.points.size()), "-");
      key.write(out + "key_numbers.json");
      std::cout << "ch05_comparin_singh: " << c.branch.summary() << "\n  prediction: "
                << cls.describe(sol.omega_min, sol.omega_max) << "\n  -> " << out << "frc.csv\n";
      return;
    }
    write_file_atomic(out + "params.json", P.to_json().dump(2) + "\n");

    // ---- Step 1: the reduction and the natural frequencies ------------------
    const double M = pair.M();
    key.add("reduced_mass", M, "kg");
    key.add("omega_open", std::sqrt(pair.k / M), "rad/s");
    key.add("omega_closed", std::sqrt((pair.k + pair.kc) / M), "rad/s");

    // ---- Step 2: Figs. 25-30, both gaps of each figure ------------------------
    const std::vector<Case> cases = {
        {"fig25_g-20", "25", {4.1, 0.05, -20}}, {"fig25_g-15", "25", {4.1, 0.05, -15}},
        {"fig26_g-1", "26", {4.1, 0.05, -1}},   {"fig26_g6", "26", {4.1, 0.05, 6}},
        {"fig27_g-20", "27", {4.1, 0.1, -20}},  {"fig27_g-30", "27", {4.1, 0.1, -30}},
        {"fig28_g6", "28", {4.1, 0.1, 6}},      {"fig28_g20", "28", {4.1, 0.1, 20}},
        {"fig29_g-15", "29", {2.1, 0.05, -15}}, {"fig29_g-8", "29", {2.1, 0.05, -8}},
        {"fig30_g6", "30", {2.1, 0.05, 6}},     {"fig30_g10", "30", {2.1, 0.05, 10}},
    };
    Table index({"label", "figure", "Fm", "Fp", "gap", "static_penetration_open", "prediction",
                 "intermittent_from", "intermittent_to", "hb_states", "points", "folds", "rejected_steps",
                 "failures"});
    int thesis_failures = 0, thesis_prediction_mismatch = 0;
    for (const auto& cs : cases) {
      const auto t0 = std::chrono::steady_clock::now();
      HarmonicBalance hb = make_model(pair, cs.load, sol.H, sol.N);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol), cs.label), cs.label);
      frequency_response_table(hb, c, q).write(out + "frc_" + cs.label + ".csv");
      const Classifier cls{pair, cs.load};
      write_prediction(cls, sol, out + "prediction_" + cs.label + ".csv");
      // Which contact states the HB branch visits, and whether that is what the
      // classifier predicts somewhere in the range.
      ResponseEvaluator ev(hb, q);
      bool seen[3] = {false, false, false};
      for (const auto& p : c.branch.points) seen[int(ev.summarize(p.X).contact)] = true;
      std::string states;
      for (int s = 0; s < 3; ++s)
        if (seen[s]) states += (states.empty() ? "" : "+") + std::string(to_string(ContactState(s)));
      bool pred[3] = {false, false, false};
      for (int i = 0; i <= 2000; ++i)
        pred[int(regime_state(cls.regime(sol.omega_min + (sol.omega_max - sol.omega_min) * i / 2000.0)))] = true;
      for (int s = 0; s < 3; ++s) thesis_prediction_mismatch += (seen[s] != pred[s]);
      const auto b = cls.intermittent_bounds();
      thesis_failures += int(c.branch.failures.size());
      index.add_row({cs.label, cs.figure, cs.load.Fm, cs.load.Fp, cs.load.gap, cs.load.gap + cls.dm_open(),
                     cls.describe(sol.omega_min, sol.omega_max), b.size() == 2 ? Table::Cell(b[0]) : Table::Cell(std::string()),
                     b.size() == 2 ? Table::Cell(b[1]) : Table::Cell(std::string()), states, long(c.branch.points.size()),
                     long(c.branch.folds.size()), long(c.branch.rejected_steps),
                     long(c.branch.failures.size())});
      std::cout << "ch05_comparin_singh: " << cs.label << ": " << c.branch.summary() << "; predicted "
                << cls.describe(sol.omega_min, sol.omega_max) << "; HB states " << states << "\n";

      // Key numbers of the one intermittent thesis case (Fig. 26, g = -1 m): the
      // HB branch leaves full contact exactly where the closed linear amplitude
      // reaches the mean penetration (closed form in reference/).
      if (cs.label == "fig26_g-1") {
        key.add("separation_omega_fig26_g-1", first_transition(hb, c, opens_somewhere(hb)), "rad/s");
        key.add("predicted_intermittent_from_fig26_g-1", b.at(0), "rad/s");
        key.add("predicted_intermittent_to_fig26_g-1", b.at(1), "rad/s");
        key.add("folds_fig26_g-1", double(c.branch.folds.size()), "-");
        double peak = -INFINITY;
        for (const auto& p : c.branch.points) peak = std::max(peak, ev.summarize(p.X).x_max);
        key.add("delta_max_peak_fig26_g-1", peak, "m");
      }
      if (cs.label == "fig25_g-20") {   // type 1: exactly the open linear resonance
        // HB (Newton) at W = sqrt(k/M): first-harmonic amplitude of delta; closed form Fa/(c W).
        const double wn = std::sqrt(pair.k / M);
        VectorXd X = hb.open_contact_solution(wn);
        newton_solve(hb, X, wn, c.scaling);
        key.add("open_resonance_amplitude_fig25_g-20", ev.summarize(X).x_h1, "m");
      }
    }
    index.write(out + "cases.csv");
    key.add("thesis_cases_corrector_failures", double(thesis_failures), "-");
    key.add("thesis_cases_state_set_mismatches", double(thesis_prediction_mismatch), "-");

    lap("before Step 3");
    // ---- Step 3: validation of the classifier on a (g, Fm, Fp, W) grid -----
    {
      // Static penetration with the contact open, s = g + Fm/k: the classifier's
      // natural variable (sign decides type 1 vs type 2 candidate). 12 values
      // spanning the open / closed resonance amplitudes of the two Fp levels.
      const double s_all[12] = {-8.0, -4.0, -2.0, -1.0, -0.5, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 10.0};
      Table t({"Fm", "Fp", "gap", "omega", "prediction", "n_solutions", "hb_states", "hb_stable",
               "verdict", "open_margin", "closed_margin", "newton_failures"});
      long n = 0, agree = 0, agree_coexist = 0, disagree = 0, newton_fail = 0;
      long by_pred[3] = {0, 0, 0};
      for (double Fm : {2.1, 4.1})
        for (double Fp : {0.05, 0.1})
          for (int is = 0; is < val.grid_gaps; ++is) {
            const int idx = val.grid_gaps == 12 ? is : (is * 11) / std::max(1, val.grid_gaps - 1);
            const Loading l{Fm, Fp, s_all[idx] - Fm / pair.k};
            HarmonicBalance hb = make_model(pair, l, sol.H, sol.N);
            const std::string label = "grid_Fm" + fmt(Fm) + "_Fp" + fmt(Fp) + "_g" + fmt(l.gap);
            const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol), label), label);
            ResponseEvaluator ev(hb, q);
            const Classifier cls{pair, l};
            for (int j = 0; j < val.grid_omegas; ++j) {
              const double w = val.grid_omegas == 1
                                   ? 0.5 * (val.grid_omega_min + val.grid_omega_max)
                                   : val.grid_omega_min + (val.grid_omega_max - val.grid_omega_min) * j /
                                                              (val.grid_omegas - 1);
              const Regime r = cls.regime(w);
              const auto sols = solutions_at(hb, c, w);
              std::string states, stab;
              bool has_pred = false, all_pred = true;
              long nf = 0;
              for (const auto& s : sols) {
                const ContactState st = ev.summarize(s.X).contact;
                states += (states.empty() ? "" : "+") + std::string(to_string(st));
                // Hill stability of this solution: the flag of the nearest branch point.
                std::size_t best = 0;
                double dbest = INFINITY;
                for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
                  const double d = (c.branch.points[i].X - s.X).cwiseQuotient(c.scaling.x).norm() +
                                   std::fabs(c.branch.points[i].omega - w) / c.scaling.omega;
                  if (d < dbest) { dbest = d; best = i; }
                }
                stab += (stab.empty() ? "" : "+") + std::string(c.stable[best] ? "1" : "0");
                has_pred = has_pred || st == regime_state(r);
                all_pred = all_pred && st == regime_state(r);
                nf += !s.converged;
              }
              const std::string verdict = sols.empty() ? "no_solution"
                                          : !has_pred  ? "disagree"
                                          : all_pred   ? "agree"
                                                       : "agree_coexisting";
              ++n;
              ++by_pred[int(r)];
              agree += verdict == "agree";
              agree_coexist += verdict == "agree_coexisting";
              disagree += verdict == "disagree" || verdict == "no_solution";
              newton_fail += nf;
              t.add_row({Fm, Fp, l.gap, w, std::string(regime_name(r)), long(sols.size()), states, stab, verdict,
                         cls.open_margin(w), cls.closed_margin(w), nf});
            }
          }
      t.write(out + "classifier_validation.csv");
      key.add("grid_points", double(n), "-");
      key.add("grid_agree", double(agree), "-");
      key.add("grid_agree_with_coexisting_intermittent", double(agree_coexist), "-");
      key.add("grid_disagree", double(disagree), "-");
      key.add("grid_newton_failures", double(newton_fail), "-");
      key.add("grid_predicted_type1", double(by_pred[0]), "-");
      key.add("grid_predicted_type2", double(by_pred[1]), "-");
      key.add("grid_predicted_intermittent", double(by_pred[2]), "-");
      std::cout << "ch05_comparin_singh: classifier validation: " << n << " grid points, " << agree
                << " agree, " << agree_coexist << " agree with a coexisting intermittent solution, "
                << disagree << " disagree\n";
    }

    lap("before Step 4");
    // ---- Step 4: describing functions (GSL quadrature) vs HB at H = 1 --------
    {
      const Loading l = cases[2].load;   // Fig. 26, g = -1 m: full and intermittent contact
      HarmonicBalance hb = make_model(pair, l, 1, 0);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol), "describing_function_H1"), "describing_function_H1");
      const PiecewiseLinearForce f{pair.k, pair.kc, l.gap};
      const double Fa = M / pair.m1 * l.Fp;
      Table t({"omega", "dm", "dp", "contact_angle", "N_fm", "N_fp", "rel_err_static", "rel_err_dynamic",
               "quadrature_error", "stable"});
      double worst = 0.0, worst_intermittent = 0.0;
      long n_int = 0;
      for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
        const auto& p = c.branch.points[i];
        const double dm = p.X[hb.index(0, 0)], dp = std::hypot(p.X[hb.index(1, 0)], p.X[hb.index(2, 0)]);
        const DescribingFunction d = describing_function(f, dm, dp);
        const double e0 = std::fabs(dm * d.N_fm - l.Fm) / l.Fm;
        const double e1 =
            std::fabs(std::abs(std::complex<double>(d.N_fp - M * p.omega * p.omega, pair.c * p.omega)) * dp - Fa) / Fa;
        worst = std::max({worst, e0, e1});
        if (d.contact_angle > 0 && d.contact_angle < M_PI) {
          worst_intermittent = std::max({worst_intermittent, e0, e1});
          ++n_int;
        }
        t.add_row({p.omega, dm, dp, d.contact_angle, d.N_fm, d.N_fp, e0, e1, d.abs_error, long(c.stable[i])});
      }
      t.write(out + "describing_function_check.csv");
      key.add("describing_function_max_rel_residual_H1", worst, "-");
      key.add("describing_function_intermittent_points_H1", double(n_int), "-");
      std::cout << "ch05_comparin_singh: describing functions vs H = 1 HB: worst relative residual " << worst
                << " (" << n_int << " intermittent points, worst there " << worst_intermittent << ")\n";
    }

    lap("before Step 5");
    // ---- Step 5: harmonic balance vs GSL time integration (Fig. 26, g = -1) --
    {
      const Loading l = cases[2].load;
      HarmonicBalance hb = make_model(pair, l, sol.H, sol.N);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol), "check"), "check");
      TimeIntegrationCheckOptions o;
      o.points = val.ti_points;
      const TimeIntegrationCheck chk = compare_with_time_integration(hb, c, q, o);
      time_integration_table(chk).write(out + "check_time_integration.csv");
      key.add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
      key.add("time_integration_points", double(chk.points), "-");

      // The reduction itself: integrate the TWO-mass equations (lib TimeIntegrator,
      // GSL rk8pd) from the state the reduced HB solution implies until periodic, and
      // compare max(x1 - x2) over the last period with the reduced HB x_max. The centre
      // of mass moves as xc = -Fp cos(Wt) / ((m1 + m2) W^2) (no static part: the mean
      // forces cancel), so x1 = xc + m2/(m1+m2) delta, x2 = xc - m1/(m1+m2) delta.
      Table t2({"omega", "delta_max_hb_reduced", "delta_max_two_mass", "rel_diff", "periods", "contact"});
      double worst2 = 0.0;
      ResponseEvaluator ev(hb, q);
      const auto& Pts = c.branch.points;
      const HarmonicBalance two = two_mass_model(pair, l);
      const TimeIntegrator ti2(two);
      TimeIntegrationOptions to2;
      to2.x_scale = c.scaling.x[0];
      for (double wt : {0.9, 1.3, 1.408, 1.416, 1.6}) {
        // the stable point closest to wt on the branch
        std::size_t best = 0;
        for (std::size_t i = 0; i < Pts.size(); ++i)
          if (c.stable[i] && std::fabs(Pts[i].omega - wt) < std::fabs(Pts[best].omega - wt)) best = i;
        const double w = Pts[best].omega, mt = pair.m1 + pair.m2;
        VectorXd d0, dv0;
        hb_initial_state(hb, Pts[best].X, w, d0, dv0);
        const Eigen::Vector2d x0(-l.Fp / (mt * w * w) + pair.m2 / mt * d0[0], -l.Fp / (mt * w * w) - pair.m1 / mt * d0[0]);
        const Eigen::Vector2d v0(pair.m2 / mt * dv0[0], -pair.m1 / mt * dv0[0]);
        const SteadyState ss = ti2.steady_state(x0, v0, w, to2);
        if (!ss.converged)
          throw std::runtime_error("two-mass time integration did not become periodic at omega = " + fmt(w));
        const double dmax = (ss.x.col(0) - ss.x.col(1)).maxCoeff();
        const ResponseSummary rs = ev.summarize(Pts[best].X);
        const double xm = rs.x_max, rel = std::fabs(xm - dmax) / std::fabs(dmax);
        worst2 = std::max(worst2, rel);
        t2.add_row({w, xm, dmax, rel, long(ss.periods), std::string(to_string(rs.contact))});
      }
      t2.write(out + "check_two_mass.csv");
      key.add("xmax_rel_diff_reduced_vs_two_mass", worst2, "-");
    }

    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    key.write(out + "key_numbers.json");
    std::cout << "ch05_comparin_singh: data in " << cl.out_dir << " (" << secs << " s)\n";
  });
}
