// ===========================================================================
// ch04_two_masses: two masses that can touch each other (thesis ch. 4, Figs. 20-23)
// ===========================================================================
//
// The equations (thesis §4, SPEC §4, sign convention of contact.hpp):
//
//     m x1'' + c11 x1' + k x1 + Fc = F1 cos(w t)
//     m x2'' + c22 x2' + k x2 - Fc = F2 cos(w t)        Fc = max( kc (g + x1 - x2), 0 )
//
// i.e. M x'' + C x' + K x + n Fc = f cos(w t) with the contact normal n = [1, -1]:
// the masses touch when the relative displacement x1 - x2 exceeds -g (g < 0 a
// clearance, g > 0 a preload), and the contact pushes mass 1 back (-x) and mass 2
// forward (+x). Each mass is tied to ground by k; Rayleigh damping C = alpha M + beta K
// (K the support springs, as the thesis writes it). Thesis defaults: m = 1 kg,
// k = 5 N/m, kc = 2 N/m, alpha = 0, beta = 0.01 s, F1 = 0.025 N, F2 = 0.02 N.
//
// Why it is worth a chapter: with equal masses and supports the coordinates
// s = (x1 + x2)/2 and d = x1 - x2 decouple. The in-phase motion s never strains the
// contact (resonance sqrt(k/m) open and closed), while d obeys
//     d'' + (c/m) d' + (k/m) d + (2/m) max(kc (g + d), 0) = ((F1 - F2)/m) cos(w t),
// the mass-against-wall oscillator of ch. 3 with stiffness k, contact 2 kc and force F1 - F2.
// Hence the modes: open sqrt(k/m) twice, closed sqrt(k/m) and sqrt((k + 2 kc)/m) = 3 rad/s.
//
// Steps in main:
//   1. modal analysis, open and closed, with the mass normalisation checked;
//   2. the four frequency responses (harmonic balance + arc-length continuation + Hill);
//   3. the checks against closed forms (linear FRF of the decoupled d, contact onset);
//   4. harmonic balance against GSL time integration (g = -0.005, intermittent).
//
// What it makes (data in --out, default build/data/ch04_two_masses; figures by
// figures/ch04_two_masses.py through `make figures`):
//   Figs. 20-23  g = -0.5, -0.005, 0.15, 0.6     frc_<gap>.csv (d = x1 - x2),
//                                                 frc_<gap>_x1.csv, frc_<gap>_x2.csv
//   modes.csv (natural frequencies and mass-normalised shapes), cases.csv,
//   check_time_integration.csv, key_numbers.json, params.json.
//
// Exact commands:
//   build/bin/ch04_two_masses --out build/data/ch04_two_masses            (every figure)
//   build/bin/ch04_two_masses --out DIR --set gap=-0.02 --set F1=0.05     (one curve: DIR/frc*.csv)
// ===========================================================================
#include <cmath>
#include <complex>
#include <iostream>
#include <string>
#include <vector>

#include "gearhb/app/tables.hpp"
#include "gearhb/app/cli.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/hb/response.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults (§4, §4.3) --------
struct TwoMasses {
  double m = 1.0;       // each mass [kg]
  double k = 5.0;       // each support spring to ground [N/m]
  double kc = 2.0;      // contact stiffness on x1 - x2 [N/m]
  double alpha = 0.0;   // Rayleigh, mass-proportional [1/s]
  double beta = 0.01;   // Rayleigh, stiffness-proportional [s]
};
struct Loading {
  double gap = -0.005;  // g [m] (single-case runs): < 0 clearance, > 0 preload
  double F1 = 0.025;    // harmonic force on mass 1 [N]
  double F2 = 0.02;     // harmonic force on mass 2 [N]
  double F01 = 0.0;     // static force on mass 1 [N]
  double F02 = 0.0;     // static force on mass 2 [N]
};
struct Solver {
  int H = 10;                 // harmonics
  double omega_min = 1.0;     // [rad/s]
  double omega_max = 4.0;     // [rad/s]
  int check_points = 8;       // HB vs time integration comparisons (step 4)
};

LinearSystem open_system(const TwoMasses& p) {
  const MatrixXd M = p.m * MatrixXd::Identity(2, 2), K = p.k * MatrixXd::Identity(2, 2);
  return {M, rayleigh_damping(M, K, p.alpha, p.beta), K};
}

const Vector2d kNormal(1.0, -1.0);   // d = x1 - x2 = w' x

HarmonicBalance make_model(const TwoMasses& p, const Loading& l, const Solver& s) {
  UnilateralContact contact{kNormal, p.kc, l.gap, {}};
  Excitation f{Vector2d(l.F01, l.F02), Vector2d(l.F1, l.F2), VectorXd::Zero(2)};
  return HarmonicBalance(open_system(p), {contact}, f, s.H);
}

SweepOptions sweep_options(const Solver& s) {
  SweepOptions o;
  o.omega_min = s.omega_min;
  o.omega_max = s.omega_max;
  return o;
}

// One case: the curve of d = x1 - x2 and of each mass, written as three tables.
FrequencyCurve run_case(const HarmonicBalance& hb, const Solver& s, const std::string& stem,
                        const std::string& out) {
  const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(s), stem), stem);
  frequency_response_table(hb, c, kNormal).write(out + stem + ".csv");
  frequency_response_table(hb, c, Vector2d(1, 0)).write(out + stem + "_x1.csv");
  frequency_response_table(hb, c, Vector2d(0, 1)).write(out + stem + "_x2.csv");
  return c;
}

// Largest deviation of the branch's d = x1 - x2 from the linear response of the
// system with the contact open (closed = false) or permanently closed: static part
// (K_eff^-1 f0_eff) and first harmonic (closed-form FRF), relative to the first
// harmonic amplitude. Exact when the contact state really is open / full.
double deviation_from_linear(const HarmonicBalance& hb, const FrequencyCurve& c, const TwoMasses& p,
                             bool closed) {
  LinearSystem sys = hb.system();
  VectorXd f0 = hb.excitation().f0;
  if (closed) {
    sys.K += p.kc * kNormal * kNormal.transpose();
    f0 -= p.kc * hb.contacts()[0].gap * kNormal;
  }
  const Eigen::VectorXcd F = hb.excitation().fc.cast<std::complex<double>>();
  double worst = 0.0;
  for (const auto& pt : c.branch.points) {
    const std::complex<double> d1 = kNormal.cast<std::complex<double>>().dot(frequency_response(sys, F, pt.omega));
    const double d0 = kNormal.dot(sys.K.partialPivLu().solve(f0));
    const VectorXd dc = hb.project(pt.X, kNormal);
    // X = [a0, a1, b1, ...]: a1 = Re(Z), b1 = -Im(Z) for the response Re(Z e^{i w t}).
    const double err = std::max({std::fabs(dc[0] - d0), std::fabs(dc[1] - d1.real()),
                                 std::fabs(dc[2] + d1.imag()), dc.tail(dc.size() - 3).cwiseAbs().maxCoeff()});
    worst = std::max(worst, err / std::abs(d1));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  TwoMasses sys;
  Loading load;
  Solver sol;
  ParameterSet P;
  P.add("m", &sys.m, "kg", "each mass", Range::positive());
  P.add("k", &sys.k, "N/m", "each support spring", Range::positive());
  P.add("kc", &sys.kc, "N/m", "contact stiffness on x1 - x2", Range::nonnegative());
  P.add("alpha", &sys.alpha, "1/s", "Rayleigh damping, mass-proportional", Range::nonnegative());
  P.add("beta", &sys.beta, "s", "Rayleigh damping, stiffness-proportional", Range::nonnegative());
  P.add("gap", &load.gap, "m", "g: < 0 clearance, > 0 preload (single-case run)");
  P.add("F1", &load.F1, "N", "harmonic force on mass 1");
  P.add("F2", &load.F2, "N", "harmonic force on mass 2");
  P.add("F01", &load.F01, "N", "static force on mass 1");
  P.add("F02", &load.F02, "N", "static force on mass 2");
  P.add("H", &sol.H, "-", "number of harmonics", Range::at_least(1));
  P.add("omega_min", &sol.omega_min, "rad/s", "start of the frequency range", Range::positive());
  P.add("omega_max", &sol.omega_max, "rad/s", "end of the frequency range", Range::positive());
  P.add("check_points", &sol.check_points, "-", "HB vs time-integration comparisons", Range::at_least(1));

  const std::string usage =
      "ch04_two_masses: two masses on springs that can touch, contact max(kc (g + x1 - x2), 0)\n"
      "(thesis ch. 4). With no --set other than H/check_points: Figs. 20-23. Otherwise one curve in DIR/frc*.csv.";
  return run_chapter("ch04_two_masses", usage, argc, argv, P, "build/data/ch04_two_masses",
                     [&](const CommandLine& cl) {
    ParameterSet::require(sol.omega_min < sol.omega_max, "parameter 'omega_min' must be < omega_max");
    const std::string out = cl.out_dir + "/";
    KeyNumbers key;
    write_file_atomic(out + "params.json", P.to_json().dump(2) + "\n");

    // ---- Single case: the user's own parameters ----------------------------
    bool own = false;
    for (const char* name : {"m", "k", "kc", "alpha", "beta", "gap", "F1", "F2", "F01", "F02", "omega_min", "omega_max"})
      own = own || P.was_set(name);
    if (own) {
      const HarmonicBalance hb = make_model(sys, load, sol);
      const FrequencyCurve c = run_case(hb, sol, "frc", out);
      key.add("folds", double(c.branch.folds.size()), "-");
      key.add("points", double(c.branch.points.size()), "-");
      key.write(out + "key_numbers.json");
      std::cout << "ch04_two_masses: " << c.branch.summary() << " -> " << out << "frc.csv\n";
      return;
    }

    // ---- Step 1: modal analysis, open and closed contact (thesis §4.1) -----
    {
      const LinearSystem open = open_system(sys);
      const MatrixXd Kc = sys.kc * kNormal * kNormal.transpose();
      Table t({"state", "mode", "omega", "phi_x1", "phi_x2"});
      for (bool closed : {false, true}) {
        const MatrixXd K = closed ? MatrixXd(open.K + Kc) : open.K;
        const Modes md = modal_analysis(open.M, K);
        const std::string st = closed ? "closed" : "open";
        // Phi' M Phi = I and Phi' K Phi = diag(w^2), checked rather than assumed.
        const MatrixXd PMP = md.Phi.transpose() * open.M * md.Phi;
        const MatrixXd PKP = md.Phi.transpose() * K * md.Phi;
        const MatrixXd W2 = md.omega.cwiseProduct(md.omega).asDiagonal();
        key.add("mass_normalisation_error_" + st, (PMP - MatrixXd::Identity(2, 2)).cwiseAbs().maxCoeff(), "-");
        key.add("stiffness_diagonalisation_error_" + st, (PKP - W2).cwiseAbs().maxCoeff() / W2.maxCoeff(), "-");
        for (int j = 0; j < 2; ++j) {
          key.add("omega_" + st + "_" + std::to_string(j + 1), md.omega[j], "rad/s");
          t.add_row({st, long(j + 1), md.omega[j], md.Phi(0, j), md.Phi(1, j)});
        }
      }
      t.write(out + "modes.csv");
    }

    // ---- Step 2: frequency responses of Figs. 20-23 -------------------------
    struct Case { const char* stem; const char* figure; double gap; };
    const Case cases[] = {{"g-0.5", "20", -0.5}, {"g-0.005", "21", -0.005},
                          {"g0.15", "22", 0.15}, {"g0.6", "23", 0.6}};
    Table index({"stem", "figure", "gap", "points", "folds", "rejected_steps", "intermittent_points",
                 "full_points"});
    for (const auto& cs : cases) {
      Loading l = load;
      l.gap = cs.gap;
      const HarmonicBalance hb = make_model(sys, l, sol);
      const FrequencyCurve c = run_case(hb, sol, std::string("frc_") + cs.stem, out);
      ResponseEvaluator ev(hb, kNormal);
      long inter = 0, full = 0;
      for (const auto& pt : c.branch.points) {
        const ContactState s = ev.summarize(pt.X).contact;
        inter += s == ContactState::intermittent;
        full += s == ContactState::full;
      }
      index.add_row({std::string(cs.stem), std::string(cs.figure), cs.gap, long(c.branch.points.size()),
                     long(c.branch.folds.size()), long(c.branch.rejected_steps), inter, full});
      std::cout << "ch04_two_masses: g = " << cs.gap << ": " << c.branch.summary() << "\n";
      const std::string s = cs.stem;
      key.add("intermittent_points_" + s, double(inter), "-");
      key.add("folds_" + s, double(c.branch.folds.size()), "-");

      // ---- Step 3: closed-form checks of each case ------------------------
      if (cs.gap == -0.5)   // never touches: the whole curve is the open linear response
        key.add("deviation_from_open_linear_" + s, deviation_from_linear(hb, c, sys, false), "-");
      if (cs.gap > 0) {     // never separates: the whole curve is the closed linear response
        key.add("deviation_from_closed_linear_" + s, deviation_from_linear(hb, c, sys, true), "-");
        key.add("full_points_fraction_" + s, double(full) / c.branch.points.size(), "-");
      }
      if (cs.gap == -0.005) {
        key.add("onset_omega_" + s, first_transition(hb, c, touches_somewhere(hb)), "rad/s");
        double peak = -INFINITY, w_peak = 0;
        for (const auto& pt : c.branch.points) {
          const double xm = ev.summarize(pt.X).x_max;
          if (xm > peak) { peak = xm; w_peak = pt.omega; }
        }
        key.add("d_max_peak_" + s, peak, "m");
        key.add("d_max_peak_omega_" + s, w_peak, "rad/s");
        if (!c.branch.folds.empty()) key.add("upper_fold_omega_" + s, c.branch.folds.front().omega, "rad/s");

        // ---- Step 4: harmonic balance against GSL time integration ----------
        TimeIntegrationCheckOptions to;
        to.points = sol.check_points;
        const TimeIntegrationCheck chk = compare_with_time_integration(hb, c, kNormal, to);
        time_integration_table(chk).write(out + "check_time_integration.csv");
        key.add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
        key.add("time_integration_points", double(chk.points), "-");
      }
    }
    index.write(out + "cases.csv");
    key.write(out + "key_numbers.json");
    std::cout << "ch04_two_masses: data in " << cl.out_dir << "\n";
  });
}
