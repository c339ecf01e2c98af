// Unit tests of lib/ste: the STE over the mesh cycle of thesis ch. 7.
// Constant 6 mm thickness (§7.4), EI = 207e9 x 0.02 x 0.006^3 / 12 = 74.52 N m^2,
// element length 0.675 mm, F = 300 / 0.075 = 4000 N:
//   one pair 6-18:  F [(5 L)^3 + (6 L)^3] / (3 EI) = 1.876427 um
//   two pairs:      each fused pair a clamped-guided beam of 11 L carrying F/2:
//                   X = 2000 (11 L)^3 / (12 EI) = 0.915515 um.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/gears/tooth/hertz.hpp"
#include "gearhb/gears/pair/ste.hpp"

using namespace gearhb;

namespace {
SteModel thesis_first_model(bool constant) {
  SteModel m;
  m.positions_per_base_pitch = 6;
  m.constant_thickness = constant;
  return m;
}
}  // namespace

TEST(Ste, ElementCountFollowsContactRatio) {
  SteModel m;
  m.positions_per_base_pitch = 6;
  EXPECT_EQ(m.elements(), 10);   // floor(6 x 1.7547): thesis Fig. 46
  m.positions_per_base_pitch = 8;
  EXPECT_EQ(m.elements(), 14);   // floor(8 x 1.7547): thesis Fig. 62
}

TEST(Ste, ThesisContactNodePairs) {
  // Positions of the 10-element model: 2-22/30-38, 3-21/31-37, 4-20/32-36,
  // 5-19/33-35, 6-18, 7-17 (beams of 11 nodes numbered 1-11, 12-22, 23-33, 34-44).
  SteModel m = thesis_first_model(true);
  m.hertz = HertzCount::none;
  const auto c = ste_over_mesh_cycle(m, 300);
  ASSERT_EQ(c.size(), 6u);
  const int A1[6] = {2, 3, 4, 5, 6, 7}, A2[6] = {22, 21, 20, 19, 18, 17};
  const int B1[4] = {30, 31, 32, 33}, B2[4] = {38, 37, 36, 35};
  for (int j = 0; j < 6; ++j) {
    EXPECT_EQ(c[j].kA1 + 1, A1[j]);
    EXPECT_EQ(11 + c[j].kA2 + 1, A2[j]);
    EXPECT_EQ(c[j].pairs, j < 4 ? 2 : 1);
    if (j < 4) {
      EXPECT_EQ(22 + c[j].kB1 + 1, B1[j]);
      EXPECT_EQ(33 + c[j].kB2 + 1, B2[j]);
    }
    EXPECT_NEAR(c[j].phase, j / 6.0, 1e-15);
  }
}

TEST(Ste, ConstantThicknessMatchesExactBeamFormulas) {
  SteModel m = thesis_first_model(true);
  m.hertz = HertzCount::none;
  const auto c = ste_over_mesh_cycle(m, 300);
  const double EI = 74.52, L = 0.675e-3;
  const double single = 4000 * (std::pow(5 * L, 3) + std::pow(6 * L, 3)) / (3 * EI);
  const double two = 2000 * std::pow(11 * L, 3) / (12 * EI);
  EXPECT_NEAR(single, 1.8764266304347825e-6, 1e-18);
  for (const auto& p : c) {
    if (p.pairs == 1) {
      EXPECT_NEAR(p.ste, single, 1e-11 * single);
    } else {
      EXPECT_NEAR(p.ste, two, 1e-11 * two);
      EXPECT_NEAR(p.force_A, 2000, 1e-7);   // equal stiffness: half the force each
      EXPECT_NEAR(p.force_B, 2000, 1e-7);
    }
    EXPECT_NEAR(p.elastic_linear, p.elastic_closed_form, 1e-11 * p.elastic_closed_form);
  }
}

TEST(Ste, VariableThicknessFeEqualsSteppedBeamClosedForm) {
  for (int P : {6, 8, 16}) {
    SteModel m;
    m.positions_per_base_pitch = P;
    for (const auto& p : ste_over_mesh_cycle(m, 200))
      EXPECT_NEAR(p.elastic_linear, p.elastic_closed_form, 1e-10 * p.elastic_closed_form) << "P " << P;
  }
}

TEST(Ste, HertzReadings) {
  SteModel m = thesis_first_model(false);
  const double F = 4000, b = 0.02;
  m.hertz = HertzCount::per_contact;
  auto once = ste_over_mesh_cycle(m, 300);
  m.hertz = HertzCount::per_tooth;
  auto twice = ste_over_mesh_cycle(m, 300);
  for (std::size_t j = 0; j < once.size(); ++j) {
    EXPECT_NEAR(twice[j].hertz, 2 * once[j].hertz, 1e-20);
    if (once[j].pairs == 1) EXPECT_NEAR(once[j].hertz, palmgren_line_contact_approach(F, b), 1e-20);
    else EXPECT_NEAR(once[j].hertz, palmgren_line_contact_approach(F / 2, b), 1e-20);
  }
}

TEST(Ste, ConsistentSplitClosesTheSameApproachOnBothPairs) {
  SteModel m = thesis_first_model(false);
  m.two_pair_hertz = TwoPairHertz::consistent;
  const auto c = ste_over_mesh_cycle(m, 300);
  const ToothBeam t = tooth_beam(m);
  for (const auto& p : c) {
    if (p.pairs != 2) continue;
    const TwoPairSolve s = solve_two_pairs(t, p.kA1, p.kA2, p.kB1, p.kB2, 4000);
    const double XA = p.force_A / s.stiffness_A + 2 * palmgren_line_contact_approach(p.force_A, 0.02);
    const double XB = p.force_B / s.stiffness_B + 2 * palmgren_line_contact_approach(p.force_B, 0.02);
    EXPECT_NEAR(XA, XB, 1e-9 * XA);
    EXPECT_NEAR(p.ste, XA, 1e-9 * XA);
    EXPECT_NEAR(p.force_A + p.force_B, 4000, 1e-6);
  }
}

TEST(Ste, MeanStiffnessHandComputed) {
  // Four positions with STE 1, 2, 2, 4 um at F = 1000 N: F/STE = 1e9, 5e8, 5e8, 2.5e8 N/m,
  // mean 5.625e8 N/m (by hand).
  std::vector<MeshPosition> c(4);
  const double ste[4] = {1e-6, 2e-6, 2e-6, 4e-6};
  for (int j = 0; j < 4; ++j) c[j].ste = ste[j];
  EXPECT_NEAR(mean_mesh_stiffness(c, 1000), 5.625e8, 1e-6);
}

TEST(Ste, MeanStiffnessOfThePiecewiseConstantSteClosedForm) {
  // Constant 6 mm tooth, no Hertz, 10 elements of Le = 0.675 mm, EI = 74.52 N m^2: the STE
  // is piecewise constant over the cycle, 4 two-pair positions with k = 2 x 12 EI / (11 Le)^3
  // (two clamped-guided beams) and 2 one-pair positions (6-18, 7-17) with
  // k = 3 EI / ((5 Le)^3 + (6 Le)^3) (two cantilevers in series), so
  //   mean k = [4 x 24 EI / (1331 Le^3) + 2 x 3 EI / (341 Le^3)] / 6
  //          = (EI / Le^3) (96/1331 + 6/341) / 6 = 2.4230453e11 N/m x 0.01495359 = 3623.322 MN/m
  SteModel m = thesis_first_model(true);
  m.hertz = HertzCount::none;
  const double EI = 74.52, Le = 0.675e-3;
  const double expected = EI / (Le * Le * Le) * (96.0 / 1331.0 + 6.0 / 341.0) / 6.0;
  EXPECT_NEAR(expected / 1e6, 3623.322, 1e-3);   // the same formula evaluated by hand
  EXPECT_NEAR(mean_mesh_stiffness(ste_over_mesh_cycle(m, 300), 4000), expected, 1e-9 * expected);
}

TEST(Ste, FourierMeanIsTheMeanSte) {
  SteModel m;
  const auto c = ste_over_mesh_cycle(m, 300);
  double mean = 0;
  for (const auto& p : c) mean += p.ste;
  int H = 0;
  const Eigen::VectorXd a = ste_fourier(c, &H);
  EXPECT_EQ(H, 3);   // 8 samples carry 3 harmonics
  EXPECT_NEAR(a[0], mean / c.size(), 1e-18);
}

TEST(Ste, ToothForceReadings) {
  SteModel m;
  EXPECT_NEAR(m.force(300), 4000, 1e-9);
  m.tooth_force = ToothForce::over_base_radius;
  EXPECT_NEAR(m.force(300), 300 / (0.075 * std::cos(20 * M_PI / 180)), 1e-9);
}
