// Unit tests of lib/gearhb/gears/geometry/tooth_form (the generated tooth form of an external spur
// gear). Expected values come from closed forms written out here (ISO 21771, Niemann &
// Winter §21) or from an independent computation: the rack cut simulated by brute force
// (`RackCut`: the basic rack's tooth as a region, rolled on the pitch circle; a point of the
// form must lie outside every rack position and touch one), never from tooth_form itself.
//
// Gears: the thesis gear (z 50, m 3 mm, x 0), FZG type C (z 16 / 24, m 4.5 mm,
// x 0.1817 / 0.1715, rho_fP* = 0.38: DIN ISO 14635-1), a z = 10 pinion
// (undercut), all with ha* = 1, hf* = 1.25, alpha = 20 deg.
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"
#include "gearhb/gears/geometry/tooth_form.hpp"
#include "../tooth_form/example_gears.hpp"

using namespace gearhb;

namespace tooth_form_test {

using Vec = Eigen::Vector2d;
constexpr double alpha = 20.0 * M_PI / 180.0;
constexpr double hf_star = 1.25, rho_star = 0.38;   // example_gears.hpp's hf*; rho_f* of all cases

using namespace tooth_form_examples;

ToothFormOptions spaced(double spacing) {
  ToothFormOptions o;
  o.root_radius_coefficient = rho_star;
  o.spacing = spacing;
  return o;
}

// Polar angle from the tooth centre line +y, positive toward +x; |psi| for both flanks.
double psi(const Vec& p) { return std::atan2(p.x(), p.y()); }
double inv(double a) { return std::tan(a) - a; }

// ISO 21771: half the tooth angle at the base circle and on the involute at radius R.
double theta_b(const GearGeometry& g) {
  return (M_PI / 2 + 2 * g.profile_shift * std::tan(alpha)) / g.teeth + inv(alpha);
}
double involute_psi(const GearGeometry& g, double R) {
  return theta_b(g) - inv(std::acos(g.base_radius() / R));
}

// The basic rack (tip radius rho = rho_f* m) rolling on the pitch circle, written from its
// definition (not from tooth_form): at rolling angle tau the gear point Q has the rack
// coordinates u = (Q turned counterclockwise by tau).x + r tau, v = (...).y - r - x m
// (u = 0 in the middle of a rack space, v = 0 on the datum line, v > 0 away from the gear).
// The rack tooth centred at u = p/2 is the set of points within rho of its core
// K = {v >= v_c, |u - p/2| <= p/4 + v tan(alpha) - rho / cos(alpha)}, v_c = -(hf - rho):
// a trapezoid with the flanks and tip line moved inward by rho, so its rho-neighbourhood
// is the rack tooth with the tip corners rounded by rho.
struct RackCut {
  double r, xm, p, hf, rho;
  explicit RackCut(const GearGeometry& g, double rho_f = rho_star)
      : r(g.pitch_radius()), xm(g.profile_shift * g.module), p(M_PI * g.module), hf(g.dedendum),
        rho(rho_f * g.module) {}
  // Rack coordinates (u relative to the nearest rack tooth's centre, v).
  Vec rack_point(const Vec& Q, double tau) const {
    const double c = std::cos(tau), s = std::sin(tau);
    const double u = Q.x() * c - Q.y() * s + r * tau, v = Q.x() * s + Q.y() * c - r - xm;
    return {u - p * std::floor(u / p) - p / 2, v};
  }
  // Signed distance of a rack point from the core K (negative inside: minus the distance to
  // the nearer of its bottom and flank lines, K being convex).
  double core_distance(const Vec& q) const {
    const double t = std::tan(alpha), vc = -(hf - rho), w0 = p / 4 - rho / std::cos(alpha);
    const double au = std::fabs(q.x()), v = q.y();
    if (v >= vc && au <= w0 + v * t) return -std::min(v - vc, (w0 + v * t - au) * std::cos(alpha));
    const double uw = w0 + vc * t;   // half width of the core's bottom
    const double d_bottom = std::hypot(std::max(au - uw, 0.0), v - vc);
    const Vec dir = Vec(t, 1.0).normalized();   // along the core's flank, upward
    const Vec rel(au - uw, v - vc);
    const double s = std::max(rel.dot(dir), 0.0);
    return std::min(d_bottom, (rel - s * dir).norm());
  }
  // Clearance of Q from the rack at tau: > 0 outside the rack tooth, < 0 inside.
  double clearance(const Vec& Q, double tau) const { return core_distance(rack_point(Q, tau)) - rho; }
  // Its minimum over the generating motion: a grid of positions, then a golden section
  // around every local minimum of the grid (a point can touch the flank at one position and
  // be cut by the rounding at another).
  double min_clearance(const Vec& Q) const {
    const int n = 4000;
    const double lo = -1.3, hi = 1.3, h = (hi - lo) / n;
    std::vector<double> c(n + 1);
    for (int i = 0; i <= n; ++i) c[i] = clearance(Q, lo + i * h);
    double best = *std::min_element(c.begin(), c.end());
    const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 1; i < n; ++i) {
      if (!(c[i] <= c[i - 1] && c[i] <= c[i + 1])) continue;
      double a = lo + (i - 1) * h, b = lo + (i + 1) * h;
      for (int it = 0; it < 80; ++it) {
        const double t1 = b - gr * (b - a), t2 = a + gr * (b - a);
        if (clearance(Q, t1) < clearance(Q, t2)) b = t2;
        else a = t1;
      }
      best = std::min(best, clearance(Q, 0.5 * (a + b)));
    }
    return best;
  }
};

// Rack tip rounding centre (u_c, v_c) of the rack tooth right of the tooth, on its datum-line
// coordinates (tangent to the flank u = p/4 - v tan(alpha) and the tip line v = -hf).
double rounding_centre_u(const GearGeometry& g) {
  const double m = g.module, rho = rho_star * m, hf = g.dedendum;
  return M_PI * m / 4 + (hf - rho) * std::tan(alpha) + rho / std::cos(alpha);
}
// The centre in the gear frame at rolling angle tau (the rack point (u_c, v_c) moved as
// RackCut moves it, inverted: Q = turn_clockwise(tau) (u - r tau, r + x m + v)).
Vec rounding_centre(const GearGeometry& g, double tau) {
  const double r = g.pitch_radius(), u = rounding_centre_u(g) - r * tau;
  const double v = r + g.profile_shift * g.module - (g.dedendum - rho_star * g.module);
  return {u * std::cos(tau) + v * std::sin(tau), -u * std::sin(tau) + v * std::cos(tau)};
}

// ISO 21771 form circle of a rack-generated gear without undercut:
// r_Ff = sqrt(rb^2 + (r sin(alpha) - (hf - rho (1 - sin alpha) - x m) / sin(alpha))^2).
double iso_form_radius(const GearGeometry& g) {
  const double m = g.module, h = g.dedendum - rho_star * m * (1 - std::sin(alpha)) - g.profile_shift * m;
  const double xi = g.pitch_radius() * std::sin(alpha) - h / std::sin(alpha);
  return std::hypot(g.base_radius(), xi);
}

// The profile shift at which undercut begins (header of tooth_form.hpp, section 4):
// hf* - rho* (1 - sin(alpha)) - x = z sin^2(alpha) / 2.
double limit_shift(int z) {
  return hf_star - rho_star * (1 - std::sin(alpha)) - z * std::pow(std::sin(alpha), 2) / 2;
}

std::vector<size_t> indices(const ToothForm& f, ToothSegment s) {
  std::vector<size_t> out;
  for (size_t i = 0; i < f.points.size(); ++i)
    if (f.segment[i] == s) out.push_back(i);
  return out;
}

double angle_between(const Vec& a, const Vec& b) { return std::atan2(std::fabs(a.x() * b.y() - a.y() * b.x()), a.dot(b)); }

// Do segments ab and cd cross (proper intersection)?
bool segments_cross(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  auto orient = [](const Vec& p, const Vec& q, const Vec& r) {
    const double v = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
    return (v > 0) - (v < 0);
  };
  return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

// The tests stay inside this namespace: the unit tests compile in unity batches, and its
// helpers must not leak into the next file of a batch.


TEST(ToothForm, InvolutePointsSatisfyThePolarEquations) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), pinion10()}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 50));
    const double rb = g.base_radius();
    const std::vector<size_t> inv_points = indices(f, ToothSegment::involute);
    ASSERT_GT(inv_points.size(), 20u);
    for (size_t i : inv_points) {
      const Vec& P = f.points[i];
      const double R = P.norm();
      // r cos(alpha_y) = rb defines alpha_y; the polar angle is theta_b - inv(alpha_y)
      // (ISO 21771, Niemann & Winter §21.1), to rounding.
      EXPECT_NEAR(std::fabs(psi(P)), involute_psi(g, R), 1e-12) << "z " << g.teeth << " R " << R;
      EXPECT_GE(R, f.form_radius * (1 - 1e-14));
      EXPECT_LE(R, g.tip_radius() * (1 + 1e-14));
      // The involute's normal is the tangent to the base circle: |P x n| = rb, n.P = xi > 0.
      const Vec& n = f.normals[i];
      EXPECT_NEAR(std::fabs(P.x() * n.y() - P.y() * n.x()), rb, 1e-12 * rb);
      EXPECT_NEAR(n.dot(P), std::sqrt(R * R - rb * rb), 1e-12 * rb);
    }
  }
}

TEST(ToothForm, ThicknessAtThePitchAndTipCircles) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), pinion10()}) {
    const double spacing = g.module / 400;
    const ToothForm f = tooth_form(g, spaced(spacing));
    const double r = g.pitch_radius(), m = g.module, x = g.profile_shift;
    // Pitch circle: the right flank's two involute points around r, psi linear in R between
    // them (error 2 r |psi''| h^2 / 8 < 2e-9 m for h = m/400 on these gears).
    double s_pitch = NAN;
    for (size_t i : indices(f, ToothSegment::involute)) {
      if (i + 1 >= f.points.size() || f.points[i].x() < 0) continue;
      const double R0 = f.points[i].norm(), R1 = f.points[i + 1].norm();
      if ((R0 - r) * (R1 - r) <= 0) {
        const double w = (r - R0) / (R1 - R0);
        s_pitch = 2 * r * ((1 - w) * psi(f.points[i]) + w * psi(f.points[i + 1]));
      }
    }
    EXPECT_NEAR(s_pitch, m * (M_PI / 2 + 2 * x * std::tan(alpha)), 1e-8) << "z " << g.teeth;   // ISO 21771
    // Tip: the tip arc spans the chordless thickness s_a = d_a (s/d + inv(alpha) - inv(alpha_a))
    // (ISO 21771, s = m (pi/2 + 2 x tan(alpha)), d = m z).
    const double ra = g.tip_radius(), s = m * (M_PI / 2 + 2 * x * std::tan(alpha));
    const double s_a = 2 * ra * (s / (m * g.teeth) + inv(alpha) - inv(std::acos(g.base_radius() / ra)));
    double psi_edge = 0;
    for (size_t i : indices(f, ToothSegment::tip)) {
      EXPECT_NEAR(f.points[i].norm(), ra, 1e-14 * ra);
      psi_edge = std::max(psi_edge, std::fabs(psi(f.points[i])));
    }
    EXPECT_NEAR(2 * ra * psi_edge, s_a, 1e-13) << "z " << g.teeth;
  }
}

TEST(ToothForm, RootCircleAndTheFilletsRootAngle) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), pinion10()}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 50));
    const double m = g.module, rf = m * (g.teeth / 2.0 - hf_star + g.profile_shift);   // ISO 21771
    EXPECT_NEAR(f.root_radius, rf, 1e-14 * rf);
    double r_min = INFINITY;
    for (const Vec& p : f.points) r_min = std::min(r_min, p.norm());
    EXPECT_NEAR(r_min, rf, 1e-14 * rf);   // nothing below the root circle
    for (size_t i : indices(f, ToothSegment::root)) EXPECT_NEAR(f.points[i].norm(), rf, 1e-14 * rf);
    // The first and last point: the root midpoints between teeth, at -pi/z and +pi/z.
    EXPECT_NEAR(psi(f.points.front()), -M_PI / g.teeth, 1e-14);
    EXPECT_NEAR(psi(f.points.back()), M_PI / g.teeth, 1e-14);
    // The fillet reaches the root circle at theta_f = u_c / r, the angle the potential-energy
    // model's fillet foundation takes (potential_energy.hpp, its own formula).
    PeGear pe;
    pe.teeth = g.teeth;
    pe.module = m;
    pe.profile_shift = g.profile_shift;
    pe.root_radius_coefficient = rho_star;
    EXPECT_NEAR(f.fillet_root_angle, pe_tooth_geometry(pe).theta_f, 1e-14);
    EXPECT_NEAR(f.fillet_root_angle, rounding_centre_u(g) / g.pitch_radius(), 1e-14);
  }
}

TEST(ToothForm, FilletPointsLieOnTheRackTipCircleOfTheirGeneratingPosition) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), pinion10()}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 50));
    const double rho = rho_star * g.module, r = g.pitch_radius();
    const std::vector<size_t> fillet = indices(f, ToothSegment::fillet);
    ASSERT_GT(fillet.size(), 10u);
    for (size_t i : fillet) {
      const Vec F(std::fabs(f.points[i].x()), f.points[i].y());   // the right flank's point
      const double tau = f.parameter[i];
      const Vec C = rounding_centre(g, tau), I = r * Vec(std::sin(tau), std::cos(tau));
      EXPECT_NEAR((F - C).norm(), rho, 1e-14 * r) << "z " << g.teeth;
      // Envelope: the contact normal passes through the pitch point I (F, C, I collinear).
      const Vec a = F - C, b = C - I;
      EXPECT_NEAR(a.x() * b.y() - a.y() * b.x(), 0.0, 1e-12 * rho * b.norm());
      // The outward normal points from the fillet into the rack's rounding.
      Vec n = f.normals[i];
      if (f.points[i].x() < 0) n.x() = -n.x();   // the left flank's normal, mirrored
      EXPECT_NEAR(n.dot((C - F) / rho), 1.0, 1e-13);
    }
  }
}

TEST(ToothForm, FormIsExactlyWhatTheRackLeaves) {
  // Every root, fillet and involute point touches some rack position (minimum clearance 0)
  // and no rack position cuts it (the brute-force RackCut: grid of 4001 positions plus a
  // golden-section refinement; 1e-10 m is its resolution on these gears).
  for (const GearGeometry& g : {thesis(), fzg16(), pinion10(), spur(17, 3e-3, 0.0), spur(18, 3e-3, 0.0),
                                spur(10, 3e-3, limit_shift(10) - 1e-3), spur(10, 3e-3, limit_shift(10) + 1e-3)}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 20));
    const RackCut rack(g);
    double worst = 0;
    for (size_t i = 0; i < f.points.size(); ++i) {
      if (f.segment[i] == ToothSegment::tip) continue;
      const Vec Q(std::fabs(f.points[i].x()), f.points[i].y());
      worst = std::max(worst, std::fabs(rack.min_clearance(Q)));
    }
    EXPECT_LT(worst, 1e-10 * g.module / 3e-3) << "z " << g.teeth;
  }
  // Other rack tip radii: 0 (a sharp corner: the fillet is the corner's trochoid) and 0.25.
  for (double rho_f : {0.0, 0.25})
    for (const GearGeometry& g : {fzg16(), pinion10()}) {
      ToothFormOptions o = spaced(g.module / 20);
      o.root_radius_coefficient = rho_f;
      const ToothForm f = tooth_form(g, o);
      const RackCut rack(g, rho_f);
      double worst = 0;
      for (size_t i = 0; i < f.points.size(); ++i)
        if (f.segment[i] != ToothSegment::tip)
          worst = std::max(worst, std::fabs(rack.min_clearance(Vec(std::fabs(f.points[i].x()), f.points[i].y()))));
      EXPECT_LT(worst, 1e-10 * g.module / 3e-3) << "z " << g.teeth << " rho_f* " << rho_f;
    }
}

TEST(ToothForm, UndercutExactlyWhenTheRackFlankPassesTheInterferencePoint) {
  // Undercut iff the rack's straight flank, ending at the depth
  // h* = hf* - rho* (1 - sin alpha) below the datum, reaches below the base circle's tangent
  // point T on the line of action (depth r sin^2(alpha) below the generating line):
  //     hf* - rho* (1 - sin(alpha)) - x > z sin^2(alpha) / 2
  // (Niemann & Winter §21.2; the same limit as undercut_limit_teeth: z < z_min).
  struct Case {
    int z;
    double x;
    bool undercut;
  };
  const Case cases[] = {{10, 0.0, true},                      // z_min = 17.1
                        {30, 0.0, false},
                        {17, 0.0, true},                      // z = 17 < z_min = 17.097: just undercut
                        {18, 0.0, false},
                        {10, limit_shift(10) - 1e-3, true},   // borderline by x, each side
                        {10, limit_shift(10) + 1e-3, false}};
  for (const Case& c : cases) {
    const GearGeometry g = spur(c.z, 3e-3, c.x);
    EXPECT_EQ(c.z < undercut_limit_teeth(hf_star, rho_star, c.x, 20.0), c.undercut);
    const ToothForm f = tooth_form(g, spaced(g.module / 50));
    EXPECT_EQ(f.undercut, c.undercut) << "z " << c.z << " x " << c.x;
    const double rb = g.base_radius();
    if (!c.undercut) {
      EXPECT_NEAR(f.form_radius, iso_form_radius(g), 1e-14 * rb) << "z " << c.z;   // ISO 21771 d_Ff / 2
      continue;
    }
    // The involute starts above the base circle; near the limit only just above it.
    EXPECT_GT(f.form_radius, rb) << "z " << c.z;
    EXPECT_LT(f.form_radius, rb * (c.z == 10 && c.x == 0.0 ? 1.01 : 1.001)) << "z " << c.z << " x " << c.x;
  }
}

TEST(ToothForm, UndercutFormRadiusIsWhereTheRackStopsCuttingTheInvolute) {
  // Brute force (RackCut): the involute point of radius R is cut by some rack position below
  // r_Ff and only touched above it; bisection on R. Also a numpy prototype of the same
  // simulation (400001 positions) gave r_Ff / m = 4.7256022 for z = 10, x = 0.
  for (const GearGeometry& g : {pinion10(), spur(12, 3e-3, 0.0), spur(14, 4.5e-3, 0.1)}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 50));
    ASSERT_TRUE(f.undercut);
    const RackCut rack(g);
    auto cut = [&](double R) {
      const double p = involute_psi(g, R);
      return rack.min_clearance(Vec(R * std::sin(p), R * std::cos(p))) < -1e-12 * g.module;
    };
    double lo = g.base_radius() * (1 + 1e-6), hi = f.form_radius + 0.1 * g.module;
    ASSERT_TRUE(cut(lo));
    ASSERT_FALSE(cut(hi));
    for (int it = 0; it < 50; ++it) (cut(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(f.form_radius, 0.5 * (lo + hi), 1e-9) << "z " << g.teeth;
  }
  EXPECT_NEAR(tooth_form(pinion10(), spaced(3e-3 / 50)).form_radius / 3e-3, 4.7256022, 2e-7);   // numpy brute force
}

TEST(ToothForm, FilletTangentToInvoluteAndRootWithoutUndercutCornerWithIt) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), spur(18, 3e-3, 0.0), pinion10()}) {
    const double h = g.module / 1000, rho = rho_star * g.module;
    const ToothForm f = tooth_form(g, spaced(h));
    // Right flank: the involute's first point (on the form circle) and the fillet after it.
    size_t j = 0;
    for (size_t i = 0; i + 1 < f.points.size(); ++i)
      if (f.points[i].x() > 0 && f.segment[i] == ToothSegment::involute && f.segment[i + 1] == ToothSegment::fillet) j = i;
    ASSERT_GT(j, 0u);
    EXPECT_NEAR(f.points[j].norm(), f.form_radius, 1e-14 * f.form_radius);
    // One-sided chord directions on each side of the junction.
    const Vec t_inv = (f.points[j] - f.points[j - 1]).normalized(), t_fil = (f.points[j + 1] - f.points[j]).normalized();
    const double kink = angle_between(t_inv, t_fil);
    if (!f.undercut) {
      // C1: the chords turn by at most h times the curvatures (<= 1/rho on the fillet,
      // 1/xi on the involute).
      EXPECT_LT(kink, h / rho + h / f.form_roll) << "z " << g.teeth;
      // The fillet's normal at the junction from its generating position tau_j =
      // (u_c + eta / tan(alpha)) / r equals the involute's normal there.
      const double eta = g.dedendum - rho - g.profile_shift * g.module;
      const double tau_j = (rounding_centre_u(g) + eta / std::tan(alpha)) / g.pitch_radius();
      const Vec n_fillet = (rounding_centre(g, tau_j) - f.points[j]) / rho;
      EXPECT_NEAR((rounding_centre(g, tau_j) - f.points[j]).norm(), rho, 1e-12 * rho);
      EXPECT_LT(angle_between(n_fillet, f.normals[j]), 1e-10) << "z " << g.teeth;
    } else {
      EXPECT_GT(kink, 0.05) << "the undercut corner, z " << g.teeth;   // a corner, not C1
    }
    // Root: the fillet leaves the root circle tangentially (radial normal there).
    size_t k = 0;
    for (size_t i = 0; i + 1 < f.points.size(); ++i)
      if (f.points[i].x() > 0 && f.segment[i] == ToothSegment::fillet && f.segment[i + 1] == ToothSegment::root) k = i;
    ASSERT_GT(k, 0u);
    EXPECT_LT(angle_between(f.normals[k], f.points[k]), 1e-14);
    EXPECT_LT(angle_between((f.points[k] - f.points[k - 1]), (f.points[k + 1] - f.points[k])), 2 * h / rho);
  }
}

TEST(ToothForm, TipReliefIsTheNormalOffsetFromTheInvolute) {
  for (ReliefShape shape : {ReliefShape::linear, ReliefShape::parabolic}) {
    const GearGeometry g = fzg16();
    ToothFormOptions o = spaced(g.module / 100);
    o.relief = tip_relief(g, 0.1e-3, ReliefStart::diameter, 79e-3, shape);   // Ca 100 um from d 79 mm
    const ToothForm f = tooth_form(g, o);
    EXPECT_NEAR(f.relief_start_radius, 39.5e-3, 1e-14 * 39.5e-3);
    const double rb = g.base_radius();
    const std::vector<size_t> relief = indices(f, ToothSegment::relief);
    ASSERT_GT(relief.size(), 20u);
    double largest = 0;
    for (size_t i : relief) {
      const Vec& Q = f.points[i];
      const double R = Q.norm();
      // Normal distance from the involute = rb x (polar-angle deficit at the same radius);
      // its foot on the involute has the roll length sqrt(R^2 - rb^2) + distance.
      const double d = rb * (involute_psi(g, R) - std::fabs(psi(Q)));
      const double foot = std::sqrt(R * R - rb * rb) + d;
      EXPECT_NEAR(d, tip_relief_at(o.relief, foot), 1e-12) << "R " << R;
      EXPECT_GE(R, f.relief_start_radius * (1 - 1e-14));
      largest = std::max(largest, d);
    }
    EXPECT_NEAR(largest, 0.1e-3, 1e-12);   // Ca where the relieved flank meets the tip circle
  }
}

TEST(ToothForm, TipRoundingTangentToFlankAndTipCircle) {
  const GearGeometry g = fzg24();
  ToothFormOptions o = spaced(g.module / 100);
  const double r_k = 0.2 * g.module, rb = g.base_radius(), ra = g.tip_radius();
  o.tip_rounding_radius = r_k;
  const ToothForm f = tooth_form(g, o);
  // On the involute the circle's centre M = P - r_k n lies on P's base tangent at the roll
  // length xi - r_k, and |M| = ra - r_k: xi_k = r_k + sqrt((ra - r_k)^2 - rb^2).
  const double xi_k = r_k + std::sqrt(std::pow(ra - r_k, 2) - rb * rb);
  EXPECT_NEAR(f.rounding_start_radius, std::hypot(rb, xi_k), 1e-13);
  const std::vector<size_t> round = indices(f, ToothSegment::rounding);
  ASSERT_GT(round.size(), 5u);
  for (size_t i : round) {
    const Vec M = f.points[i] - r_k * f.normals[i];   // every point r_k from one centre
    EXPECT_NEAR(M.norm(), ra - r_k, 1e-13);
    EXPECT_NEAR(std::fabs(psi(M)), std::fabs(psi(f.points[round.front()] - r_k * f.normals[round.front()])), 1e-12);
  }
}

TEST(ToothForm, NormalsAreUnitAndOutward) {
  for (const GearGeometry& g : {thesis(), fzg16(), pinion10()}) {
    const double h = g.module / 400;
    ToothFormOptions o = spaced(h);
    o.relief = tip_relief(g, 20e-6, ReliefStart::roll_angle_deg, 25.0, ReliefShape::parabolic);
    const ToothForm f = tooth_form(g, o);
    for (size_t i = 1; i + 1 < f.points.size(); ++i) {
      EXPECT_NEAR(f.normals[i].norm(), 1.0, 1e-14);
      if (f.segment[i - 1] != f.segment[i] || f.segment[i + 1] != f.segment[i]) continue;   // corners
      // Clockwise traversal: the outward normal is the chord direction turned by +90 deg,
      // to O(h / radius of curvature) (radii >= rho here).
      const Vec t = (f.points[i + 1] - f.points[i - 1]).normalized();
      EXPECT_LT(angle_between(Vec(-t.y(), t.x()), f.normals[i]), h / (rho_star * g.module)) << i;
      EXPECT_GT(Vec(-t.y(), t.x()).dot(f.normals[i]), 0.0);
    }
  }
}

TEST(ToothForm, OutlineClosesWithoutSelfIntersectionAndItsArea) {
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24(), pinion10()}) {
    const double spacing = g.module / 10;
    ToothFormOptions o = spaced(spacing);
    o.tip_rounding_radius = 0.1 * g.module;
    const ToothForm f = tooth_form(g, o);
    const FormPolyline outline = gear_outline(f);
    ASSERT_TRUE(outline.closed);
    const size_t N = outline.points.size();
    EXPECT_EQ(N, size_t(g.teeth) * (f.points.size() - 1));
    // The last tooth's right root midpoint is the first tooth's left one: the closing edge is
    // one of the root arc's (at most `spacing` long), and the tooth's ends are pi/z either side.
    EXPECT_LE((outline.points.back() - outline.points.front()).norm(), spacing * (1 + 1e-12));
    EXPECT_NEAR(outline.points.front().norm(), f.root_radius, 1e-14 * f.root_radius);
    // No two non-adjacent edges cross (O(N^2); N = z x tooth points).
    int crossings = 0;
    for (size_t a = 0; a < N; ++a)
      for (size_t b = a + 2; b < N; ++b) {
        if (a == 0 && b == N - 1) continue;   // adjacent across the closing edge
        if (segments_cross(outline.points[a], outline.points[(a + 1) % N], outline.points[b],
                           outline.points[(b + 1) % N]))
          ++crossings;
      }
    EXPECT_EQ(crossings, 0) << "z " << g.teeth;
    // Area (shoelace), clockwise: negative.
    double twice_area = 0;
    for (size_t a = 0; a < N; ++a) {
      const Vec &p = outline.points[a], &q = outline.points[(a + 1) % N];
      twice_area += p.x() * q.y() - p.y() * q.x();
    }
    const double area = -0.5 * twice_area;
    // Loose check: between the root and tip circles' areas, and within 25 % of the annulus
    // rf..ra shared half-and-half by teeth and spaces (s ~ p / 2 on the pitch circle).
    const double rf = f.root_radius, ra = f.tip_radius;
    EXPECT_GT(area, M_PI * rf * rf);
    EXPECT_LT(area, M_PI * ra * ra);
    const double estimate = M_PI * rf * rf + 0.5 * M_PI * (ra * ra - rf * rf);
    EXPECT_NEAR(area, estimate, 0.25 * (estimate - M_PI * rf * rf)) << "z " << g.teeth;
  }
}

TEST(ToothForm, AreaOfTheToothWithoutUndercutFromClosedForms) {
  // (1/2) closed-integral of r^2 dpsi over the outline (the shoelace area), per half tooth:
  //   root arc   rf^2 (pi/z - theta_f) / 2,
  //   fillet     between rf^2 dpsi_F / 2 and r_Ff^2 dpsi_F / 2 (psi monotone on it),
  //              dpsi_F = theta_f - psi(r_Ff),
  //   involute   rb^2 (tan^3 alpha_a - tan^3 alpha_Ff) / 6   (r = rb sec a, dpsi = -tan^2 a da),
  //   tip arc    ra^2 psi_a / 2.
  for (const GearGeometry& g : {thesis(), fzg16(), fzg24()}) {
    const ToothForm f = tooth_form(g, spaced(g.module / 400));
    const FormPolyline outline = gear_outline(f);
    double twice_area = 0;
    for (size_t a = 0; a < outline.points.size(); ++a) {
      const Vec &p = outline.points[a], &q = outline.points[(a + 1) % outline.points.size()];
      twice_area += p.x() * q.y() - p.y() * q.x();
    }
    const double area = -0.5 * twice_area;
    const double rb = g.base_radius(), rf = f.root_radius, ra = g.tip_radius(), r_Ff = iso_form_radius(g);
    const double theta_f = rounding_centre_u(g) / g.pitch_radius(), z = g.teeth;
    const double a_a = std::acos(rb / ra), a_F = std::acos(rb / r_Ff);
    const double dpsi_F = theta_f - involute_psi(g, r_Ff);
    const double rest = rf * rf * (M_PI / z - theta_f) / 2 +
                        rb * rb * (std::pow(std::tan(a_a), 3) - std::pow(std::tan(a_F), 3)) / 6 +
                        ra * ra * involute_psi(g, ra) / 2;
    const double lower = 2 * z * (rest + rf * rf * dpsi_F / 2), upper = 2 * z * (rest + r_Ff * r_Ff * dpsi_F / 2);
    // Chords cut the convex parts: the polygon is short by O(N h^3 / radius), < 1e-9 here.
    EXPECT_GT(area, lower - 1e-9) << "z " << g.teeth;
    EXPECT_LT(area, upper) << "z " << g.teeth;
    EXPECT_LT((upper - lower) / area, 0.05);   // the fillet zone's width: 0.9 % (z 50) to 4.5 % (z 16)
  }
}

TEST(ToothForm, SectorOfTeeth) {
  const ToothForm f = tooth_form(fzg16(), spaced(4.5e-3 / 20));
  const FormPolyline s = form_sector(f, -1, 3);
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.points.size(), 3 * f.points.size() - 2);
  EXPECT_EQ(s.tooth.front(), -1);
  EXPECT_EQ(s.tooth.back(), 1);
  // Tooth k is tooth 0 turned clockwise by 2 pi k / z: its tip centre at psi = 2 pi k / 16.
  const size_t n = f.points.size(), tip0 = n / 2;
  ASSERT_EQ(f.segment[tip0], ToothSegment::tip);
  EXPECT_NEAR(psi(s.points[tip0]), -2 * M_PI / 16, 1e-14);
  EXPECT_NEAR(psi(s.points[(n - 1) + tip0]), 0.0, 1e-14);
  EXPECT_NEAR(psi(s.points[2 * (n - 1) + tip0]), 2 * M_PI / 16, 1e-14);
}

TEST(ToothForm, RefusesWhatItDoesNotSupport) {
  ToothFormOptions o = spaced(0);
  EXPECT_THROW(tooth_form(spur(20, 3e-3, 0.9), o), std::invalid_argument);   // hf* - rho* - x < 0
  EXPECT_THROW(tooth_form(spur(6, 3e-3, 0.8), o), std::invalid_argument);    // pointed: s(ra) < 0
  ToothFormOptions big = o;
  big.tip_rounding_radius = 3e-3;
  EXPECT_THROW(tooth_form(thesis(), big), std::invalid_argument);            // rounding wider than the tip
  ToothFormOptions low = o;
  low.relief = tip_relief(thesis(), 20e-6, ReliefStart::diameter, 2 * 71.0e-3, ReliefShape::linear);
  EXPECT_THROW(tooth_form(thesis(), low), std::invalid_argument);            // relief below the form circle
  ToothFormOptions fat = o;
  fat.root_radius_coefficient = 0.5;   // u_c > p/2 for hf* = 1.25
  EXPECT_THROW(tooth_form(thesis(), fat), std::invalid_argument);
}

TEST(ToothForm, TipReliefSlopeIsTheDerivativeOfTheRelief) {
  // gear_geometry's tip_relief_slope against central differences of tip_relief_at
  // (exact for the linear shape, O(h^2) = 0 for the parabola's constant second derivative).
  const GearGeometry g = fzg16();
  for (ReliefShape shape : {ReliefShape::linear, ReliefShape::parabolic}) {
    const TipRelief r = tip_relief(g, 0.1e-3, ReliefStart::diameter, 79e-3, shape);
    const double h = 1e-6;
    for (double u : {0.1, 0.4, 0.7, 0.95}) {
      const double xi = r.start_roll + u * (r.tip_roll - r.start_roll);
      const double fd = (tip_relief_at(r, xi + h) - tip_relief_at(r, xi - h)) / (2 * h);
      EXPECT_NEAR(tip_relief_slope(r, xi), fd, 1e-9);
    }
    EXPECT_EQ(tip_relief_slope(r, r.start_roll - h), 0.0);   // below the start
    EXPECT_EQ(tip_relief_slope(r, r.tip_roll + h), 0.0);     // beyond the tip: Ca held
  }
}

}  // namespace tooth_form_test
