// Backlash (lib/gearhb/gears/pair/backlash.hpp, thesis §9) against independent values:
// the normal-backlash formula, the geometry of §9 with both readings of T2C, the
// clip, and the contact reading against a two-spring case solved by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/gears/pair/backlash.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

using namespace gearhb;

namespace {
const double kDeg = M_PI / 180.0;
const double kB = 15e-6;   // thesis §9, nominal backlash [m]

// One synthetic STE point of the continuous reading.
StePoint point(double phase, int pairs, double ste) {
  StePoint p;
  p.phase = phase;
  p.pairs = pairs;
  p.ste = ste;
  return p;
}
}  // namespace

// b_n = b cos(mu): 15 um cos(20 deg) = 14.095389311788626 um (Python math, 17 digits).
TEST(Backlash, NormalBacklashFormula) {
  EXPECT_NEAR(normal_backlash(kB, 20 * kDeg), 14.095389311788626e-6, 1e-12 * kB);
  EXPECT_DOUBLE_EQ(normal_backlash(kB, 0.0), kB);
  EXPECT_NEAR(normal_backlash(kB, M_PI / 2), 0.0, 1e-20);
}

// Thesis §9 geometry, gear of ch. 7 (m = 3 mm, z = 50, alpha = 20 deg, ha = 3 mm).
// Exact: eps = atan((T2C + AC)/rb) - alpha = 5.371225157726041 deg, eps' = atan(CE'/rb)
// = 0.8831062370225886 deg, CE' = pb - AC = 1.0863550617984698 mm, b_n(E') =
// 13.452589548416844 um (Python math from the same closed forms, independent code).
// Printed values: eps from T2C = rb sin(alpha) and lengths rounded to 0.1 mm =
// 4.34590862240735 deg (thesis 4.35), eps' = atan(1.1 mm / rb) = 0.8941965205098669 deg
// (thesis 0.8942), b_n(E') = 13.567931991966413 um (thesis 13.5).
TEST(Backlash, GeometryBothReadings) {
  const GearGeometry g;
  const BacklashGeometry ex = backlash_geometry(g, kB, BacklashValues::exact);
  EXPECT_NEAR(ex.mu_C, 20 * kDeg, 1e-15);
  EXPECT_NEAR(ex.bn_C, 14.095389311788626e-6, 1e-12 * kB);
  EXPECT_NEAR(ex.CE_prime, 1.0863550617984698e-3, 1e-12);
  EXPECT_NEAR(ex.epsilon / kDeg, 5.371225157726041, 1e-10);
  EXPECT_NEAR(ex.epsilon_prime / kDeg, 0.8831062370225886, 1e-10);
  EXPECT_NEAR(ex.bn_E_prime, 13.452589548416844e-6, 1e-10 * kB);
  EXPECT_NEAR(ex.bn_A_prime, ex.bn_E_prime, 1e-12 * kB);   // identical gears: AC = CE
  const BacklashGeometry th = backlash_geometry(g, kB, BacklashValues::thesis_printed);
  EXPECT_NEAR(th.epsilon / kDeg, 4.34590862240735, 1e-10);
  EXPECT_NEAR(th.epsilon_prime / kDeg, 0.8941965205098669, 1e-10);
  EXPECT_NEAR(th.epsilon_prime / kDeg, 0.8942, 5e-5);   // the printed value, to its 4 decimals
  EXPECT_NEAR(th.bn_E_prime, 13.567931991966413e-6, 1e-10 * kB);
}

// The roll reading passes through both thesis values and grows monotonically from C;
// the involute reading is alpha everywhere.
TEST(Backlash, AngleAlongTheSinglePairZone) {
  const BacklashGeometry bg = backlash_geometry(GearGeometry{}, kB, BacklashValues::thesis_printed);
  EXPECT_NEAR(backlash_angle(bg, bg.AC, BacklashAngle::roll), bg.alpha, 1e-15);
  EXPECT_NEAR(backlash_angle(bg, bg.s_E_prime, BacklashAngle::roll), bg.mu_E_prime, 1e-14);
  EXPECT_NEAR(backlash_angle(bg, bg.s_A_prime, BacklashAngle::roll), bg.mu_A_prime, 1e-14);
  double last = bg.alpha;
  for (int i = 1; i <= 20; ++i) {
    const double mu = backlash_angle(bg, bg.AC + (bg.s_E_prime - bg.AC) * i / 20.0, BacklashAngle::roll);
    EXPECT_GT(mu, last);
    last = mu;
  }
  EXPECT_DOUBLE_EQ(backlash_angle(bg, bg.s_E_prime, BacklashAngle::involute), bg.alpha);
}

// Clip: at C (mu = alpha) a single-pair STE of 14.5 um becomes b cos(alpha); 13 um stays;
// a two-pair point stays whatever its value.
TEST(Backlash, ClipReading) {
  const SteModel m;
  const BacklashGeometry bg = backlash_geometry(m.gear, kB, BacklashValues::thesis_printed);
  const double phase_C = bg.AC / bg.pb;
  const std::vector<StePoint> cycle = {point(phase_C, 1, 14.5e-6), point(phase_C, 1, 13e-6), point(0.1, 2, 20e-6)};
  BacklashSettings s;
  s.model = BacklashModel::clip;
  const auto out = ste_with_backlash(m, 300.0, cycle, s);
  EXPECT_NEAR(out[0].ste, 14.095389311788626e-6, 1e-12 * kB);
  EXPECT_TRUE(out[0].limited);
  EXPECT_DOUBLE_EQ(out[1].ste, 13e-6);
  EXPECT_FALSE(out[1].limited);
  EXPECT_DOUBLE_EQ(out[2].ste, 20e-6);
  EXPECT_DOUBLE_EQ(out[0].ste_free, 14.5e-6);
}

// F = k1 d + k2 max(d - bn, 0), solved by hand: k1 = 2, k2 = 3, bn = 1.
//   F = 1: d = F/k1 = 0.5 < bn, not engaged;  F = 2: d = 1 = bn (just touching);
//   F = 7: d = (F + k2 bn)/(k1 + k2) = 10/5 = 2, forces k1 d = 4 and k2 (d - bn) = 3.
TEST(Backlash, TwoSpringsByHand) {
  TwoSpringSolution t = two_spring_deflection(1.0, 2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(t.d, 0.5);
  EXPECT_FALSE(t.engaged);
  EXPECT_DOUBLE_EQ(t.force_2, 0.0);
  t = two_spring_deflection(2.0, 2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(t.d, 1.0);
  EXPECT_FALSE(t.engaged);
  t = two_spring_deflection(7.0, 2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(t.d, 2.0);
  EXPECT_TRUE(t.engaged);
  EXPECT_DOUBLE_EQ(t.force_1, 4.0);
  EXPECT_DOUBLE_EQ(t.force_2, 3.0);
  EXPECT_THROW(two_spring_deflection(1.0, 0.0, 3.0, 1.0), std::invalid_argument);
}

// Contact reading on the gear: a single-pair point at C carrying F = 4000 N (300 N m)
// with STE 16 um (k1 = F / 16 um = 250 MN/m) and the adjacent pair of stiffness k2 at the
// path end: the deflection solves F = k1 d + k2 (d - b cos alpha), and the pair forces
// add up to F. (k2 from single_pair_ste at A or E, identical by symmetry.)
TEST(Backlash, ContactReadingOnTheGear) {
  const SteModel m;
  const BacklashGeometry bg = backlash_geometry(m.gear, kB, BacklashValues::exact);
  const double F = m.force(300.0), k1 = F / 16e-6;
  const double k2 = F / single_pair_ste(m, tooth_beam(m), 0.0, F);
  EXPECT_NEAR(single_pair_ste(m, tooth_beam(m), bg.AE, F), F / k2, 1e-9 * F / k2);
  BacklashSettings s;
  s.model = BacklashModel::contact;
  s.values = BacklashValues::exact;
  const auto out = ste_with_backlash(m, 300.0, {point(bg.AC / bg.pb, 1, 16e-6)}, s);
  const double bn = 14.095389311788626e-6;
  EXPECT_NEAR(out[0].ste, (F + k2 * bn) / (k1 + k2), 1e-12 * bn);
  EXPECT_NEAR(k1 * out[0].ste + out[0].adjacent_force, F, 1e-9 * F);
  EXPECT_GT(out[0].ste, bn);   // the spring is softer than a wall: between b_n and 16 um
  EXPECT_LT(out[0].ste, 16e-6);
}

// single_pair_ste is the STE that ste_continuous reports in the single-pair zone.
TEST(Backlash, SinglePairSteMatchesTheContinuousSte) {
  const SteModel m;
  const auto cycle = ste_continuous(m, 300.0, 64);
  const double pb = path_of_contact(m.gear, m.gear).base_pitch;
  int single = 0;
  for (const auto& p : cycle) {
    if (p.pairs != 1) continue;
    ++single;
    EXPECT_NEAR(single_pair_ste(m, tooth_beam(m), p.phase * pb, m.force(300.0)), p.ste, 1e-15);
  }
  EXPECT_GT(single, 10);
}
