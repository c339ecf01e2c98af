#pragma once
// Involute spur-gear geometry for the static transmission error (thesis ch. 7).
//
// An involute spur gear of module m, z teeth, pressure angle alpha and profile
// shift coefficient x (ISO 21771; x = 0 in the thesis) has
//
//     pitch radius    r   = m z / 2
//     base radius     rb  = r cos(alpha)
//     tip radius      ra  = r + ha + x m      (ha: addendum = ha* m)
//     root radius     rf  = r - hf + x m      (hf: dedendum = hf* m)
//     base pitch      pb  = 2 pi rb / z = pi m cos(alpha)
//     involute        inv(a) = tan(a) - a,    a(r) = acos(rb / r)
//
// (no tip shortening: ra as above, as ISO 21771 eq. for the tip diameter with
// k = 0; the FZG type C tip radii 41.318 / 59.272 mm follow from it).
//
// Two gears mesh at the centre distance a; the shifts imply (ISO 21771)
//
//     inv(alpha_w) = inv(alpha) + 2 tan(alpha) (x1 + x2) / (z1 + z2),
//     a = (rb1 + rb2) / cos(alpha_w),
//
// and a given a fixes cos(alpha_w) = (rb1 + rb2) / a. The gears touch along the
// line of action T1-T2 (tangent to both base circles, T_i the tangency points,
// T1T2 = a sin(alpha_w)). Contact starts at A, where the tip circle of the driven
// gear 2 cuts T1T2, and ends at E, where the tip circle of the driver 1 cuts it;
// C is the pitch point (operating pitch radii rw_i = rb_i / cos(alpha_w)):
//
//     T1C = rb1 tan(alpha_w),                  T1E = sqrt(ra1^2 - rb1^2),
//     T2A = sqrt(ra2^2 - rb2^2),               CE = T1E - T1C,  AC = T2A - T2C,
//     contact ratio  eps_alpha = (AC + CE) / pb,
//     B = E - pb (single contact begins), D = A + pb (single contact ends):
//     A-B and D-E carry two pairs, B-D one (for 1 < eps_alpha < 2).
//
// A point P of AE at distance T1P from T1 lies on the involute of gear 1 at
// radius r1(P) = sqrt(rb1^2 + T1P^2) (and likewise for gear 2 with T2P): the
// radius at which that contact point meets each tooth.
//
// Tooth thickness on the circle of radius r (thesis §7.5; standard
// involute relation, e.g. Niemann & Winter, Maschinenelemente II, §21; ISO 21771
// for the shift):
//
//     s(r) = r s0 / r0 + 2 r [inv(alpha0) - inv(a(r))],   s0 = m (pi/2 + 2 x tan(alpha0)).
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
  double profile_shift = 0.0;      // x (ISO 21771; positive away from the centre)

  double pressure_angle_rad() const;   // alpha0 [rad]
  double pitch_radius() const;     // r0 = m z / 2
  double base_radius() const;      // rb = r0 cos(alpha0)
  double tip_radius() const;       // ra = r0 + ha + x m
  double root_radius() const;      // rf = r0 - hf + x m
  double base_pitch() const;       // pb = pi m cos(alpha0)
  double tooth_height() const;     // ha + hf (the beam length of the tooth model)
};

// inv(a) = tan(a) - a.
double involute(double a);
// Pressure angle of the involute at radius r >= rb: acos(rb / r).
double pressure_angle_at(const GearGeometry& g, double r);
// Tooth thickness s(r) (chordless arc thickness, formula above). Needs r >= rb.
double tooth_thickness(const GearGeometry& g, double r);

// The inverse of inv(a) = tan(a) - a on [0, pi/2) (Newton from the series
// a ~ (3 v)^(1/3), to machine precision). v >= 0.
double inverse_involute(double v);

// Operating pressure angle alpha_w [rad] and centre distance a [m] of two gears:
// `centre_distance` > 0 given (cos(alpha_w) = (rb1 + rb2) / a), or 0 for the one
// the shifts imply (formula above; x1 + x2 = 0 gives alpha_w = alpha exactly).
// Throws std::invalid_argument when the gears do not share module and pressure
// angle or a is below rb1 + rb2.
struct OperatingMesh {
  double centre_distance = 0;        // a [m]
  double pressure_angle = 0;         // alpha_w [rad]
  double pitch_radius1 = 0, pitch_radius2 = 0;   // rw_i = rb_i / cos(alpha_w) [m]
};
OperatingMesh operating_mesh(const GearGeometry& g1, const GearGeometry& g2, double centre_distance = 0.0);

// Path of contact of two gears (gear 1 drives) at the centre distance of
// operating_mesh(g1, g2, centre_distance).
struct PathOfContact {
  double T1T2 = 0;            // length of the line of action between tangency points
  double T1C = 0, T2C = 0;    // tangency point to pitch point (rb tan(alpha_w))
  double T1A = 0, T1E = 0;    // start A and end E of contact, measured from T1
  double T1B = 0, T1D = 0;    // B = E - pb, D = A + pb (single-pair zone B-D when eps < 2)
  double AC = 0, CE = 0, AE = 0;
  double base_pitch = 0;
  double contact_ratio = 0;   // AE / pb
  OperatingMesh mesh;         // a, alpha_w, rw1, rw2
};
PathOfContact path_of_contact(const GearGeometry& g1, const GearGeometry& g2, double centre_distance = 0.0);

// Radius at which the point of AE at distance `s_from_A` from A meets the
// tooth of gear 1 (driver) and of gear 2 (driven).
struct ContactRadii {
  double r1 = 0, r2 = 0;
};
ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, double s_from_A);
ContactRadii contact_radii(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& path,
                           double s_from_A);

// Normal backlash (along the line of action) of two gears at the pair's centre
// distance, from the tooth-thickness allowances A_s1, A_s2 on the reference circles
// (<= 0: thinner teeth; DIN 3967 / ISO 21771 vocabulary). Exact for involutes: with
// s_i = m (pi/2 + 2 x_i tan alpha) + A_si, the space left on the operating pitch circle
// p_w - s_w1 - s_w2, times cos(alpha_w), is
//     j_n = m cos(alpha) [(z1 + z2)(inv alpha_w - inv alpha) - 2 tan(alpha)(x1 + x2)]
//           - (A_s1 + A_s2) cos(alpha),
// the bracket vanishing at the centre distance the shifts imply (then
// j_n = -(A_s1 + A_s2) cos alpha). Negative: the teeth would interpenetrate.
double normal_backlash(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& path,
                       double thickness_allowance1, double thickness_allowance2);

// Undercut by the generating rack (ISO 21771, Niemann & Winter §21.2): the rack's
// straight flank reaches h* = hf* - rho_f* (1 - sin(alpha)) (in module units) below
// the pitch line, so the involute is undercut when
//     z < z_min = 2 (h* - x) / sin^2(alpha)
// (hf* = 1.25, rho_f* = 0.38, x = 0: z_min = 17.1, the textbook limit).
double undercut_limit_teeth(double dedendum_coefficient, double root_radius_coefficient,
                            double profile_shift, double pressure_angle_deg);

// Tip relief of one gear (ISO 21771 / KISSsoft vocabulary): the profile is cut
// back by C(P) = Ca ((xi - xi_S) / (xi_a - xi_S))^n beyond its start, xi the roll
// length sqrt(r^2 - rb^2) of the contact point on that gear's involute, xi_S the
// start, xi_a the tip's; n = 1 linear, 2 parabolic. Zero below the start.
enum class ReliefShape : int { linear = 1, parabolic = 2 };
struct TipRelief {
  double amount = 0.0;        // Ca [m] at the tip circle (0: no relief)
  double start_roll = 0.0;    // xi_S [m]: roll length of the start point from T_i
  double tip_roll = 0.0;      // xi_a [m]: roll length of the tip circle, sqrt(ra^2 - rb^2)
  ReliefShape shape = ReliefShape::linear;
};
// Ca at the roll length xi (distance from T_i along the line of action) [m].
double tip_relief_at(const TipRelief& relief, double roll);
// Its slope dCa/dxi (one-sided from above at the start; 0 beyond the tip roll, where
// tip_relief_at holds Ca).
double tip_relief_slope(const TipRelief& relief, double roll);
// How the start may be given: roll angle xi_S / rb [deg], diameter d_Ca [m], or
// length L_Ca along the path of contact measured from the tip end [m].
enum class ReliefStart { roll_angle_deg, diameter, length };
// Roll length of the start from the given value (no checks beyond finiteness;
// a diameter inside the base circle gives -1).
double relief_start_roll(const GearGeometry& g, ReliefStart kind, double value);
// The relief of gear g: amount Ca [m], start as `kind` says, tip_roll of g's tip circle.
TipRelief tip_relief(const GearGeometry& g, double amount, ReliefStart kind, double start, ReliefShape shape);

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

// The checks a gear pair from a drawing must pass before its STE is computed,
// each with the key of the gear-pair file it names (`key`, "" when all pass) and
// a sentence with the numbers (`why`):
//   * each pointed tip: s(ra) >= 0.2 m (the usual minimum tip thickness of
//     Niemann & Winter §21.2 / DIN 3960 practice; key gears.<i>.x);
//   * tip/root clearance a - ra1 - rf2 > 0 and a - ra2 - rf1 > 0 (key centre_distance);
//   * involute interference: A and E between T1 and T2 (the tip of one gear meets the
//     other on its involute, not inside its base circle; key gears.<i>.z);
//   * contact ratio >= 1 (key gears);
//   * each relief: 0 <= amount, start above the base circle and inside the path
//     of contact on that gear (xi_S >= the roll length of the first contact point;
//     key gears.<i>.tip_relief).
// Gear index i: 0 = driver (gear 1), 1 = driven (gear 2).
struct GeometryProblem {
  std::string key, why;
};
constexpr double min_tip_thickness_per_module = 0.2;
GeometryProblem gear_pair_problem(const GearGeometry& g1, const GearGeometry& g2, const PathOfContact& path,
                                  const TipRelief& relief1, const TipRelief& relief2);

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
