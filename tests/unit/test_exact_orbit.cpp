// The exact periodic orbit behind every harmonic-balance point (hb/exact_orbit.hpp):
// the HB point corrected by shooting on the exact piecewise-linear flow
// (floquet_of_hb_orbit), then measured by ExactOrbit. Independent checks:
//  - closed forms of linear periodic solutions, x = x_mean + Re(A e^{i w t}),
//    A = F / (k_eff - m w^2 + i c w): a linear oscillator without contact, the mass
//    against the wall with the contact closed all period (k_eff = k + kc, mean contact
//    force kc (g + x_mean)) and open all period; started from an HB point perturbed by
//    1e-3, so the shooting Newton does the work; to 1e-12 of max(amplitude, |mean|);
//  - GSL rk8pd (hb/time_integration.hpp, rel_tol 1e-12) from the corrected state over one
//    period on NLvib example 03 (an impacting point) and on the mass against the wall at
//    a near-grazing point (penetration depth 1e-3 of the amplitude): the state at 4096
//    samples, the mean, the AC RMS and the first harmonic by the periodic trapezoid rule
//    on those samples, x_max by the integrator's own Brent-refined crest; to 1e-9.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/hb/exact_orbit.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::VectorXd;

namespace {

// A linear 1-DOF oscillator m = 1, c = 0.01, k = 1 with forcing F0 + F cos(w t), no contact.
HarmonicBalance oscillator(int H, double F0, double F) {
  LinearSystem s{Eigen::MatrixXd::Constant(1, 1, 1.0), Eigen::MatrixXd::Constant(1, 1, 0.01),
                 Eigen::MatrixXd::Constant(1, 1, 1.0)};
  Excitation f{VectorXd::Constant(1, F0), VectorXd::Constant(1, F), VectorXd::Zero(1)};
  return HarmonicBalance(s, {}, f, H);
}

// The HB point at omega by Newton from the better linear solution.
VectorXd hb_point(const HarmonicBalance& hb, double w) {
  VectorXd X = hb.contacts().empty() ? hb.open_contact_solution(w) : hb.closed_contact_solution(w);
  if (!hb.contacts().empty()) {
    VectorXd R, Ro;
    VectorXd Xo = hb.open_contact_solution(w);
    hb.evaluate(X, w, R, nullptr, nullptr);
    hb.evaluate(Xo, w, Ro, nullptr, nullptr);
    if (Ro.norm() < R.norm()) X = Xo;
  }
  const NewtonReport nr = newton_solve(hb, X, w, hb.scaling(w, w));
  EXPECT_TRUE(nr.converged) << nr.message;
  return X;
}

// The shooting correction of the HB point X at omega, to a residual of 1e-13.
FloquetResult shoot(const HarmonicBalance& hb, const VectorXd& X, double w, double x_scale) {
  FloquetOptions o;
  o.tolerance = 1e-13;
  const FloquetResult r = floquet_of_hb_orbit(hb, X, w, x_scale, o);
  EXPECT_TRUE(r.corrected) << "shooting residual " << r.shooting_residual;
  return r;
}

// The corrected orbit of the HB point X (perturbed by `perturb` relative) at omega.
ExactOrbit corrected(const HarmonicBalance& hb, VectorXd X, double w, double x_scale, double perturb = 0.0) {
  X *= 1.0 + perturb;
  const FloquetResult r = shoot(hb, X, w, x_scale);
  ExactOrbit orbit(hb, X, w, r.x0, r.v0);
  EXPECT_TRUE(orbit.consistent());
  EXPECT_LT(orbit.period_mismatch(), 1e-12);
  return orbit;
}

// tol relative to the orbit's size max(amplitude, |mean|) (the rounding of x itself)
void expect_linear(const ExactMeasures& e, double mean, double amp, double tol) {
  const double size = std::max(amp, std::fabs(mean));
  EXPECT_NEAR(e.x_mean, mean, tol * size);
  EXPECT_NEAR(e.x_h1, amp, tol * size);
  EXPECT_NEAR(e.x_rms_ac, amp / std::sqrt(2.0), tol * size);
  EXPECT_NEAR(e.x_max, mean + amp, tol * size);
  EXPECT_NEAR(e.x_min, mean - amp, tol * size);
}

double amplitude(double k, double w, double F) { return std::abs(F / std::complex<double>(k - w * w, 0.01 * w)); }

}  // namespace

TEST(ExactOrbit, LinearOscillatorClosedForm) {
  const double F0 = 0.3, F = 0.01;
  for (double w : {0.5, 0.97, 1.0, 2.5}) {
    const HarmonicBalance hb = oscillator(5, F0, F);
    const ExactOrbit o = corrected(hb, hb_point(hb, w), w, 0.1, 1e-3);
    expect_linear(o.measures(VectorXd::Ones(1)), F0, amplitude(1.0, w, F), 1e-12);
  }
}

TEST(ExactOrbit, FullContactClosedForm) {
  // g = 10: x ~ -5, u = g + x ~ 5 > 0 all period; k_eff = 2, x_mean = (F0 - kc g) / 2
  const double g = 10.0, F0 = 0.2, F = 0.01;
  for (double w : {0.5, 1.41, 3.0}) {
    const HarmonicBalance hb = test_models::mass_wall(g, 7, F0, F);
    const ExactOrbit o = corrected(hb, hb_point(hb, w), w, 0.1, 1e-3);
    const double mean = (F0 - g) / 2.0;
    expect_linear(o.measures(VectorXd::Ones(1)), mean, amplitude(2.0, w, F), 1e-12);
    EXPECT_NEAR(o.mean_contact_force(0), g + mean, 1e-12 * std::fabs(g + mean));
  }
}

TEST(ExactOrbit, OpenContactClosedForm) {
  // g = -1: the wall 1 away, amplitudes <= 0.05 never reach it
  const double g = -1.0, F0 = 0.0, F = 0.01;
  for (double w : {0.5, 0.9, 1.3}) {
    const HarmonicBalance hb = test_models::mass_wall(g, 7, F0, F);
    const ExactOrbit o = corrected(hb, hb_point(hb, w), w, 0.1, 1e-3);
    expect_linear(o.measures(VectorXd::Ones(1)), F0, amplitude(1.0, w, F), 1e-12);
    EXPECT_EQ(o.mean_contact_force(0), 0.0);
  }
}

namespace {

// The exact orbit against GSL rk8pd from its own phase-0 state over one period.
struct Rk8pdCheck {
  double state = 0.0;                               // max |x_exact(t_j) - x_rk(t_j)| / max |x|
  double mean = 0.0, rms = 0.0, h1 = 0.0, crest = 0.0;   // |exact - rk8pd| / amplitude of q' x
};

Rk8pdCheck against_rk8pd(const HarmonicBalance& hb, const ExactOrbit& o, const VectorXd& x0, const VectorXd& v0,
                         const VectorXd& q, double x_scale) {
  const double w = o.omega(), T = 2.0 * M_PI / w;
  TimeIntegrationOptions opt;
  opt.rel_tol = 1e-12;
  opt.abs_tol = 1e-14;
  opt.x_scale = x_scale;
  opt.samples_per_period = 4096;
  const TimeIntegrator ti(hb);
  const Eigen::MatrixXd s = ti.sample(x0, v0, w, 0, 1, opt);   // samples x n
  const int N = int(s.rows());
  Rk8pdCheck c;
  const double xs = s.cwiseAbs().maxCoeff();
  VectorXd y(N);
  for (int j = 0; j < N; ++j) {
    c.state = std::max(c.state, (o.x_at(T * j / N) - s.row(j).transpose()).cwiseAbs().maxCoeff() / xs);
    y[j] = s.row(j).dot(q);
  }
  const double mean = y.mean();
  const double rms = std::sqrt((y.array() - mean).square().mean());
  double a = 0.0, b = 0.0;
  for (int j = 0; j < N; ++j) {
    a += 2.0 / N * y[j] * std::cos(2.0 * M_PI * j / N);
    b += 2.0 / N * y[j] * std::sin(2.0 * M_PI * j / N);
  }
  const ExactMeasures e = o.measures(q);
  const double amp = 0.5 * (e.x_max - e.x_min);
  c.mean = std::fabs(e.x_mean - mean) / amp;
  c.rms = std::fabs(e.x_rms_ac - rms) / amp;
  c.h1 = std::fabs(e.x_h1 - std::hypot(a, b)) / amp;
  c.crest = std::fabs(e.x_max - ti.max_over_period(x0, v0, w, q, opt)) / amp;
  return c;
}

void expect_rk8pd(const Rk8pdCheck& c, double tol) {
  EXPECT_LT(c.state, tol);
  EXPECT_LT(c.mean, tol);
  EXPECT_LT(c.rms, tol);
  EXPECT_LT(c.h1, tol);
  EXPECT_LT(c.crest, tol);
}

}  // namespace

TEST(ExactOrbit, NlvibEx03AgainstRk8pd) {
  // H = 5 (HB orbit error ~1e-3 here): the corrected orbit is exact whatever H. Points of
  // the swept branch in contact: the first below omega = 0.72 and the largest x1.
  const HarmonicBalance hb = test_models::nlvib_ex03(5);
  const FrequencyCurve c = sweep_frequency(hb, test_models::nlvib_ex03_sweep(StabilityMethod::none), "ex03");
  const ResponseEvaluator ev(hb, Eigen::Vector2d(1, 0));
  std::size_t first = 0, peak = 0;
  double top = -INFINITY;
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const ResponseSummary s = ev.summarize(c.branch.points[i].X);
    if (s.contact != ContactState::intermittent) continue;
    if (first == 0 && c.branch.points[i].omega < 0.72) first = i;
    if (s.x_max > top) top = s.x_max, peak = i;
  }
  ASSERT_GT(first, 0u);
  for (std::size_t i : {first, peak}) {
    const VectorXd& X = c.branch.points[i].X;
    const double w = c.branch.points[i].omega;
    const FloquetResult r = shoot(hb, X, w, 1.0);
    const ExactOrbit o(hb, X, w, r.x0, r.v0);
    EXPECT_TRUE(o.consistent());
    const Rk8pdCheck ck = against_rk8pd(hb, o, r.x0, r.v0, Eigen::Vector2d(1, 0), 1.0);
    SCOPED_TRACE("omega " + std::to_string(w) + ": state " + std::to_string(ck.state));
    expect_rk8pd(ck, 1e-9);
    // the mean of the equation of motion: K x_mean + e1 f_mean = 0
    const Eigen::Vector2d xm(o.measures(Eigen::Vector2d(1, 0)).x_mean, o.measures(Eigen::Vector2d(0, 1)).x_mean);
    EXPECT_NEAR(o.mean_contact_force(0), -(hb.system().K * xm)[0], 1e-11);
    EXPECT_NEAR((hb.system().K * xm)[1], 0.0, 1e-11);
  }
}

TEST(ExactOrbit, MassWallNearGrazingAgainstRk8pd) {
  // the wall at 0.999 of the open-contact amplitude: a contact of depth ~1e-4 of the amplitude
  const double w = 0.95, F = 0.01;
  const double g = -0.999 * amplitude(1.0, w, F);
  const HarmonicBalance hb = test_models::mass_wall(g, 10, 0.0, F);
  const VectorXd X = hb_point(hb, w);
  ASSERT_EQ(ResponseEvaluator(hb, VectorXd::Ones(1)).summarize(X).contact, ContactState::intermittent);
  const FloquetResult r = shoot(hb, X, w, 0.1);
  const ExactOrbit o(hb, X, w, r.x0, r.v0);
  EXPECT_TRUE(o.consistent());
  EXPECT_GT(o.measures(VectorXd::Ones(1)).x_max, -g);   // it does touch
  expect_rk8pd(against_rk8pd(hb, o, r.x0, r.v0, VectorXd::Ones(1), 0.1), 1e-9);
}
