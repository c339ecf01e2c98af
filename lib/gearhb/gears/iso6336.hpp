#pragma once
// Mesh stiffness of spur gears by ISO 6336-1:2006, clause 9 (Method B), the
// estimate a gear engineer would use beside the beam model of thesis ch. 7.
//
// Theoretical single stiffness of one tooth pair (solid disc gears, x = 0 here
// but the profile-shift terms are kept), per unit face width [N/(mm um)]:
//     1 / c'_th = q' = C1 + C2/zn1 + C3/zn2 + C4 x1/zn1 + C5 x2/zn2
//                      + C6 x1 + C7 x2 + C8 x1^2 + C9 x2^2      [mm um / N]
//     C1..C9 = 0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
//              -0.00193, -0.24188, 0.00529, 0.00182   (ISO 6336-1 Table 9;
//     the same constants as DIN 3990-1).
// Single stiffness       c' = c'_th C_M C_R C_B cos(beta)
//     C_M = 0.8 (correction between measured and theoretical values),
//     C_R = 1 (solid gear blanks),
//     C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_n)] (basic rack),
// Mesh stiffness (mean over the mesh, spur gears)
//     c_gamma_alpha = c' (0.75 eps_alpha + 0.25).
// Valid for a line load F_t K_A / b >= 100 N/mm; below that ISO multiplies c'
// by (F_t K_A / b / 100)^0.25, which `line_load_N_per_mm` applies.
// Multiply by the face width b [mm] to get a stiffness in N/um = MN/m.
namespace gearhb {

struct Iso6336Stiffness {
  double q_prime = 0;          // [mm um / N]
  double c_th = 0;             // c'_th [N/(mm um)]
  double C_M = 0.8, C_R = 1.0, C_B = 1.0, load_factor = 1.0;
  double c_single = 0;         // c' [N/(mm um)]
  double c_gamma_alpha = 0;    // [N/(mm um)]
  double c_single_total = 0;   // c' b [N/m]
  double c_gamma_alpha_total = 0;   // c_gamma_alpha b [N/m]
};

// z1, z2 teeth; x1, x2 profile shift coefficients; pressure_angle_deg alpha_n [deg];
// h_fP / m_n the basic-rack dedendum over module; eps_alpha the contact ratio;
// face width b [m]; line_load F_t / b [N/mm] (<= 0: take the >= 100 N/mm branch).
Iso6336Stiffness iso6336_mesh_stiffness(int z1, int z2, double x1, double x2, double pressure_angle_deg,
                                        double hfP_over_mn, double eps_alpha, double face_width_m,
                                        double line_load_N_per_mm);

}  // namespace gearhb
