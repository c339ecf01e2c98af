// The time-varying contact stiffness (hb/contact.hpp stiffness_profile), its
// harmonic balance and Floquet multipliers, the parametric gear-mesh model
// (gears/dynamics/dte_model.hpp) and the first guess of a system without a spring to
// ground (K = 0), against independent values:
//  - Gauss-Legendre moments of a weighted indicator: closed-form integrals of
//    (2 + cos t) cos(m t) over an interval;
//  - the Galerkin force of k(t) d(t) on a contact interval: closed-form integral
//    of (1 + e cos t)(a0 + a1 cos t) over [-tc, tc], tc = acos(-a0/a1);
//  - a deflection d = F0 / k(t) (the quasi-static solution) gives a constant force F0;
//  - damped Hill equation x'' + c x' + (d + e cos t) x = 0 (x = exp(-c t/2) y):
//    outside the Mathieu tongue both multipliers have modulus exp(-c pi) exactly,
//    inside the first tongue (d = 1/4 + c^2/4) the critical one is real, < -1
//    (Nayfeh & Mook §5.2.2), and mu1 mu2 = exp(-2 pi c) (Liouville);
//  - GSL's variational equation along the integrated orbit (TimeIntegrator::monodromy);
//  - K = 0 under a static load: the open-contact solution does not exist, the
//    closed one x0 = F0 / kc is exact.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
// int_a^b cos(k t) dt and int_a^b sin(k t) dt (k >= 0)
double icos(int k, double a, double b) { return k == 0 ? b - a : (std::sin(k * b) - std::sin(k * a)) / k; }
double isin(int k, double a, double b) { return k == 0 ? 0.0 : (std::cos(k * a) - std::cos(k * b)) / k; }

// One DOF, M = 1, damping c, no spring to ground, unilateral contact of stiffness
// kc s(theta) with no gap, static load F0.
HarmonicBalance parametric_oscillator(double c, double kc, std::function<double(double)> s, double F0, int H,
                                      ContactQuadrature q = ContactQuadrature::exact) {
  const MatrixXd M = MatrixXd::Ones(1, 1), C = MatrixXd::Constant(1, 1, c), K = MatrixXd::Zero(1, 1);
  UnilateralContact ct{VectorXd::Ones(1), kc, 0.0, {}, std::move(s)};
  Excitation f{VectorXd::Constant(1, F0), VectorXd::Zero(1), VectorXd::Zero(1)};
  return HarmonicBalance(LinearSystem{M, C, K}, {ct}, f, H, 0, q);
}
}  // namespace

// (1/2pi) int_a^b (2 + cos t) {cos, sin}(m t) dt in closed form (product to sum).
TEST(ParametricContact, WeightedMomentsMatchClosedForm) {
  const double a = 0.3, b = 2.1;
  const int M = 8;
  std::vector<double> Sc(M + 1), Ss(M + 1);
  weighted_indicator_moments({{a, b}}, [](double t) { return 2.0 + std::cos(t); }, M, 0.2, Sc.data(), Ss.data());
  for (int m = 0; m <= M; ++m) {
    const double c = (2 * icos(m, a, b) + 0.5 * (icos(std::abs(m - 1), a, b) + icos(m + 1, a, b))) / (2 * M_PI);
    // sin(m t) cos t = [sin((m+1) t) + sin((m-1) t)] / 2, sin((m-1)t) = -sin((1-m)t)
    const double s = (2 * isin(m, a, b) + 0.5 * (isin(m + 1, a, b) + (m >= 1 ? isin(m - 1, a, b) : -isin(1, a, b)))) /
                     (2 * M_PI);
    EXPECT_NEAR(Sc[m], c, 1e-14) << "m = " << m;
    EXPECT_NEAR(Ss[m], s, 1e-14) << "m = " << m;
  }
  // w = 1: the closed-form indicator moments
  std::vector<double> Ic(M + 1), Is(M + 1);
  indicator_moments({{a, b}}, M, Ic.data(), Is.data());
  weighted_indicator_moments({{a, b}}, [](double) { return 1.0; }, M, 0.2, Sc.data(), Ss.data());
  for (int m = 0; m <= M; ++m) {
    EXPECT_NEAR(Sc[m], Ic[m], 1e-14);
    EXPECT_NEAR(Ss[m], Is[m], 1e-14);
  }
}

// Mean contact force of d = a0 + a1 cos t, a0 < a1 (contact on [-tc, tc]) with the
// stiffness kc (1 + e cos t): kc/(2pi) [2 a0 tc + 2 (a1 + e a0) sin tc + e a1 (tc + sin tc cos tc)].
// K = 0, no load: the static residual is exactly that force.
TEST(ParametricContact, GalerkinForceOnTheExactContactInterval) {
  const double kc = 3.0, e = 0.4, a0 = 0.3, a1 = 1.0;
  const HarmonicBalance hb = parametric_oscillator(0.1, kc, [e](double t) { return 1.0 + e * std::cos(t); }, 0.0, 4);
  VectorXd X = VectorXd::Zero(hb.size()), R;
  X[0] = a0;
  X[1] = a1;
  MatrixXd J;
  hb.evaluate(X, 0.7, R, &J, nullptr);
  const double tc = std::acos(-a0 / a1);
  const double F = kc / (2 * M_PI) *
                   (2 * a0 * tc + 2 * (a1 + e * a0) * std::sin(tc) + e * a1 * (tc + std::sin(tc) * std::cos(tc)));
  EXPECT_NEAR(R[0], F, 1e-13 * F);
  // the Jacobian is the exact derivative (central differences, the law is smooth away from the crossings)
  for (int j = 0; j < hb.size(); ++j) {
    VectorXd Xp = X, Xm = X, Rp, Rm;
    Xp[j] += 1e-6;
    Xm[j] -= 1e-6;
    hb.evaluate(Xp, 0.7, Rp, nullptr, nullptr);
    hb.evaluate(Xm, 0.7, Rm, nullptr, nullptr);
    EXPECT_LT(((Rp - Rm) / 2e-6 - J.col(j)).lpNorm<Eigen::Infinity>(), 1e-7) << "column " << j;
  }
}

// d = F0 / k(t) makes k d = F0 constant: with k = kc / (1 + e cos t), d = (F0/kc)(1 + e cos t)
// and the residual is only the inertia term -(w^2) d_c1 (exact, sampled to round-off too).
TEST(ParametricContact, QuasiStaticDeflectionCarriesTheLoad) {
  const double kc = 5.0, e = 0.3, F0 = 2.0, w = 0.05;
  for (ContactQuadrature q : {ContactQuadrature::exact, ContactQuadrature::sampled}) {
    const HarmonicBalance hb = parametric_oscillator(0.0, kc, [e](double t) { return 1.0 / (1.0 + e * std::cos(t)); },
                                                     F0, 3, q);
    VectorXd X = VectorXd::Zero(hb.size()), R;
    X[0] = F0 / kc;
    X[1] = e * F0 / kc;
    hb.evaluate(X, w, R, nullptr, nullptr);
    VectorXd expect = VectorXd::Zero(hb.size());
    expect[1] = -w * w * X[1];
    // sampled: 1/(1 + e cos) has all harmonics; (1 + e cos) / (1 + e cos) = 1 sample by sample
    EXPECT_LT((R - expect).lpNorm<Eigen::Infinity>(), 1e-14 * F0);
  }
}

// Damped Hill equation in full contact (x = d - d_orbit obeys x'' + c x' + (dl + e cos t) x = 0).
TEST(ParametricContact, FloquetOfTheDampedMathieuEquation) {
  const double c = 0.01, e = 0.1;
  const double F0 = 1.0;
  struct Point { double dl; bool inside; };
  for (const Point p : {Point{0.45, false}, Point{0.25 + c * c / 4, true}}) {
    const HarmonicBalance hb = parametric_oscillator(c, 1.0, [&](double t) { return p.dl + e * std::cos(t); }, F0, 12);
    const double w = 1.0;
    VectorXd X = linear_first_guess(hb, w);
    ASSERT_TRUE(newton_solve(hb, X, w, hb.scaling(w, w)).converged);
    const Aft aft(12, 256);
    ASSERT_GT(aft.to_time(X).minCoeff(), 0.0) << "the orbit must stay in full contact";
    const FloquetResult r = floquet_of_hb_orbit(hb, X, w, 1.0);
    const std::complex<double> m1 = r.multipliers[0], m2 = r.multipliers[1];
    EXPECT_NEAR(std::abs(m1 * m2), std::exp(-2 * M_PI * c), 1e-9);   // Liouville
    if (p.inside) {
      EXPECT_NEAR(m1.imag(), 0.0, 1e-12);
      EXPECT_LT(m1.real(), -1.0);   // period doubling tongue
      EXPECT_FALSE(r.stable);
    } else {
      EXPECT_NEAR(std::abs(m1), std::exp(-M_PI * c), 1e-9);
      EXPECT_NEAR(std::abs(m2), std::exp(-M_PI * c), 1e-9);
      EXPECT_TRUE(r.stable);
    }
    // GSL's variational equation along the integrated orbit from the HB state
    VectorXd x0, v0;
    hb_initial_state(hb, X, w, x0, v0);
    TimeIntegrationOptions o;
    const MatrixXd Phi = TimeIntegrator(hb).monodromy(x0, v0, w, o);
    EXPECT_NEAR((Phi - r.monodromy).lpNorm<Eigen::Infinity>(), 0.0, 1e-7);
  }
}

// With contact loss the multipliers (variational equation with the switches as
// breakpoints) agree with GSL's along the integrated orbit (to the HB orbit error).
TEST(ParametricContact, FloquetWithContactLossAgreesWithGsl) {
  const double c = 0.2;
  const HarmonicBalance hb = parametric_oscillator(c, 1.0, [](double t) { return 1.0 + 0.3 * std::cos(t); }, 0.02, 25);
  // forced only through the stiffness modulation (amplitude ~ 0.3 F0 / (c w) at the
  // primary resonance w = 1, 1.5 times the static deflection): the contact opens
  SweepOptions o;
  o.omega_min = 0.6;
  o.omega_max = 1.4;
  o.locate_bifurcations = false;
  const FrequencyCurve fc = sweep_frequency(hb, o, "test");
  ASSERT_TRUE(fc.complete);
  const Aft aft(25, 512);
  int checked = 0;
  for (std::size_t i = 0; i < fc.branch.points.size(); i += 7) {
    const auto& P = fc.branch.points[i];
    VectorXd x0, v0;
    hb_initial_state(hb, P.X, P.omega, x0, v0);
    TimeIntegrationOptions to;
    to.x_scale = fc.scaling.x[0];
    const Eigen::VectorXcd mu =
        general_eigenvalues(TimeIntegrator(hb).monodromy(x0, v0, P.omega, to), "GSL monodromy");
    // the HB orbit (H = 25) and the integrated one differ by the truncation error, which
    // moves the contact switches: ~1e-4 in |mu| near the folds, round-off in full contact
    EXPECT_NEAR(mu.cwiseAbs().maxCoeff(), fc.floquet[i].modulus, 1e-3) << "omega = " << P.omega;
    checked += aft.to_time(P.X).minCoeff() < 0.0 ? 1 : 0;
  }
  EXPECT_GT(checked, 0) << "no contact-loss point was compared";
}

// The parametric gear mesh: at low speed d -> e (k = F0 / e), the mean force is F0.
TEST(ParametricContact, GearMeshLowSpeedLimitIsTheSte) {
  DteGear g;
  g.me = 1.4;
  g.kc = 4.7e8;
  g.c = mesh_damping(0.08, g.kc, g.me);
  g.F0 = 4000;
  g.ste = VectorXd::Zero(7);
  g.ste << 10e-6, 0.3e-6, -0.2e-6, 0.1e-6, 0.05e-6, 0.02e-6, 0.0;
  const HarmonicBalance hb = dte_harmonic_balance(g, 3, 0, ContactQuadrature::exact, DteModel::parametric);
  const double w = 2 * M_PI * 1.0;   // (w / wn)^2 ~ 1e-7, c w / k ~ 1e-4
  VectorXd X = linear_first_guess(hb, w);
  ASSERT_TRUE(newton_solve(hb, X, w, hb.scaling(w, w)).converged);
  EXPECT_LT((X - ste_harmonics(g, 3)).lpNorm<Eigen::Infinity>(), 1e-3 * 0.3e-6);
  EXPECT_NEAR(dte_mean_contact_force(hb, X) / g.F0, 1.0, 1e-9);
  EXPECT_NEAR(dte_parametric_stiffness(g, 3, 0.0), g.F0 / (10e-6 + 0.3e-6 + 0.1e-6 + 0.02e-6), 1e-12 * 3.84e8);
  DteGear bad = g;
  bad.ste[1] = 12e-6;   // e < 0 somewhere: no parametric stiffness
  EXPECT_THROW(dte_harmonic_balance(bad, 3, 0, ContactQuadrature::exact, DteModel::parametric), std::invalid_argument);
}

// K = 0 (no spring to ground) under a static load: the open-contact solution has no
// static part (NaN), the first guess is the closed one, and the solution is exact.
TEST(FirstGuess, FreeRigidBodyModeUnderLoad) {
  const MatrixXd M = MatrixXd::Constant(1, 1, 2.0), C = MatrixXd::Constant(1, 1, 0.1), K = MatrixXd::Zero(1, 1);
  const double kc = 4.0, F0 = 3.0, gap = 0.5;
  Excitation f{VectorXd::Constant(1, F0), VectorXd::Constant(1, 0.2), VectorXd::Zero(1)};
  const HarmonicBalance hb(LinearSystem{M, C, K}, {UnilateralContact{VectorXd::Ones(1), kc, gap, {}}}, f, 3);
  EXPECT_TRUE(std::isnan(hb.open_contact_solution(1.0)[0]));
  const VectorXd X = linear_first_guess(hb, 1.0);
  ASSERT_TRUE(X.allFinite());
  EXPECT_NEAR(X[0], F0 / kc - gap, 1e-15);   // kc (gap + x0) = F0
  // the closed orbit x0 + A cos: amplitude 0.2 / |kc - 2 + 0.1 i| stays in contact
  VectorXd Xs = X;
  ASSERT_TRUE(newton_solve(hb, Xs, 1.0, hb.scaling(1.0, 1.0)).converged);
  EXPECT_NEAR(Xs[0], F0 / kc - gap, 1e-12);
  EXPECT_NEAR(std::hypot(Xs[1], Xs[2]), 0.2 / std::hypot(kc - 2.0, 0.1), 1e-12);
  // the sweep starts and completes without a torsional spring
  SweepOptions o;
  o.omega_min = 0.5;
  o.omega_max = 3.0;
  EXPECT_TRUE(sweep_frequency(hb, o, "K=0").complete);
  // no contact to hold the load: neither guess exists
  const HarmonicBalance free(LinearSystem{M, C, K}, {}, f, 3);
  EXPECT_THROW(linear_first_guess(free, 1.0), std::invalid_argument);
  // no static load: the open solution exists (x0 = 0)
  Excitation f0{VectorXd::Zero(1), VectorXd::Constant(1, 0.2), VectorXd::Zero(1)};
  const HarmonicBalance unloaded(LinearSystem{M, C, K}, {}, f0, 3);
  EXPECT_TRUE(linear_first_guess(unloaded, 1.0).allFinite());
}

// A Mathieu tongue narrower than a continuation step. x'' + c x' + (1 + e cos(w t)) x = F0
// in full contact (c = 0.05, e = 0.1002, just above the threshold e ~ 2c): the principal
// parametric resonance near w = 2 is unstable over a band ~6e-3 wide, and a coarse sweep
// steps over it with both neighbours stable. The sweep must list both crossings (period
// doublings) at the band's edges; the edges are checked against an independent bisection
// on the monodromy of the linear Hill equation (monodromy_linear_periodic, no harmonic
// balance), to 1e-6 in w (the HB orbit is in full contact, so its linearisation is the
// Hill equation itself).
TEST(ParametricContact, NarrowMathieuTongueBetweenTwoStablePointsIsFound) {
  const double c = 0.05, e = 0.1002;
  const HarmonicBalance hb = parametric_oscillator(c, 1.0, [e](double t) { return 1.0 + e * std::cos(t); }, 1.0, 8);
  SweepOptions o;
  o.omega_min = 1.6;
  o.omega_max = 2.4;
  o.continuation.ds_max = 0.2;
  const FrequencyCurve fc = sweep_frequency(hb, o, "narrow tongue");
  ASSERT_TRUE(fc.complete) << fc.failure;
  for (bool st : fc.stable) ASSERT_TRUE(st) << "the sweep must step over the band (it has a point inside)";
  // independent band edges: |mu| of the Hill equation = 1, by bisection in w
  auto hill_modulus = [&](double w) {
    auto A = [&](double t, MatrixXd& out) {
      out.resize(2, 2);
      out << 0, 1, -(1 + e * std::cos(w * t)), -c;
    };
    return general_eigenvalues(monodromy_linear_periodic(A, 2, 2 * M_PI / w), "Hill").cwiseAbs().maxCoeff();
  };
  ASSERT_GT(hill_modulus(2.0 - 2.5e-4), 1.0) << "the band must exist";
  auto edge = [&](double inside, double outside) {
    for (int k = 0; k < 40; ++k) {
      const double m = 0.5 * (inside + outside);
      (hill_modulus(m) > 1.0 ? inside : outside) = m;
    }
    return 0.5 * (inside + outside);
  };
  const double lo = edge(2.0 - 2.5e-4, 1.98), hi = edge(2.0 - 2.5e-4, 2.02);
  EXPECT_LT(hi - lo, 1e-2);
  std::vector<double> pd;
  for (const auto& b : fc.bifurcations)
    if (b.type == BifurcationType::period_doubling) pd.push_back(b.omega);
  ASSERT_EQ(pd.size(), 2u);
  std::sort(pd.begin(), pd.end());
  EXPECT_NEAR(pd[0], lo, 1e-6);
  EXPECT_NEAR(pd[1], hi, 1e-6);
}
