// Floquet multipliers on the exact piecewise-linear flow (lib/gearhb/hb/floquet.hpp),
// against independent truths:
//  - linear oscillator (contact never or always closed): multipliers exp(lambda T),
//    lambda the eigenvalues of [0 1; -k/m -c/m] (exact);
//  - Meissner equation x'' + (a + b sgn cos t) x = 0: exact trace of the monodromy
//    2 cos(p1 t1) cos(p2 t2) - (p1/p2 + p2/p1) sin(p1 t1) sin(p2 t2) (closed form);
//  - Mathieu equation x'' + (d + e cos t) x = 0: transition curves of the first
//    tongue d = 1/4 -+ e/2 - e^2/8 + O(e^3) (Nayfeh & Mook, Nonlinear Oscillations, §5.2.2)
//    and Liouville's det = exp(-int trace) = 1;
//  - GSL monodromy (variational equations, rk8pd) about the orbit after GSL
//    integration to a periodic steady state;
//  - the middle branch between two folds of chapter 3's mass against a wall is unstable.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(Floquet, LinearOscillatorMultipliersAreExpLambdaT) {
  for (double gap : {-10.0, 10.0}) {   // open (k = 1) and always closed (k = 1 + kc = 2)
    HarmonicBalance hb = test_models::mass_wall(gap, 5);
    const double k = gap < 0 ? 1.0 : 2.0, c = 0.01;
    for (double w : {0.5, 1.3}) {
      const VectorXd X = gap < 0 ? hb.open_contact_solution(w) : hb.closed_contact_solution(w);
      const FloquetResult r = floquet_of_hb_orbit(hb, X, w, 1.0);
      const std::complex<double> lambda(-c / 2, std::sqrt(k - c * c / 4));
      const std::complex<double> mu = std::exp(lambda * (2 * M_PI / w));
      ASSERT_EQ(r.multipliers.size(), 2);
      for (int i = 0; i < 2; ++i)
        EXPECT_NEAR(std::min(std::abs(r.multipliers[i] - mu), std::abs(r.multipliers[i] - std::conj(mu))), 0.0, 1e-11)
            << "gap " << gap << ", w " << w;
      EXPECT_TRUE(r.stable);
      EXPECT_TRUE(r.corrected);
      EXPECT_LT(r.orbit_error, 1e-12);   // the HB solution of a linear system is exact
    }
  }
}

namespace {
double meissner_trace(double a, double b, double T) {
  // x'' + (a + b) x = 0 on [0, T/4) and [3T/4, T), x'' + (a - b) x = 0 on [T/4, 3T/4) (sgn cos)
  const double p1 = std::sqrt(a + b), p2 = std::sqrt(a - b), t1 = T / 2, t2 = T / 2;
  return 2 * std::cos(p1 * t1) * std::cos(p2 * t2) - (p1 / p2 + p2 / p1) * std::sin(p1 * t1) * std::sin(p2 * t2);
}
}  // namespace

TEST(Floquet, MeissnerSquareWaveStiffnessMatchesTheClosedFormTrace) {
  const double T = 2 * M_PI;
  for (double a : {0.2, 0.3, 0.9, 1.1, 2.0}) {
    const double b = 0.1;
    auto A = [&](double t, MatrixXd& out) {
      out.resize(2, 2);
      const double q = a + (std::cos(t) >= 0 ? b : -b);
      out << 0, 1, -q, 0;
    };
    const MatrixXd Phi = monodromy_linear_periodic(A, 2, T, {T / 4, 3 * T / 4});
    EXPECT_NEAR(Phi.trace(), meissner_trace(a, b, T), 1e-10) << "a = " << a;
    EXPECT_NEAR(Phi.determinant(), 1.0, 1e-10);
    // stability from the trace: |tr| < 2 <=> stable (a test that can fail both ways)
    const bool stable = std::fabs(meissner_trace(a, b, T)) < 2.0;
    const double mu = general_eigenvalues(Phi, "Meissner").cwiseAbs().maxCoeff();
    EXPECT_EQ(mu < 1.0 + 1e-8, stable) << "a = " << a;
  }
}

// Breakpoints given twice (contacts that switch at the same instant: the in-phase meshes of
// a planetary set) leave a segment of zero length, which GSL's driver refuses (it crashed
// gearhb_planetary, issue 36): the same closed-form Meissner trace with every breakpoint twice.
TEST(Floquet, RepeatedBreakpointsAreOneBreakpoint) {
  const double T = 2 * M_PI, a = 0.3, b = 0.1;
  auto A = [&](double t, MatrixXd& out) {
    out.resize(2, 2);
    out << 0, 1, -(a + (std::cos(t) >= 0 ? b : -b)), 0;
  };
  const MatrixXd Phi = monodromy_linear_periodic(A, 2, T, {T / 4, T / 4, 3 * T / 4, 3 * T / 4});
  EXPECT_NEAR(Phi.trace(), meissner_trace(a, b, T), 1e-10);
}

TEST(Floquet, MathieuFirstTongueFromTheVariationalEquation) {
  const double e = 0.1;
  const double lower = 0.25 - e / 2 - e * e / 8, upper = 0.25 + e / 2 - e * e / 8;   // +O(e^3) ~ 3e-5
  for (double d : {lower - 0.01, 0.25, upper + 0.01, lower + 0.01, upper - 0.01}) {
    auto A = [&](double t, MatrixXd& out) {
      out.resize(2, 2);
      out << 0, 1, -(d + e * std::cos(t)), 0;
    };
    const MatrixXd Phi = monodromy_linear_periodic(A, 2, 2 * M_PI);
    EXPECT_NEAR(Phi.determinant(), 1.0, 1e-10);
    const bool inside = d > lower && d < upper;
    EXPECT_EQ(std::fabs(Phi.trace()) > 2.0, inside) << "d = " << d << ", trace " << Phi.trace();
    if (inside) {
      EXPECT_LT(Phi.trace(), -2.0);   // the first tongue is a period doubling (multiplier -1)
    }
  }
}

namespace {
Branch ch3_branch(const HarmonicBalance& hb) {
  ContinuationOptions o;
  o.omega_start = 0.5;
  o.omega_end = 2.0;
  return arc_length_continuation(hb, hb.open_contact_solution(0.5), hb.scaling(0.5, 2.0), o);
}
}  // namespace

TEST(Floquet, AgreesWithGslMonodromyOfTheConvergedTimeIntegration) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 10);
  for (double w : {1.05, 1.2, 1.5}) {
    // a stable intermittent orbit: Newton from the open solution, then the exact-flow multipliers
    VectorXd X = hb.open_contact_solution(w);
    const Branch b = ch3_branch(hb);
    // the point of the upper (resonant) part nearest to w
    std::size_t best = 0;
    for (std::size_t i = 0; i < b.points.size(); ++i)
      if (std::fabs(b.points[i].omega - w) < std::fabs(b.points[best].omega - w)) best = i;
    X = b.points[best].X;
    const double wb = b.points[best].omega;
    const FloquetResult r = floquet_of_hb_orbit(hb, X, wb, 0.6);
    ASSERT_TRUE(r.corrected) << "w = " << wb;
    TimeIntegrator ti(hb);
    TimeIntegrationOptions o;
    o.x_scale = 0.6;
    VectorXd x0, v0;
    hb_initial_state(hb, X, wb, x0, v0);
    const SteadyState ss = ti.steady_state(x0, v0, wb, o);
    ASSERT_TRUE(ss.converged);
    // the same periodic state (up to the GSL tolerance) and the same multipliers
    EXPECT_LT((ss.x0 - r.x0).cwiseAbs().maxCoeff(), 1e-7) << "w = " << wb;
    const MatrixXd Pg = ti.monodromy(ss.x0, ss.v0, wb, o);
    Eigen::VectorXcd mg = general_eigenvalues(Pg, "GSL monodromy");
    for (int i = 0; i < 2; ++i) {
      double dmin = INFINITY;
      for (int j = 0; j < 2; ++j) dmin = std::min(dmin, std::abs(mg[j] - r.multipliers[i]));
      EXPECT_LT(dmin, 1e-6) << "w = " << wb << ", multiplier " << r.multipliers[i];
    }
  }
}

TEST(Floquet, MiddleBranchOfChapter3IsUnstableWithAMultiplierAboveOne) {
  HarmonicBalance hb = test_models::mass_wall(-0.6, 7);
  const Branch b = ch3_branch(hb);
  ASSERT_EQ(b.folds.size(), 2u);
  int middle = 0, outer = 0;
  for (const auto& p : b.points) {
    bool near = false;
    for (const auto& f : b.folds) near = near || std::fabs(f.omega - p.omega) < 2e-4;
    if (near) continue;
    const FloquetResult r = floquet_of_hb_orbit(hb, p.X, p.omega, 0.6);
    if (p.tangent_omega < 0.0) {
      EXPECT_FALSE(r.stable) << "omega = " << p.omega;
      EXPECT_GT(r.critical.real(), 1.0);            // real, above +1 (saddle)
      EXPECT_NEAR(r.critical.imag(), 0.0, 1e-12);
      ++middle;
    } else {
      EXPECT_TRUE(r.stable) << "omega = " << p.omega;
      ++outer;
    }
  }
  EXPECT_GT(middle, 5);
  EXPECT_GT(outer, 50);
}

// The monodromy matrix of chapter 6's gear pair with the printed kc = 5e2 N/m
// (Fi = 1e7 N m, Fa = 1e4, H = 10, point of the continuation at 12417.62 rad/s),
// hexadecimal so it is bit-exact. Gear 2's x and y supports share sqrt(k/m), so it
// has two nearly equal complex pairs, and Eigen's real Schur iteration (EigenSolver)
// does not converge on it (info = NoConvergence); its eigenvalues were garbage and made
// an isolated "unstable" point (|mu| = 35.7). general_eigenvalues falls back to the
// complex Schur iteration. Independent checks: sum = trace, product = determinant, each
// eigenvalue makes Phi - mu I singular (smallest singular value), and all lie inside
// the unit circle (the mesh force is < 10 N against 1e4 N of forcing: the damped
// linear system, largest |mu| = 0.9624 at the neighbouring points).
TEST(Floquet, EigenvaluesOfAMonodromyMatrixWithRepeatedPairs) {
  MatrixXd Phi(12, 12);
  Phi << 
      -0x1.08fa9e1ceaa46p-3, 0x1.1fcd68d949bb4p-18, 0x1.b92ef1c1f9683p-27, 0x1.8289957cfe895p-18, -0x1.61f0f9d0ad9c4p-19, -0x1.7dfbe7e8ff4b6p-25, 0x1.ecba7d4137697p-15, 0x1.a875a4006ecdap-34, -0x1.5260a23c137f3p-39, -0x1.97dd483c3f3e3p-32, 0x1.7578440fcc6aep-33, 0x1.8d128e37c48b1p-38,
      0x1.1fcd68d948d9cp-18, -0x1.08f6bc6a41828p-3, -0x1.93faa26697261p-28, -0x1.61f0f9d0ab646p-19, 0x1.44180e5c20a4p-20, 0x1.5dc599025bbeep-26, 0x1.a875a400707c5p-34, 0x1.ecbad8d9c125dp-15, 0x1.35d7b525c66e4p-40, 0x1.7578440fbac16p-33, -0x1.55f9c371730a2p-34, -0x1.6b96840eab882p-39,
      0x1.a7a25d1db862dp-26, -0x1.83e8e807831c2p-27, 0x1.e0d91fabff0c9p-2, 0x1.cc68e037799bfp-27, -0x1.a59581b8831dcp-28, 0x1.811b509c6f9d7p-29, -0x1.71133fcc67952p-39, 0x1.51f39e2653b26p-40, 0x1.40819ee40ec6ep-18, 0x1.83637ad19b616p-42, -0x1.62b87f30773b5p-43, 0x1.9bdd9830efbbcp-44,
      0x1.0010eeb5f6f74p-18, -0x1.d4f1e7274d30cp-20, 0x1.f690e703d5252p-27, 0x1.ebd591f6f8f3ap-1, -0x1.f2ecf28bce8ddp-21, -0x1.a31016466b767p-23, -0x1.237a6f8394adp-32, 0x1.0ae5f968ce1afp-33, 0x1.6e8fd4bbadb4dp-41, -0x1.2069c68ba5bap-18, -0x1.6c8e2edd5b925p-32, -0x1.158f34d587737p-40,
      -0x1.d4f1e72760effp-20, 0x1.ad664613c19e1p-21, -0x1.cc2f7530dc63cp-28, -0x1.f2ecf28bc602bp-21, 0x1.ebd55c21e6528p-1, 0x1.7fb9513cbfdefp-24, 0x1.0ae5f968d6493p-33, -0x1.e8c84b27aa804p-35, -0x1.4fa675429f034p-42, -0x1.6c8e2edd593dap-32, -0x1.20739bf39564dp-18, 0x1.fc4e7424b1d8dp-42,
      -0x1.51886ebc1e1dfp-27, 0x1.3511bd05216f2p-28, -0x1.13c0e710b1332p-31, -0x1.0b2c7a1ca3684p-26, 0x1.e94968850156bp-28, -0x1.c7bb78bca979p-6, -0x1.01b511036946cp-39, 0x1.d7f34ff89cd1ep-41, -0x1.34deb53bc1ff5p-45, 0x1.3064644e5b5bfp-38, -0x1.16b924e4fffabp-39, 0x1.11377597f6bb5p-16,
      -0x1.cae4178258d1ap+13, 0x1.6564e4136a69bp-9, -0x1.14d626507478ep-12, 0x1.0acbda54c20f7p-3, -0x1.e89874d22d132p-5, -0x1.b9207ff0ac77bp-9, -0x1.270e462641b5ap-3, 0x1.4b8aa49fd9c2dp-18, 0x1.2bb39a50ad2a4p-25, 0x1.e0cc68fc7ca73p-18, -0x1.b840e2abff703p-19, -0x1.03beb7cc0d15cp-24,
      0x1.6564e41243835p-9, -0x1.cae40dde5e248p+13, 0x1.fafb8d2618a65p-14, -0x1.e89874d215cacp-5, 0x1.bf649baa25117p-6, 0x1.93ed6869e18f6p-10, 0x1.4b8aa49fd7534p-18, -0x1.2709cd6f0aa8bp-3, -0x1.126d9da7a2a1p-26, -0x1.b840e2abf84bp-19, 0x1.9320a68db94e6p-20, 0x1.dbaea29c8160ep-26,
      -0x1.9239234e7fbc4p-14, 0x1.704de776b7c28p-15, -0x1.7eaf8593e46ep+13, 0x1.7ea9fb884ce41p-10, -0x1.5e64fea5bc2c4p-11, -0x1.9b6986845f5c5p-13, -0x1.b1a82b9c5bdd3p-27, 0x1.8d1657a326f0cp-28, 0x1.d44eec4865622p-2, 0x1.ce4f045cee909p-29, -0x1.a752a701f228dp-30, 0x1.ab96f8d64dba9p-28,
      0x1.7f576d842de63p-5, -0x1.5f03d0473f32p-6, 0x1.58ee4f682a5b8p-11, 0x1.4597a48b957e4p+9, 0x1.52f72173d8345p-5, -0x1.ccb5f93d2b935p-13, 0x1.628d49d0dfcc7p-18, -0x1.44a72fdef9c86p-19, 0x1.3498408796661p-26, 0x1.ec2a84e7aff7ep-1, 0x1.1736d149f145dp-21, -0x1.4786a3edeb78ep-25,
      -0x1.5f03d0473ea3dp-6, 0x1.416a11cfb3e99p-7, -0x1.3bd7e879ecc98p-12, 0x1.52f72173da094p-5, 0x1.45a0c93e0e6a4p+9, 0x1.a5dc1a58c147bp-14, -0x1.44a72fdf03753p-19, 0x1.29468b6aa8fffp-20, -0x1.1a9247577cbf9p-27, 0x1.1736d14a1cc2cp-21, 0x1.ec2aa30824891p-1, 0x1.2be7fa6fa0789p-26,
      0x1.a58483e61fff7p-10, -0x1.81f8c04a7b4c3p-11, 0x1.2ede816323772p-13, -0x1.cbd785b832e61p-11, 0x1.a5106920b7bcep-12, -0x1.a122c11b1b486p+14, -0x1.628b5567962fp-24, 0x1.44a565a8a171cp-25, 0x1.4ac33e3b75646p-31, 0x1.05dc00af9244fp-25, -0x1.df8de9c61326cp-27, -0x1.be90c46b24a44p-5;
  const Eigen::VectorXcd mu = general_eigenvalues(Phi, "test");
  ASSERT_EQ(mu.size(), 12);
  ASSERT_TRUE(mu.allFinite());
  EXPECT_NEAR(std::abs(mu.sum() - std::complex<double>(Phi.trace(), 0.0)), 0.0, 1e-12 * Phi.norm());
  EXPECT_NEAR(std::abs(mu.prod() / Phi.determinant() - 1.0), 0.0, 1e-8);
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    const Eigen::MatrixXcd D = Phi.cast<std::complex<double>>() - mu[i] * Eigen::MatrixXcd::Identity(12, 12);
    EXPECT_LT(smallest_singular_value(D), 1e-7 * Phi.norm()) << "mu = " << mu[i];
    EXPECT_LT(std::abs(mu[i]), 0.97);
  }
}

namespace {
// max relative difference of the period maps (x, v at T and the monodromy) of the
// diagonalised and the Pade propagators from one initial state
double spectral_vs_pade(const HarmonicBalance& hb, const VectorXd& X, double w, int* spectral_states = nullptr) {
  VectorXd x0, v0;
  hb_initial_state(hb, X, w, x0, v0);
  std::vector<double> nodes;
  for (int j = 0; j < 64; ++j) nodes.push_back(2.0 * M_PI / w * j / 64);
  PiecewiseLinearFlow fast(hb, true), pade(hb, false);
  VectorXd xa, va, xb, vb;
  MatrixXd Pa, Pb;
  fast.period_map(x0, v0, w, nodes, xa, va, Pa);
  pade.period_map(x0, v0, w, nodes, xb, vb, Pb);
  if (spectral_states) *spectral_states = fast.spectral_states();
  EXPECT_EQ(pade.spectral_states(), 0);
  const double dx = (xa - xb).cwiseAbs().maxCoeff() / xb.cwiseAbs().maxCoeff();
  const double dv = (va - vb).cwiseAbs().maxCoeff() / vb.cwiseAbs().maxCoeff();
  const double dP = (Pa - Pb).cwiseAbs().maxCoeff() / Pb.cwiseAbs().maxCoeff();
  return std::max({dx, dv, dP});
}
}  // namespace

// The diagonalised propagators (floquet.hpp) against Eigen's Pade exponentials on
// the same states: NLvib ex. 03 (open and closed generators, 2 contact switches per
// period) and the chapter 6 gear pair (15 x 15 generators, stiffness 1e8 N/m
// beside masses of 0.4 kg) with the mesh opening and closing.
TEST(Floquet, SpectralPropagatorsMatchPadeExponentials) {
  const HarmonicBalance ex03 = test_models::nlvib_ex03(21);
  for (double w : {0.55, 0.65, 0.75}) {
    int used = 0;
    EXPECT_LT(spectral_vs_pade(ex03, 4.0 * ex03.closed_contact_solution(w), w, &used), 1e-11) << "omega = " << w;
    EXPECT_EQ(used, 2);   // both contact states diagonalised
  }
  GearPairParameters g;
  g.kc = 5e8;
  const HarmonicBalance gear(gear_pair_system(g), {gear_pair_mesh(g)},
                             Excitation{gear_pair_static_torque(g, 1e3), VectorXd::Constant(6, 1e4), VectorXd::Zero(6)}, 10);
  for (double w : {5000.0, 7600.0, 14000.0}) {
    int used = 0;
    EXPECT_LT(spectral_vs_pade(gear, gear.open_contact_solution(w), w, &used), 1e-10) << "omega = " << w;
    EXPECT_GE(used, 1);
  }
}

// Balancing (core balance(), Parlett & Reinsch): [[1, 1e4], [1e-4, 1]] has eigenvalues
// 0 and 2 (det 0, trace 2); balanced, its off-diagonal entries are within a factor 4
// of each other, D is a power of 2 (so D B D^-1 gives A back exactly) and the
// eigenvalues are unchanged.
TEST(Floquet, BalancingEqualisesRowsAndColumnsExactly) {
  MatrixXd A(2, 2);
  A << 1, 1e4, 1e-4, 1;
  MatrixXd B = A;
  const VectorXd d = balance(B);
  EXPECT_LE(std::max(std::fabs(B(0, 1) / B(1, 0)), std::fabs(B(1, 0) / B(0, 1))), 4.0);
  EXPECT_EQ(MatrixXd(d.asDiagonal() * B * d.cwiseInverse().asDiagonal()), A);
  for (Eigen::Index i = 0; i < 2; ++i) EXPECT_EQ(std::exp2(std::round(std::log2(d[i]))), d[i]);
  const Eigen::VectorXcd mu = general_eigenvalues(B, "balanced");
  std::vector<double> re{mu[0].real(), mu[1].real()};
  std::sort(re.begin(), re.end());
  EXPECT_NEAR(re[0], 0.0, 1e-12);
  EXPECT_NEAR(re[1], 2.0, 1e-12);
}

namespace {
// A free mass (no spring to ground: K = 0) pushed by f0 = 0.5 N into a contact spring
// kc = 10 N/m behind a gap of 1 m, forced by cos: its open generator has a Jordan block
// at 0 (x' = v and the constant forcing state), so no eigenvector basis exists.
HarmonicBalance free_mass_on_a_spring(int H) {
  LinearSystem s{MatrixXd::Constant(1, 1, 1.0), MatrixXd::Constant(1, 1, 0.1), MatrixXd::Zero(1, 1)};
  UnilateralContact c{VectorXd::Constant(1, 1.0), 10.0, -1.0, {}};
  return HarmonicBalance(s, {c}, Excitation{VectorXd::Constant(1, 0.5), VectorXd::Constant(1, 1.0), VectorXd::Zero(1)}, H);
}

// Monodromy of the exact flow from (x0, v0) against GSL rk8pd's variational equations
// from the same state (time_integration.hpp; rel_tol 1e-10): max |difference| / max |entry|.
double flow_vs_gsl(const HarmonicBalance& hb, const VectorXd& x0, const VectorXd& v0, double w, double x_scale,
                   PiecewiseLinearFlow& flow) {
  std::vector<double> nodes;
  for (int j = 0; j < 64; ++j) nodes.push_back(2.0 * M_PI / w * j / 64);
  VectorXd xT, vT;
  MatrixXd Phi;
  flow.period_map(x0, v0, w, nodes, xT, vT, Phi);
  TimeIntegrationOptions o;
  o.x_scale = x_scale;
  const MatrixXd Pg = TimeIntegrator(hb).monodromy(x0, v0, w, o);
  return (Phi - Pg).cwiseAbs().maxCoeff() / Pg.cwiseAbs().maxCoeff();
}
}  // namespace

// The exact flow's monodromy against an independent one, in both propagator modes:
// diagonalised (NLvib ex. 03, two switches per period) and the Pade fallback of a
// defective generator (the free mass; the closed state, a spring, diagonalises).
// Measured 2e-12 ... 7e-10 (GSL rk8pd at rel_tol 1e-10 sets it); bound 1e-8.
TEST(Floquet, PeriodMapMonodromyMatchesGslInBothPropagatorModes) {
  const HarmonicBalance ex03 = test_models::nlvib_ex03(5);
  for (double w : {0.6, 0.7}) {
    VectorXd x0, v0;
    hb_initial_state(ex03, 4.0 * ex03.closed_contact_solution(w), w, x0, v0);
    PiecewiseLinearFlow flow(ex03);
    EXPECT_LT(flow_vs_gsl(ex03, x0, v0, w, 1.0, flow), 1e-8) << "omega = " << w;
    EXPECT_EQ(flow.spectral_states(), 2);
    EXPECT_EQ(flow.pade_states(), 0);
  }
  const HarmonicBalance free_mass = free_mass_on_a_spring(5);
  for (double w : {1.5, 3.0}) {
    VectorXd x0 = VectorXd::Constant(1, 1.05), v0 = VectorXd::Constant(1, 0.4);   // starts in contact, leaves it
    PiecewiseLinearFlow flow(free_mass);
    EXPECT_LT(flow_vs_gsl(free_mass, x0, v0, w, 1.0, flow), 1e-8) << "omega = " << w;
    EXPECT_EQ(flow.pade_states(), 1) << "omega = " << w;       // open: defective
    EXPECT_EQ(flow.spectral_states(), 1) << "omega = " << w;   // closed
  }
}
