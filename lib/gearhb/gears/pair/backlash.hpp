#pragma once
// Backlash and the static transmission error it limits (thesis §9).
//
// Normal backlash. The nominal backlash b is measured circumferentially, along the
// pitch circle; the thesis scales it onto the line of action AE,
//
//     b_n = b cos(mu),    mu = angle between the circumferential direction and AE.
//
//  * at the pitch point C: mu = alpha, b_n = b cos(alpha) (the largest);
//  * at E', the end of the single-pair zone (CE' = pb - AC, pb = pi d_b / z), the
//    adjacent pair is at A, and the thesis takes
//        mu(E') = alpha + eps + eps',  eps  = atan((T2C + AC) / rb) - alpha   (§7.7),
//                                      eps' = atan(CE' / rb);
//    A' mirrors E' (CA' = pb - CE, the adjacent pair at E; eps from CE instead of AC).
//
// The thesis gives mu only at C and E'. Reading `roll` (ours, chapters/ch09_backlash/
// README.md): mu grows with the roll angle of the gear from C. For a point P of AE
// the angle between the circumferential direction at P and AE is exactly
// atan(TP / rb) = alpha + theta(P), theta(P) = angle C O P (right triangle O T P, T
// the tangency point on the far side of C), so
//
//     mu(P) = alpha + (mu(E') - alpha) theta(P) / theta(E')       (E' side; A' alike)
//
// which is alpha at C and the thesis' value at E' (and at A').
// Reading `involute`: mu = alpha everywhere. Two involutes of one base circle are
// parallel curves (their normal distance is the arc between them on the base
// circle), so for ideal involute teeth the backlash along the line of action is
// b rb / r = b cos(alpha) at every contact point: the physics.
//
// `BacklashValues::thesis_printed`: eps from the printed T2C = rb sin(alpha) with the
// lengths rounded to 0.1 mm as §7.7 prints them (4.35 deg), eps' from CE' rounded
// to 0.1 mm over the unrounded rb (gives the printed 0.8942 deg). `exact`: the
// geometry of path_of_contact (T2C = rb tan(alpha)), nothing rounded.
//
// The STE with backlash, in the single-pair zone A'E' (two-pair points unchanged):
//  * clip (the thesis' reading): ste = min(ste, b_n(P));
//  * contact: the adjacent pair is a unilateral spring that engages once the
//    deflection d closes b_n,  F = k1 d + k2 max(d - b_n, 0),  k1 = F / ste(P) the
//    secant stiffness of the loaded pair, k2 = F / ste_single(Q) the secant
//    stiffness of the adjacent pair as a single pair at the end Q of the path of
//    contact nearer to it (E' side: A, where the incoming pair enters; A' side: E),
//    where it touches first (the tip of the tooth that has not reached the path).
//    Solved in closed form (two_spring_deflection).
#include <vector>

#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

namespace gearhb {

enum class BacklashValues { thesis_printed, exact };
enum class BacklashAngle { roll, involute };
enum class BacklashModel { clip, contact };

// b cos(mu).
double normal_backlash(double b, double mu);

struct BacklashGeometry {
  double b = 0.0;                    // nominal backlash [m]
  double alpha = 0.0, rb = 0.0, pb = 0.0, T2C = 0.0, AC = 0.0, CE = 0.0, AE = 0.0;   // exact geometry
  double CE_prime = 0.0, CA_prime = 0.0;   // pb - AC, pb - CE (as used: rounded for thesis_printed)
  double epsilon = 0.0, epsilon_prime = 0.0;           // E' side [rad]
  double epsilon_A = 0.0, epsilon_prime_A = 0.0;       // A' side [rad]
  double mu_C = 0.0, mu_E_prime = 0.0, mu_A_prime = 0.0;   // [rad]
  double bn_C = 0.0, bn_E_prime = 0.0, bn_A_prime = 0.0;   // [m]
  double s_A_prime = 0.0, s_E_prime = 0.0;   // the single-pair zone, distance from A [m] (exact)
};
// Identical gears g at the standard centre distance.
BacklashGeometry backlash_geometry(const GearGeometry& g, double b, BacklashValues values);

// mu at the contact point s from A (s in the single-pair zone) [rad].
double backlash_angle(const BacklashGeometry& bg, double s, BacklashAngle reading);

// F = k1 d + k2 max(d - bn, 0) for d (the adjacent spring engages once d > bn).
struct TwoSpringSolution {
  double d = 0.0, force_1 = 0.0, force_2 = 0.0;
  bool engaged = false;
};
TwoSpringSolution two_spring_deflection(double F, double k1, double k2, double bn);

struct BacklashSettings {
  double b = 15e-6;   // nominal backlash [m] (thesis §9)
  BacklashModel model = BacklashModel::clip;
  BacklashAngle angle = BacklashAngle::roll;
  BacklashValues values = BacklashValues::thesis_printed;
};

struct BacklashPoint {
  double phase = 0.0, s = 0.0;   // mesh phase, loaded contact point from A [m]
  int pairs = 1;
  double ste_free = 0.0;         // STE without backlash [m]
  double bn = 0.0;               // local normal backlash [m] (single-pair points; 0 for two pairs)
  double ste = 0.0;              // STE with backlash [m]
  double adjacent_force = 0.0;   // force on the adjacent pair [N] (contact reading; 0 for the clip)
  bool limited = false;          // the backlash changed this point
};
// Over the continuous STE (ste_continuous) or ch. 7's positions (ste_over_mesh_cycle)
// of model m at torque T [N m].
std::vector<BacklashPoint> ste_with_backlash(const SteModel& m, double torque, const std::vector<StePoint>& cycle,
                                             const BacklashSettings& set);
std::vector<BacklashPoint> ste_with_backlash(const SteModel& m, double torque,
                                             const std::vector<MeshPosition>& cycle, const BacklashSettings& set);

std::vector<double> ste_values(const std::vector<BacklashPoint>& cycle);

}  // namespace gearhb
