#include "gearhb/gears/geometry/gear_geometry.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace gearhb {

namespace {
double round_to(double v, double step) { return std::round(v / step) * step; }
// Operating pitch radius rw = rb / cos(alpha_w) (= r when alpha_w = alpha).
double operating_pitch_radius(const GearGeometry& g, double alpha_w) {
  return alpha_w == g.pressure_angle_rad() ? g.pitch_radius() : g.base_radius() / std::cos(alpha_w);
}
}  // namespace

double GearGeometry::pressure_angle_rad() const { return pressure_angle_deg * M_PI / 180.0; }
double GearGeometry::pitch_radius() const { return 0.5 * module * teeth; }
double GearGeometry::base_radius() const { return pitch_radius() * std::cos(pressure_angle_rad()); }
double GearGeometry::tip_radius() const { return pitch_radius() + addendum + profile_shift * module; }
double GearGeometry::root_radius() const { return pitch_radius() - dedendum + profile_shift * module; }
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
  const double s0 = g.module * (0.5 * M_PI + 2.0 * g.profile_shift * std::tan(g.pressure_angle_rad()));
  return r * s0 / r0 + 2.0 * r * (involute(g.pressure_angle_rad()) - involute(pressure_angle_at(g, r)));
}

double inverse_involute(double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) throw std::domain_error("inverse_involute: needs a finite v >= 0");
  if (v == 0.0) return 0.0;
  // inv(a) = a^3/3 + ...: start from (3 v)^(1/3) (below the root, Newton then climbs
  // monotonically since inv is convex on [0, pi/2)); inv'(a) = tan(a)^2.
  double a = std::min(std::cbrt(3.0 * v), 1.5);
  for (int it = 0; it < 100; ++it) {
    const double t = std::tan(a), f = t - a - v;
    const double next = a - f / (t * t);
    if (std::fabs(next - a) <= 1e-15 * a) {
      a = next;
      break;
    }
    a = std::min(next, 0.5 * (a + 0.5 * M_PI));   // stay inside [0, pi/2)
  }
  return a;
}

OperatingMesh operating_mesh(const GearGeometry& g1, const GearGeometry& g2, double centre_distance) {
  if (std::fabs(g1.pressure_angle_deg - g2.pressure_angle_deg) > 1e-12 ||
      std::fabs(g1.module - g2.module) > 1e-15)
    throw std::invalid_argument("path_of_contact: gears must share module and pressure angle");
  OperatingMesh mesh;
  const double alpha = g1.pressure_angle_rad(), rb = g1.base_radius() + g2.base_radius();
  if (centre_distance > 0.0) {
    if (!(centre_distance > rb))
      throw std::invalid_argument("operating_mesh: centre distance below rb1 + rb2");
    mesh.centre_distance = centre_distance;
    mesh.pressure_angle = std::acos(rb / centre_distance);
  } else {
    const double xs = g1.profile_shift + g2.profile_shift;
    // x1 + x2 = 0: alpha_w = alpha exactly (no round trip through inv^-1).
    mesh.pressure_angle = xs == 0.0 ? alpha
                                 : inverse_involute(involute(alpha) + 2.0 * std::tan(alpha) * xs /
                                                                          double(g1.teeth + g2.teeth));
    mesh.centre_distance = xs == 0.0 ? g1.pitch_radius() + g2.pitch_radius() : rb / std::cos(mesh.pressure_angle);
  }
  mesh.pitch_radius1 = operating_pitch_radius(g1, mesh.pressure_angle);
  mesh.pitch_radius2 = operating_pitch_radius(g2, mesh.pressure_angle);
  return mesh;
}

PathOfContact path_of_contact(const GearGeometry& g1, const GearGeometry& g2, double centre_distance) {
  PathOfContact p;
  p.mesh = operating_mesh(g1, g2, centre_distance);
  const double a = p.mesh.pressure_angle;
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
  p.T1B = p.T1E - p.base_pitch;
  p.T1D = p.T1A + p.base_pitch;
  return p;
}

ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, double s_from_A) {
  return contact_radii(g1, g2, path_of_contact(g1, g2), s_from_A);
}

ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& p,
                           double s_from_A) {
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
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}
}  // namespace

double normal_backlash(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& path, double A1,
                       double A2) {
  const double a = g1.pressure_angle_rad(), aw = path.mesh.pressure_angle, m = g1.module;
  return m * std::cos(a) *
             (double(g1.teeth + g2.teeth) * (involute(aw) - involute(a)) -
              2.0 * std::tan(a) * (g1.profile_shift + g2.profile_shift)) -
         (A1 + A2) * std::cos(a);
}

double undercut_limit_teeth(double dedendum_coefficient, double root_radius_coefficient, double profile_shift,
                            double pressure_angle_deg) {
  const double a = pressure_angle_deg * M_PI / 180.0, s = std::sin(a);
  const double h = dedendum_coefficient - root_radius_coefficient * (1.0 - s);
  return 2.0 * (h - profile_shift) / (s * s);
}

double tip_relief_at(const TipRelief& r, double roll) {
  if (!(r.amount > 0.0) || roll <= r.start_roll) return 0.0;
  const double u = std::min(1.0, (roll - r.start_roll) / (r.tip_roll - r.start_roll));
  return r.shape == ReliefShape::parabolic ? r.amount * u * u : r.amount * u;
}

double tip_relief_slope(const TipRelief& r, double roll) {
  if (!(r.amount > 0.0) || roll < r.start_roll || roll >= r.tip_roll) return 0.0;
  const double length = r.tip_roll - r.start_roll, u = (roll - r.start_roll) / length;
  return r.shape == ReliefShape::parabolic ? 2.0 * r.amount * u / length : r.amount / length;
}

double relief_start_roll(const GearGeometry& g, ReliefStart kind, double value) {
  const double rb = g.base_radius(), ra = g.tip_radius();
  switch (kind) {
    case ReliefStart::roll_angle_deg: return rb * value * M_PI / 180.0;
    case ReliefStart::diameter: {
      const double r = 0.5 * value;
      return r > rb ? std::sqrt(r * r - rb * rb) : -1.0;   // -1: below the base circle
    }
    case ReliefStart::length: return std::sqrt(ra * ra - rb * rb) - value;
  }
  return -1.0;
}

TipRelief tip_relief(const GearGeometry& g, double amount, ReliefStart kind, double start, ReliefShape shape) {
  TipRelief r;
  r.amount = amount;
  r.start_roll = relief_start_roll(g, kind, start);
  const double ra = g.tip_radius(), rb = g.base_radius();
  r.tip_roll = std::sqrt(ra * ra - rb * rb);
  r.shape = shape;
  return r;
}

GeometryProblem gear_pair_problem(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& p,
                                  const TipRelief& relief1, const TipRelief& relief2) {
  const GearGeometry* g[2] = {&g1, &g2};
  const TipRelief* rel[2] = {&relief1, &relief2};
  auto gear_key = [](int i, const char* k) { return "gears." + std::to_string(i) + "." + k; };
  for (int i = 0; i < 2; ++i) {
    const double ra = g[i]->tip_radius(), sa = tooth_thickness(*g[i], ra), lim = min_tip_thickness_per_module * g[i]->module;
    if (!(sa >= lim))
      return {gear_key(i, "x"), "gives a pointed tooth: tip thickness s(ra) = " + mm(sa) + " below the limit " +
                                    num(min_tip_thickness_per_module) + " m = " + mm(lim)};
  }
  const double a = p.mesh.centre_distance;
  for (int i = 0; i < 2; ++i) {
    const double c = a - g[i]->tip_radius() - g[1 - i]->root_radius();
    if (!(c > 0.0))
      return {"centre_distance", "leaves no tip clearance: a - ra" + std::to_string(i + 1) + " - rf" +
                                     std::to_string(2 - i) + " = " + mm(c) + " (the tip of gear " + std::to_string(i + 1) +
                                     " hits the root of gear " + std::to_string(2 - i) + ")"};
  }
  if (!(p.T1A > 0.0))
    return {gear_key(1, "z"), "interferes: the tip of gear 2 meets gear 1 inside its base circle (T1A = " + mm(p.T1A) +
                                  " <= 0, involute interference)"};
  if (!(p.T1E < p.T1T2))
    return {gear_key(0, "z"), "interferes: the tip of gear 1 meets gear 2 inside its base circle (T2E = " +
                                  mm(p.T1T2 - p.T1E) + " <= 0, involute interference)"};
  if (!(p.contact_ratio >= 1.0))
    return {"gears", "have a transverse contact ratio " + num(p.contact_ratio) +
                         " < 1: at some positions no pair of teeth is in contact"};
  for (int i = 0; i < 2; ++i) {
    const TipRelief& r = *rel[i];
    if (r.amount == 0.0) continue;
    const std::string key = gear_key(i, "tip_relief");
    if (!(r.amount > 0.0)) return {key + ".amount", "must be >= 0"};
    // Lowest contact point on gear i: A on gear 1 (T1A), E on gear 2 (T2E).
    const double lowest = i == 0 ? p.T1A : p.T1T2 - p.T1E;
    if (!(r.start_roll < r.tip_roll))
      return {key, "starts at or above the tip circle (roll length " + mm(r.start_roll) + " >= " + mm(r.tip_roll) + ")"};
    if (!(r.start_roll >= lowest))
      return {key, "is longer than the path of contact allows: it starts at roll length " + mm(r.start_roll) +
                       ", below the lowest contact point on this gear (" + mm(lowest) + "; relief length " +
                       mm(r.tip_roll - r.start_roll) + " > path " + mm(r.tip_roll - lowest) + ")"};
  }
  return {};
}

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
