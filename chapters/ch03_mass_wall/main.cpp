// ===========================================================================
// ch03_mass_wall: a mass against a wall (thesis ch. 3, Figs. 7-18)
// ===========================================================================
//
// The equation (thesis §3, SPEC §4, sign convention of contact.hpp):
//
//     m x'' + c x' + k x + max( kc (g + x), 0 ) = F0 + F cos(w t)
//
// g < 0 is a clearance (the mass touches the wall when x > -g), g > 0 a preload
// (pressed against the wall at x = 0). Solved by harmonic balance with the
// static term kept, contact by AFT with exact projection, pseudo-arc-length
// continuation, Hill stability (lib/). Thesis defaults: m = 1 kg, c = 0.01 N s/m,
// k = 1 N/m, kc = 1 N/m, F = 0.01 N.
//
// What it makes (data in --out, default build/data/ch03_mass_wall; figures by
// figures/ch03_mass_wall.py, all through `make figures`):
//   Fig. 7   linear FRF, open (k) and full contact (k + kc)       fig07_linear.csv
//   Fig. 8   contact force N0 + kc x0 cos(theta) clipped at 0     fig08_contact_force.csv
//   Fig. 9   g = -1.2 and -0.6                                    frc_<case>.csv
//   Fig. 10  g = 1 and 0.4
//   Fig. 11  g = -0.6 with F = 0.01 and 0.001
//   Fig. 12  g = -1.2 with F = 0.01 and 0.03
//   Figs. 13-15  g = -1.5, F0 = 1 N: FRC + time history at 3 marked points
//   Figs. 16-18  g = -0.5, F0 = 1 N (starts in contact, separates)  time_<case>_<A|B|C>.csv
//   plus cases.csv (index), marks.csv, sample_study.csv (effect of the number
//   of AFT samples), key_numbers.json, params.json.
//
// Exact commands:
//   build/bin/ch03_mass_wall --out build/data/ch03_mass_wall          (every figure)
//   build/bin/ch03_mass_wall --out DIR --set gap=-0.8 --set F=0.02     (one curve: DIR/frc.csv)
// ===========================================================================
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gearhb/app/tables.hpp"
#include "gearhb/app/cli.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults -------------------
struct Oscillator {
  double m = 1.0;     // mass [kg]
  double c = 0.01;    // viscous damping [N s/m]
  double k = 1.0;     // spring to ground [N/m]
  double kc = 1.0;    // contact stiffness [N/m]
};
struct Loading {
  double gap = -0.6;  // g [m]: < 0 clearance, > 0 preload (single-case runs)
  double F = 0.01;    // harmonic force amplitude [N]
  double F0 = 0.0;    // static force [N]
};
struct Solver {
  int H = 10;                 // harmonics
  int N = 0;                  // AFT samples per period (0 = 4 (2H+1))
  int exact_contact = 1;      // 1 = exact projection of the contact law, 0 = sampled AFT
  int natural = 0;            // 1 = natural continuation (teaching; stops at a fold)
  double omega_min = 0.5;     // [rad/s]
  double omega_max = 2.0;     // [rad/s]
};

struct Case {
  std::string label;   // file stem
  std::string figure;  // thesis figure(s)
  Loading load;
};

HarmonicBalance make_model(const Oscillator& o, const Loading& l, const Solver& s) {
  LinearSystem sys{MatrixXd::Constant(1, 1, o.m), MatrixXd::Constant(1, 1, o.c),
                   MatrixXd::Constant(1, 1, o.k)};
  UnilateralContact wall{VectorXd::Constant(1, 1.0), o.kc, l.gap, {}};
  Excitation f{VectorXd::Constant(1, l.F0), VectorXd::Constant(1, l.F), VectorXd::Zero(1)};
  return HarmonicBalance(sys, {wall}, f, s.H, s.N,
                         s.exact_contact ? ContactQuadrature::exact : ContactQuadrature::sampled);
}

using Curve = FrequencyCurve;

SweepOptions sweep_options(const Solver& s) {
  SweepOptions o;
  o.omega_min = s.omega_min;
  o.omega_max = s.omega_max;
  o.natural = s.natural;
  return o;
}

void write_curve(const HarmonicBalance& hb, const Curve& c, const std::string& path) {
  frequency_response_table(hb, c, VectorXd::Constant(1, 1.0)).write(path);
}

}  // namespace

int main(int argc, char** argv) {
  Oscillator osc;
  Loading load;
  Solver sol;
  ParameterSet P;
  P.add("m", &osc.m, "kg", "mass", Range::positive());
  P.add("c", &osc.c, "N s/m", "viscous damping", Range::nonnegative());
  P.add("k", &osc.k, "N/m", "spring to ground", Range::positive());
  P.add("kc", &osc.kc, "N/m", "contact stiffness", Range::nonnegative());
  P.add("gap", &load.gap, "m", "g: < 0 clearance, > 0 preload (single-case run)");
  P.add("F", &load.F, "N", "harmonic force amplitude");
  P.add("F0", &load.F0, "N", "static force");
  P.add("H", &sol.H, "-", "number of harmonics", Range::at_least(1));
  P.add("N", &sol.N, "-", "AFT time samples per period (0 = 4(2H+1))", Range::nonnegative());
  P.add("exact_contact", &sol.exact_contact, "-", "1 exact projection of the contact law, 0 sampled AFT", Range::between(0, 1));
  P.add("natural", &sol.natural, "-", "1 natural continuation (stops at a fold), 0 arc-length", Range::between(0, 1));
  P.add("omega_min", &sol.omega_min, "rad/s", "start of the frequency range", Range::positive());
  P.add("omega_max", &sol.omega_max, "rad/s", "end of the frequency range", Range::positive());

  const std::string usage =
      "ch03_mass_wall: mass against a wall, m x'' + c x' + k x + max(kc (g + x), 0) = F0 + F cos(w t)\n"
      "(thesis ch. 3). With no --set: every case of Figs. 7-18. With --set: one curve in DIR/frc.csv.";
  return run_chapter("ch03_mass_wall", usage, argc, argv, P, "build/data/ch03_mass_wall",
                     [&](const CommandLine& cl) {
    ParameterSet::require(sol.omega_min < sol.omega_max, "parameter 'omega_min' must be < omega_max");
    ParameterSet::require(sol.N == 0 || sol.N >= 4 * sol.H + 2,
                          "parameter 'N' must be 0 or >= 4H+2 (" + std::to_string(4 * sol.H + 2) + ")");
    const std::string out = cl.out_dir + "/";
    KeyNumbers key;
    write_file_atomic(out + "params.json", P.to_json().dump(2) + "\n");

    // ---- Single case: the user's own parameters -------------------------
    if (P.any_set()) {
      HarmonicBalance hb = make_model(osc, load, sol);
      const Curve c = require_complete(sweep_frequency(hb, sweep_options(sol), "frc"), "frc");
      write_curve(hb, c, out + "frc.csv");
      key.add("folds", double(c.branch.folds.size()), "-");
      key.add("points", double(c.branch.points.size()), "-");
      double peak = -INFINITY;
      for (const auto& p : c.branch.points)
        peak = std::max(peak, ResponseEvaluator(hb, VectorXd::Constant(1, 1.0)).summarize(p.X).x_max);
      key.add("x_max_peak", peak, "m");
      key.write(out + "key_numbers.json");
      std::cout << "ch03_mass_wall: " << c.branch.summary() << " -> " << out << "frc.csv\n";
      return;
    }

    // ---- Step 1: linear references (Fig. 7) and the natural frequencies ----
    {
      Table t({"omega", "x_open", "x_full"});
      LinearSystem open{MatrixXd::Constant(1, 1, osc.m), MatrixXd::Constant(1, 1, osc.c),
                        MatrixXd::Constant(1, 1, osc.k)};
      LinearSystem full = open;
      full.K(0, 0) += osc.kc;
      const Eigen::VectorXcd F = Eigen::VectorXcd::Constant(1, load.F);
      for (int i = 0; i <= 600; ++i) {
        const double w = sol.omega_min + (sol.omega_max - sol.omega_min) * i / 600.0;
        t.add_row({w, std::abs(frequency_response(open, F, w)[0]), std::abs(frequency_response(full, F, w)[0])});
      }
      t.write(out + "fig07_linear.csv");
      key.add("omega_open", modal_analysis(open.M, open.K).omega[0], "rad/s");
      key.add("omega_closed", modal_analysis(full.M, full.K).omega[0], "rad/s");
    }

    // ---- Step 2: the contact force of Fig. 8 (law of contact.hpp) ----------
    {
      // x0 = 1 m oscillation on three preloads N0 = kc g: full, intermittent, open.
      Table t({"theta", "F_full", "F_intermittent", "F_open"});
      for (int i = 0; i <= 360; ++i) {
        const double th = 2 * M_PI * i / 360.0, x = std::cos(th);
        t.add_row({th, contact_force(osc.kc, 1.5 + x), contact_force(osc.kc, 0.5 + x),
                   contact_force(osc.kc, -1.5 + x)});
      }
      t.write(out + "fig08_contact_force.csv");
    }

    // ---- Step 3: frequency responses of Figs. 9-18 ------------------------
    const std::vector<Case> cases = {
        {"g-1.2_F0.01", "9+12", {-1.2, 0.01, 0.0}},  {"g-0.6_F0.01", "9+11", {-0.6, 0.01, 0.0}},
        {"g1_F0.01", "10", {1.0, 0.01, 0.0}},         {"g0.4_F0.01", "10", {0.4, 0.01, 0.0}},
        {"g-0.6_F0.001", "11", {-0.6, 0.001, 0.0}},   {"g-1.2_F0.03", "12", {-1.2, 0.03, 0.0}},
        {"g-1.5_F0.01_F01", "13-15", {-1.5, 0.01, 1.0}}, {"g-0.5_F0.01_F01", "16-18", {-0.5, 0.01, 1.0}},
    };
    Table index({"label", "figure", "gap", "F", "F0", "points", "folds", "rejected_steps", "seconds"});
    Table marks({"label", "mark", "omega", "x_max", "contact"});
    for (const auto& cs : cases) {
      const auto t0 = std::chrono::steady_clock::now();
      HarmonicBalance hb = make_model(osc, cs.load, sol);
      const Curve c = require_complete(sweep_frequency(hb, sweep_options(sol), cs.label), cs.label);
      write_curve(hb, c, out + "frc_" + cs.label + ".csv");
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      index.add_row({cs.label, cs.figure, cs.load.gap, cs.load.F, cs.load.F0, long(c.branch.points.size()),
                     long(c.branch.folds.size()), long(c.branch.rejected_steps), secs});
      std::cout << "ch03_mass_wall: " << cs.label << ": " << c.branch.summary() << "\n";

      // Key numbers: contact onset / separation along the rising branch, located on
      // the HB branch and checked against the closed-form linear FRF (reference/).
      if (cs.label == "g-0.6_F0.01" || cs.label == "g-1.5_F0.01_F01")
        key.add("onset_omega_" + cs.label, first_transition(hb, c, touches_somewhere(hb)), "rad/s");
      if (cs.label == "g0.4_F0.01" || cs.label == "g-0.5_F0.01_F01")
        key.add("separation_omega_" + cs.label, first_transition(hb, c, opens_somewhere(hb)), "rad/s");
      if (cs.label == "g-0.6_F0.01") key.add("folds_" + cs.label, double(c.branch.folds.size()), "-");
      if (cs.label == "g-1.2_F0.01") {
        // open resonance amplitude F/(c w) at w = sqrt(k/m), by HB (Newton at that omega)
        VectorXd X = hb.open_contact_solution(1.0);
        const double wn = std::sqrt(osc.k / osc.m);
        newton_solve(hb, X, wn, hb.scaling(sol.omega_min, sol.omega_max));
        key.add("open_resonance_amplitude", std::hypot(X[hb.index(1, 0)], X[hb.index(2, 0)]), "m");
      }
      // Figs. 13-18: time histories at three marked points: before the contact
      // change (A), at the largest response (B), after it (C).
      if (cs.load.F0 != 0.0) {
        ResponseEvaluator ev(hb, VectorXd::Constant(1, 1.0));
        const auto& Pts = c.branch.points;
        const ContactState start_state = ev.summarize(Pts.front().X).contact;
        std::size_t first = Pts.size(), last = 0, peak = 0;
        for (std::size_t i = 0; i < Pts.size(); ++i) {
          const auto r = ev.summarize(Pts[i].X);
          if (r.contact != start_state) { first = std::min(first, i); last = i; }
          if (r.x_max - r.x_min > ev.summarize(Pts[peak].X).x_max - ev.summarize(Pts[peak].X).x_min) peak = i;
        }
        if (first == Pts.size()) throw std::runtime_error(cs.label + ": no contact change along the branch");
        // A: 0.02 rad/s before the change; C: 0.05 rad/s after it ends.
        std::size_t a = first, cidx = last;
        while (a > 0 && Pts[a].omega > Pts[first].omega - 0.02) --a;
        while (cidx + 1 < Pts.size() && Pts[cidx].omega < Pts[last].omega + 0.05) ++cidx;
        const std::pair<const char*, std::size_t> chosen[] = {{"A", a}, {"B", peak}, {"C", cidx}};
        for (const auto& [name, i] : chosen) {
          const auto r = ev.summarize(Pts[i].X);
          marks.add_row({cs.label, std::string(name), Pts[i].omega, r.x_max, std::string(to_string(r.contact))});
          const VectorXd x = ev.history(Pts[i].X);
          Table th({"t", "x"});
          const double T = 2 * M_PI / Pts[i].omega;
          for (int period = 0; period < 2; ++period)
            for (int j = 0; j < x.size(); ++j) th.add_row({T * (period + double(j) / x.size()), x[j]});
          th.write(out + "time_" + cs.label + "_" + name + ".csv");
        }
      }
    }
    index.write(out + "cases.csv");
    marks.write(out + "marks.csv");

    // ---- Step 4: harmonic balance against GSL time integration (g = -0.6) ---
    {
      HarmonicBalance hb = make_model(osc, {-0.6, 0.01, 0.0}, sol);
      const Curve c = require_complete(sweep_frequency(hb, sweep_options(sol), "check"), "check");
      const TimeIntegrationCheck chk = compare_with_time_integration(hb, c, VectorXd::Constant(1, 1.0));
      time_integration_table(chk).write(out + "check_time_integration.csv");
      key.add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
      key.add("time_integration_points", double(chk.points), "-");
    }

    // ---- Step 5: effect of the number of AFT samples (g = -0.6) -------------
    {
      Table t({"quadrature", "H", "N", "points", "folds", "upper_fold_omega", "seconds"});
      for (int exact : {0, 1})
        for (int N : {42, 84, 168, 336, 672, 1344}) {
          if (exact && N != 84) continue;   // exact projection: N only brackets crossings
          Solver s2 = sol;
          s2.H = 10;
          s2.N = N;
          s2.exact_contact = exact;
          HarmonicBalance hb = make_model(osc, {-0.6, 0.01, 0.0}, s2);
          const auto t0 = std::chrono::steady_clock::now();
          ContinuationOptions opt;
          opt.omega_start = sol.omega_min;
          opt.omega_end = sol.omega_max;
          const Branch b = arc_length_continuation(hb, hb.open_contact_solution(sol.omega_min),
                                                   hb.scaling(sol.omega_min, sol.omega_max), opt);
          const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          double upper = NAN;
          for (const auto& f : b.folds) upper = std::isnan(upper) ? f.omega : std::max(upper, f.omega);
          t.add_row({std::string(exact ? "exact" : "sampled"), long(10), long(N),
                     long(b.points.size()), long(b.folds.size()), upper, secs});
        }
      t.write(out + "sample_study.csv");
    }
    key.write(out + "key_numbers.json");
    std::cout << "ch03_mass_wall: data in " << cl.out_dir << "\n";
  });
}
