#include "gearhb/gears/gear_geometry.hpp"

#include <cmath>
#include <stdexcept>

namespace gearhb {

namespace {
constexpr double kPi = 3.14159265358979323846;
double round_to(double v, double step) { return std::round(v / step) * step; }
}  // namespace

double GearGeometry::pressure_angle() const { return pressure_angle_deg * kPi / 180.0; }
double GearGeometry::pitch_radius() const { return 0.5 * module * teeth; }
double GearGeometry::base_radius() const { return pitch_radius() * std::cos(pressure_angle()); }
double GearGeometry::tip_radius() const { return pitch_radius() + addendum; }
double GearGeometry::root_radius() const { return pitch_radius() - dedendum; }
double GearGeometry::base_pitch() const { return kPi * module * std::cos(pressure_angle()); }
double GearGeometry::tooth_height() const { return addendum + dedendum; }

double involute(double a) { return std::tan(a) - a; }

double pressure_angle_at(const GearGeometry& g, double r) {
  const double rb = g.base_radius();
  if (r < rb * (1.0 - 1e-12))
    throw std::domain_error("pressure_angle_at: radius below the base circle (no involute)");
  return std::acos(std::min(1.0, rb / r));
}

double tooth_thickness(const GearGeometry& g, double r) {
  const double r0 = g.pitch_radius();
  const double s0 = 0.5 * kPi * g.module;
  return r * s0 / r0 + 2.0 * r * (involute(g.pressure_angle()) - involute(pressure_angle_at(g, r)));
}

PathOfContact path_of_contact(const GearGeometry& g1, const GearGeometry& g2) {
  if (std::fabs(g1.pressure_angle_deg - g2.pressure_angle_deg) > 1e-12 ||
      std::fabs(g1.module - g2.module) > 1e-15)
    throw std::invalid_argument("path_of_contact: gears must share module and pressure angle");
  PathOfContact p;
  const double a = g1.pressure_angle();
  const double rb1 = g1.base_radius(), rb2 = g2.base_radius();
  p.T1C = rb1 * std::tan(a);
  p.T2C = rb2 * std::tan(a);
  p.T1T2 = p.T1C + p.T2C;
  p.T1E = std::sqrt(g1.tip_radius() * g1.tip_radius() - rb1 * rb1);
  const double T2A = std::sqrt(g2.tip_radius() * g2.tip_radius() - rb2 * rb2);
  p.T1A = p.T1T2 - T2A;
  p.CE = p.T1E - p.T1C;
  p.AC = T2A - p.T2C;
  p.AE = p.AC + p.CE;
  p.base_pitch = g1.base_pitch();
  p.contact_ratio = p.AE / p.base_pitch;
  return p;
}

ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, double s_from_A) {
  const PathOfContact p = path_of_contact(g1, g2);
  const double T1P = p.T1A + s_from_A;
  const double T2P = p.T1T2 - T1P;
  const double rb1 = g1.base_radius(), rb2 = g2.base_radius();
  return {std::sqrt(rb1 * rb1 + T1P * T1P), std::sqrt(rb2 * rb2 + T2P * T2P)};
}

ToothAxisAngles tooth_axis_angles(const GearGeometry& g, const PathOfContact& path,
                                  T2CFormula formula, bool round_like_thesis) {
  const double a = g.pressure_angle();
  ToothAxisAngles t;
  t.rb = g.base_radius();
  t.AC = path.AC;
  t.CE = path.CE;
  t.T2C = formula == T2CFormula::thesis_rb_sin ? t.rb * std::sin(a) : t.rb * std::tan(a);
  if (round_like_thesis) {
    const double step = 1e-4;   // the thesis prints these to 0.1 mm
    t.rb = round_to(t.rb, step);
    t.AC = round_to(t.AC, step);
    t.CE = round_to(t.CE, step);
    t.T2C = round_to(t.T2C, step);
  }
  t.T2E = t.T2C - t.CE;
  if (round_like_thesis) t.T2E = round_to(t.T2E, 1e-4);
  t.beta = a - std::atan(t.T2E / t.rb);
  t.epsilon = std::atan((t.T2C + t.AC) / t.rb) - a;
  t.cos_alpha_minus_beta = std::cos(a - t.beta);
  t.cos_alpha_plus_epsilon = std::cos(a + t.epsilon);
  t.force_variation =
      (t.cos_alpha_minus_beta - t.cos_alpha_plus_epsilon) / t.cos_alpha_plus_epsilon;
  return t;
}

}  // namespace gearhb
