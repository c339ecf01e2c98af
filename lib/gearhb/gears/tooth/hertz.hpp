#pragma once
// Hertzian approach of two steel cylinders in line contact (thesis §7.3, §7.5):
// the Palmgren formula,
//
//     delta [mm] = 3.84e-5 * F[N]^0.9 / L[mm]^0.8,
//
// F the normal contact force, L the length of the line of contact (the face
// width; the smaller one if the gears differ). Source: A. Palmgren, Ball and
// Roller Bearing Engineering (SKF, 3rd ed. 1959); quoted in T. A. Harris,
// Rolling Bearing Analysis, eq. for the line-contact deformation of steel
// bodies. The formula is semi-empirical and dimensional: it is valid only in
// the units above, so the function converts explicitly from and to SI.
//
// delta is the TOTAL approach of the two bodies (both surfaces together): one
// term per contact. The thesis adds it per tooth (twice per contact); which
// reading the chapter uses is its choice, documented there.
namespace gearhb {

// Approach [m] for force [N] >= 0 and contact length [m] > 0. F = 0 gives 0.
double palmgren_line_contact_approach(double force_N, double length_m);

// d delta / d F [m/N] (for Newton iterations on a force split).
double palmgren_line_contact_compliance(double force_N, double length_m);

}  // namespace gearhb
