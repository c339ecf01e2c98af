// The continuous-load STE, the STE file reader and the 1-DOF DTE model
// (lib/gearhb/gears/{ste_continuous,ste_file,dte_model}) against independent values.
#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/gears/pair/ste_file.hpp"
#include "gearhb/gears/tooth/tooth_fe.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

using namespace gearhb;

namespace {
ToothBeam uniform_beam(int ne, double h, double EI) {
  ToothBeam t;
  for (int i = 0; i <= ne; ++i) t.x.push_back(h * i / ne);
  t.EI.assign(ne, EI);
  t.s.assign(ne, 0.0);
  return t;
}
}  // namespace

// Cantilever, force between nodes: consistent loads give the exact tip
// deflection and rotation (Roark table 8.1 case 1a: w(L) = F a^2 (3L - a)/(6 EI),
// theta(L) = F a^2 / (2 EI)); at the load point the Hermite cubic is within
// O((L_e/a)^3) of the exact F a^3 / (3 EI).
TEST(SteContinuous, FlexibilityAgainstCantileverFormulas) {
  const double EI = 2.0, h = 1.0, a = 0.537;
  const ToothBeam t = uniform_beam(14, h, EI);
  const Eigen::Matrix2d G = tooth_flexibility(t, a);
  EXPECT_NEAR(G(0, 0), a * a * a / (3 * EI), 1e-3 * a * a * a / (3 * EI));
  EXPECT_NEAR(G(0, 1), G(1, 0), 1e-14);                 // reciprocity (Maxwell-Betti)
  EXPECT_NEAR(G(1, 0), a * a / (2 * EI), 2e-3 * a * a / (2 * EI));   // rotation at a under F
  // rotation under a moment between nodes: the Hermite slope is quadratic where the
  // exact one has a kink at a, so the error is O(L_e / a) (here 0.8 %)
  EXPECT_NEAR(G(1, 1), a / EI, 1e-2 * a / EI);
  EXPECT_NEAR(tooth_flexibility(t, t.x[7])(1, 1), t.x[7] / EI, 1e-12);   // exact at a node
  // At a node the result is exact.
  const double an = t.x[7];
  EXPECT_NEAR(tooth_flexibility(t, an)(0, 0), an * an * an / (3 * EI), 1e-12 * an * an * an / EI);
  EXPECT_THROW(tooth_flexibility(t, 1.5), std::invalid_argument);
  EXPECT_THROW(tooth_flexibility(t, 0.0), std::invalid_argument);
}

// Fused pair with loads on nodes: the 4x4 flexibility route gives the stiffness of
// ch. 7's FE fused model (solve_two_pairs) and of the closed-form clamped-guided beam.
TEST(SteContinuous, FusedPairMatchesChapter7AtNodes) {
  SteModel m;
  const ToothBeam t = tooth_beam(m);
  const int k1 = 3, k2 = m.elements() + 1 - k1;
  const TwoPairSolve s = solve_two_pairs(t, k1, k2, k1 + 8, m.elements() + 1 - k1 - 8, 1000.0);
  EXPECT_NEAR(fused_pair_stiffness(t, t.x[k1], t.x[k2]), s.stiffness_A, 1e-9 * s.stiffness_A);
  // Closed form (uniform beam of length 2a, guided-clamped): 12 EI / (2a)^3.
  const ToothBeam u = uniform_beam(10, 1.0, 3.0);
  EXPECT_NEAR(fused_pair_stiffness(u, 0.5, 0.5), 12 * 3.0 / 1.0, 1e-10 * 36.0);
}

// Single-pair positions and the periodic Fourier helper.
TEST(SteContinuous, CycleSanityAndFourier) {
  SteModel m;
  const auto c = ste_continuous(m, 300.0, 64);
  ASSERT_EQ(c.size(), 64u);
  int two = 0;
  for (const auto& p : c) two += p.pairs == 2;
  // Two pairs for phase <= eps - 1 (eps = 1.755): 49 of 64 phases.
  const double eps = path_of_contact(m.gear, m.gear).contact_ratio;
  EXPECT_EQ(two, int(std::floor((eps - 1) * 64)) + 1);
  std::vector<double> v(32);
  for (int j = 0; j < 32; ++j) v[j] = 1.0 + 0.5 * std::cos(2 * M_PI * 3 * j / 32.0) - 0.25 * std::sin(2 * M_PI * j / 32.0);
  const Eigen::VectorXd f = periodic_fourier(v, 20);
  EXPECT_NEAR(f[0], 1.0, 1e-14);
  EXPECT_NEAR(f[5], 0.5, 1e-14);
  EXPECT_NEAR(f[2], -0.25, 1e-14);
  EXPECT_NEAR(f[40], 0.0, 1e-14);   // beyond what 32 samples carry: zero
  EXPECT_NEAR(mean_stiffness({1.0, 2.0}, 4.0), 3.0, 1e-15);
}

TEST(SteFile, ReadsAndRejects) {
  const std::string p = ::testing::TempDir() + "ste_test.csv";
  auto write = [&](const std::string& text) { std::ofstream(p) << text; };
  write("# comment\nphase,ste_um\n0,10\n0.25,12\n0.5,10\n0.75,8\n");
  const SteFile f = read_ste_file(p, 3, true);
  ASSERT_EQ(f.ste.size(), 4u);
  EXPECT_DOUBLE_EQ(f.ste[1], 12e-6);
  EXPECT_THROW(read_ste_file(p, 5, true), SteFileError);            // too few rows
  write("phase,ste_um\n0,10\n0.3,12\n0.5,10\n0.75,8\n");
  EXPECT_THROW(read_ste_file(p, 3, true), SteFileError);            // non-uniform
  write("phase,ste_um\n0,10\n0.25,x\n0.5,10\n0.75,8\n");
  try {
    read_ste_file(p, 3, true);
    FAIL();
  } catch (const SteFileError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  write("phase,ste_um\n0,10\n0.25,-1\n0.5,10\n0.75,8\n");
  EXPECT_THROW(read_ste_file(p, 3, true), SteFileError);            // STE <= 0 with kc from F/STE
  EXPECT_NO_THROW(read_ste_file(p, 3, false));
  std::remove(p.c_str());
}

// The periodic gap in the contact law: in full contact the HB solution is the
// closed-form linear response; the mean contact force is F0.
TEST(DteModel, FullContactClosedFormAndMeanForce) {
  DteGear g;
  g.me = 1.4;
  g.kc = 4.7e8;
  g.c = mesh_damping(0.08, g.kc, g.me);
  g.F0 = 4000;
  g.ste = Eigen::VectorXd::Zero(7);
  g.ste << 10e-6, 0.3e-6, -0.2e-6, 0.1e-6, 0.05e-6, 0.02e-6, 0.0;
  EXPECT_NEAR(equivalent_mass(0.0158, 0.0158, 0.075, 0.075), 0.0158 / (2 * 0.075 * 0.075), 1e-15);
  EXPECT_NEAR(g.c, 2 * 0.08 * std::sqrt(4.7e8 * 1.4), 1e-9);
  const HarmonicBalance hb = dte_harmonic_balance(g, 3);
  const double w = 2 * M_PI * 800;
  Eigen::VectorXd X = linear_first_guess(hb, w);
  newton_solve(hb, X, w, hb.scaling(w, w));
  const Eigen::VectorXd Xc = dte_closed_contact(g, 3, w);
  EXPECT_LT((X - Xc).lpNorm<Eigen::Infinity>(), 1e-9 * Xc.tail(6).lpNorm<Eigen::Infinity>());
  // Independent: at w -> 0 the closed solution is x = F0/kc - e (rigid follow of the STE).
  const Eigen::VectorXd X0 = dte_closed_contact(g, 3, 1e-3);
  EXPECT_NEAR(X0[1], -g.ste[1], 1e-7 * std::fabs(g.ste[1]));   // c w / kc ~ 1e-8 at w = 1e-3
  EXPECT_NEAR(dte_mean_contact_force(hb, X) / g.F0, 1.0, 1e-9);
  EXPECT_NEAR(rms_ac(X0), std::sqrt(0.5 * g.ste.tail(6).squaredNorm()), 1e-9 * rms_ac(X0));
}
