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
  // Gear 2 an internal gear (a ring meshing the external gear 1): its virtual number of
  // teeth is infinite, so the terms C3 / zn2 and C7 x2 / zn2 of q' vanish (z2 is not used;
  // ISO 6336-1:2006 9.3.2, as DIN 3990-1); x2 its profile shift.
  bool internal2 = false;
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

// ---------------------------------------------------------------------------------------
// Dynamic factor K_v by ISO 6336-1:2006 clause 6.3 (method B), the one-mass estimate of the
// dynamic tooth load a gear engineer sets beside a computed response (README "The pair over
// its speed range"). Units are ISO's: mm, um, N/mm, kg/mm, rpm.
//
// Resonance speed of gear 1 and resonance ratio (eqs. (6), (9)):
//     n_E1 = 30000 / (pi z1) sqrt(c_gamma_alpha / m_red)   [rpm],     N = n1 / n_E1,
//   m_red the reduced mass of the pair per unit face width on the line of action [kg/mm]:
//   m_red = m1* m2* / (m1* + m2*), m* = J* / r_b^2 (eq. (30) for solid discs:
//   m_red = (pi/8) (d_m1/d_b1)^2 d_m1^2 / (1/rho1 + 1/(rho2 u^2)), d_m = (d_a + d_f)/2).
// Lower limit of the main resonance range (eqs. (11), (12)), line load F_t K_A / b:
//     N_S = 0.5 + 0.35 sqrt(F_t K_A / (100 b))   for F_t K_A / b < 100 N/mm,   N_S = 0.85 otherwise.
// Deviation and relief terms (eqs. (15)-(17)):
//     B_p = c' f_pb,eff / (K_A F_t / b),   B_f = c' f_f,eff / (K_A F_t / b),
//     B_k = |1 - c' C_a / (K_A F_t / b)|,
//   f_pb,eff = f_pb - y_p, f_f,eff = f_falpha - y_f (running-in allowances), C_a the tip relief.
// K_v per range (eqs. (13), (14), (20)-(22)):
//     subcritical   N <= N_S:          K_v = N (C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1,
//     main resonance N_S < N <= 1.15:  K_v = C_v1 B_p + C_v2 B_f + C_v4 B_k + 1,
//     supercritical N >= 1.5:          K_v = C_v5 B_p + C_v6 B_f + C_v7,
//     intermediate  1.15 < N < 1.5:    linear in N between K_v(1.15) and K_v(1.5).
// The coefficients (Table 8), eps_gamma the total contact ratio:
//     1 < eps_gamma <= 2: C_v1..C_v6 = 0.32, 0.34, 0.23, 0.90, 0.47, 0.47;
//     eps_gamma > 2: C_v1 = 0.32, C_v2 = 0.57/(eps_gamma - 0.3), C_v3 = 0.096/(eps_gamma - 1.56),
//                    C_v4 = (0.57 - 0.05 eps_gamma)/(eps_gamma - 1.44), C_v5 = 0.47,
//                    C_v6 = 0.12/(eps_gamma - 1.74);
//     C_v7 = 0.75 (eps_gamma <= 1.5), 0.125 sin(pi (eps_gamma - 2)) + 0.875 (1.5..2.5), 1 (> 2.5).
//
// Check: ISO/TR 6336-30:2017 Example 01 prints K_v = 1.003 (tests/unit/test_iso6336.cpp, with
// the deviations of ISO 1328-1:1995 grade 5, C_a = 70 um, K_A = 1).
enum class Iso6336KvRange : int { subcritical = 0, main_resonance = 1, intermediate = 2, supercritical = 3 };

struct Iso6336KvInput {
  int z1 = 0;                  // teeth of gear 1 (whose speed n1 is given)
  double eps_gamma = 0;        // total contact ratio eps_alpha + eps_beta (spur: eps_alpha)
  double c_prime = 0;          // single stiffness c' [N/(mm um)]
  double c_gamma_alpha = 0;    // mesh stiffness c_gamma_alpha [N/(mm um)]
  double m_red = 0;            // reduced mass per unit face width [kg/mm]
  double line_load = 0;        // K_A F_t / b [N/mm]
  double f_pb_eff = 0;         // effective base pitch deviation after running-in [um]
  double f_f_alpha_eff = 0;    // effective profile form deviation after running-in [um]
  double C_a = 0;              // tip relief [um] (none: the running-in amount C_ay)
};

struct Iso6336Kv {
  double n_E1_rpm = 0;         // resonance speed of gear 1 [rpm]
  double N = 0;                // resonance ratio n1 / n_E1
  double N_S = 0;              // lower limit of the main resonance range
  double B_p = 0, B_f = 0, B_k = 0;
  double C_v[7] = {};          // C_v1..C_v7
  Iso6336KvRange range = Iso6336KvRange::subcritical;
  double K_v = 1;
};

// K_v at speed n1 [rpm] of gear 1; std::invalid_argument for non-positive stiffness, mass,
// line load or eps_gamma <= 1, or negative deviations / relief.
Iso6336Kv iso6336_dynamic_factor(const Iso6336KvInput& in, double n1_rpm);

// m_red of two solid discs, ISO 6336-1:2006 eq. (30) as printed (above): d_m1, d_b1 [mm],
// u = z2 / z1, densities [kg/mm^3]; [kg/mm].
double iso6336_reduced_mass_solid(double d_m1_mm, double d_b1_mm, double u, double rho1, double rho2);

// Running-in allowance of case-hardened or nitrided steel (ISO 6336-1:2006 clause 7.3.3,
// used for y_p = y_alpha with f = f_pb and for y_f with f = f_falpha):
//     y = 0.075 f,  at most 3 um.
double iso6336_running_in_case_hardened(double f_um);

// Tip relief produced by running-in when none is made (ISO 6336-1:2006 Table 8):
//     C_ay = (1/18) (sigma_Hlim / 97 - 18.45)^2 + 1.5   [um],  sigma_Hlim [N/mm^2].
double iso6336_running_in_relief(double sigma_Hlim);

// Single pitch and profile form tolerances of ISO 1328-1:1995 (its Annex B for f_falpha),
// accuracy grade Q = 1..12 [um]:
//     f_pt   = [0.3 (m + 0.4 sqrt(d)) + 4] 2^((Q-5)/2),
//     f_falpha = [2.5 sqrt(m) + 0.17 sqrt(d) + 0.5] 2^((Q-5)/2),
// with m and d the geometric means of the bounds of the standard's range that holds the
// gear (m: 0.5, 2, 3.5, 6, 10, 16, 25, 40, 70 mm; d: 5, 20, 50, 125, 280, 560, 1000, 1600,
// 2500, 4000, 6000, 8000, 10000 mm; a value on a bound belongs to the lower range), and
// rounded as the standard rounds: above 10 um to whole um, 5..10 um to 0.5 um, below 5 um
// to 0.1 um. The base pitch deviation is the single pitch one projected on the base circle,
// f_pb = f_pt cos(alpha_t) (ISO/TR 10064-1).
struct Iso1328Tolerances {
  double m_class = 0, d_class = 0;   // the geometric means used [mm]
  double f_pt = 0;                   // [um]
  double f_f_alpha = 0;              // [um]
};
// std::domain_error when m_n or d lie outside the ranges above or Q outside 1..12.
Iso1328Tolerances iso1328_tolerances(int grade, double m_n_mm, double d_mm);
double iso1328_round(double value_um);

}  // namespace gearhb
