#include "gearhb/gears/gear_geometry.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace gearhb {

namespace {
double round_to(double v, double step) { return std::round(v / step) * step; }
}  // namespace

double GearGeometry::pressure_angle_rad() const { return pressure_angle_deg * M_PI / 180.0; }
double GearGeometry::pitch_radius() const { return 0.5 * module * teeth; }
double GearGeometry::base_radius() const { return pitch_radius() * std::cos(pressure_angle_rad()); }
double GearGeometry::tip_radius() const { return pitch_radius() + addendum; }
double GearGeometry::root_radius() const { return pitch_radius() - dedendum; }
double GearGeometry::base_pitch() const { return M_PI * module * std::cos(pressure_angle_rad()); }
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
  const double s0 = 0.5 * M_PI * g.module;
  return r * s0 / r0 + 2.0 * r * (involute(g.pressure_angle_rad()) - involute(pressure_angle_at(g, r)));
}

PathOfContact path_of_contact(const GearGeometry& g1, const GearGeometry& g2) {
  if (std::fabs(g1.pressure_angle_deg - g2.pressure_angle_deg) > 1e-12 ||
      std::fabs(g1.module - g2.module) > 1e-15)
    throw std::invalid_argument("path_of_contact: gears must share module and pressure angle");
  PathOfContact p;
  const double a = g1.pressure_angle_rad();
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
  const double a = g.pressure_angle_rad();
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

namespace {
std::string mm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g mm", v * 1e3);
  return b;
}
}  // namespace

std::string involute_tooth_model_problem(const GearGeometry& g) {
  const double rb = g.base_radius(), rf = g.root_radius(), ra = g.tip_radius();
  if (!std::isfinite(rb) || !std::isfinite(ra) || !(rb > 0.0))
    return "the gear radii are not finite positive numbers";
  if (!(rf > rb))
    return "the root circle (rf = r - hf = " + mm(rf) + ") lies inside the base circle (rb = " + mm(rb) +
           "), where the involute thickness s(r) of the tooth model does not exist";
  const double s_tip = tooth_thickness(g, ra);
  if (!(s_tip > 0.0))
    return "the tooth is pointed: its thickness at the tip circle (ra = " + mm(ra) + ") is s(ra) = " +
           mm(s_tip) + " <= 0";
  const double eps = path_of_contact(g, g).contact_ratio;
  char b[64];
  std::snprintf(b, sizeof b, "%.4g", eps);
  if (!(eps > 1.0))
    return std::string("the contact ratio is ") + b + " <= 1: at some positions no pair of teeth is in contact";
  if (!(eps < 2.0))
    return std::string("the contact ratio is ") + b +
           " >= 2: three pairs would share the load, the model has at most two";
  return "";
}

bool admissible_interval(const GearGeometry& g, void (*set)(GearGeometry&, double), double lo,
                         double hi, bool integer, double* from, double* to) {
  GearGeometry t = g;
  auto ok = [&](double v) {
    set(t, v);
    return involute_tooth_model_problem(t).empty();
  };
  // Samples over [lo, hi]: every whole number, or 4001 points (logarithmic over decades).
  std::vector<double> v;
  const bool logarithmic = lo > 0.0 && hi / lo > 100.0;
  const int n = integer && hi - lo <= 100000 ? int(hi - lo) : 4000;
  for (int i = 0; i <= n; ++i) {
    const double f = double(i) / n;
    double x = logarithmic ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f;
    v.push_back(integer ? std::round(x) : x);
  }
  int first = -1, last = -1;
  for (int i = 0; i <= n; ++i)
    if (ok(v[i])) {
      if (first < 0) first = i;
      last = i;
    }
  if (first < 0) return false;
  // Refine each end between its last bad and first good sample.
  auto refine = [&](double bad, double good) {
    for (int it = 0; it < 200 && std::fabs(good - bad) > (integer ? 1.0 : 1e-12 * std::fabs(good)); ++it) {
      const double mid = integer ? std::round(0.5 * (bad + good)) : 0.5 * (bad + good);
      if (mid == bad || mid == good) break;
      (ok(mid) ? good : bad) = mid;
    }
    return good;
  };
  *from = first > 0 ? refine(v[first - 1], v[first]) : v[first];
  *to = last < n ? refine(v[last + 1], v[last]) : v[last];
  return true;
}

}  // namespace gearhb
