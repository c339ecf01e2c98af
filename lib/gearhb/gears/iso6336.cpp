#include "gearhb/gears/iso6336.hpp"

#include <cmath>
#include <stdexcept>

namespace gearhb {

Iso6336Stiffness iso6336_mesh_stiffness(int z1, int z2, double x1, double x2, double pressure_angle_deg,
                                        double hfP_over_mn, double eps_alpha, double face_width_m,
                                        double line_load_N_per_mm) {
  if (z1 <= 0 || z2 <= 0 || !(face_width_m > 0) || !(eps_alpha > 0))
    throw std::invalid_argument("iso6336_mesh_stiffness: invalid gear data");
  const double C[9] = {0.04723, 0.15551, 0.25791, -0.00635, -0.11654,
                       -0.00193, -0.24188, 0.00529, 0.00182};
  Iso6336Stiffness s;
  // Spur gears: the virtual tooth numbers are the tooth numbers.
  const double zn1 = z1, zn2 = z2;
  s.q_prime = C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 / zn1 + C[4] * x2 / zn2 + C[5] * x1 +
              C[6] * x2 + C[7] * x1 * x1 + C[8] * x2 * x2;
  s.c_th = 1.0 / s.q_prime;
  s.C_B = (1.0 + 0.5 * (1.2 - hfP_over_mn)) * (1.0 - 0.02 * (20.0 - pressure_angle_deg));
  if (line_load_N_per_mm > 0.0 && line_load_N_per_mm < 100.0)
    s.load_factor = std::pow(line_load_N_per_mm / 100.0, 0.25);
  s.c_single = s.c_th * s.C_M * s.C_R * s.C_B * s.load_factor;   // cos(beta) = 1 (spur)
  s.c_gamma_alpha = s.c_single * (0.75 * eps_alpha + 0.25);
  const double b_mm = face_width_m * 1e3;
  // N/(mm um) * mm = N/um = 1e6 N/m.
  s.c_single_total = s.c_single * b_mm * 1e6;
  s.c_gamma_alpha_total = s.c_gamma_alpha * b_mm * 1e6;
  return s;
}

}  // namespace gearhb
