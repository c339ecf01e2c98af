#pragma once
// Mesh stiffness of one spur tooth pair by the potential-energy (energy) method, the
// second model of issue 20 beside the beam model of thesis ch. 7. Pure functions of
// plain scalars: the load sharing over the mesh cycle (which pairs touch, tip-relief
// separations) belongs to the caller; this file gives the stiffness of ONE pair as a
// function of the two contact radii.
//
// Geometry of a tooth (external spur gear, rack-generated; Niemann & Winter,
// Maschinenelemente II, §21; ISO 21771). z teeth, module m, pressure angle alpha0,
// profile shift x, basic rack ha*, hf*, rho_f* (in units of m):
//     r0 = m z / 2,  rb = r0 cos(alpha0),  ra = r0 + m (ha* + x),  rf = r0 - m (hf* - x),
//     half tooth angle at the base circle   theta_b = (pi/2 + 2 x tan(alpha0)) / z + inv(alpha0),
//     involute point of pressure angle a:   r = rb / cos(a),  theta(a) = theta_b - inv(a),
//                                            x(a) = r cos(theta),  y(a) = r sin(theta),
//     dx/da = (cos(theta) + sin(theta) tan(a)) rb sin(a) / cos^2(a)
// (x along the tooth centre line from the gear centre, y the half thickness; d theta/dr =
// -tan(a)/r). The tooth is a cantilever clamped at the root circle:
//   * rf >= rb (z large enough: z >= 42 for ha* = 1, hf* = 1.25, 20 deg, x = 0): the
//     involute from the root circle (a_f = acos(rb / rf)) to the load; the fillet is not
//     part of the beam (its flexibility is in the fillet-foundation term below);
//   * rf < rb: between root and base circle the flank is a straight line parallel to the
//     centre line at the base-circle half thickness h_b = rb sin(theta_b), from
//     x_f = sqrt(rf^2 - h_b^2) to x_b = rb cos(theta_b) (the usual simplification, e.g.
//     X. Liang, M. J. Zuo, M. Pandey, Mech. Mach. Theory 76 (2014) 20-38), then the
//     involute from the base circle (a = 0).
//
// Load: unit force along the line of action at the contact radius r_c on the involute,
// a_c = acos(rb / r_c), theta_c = theta(a_c), (x_c, y_c) the contact point, load angle
// (between the force and the normal to the centre line)   alpha_m = a_c - theta_c.
// Components F_b = F cos(alpha_m) (bending, shear), F_a = F sin(alpha_m) (compression);
// moment at section x: M(x) = F_b (x_c - x) - F_a y_c. With A(x) = 2 y b, I(x) = (2 y)^3 b / 12
// and the strain energies U = F^2 / (2 k):
//     1/k_b = int_root^x_c [cos(alpha_m) (x_c - x) - sin(alpha_m) y_c]^2 / (E' I(x)) dx
//     1/k_s = int_root^x_c 1.2 cos^2(alpha_m) / (G A(x)) dx          (1.2 = 1/kappa, kappa = 5/6)
//     1/k_a = int_root^x_c sin^2(alpha_m) / (E' A(x)) dx
// D. C. H. Yang, J. Y. Lin, J. Mech. Transm. Autom. Des. 109 (1987) 189-196 (bending,
// axial compression, Hertz); X. Tian, MSc thesis, Univ. of Alberta (2004) (shear added);
// F. Chaari, T. Fakhfakh, M. Haddar, Eur. J. Mech. A/Solids 28 (2009) 461-468 (the same
// integrals with the fillet foundation). The integrals are taken by Gauss-Legendre
// quadrature (GSL glfixed) on each piece of the tooth, in the variable a on the involute
// (smooth there; in r it has a square-root singularity at the base circle) and in x on
// the straight piece.
// E' = E / (1 - nu^2) (plane strain: a face width b much larger than the tooth thickness
// bends as a plate, S. Timoshenko, J. N. Goodier, Theory of Elasticity, §17; the default)
// or E' = E (plane stress, narrow teeth; Tian 2004 writes E, and so does ROSS,
// petrobras/ross gear_mesh_TVMS.py); G = E / (2 (1 + nu)) in both.
//
// Fillet foundation (the gear body under the tooth): P. Sainsot, P. Velex, O. Duverger,
// J. Mech. Des. 126 (2004) 748-752, eq. (11) and Table 1:
//     1/k_f = cos^2(alpha_m) / (E b) [L* (u_f/S_f)^2 + M* (u_f/S_f) + P* (1 + Q* tan^2(alpha_m))]
//     X*(h_f, theta_f) = A/theta_f^2 + B h_f^2 + C h_f/theta_f + D/theta_f + E h_f + F,
//          A          B           C           D           E        F
//     L* -5.574e-5  -1.9986e-3  -2.3015e-4   4.7702e-3   0.0271   6.8045
//     M* 60.111e-5  28.100e-3  -83.431e-4   -9.9256e-3   0.1624   0.9086
//     P* -50.952e-5 185.50e-3    0.0538e-4  53.300e-3    0.2895   0.9236
//     Q* -6.2042e-5   9.0889e-3 -4.0964e-4   7.8297e-3  -0.1472   0.6904
// h_f = rf / r_int (r_int the bore or rim radius), theta_f the half angle of the tooth at
// the root circle, S_f = 2 rf theta_f, u_f = x_c - y_c tan(alpha_m) - rf the distance
// from the root circle to where the line of action cuts the centre line. Fitted on FE
// for 1.4 <= h_f <= 7 and 0.01 <= theta_f <= 0.12 rad (outside: extrapolated, flagged
// by `pe_fillet_in_range`). E is Young's modulus as in the published formula.
// theta_f is, by default, the angle of the point where the rack's tip rounding generates
// the root circle (the fillet centre of the rack, lateral distance from the tooth centre
// line m [pi/4 + (hf* - rho_f*) tan(alpha0) + rho_f* / cos(alpha0)] on the pitch line):
//     theta_f = [pi/2 + 2 (hf* - rho_f*) tan(alpha0) + 2 rho_f* / cos(alpha0)] / z
// (independent of x); `PeRootAngle::beam_root` takes the root half angle of the beam
// above instead (the involute's at rf, or asin(h_b / rf)).
//
// Hertzian contact, linear (independent of the load), Yang & Sun, J. Mech. Transm.
// Autom. Des. 107 (1985) 167-172:
//     1/k_h = 4 (1 - nu^2) / (pi E b)                              (one material)
//           = (2 / (pi b)) [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]       (two materials),
// b the common face width min(b1, b2).
//
// A pair: 1/k = sum over both teeth (1/k_b + 1/k_s + 1/k_a + 1/k_f) + 1/k_h; pairs in
// contact at the same time add as springs in parallel (the caller's part).
// All lengths in metres, angles in radians, compliances in m/N, stiffnesses in N/m.
#include <functional>

namespace gearhb {

struct PeGear {
  int teeth = 50;                         // z
  double module = 3e-3;                   // m [m]
  double pressure_angle = 0.3490658503988659;   // alpha0 [rad] (20 deg)
  double profile_shift = 0;               // x
  double addendum_coefficient = 1.0;      // ha*
  double dedendum_coefficient = 1.25;     // hf*
  double root_radius_coefficient = 0.38;  // rho_f*
  double face_width = 0.02;               // b [m]
  double youngs_modulus = 206e9;          // E [Pa]
  double poisson_ratio = 0.3;             // nu
  double bore_radius = 0;                 // r_int [m] for the fillet foundation (required if it is on)
};

enum class PeElasticity { plane_strain, plane_stress };
enum class PeRootAngle { generated_fillet, beam_root };

struct PeOptions {
  PeElasticity elasticity = PeElasticity::plane_strain;
  PeRootAngle root_angle = PeRootAngle::generated_fillet;
  bool fillet_foundation = true;
  int quadrature_points = 24;   // Gauss-Legendre points per piece of the tooth (24: <= 3e-13 relative, tests)
};

// The radii and angles above for one gear.
struct PeToothGeometry {
  double r0 = 0, rb = 0, ra = 0, rf = 0;
  double theta_b = 0;           // half tooth angle at the base circle
  double a_root = 0;            // pressure angle where the involute part of the beam starts
  double x_root = 0;            // centre-line coordinate of the clamped root section
  double half_thickness_base = 0;   // h_b = rb sin(theta_b)
  bool root_below_base = false; // rf < rb: straight piece from x_root to rb cos(theta_b)
  double theta_f = 0;           // root half angle used by the fillet foundation
  double theta_f_beam = 0;      // root half angle of the beam
  double h_f = 0;               // rf / r_int (0 without a bore radius)
  double r_min_contact = 0;     // lowest radius the load may sit at: max(rb, rf)
};
PeToothGeometry pe_tooth_geometry(const PeGear& g, PeRootAngle root_angle = PeRootAngle::generated_fillet);

// The four parts of one tooth's compliance at contact radius r [m/N].
struct PeToothCompliance {
  double bending = 0, shear = 0, axial = 0, fillet = 0;
  double load_angle = 0;        // alpha_m [rad]
  double u_f = 0, S_f = 0;      // fillet-foundation lengths [m]
  double total() const { return bending + shear + axial + fillet; }
};
// r in [max(rb, rf), ra] (std::domain_error otherwise).
PeToothCompliance pe_tooth_compliance(const PeGear& g, double contact_radius, const PeOptions& o = {});

// One tooth of an INTERNAL gear (a ring; z teeth, module m, alpha0, no profile shift, ha*,
// hf*): its flanks are involutes of the base circle rb = r0 cos(alpha0) with the material on
// the other side, the tooth reaching inwards from the root circle rf = r0 + hf* m to the tip
// circle ra = r0 - ha* m (> rb). Its half angle at radius r (a = acos(rb / r)):
//     psi(a) = pi / (2 z) - inv(alpha0) + inv(a)      (half the pitch angle less the space's,
//                                                      the space being an external tooth's)
// so that the tooth widens towards its root (half thickness pi m / 4 on the pitch circle).
// Along the centre line, x = -r cos(psi) (the distance from the gear centre, negated so that
// x grows from the root to the tip as on an external tooth), y = r sin(psi). A force along the
// line of action at the contact radius r_c (a_c, psi_c) points into the tooth and towards the
// root: its angle with the normal to the centre line is
//     alpha_m = a_c + psi_c          (external: a_c - theta_c)
// (the line of action meets the radius at the contact point at 90 deg - a_c, on the side of
// the tooth's centre line), and the moment at a section is M(x) = F_b (x_c - x) - F_a y_c as
// for the external tooth: the same integrals (pe_beam_integrals) from the root circle to r_c,
// all on the involute. The ring's body under the tooth (Sainsot's foundation is fitted on
// external gears) is not modelled: fillet = 0 (a stiff rim; Liang, Zuo & Pandey, Mech. Mach.
// Theory 76 (2014) 20-38 treat the ring tooth the same way, as a cantilever on a rigid base).
// r_c in [ra, rf] (std::domain_error otherwise); std::invalid_argument for a shifted gear or a
// tip circle inside the base circle.
PeToothCompliance pe_internal_tooth_compliance(const PeGear& g, double contact_radius, const PeOptions& o = {});

// Linear Hertz compliance 1/k_h of two teeth [m/N] (formula above).
double pe_hertz_compliance(const PeGear& g1, const PeGear& g2);

// Stiffness of one tooth pair [N/m]: gear 1 touched at radius r1, gear 2 at r2.
double pe_pair_stiffness(const PeGear& g1, const PeGear& g2, double r1, double r2, bool hertz = true,
                         const PeOptions& o = {});

// Sainsot's X* coefficients (L*, M*, P*, Q*) at h_f, theta_f; and whether (h_f, theta_f)
// lies in the fitted range.
struct SainsotCoefficients {
  double L = 0, M = 0, P = 0, Q = 0;
};
SainsotCoefficients sainsot_coefficients(double h_f, double theta_f);

// The structural coupling of neighbouring loaded teeth that the bodies' torsion makes
// (reference/fe_tooth_contact.md §9): a load on one tooth turns the rim against the bore,
// which moves every other tooth's contact point along the line of action by rb^2 c per
// unit force, c the torsional compliance of the annulus r_int..r_f (a closed form, checked
// against the FE's body in §4: 0.2 % for ROSS's deep web, 3-7 % for the rim gears),
//     c = (1 / r_int^2 - 1 / r_f^2) / (4 pi G b),   G = E / (2 (1 + nu)).
// Sainsot's foundation holds the body's share under the loaded tooth itself, so this is an
// off-diagonal term only [m/N]. It is the rigid part of the coupling: the FE's off-diagonal
// is 1.8 (ROSS) to 6.7 (thesis) times larger, the rest being the rim's bending between the
// teeth (§9). Throws std::invalid_argument without a bore (bore_radius <= 0 or >= r_f).
double pe_body_coupling(const PeGear& g);
bool pe_fillet_in_range(double h_f, double theta_f);

// The integration kernel, for any tooth shape: the bending, shear and axial integrals
// above for a beam whose section at parameter t in [t0, t1] has centre-line coordinate
// x(t), half thickness y(t) and dx/dt, loaded at (x_c, y_c) at load angle alpha_m, face
// width b, moduli E' (bending, axial) and G, by an n-point Gauss-Legendre rule.
struct PeSection {
  double x = 0, half_thickness = 0, dx_dt = 0;
};
struct PeBeamIntegrals {
  double bending = 0, shear = 0, axial = 0;
};
PeBeamIntegrals pe_beam_integrals(const std::function<PeSection(double)>& section, double t0, double t1,
                                  double x_c, double y_c, double alpha_m, double face_width,
                                  double E_prime, double G, int n_points);

}  // namespace gearhb
