#pragma once
// The dynamics of a spur gear pair from its drawing (gearhb_gear; README of
// programs/gearhb_gear, "The pair over its speed range"): the mesh model a scene needs,
// both flanks, and what a gear engineer reads off each periodic orbit.
//
// Models (one DteGear: F0, me, kc, c, the STE e(theta), the no-load transmission error g,
// the normal backlash b_n and the back-flank phase psi; dte_model.hpp):
//  * one_dof   chapter 8's torsional model along the line of action, x the dynamic
//              transmission error (rigid shafts and bearings): dte_harmonic_balance;
//  * bearings  chapter 6's six DOFs x_i, y_i, theta_i, the gear centres on isotropic
//              bearings of stiffness k_i (damping ratio zeta_b of each bearing mode
//              alone), the shafts free in torsion and driven by the constant torques
//              T1 and T2 = T1 rb2 / rb1. The rigid-body rotation of the pair (both gears
//              turning together, no mesh deflection) carries no force and is removed
//              exactly: the coordinates are q = [x1, y1, x2, y2, p], p = rb1 th1 - rb2 th2
//              the transmission error, whose equation is chapter 8's
//                  me p'' + c p' + N = F0,   me = I1 I2 / (I1 rb2^2 + I2 rb1^2),
//              and the gear centres feel -N along the line of action (chapter 6's T1 row):
//                  m1 x1'' + c1 x1' + k1 x1 = -cos(a_w) N,   m1 y1'' + ... = sin(a_w) N,
//                  m2 x2'' + ...            =  cos(a_w) N,   m2 y2'' + ... = -sin(a_w) N,
//              with the mesh deflection  n'q = cos(a_w)(x1 - x2) - sin(a_w)(y1 - y2) + p
//              in place of x. As k_i -> infinity it is the one_dof model (a unit test).
//
// The back-flank phase psi (DteGear::back_phase). A drive flank of gear 1 is an involute
// unwound from its origin on the base circle; its contact with the drive line of action
// (tangent at T1) lies at L_d = rb1 (angle from the origin to T1). The back flank of the
// same tooth starts s_b1 further on the base circle (the base tooth thickness) and meets
// the second line of action (tangent at T1', the mirror of T1 about the line of centres,
// 2 alpha_w away) at L_b = rb1 (angle from T1' back to its origin). Hence
//     L_d + L_b = s_b1 + 2 alpha_w rb1   (mod pb),   s_b1 = rb1 (s1 / r1 + 2 inv alpha),
// s1 = m (pi/2 + 2 x1 tan alpha) the nominal tooth thickness (the backlash allowance is
// neglected here: it moves psi by at most b_n / pb of a cycle, 0.2 % for the thesis gear).
// On the back line the configurations are the mirror images of the drive line's, met in the
// opposite order, starting from the mirror of A (at T1A from T1'): the back pairs are where
// the drive pairs are at phase
//     psi - theta,   psi = 2 pi (s_b1 + 2 alpha_w rb1 - 2 T1A) / pb   (mod 2 pi).
// Check: identical unshifted gears give psi = pi (1 + 2 eps_alpha), and since their STE is
// symmetric, e(eps - phi) = e(phi), the back flank sees e shifted by half a mesh cycle.
//
// Measures of one orbit (mesh_orbit_measures): the DTE (the output coordinate: x, or p)
// RMS of its oscillating part and peak-to-peak; the mesh force N(theta) = drive force - back
// force, its largest and smallest value over the period (exact for a constant kc: the
// refined extremes of the penetrations; sampled on 4096 points for a stiffness profile); the
// dynamic factor K_v = max |N| / F0 (the largest tooth load on either flank over the static
// one); the state of each flank and the contact class full | drive_loss | back_impact |
// drive_loss+back_impact.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/rating/iso6336.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/gears/pair/pair_helical.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// psi [rad] in [0, 2 pi) for the pair (derivation above).
double back_flank_phase(const PairSteModel& m);

// The mesh of the pair m at gear 1's torque T from its STE over the mesh cycle (pair_ste):
// F0 = m.force(T) (the file's tooth-force reading, radius r1 = T / F0, r2 = r1 z2 / z1),
// me = I1 I2 / (I1 r2^2 + I2 r1^2), the no-load transmission error g(theta) = the smallest
// tip-relief separation of the pairs on the path, kc = the mean of F0 / (e - g) (chapter 8's
// mean of F0 / e without relief; with relief the elastic part, so that a relief larger than
// the deflection does not read as a soft mesh), c = 2 zeta sqrt(kc me), the STE and g up to
// `harmonics`; the back flank at normal backlash `backlash` (infinite: none) and phase psi.
DteGear gear_pair_mesh(const PairSteModel& m, const std::vector<PairStePoint>& ste, double torque, double I1,
                       double I2, double zeta, double backlash, int harmonics = 20);

// ISO 6336-1 method B's dynamic factor for the same spur pair (iso6336.hpp), the estimate set
// beside the computed K_v. At gear 1's torque T: F_t = T / r1 (reference radius), K_A = 1 (the
// file's torques are the loads), line load F_t / b, c' and c_gamma_alpha of iso6336_mesh_stiffness
// at that line load (hfP_over_m the basic-rack dedendum), eps_gamma = eps_alpha; the reduced mass
// from the file's inertias on the base radii, m_red = I1 I2 / (I1 rb2^2 + I2 rb1^2) / b (ISO's
// m* = J* / rb^2, so no disc shape is assumed); f_pb = f_pt cos(alpha) and f_falpha of
// ISO 1328-1:1995 grade `grade`, the larger of the two gears, less the running-in allowance of
// case-hardened steel; C_a the larger tip relief of the two gears, or without relief the
// running-in amount C_ay of case-hardened steel (sigma_Hlim = 1500 N/mm^2: 1.995 um).
// std::domain_error when the module or a reference diameter is outside ISO 1328-1's ranges.
struct PairIsoKv {
  Iso6336KvInput input;
  double f_pb = 0, f_f_alpha = 0;    // the pair's (larger) deviations before running-in [um]
  bool relief_from_running_in = false;   // C_a = C_ay (the gears carry no tip relief)
};
// A helical pair (h.helix_angle > 0; m its transverse section): the normal module and
// pressure angle of h, the section's reference diameter, f_pb = f_pt cos(alpha_t) and
// eps_gamma = eps_alpha + eps_beta (pair_helical.hpp).
PairIsoKv pair_iso6336_kv(const PairSteModel& m, double hfP_over_m, double torque, double I1, double I2, int grade,
                          const HelicalPair& h = HelicalPair());

// ISO 6336-1 method B's input for the pair m (spur, or the transverse section of the helical
// pair h): z, x, alpha_n and beta (the section's own for a spur pair; h's normal shifts and
// angle for a helical one), the section's transverse eps_alpha, its contact width, the line
// load F_t / b [N/mm] given, hfP / m_n the basic rack's dedendum coefficient.
Iso6336Input pair_iso6336_input(const PairSteModel& m, const HelicalPair& h, double hfP_over_mn, double line_load_N_per_mm);

// The model of the mesh: torsional only, or the six DOFs with bearings.
enum class MeshDofs { one_dof, bearings };
const char* to_string(MeshDofs d);   // "one_dof" | "six_dof"

// A single-helical pair on bearings (issue 35 c): one axial translation z_i per gear on an
// axial bearing of stiffness ka_i. The tooth force acts along the contact normal, inclined at
// the base helix angle beta_b to the transverse plane; with N the transverse component along
// the line of action (the model's mesh force, F0 = T1 / rb1 static) its axial component is
// N tan(beta_b), on the gears in opposite senses. In transverse-equivalent terms (kc the
// transverse mesh stiffness, as the STE gives it) the mesh deflection gains tan(beta_b)(z1 - z2):
//     q = [x1, y1, x2, y2, z1, z2, p],   n = [cos a_w, -sin a_w, -cos a_w, sin a_w, t, -t, 1],
//     m_i z_i'' + ca_i z_i' + ka_i z_i = -/+ t N,   t = tan(beta_b),
// so the static axial bearing force is F0 t = (T1 / rb1) tan(beta_b) = F_t tan(beta), F_t the
// tangential force at the reference circle. t = 0 (a spur or a double-helical pair, whose
// halves' axial forces cancel): no axial DOFs, the model above unchanged.
struct BearingSupport {
  double mass[2] = {0.0, 0.0};        // gear masses m1, m2 [kg]
  double stiffness[2] = {0.0, 0.0};   // isotropic bearing stiffnesses k1, k2 [N/m]
  double zeta = 0.02;                 // damping ratio of each bearing mode alone
  double pressure_angle = 0.0;        // operating pressure angle alpha_w [rad] (line of action)
  double axial_stiffness[2] = {0.0, 0.0};   // axial bearing stiffnesses ka1, ka2 [N/m] (t > 0)
  double helix_tan = 0.0;             // t = tan(beta_b) of a single-helical pair; 0: no axial DOFs
  bool axial() const { return helix_tan > 0.0; }
  int dofs() const { return axial() ? 7 : 5; }
};

// The harmonic-balance model of the mesh g with H harmonics: dte_harmonic_balance for
// one_dof, the bearing model above otherwise (q = [x1, y1, x2, y2, p], or with the axial
// DOFs [x1, y1, x2, y2, z1, z2, p]).
HarmonicBalance gear_mesh_model(const DteGear& g, MeshDofs dofs, const BearingSupport& b, int H, int N,
                                DteModel model);
// The output coordinate (the DTE): [1], or p (the last coordinate) for the bearing model.
Eigen::VectorXd dte_coordinate(MeshDofs dofs, const BearingSupport& b = {});
// The static (mean) axial bearing force of gear i (0, 1) [N] of the bearing model's state X:
// -ka_i times the mean of z_i (with the axial DOFs; 0 without).
double mean_axial_bearing_force(const HarmonicBalance& hb, const BearingSupport& b, const Eigen::VectorXd& X, int i);

// Closed-contact natural frequencies [Hz] of the model (drive flank closed, mean stiffness kc):
// one_dof sqrt(kc / me) / 2 pi; bearings the five (seven with axial DOFs) undamped modes of M, K + kc n n'.
std::vector<double> closed_contact_frequencies(const DteGear& g, MeshDofs dofs, const BearingSupport& b);

enum class MeshContact { full, drive_loss, back_impact, drive_loss_back_impact };
const char* to_string(MeshContact c);   // full | drive_loss | back_impact | drive_loss+back_impact
// The class of a mesh from the states of its flanks: drive_loss where the drive flank is not
// in full contact, back_impact where the back flank is not open, both, or full.
MeshContact mesh_contact(ContactState drive, ContactState back);

struct MeshOrbitMeasures {
  double dte_rms = 0.0, dte_ptp = 0.0;         // [m]
  double force_max = 0.0, force_min = 0.0;     // mesh force N = drive - back over the period [N]
  double dynamic_factor = 0.0;                 // max |N| / F0
  ContactState drive = ContactState::full, back = ContactState::open;
  MeshContact contact = MeshContact::full;
};
// Contacts 0 (drive) and 1 (back, if any) of hb; q the DTE coordinate.
MeshOrbitMeasures mesh_orbit_measures(const HarmonicBalance& hb, const Eigen::VectorXd& X, double F0,
                                      const Eigen::VectorXd& q);

// What one curve shows (stable points only where the key numbers ask for them).
struct MeshCurveSummary {
  std::vector<MeshOrbitMeasures> points;      // per branch point
  // largest DTE RMS and K_v of the points whose stable label is resolved (resolved_stable,
  // hb/period_doubling.hpp: not where a stable stretch has no converged shooting correction)
  double dte_rms_peak = 0.0, dte_rms_peak_omega = NAN;
  double dynamic_factor_peak = 0.0, dynamic_factor_peak_omega = NAN;
  double drive_loss_first_omega = NAN;        // first drive-flank loss along the branch (refined); NaN: none
  double back_impact_first_omega = NAN;       // first back-flank touch along the branch (refined); NaN: none
  double mean_force_rel_dev = 0.0;            // max |mean N - F0| / F0 over the points
};
MeshCurveSummary mesh_curve_summary(const HarmonicBalance& hb, const FrequencyCurve& c, double F0,
                                    const Eigen::VectorXd& q);

// The DTE RMS and the dynamic factor of one point by harmonic balance against GSL rk8pd
// integrated to the periodic state of the same model (both flanks, the same mesh law).
struct MeshTimeComparison {
  double omega = 0.0;
  MeshContact contact = MeshContact::full;
  double dte_rms_hb = 0.0, dte_rms_ti = 0.0, dynamic_factor_hb = 0.0, dynamic_factor_ti = 0.0;
  double rel_diff = 0.0;   // the larger of the two relative differences
  int periods = 0;
};
// Up to `points` stable points at least 0.5 % (in omega) from every fold and bifurcation,
// whose orbit the Floquet shooting corrected (an exact period-1 orbit next to the HB point:
// where the correction failed there is none for the integration to settle on), spread over
// the branch, at most a third of them each with a back impact and with a drive loss only
// (where the curve has them), the rest in full contact; a category that falls short is
// filled from the others. `progress` (if given) is called after every integrated period
// with the branch point, the periods so far and the mismatch. Throws std::runtime_error
// naming the frequency if an integration does not become periodic.
std::vector<MeshTimeComparison> mesh_time_integration_check(
    const HarmonicBalance& hb, const FrequencyCurve& c, const MeshCurveSummary& s, double F0, const Eigen::VectorXd& q,
    int points = 8, const std::function<void(std::size_t point, int period, double mismatch)>& progress = {});

// The DTE and the dynamic factor of a time-integrated motion that need not be periodic (where
// no stable periodic orbit of the harmonic balance exists: period-n, chaotic): from (x0, v0) at
// phase 0 and omega, `periods` forcing periods of GSL rk8pd (TimeIntegrator::sample, x_scale the
// typical displacement), `samples` per period; the DTE RMS of the oscillating part over all the
// samples and K_v = max |N| / F0 over them (N the mesh force of the model's own contact law at
// each sample: a sampled maximum, a lower bound of the true one by the force's variation between
// samples).
struct MeshMotionMeasures {
  double dte_rms = 0.0;          // [m]
  double dynamic_factor = 0.0;   // max |N| / F0
};
MeshMotionMeasures mesh_motion_measures(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                        double omega, int periods, int samples, double F0, const Eigen::VectorXd& q,
                                        double x_scale);

}  // namespace gearhb
