#include "gearhb/gears/iso6336.hpp"

#include <cmath>
#include <stdexcept>

#include "gearhb/gears/gear_geometry.hpp"

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
  if (in.z1 <= 0 || in.z2 <= 0 || !(in.face_width_m > 0) || !(in.eps_alpha > 0) ||
      !(std::fabs(in.helix_angle_deg) < 90.0))
    throw std::invalid_argument("iso6336_mesh_stiffness: invalid gear data");
  const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
                       -0.00193, -0.24188, 0.00529, 0.00182};
  const double alpha_n = in.normal_pressure_angle_deg * M_PI / 180.0, beta = in.helix_angle_deg * M_PI / 180.0;
  Iso6336Stiffness s;
  s.zn1 = iso6336_virtual_teeth(in.z1, alpha_n, beta);
  s.zn2 = iso6336_virtual_teeth(in.z2, alpha_n, beta);
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

}  // namespace gearhb
