// The Kahraman & Singh (1990) clearance oscillator (issue 21: the engine under a gear pair
// with backlash):
//
//   x'' + 2 zeta x' + f(x) = F_m + F_a cos(Omega t),  f the dead zone of half-width 1,
//
// as the library writes it: M = 1, C = 2 zeta = 0.1, K = 0, two contacts with normals
// [1] (drive flank) and [-1] (back flank), gap -1, kc 1; F_m = 0.1.
// Independent truths:
//  - steady states (x_max, x_min) by scipy's DOP853, reference/scripts/
//    clearance_oscillator_time_integration.py (no gearhb code; its output is quoted
//    below with the case names of the script);
//  - GSL rk8pd time integration (hb/time_integration.hpp) from the HB orbit, and its
//    variational monodromy, against the Floquet multipliers of the exact flow;
//  - with no spring to ground and clearances on both sides the sweep must start from
//    either end of the range (first_point.hpp); K = 0 has no open-contact equilibrium.
#include <cmath>
#include <complex>
#include <iostream>
#include <map>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/first_point.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::VectorXd;

namespace {

HarmonicBalance clearance_oscillator(double Fa, int H = 20) {
  LinearSystem s;
  s.M = Eigen::MatrixXd::Ones(1, 1);
  s.C = 0.1 * s.M;
  s.K = Eigen::MatrixXd::Zero(1, 1);
  UnilateralContact drive, back;
  drive.normal = VectorXd::Ones(1);
  drive.kc = 1.0;
  drive.gap = -1.0;
  drive.gap_harmonics = VectorXd::Zero(2 * H + 1);
  back = drive;
  back.normal = -drive.normal;
  const Excitation f{VectorXd::Constant(1, 0.1), VectorXd::Constant(1, Fa), VectorXd::Zero(1)};
  return HarmonicBalance(s, {drive, back}, f, H);
}

FrequencyCurve sweep(const HarmonicBalance& hb, double from, double to) {
  SweepOptions o;
  o.omega_min = std::min(from, to);
  o.omega_max = std::max(from, to);
  o.direction = from < to ? SweepDirection::up : SweepDirection::down;
  return sweep_frequency(hb, o, "clearance oscillator");
}

// The four sweeps (F_a = 0.1, 0.5; down from 2.0, up from 0.3), computed once.
const FrequencyCurve& cached_sweep(const HarmonicBalance& hb, double Fa, bool up) {
  static std::map<std::pair<double, bool>, FrequencyCurve> cache;
  auto it = cache.find({Fa, up});
  if (it == cache.end()) it = cache.emplace(std::make_pair(Fa, up), up ? sweep(hb, 0.3, 2.0) : sweep(hb, 2.0, 0.3)).first;
  return it->second;
}

// The HB orbit at omega on the branch: of the branch segments that bracket omega, the one
// whose end point starts (phase 0) nearest x0_seed, re-solved by Newton at omega exactly.
// Empty if no segment brackets omega.
VectorXd hb_at(const HarmonicBalance& hb, const FrequencyCurve& c, double w, double x0_seed) {
  const auto& P = c.branch.points;
  VectorXd best;
  double d = INFINITY;
  for (std::size_t i = 1; i < P.size(); ++i) {
    if ((P[i - 1].omega - w) * (P[i].omega - w) > 0) continue;
    VectorXd X = P[i].X;
    if (!newton_solve(hb, X, w, c.scaling).converged) continue;
    VectorXd x0, v0;
    hb_initial_state(hb, X, w, x0, v0);
    if (std::fabs(x0[0] - x0_seed) < d) d = std::fabs(x0[0] - x0_seed), best = X;
  }
  return best;
}

ContactState state_of(const HarmonicBalance& hb, const VectorXd& X, std::size_t i) {
  const Aft aft(hb.harmonics(), 1024);
  const VectorXd u = hb.penetration(X, i);
  return contact_state(u, aft.to_time(u));
}

struct Case {
  const char* what;
  double Fa, omega, seed;   // seed: x at phase 0 near the orbit wanted (where orbits coexist)
  double x_max, x_min;      // scipy DOP853 (reference/scripts/clearance_oscillator_time_integration.py)
  ContactState drive, back; // expected state of each flank over the period
};

// clang-format off
const Case cases[] = {
  {"no impact",                      0.1, 1.8,     1.06,  1.1444994154,  1.0555005839, ContactState::full,         ContactState::open},
  {"one-sided impacts",              0.1, 1.0,     0.81,  1.3042264980,  0.8039478116, ContactState::intermittent, ContactState::open},
  {"one-sided, small orbit of three",0.1, 0.49,    1.28,  1.2836910951,  0.9754997353, ContactState::intermittent, ContactState::open},
  {"one-sided, middle orbit",        0.1, 0.49,   -0.58,  1.6262003373, -0.7165373467, ContactState::intermittent, ContactState::open},
  {"two-sided, large orbit",         0.1, 0.49,    0.82,  1.9599039085, -1.4480354778, ContactState::intermittent, ContactState::intermittent},
  {"two-sided impacts",              0.5, 0.8,     3.18,  4.6700081356, -4.4094891517, ContactState::intermittent, ContactState::intermittent},
  {"back-flank grazing",             0.5, 0.7305, -1.00,  1.5722292327, -1.0227330306, ContactState::intermittent, ContactState::intermittent},
};
// clang-format on

}  // namespace

// K = 0 with clearances on both sides: the first point is found from either end of the
// range (with the linear guesses alone Newton stops on a singular Jacobian).
TEST(ClearanceOscillator, SweepStartsFromEitherEnd) {
  for (double Fa : {0.05, 0.1, 0.2, 0.5}) {
    const HarmonicBalance hb = clearance_oscillator(Fa);
    for (bool up : {false, true}) {
      const FrequencyCurve c = up ? sweep(hb, 0.3, 2.0) : sweep(hb, 2.0, 0.3);
      EXPECT_TRUE(c.complete) << "F_a = " << Fa << (up ? " up: " : " down: ") << c.failure;
      EXPECT_NE(c.first_point, FirstPointMethod::linear_guess) << "the linear guess alone starts no sweep here";
    }
  }
}

// At Omega = 0.3, F_a = 0.1 (a regime no linear solution is near) the forcing-amplitude
// continuation from the loaded static equilibrium is what finds the point; it is the
// stable orbit scipy reaches from rest (x_max 1.2494844384, x_min 0.9216513662).
TEST(ClearanceOscillator, FirstPointByAmplitudeContinuation) {
  const HarmonicBalance hb = clearance_oscillator(0.1);
  const Scaling s = hb.scaling(0.3, 2.0);
  const FirstPoint fp = find_first_point(hb, 0.3, s);
  ASSERT_TRUE(fp.found) << fp.failure;
  EXPECT_EQ(fp.method, FirstPointMethod::amplitude_continuation);
  EXPECT_EQ(fp.contact_set, 1u) << "the static start: drive flank closed, back flank open";
  const ResponseSummary r = ResponseEvaluator(hb, VectorXd::Ones(1)).summarize(fp.X);
  EXPECT_NEAR(r.x_max, 1.2494844384, 1e-2 * 1.2494844384);
  EXPECT_NEAR(r.x_min, 0.9216513662, 1e-2 * 0.9216513662);
}

// A static load that no contact can hold (K = 0, only the back flank, F_m pushing away
// from it): there is no periodic solution at all (the mean drifts). The sweep says it
// cannot start and why, instead of returning an empty success.
TEST(ClearanceOscillator, NoStartWithoutEquilibriumSaysWhy) {
  const HarmonicBalance two = clearance_oscillator(0.1);
  const HarmonicBalance hb(two.system(), {two.contacts()[1]}, two.excitation(), two.harmonics());
  const FrequencyCurve c = sweep(hb, 0.5, 2.0);
  EXPECT_FALSE(c.complete);
  EXPECT_TRUE(c.branch.points.empty());
  EXPECT_NE(c.failure.find("cannot start"), std::string::npos) << c.failure;
  EXPECT_NE(c.failure.find("no static equilibrium"), std::string::npos) << c.failure;
}

// HB, Floquet and GSL time integration agree with scipy at points with no impact,
// one-sided and two-sided impacts and a back-flank graze, on the branches of both sweep
// directions (1 % on x_max and x_min, the criterion).
TEST(ClearanceOscillator, HbFloquetAndTimeIntegrationAgree) {
  for (const Case& k : cases) {
    const HarmonicBalance hb = clearance_oscillator(k.Fa);
    for (bool up : {false, true}) {
      const FrequencyCurve& c = cached_sweep(hb, k.Fa, up);
      ASSERT_TRUE(c.complete) << c.failure;
      const std::string at = std::string(k.what) + (up ? " (up sweep)" : " (down sweep)");
      const VectorXd X = hb_at(hb, c, k.omega, k.seed);
      ASSERT_GT(X.size(), 0) << at << ": the branch does not pass omega";
      const ResponseSummary r = ResponseEvaluator(hb, VectorXd::Ones(1)).summarize(X);
      EXPECT_NEAR(r.x_max, k.x_max, 1e-2 * std::fabs(k.x_max)) << at;
      EXPECT_NEAR(r.x_min, k.x_min, 1e-2 * std::fabs(k.x_min)) << at;
      EXPECT_EQ(state_of(hb, X, 0), k.drive) << at << ": drive flank";
      EXPECT_EQ(state_of(hb, X, 1), k.back) << at << ": back flank";
      const FloquetResult fl = floquet_of_hb_orbit(hb, X, k.omega, c.scaling.x[0]);
      EXPECT_TRUE(fl.corrected && fl.stable) << at << ": |mu| = " << fl.modulus;
      // GSL from the HB state to the periodic steady state, and its variational monodromy
      TimeIntegrator ti(hb);
      TimeIntegrationOptions to;
      to.x_scale = c.scaling.x[0];
      VectorXd x0, v0;
      hb_initial_state(hb, X, k.omega, x0, v0);
      const SteadyState ss = ti.steady_state(x0, v0, k.omega, to);
      ASSERT_TRUE(ss.converged) << at;
      EXPECT_NEAR(ss.x.maxCoeff(), k.x_max, 1e-2 * std::fabs(k.x_max)) << at;
      EXPECT_NEAR(ss.x.minCoeff(), k.x_min, 1e-2 * std::fabs(k.x_min)) << at;
      // every multiplier (a complex pair's modulus alone is fixed by det = exp(-2 zeta T);
      // the pair itself is not): each Floquet one has a GSL one within 1e-6
      const Eigen::VectorXcd mu = general_eigenvalues(ti.monodromy(ss.x0, ss.v0, k.omega, to), "GSL monodromy");
      for (Eigen::Index i = 0; i < fl.multipliers.size(); ++i)
        EXPECT_LT((mu.array() - fl.multipliers[i]).abs().minCoeff(), 1e-6) << at << ": multiplier " << fl.multipliers[i];
    }
  }
}

// Where Floquet says unstable, the time integration leaves the orbit: at Omega = 0.7305,
// F_a = 0.5 the orbit between the back-flank graze and the large two-sided one
// (x_max 1.606, |mu| 2.3) is left within a few periods, for the stable large orbit.
TEST(ClearanceOscillator, TimeIntegrationLeavesAnOrbitFloquetCallsUnstable) {
  const HarmonicBalance hb = clearance_oscillator(0.5);
  const FrequencyCurve& c = cached_sweep(hb, 0.5, false);
  const VectorXd X = hb_at(hb, c, 0.7305, -1.076);
  ASSERT_GT(X.size(), 0);
  const ResponseSummary r = ResponseEvaluator(hb, VectorXd::Ones(1)).summarize(X);
  ASSERT_NEAR(r.x_max, 1.606, 5e-3) << "the unstable middle orbit";
  const FloquetResult fl = floquet_of_hb_orbit(hb, X, 0.7305, c.scaling.x[0]);
  ASSERT_FALSE(fl.stable);
  EXPECT_GT(fl.modulus, 2.0);
  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.x_scale = c.scaling.x[0];
  // from the corrected orbit itself, displaced by 1e-6: it grows like |mu|^periods
  const SteadyState ss = ti.steady_state(fl.x0 + VectorXd::Constant(1, 1e-6), fl.v0, 0.7305, to);
  ASSERT_TRUE(ss.converged);
  EXPECT_GT(ss.periods, 10);
  // it settles on the large stable orbit of the same frequency (scipy: x_max 3.8296233290
  // from rest, reference/scripts/clearance_oscillator_time_integration.py)
  EXPECT_NEAR(ss.x.maxCoeff(), 3.8296233290, 1e-2 * 3.8296233290);
}

// Issue 21 §2: near Omega = 0.3145 at F_a = 0.1 a fold and a period doubling lie 1.3e-4
// apart; before the fix bifurcations listed the doubling twice and missed the fold
// (H = 20) or listed both twice (H = 10). Each crossing once, with its own type; the
// doubling is where GSL's variational monodromy (independent of the Floquet exponentials)
// has its multiplier cross -1.
TEST(ClearanceOscillator, FoldAndPeriodDoublingEachListedOnce) {
  for (int H : {10, 20}) {
    const HarmonicBalance hb = clearance_oscillator(0.1, H);
    const FrequencyCurve c = sweep(hb, 2.0, 0.3);
    ASSERT_TRUE(c.complete) << c.failure;
    int folds = 0, doublings = 0;
    double w_pd = NAN;
    for (const auto& b : c.bifurcations) {
      if (b.omega < 0.3144 || b.omega > 0.3147) continue;
      folds += b.type == BifurcationType::fold;
      if (b.type == BifurcationType::period_doubling) ++doublings, w_pd = b.omega;
    }
    EXPECT_EQ(folds, 1) << "H = " << H;
    EXPECT_EQ(doublings, 1) << "H = " << H;
    for (std::size_t i = 0; i < c.bifurcations.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE(c.bifurcations[i].type == c.bifurcations[j].type &&
                     std::fabs(c.bifurcations[i].omega - c.bifurcations[j].omega) < 1e-6)
            << "H = " << H << ": " << to_string(c.bifurcations[i].type) << " at " << c.bifurcations[i].omega << " twice";
    // the doubling against GSL: the real multiplier below -1 just above it, above -1 below
    ASSERT_TRUE(std::isfinite(w_pd));
    TimeIntegrator ti(hb);
    TimeIntegrationOptions to;
    to.x_scale = c.scaling.x[0];
    for (double dw : {-3e-5, 3e-5}) {
      const double w = w_pd + dw;
      const VectorXd X = hb_at(hb, c, w, 1.0);
      ASSERT_GT(X.size(), 0);
      const FloquetResult fl = floquet_of_hb_orbit(hb, X, w, c.scaling.x[0]);
      const Eigen::VectorXcd mu = general_eigenvalues(ti.monodromy(fl.x0, fl.v0, w, to), "GSL monodromy");
      double most_negative = 0.0;
      for (Eigen::Index i = 0; i < mu.size(); ++i)
        if (std::fabs(mu[i].imag()) < 1e-9) most_negative = std::min(most_negative, mu[i].real());
      if (dw < 0) EXPECT_GT(most_negative, -1.0) << "H = " << H << " below the doubling";
      else EXPECT_LT(most_negative, -1.0) << "H = " << H << " above the doubling";
    }
  }
}

// The parametric clearance oscillator of Kahraman & Singh (1991): both flanks with the
// stiffness 1 + 0.2 cos(Omega t) (gearhb_frc's parametric_clearance_oscillator.json). No
// exact flow exists, so the HB orbit is corrected by shooting on GSL's period map
// (floquet_of_hb_shooting_gsl). At Omega = 0.3, F_a = 0.1 (drive flank lost every period)
// the corrected orbit's extremes match scipy's steady state, x_max = 1.2723016454,
// x_min = 0.8821561106 (reference/scripts/clearance_oscillator_time_integration.py
// --parametric, 'parametric example start'), to 1e-8, far below the H = 20 HB error
// (~1e-5) that orbit_error reports.
TEST(ClearanceOscillator, ParametricOrbitCorrectedByShootingMatchesScipy) {
  const double w = 0.3;
  HarmonicBalance base = clearance_oscillator(0.1);
  std::vector<UnilateralContact> contacts = base.contacts();
  for (auto& ct : contacts) ct.stiffness_profile = [](double th) { return 1.0 + 0.2 * std::cos(th); };
  const HarmonicBalance hb(base.system(), contacts, base.excitation(), 20);
  const Scaling s = hb.scaling(w, w);
  const FirstPoint fp = find_first_point(hb, w, s);
  ASSERT_TRUE(fp.found) << fp.failure;
  const FloquetResult fl = floquet_of_hb_orbit(hb, fp.X, w, s.x[0]);
  EXPECT_TRUE(fl.corrected);
  EXPECT_LT(fl.shooting_residual, 1e-10);
  EXPECT_GT(fl.orbit_error, 1e-7) << "H = 20 is not exact for an impacting orbit";
  EXPECT_LT(fl.orbit_error, 1e-4);
  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.rel_tol = 1e-12;
  to.abs_tol = 1e-13;
  to.samples_per_period = 2000;
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  EXPECT_NEAR(ti.max_over_period(fl.x0, fl.v0, w, one, to), 1.2723016454, 1e-8);
  EXPECT_NEAR(-ti.max_over_period(fl.x0, fl.v0, w, -one, to), 0.8821561106, 1e-8);
  // the corrected orbit is periodic under an independent integration (steady_state from it)
  const SteadyState ss = ti.steady_state(fl.x0, fl.v0, w, to);
  EXPECT_TRUE(ss.converged);
  EXPECT_LE(ss.periods, 2);
  EXPECT_TRUE(fl.stable);
}
