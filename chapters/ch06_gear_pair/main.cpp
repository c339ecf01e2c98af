// ===========================================================================
// ch06_gear_pair: a spur-gear pair with 6 DOFs and external forcing
// (thesis ch. 6, Figs. 40-45)
// ===========================================================================
//
// The equation (thesis §6.1, SPEC §4; matrices in lib/include/gearhb/gear_pair.hpp):
//
//     q = [x1, y1, th1, x2, y2, th2]
//     M q'' + C q' + K q = F0 + F cos(w t) + T1 max(kc Delta, 0),   Delta = T2 q
//     T2 = [cos a, -sin a, rb1, -cos a, sin a, -rb2],  T1 = -T2'
//     closed mesh: K + Kc,  Kc = -T1 kc T2 = kc T2' T2
//     C = alpha M + beta K (K = support stiffness; --set damp_mesh=1 uses K + Kc)
//     F0 = [0, 0, Fi, 0, 0, -Fi rb2/rb1],  F = Fa [1, 0, 1, 1, 0, 1]
//
// Delta > 0: teeth pressed together (mesh force kc Delta); Delta < 0: teeth apart.
// The plotted coordinate is the mesh deflection Delta (the thesis' "moto relativo"
// Delta = delta1 - delta2). Harmonic balance (static term kept), exact contact
// projection, pseudo-arc-length continuation, Hill stability (lib/).
//
// What it makes (data in --out, default build/data/ch06_gear_pair; figures by
// figures/ch06_gear_pair.py):
//   modes.csv                        natural frequencies, open and closed mesh, both kc
//   linear_kc<kc>.csv                linear |Delta| of the open and closed systems (F = 1e4)
//   frc_fig<NN>_kc<kc>.csv           Figs. 40-45 for kc = kc (default 5e8) and kc_alt (5e2)
//                                    Fig. 40 Fi = 1e5, 41 Fi = 1e7, 42 Fi = -1e8, 43 Fi = -1e6
//                                    (Fa = 1e4); 44 Fi = 1e7, 45 Fi = -1e8 (Fa = 1e6)
//   cases.csv                        contact summary of every curve (transitions, ranges)
//   check_time_integration.csv       HB (H_check = 16) vs GSL rk8pd, Fig. 43, stable intermittent points
//                                    (stable by Hill AND by the Floquet multipliers; column stable_floquet)
//   h_study.csv                      peak Delta_max / Delta_min vs H on the Fig. 43 curve (10-20 krad/s)
//   key_numbers.json, params.json
//
// Exact commands:
//   build/bin/ch06_gear_pair --out build/data/ch06_gear_pair            (every figure)
//   build/bin/ch06_gear_pair --out DIR --set single=1 --set Fi=1e6 --set Fa=1e5
//                                                   (one curve with your parameters: DIR/frc.csv)
//   build/bin/ch06_gear_pair --out DIR --set quick=1   (regression subset, a few seconds)
// ===========================================================================
#include <algorithm>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gearhb/app/tables.hpp"
#include "gearhb/app/cli.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/gears/gear_pair.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults -------------------
// Gear pair: GearPairParameters (gear_pair.hpp), thesis §6.2 table, except kc
// (printed 5e2 N/m; 5e8 N/m reproduces the text, see README).
struct Loading {
  double Fi = -1e6;    // static torque on gear 1 [N m] (single-curve runs)
  double Fa = 1e4;     // harmonic amplitude of every nonzero entry of F [N or N m]
};
struct Solver {
  int H = 10;                  // harmonics (h_study.csv: peak within 0.3 % of H = 20)
  int N = 0;                   // AFT samples per period (0 = 4 (2H+1))
  double omega_min = 2000.0;   // [rad/s]
  double omega_max = 62000.0;  // [rad/s] ~1.2 x the highest closed natural frequency
  double ds_max = 0.005;       // largest scaled arc-length step (library default 0.02 steps over
                               // the small fold pairs near 7.5-8.4 krad/s of Figs. 40/44, README)
  double ds_max_alt = 0.02;    // the same for the kc_alt curves (no folds: contact force < 10 N)
  double kc_alt = 5e2;         // the other mesh stiffness of the kc study [N/m]
  int single = 0;              // 1 = one curve with Fi, Fa (DIR/frc.csv)
  int quick = 0;               // 1 = regression subset (key numbers only)
  int ti_points = 8;           // HB vs time-integration comparisons
  double tolerance = 1e-9;     // corrector tolerance (scaled; library default 1e-10 is out of
                               // Newton's reach at some grazing points with ds_max = 0.005, README)
  int corrector_iterations = 12;  // corrector Newton iterations (library default)
  int H_check = 16;            // harmonics of the time-integration check (README: H = 10 gives 0.52 %)
};

struct Case {
  int figure;
  double Fi, Fa;
};
const std::vector<Case> kCases = {{40, 1e5, 1e4}, {41, 1e7, 1e4}, {42, -1e8, 1e4},
                                  {43, -1e6, 1e4}, {44, 1e7, 1e6}, {45, -1e8, 1e6}};

VectorXd harmonic_shape(double Fa) {
  VectorXd f(6);
  f << Fa, 0.0, Fa, Fa, 0.0, Fa;
  return f;
}

// Time unit. The GSL variational equations of the monodromy matrix mix entries of
// order 1 and w ~ 1e4 under one absolute tolerance (and Hill's companion matrix
// did too before stability.cpp scaled it; README). The
// model is therefore solved in the nondimensional time tau = w0 t with w0 the
// lowest open natural frequency (from the data, not tuned):
//   M q'' + (C/w0) q' + (K/w0^2) q + T2' max((kc/w0^2) T2 q, 0) = (F0 + F cos(W tau))/w0^2,
// W = omega/w0. Displacements are unchanged; every omega written is multiplied back by w0.
HarmonicBalance make_model(const GearPairParameters& g, double Fi, double Fa, const Solver& s, double w0) {
  LinearSystem sys = gear_pair_system(g);
  sys.C /= w0;
  sys.K /= w0 * w0;
  UnilateralContact mesh = gear_pair_mesh(g);
  mesh.kc /= w0 * w0;
  Excitation f{gear_pair_static_torque(g, Fi) / (w0 * w0), harmonic_shape(Fa) / (w0 * w0), VectorXd::Zero(6)};
  return HarmonicBalance(sys, {mesh}, f, s.H, s.N);
}

// Largest Floquet multiplier modulus of the HB orbit: monodromy matrix from the GSL
// variational equations (time_integration.hpp) started on the HB state at phase 0.
// The independent stability check: on this problem it exposed Hill's missed period
// doublings (fixed in stability.cpp; a few narrow windows still differ, README), so
// every point gets both flags.
double floquet_max(const HarmonicBalance& hb, const VectorXd& X, double omega, double x_scale) {
  TimeIntegrator ti(hb);
  VectorXd x0, v0;
  hb_initial_state(hb, X, omega, x0, v0);
  TimeIntegrationOptions o;
  o.x_scale = x_scale;
  return ti.monodromy(x0, v0, omega, o).eigenvalues().cwiseAbs().maxCoeff();
}
std::vector<bool> floquet_stability(const HarmonicBalance& hb, const FrequencyCurve& c) {
  std::vector<bool> st;
  for (const auto& p : c.branch.points) st.push_back(floquet_max(hb, p.X, p.omega, c.scaling.x[0]) < 1.0);
  return st;
}

// The standard FRC table (response.hpp columns) with omega back in rad/s, plus the
// Floquet stability flag (stable = Hill, SPEC §2).
Table frc_table(const HarmonicBalance& hb, const FrequencyCurve& c, const std::vector<bool>& floquet,
                const VectorXd& q, double w0) {
  ResponseEvaluator ev(hb, q);
  Table t({"omega", "x_max", "x_min", "x_rms_ac", "x_h1", "x_mean", "stable", "contact", "stable_floquet"});
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const auto r = ev.summarize(c.branch.points[i].X);
    t.add_row({c.branch.points[i].omega * w0, r.x_max, r.x_min, r.x_rms_ac, r.x_h1, r.x_mean,
               long(c.stable[i] ? 1 : 0), std::string(to_string(r.contact)), long(floquet[i] ? 1 : 0)});
  }
  return t;
}

SweepOptions sweep_options(const Solver& s, double wmin, double wmax, double w0) {
  SweepOptions o;
  o.omega_min = wmin / w0;
  o.omega_max = wmax / w0;
  o.continuation.ds_max = s.ds_max;
  o.continuation.tolerance = s.tolerance;
  // (At grazing the contact force is only C1 in the unknowns and Newton slows down;
  // tolerance and corrector_iterations are settable for experiments, README.)
  o.continuation.corrector_max_iterations = s.corrector_iterations;
  o.continuation.ds_initial = std::min(o.continuation.ds_initial, s.ds_max);
  return o;
}

std::string kc_tag(double kc) {
  std::ostringstream os;
  os << kc;   // 5e+08 -> "5e+08"
  std::string t = os.str();
  t.erase(std::remove(t.begin(), t.end(), '+'), t.end());
  return t;   // "5e08", "500"
}

// Contact summary of one curve along the branch (continuation order).
struct ContactSummary {
  int transitions = 0;          // changes of the contact state between consecutive points
  std::string start, end;       // state at omega_min and at omega_max
  double intermittent_lo = NAN, intermittent_hi = NAN;   // omega span of non-start states
  double delta_max = -INFINITY, delta_min = INFINITY;    // over the whole curve [m]
};
ContactSummary summarize_contact(const HarmonicBalance& hb, const FrequencyCurve& c, const VectorXd& q,
                                 double w0) {
  ResponseEvaluator ev(hb, q);
  ContactSummary s;
  ContactState prev = ContactState::open;
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const auto r = ev.summarize(c.branch.points[i].X);
    const double w = c.branch.points[i].omega * w0;
    if (i == 0) s.start = to_string(r.contact);
    else if (r.contact != prev) ++s.transitions;
    if (std::string(to_string(r.contact)) != s.start) {
      s.intermittent_lo = std::isnan(s.intermittent_lo) ? w : std::min(s.intermittent_lo, w);
      s.intermittent_hi = std::isnan(s.intermittent_hi) ? w : std::max(s.intermittent_hi, w);
    }
    s.delta_max = std::max(s.delta_max, r.x_max);
    s.delta_min = std::min(s.delta_min, r.x_min);
    prev = r.contact;
  }
  s.end = to_string(prev);
  return s;
}

// First omega (solver units) along the branch where `state` switches on; NaN if never.
// Up to the first contact change the branch is exactly the linear solution of the
// starting state (open, or closed for a full-contact start). The HB branch gives the
// bracket [P[i-1], P[i]]; the point before it is checked against that linear solution
// (relative 1e-6, else an error), and the change is located inside the bracket by
// bisection on the linear solution. (The library's first_transition corrects with a
// fixed 1e-12 step tolerance that this problem cannot meet at grazing; README.)
double first_change(const HarmonicBalance& hb, const FrequencyCurve& c,
                    const std::function<bool(const VectorXd&)>& state, bool closed_start) {
  const auto& P = c.branch.points;
  auto linear = [&](double w) { return closed_start ? hb.closed_contact_solution(w) : hb.open_contact_solution(w); };
  if (P.empty() || state(P[0].X)) return P.empty() ? NAN : P[0].omega;
  for (std::size_t i = 1; i < P.size(); ++i) {
    if (!state(P[i].X)) continue;
    const VectorXd L = linear(P[i - 1].omega);
    if ((L - P[i - 1].X).norm() > 1e-6 * L.norm())
      throw std::runtime_error("first_change: the branch before the first contact change is not the linear solution");
    double lo = P[i - 1].omega, hi = P[i].omega;
    if (state(linear(lo)) || !state(linear(hi))) return 0.5 * (lo + hi);   // (not expected)
    while (hi - lo > 1e-13 * hi) {
      const double mid = 0.5 * (lo + hi);
      (state(linear(mid)) ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
  return NAN;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// HB x_max of Delta against GSL rk8pd integrated to a periodic steady state, at up to
// `points` points spread evenly over the stable intermittent part of the branch:
// Hill-stable AND Floquet-stable (where they differ the orbit may be period-2 and the
// integration never becomes 1-periodic, README), and at least
// 0.2 % in omega away from any fold, and not grazing (x_max >= 10 % of the amplitude);
// lib's compare_with_time_integration with the Floquet test as its `accept` filter.
void time_integration_check(const HarmonicBalance& hb, const FrequencyCurve& c, const VectorXd& q, double w0,
                            int points, const std::string& out, KeyNumbers& key) {
  const auto t0 = std::chrono::steady_clock::now();
  long hill_only = 0;   // Hill-stable candidates that Floquet calls unstable
  TimeIntegrationCheckOptions o;
  o.points = points;
  o.min_crest_fraction = 0.1;
  o.omega_factor = w0;
  o.accept = [&](std::size_t i) {
    const auto& p = c.branch.points[i];
    const bool ok = floquet_max(hb, p.X, p.omega, c.scaling.x[0]) < 1.0;
    hill_only += !ok;
    return ok;
  };
  const TimeIntegrationCheck chk = compare_with_time_integration(hb, c, q, o);
  time_integration_table(chk).write(out + "check_time_integration.csv");
  key.add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
  key.add("time_integration_points", double(chk.points), "-");
  std::cout << "ch06_gear_pair: time-integration check (Fig. 43): " << chk.points << " points, worst "
            << chk.worst_rel_diff << "; " << hill_only << " Hill-stable intermittent points are Floquet-unstable ("
            << seconds_since(t0) << " s)\n";
}

}  // namespace

int main(int argc, char** argv) {
  GearPairParameters gp;
  Loading load;
  Solver sol;
  int damping_on_mesh = 0;
  ParameterSet P;
  P.add("alpha_deg", &gp.alpha_deg, "deg", "pressure angle", Range::between(0.0, 89.0));
  P.add("I1", &gp.I1, "kg m^2", "gear 1 polar inertia", Range::positive());
  P.add("m1", &gp.m1, "kg", "gear 1 mass", Range::positive());
  P.add("rb1", &gp.rb1, "m", "gear 1 base radius", Range::positive());
  P.add("I2", &gp.I2, "kg m^2", "gear 2 polar inertia", Range::positive());
  P.add("m2", &gp.m2, "kg", "gear 2 mass", Range::positive());
  P.add("rb2", &gp.rb2, "m", "gear 2 base radius", Range::positive());
  P.add("kx1", &gp.kx1, "N/m", "gear 1 support stiffness along x", Range::positive());
  P.add("ky1", &gp.ky1, "N/m", "gear 1 support stiffness along y", Range::positive());
  P.add("kth1", &gp.kth1, "N m/rad", "gear 1 torsional support stiffness (thesis prints 'N')", Range::positive());
  P.add("kx2", &gp.kx2, "N/m", "gear 2 support stiffness along x", Range::positive());
  P.add("ky2", &gp.ky2, "N/m", "gear 2 support stiffness along y", Range::positive());
  P.add("kth2", &gp.kth2, "N m/rad", "gear 2 torsional support stiffness (thesis prints 'N')", Range::positive());
  P.add("kc", &gp.kc, "N/m", "mesh stiffness (thesis prints 5e2; 5e8 reproduces its text, README)", Range::positive());
  P.add("kc_alt", &sol.kc_alt, "N/m", "the other mesh stiffness of the kc study", Range::positive());
  P.add("ray_alpha", &gp.rayleigh_alpha, "1/s", "C = alpha M + beta K", Range::nonnegative());
  P.add("ray_beta", &gp.rayleigh_beta, "s", "C = alpha M + beta K", Range::nonnegative());
  P.add("damp_mesh", &damping_on_mesh, "-", "1: beta multiplies K + Kc, 0: K (supports) only", Range::between(0, 1));
  P.add("Fi", &load.Fi, "N m", "static torque on gear 1 (single=1); gear 2 gets -Fi rb2/rb1");
  P.add("Fa", &load.Fa, "N, N m", "harmonic amplitude of F = Fa [1,0,1,1,0,1] (single=1)", Range::nonnegative());
  P.add("H", &sol.H, "-", "number of harmonics", Range::at_least(1));
  P.add("N", &sol.N, "-", "AFT time samples per period (0 = 4(2H+1))", Range::nonnegative());
  P.add("omega_min", &sol.omega_min, "rad/s", "start of the frequency range (>= 1 % of the lowest natural frequency)", Range::positive());
  P.add("omega_max", &sol.omega_max, "rad/s", "end of the frequency range", Range::positive());
  P.add("tolerance", &sol.tolerance, "-", "corrector tolerance (scaled residual and step)", Range::positive());
  P.add("corr_iter", &sol.corrector_iterations, "-", "corrector Newton iterations per step", Range::at_least(1));
  P.add("ds_max", &sol.ds_max, "-", "largest scaled arc-length step", Range::positive());
  P.add("ds_max_alt", &sol.ds_max_alt, "-", "largest scaled arc-length step of the kc_alt curves", Range::positive());
  P.add("ti_points", &sol.ti_points, "-", "HB vs time-integration comparison points", Range::at_least(1));
  P.add("H_check", &sol.H_check, "-", "harmonics of the HB vs time-integration check (Fig. 43)", Range::at_least(1));
  P.add("single", &sol.single, "-", "1: one curve with Fi, Fa into DIR/frc.csv", Range::between(0, 1));
  P.add("quick", &sol.quick, "-", "1: regression subset (key numbers, reduced sizes)", Range::between(0, 1));

  const std::string usage =
      "ch06_gear_pair: 6-DOF spur-gear pair, M q'' + C q' + K q = F0 + F cos(w t) + T1 max(kc T2 q, 0)\n"
      "(thesis ch. 6, Figs. 40-45). Default: every figure for kc and kc_alt. single=1: one curve.";
  return run_chapter("ch06_gear_pair", usage, argc, argv, P, "build/data/ch06_gear_pair",
                     [&](const CommandLine& cl) {
    gp.damping_on_mesh = damping_on_mesh != 0;
    ParameterSet::require(sol.omega_min < sol.omega_max, "parameter 'omega_min' must be < omega_max");
    ParameterSet::require(sol.N == 0 || sol.N >= 4 * sol.H + 2,
                          "parameter 'N' must be 0 or >= 4H+2 (" + std::to_string(4 * sol.H + 2) + ")");
    // Below ~1 % of the lowest natural frequency the response is quasi-static
    // (1e-4 relative dynamic amplification) and the arc length would spend its steps there.
    const double w_low = modal_analysis(gear_pair_mass(gp), gear_pair_support_stiffness(gp)).omega.minCoeff();
    {
      std::ostringstream os;
      os << "parameter 'omega_min' must be >= 1 % of the lowest natural frequency (" << 0.01 * w_low << " rad/s)";
      ParameterSet::require(sol.omega_min >= 0.01 * w_low, os.str());
    }
    const double w0 = w_low;   // time unit of the solver (make_model)
    const std::string out = cl.out_dir + "/";
    const VectorXd T2 = gear_pair_T2(gp);
    KeyNumbers key;
    write_file_atomic(out + "params.json", P.to_json().dump(2) + "\n");

    // ---- Single curve: the user's own parameters ---------------------------
    if (sol.single) {
      HarmonicBalance hb = make_model(gp, load.Fi, load.Fa, sol, w0);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sol, sol.omega_min, sol.omega_max, w0), "frc"), "frc");
      frc_table(hb, c, floquet_stability(hb, c), T2, w0).write(out + "frc.csv");
      const ContactSummary s = summarize_contact(hb, c, T2, w0);
      key.add("transitions", s.transitions, "-");
      key.add("folds", double(c.branch.folds.size()), "-");
      key.add("delta_max", s.delta_max, "m");
      key.add("delta_min", s.delta_min, "m");
      key.write(out + "key_numbers.json");
      std::cout << "ch06_gear_pair: " << c.branch.summary() << " -> " << out << "frc.csv\n";
      return;
    }

    // ---- Step 1: modal analysis, open and closed mesh, both kc -------------
    const std::vector<double> kcs = {gp.kc, sol.kc_alt};
    {
      Table t({"kc", "mode", "omega_open", "omega_closed"});
      for (std::size_t j = 0; j < kcs.size(); ++j) {
        GearPairParameters g = gp;
        g.kc = kcs[j];
        const MatrixXd M = gear_pair_mass(g), K = gear_pair_support_stiffness(g);
        const Modes open = modal_analysis(M, K), closed = modal_analysis(M, K + gear_pair_mesh_stiffness(g));
        for (int i = 0; i < 6; ++i) {
          t.add_row({kcs[j], long(i + 1), open.omega[i], closed.omega[i]});
          if (j == 0) key.add("omega_open_" + std::to_string(i + 1), open.omega[i], "rad/s");
          key.add("omega_closed_" + std::to_string(i + 1) + "_kc" + kc_tag(kcs[j]), closed.omega[i], "rad/s");
        }
      }
      t.write(out + "modes.csv");
    }

    // ---- Step 2: linear |Delta| of the open and closed systems -------------
    if (!sol.quick)
      for (double kc : kcs) {
        GearPairParameters g = gp;
        g.kc = kc;
        LinearSystem open = gear_pair_system(g), closed = open;
        closed.K += gear_pair_mesh_stiffness(g);
        Table t({"omega", "delta_open", "delta_closed"});
        const Eigen::VectorXcd F = harmonic_shape(1e4).cast<std::complex<double>>();
        for (int i = 0; i <= 3000; ++i) {
          const double w = sol.omega_min + (sol.omega_max - sol.omega_min) * i / 3000.0;
          t.add_row({w, std::abs(T2.dot(frequency_response(open, F, w))),
                     std::abs(T2.dot(frequency_response(closed, F, w)))});
        }
        t.write(out + "linear_kc" + kc_tag(kc) + ".csv");
      }

    // ---- Step 3: the frequency responses of Figs. 40-45, both kc -----------
    Table index({"figure", "kc", "Fi", "Fa", "static_delta_open", "static_delta_closed", "points", "folds",
                 "unstable_points", "hill_stable_floquet_unstable", "rejected_steps", "transitions", "start", "end", "changed_lo",
                 "changed_hi", "first_change_omega", "delta_max", "delta_min"});
    for (double kc : kcs) {
      if (sol.quick && kc != gp.kc) continue;
      GearPairParameters g = gp;
      g.kc = kc;
      for (const Case& cs : kCases) {
        // quick: the two curves whose first transitions are checked, Fig. 41 and 43,
        // on the part of the range that holds them.
        if (sol.quick && cs.figure != 41 && cs.figure != 43) continue;
        // quick: up to just past the first contact change (Fig. 41: 13567.6 rad/s) and, for
        // Fig. 43, over the first stable intermittent band (11.2-12.7 krad/s) for the check.
        const double wmax = sol.quick ? std::min(sol.omega_max, cs.figure == 41 ? 13570.0 : 11000.0) : sol.omega_max;
        const auto t0 = std::chrono::steady_clock::now();
        // quick: the first contact change is located on the linear solution inside the
        // HB bracket (first_change), which does not depend on H: H = 3 is enough there.
        Solver sc = sol;
        if (sol.quick) sc.H = std::min(sol.H, 3), sc.N = 0;
        if (kc != gp.kc) sc.ds_max = sol.ds_max_alt;
        HarmonicBalance hb = make_model(g, cs.Fi, cs.Fa, sc, w0);
        const std::string label = "fig" + std::to_string(cs.figure) + " kc=" + kc_tag(kc);
        const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sc, sol.omega_min, wmax, w0), label), label);
        const std::string stem = "fig" + std::to_string(cs.figure) + "_kc" + kc_tag(kc);
        const std::vector<bool> floq = sol.quick ? c.stable : floquet_stability(hb, c);
        long hill_only = 0;   // Hill-stable points that Floquet calls unstable
        for (std::size_t i = 0; i < floq.size(); ++i) hill_only += (c.stable[i] && !floq[i]) ? 1 : 0;
        if (!sol.quick) frc_table(hb, c, floq, T2, w0).write(out + "frc_" + stem + ".csv");
        const ContactSummary s = summarize_contact(hb, c, T2, w0);
        const double first = w0 * first_change(hb, c, cs.Fi > 0 ? opens_somewhere(hb) : touches_somewhere(hb), cs.Fi > 0);
        const VectorXd F0 = gear_pair_static_torque(g, cs.Fi);
        const MatrixXd K = gear_pair_support_stiffness(g);
        const double d_open = T2.dot(K.ldlt().solve(F0));
        const double d_closed = T2.dot((K + gear_pair_mesh_stiffness(g)).ldlt().solve(F0));
        long unstable = 0;
        for (bool st : c.stable) unstable += st ? 0 : 1;
        index.add_row({long(cs.figure), kc, cs.Fi, cs.Fa, d_open, d_closed, long(c.branch.points.size()),
                       long(c.branch.folds.size()), unstable, hill_only, long(c.branch.rejected_steps), long(s.transitions),
                       s.start, s.end, s.intermittent_lo, s.intermittent_hi, first, s.delta_max, s.delta_min});
        key.add("transitions_" + stem, s.transitions, "-");
        key.add("first_change_omega_" + stem, std::isnan(first) ? 0.0 : first, "rad/s");
        std::cout << "ch06_gear_pair: " << stem << ": " << c.branch.summary() << ", " << s.transitions
                  << " contact transitions (" << s.start << " -> " << s.end << ")\n";
      }
    }
    index.write(out + "cases.csv");

    // ---- Step 4: harmonic balance against GSL time integration (Fig. 43) ---
    // Its own sweep with H_check harmonics from the open state at 10 krad/s over the
    // intermittent band (quick: its first stable part, up to 12.6 krad/s).
    {
      Solver sc = sol;
      sc.H = sol.H_check;
      sc.N = 0;
      sc.ds_max = 0.02;   // library default: 10-20 krad/s of Fig. 43 has no fold pair it steps over
      const double whi = sol.quick ? 12600.0 : 20000.0;
      ParameterSet::require(sol.omega_min <= 10000.0 && sol.omega_max >= whi,
                            "parameter 'omega_min'/'omega_max' must contain 10-20 krad/s for the time-integration check");
      HarmonicBalance hb = make_model(gp, -1e6, 1e4, sc, w0);
      const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(sc, 10000.0, whi, w0), "check"), "check");
      time_integration_check(hb, c, T2, w0, sol.quick ? 6 : sol.ti_points, out, key);
    }

    // ---- Step 5: convergence in H (Fig. 43 case, intermittent band) -------
    if (!sol.quick) {
      Table t({"H", "points", "folds", "delta_max_peak", "delta_min_peak"});
      for (int H : {3, 5, 8, 10, 14}) {
        Solver s2 = sol;
        s2.H = H;
        s2.N = 0;
        const auto t0 = std::chrono::steady_clock::now();
        HarmonicBalance hb = make_model(gp, -1e6, 1e4, s2, w0);
        const FrequencyCurve c = require_complete(sweep_frequency(hb, sweep_options(s2, 10000.0, 20000.0, w0), "H study"), "H study");
        const ContactSummary s = summarize_contact(hb, c, T2, w0);
        t.add_row({long(H), long(c.branch.points.size()), long(c.branch.folds.size()), s.delta_max,
                   s.delta_min});
      }
      t.write(out + "h_study.csv");
    }
    key.write(out + "key_numbers.json");
    std::cout << "ch06_gear_pair: data in " << cl.out_dir << "\n";
  });
}
