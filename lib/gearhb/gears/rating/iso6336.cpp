#include "gearhb/gears/rating/iso6336.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>

#include "gearhb/gears/geometry/gear_geometry.hpp"

namespace gearhb {

namespace {

// alpha with tan(alpha) - alpha = v, 0 <= v < 1 (Newton from the cube-root start
// alpha ~ (3 v)^(1/3), monotone convergence from above since inv is convex).
double solve_involute(double v) {
  if (!(v >= 0.0) || !(v < 1.0)) throw std::domain_error("iso_transverse_geometry: involute function out of range");
  double a = std::cbrt(3.0 * v);
  for (int it = 0; it < 60; ++it) {
    const double t = std::tan(a);
    const double step = (t - a - v) / (t * t);   // d inv / d a = tan^2
    a -= step;
    if (std::fabs(step) <= 1e-16 * a) break;
  }
  return a;
}

}  // namespace

double iso6336_virtual_teeth(int z, double alpha_n, double beta) {
  const double beta_b = std::asin(std::sin(beta) * std::cos(alpha_n));
  const double cb = std::cos(beta_b);
  return z / (cb * cb * std::cos(beta));
}

Iso6336Stiffness iso6336_mesh_stiffness(const Iso6336Input& in) {
  if (in.z1 <= 0 || (in.z2 <= 0 && !in.internal2) || !(in.face_width_m > 0) || !(in.eps_alpha > 0) ||
      !(std::fabs(in.helix_angle_deg) < 90.0))
    throw std::invalid_argument("iso6336_mesh_stiffness: invalid gear data");
  const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
                       -0.00193, -0.24188, 0.00529, 0.00182};
  const double alpha_n = in.normal_pressure_angle_deg * M_PI / 180.0, beta = in.helix_angle_deg * M_PI / 180.0;
  Iso6336Stiffness s;
  s.zn1 = iso6336_virtual_teeth(in.z1, alpha_n, beta);
  s.zn2 = in.internal2 ? INFINITY : iso6336_virtual_teeth(in.z2, alpha_n, beta);
  const double x1 = in.x1, x2 = in.x2;
  s.q_prime = C[0] + C[1] / s.zn1 + C[2] / s.zn2 + C[3] * x1 + C[4] * x1 / s.zn1 + C[5] * x2 +
              C[6] * x2 / s.zn2 + C[7] * x1 * x1 + C[8] * x2 * x2;
  s.c_th = 1.0 / s.q_prime;
  s.C_M = in.C_M;
  s.C_R = in.C_R;
  s.C_B = (1.0 + 0.5 * (1.2 - in.hfP_over_mn)) * (1.0 - 0.02 * (20.0 - in.normal_pressure_angle_deg));
  if (in.line_load_N_per_mm > 0.0 && in.line_load_N_per_mm < 100.0)
    s.load_factor = std::pow(in.line_load_N_per_mm / 100.0, 0.25);
  s.cos_beta = std::cos(beta);
  s.c_single = s.c_th * s.C_M * s.C_R * s.C_B * s.cos_beta * s.load_factor;
  s.c_gamma_alpha = s.c_single * (0.75 * in.eps_alpha + 0.25);
  s.c_gamma_beta = 0.85 * s.c_gamma_alpha;
  const double b_mm = in.face_width_m * 1e3;
  // N/(mm um) * mm = N/um = 1e6 N/m.
  s.c_single_total = s.c_single * b_mm * 1e6;
  s.c_gamma_alpha_total = s.c_gamma_alpha * b_mm * 1e6;
  return s;
}

Iso6336Stiffness iso6336_mesh_stiffness(int z1, int z2, double x1, double x2, double pressure_angle_deg,
                                        double hfP_over_mn, double eps_alpha, double face_width_m,
                                        double line_load_N_per_mm) {
  Iso6336Input in;
  in.z1 = z1;
  in.z2 = z2;
  in.x1 = x1;
  in.x2 = x2;
  in.normal_pressure_angle_deg = pressure_angle_deg;
  in.hfP_over_mn = hfP_over_mn;
  in.eps_alpha = eps_alpha;
  in.face_width_m = face_width_m;
  in.line_load_N_per_mm = line_load_N_per_mm;
  return iso6336_mesh_stiffness(in);
}

IsoTransverseGeometry iso_transverse_geometry(int z1, int z2, double m_n, double alpha_n, double beta,
                                              double x1, double x2, double haP_over_mn, double a_w,
                                              double d_a1, double d_a2) {
  if (z1 <= 0 || z2 <= 0 || !(m_n > 0) || !(alpha_n > 0) || !(std::fabs(beta) < M_PI / 2))
    throw std::invalid_argument("iso_transverse_geometry: invalid gear data");
  IsoTransverseGeometry g;
  const double cb = std::cos(beta);
  g.alpha_t = std::atan(std::tan(alpha_n) / cb);
  g.d1 = z1 * m_n / cb;
  g.d2 = z2 * m_n / cb;
  g.db1 = g.d1 * std::cos(g.alpha_t);
  g.db2 = g.d2 * std::cos(g.alpha_t);
  g.da1 = d_a1 > 0 ? d_a1 : g.d1 + 2.0 * m_n * (haP_over_mn + x1);
  g.da2 = d_a2 > 0 ? d_a2 : g.d2 + 2.0 * m_n * (haP_over_mn + x2);
  if (a_w > 0) {
    const double c = (g.db1 + g.db2) / (2.0 * a_w);
    if (!(c < 1.0)) throw std::domain_error("iso_transverse_geometry: centre distance below the base radii sum");
    g.alpha_wt = std::acos(c);
    g.centre_distance = a_w;
  } else {
    g.alpha_wt = solve_involute(involute(g.alpha_t) + 2.0 * std::tan(alpha_n) * (x1 + x2) / (z1 + z2));
    g.centre_distance = (g.db1 + g.db2) / (2.0 * std::cos(g.alpha_wt));
  }
  g.p_bt = M_PI * m_n * std::cos(g.alpha_t) / cb;
  const double g1 = 0.5 * std::sqrt(g.da1 * g.da1 - g.db1 * g.db1);
  const double g2 = 0.5 * std::sqrt(g.da2 * g.da2 - g.db2 * g.db2);
  g.eps_alpha = (g1 + g2 - g.centre_distance * std::sin(g.alpha_wt)) / g.p_bt;
  return g;
}

namespace {

// Table 8 of ISO 6336-1:2006 (formulas in the header).
void kv_coefficients(double eg, double C[7]) {
  C[0] = 0.32;
  C[4] = 0.47;
  if (eg <= 2.0) {
    C[1] = 0.34, C[2] = 0.23, C[3] = 0.90, C[5] = 0.47;
  } else {
    C[1] = 0.57 / (eg - 0.3);
    C[2] = 0.096 / (eg - 1.56);
    C[3] = (0.57 - 0.05 * eg) / (eg - 1.44);
    C[5] = 0.12 / (eg - 1.74);
  }
  C[6] = eg <= 1.5 ? 0.75 : eg <= 2.5 ? 0.125 * std::sin(M_PI * (eg - 2.0)) + 0.875 : 1.0;
}

}  // namespace

Iso6336Kv iso6336_dynamic_factor(const Iso6336KvInput& in, double n1_rpm) {
  if (in.z1 <= 0 || !(in.eps_gamma > 1.0) || !(in.c_prime > 0) || !(in.c_gamma_alpha > 0) || !(in.m_red > 0) ||
      !(in.line_load > 0) || !(in.f_pb_eff >= 0) || !(in.f_f_alpha_eff >= 0) || !(in.C_a >= 0) || !(n1_rpm >= 0))
    throw std::invalid_argument("iso6336_dynamic_factor: invalid input");
  Iso6336Kv k;
  k.n_E1_rpm = 30000.0 / (M_PI * in.z1) * std::sqrt(in.c_gamma_alpha / in.m_red);
  k.N = n1_rpm / k.n_E1_rpm;
  k.N_S = in.line_load < 100.0 ? 0.5 + 0.35 * std::sqrt(in.line_load / 100.0) : 0.85;
  k.B_p = in.c_prime * in.f_pb_eff / in.line_load;
  k.B_f = in.c_prime * in.f_f_alpha_eff / in.line_load;
  k.B_k = std::fabs(1.0 - in.c_prime * in.C_a / in.line_load);
  kv_coefficients(in.eps_gamma, k.C_v);
  const double* C = k.C_v;
  const double resonance = C[0] * k.B_p + C[1] * k.B_f + C[3] * k.B_k + 1.0;   // K_v(N_S < N <= 1.15)
  const double super = C[4] * k.B_p + C[5] * k.B_f + C[6];                    // K_v(N >= 1.5)
  if (k.N <= k.N_S) {
    k.range = Iso6336KvRange::subcritical;
    k.K_v = k.N * (C[0] * k.B_p + C[1] * k.B_f + C[2] * k.B_k) + 1.0;
  } else if (k.N <= 1.15) {
    k.range = Iso6336KvRange::main_resonance;
    k.K_v = resonance;
  } else if (k.N < 1.5) {
    k.range = Iso6336KvRange::intermediate;
    k.K_v = super + (resonance - super) * (1.5 - k.N) / 0.35;
  } else {
    k.range = Iso6336KvRange::supercritical;
    k.K_v = super;
  }
  return k;
}

double iso6336_reduced_mass_solid(double d_m1_mm, double d_b1_mm, double u, double rho1, double rho2) {
  if (!(d_m1_mm > 0) || !(d_b1_mm > 0) || !(u > 0) || !(rho1 > 0) || !(rho2 > 0))
    throw std::invalid_argument("iso6336_reduced_mass_solid: invalid input");
  const double r = d_m1_mm / d_b1_mm;
  return M_PI / 8.0 * r * r * d_m1_mm * d_m1_mm / (1.0 / rho1 + 1.0 / (rho2 * u * u));
}

double iso6336_running_in_case_hardened(double f_um) { return std::min(0.075 * f_um, 3.0); }

double iso6336_running_in_relief(double sigma_Hlim) {
  const double t = sigma_Hlim / 97.0 - 18.45;
  return t * t / 18.0 + 1.5;
}

double iso1328_round(double v) {
  const double step = v > 10.0 ? 1.0 : v >= 5.0 ? 0.5 : 0.1;
  return std::round(v / step) * step;
}

Iso1328Tolerances iso1328_tolerances(int grade, double m_n_mm, double d_mm) {
  static const double m_bounds[] = {0.5, 2, 3.5, 6, 10, 16, 25, 40, 70};
  static const double d_bounds[] = {5, 20, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6000, 8000, 10000};
  auto class_mean = [](double v, const double* b, std::size_t n, const char* what) {
    if (!(v >= b[0]) || !(v <= b[n - 1])) {
      char m[160];
      std::snprintf(m, sizeof m, "%s %g mm is outside ISO 1328-1:1995's range %g..%g mm", what, v, b[0], b[n - 1]);
      throw std::domain_error(m);
    }
    std::size_t i = 1;
    while (v > b[i]) ++i;   // b[i-1] < v <= b[i] (the first range includes its lower bound)
    return std::sqrt(b[i - 1] * b[i]);
  };
  if (grade < 1 || grade > 12) throw std::domain_error("iso1328_tolerances: grade outside 1..12");
  Iso1328Tolerances t;
  t.m_class = class_mean(m_n_mm, m_bounds, std::size(m_bounds), "module");
  t.d_class = class_mean(d_mm, d_bounds, std::size(d_bounds), "reference diameter");
  const double q = std::pow(2.0, 0.5 * (grade - 5));
  t.f_pt = iso1328_round((0.3 * (t.m_class + 0.4 * std::sqrt(t.d_class)) + 4.0) * q);
  t.f_f_alpha = iso1328_round((2.5 * std::sqrt(t.m_class) + 0.17 * std::sqrt(t.d_class) + 0.5) * q);
  return t;
}

}  // namespace gearhb
