// Unit tests of lib/gear_geometry and lib/iso6336 against hand-computed values.
//
// Thesis gear (§7.4): m = 3 mm, z = 50, alpha = 20 deg, ha = 3 mm, hf = 3.75 mm.
//   r0 = m z / 2 = 75 mm;  rb = 75 cos 20 = 70.476947 mm;  ra = 78 mm;  rf = 71.25 mm
//   pb = pi m cos 20 = 8.856394 mm
//   T1C = rb tan 20 = r0 sin 20 = 25.651511 mm
//   T1E = sqrt(78^2 - 70.476947^2) = 33.421550 mm,  CE = T1E - T1C = 7.770039 mm = AC
//   contact ratio = (AC + CE) / pb = 15.540078 / 8.856394 = 1.754673
//   T1A = T1T2 - T2A = 2 (25.651511) - 33.421550 = 17.881472 mm,
//   driver radius at A = sqrt(rb^2 + T1A^2) = 72.710020 mm
//   s(r0) = pi m / 2 = 4.712389 mm (the involute terms cancel)
//   s(rb) = rb s0/r0 + 2 rb inv(20 deg) = 4.428184 + 2.100844 = 6.529028 mm
//   s(ra) = 2.326290 mm
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/rating/iso6336.hpp"

using namespace gearhb;

TEST(Geometry, BasicRadiiAndPitch) {
  const GearGeometry g;
  EXPECT_NEAR(g.pitch_radius(), 0.075, 1e-15);
  EXPECT_NEAR(g.base_radius(), 70.47694655894313e-3, 1e-14);
  EXPECT_NEAR(g.tip_radius(), 0.078, 1e-15);
  EXPECT_NEAR(g.root_radius(), 0.07125, 1e-15);
  EXPECT_NEAR(g.base_pitch(), 8.856394302280648e-3, 1e-14);
  EXPECT_NEAR(g.tooth_height(), 6.75e-3, 1e-15);
}

TEST(Geometry, InvoluteFunction) {
  EXPECT_NEAR(involute(20 * M_PI / 180), 0.014904383867336446, 1e-15);   // tan - angle
  EXPECT_EQ(involute(0.0), 0.0);
}

TEST(Geometry, PathOfContactThesisGear) {
  const GearGeometry g;
  const PathOfContact p = path_of_contact(g, g);
  EXPECT_NEAR(p.T1C, 25.651510749425153e-3, 1e-14);
  EXPECT_NEAR(p.T1E, 33.42154998990732e-3, 1e-14);
  EXPECT_NEAR(p.CE, 7.770039240482166e-3, 1e-14);
  EXPECT_NEAR(p.AC, p.CE, 1e-15);          // identical gears: symmetric path
  EXPECT_NEAR(p.contact_ratio, 1.754673284698101, 1e-12);
  EXPECT_NEAR(p.T1A, 17.881471508942987e-3, 1e-14);
}

TEST(Geometry, ContactRadiiAtTheEndsOfThePath) {
  const GearGeometry g;
  const PathOfContact p = path_of_contact(g, g);
  // At A the driven tooth touches with its tip; at E the driver with its tip.
  const ContactRadii a = contact_radii(g, g, 0.0), e = contact_radii(g, g, p.AE);
  EXPECT_NEAR(a.r2, g.tip_radius(), 1e-14);
  EXPECT_NEAR(e.r1, g.tip_radius(), 1e-14);
  EXPECT_NEAR(a.r1, 72.71002007699671e-3, 1e-13);
  // At the pitch point both meet the tooth on the pitch circle.
  const ContactRadii c = contact_radii(g, g, p.AC);
  EXPECT_NEAR(c.r1, g.pitch_radius(), 1e-14);
  EXPECT_NEAR(c.r2, g.pitch_radius(), 1e-14);
}

TEST(Geometry, ToothThickness) {
  const GearGeometry g;
  EXPECT_NEAR(tooth_thickness(g, g.pitch_radius()), M_PI * 3e-3 / 2, 1e-15);
  EXPECT_NEAR(tooth_thickness(g, g.base_radius()), 6.529028081764814e-3, 1e-14);
  EXPECT_NEAR(tooth_thickness(g, g.tip_radius()), 2.3262901569979304e-3, 1e-14);
  EXPECT_THROW(tooth_thickness(g, 0.9 * g.base_radius()), std::domain_error);
}

TEST(Geometry, ToothAxisAnglesAsThesisPrinted) {
  // Thesis §7.7 with its printed values rb = 0.0705, T2C = 0.0241, CE = AC = 0.0078,
  // T2E = 0.0163:  beta = 20 deg - atan(0.0163/0.0705) = 20 - 13.0184 = 6.9816 deg,
  // eps = atan(0.0319/0.0705) - 20 deg = 24.3459 - 20 = 4.3459 deg,
  // [cos(13.0184) - cos(24.3459)] / cos(24.3459) = (0.974298 - 0.911073)/0.911073 = 6.9396 %.
  const GearGeometry g;
  const ToothAxisAngles t = tooth_axis_angles(g, path_of_contact(g, g), T2CFormula::thesis_rb_sin, true);
  EXPECT_NEAR(t.T2C, 0.0241, 1e-15);
  EXPECT_NEAR(t.T2E, 0.0163, 1e-15);
  EXPECT_NEAR(t.beta * 180 / M_PI, 20.0 - std::atan(0.0163 / 0.0705) * 180 / M_PI, 1e-12);
  EXPECT_NEAR(t.beta * 180 / M_PI, 6.98164, 1e-5);
  EXPECT_NEAR(t.epsilon * 180 / M_PI, 4.34591, 1e-5);
  EXPECT_NEAR(t.force_variation, 0.0693958, 1e-6);
}

TEST(Geometry, ToothAxisAnglesCorrectedT2C) {
  // T2C = rb tan(alpha) = 25.6515 mm; T2E = 25.6515 - 7.7700 = 17.8815 mm;
  // beta = 20 - atan(17.8815/70.4769) = 20 - 14.2367 = 5.7633 deg;
  // eps = atan(33.4216/70.4769) - 20 = 25.3712 - 20 = 5.3712 deg.
  const GearGeometry g;
  const ToothAxisAngles t = tooth_axis_angles(g, path_of_contact(g, g), T2CFormula::rb_tan, false);
  EXPECT_NEAR(t.T2C, 25.651510749425153e-3, 1e-14);
  EXPECT_NEAR(t.beta * 180 / M_PI, 5.76328, 1e-5);
  EXPECT_NEAR(t.epsilon * 180 / M_PI, 5.37123, 1e-5);
}

TEST(Geometry, Iso6336MeshStiffnessHandComputed) {
  // q' = 0.04723 + 0.15551/50 + 0.25791/50 = 0.0554984 mm um/N, c'_th = 18.01854,
  // C_B = [1 + 0.5 (1.2 - 1.25)] [1 - 0] = 0.975, c' = 18.01854 * 0.8 * 1 * 0.975 = 14.05446,
  // c_gamma_alpha = 14.05446 (0.75 * 1.754673 + 0.25) = 22.00935 N/(mm um), x 20 mm = 440.187 N/um.
  const Iso6336Stiffness s = iso6336_mesh_stiffness(50, 50, 0, 0, 20, 1.25, 1.754673284698101, 0.02, 200);
  EXPECT_NEAR(s.q_prime, 0.0554984, 1e-12);
  EXPECT_NEAR(s.C_B, 0.975, 1e-15);
  EXPECT_NEAR(s.c_single, 14.054459227653409, 1e-10);
  EXPECT_NEAR(s.c_gamma_alpha_total / 1e6, 440.18705820289915, 1e-8);
  // Below 100 N/mm the single stiffness drops by (load/100)^0.25.
  const Iso6336Stiffness low = iso6336_mesh_stiffness(50, 50, 0, 0, 20, 1.25, 1.754673284698101, 0.02, 50);
  EXPECT_NEAR(low.c_single / s.c_single, std::pow(0.5, 0.25), 1e-14);
}

TEST(Geometry, InvoluteToothModelProblemsAndAdmissibleTeeth) {
  GearGeometry g;
  EXPECT_EQ(involute_tooth_model_problem(g), "");
  // Root above the base circle: m z (1 - cos 20 deg) / 2 > hf = 3.75 mm needs
  // z > 2.5 / (1 - cos 20 deg) = 41.45, so z >= 42 (hand computed).
  g.teeth = 41;
  EXPECT_NE(involute_tooth_model_problem(g).find("base circle"), std::string::npos);
  double from = 0, to = 0;
  ASSERT_TRUE(admissible_interval(g, [](GearGeometry& t, double v) { t.teeth = int(v); }, 3, 10000, true, &from, &to));
  EXPECT_EQ(from, 42);
  // The contact ratio grows with z towards 2 (rack limit 1.9 for ha = m at 20 deg) and
  // stays below 2: the whole rest of the range admits.
  EXPECT_EQ(to, 10000);
  // Dedendum: hf < m z (1 - cos 20) / 2 = 3 x 50 x 0.0603074 / 2 = 4.523 mm.
  g = GearGeometry();
  ASSERT_TRUE(admissible_interval(g, [](GearGeometry& t, double v) { t.dedendum = v; }, 1e-6, 1, false, &from, &to));
  EXPECT_NEAR(to, 0.075 * (1 - std::cos(20 * M_PI / 180)), 1e-12);
  // A huge module makes the 3 mm addendum negligible: contact ratio < 1.
  g.module = 1;
  EXPECT_NE(involute_tooth_model_problem(g).find("contact ratio"), std::string::npos);
}

// ---------------------------------------------------------------------------
// Shifted gears, a pair from a drawing (issue 20).
//
// FZG type C test gear (Höhn, Oster, Michaelis; DIN ISO 14635-1):
// m = 4.5 mm, z = 16 / 24, x = 0.1817 / 0.1715, alpha = 20 deg, ha* = 1, hf* = 1.25,
// rho_f* = 0.38; published a = 91.5 mm, eps_alpha = 1.4625, rb = 33.829 / 50.743 mm,
// ra = 41.318 / 59.272 mm, path of contact 19.43 mm, pb = 13.285 mm.
// Closed forms evaluated by hand in Python (bisection for inv^-1, no gearhb):
//   from the shifts: alpha_w = 22.43891042912648 deg, a = 91.50007859607551 mm,
//                    g_alpha = 19.427796892816394 mm, eps = 1.4624308892700995;
//   at the drawing's a = 91.5 mm: alpha_w = 22.438791252720602 deg,
//                    g_alpha = 19.428002804925376 mm, eps = 1.4624463893409676
//   (the published 1.4625 is this to 4 digits; the shifts 0.1817 / 0.1715 are
//   rounded, so the a they imply is 0.08 um off 91.5 mm).
namespace {
GearGeometry fzg(int z, double x) {
  GearGeometry g;
  g.module = 4.5e-3;
  g.teeth = z;
  g.addendum = 4.5e-3;
  g.dedendum = 1.25 * 4.5e-3;
  g.face_width = 14e-3;
  g.profile_shift = x;
  return g;
}
}  // namespace

TEST(Geometry, InverseInvolute) {
  // Forward residual to the round-off of evaluating tan(a) - a (absolute eps a:
  // the round trip a -> inv -> a is ill-conditioned at small a, where it cancels).
  for (double v : {3e-7, 1e-4, 0.014904383867336446, 0.1, 2.0}) {
    const double a = inverse_involute(v);
    EXPECT_NEAR(involute(a), v, 4e-16 * (a + std::tan(a)));
  }
  EXPECT_NEAR(inverse_involute(involute(20 * M_PI / 180)), 20 * M_PI / 180, 1e-15);
  EXPECT_EQ(inverse_involute(0.0), 0.0);
}

TEST(Geometry, FzgTypeCFromTheShifts) {
  const GearGeometry g1 = fzg(16, 0.1817), g2 = fzg(24, 0.1715);
  EXPECT_NEAR(g1.base_radius(), 33.8289343482927e-3, 1e-15);   // 33.829 mm published
  EXPECT_NEAR(g2.base_radius(), 50.74340152243905e-3, 1e-15);  // 50.743
  EXPECT_NEAR(g1.tip_radius(), 41.31765e-3, 1e-15);            // 41.318
  EXPECT_NEAR(g2.tip_radius(), 59.27175e-3, 1e-15);            // 59.272
  EXPECT_NEAR(g1.base_pitch(), 13.284591453420971e-3, 1e-15);  // 13.285
  const PathOfContact p = path_of_contact(g1, g2);
  EXPECT_NEAR(p.mesh.pressure_angle * 180 / M_PI, 22.43891042912648, 1e-11);
  EXPECT_NEAR(p.mesh.centre_distance, 91.50007859607551e-3, 1e-14);
  EXPECT_NEAR(p.AE, 19.427796892816394e-3, 1e-14);
  EXPECT_NEAR(p.contact_ratio, 1.4624308892700995, 1e-11);
  EXPECT_NEAR(p.T1T2, p.mesh.centre_distance * std::sin(p.mesh.pressure_angle), 1e-15);
  // Operating pitch radii divide a in the ratio of the teeth: rw1 + rw2 = a, rw2/rw1 = z2/z1.
  EXPECT_NEAR(p.mesh.pitch_radius1 + p.mesh.pitch_radius2, p.mesh.centre_distance, 1e-15);
  EXPECT_NEAR(p.mesh.pitch_radius2 / p.mesh.pitch_radius1, 1.5, 1e-14);
  // Single-pair zone B-D: AB = DE = AE - pb, BD = 2 pb - AE.
  EXPECT_NEAR(p.T1B - p.T1A, p.AE - p.base_pitch, 1e-15);
  EXPECT_NEAR(p.T1D - p.T1B, 2 * p.base_pitch - p.AE, 1e-15);
}

TEST(Geometry, FzgTypeCAtTheDrawingsCentreDistance) {
  const PathOfContact p = path_of_contact(fzg(16, 0.1817), fzg(24, 0.1715), 91.5e-3);
  EXPECT_NEAR(p.mesh.centre_distance, 91.5e-3, 1e-16);
  EXPECT_NEAR(p.mesh.pressure_angle * 180 / M_PI, 22.438791252720602, 1e-11);
  EXPECT_NEAR(p.AE, 19.428002804925376e-3, 1e-14);             // 19.43 mm published
  EXPECT_NEAR(p.contact_ratio, 1.4624463893409676, 1e-11);
  // Published 1.4625: the same formula with the published radii rounded to 1 um
  // (rb 33.829 / 50.743, ra 41.318 / 59.272 mm) gives g_alpha = 19.42885 mm and
  // eps = 1.46251 (pb exact) or 1.46247 (pb = 13.285 mm): the last digit is rounding.
  EXPECT_NEAR(p.contact_ratio, 1.4625, 6e-5);
}

// Tooth thickness with shift: at the pitch circle s0 = m (pi/2 + 2 x tan alpha)
// (ISO 21771), 7.663783994672554 mm for the FZG pinion; at any r the same
// involute relation, so s(r)/r - s(r')/r' = 2 (inv a(r') - inv a(r)).
TEST(Geometry, ToothThicknessWithShift) {
  const GearGeometry g = fzg(16, 0.1817);
  EXPECT_NEAR(tooth_thickness(g, g.pitch_radius()), 7.663783994672554e-3, 1e-15);
  const double r1 = 36.5e-3, r2 = 40e-3;
  EXPECT_NEAR(tooth_thickness(g, r1) / r1 - tooth_thickness(g, r2) / r2,
              2 * (involute(pressure_angle_at(g, r2)) - involute(pressure_angle_at(g, r1))), 1e-14);
  // Tip thickness s_a / m = 0.5814177294402534 (hand formula), above the 0.2 m limit.
  EXPECT_NEAR(tooth_thickness(g, g.tip_radius()) / g.module, 0.5814177294402534, 1e-12);
}

// Undercut limit (Niemann & Winter §21.2): z_min = 2 (hf* - rho* (1 - sin a) - x) / sin^2 a;
// for the standard rack (1.25, 0.38) h* = 1.0000 and z_min(x = 0) = 17.0967 (the
// textbook 2 / sin^2(20 deg) = 17.097 with ha* = 1).
TEST(Geometry, UndercutLimit) {
  EXPECT_NEAR(undercut_limit_teeth(1.25, 0.38, 0.0, 20.0), 17.096711320642623, 1e-12);
  const double s2 = std::pow(std::sin(20 * M_PI / 180), 2);
  EXPECT_NEAR(undercut_limit_teeth(1.25, 0.38, 0.3, 20.0), 17.096711320642623 - 0.6 / s2, 1e-12);
}

TEST(Geometry, TipReliefLaw) {
  TipRelief r;
  r.amount = 10e-6;
  r.start_roll = 20e-3;
  r.tip_roll = 30e-3;
  EXPECT_EQ(tip_relief_at(r, 19e-3), 0.0);
  EXPECT_NEAR(tip_relief_at(r, 25e-3), 5e-6, 1e-18);
  EXPECT_NEAR(tip_relief_at(r, 30e-3), 10e-6, 1e-18);
  r.shape = ReliefShape::parabolic;
  EXPECT_NEAR(tip_relief_at(r, 25e-3), 2.5e-6, 1e-18);
  const GearGeometry g;   // thesis gear: rb = 70.4769 mm, ra = 78 mm
  EXPECT_NEAR(relief_start_roll(g, ReliefStart::length, 5e-3), 33.42155e-3 - 5e-3, 1e-8);
  EXPECT_NEAR(relief_start_roll(g, ReliefStart::diameter, 2 * 76e-3),
              std::sqrt(76e-3 * 76e-3 - g.base_radius() * g.base_radius()), 1e-15);
  EXPECT_NEAR(relief_start_roll(g, ReliefStart::roll_angle_deg, 20.0), g.base_radius() * 20 * M_PI / 180, 1e-15);
}

// The checks name the key of the gear-pair file.
TEST(Geometry, GearPairChecks) {
  const GearGeometry g;   // thesis gear: passes
  const PathOfContact p = path_of_contact(g, g);
  EXPECT_EQ(gear_pair_problem(g, g, p, {}, {}).key, "");
  GearGeometry pointed = g;
  pointed.teeth = 20;
  pointed.profile_shift = 1.0;   // s(ra) = 0.164 m < 0.2 m (hand formula)
  EXPECT_EQ(gear_pair_problem(pointed, g, path_of_contact(pointed, g), {}, {}).key, "gears.0.x");
  GearGeometry short_teeth = g;
  short_teeth.addendum = 0.4 * g.module;   // eps < 1
  const PathOfContact ps = path_of_contact(short_teeth, short_teeth);
  EXPECT_LT(ps.contact_ratio, 1.0);
  EXPECT_EQ(gear_pair_problem(short_teeth, short_teeth, ps, {}, {}).key, "gears");
  // Small pinion, large wheel at the standard centre distance: the wheel's tip
  // reaches beyond T1 (z1 = 10, z2 = 100, x = 0: T1A < 0).
  GearGeometry pin = g, wheel = g;
  pin.teeth = 10;
  wheel.teeth = 100;
  EXPECT_EQ(gear_pair_problem(pin, wheel, path_of_contact(pin, wheel), {}, {}).key, "gears.1.z");
  // A relief longer than the path: starts below A on gear 1.
  TipRelief r;
  r.amount = 10e-6;
  r.tip_roll = p.T1E;
  r.start_roll = p.T1A - 1e-4;
  EXPECT_EQ(gear_pair_problem(g, g, p, r, {}).key, "gears.0.tip_relief");
  r.start_roll = p.T1A + 1e-4;
  EXPECT_EQ(gear_pair_problem(g, g, p, r, {}).key, "");
  // Centre distance pulled in: no tip clearance.
  EXPECT_EQ(gear_pair_problem(g, g, path_of_contact(g, g, 0.1485), {}, {}).key, "centre_distance");
}

// Normal backlash from tooth-thickness allowances. At the centre distance the shifts
// imply, j_n = -(A_s1 + A_s2) cos(alpha) (the base-circle thickness reductions). Moving
// the centre distance out by da opens it by 2 da sin(alpha_w) to first order (the
// gears part along the line of action on both flanks: d j_n / da = 2 sin(alpha_w),
// from d(inv alpha_w)/da = tan^2(alpha_w) d(alpha_w)/da and cos(alpha_w) = (rb1 + rb2)/a).
TEST(Geometry, NormalBacklashFromAllowances) {
  const GearGeometry g1 = fzg(16, 0.1817), g2 = fzg(24, 0.1715);
  const PathOfContact p0 = path_of_contact(g1, g2);
  const double c = std::cos(20 * M_PI / 180);
  EXPECT_NEAR(normal_backlash(g1, g2, p0, -50e-6, -70e-6), 120e-6 * c, 1e-15);
  EXPECT_NEAR(normal_backlash(g1, g2, p0, 0.0, 0.0), 0.0, 1e-15);
  const double da = 1e-6;
  const PathOfContact p1 = path_of_contact(g1, g2, p0.mesh.centre_distance + da);
  EXPECT_NEAR(normal_backlash(g1, g2, p1, 0.0, 0.0), 2 * da * std::sin(p0.mesh.pressure_angle), 1e-3 * 2 * da);
}
