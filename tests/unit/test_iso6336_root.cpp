// Unit tests of lib/gearhb/gears/rating/iso6336_root (ISO 6336-3:2019 method B tooth-root geometry
// of an external spur gear, and the same section measured on the generated tooth form).
//
// The real check is the agreement of two computations of one geometry: ISO's closed forms
// (E, G, H, the theta iteration) and tooth_form's envelope of the rack rounding, measured by
// circles through neighbouring form points (form_critical_section). Their difference is the
// discretisation of the form, second order in the point spacing h: the tolerance is
// h^2 / rho_F (eight times the sagitta h^2 / (8 rho_F) of a circle of radius rho_F over h),
// checked at h = m/50 (tooth_form's default) and m/200, where it is 16 times smaller, so a
// first-order error fails.
//
// Gears (tests/tooth_form/example_gears.hpp: ha* = 1, hf* = 1.25, alpha = 20 deg), rack tip
// radius rho_fP* = 0.38: the thesis gear (z 50, m 3 mm, x 0, meshing with itself), FZG type C
// (z 16 / 24, m 4.5 mm, x 0.1817 / 0.1715, meshing with each other), z 18 (m 3 mm, x 0,
// meshing with itself), z 10 (undercut, meshing with z 30).
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/gears/rating/iso6336_root.hpp"
#include "../tooth_form/example_gears.hpp"

using namespace gearhb;

namespace iso6336_root_test {

using namespace tooth_form_examples;

constexpr double alpha = 20.0 * M_PI / 180.0;
constexpr double rho_star = 0.38;

struct Pair {
  const char* name;
  GearGeometry g, mate;
};
std::vector<Pair> pairs() {
  return {{"thesis z50", thesis(), thesis()},
          {"FZG C z16", fzg16(), fzg24()},
          {"FZG C z24", fzg24(), fzg16()},
          {"z18", spur(18, 3e-3, 0.0), spur(18, 3e-3, 0.0)},
          {"z10 undercut", pinion10(), spur(30, 3e-3, 0.0)}};
}

// ISO 6336-3 method B Y_F and Y_S written out again (header section 4).
double Y_F_by_hand(double h_Fe, double s_Fn, double alpha_Fen, double m) {
  return 6.0 * h_Fe / m * std::cos(alpha_Fen) / std::pow(s_Fn / m, 2) / std::cos(alpha);
}
double Y_S_by_hand(double s_Fn, double h_Fe, double rho_F) {
  const double L = s_Fn / h_Fe, q_s = s_Fn / (2.0 * rho_F);
  return (1.2 + 0.13 * L) * std::pow(q_s, 1.0 / (1.21 + 2.3 / L));
}

// The outer point of single contact's roll length, from the path of contact: gear 1's
// contact runs from A to E (its tip); single contact ends D = A + p_b, T1D = T1E - (eps - 1) p_b.
double outer_single_contact_roll(const GearGeometry& g, const GearGeometry& mate) {
  const PathOfContact p = path_of_contact(g, mate);
  return p.T1E - (p.contact_ratio - 1.0) * p.base_pitch;
}

ToothForm form(const GearGeometry& g, double spacing, double rho = rho_star) {
  ToothFormOptions o;
  o.root_radius_coefficient = rho;
  o.spacing = spacing;
  return tooth_form(g, o);
}

void expect_two_methods_agree(const Pair& p, double spacing) {
  SCOPED_TRACE(std::string(p.name) + ", spacing m/" + std::to_string(p.g.module / spacing));
  const Iso6336ToothRoot iso = iso6336_tooth_root(p.g, rho_star, p.mate);
  const ToothForm f = form(p.g, spacing);
  const FormCriticalSection c = form_critical_section(f);
  const double roll = outer_single_contact_roll(p.g, p.mate);
  const FormLoadLine l = form_load_line(f, roll);
  const double h_Fe = l.height - c.height;
  // Tolerances from the spacing: h^2 / rho_F on the fillet; on the involute the normal is
  // interpolated over h where the curvature radius is the roll length, an angle error of
  // order (h / roll)^2.
  const double tol = c.spacing * c.spacing / c.rho_F;
  EXPECT_NEAR(c.s_Fn, iso.section.s_Fn, tol);
  EXPECT_NEAR(c.rho_F, iso.section.rho_F, tol);
  EXPECT_NEAR(c.height, iso.section.height, tol);
  EXPECT_NEAR(h_Fe, iso.h_Fe, 2.0 * tol);   // y_L and y_F: two errors
  EXPECT_NEAR(l.alpha_Fen, iso.load.alpha_Fen, std::pow(c.spacing / roll, 2));
  // The load point diameter: ISO's d_en against the form's interpolated point.
  EXPECT_NEAR(2.0 * l.point.norm(), iso.load.d_en, tol);
  // Y_F and Y_S of the form's quantities, by hand, against ISO's: the relative errors
  // propagate as dY_F/Y_F <= dh/h + 2 ds/s + tan(alpha_Fen) d(alpha_Fen) (+ the same order
  // for Y_S, whose exponents are below 1 in q_s and about 1 in L).
  const double rel = 2.0 * tol / iso.h_Fe + 2.0 * tol / iso.section.s_Fn + tol / iso.section.rho_F;
  EXPECT_NEAR(Y_F_by_hand(h_Fe, c.s_Fn, l.alpha_Fen, p.g.module), iso.Y_F, rel * iso.Y_F);
  EXPECT_NEAR(Y_S_by_hand(c.s_Fn, h_Fe, c.rho_F), iso.Y_S, 2.0 * rel * iso.Y_S);
}

TEST(Iso6336Root, two_methods_agree_at_the_default_spacing) {
  for (const Pair& p : pairs()) expect_two_methods_agree(p, p.g.module / 50.0);
}

TEST(Iso6336Root, two_methods_agree_to_second_order_at_a_quarter_of_the_spacing) {
  // The tolerance is 16 times smaller than at m/50: an error of first order in h fails here.
  for (const Pair& p : pairs()) expect_two_methods_agree(p, p.g.module / 200.0);
}

TEST(Iso6336Root, auxiliary_values_of_the_rack) {
  // G = rho_fP* - h_fP* + x (header section 1).
  EXPECT_NEAR(iso6336_critical_section(thesis(), rho_star).G, 0.38 - 1.25, 1e-15);
  EXPECT_NEAR(iso6336_critical_section(fzg16(), rho_star).G, 0.38 - 1.25 + 0.1817, 1e-15);
  // E is the rack rounding centre's distance from the rack tooth's centre line, so
  // E = p/2 - u_c with u_c = r theta_f the centre's distance from the tooth centre line,
  // theta_f = tooth_form's fillet_root_angle (where the fillet meets the root circle).
  for (const Pair& p : pairs()) {
    const double r = p.g.pitch_radius();
    EXPECT_NEAR(iso6336_critical_section(p.g, rho_star).E,
                0.5 * M_PI * p.g.module - r * form(p.g, 0.0).fillet_root_angle, 1e-15) << p.name;
  }
  // theta solves its fixed-point equation theta = 2 G / z tan(theta) - H.
  const Iso6336CriticalSection s = iso6336_critical_section(spur(18, 3e-3, 0.0), rho_star);
  EXPECT_NEAR(s.theta, 2.0 * s.G / 18.0 * std::tan(s.theta) - s.H, 1e-14);
}

TEST(Iso6336Root, factors_by_hand_from_the_section) {
  // A second, hand-written evaluation of Y_F and Y_S (header section 4) from ISO's s_Fn,
  // rho_F, h_Fe, alpha_Fen, and of sigma_F0 = F_t / (b m) Y_F Y_S.
  for (const Pair& p : pairs()) {
    const Iso6336ToothRoot r = iso6336_tooth_root(p.g, rho_star, p.mate);
    const double s = r.section.s_Fn, h = r.h_Fe;
    EXPECT_NEAR(r.Y_F, Y_F_by_hand(h, s, r.load.alpha_Fen, p.g.module), 1e-13) << p.name;
    EXPECT_NEAR(r.Y_S, Y_S_by_hand(s, h, r.section.rho_F), 1e-13) << p.name;
    EXPECT_NEAR(r.q_s, s / (2.0 * r.section.rho_F), 1e-15) << p.name;
    EXPECT_TRUE(r.q_s_in_range) << p.name;
    // h_Fe as printed equals the distance between the load line's and the section's heights.
    EXPECT_NEAR(r.h_Fe, r.load.height - r.section.height, 1e-15) << p.name;
  }
  // sigma_F0 for F_t = 1000 N, b = 20 mm, m = 3 mm, Y_F = 1.2, Y_S = 2: 1000 / 6e-5 * 2.4 Pa.
  EXPECT_NEAR(iso6336_nominal_root_stress(1000.0, 0.02, 3e-3, 1.2, 2.0), 4.0e7, 1e-6);
}

TEST(Iso6336Root, load_point_at_the_outer_single_contact) {
  // d_en: the roll length of the tip minus (eps - 1) base pitches (header section 2); the
  // same point from gear_geometry's path of contact (T1D = T1E - (eps - 1) p_b).
  for (const Pair& p : pairs()) {
    const Iso6336ToothRoot r = iso6336_tooth_root(p.g, rho_star, p.mate);
    const double roll = outer_single_contact_roll(p.g, p.mate);
    EXPECT_NEAR(r.load.d_en, 2.0 * std::hypot(roll, p.g.base_radius()), 1e-15) << p.name;
    // alpha_Fen = tan(alpha_en) - theta_b: the load line is the base-circle tangent,
    // theta_b = (pi/2 + 2 x tan alpha) / z + inv(alpha) the half tooth angle at the base.
    const double theta_b = (0.5 * M_PI + 2.0 * p.g.profile_shift * std::tan(alpha)) / p.g.teeth + involute(alpha);
    EXPECT_NEAR(r.load.alpha_Fen, roll / p.g.base_radius() - theta_b, 1e-14) << p.name;
  }
}

TEST(Iso6336Root, larger_rack_tip_radius_gives_larger_fillet_radius_and_smaller_Y_S) {
  // A check that can fail (the direction of the effect, by both methods): rho_fP* 0.25 -> 0.38.
  for (const Pair& p : pairs()) {
    if (p.g.teeth == 10) continue;   // z 10 with rho_fP* 0.25 is a different undercut: not needed
    const Iso6336ToothRoot sharp = iso6336_tooth_root(p.g, 0.25, p.mate), round = iso6336_tooth_root(p.g, 0.38, p.mate);
    EXPECT_GT(round.section.rho_F, sharp.section.rho_F * 1.1) << p.name;
    EXPECT_LT(round.Y_S, sharp.Y_S) << p.name;
    const double h = p.g.module / 50.0;
    EXPECT_GT(form_critical_section(form(p.g, h, 0.38)).rho_F, form_critical_section(form(p.g, h, 0.25)).rho_F * 1.1)
        << p.name;
  }
  // More teeth: a thicker root and a lower Y_F (load at the tip, x = 0).
  double previous = 1e9;
  for (int z : {17, 20, 30, 50, 100}) {
    const GearGeometry g = spur(z, 1e-3, 0.0);
    const double Y_F = iso6336_tooth_root(g, rho_star, iso6336_load_point(g, 2.0 * g.tip_radius())).Y_F;
    EXPECT_LT(Y_F, previous) << z;
    previous = Y_F;
  }
}

TEST(Iso6336Root, tip_load_factors_near_the_classic_chart) {
  // LOOSE sanity check, not a reference: Y_Fa and Y_Sa (load at the tip) for x = 0 and the
  // rack alpha 20 deg, h_fP* 1.25, rho_fP* 0.38, as the classic chart of DIN 3990-3 /
  // ISO 6336-3 (method C) is widely reproduced in textbooks; values recalled to about
  // +-0.02, not read from a copy at hand. Tolerance 3 %.
  struct Chart {
    int z;
    double Y_Fa, Y_Sa;
  };
  for (const Chart& c : {Chart{17, 2.97, 1.52}, Chart{20, 2.80, 1.55}, Chart{25, 2.62, 1.59}, Chart{30, 2.52, 1.625},
                         Chart{40, 2.40, 1.67}, Chart{50, 2.32, 1.70}, Chart{60, 2.28, 1.73}, Chart{80, 2.22, 1.77},
                         Chart{100, 2.18, 1.79}}) {
    const GearGeometry g = spur(c.z, 1e-3, 0.0);
    const Iso6336ToothRoot r = iso6336_tooth_root(g, rho_star, iso6336_load_point(g, 2.0 * g.tip_radius()));
    EXPECT_NEAR(r.Y_F, c.Y_Fa, 0.03 * c.Y_Fa) << c.z;
    EXPECT_NEAR(r.Y_S, c.Y_Sa, 0.03 * c.Y_Sa) << c.z;
  }
}

TEST(Iso6336Root, refuses_what_it_does_not_cover) {
  EXPECT_THROW(iso6336_outer_single_contact(thesis(), 0.9), std::invalid_argument);
  EXPECT_THROW(iso6336_outer_single_contact(thesis(), 2.1), std::invalid_argument);
  EXPECT_THROW(iso6336_load_point(thesis(), 2.0 * thesis().base_radius()), std::invalid_argument);
  EXPECT_THROW(iso6336_critical_section(thesis(), -0.1), std::invalid_argument);
  // A tangent angle the fillet never reaches (its normal at the root circle is tilted by
  // the fillet's root angle theta_f from the centre line, so n_y < sin(89.9 deg)).
  EXPECT_THROW(form_critical_section(form(thesis(), 0.0), 89.9 * M_PI / 180.0), std::invalid_argument);
  EXPECT_THROW(form_load_line(form(thesis(), 0.0), 0.0), std::invalid_argument);
}

}  // namespace iso6336_root_test
