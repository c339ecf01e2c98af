#include "gearhb/gears/tooth/potential_energy.hpp"

#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/core/gsl_errors.hpp"
#include "gearhb/gears/geometry/gear_geometry.hpp"

namespace gearhb {

namespace {

// Gauss-Legendre nodes and weights of the n-point rule on [-1, 1], from GSL's glfixed
// tables, computed once per n (the table lookups are shared between threads).
const std::vector<std::pair<double, double>>& gauss_legendre(int n) {
  if (n < 1 || n > 1024) throw std::invalid_argument("potential energy: quadrature points must be in [1, 1024]");
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<std::vector<std::pair<double, double>>>> rules;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& rule = rules[n];
  if (!rule) {
    const GslErrorsReturned errors_returned;
    gsl_integration_glfixed_table* t = gsl_integration_glfixed_table_alloc(size_t(n));
    if (!t) throw std::runtime_error("potential energy: GSL could not build the Gauss-Legendre rule");
    auto nodes = std::make_unique<std::vector<std::pair<double, double>>>(size_t(n));
    for (int i = 0; i < n; ++i) {
      double x = 0, weight = 0;
      const int status = gsl_integration_glfixed_point(-1.0, 1.0, size_t(i), &x, &weight, t);
      if (status) {
        gsl_integration_glfixed_table_free(t);
        gsl_check(status, "potential energy: Gauss-Legendre node");
      }
      (*nodes)[size_t(i)] = {x, weight};
    }
    gsl_integration_glfixed_table_free(t);
    rule = std::move(nodes);
  }
  return *rule;
}

void check_gear(const PeGear& g) {
  if (g.teeth < 3 || !(g.module > 0) || !(g.pressure_angle > 0 && g.pressure_angle < M_PI / 2) ||
      !(g.addendum_coefficient > 0) || !(g.dedendum_coefficient > 0) || !(g.root_radius_coefficient >= 0) ||
      !(g.face_width > 0) || !(g.youngs_modulus > 0) || !(g.poisson_ratio >= 0 && g.poisson_ratio < 0.5) ||
      !std::isfinite(g.profile_shift) || !(g.bore_radius >= 0))
    throw std::invalid_argument("potential energy: invalid gear data");
}

double half_angle(const PeToothGeometry& t, double a) { return t.theta_b - involute(a); }

}  // namespace

PeToothGeometry pe_tooth_geometry(const PeGear& g, PeRootAngle root_angle) {
  check_gear(g);
  const double a0 = g.pressure_angle, m = g.module, z = g.teeth;
  PeToothGeometry t;
  t.r0 = 0.5 * m * z;
  t.rb = t.r0 * std::cos(a0);
  t.ra = t.r0 + m * (g.addendum_coefficient + g.profile_shift);
  t.rf = t.r0 - m * (g.dedendum_coefficient - g.profile_shift);
  t.theta_b = (0.5 * M_PI + 2.0 * g.profile_shift * std::tan(a0)) / z + involute(a0);
  t.half_thickness_base = t.rb * std::sin(t.theta_b);
  if (!(t.rf > 0) || !(t.ra > t.rf)) throw std::invalid_argument("potential energy: root radius must be in (0, tip radius)");
  if (!(t.ra > t.rb)) throw std::invalid_argument("potential energy: tip circle inside the base circle (no involute)");
  if (!(half_angle(t, std::acos(t.rb / t.ra)) > 0))
    throw std::invalid_argument("potential energy: pointed tooth (the flanks cross below the tip circle)");
  t.root_below_base = t.rf < t.rb;
  if (t.root_below_base) {
    if (!(t.rf > t.half_thickness_base))
      throw std::invalid_argument("potential energy: root circle too small for the base-circle tooth thickness");
    t.a_root = 0.0;
    t.x_root = std::sqrt(t.rf * t.rf - t.half_thickness_base * t.half_thickness_base);
    t.theta_f_beam = std::asin(t.half_thickness_base / t.rf);
  } else {
    t.a_root = std::acos(t.rb / t.rf);
    t.theta_f_beam = half_angle(t, t.a_root);
    t.x_root = t.rf * std::cos(t.theta_f_beam);
  }
  const double hf = g.dedendum_coefficient, rho = g.root_radius_coefficient;
  const double theta_generated = (0.5 * M_PI + 2.0 * (hf - rho) * std::tan(a0) + 2.0 * rho / std::cos(a0)) / z;
  t.theta_f = root_angle == PeRootAngle::generated_fillet ? theta_generated : t.theta_f_beam;
  t.h_f = g.bore_radius > 0 ? t.rf / g.bore_radius : 0.0;
  t.r_min_contact = std::max(t.rb, t.rf);
  return t;
}

PeBeamIntegrals pe_beam_integrals(const std::function<PeSection(double)>& section, double t0, double t1,
                                  double x_c, double y_c, double alpha_m, double face_width,
                                  double E_prime, double G, int n_points) {
  const std::vector<std::pair<double, double>>& rule = gauss_legendre(n_points);
  const double c = std::cos(alpha_m), s = std::sin(alpha_m), b = face_width;
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  double kb = 0, ks = 0, ka = 0;
  for (const auto& [node, weight] : rule) {
    const PeSection q = section(mid + half * node);
    const double dw = weight * half * q.dx_dt;
    const double area = 2.0 * q.half_thickness * b;                                       // A = 2 y b
    const double inertia = 2.0 / 3.0 * q.half_thickness * q.half_thickness * q.half_thickness * b;   // (2y)^3 b / 12
    const double moment = c * (x_c - q.x) - s * y_c;
    kb += dw * moment * moment / (E_prime * inertia);
    ks += dw * 1.2 * c * c / (G * area);
    ka += dw * s * s / (E_prime * area);
  }
  return {kb, ks, ka};
}

SainsotCoefficients sainsot_coefficients(double h_f, double theta_f) {
  // Sainsot, Velex & Duverger (2004), Table 1: rows L*, M*, P*, Q*; columns A..F.
  static const double T[4][6] = {{-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},
                                 {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},
                                 {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},
                                 {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904}};
  double X[4];
  for (int i = 0; i < 4; ++i)
    X[i] = T[i][0] / (theta_f * theta_f) + T[i][1] * h_f * h_f + T[i][2] * h_f / theta_f + T[i][3] / theta_f +
           T[i][4] * h_f + T[i][5];
  return {X[0], X[1], X[2], X[3]};
}

bool pe_fillet_in_range(double h_f, double theta_f) {
  return h_f >= 1.4 && h_f <= 7.0 && theta_f >= 0.01 && theta_f <= 0.12;
}

PeToothCompliance pe_tooth_compliance(const PeGear& g, double contact_radius, const PeOptions& o) {
  const PeToothGeometry t = pe_tooth_geometry(g, o.root_angle);
  const double slack = 1e-12 * t.ra;
  if (!(contact_radius >= t.r_min_contact - slack && contact_radius <= t.ra + slack))
    throw std::domain_error("pe_tooth_compliance: contact radius " + std::to_string(contact_radius) +
                            " m outside [max(rb, rf), ra] = [" + std::to_string(t.r_min_contact) + ", " +
                            std::to_string(t.ra) + "] m");
  const double r = std::min(std::max(contact_radius, t.r_min_contact), t.ra);
  const double E = g.youngs_modulus, nu = g.poisson_ratio, b = g.face_width;
  const double E_prime = o.elasticity == PeElasticity::plane_strain ? E / (1.0 - nu * nu) : E;
  const double G = E / (2.0 * (1.0 + nu));

  PeToothCompliance out;
  const double a_c = std::acos(std::min(1.0, t.rb / r));
  const double theta_c = half_angle(t, a_c);
  const double x_c = r * std::cos(theta_c), y_c = r * std::sin(theta_c);
  const double alpha_m = a_c - theta_c;
  out.load_angle = alpha_m;

  // Involute piece, in the pressure angle a.
  const double rb = t.rb;
  const auto involute_section = [&t, rb](double a) {
    const double ca = std::cos(a), sa = std::sin(a), r_a = rb / ca, th = t.theta_b - (std::tan(a) - a);
    const double ct = std::cos(th), st = std::sin(th);
    return PeSection{r_a * ct, r_a * st, (ct + st * sa / ca) * rb * sa / (ca * ca)};
  };
  if (a_c > t.a_root) {
    const PeBeamIntegrals p =
        pe_beam_integrals(involute_section, t.a_root, a_c, x_c, y_c, alpha_m, b, E_prime, G, o.quadrature_points);
    out.bending += p.bending;
    out.shear += p.shear;
    out.axial += p.axial;
  }
  // Straight piece between the root and the base circle.
  if (t.root_below_base) {
    const double h_b = t.half_thickness_base;
    const auto straight = [h_b](double x) { return PeSection{x, h_b, 1.0}; };
    const double x_b = t.rb * std::cos(t.theta_b);
    const PeBeamIntegrals p =
        pe_beam_integrals(straight, t.x_root, x_b, x_c, y_c, alpha_m, b, E_prime, G, o.quadrature_points);
    out.bending += p.bending;
    out.shear += p.shear;
    out.axial += p.axial;
  }
  // Fillet foundation.
  out.S_f = 2.0 * t.rf * t.theta_f;
  out.u_f = x_c - y_c * std::tan(alpha_m) - t.rf;
  if (o.fillet_foundation) {
    if (!(g.bore_radius > 0))
      throw std::invalid_argument("pe_tooth_compliance: the fillet foundation needs the bore radius (PeGear::bore_radius)");
    const SainsotCoefficients X = sainsot_coefficients(t.h_f, t.theta_f);
    const double u = out.u_f / out.S_f, c = std::cos(alpha_m), tn = std::tan(alpha_m);
    out.fillet = c * c / (E * b) * (X.L * u * u + X.M * u + X.P * (1.0 + X.Q * tn * tn));
  }
  return out;
}

PeToothCompliance pe_internal_tooth_compliance(const PeGear& g, double contact_radius, const PeOptions& o) {
  check_gear(g);
  if (g.profile_shift != 0.0) throw std::invalid_argument("pe_internal_tooth_compliance: no profile shift");
  const double a0 = g.pressure_angle, m = g.module, z = g.teeth;
  const double r0 = 0.5 * m * z, rb = r0 * std::cos(a0), ra = r0 - m * g.addendum_coefficient,
               rf = r0 + m * g.dedendum_coefficient;
  if (!(ra > rb)) throw std::invalid_argument("pe_internal_tooth_compliance: tip circle inside the base circle");
  const double slack = 1e-12 * rf;
  if (!(contact_radius >= ra - slack && contact_radius <= rf + slack))
    throw std::domain_error("pe_internal_tooth_compliance: contact radius " + std::to_string(contact_radius) +
                            " m outside [ra, rf] = [" + std::to_string(ra) + ", " + std::to_string(rf) + "] m");
  const double r = std::min(std::max(contact_radius, ra), rf);
  const double E = g.youngs_modulus, nu = g.poisson_ratio, b = g.face_width;
  const double E_prime = o.elasticity == PeElasticity::plane_strain ? E / (1.0 - nu * nu) : E;
  const double G = E / (2.0 * (1.0 + nu));
  const double psi0 = 0.5 * M_PI / z - involute(a0);
  const auto psi = [psi0](double a) { return psi0 + involute(a); };
  // The section at pressure angle a: x = -r cos(psi), y = r sin(psi), dx/da = -d(r cos psi)/da
  // with dr/da = rb sin(a) / cos^2(a), dpsi/da = tan^2(a).
  const auto section = [rb, &psi](double a) {
    const double ca = std::cos(a), sa = std::sin(a), ra_ = rb / ca, p = psi(a);
    const double dr = rb * sa / (ca * ca), dp = std::tan(a) * std::tan(a);
    return PeSection{-ra_ * std::cos(p), ra_ * std::sin(p), -(dr * std::cos(p) - ra_ * std::sin(p) * dp)};
  };
  const double a_c = std::acos(rb / r), a_f = std::acos(rb / rf), psi_c = psi(a_c);
  PeToothCompliance out;
  out.load_angle = a_c + psi_c;
  const PeBeamIntegrals p = pe_beam_integrals(section, a_f, a_c, -r * std::cos(psi_c), r * std::sin(psi_c),
                                              out.load_angle, b, E_prime, G, o.quadrature_points);
  out.bending = p.bending;
  out.shear = p.shear;
  out.axial = p.axial;
  return out;
}

double pe_hertz_compliance(const PeGear& g1, const PeGear& g2) {
  check_gear(g1);
  check_gear(g2);
  const double b = std::min(g1.face_width, g2.face_width);
  const double s1 = (1.0 - g1.poisson_ratio * g1.poisson_ratio) / g1.youngs_modulus;
  const double s2 = (1.0 - g2.poisson_ratio * g2.poisson_ratio) / g2.youngs_modulus;
  return 2.0 / (M_PI * b) * (s1 + s2);
}

double pe_body_coupling(const PeGear& g) {
  check_gear(g);
  const PeToothGeometry t = pe_tooth_geometry(g);
  if (!(g.bore_radius > 0.0 && g.bore_radius < t.rf))
    throw std::invalid_argument("pe_body_coupling: the bore radius must lie in (0, r_f)");
  const double G = g.youngs_modulus / (2.0 * (1.0 + g.poisson_ratio));
  const double c = (1.0 / (g.bore_radius * g.bore_radius) - 1.0 / (t.rf * t.rf)) / (4.0 * M_PI * G * g.face_width);
  return t.rb * t.rb * c;
}

double pe_pair_stiffness(const PeGear& g1, const PeGear& g2, double r1, double r2, bool hertz, const PeOptions& o) {
  double q = pe_tooth_compliance(g1, r1, o).total() + pe_tooth_compliance(g2, r2, o).total();
  if (hertz) q += pe_hertz_compliance(g1, g2);
  return 1.0 / q;
}

}  // namespace gearhb
