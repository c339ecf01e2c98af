#pragma once
// The transverse tooth form of an EXTERNAL spur gear as the basic rack cuts it
// (hobbing or rack-type generation), for meshing the real tooth (issue 33 §1).
// Internal gears (a ring cut by a pinion-type cutter) are NOT supported: they need the
// envelope of the cutter's involute and tip circle in the cutter/ring motion (two
// rolling circles instead of circle and line), which this file does not yet have.
//
// Coordinates: the gear centre at the origin, the centre line of the tooth along +y, x to
// the right. A point of radius R and polar angle psi, measured from +y and positive toward
// +x (clockwise), is (x, y) = R (sin psi, cos psi). The right flank (x > 0) is computed; the
// left one is its mirror image x -> -x. Lengths in metres, angles in radians.
//
// Gear (ISO 21771; gear_geometry.hpp): z, m, alpha, x, r = m z / 2, rb = r cos(alpha),
// ra = r + ha + x m, rf = r - hf + x m, inv(a) = tan(a) - a. The basic rack has the
// addendum hf (the gear's dedendum), the tip radius rho = rho_f* m, the pitch p = pi m.
//
// 1. Involute (Niemann & Winter, Maschinenelemente II, §21; ISO 21771). Half the tooth
//    angle at the base circle theta_b = (pi/2 + 2 x tan(alpha)) / z + inv(alpha); the right
//    flank's point of radius R >= rb and pressure angle a_y = acos(rb / R) has
//        psi(R) = theta_b - inv(a_y).
//    By its roll length xi = sqrt(R^2 - rb^2) = rb tan(a_y): the involute leaves the base
//    circle at psi_B = theta_b - xi / rb, B = rb e(psi_B), and
//        P(xi) = B + xi n,   n = (cos psi_B, -sin psi_B)   (unit outward normal),
//    e(psi) = (sin psi, cos psi): the normal is the tangent to the base circle at B (the
//    line of action), dP/dxi = (xi / rb) e(psi_B).
//
// 2. Tip relief (a profile modification; TipRelief, tip_relief_at in gear_geometry.hpp):
//    material C(xi) removed along the involute's normal,
//        P_C(xi) = P(xi) - C(xi) n,   |P_C| = sqrt(rb^2 + (xi - C)^2),
//    outward normal  n_C ~ ((xi - C) / rb) n + C'(xi) e(psi_B)  (normalised), from
//    dP_C/dxi = ((xi - C) / rb) e(psi_B) - C' n. The relieved flank meets the tip circle
//    where xi - C(xi) = sqrt(ra^2 - rb^2). The relief at a point is its normal distance from
//    the involute: rb times the polar-angle deficit at the same radius.
//
// 3. Generation (F. L. Litvin, A. Fuentes, Gear Geometry and Applied Theory, 2nd ed. 2004,
//    ch. 6 "Generation of planar gears by a rack-cutter" and ch. 4 (envelopes); the
//    trochoid form also in ISO 6336-3 §6). The rack's generating line (parallel to its
//    datum line and x m nearer the gear centre) rolls without slip on the pitch circle r.
//    At rolling angle tau the rack touches the pitch circle at
//    I(tau) = r e(tau), turned by tau with it: a rack point (u, v) (u along its datum line,
//    u = 0 in the middle of the rack space that forms our tooth; v away from the gear, v = 0
//    on the datum, which lies x m outside the pitch circle) is at
//        X(u, v; tau) = R(tau) (u - r tau, r + x m + v),
//        R(tau) (a, b) = (a cos tau + b sin tau, -a sin tau + b cos tau)   (clockwise turn).
//    The rack tooth to the right of ours has its flank u = p/4 - v tan(alpha) and its tip
//    line v = -hf; the tip rounding, tangent to both, has its centre at
//        u_c = p/4 + (hf - rho) tan(alpha) + rho / cos(alpha),   v_c = -(hf - rho)
//    (u_c <= p/2: the rounding fits the rack tooth). The rounding touches the flank at the
//    depth h_T = hf - rho (1 - sin(alpha)) - x m below the generating line.
//    Envelope (the fundamental law of gearing: the contact normal passes through the
//    instantaneous centre I): with eta = hf - rho - x m > 0 the depth of the rounding centre
//    below the generating line and lambda = u_c - r tau its lateral offset from I,
//        C(tau) = R(tau) (lambda, r - eta),
//        F(lambda) = R(tau) (lambda (1 + rho / L), r - eta (1 + rho / L)),
//        L = sqrt(lambda^2 + eta^2),   tau = (u_c - lambda) / r,
//    the root fillet (a trochoid's parallel curve), outward normal R(tau) (-lambda, eta) / L.
//    lambda = 0 gives the root circle at psi = theta_f = u_c / r (tangentially: the normal is
//    radial there); lambda_j = -eta / tan(alpha) is the rounding's tangent point with the
//    flank, generating the involute at the roll length
//        xi_j = r sin(alpha) - h_T / sin(alpha)        (ISO 21771 d_Ff).
// 4. Undercut (Niemann & Winter §21.2; undercut_limit_teeth): when xi_j < 0, i.e.
//        hf* - rho* (1 - sin(alpha)) - x > z sin^2(alpha) / 2,
//    the rack's straight flank reaches below the base-circle tangent point T and the
//    trochoid cuts into the involute. The form is then the trochoid from the root circle up
//    to its first crossing with the involute (found numerically from the root side) and the
//    involute above it: a corner there, and the form circle r_Ff above the base circle.
//    Without undercut the fillet joins the involute tangentially at r_Ff = sqrt(rb^2 + xi_j^2).
// 5. Tip: the tip circle ra (the turned blank) between the two flanks, optionally with a
//    tip rounding of radius r_k: the circle of radius r_k tangent to the (relieved) flank
//    and, from inside, to the tip circle (centre M with |M| = ra - r_k). Tip chamfers are
//    not supported.
//
// Supported: profile shift with hf* - rho* - x > 0 (the rounding centre below the
// generating line) and u_c <= p/2; rho* >= 0 (0: a sharp rack corner, the fillet is the
// corner's trochoid); tip relief of any TipRelief shape starting at or above the form circle.
#include <Eigen/Core>
#include <vector>

#include "gearhb/gears/geometry/gear_geometry.hpp"

namespace gearhb {

enum class ToothSegment : int { root, fillet, involute, relief, rounding, tip };
const char* tooth_segment_name(ToothSegment s);

struct ToothFormOptions {
  double root_radius_coefficient = 0.38;   // rho_f* of the basic rack (rho = rho_f* m)
  TipRelief relief;                        // amount 0: none (gear_geometry.hpp, tip_relief)
  double tip_rounding_radius = 0.0;        // r_k [m], 0: a sharp tip edge
  double spacing = 0.0;                    // distance between points [m] (about; each segment equally divided); 0: m / 50
};

// One tooth, ordered from the left root-circle midpoint between teeth (polar angle -pi/z)
// over the tip to the right one (+pi/z): clockwise. Points are not repeated: a point where
// two segments meet carries the label (and the one-sided normal) of the segment nearer the
// tip, so the involute's first point lies on the form circle. `parameter` is, for the point
// or (left flank) its mirror image: root, tip: psi; fillet: the rolling angle tau of the
// generating position; involute, relief: the roll length xi of its foot on the involute;
// rounding: the angle of its normal from +y.
struct ToothForm {
  int teeth = 0;
  double module = 0;
  std::vector<Eigen::Vector2d> points, normals;   // normals: unit, outward (into the space)
  std::vector<ToothSegment> segment;
  std::vector<double> parameter;
  double root_radius = 0;           // r_f
  double base_radius = 0;           // r_b
  double form_radius = 0;           // r_Ff: where the involute begins (junction or undercut cut)
  double form_roll = 0;             // xi_Ff = sqrt(r_Ff^2 - rb^2)
  double tip_radius = 0;            // r_a
  double relief_start_radius = 0;   // r_Ca (0: no relief)
  double rounding_start_radius = 0; // where the tip rounding leaves the flank (0: none)
  double fillet_root_angle = 0;     // theta_f = u_c / r: where the fillet meets the root circle
  bool undercut = false;
};

// The generated form (sections 1-5). Throws std::invalid_argument for a gear outside the
// supported range (see above), a pointed tooth, a relief starting below the form circle or
// a tip rounding that does not fit.
ToothForm tooth_form(const GearGeometry& g, const ToothFormOptions& options = {});

// Teeth of the gear as one polyline: tooth k is tooth_form's tooth turned clockwise by
// 2 pi k / z (so it follows tooth k - 1 in the clockwise order).
struct FormPolyline {
  std::vector<Eigen::Vector2d> points, normals;
  std::vector<ToothSegment> segment;
  std::vector<int> tooth;
  bool closed = false;   // true: the last point joins the first
};
// Teeth first .. first + count - 1 (count <= z), open, from the left root midpoint of the
// first tooth to the right root midpoint of the last (shared midpoints once).
FormPolyline form_sector(const ToothForm& form, int first, int count);
// All z teeth, closed (clockwise): the outline a mesher takes.
FormPolyline gear_outline(const ToothForm& form);

}  // namespace gearhb
