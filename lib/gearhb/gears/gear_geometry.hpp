#pragma once
// Involute spur-gear geometry for the static transmission error (thesis ch. 7).
//
// A standard (unshifted) involute spur gear of module m, z teeth and pressure
// angle alpha has
//
//     pitch radius    r   = m z / 2
//     base radius     rb  = r cos(alpha)
//     tip radius      ra  = r + ha            (ha: addendum)
//     root radius     rf  = r - hf            (hf: dedendum)
//     base pitch      pb  = 2 pi rb / z = pi m cos(alpha)
//     involute        inv(a) = tan(a) - a,    a(r) = acos(rb / r)
//
// Two gears meshing at the standard centre distance r1 + r2 touch along the
// line of action T1-T2 (tangent to both base circles, T_i the tangency points).
// Contact starts at A, where the tip circle of the driven gear 2 cuts T1T2, and
// ends at E, where the tip circle of the driver 1 cuts it; C is the pitch point:
//
//     T1C = r1 sin(alpha) = rb1 tan(alpha),    T1E = sqrt(ra1^2 - rb1^2),
//     T2A = sqrt(ra2^2 - rb2^2),               CE = T1E - T1C,  AC = T2A - T2C,
//     contact ratio  eps_alpha = (AC + CE) / pb.
//
// A point P of AE at distance T1P from T1 lies on the involute of gear 1 at
// radius r1(P) = sqrt(rb1^2 + T1P^2) (and likewise for gear 2 with T2P): the
// radius at which that contact point meets each tooth.
//
// Tooth thickness on the circle of radius r (thesis §7.5; standard
// involute relation, e.g. Niemann & Winter, Maschinenelemente II, §21):
//
//     s(r) = r s0 / r0 + 2 r [inv(alpha0) - inv(a(r))],   s0 = pi m / 2.
//
// All lengths in metres, angles in radians unless a name says _deg.
#include <string>

namespace gearhb {

struct GearGeometry {
  double module = 3e-3;            // m [m]
  int teeth = 50;                  // z
  double pressure_angle_deg = 20;  // alpha0 [deg]
  double addendum = 3e-3;          // ha [m]
  double dedendum = 3.75e-3;       // hf [m]
  double face_width = 0.02;        // b [m]

  double pressure_angle_rad() const;   // alpha0 [rad]
  double pitch_radius() const;     // r0 = m z / 2
  double base_radius() const;      // rb = r0 cos(alpha0)
  double tip_radius() const;       // ra = r0 + ha
  double root_radius() const;      // rf = r0 - hf
  double base_pitch() const;       // pb = pi m cos(alpha0)
  double tooth_height() const;     // ha + hf (the beam length of the tooth model)
};

// inv(a) = tan(a) - a.
double involute(double a);
// Pressure angle of the involute at radius r >= rb: acos(rb / r).
double pressure_angle_at(const GearGeometry& g, double r);
// Tooth thickness s(r) (chordless arc thickness, formula above). Needs r >= rb.
double tooth_thickness(const GearGeometry& g, double r);

// Path of contact of two gears at the standard centre distance.
struct PathOfContact {
  double T1T2 = 0;            // length of the line of action between tangency points
  double T1C = 0, T2C = 0;    // tangency point to pitch point (rb tan(alpha))
  double T1A = 0, T1E = 0;    // start A and end E of contact, measured from T1
  double AC = 0, CE = 0, AE = 0;
  double base_pitch = 0;
  double contact_ratio = 0;   // AE / pb
};
PathOfContact path_of_contact(const GearGeometry& g1, const GearGeometry& g2);

// Radius at which the point of AE at distance `s_from_A` from A meets the
// tooth of gear 1 (driver) and of gear 2 (driven).
struct ContactRadii {
  double r1 = 0, r2 = 0;
};
ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, double s_from_A);

// Thesis §7.7: angle between the tooth axis and the normal to the path of
// contact, at the two extreme positions of the tooth axis (through E and
// through A). With the segment lengths of the lower gear (2):
//
//     T2E  = T2C - CE,           beta    = alpha - atan(T2E / rb),
//     eps  = atan((T2C + AC) / rb) - alpha,
//     variation = [cos(alpha - beta) - cos(alpha + eps)] / cos(alpha + eps).
//
// The thesis prints T2C = rb sin(alpha) = 0.0241 m; the correct distance is
// rb tan(alpha) = r sin(alpha) = 0.0257 m (chapters/ch07_ste/README.md, "Thesis
// errors"). Both are offered.
enum class T2CFormula {
  thesis_rb_sin,   // T2C = rb sin(alpha) (as printed, wrong)
  rb_tan           // T2C = rb tan(alpha) (correct)
};
struct ToothAxisAngles {
  double rb = 0, AC = 0, CE = 0, T2C = 0, T2E = 0;   // the inputs actually used [m]
  double beta = 0, epsilon = 0;                      // [rad]
  double cos_alpha_minus_beta = 0, cos_alpha_plus_epsilon = 0;
  double force_variation = 0;                        // fraction (0.069 = 6.9 %)
};
// `round_like_thesis`: round rb to 0.1 mm and AC, CE, T2C, T2E to 0.1 mm before
// use, as the thesis did with its printed intermediate values (rb = 0.0705 m,
// AC = CE = 0.0078 m, T2C = 0.0241 m, T2E = 0.0163 m).
ToothAxisAngles tooth_axis_angles(const GearGeometry& g, const PathOfContact& path,
                                  T2CFormula formula, bool round_like_thesis);

// What the involute beam tooth model of thesis ch. 7 needs of a pair of identical
// gears: the root circle outside the base circle (s(r) exists only for r >= rb),
// a tooth that is not pointed (s(ra) > 0), and a contact ratio between 1 and 2
// (one or two pairs in contact, never none or three). Returns "" when g meets all
// three, otherwise the first one it misses, in words with the numbers.
std::string involute_tooth_model_problem(const GearGeometry& g);

// The values of one field of GearGeometry (the others held fixed) for which
// involute_tooth_model_problem is "", searched in [lo, hi] (whole numbers if
// `integer`): every condition is monotone in each field, so the admissible set is
// one interval [*from, *to]. `set` writes the field. False if no value admits.
bool admissible_interval(const GearGeometry& g, void (*set)(GearGeometry&, double), double lo,
                         double hi, bool integer, double* from, double* to);

}  // namespace gearhb
