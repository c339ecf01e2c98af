#pragma once
// Mesh stiffness of spur and helical gears by ISO 6336-1:2006, clause 9 (Method B), the
// estimate a gear engineer would use beside the beam model of thesis ch. 7.
//
// Theoretical single stiffness of one tooth pair (solid disc gears), per unit face
// width [N/(mm um)] (ISO 6336-1:2006 eq. (99) and Table 9; the same constants as
// DIN 3990-1):
//     1 / c'_th = q' = C1 + C2/zn1 + C3/zn2 + C4 x1 + C5 x1/zn1
//                      + C6 x2 + C7 x2/zn2 + C8 x1^2 + C9 x2^2      [mm um / N]
//     C1..C9 = 0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
//              -0.00193, -0.24188, 0.00529, 0.00182.
//   C9 multiplies x2^2 (the wheel's shift); some open codes use x1^2 there, which moves
//   c'_th of ISO/TR 6336-30 Example 01 by -0.07 %.
// Virtual numbers of teeth (ISO 6336-1:2006 eq. (100); ISO 21771 for beta_b):
//     zn = z / (cos^2(beta_b) cos(beta)),   sin(beta_b) = sin(beta) cos(alpha_n);
//   spur gears (beta = 0): zn = z.
// Single stiffness       c' = c'_th C_M C_R C_B cos(beta)                    (eq. (101))
//     C_M = 0.8 (correction between measured and theoretical values),
//     C_R = 1 (solid gear blanks),
//     C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)] (basic rack),
// and for a line load F_t K_A / b < 100 N/mm, c' is multiplied by
//     (F_t K_A / b / 100)^0.25                                             (eq. (102)),
// which `line_load_N_per_mm` applies.
// Mesh stiffness (mean over the mesh)
//     c_gamma_alpha = c' (0.75 eps_alpha + 0.25),   c_gamma_beta = 0.85 c_gamma_alpha
//                                                             (eqs. (103), (104)),
// eps_alpha the TRANSVERSE contact ratio (for helical gears too).
// Multiply by the face width b [mm] to get a stiffness in N/um = MN/m.
//
// Check: ISO/TR 6336-30:2017 Example 01 (helical, m_n 8 mm, alpha_n 20 deg, z 17/103,
// x 0.145/0, beta 15.8 deg, a_w 500 mm, basic rack D: h_fP = 1.4 m_n, so C_B = 0.9):
// c'_th = 17.85584, c' = 12.37047, c_gamma_alpha = 17.46485 N/(mm um) (tests/unit/
// test_iso6336.cpp).
namespace gearhb {

struct Iso6336Stiffness {
  double zn1 = 0, zn2 = 0;     // virtual numbers of teeth
  double q_prime = 0;          // [mm um / N]
  double c_th = 0;             // c'_th [N/(mm um)]
  double C_M = 0.8, C_R = 1.0, C_B = 1.0, load_factor = 1.0;
  double cos_beta = 1.0;
  double c_single = 0;         // c' [N/(mm um)]
  double c_gamma_alpha = 0;    // [N/(mm um)]
  double c_gamma_beta = 0;     // 0.85 c_gamma_alpha [N/(mm um)]
  double c_single_total = 0;   // c' b [N/m]
  double c_gamma_alpha_total = 0;   // c_gamma_alpha b [N/m]
};

// Spur gears (beta = 0, zn = z): z1, z2 teeth; x1, x2 profile shift coefficients;
// pressure_angle_deg alpha_n [deg]; h_fP / m_n the basic-rack dedendum over module;
// eps_alpha the transverse contact ratio; face width b [m]; line_load F_t K_A / b [N/mm]
// (<= 0: take the >= 100 N/mm branch).
Iso6336Stiffness iso6336_mesh_stiffness(int z1, int z2, double x1, double x2, double pressure_angle_deg,
                                        double hfP_over_mn, double eps_alpha, double face_width_m,
                                        double line_load_N_per_mm);

// Spur or helical pair: everything ISO 6336-1 method B needs.
struct Iso6336Input {
  int z1 = 0, z2 = 0;                  // teeth (external gears)
  double x1 = 0, x2 = 0;               // profile shift coefficients
  double normal_pressure_angle_deg = 20;   // alpha_n [deg]
  double helix_angle_deg = 0;          // beta [deg] (0: spur)
  double hfP_over_mn = 1.25;           // basic-rack dedendum h_fP / m_n
  double eps_alpha = 0;                // transverse contact ratio
  double face_width_m = 0;             // b [m]
  double line_load_N_per_mm = 0;       // F_t K_A / b [N/mm]; <= 0: >= 100 N/mm branch
  double C_M = 0.8, C_R = 1.0;         // ISO defaults (solid blanks)
};
Iso6336Stiffness iso6336_mesh_stiffness(const Iso6336Input& in);

// zn = z / (cos^2(beta_b) cos(beta)) (formula above); beta [rad], alpha_n [rad].
double iso6336_virtual_teeth(int z, double alpha_n, double beta);

// Transverse geometry of an external helical (or spur) pair, ISO 21771:2007 §4-5:
//     alpha_t = atan(tan(alpha_n) / cos(beta)),   d = z m_n / cos(beta),
//     d_b = d cos(alpha_t),                       p_bt = pi m_n cos(alpha_t) / cos(beta),
//     cos(alpha_wt) = (d_b1 + d_b2) / (2 a_w)     (from the centre distance), or
//     inv(alpha_wt) = inv(alpha_t) + 2 tan(alpha_n) (x1 + x2) / (z1 + z2)   (from the shifts),
//     a_w = (d1 + d2) cos(alpha_t) / (2 cos(alpha_wt)),
//     eps_alpha = [sqrt(d_a1^2 - d_b1^2)/2 + sqrt(d_a2^2 - d_b2^2)/2 - a_w sin(alpha_wt)] / p_bt,
// with the tip diameters d_a as made (default d + 2 m_n (h_aP* + x), no tip shortening).
struct IsoTransverseGeometry {
  double alpha_t = 0, alpha_wt = 0;     // [rad]
  double d1 = 0, d2 = 0, db1 = 0, db2 = 0, da1 = 0, da2 = 0;   // [m]
  double centre_distance = 0;           // a_w [m] (given, or the one the shifts imply)
  double p_bt = 0;                      // transverse base pitch [m]
  double eps_alpha = 0;
};
// a_w <= 0: the centre distance the shifts imply; otherwise alpha_wt from the given a_w.
// d_a1, d_a2 <= 0: d + 2 m_n (ha_P* + x). Lengths [m], angles [rad].
IsoTransverseGeometry iso_transverse_geometry(int z1, int z2, double m_n, double alpha_n, double beta,
                                              double x1, double x2, double haP_over_mn, double a_w,
                                              double d_a1 = 0, double d_a2 = 0);

}  // namespace gearhb
