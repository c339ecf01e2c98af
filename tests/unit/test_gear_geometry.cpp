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

#include "gearhb/gears/gear_geometry.hpp"
#include "gearhb/gears/iso6336.hpp"

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
