#include "gearhb/gears/rating/iso6336_root.hpp"

#include <cmath>
#include <stdexcept>

namespace gearhb {

namespace {

using Vec = Eigen::Vector2d;

constexpr double T_external = M_PI / 3.0;   // ISO 6336-3 clause 6: T = pi/3 for external gears

void check_gear(const GearGeometry& g, double rho_fP_star) {
  if (!(g.module > 0.0) || g.teeth < 3 || !(g.pressure_angle_deg > 0.0 && g.pressure_angle_deg < 45.0))
    throw std::invalid_argument("iso6336_root: needs m > 0, z >= 3 and 0 < alpha < 45 deg");
  if (!(rho_fP_star >= 0.0)) throw std::invalid_argument("iso6336_root: rho_fP* must be >= 0");
}

// E, G, H of the header's section 1 (s_pr = 0).
double aux_E(const GearGeometry& g, double rho_fP) {
  const double a = g.pressure_angle_rad();
  return 0.25 * M_PI * g.module - g.dedendum * std::tan(a) - (1.0 - std::sin(a)) * rho_fP / std::cos(a);
}
double aux_G(const GearGeometry& g, double rho_fP) {
  return (rho_fP - g.dedendum) / g.module + g.profile_shift;
}
double aux_H(const GearGeometry& g, double E) {
  return 2.0 / g.teeth * (0.5 * M_PI - E / g.module) - T_external;
}

}  // namespace

Iso6336CriticalSection iso6336_critical_section(const GearGeometry& g, double rho_fP_star) {
  check_gear(g, rho_fP_star);
  const double m = g.module, z = g.teeth, rho = rho_fP_star * m;
  Iso6336CriticalSection c;
  c.E = aux_E(g, rho);
  c.G = aux_G(g, rho);
  c.H = aux_H(g, c.E);
  double theta = M_PI / 6.0;
  for (c.iterations = 1; c.iterations <= 200; ++c.iterations) {
    const double next = 2.0 * c.G / z * std::tan(theta) - c.H;
    const bool done = std::fabs(next - theta) <= 1e-14;
    theta = next;
    if (done) break;
  }
  if (c.iterations > 200) throw std::runtime_error("iso6336_critical_section: theta did not converge");
  c.theta = theta;
  const double ct = std::cos(theta), rho_star = rho_fP_star;
  const double denom = z * ct * ct - 2.0 * c.G;
  if (!(denom > 0.0)) throw std::invalid_argument("iso6336_critical_section: z cos^2(theta) <= 2 G");
  c.s_Fn = m * (z * std::sin(T_external - theta) + std::sqrt(3.0) * (c.G / ct - rho_star));
  c.rho_F = m * (rho_star + 2.0 * c.G * c.G / (ct * denom));
  c.height = 0.5 * m * (z * std::cos(T_external - theta) + c.G / ct - rho_star);
  return c;
}

Iso6336LoadPoint iso6336_load_point(const GearGeometry& g, double d_en) {
  check_gear(g, 0.0);
  const double rb = g.base_radius(), a = g.pressure_angle_rad();
  if (!(d_en > 2.0 * rb && d_en <= 2.0 * g.tip_radius() * (1.0 + 1e-12)))
    throw std::invalid_argument("iso6336_load_point: the load diameter must lie between d_b and d_a");
  Iso6336LoadPoint p;
  p.d_en = d_en;
  p.alpha_en = std::acos(2.0 * rb / d_en);
  p.gamma_e = (0.5 * M_PI + 2.0 * g.profile_shift * std::tan(a)) / g.teeth + involute(a) - involute(p.alpha_en);
  p.alpha_Fen = p.alpha_en - p.gamma_e;
  p.height = 0.5 * d_en * (std::cos(p.gamma_e) - std::sin(p.gamma_e) * std::tan(p.alpha_Fen));
  return p;
}

Iso6336LoadPoint iso6336_outer_single_contact(const GearGeometry& g, double eps_alpha) {
  if (!(eps_alpha >= 1.0 && eps_alpha < 2.0))
    throw std::invalid_argument("iso6336_outer_single_contact: needs 1 <= eps_alpha < 2");
  const double ra = g.tip_radius(), rb = g.base_radius();
  const double roll = std::sqrt(ra * ra - rb * rb) - g.base_pitch() * (eps_alpha - 1.0);
  return iso6336_load_point(g, 2.0 * std::hypot(roll, rb));
}

double iso6336_bending_arm(const GearGeometry& g, double rho_fP_star, const Iso6336CriticalSection& s,
                           const Iso6336LoadPoint& p) {
  const double m = g.module, z = g.teeth, ct = std::cos(s.theta);
  return 0.5 * m *
         ((std::cos(p.gamma_e) - std::sin(p.gamma_e) * std::tan(p.alpha_Fen)) * p.d_en / m -
          z * std::cos(T_external - s.theta) - s.G / ct + rho_fP_star);
}

double iso6336_form_factor(double h_Fe, double s_Fn, double alpha_Fen, double module, double alpha) {
  const double s = s_Fn / module;
  return 6.0 * (h_Fe / module) * std::cos(alpha_Fen) / (s * s * std::cos(alpha));
}

double iso6336_stress_correction(double s_Fn, double h_Fe, double rho_F) {
  const double L = s_Fn / h_Fe, q_s = s_Fn / (2.0 * rho_F);
  return (1.2 + 0.13 * L) * std::pow(q_s, 1.0 / (1.21 + 2.3 / L));
}

double iso6336_nominal_root_stress(double F_t, double face_width, double module, double Y_F, double Y_S) {
  return F_t / (face_width * module) * Y_F * Y_S;
}

Iso6336ToothRoot iso6336_tooth_root(const GearGeometry& g, double rho_fP_star, const Iso6336LoadPoint& load) {
  Iso6336ToothRoot r;
  r.section = iso6336_critical_section(g, rho_fP_star);
  r.load = load;
  r.h_Fe = iso6336_bending_arm(g, rho_fP_star, r.section, load);
  r.L = r.section.s_Fn / r.h_Fe;
  r.q_s = r.section.s_Fn / (2.0 * r.section.rho_F);
  r.q_s_in_range = r.q_s >= 1.0 && r.q_s < 8.0;
  r.Y_F = iso6336_form_factor(r.h_Fe, r.section.s_Fn, load.alpha_Fen, g.module, g.pressure_angle_rad());
  r.Y_S = iso6336_stress_correction(r.section.s_Fn, r.h_Fe, r.section.rho_F);
  return r;
}

Iso6336ToothRoot iso6336_tooth_root(const GearGeometry& g, double rho_fP_star, const GearGeometry& mate,
                                    double centre_distance) {
  const double eps = path_of_contact(g, mate, centre_distance).contact_ratio;
  return iso6336_tooth_root(g, rho_fP_star, iso6336_outer_single_contact(g, eps));
}

// ---------------------------------------------------------------------------------------
// Measured on the generated form.

namespace {

// Circle through three points: centre and radius (the points must not be collinear).
void circle_through(const Vec& a, const Vec& b, const Vec& c, Vec* centre, double* radius) {
  const Vec ab = b - a, ac = c - a;
  const double d = 2.0 * (ab.x() * ac.y() - ab.y() * ac.x());
  if (d == 0.0) throw std::invalid_argument("form_critical_section: three collinear fillet points");
  const double ab2 = ab.squaredNorm(), ac2 = ac.squaredNorm();
  const Vec u((ac.y() * ab2 - ab.y() * ac2) / d, (ab.x() * ac2 - ac.x() * ab2) / d);
  *centre = a + u;
  *radius = u.norm();
}

bool right_segment(const ToothForm& f, size_t i, ToothSegment s) {
  return f.segment[i] == s && f.points[i].x() > 0.0;
}

}  // namespace

FormCriticalSection form_critical_section(const ToothForm& form, double tangent_angle) {
  const Vec n_star(std::cos(tangent_angle), std::sin(tangent_angle));
  const double target = n_star.y();
  const size_t N = form.points.size();
  auto fillet = [&](size_t i) { return right_segment(form, i, ToothSegment::fillet); };
  for (size_t i = 1; i + 2 < N; ++i) {
    if (!fillet(i) || !fillet(i + 1)) continue;
    const double f0 = form.normals[i].y() - target, f1 = form.normals[i + 1].y() - target;
    if ((f0 > 0.0) == (f1 > 0.0)) continue;
    if (!fillet(i - 1) || !fillet(i + 2)) break;
    // The circles through each bracketing point and its two neighbours, each giving the
    // 30-degree point and radius; both interpolated linearly in n_y to the crossing.
    const double w = f0 / (f0 - f1);
    FormCriticalSection c;
    for (size_t k = 0; k < 2; ++k) {
      const size_t j = i + k;
      Vec centre;
      double R;
      circle_through(form.points[j - 1], form.points[j], form.points[j + 1], &centre, &R);
      const double weight = k == 0 ? 1.0 - w : w;
      c.centre += weight * centre;
      c.rho_F += weight * R;
      c.point += weight * (centre - R * n_star);
    }
    c.s_Fn = 2.0 * c.point.x();
    c.height = c.point.y();
    c.spacing = 0.0;
    for (size_t j = i - 1; j <= i + 1; ++j) c.spacing = std::max(c.spacing, (form.points[j + 1] - form.points[j]).norm());
    return c;
  }
  throw std::invalid_argument("form_critical_section: the angle is not reached inside the right fillet");
}

FormLoadLine form_load_line(const ToothForm& form, double roll) {
  const size_t N = form.points.size();
  for (size_t i = 0; i + 1 < N; ++i) {
    if (!right_segment(form, i, ToothSegment::involute) || !right_segment(form, i + 1, ToothSegment::involute)) continue;
    // The right flank runs from the tip down: the roll length decreases with i.
    const double hi = form.parameter[i], lo = form.parameter[i + 1];
    if (!(roll <= hi && roll >= lo)) continue;
    const double w = (hi - roll) / (hi - lo);
    FormLoadLine l;
    l.point = (1.0 - w) * form.points[i] + w * form.points[i + 1];
    l.normal = ((1.0 - w) * form.normals[i] + w * form.normals[i + 1]).normalized();
    l.alpha_Fen = std::atan2(l.normal.y(), l.normal.x());
    l.height = l.point.y() - l.point.x() * l.normal.y() / l.normal.x();
    return l;
  }
  throw std::invalid_argument("form_load_line: the roll length lies outside the form's involute");
}

}  // namespace gearhb
