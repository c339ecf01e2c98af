#pragma once
// Helical pairs by slices (issue 35; programs/gearhb_gear/README.md "Helical pairs").
//
// The transverse section. A helical gear of helix angle beta (on the reference circle),
// normal module m_n and normal pressure angle alpha_n is, in every transverse plane, the
// spur gear of ISO 21771:
//     m_t = m_n / cos(beta),   tan(alpha_t) = tan(alpha_n) / cos(beta),
//     addendum ha* m_n, dedendum hf* m_n and shift x m_n as lengths (so the section's shift
//     coefficient is x cos(beta): m_t (pi/2 + 2 x cos(beta) tan(alpha_t)) = m_t pi/2 + 2 x m_n
//     tan(alpha_n) / cos(beta), ISO's transverse tooth thickness),
//     base helix  sin(beta_b) = sin(beta) cos(alpha_n),
// and inv(alpha_wt) = inv(alpha_t) + 2 tan(alpha_n)(x1 + x2)/(z1 + z2) follows from the
// section's own rule. At beta = 0 the section is the gear itself, exactly (alpha_t = alpha_n,
// no round trip through tan and atan).
//
// The stagger. The contact lines lie in the base plane inclined at beta_b: the section at
// distance y across the face is the one at y = 0 advanced along the line of action by
// y tan(beta_b), i.e. ahead by y tan(beta_b) / p_bt mesh cycles. Across the contact width b
// the stagger is the overlap ratio
//     eps_beta = b tan(beta_b) / p_bt = b sin(beta) / (pi m_n),
// and the total contact ratio is eps_gamma = eps_alpha + eps_beta (eps_alpha the section's).
//
// The slices. b in N equal slices, slice j centred at y_j = (j + 1/2) b / N and read at
// mesh phase phi + y_j tan(beta_b) / p_bt (mod 1). Its contact line with each tooth pair spans
// ds = eps_beta p_bt / N along the path of contact, centred at (psi + q) p_bt (psi the slice's
// phase); the part of it on the path [0, AE] (a fraction w in (0, 1]) is the slice's contact,
// read at that part's centre: its radii, its separation (both tip reliefs, plus both gears'
// lead modifications at y_j), its stiffness w k(r1, r2) / N, k the chosen tooth model's
// stiffness of the full-width section (beam or potential energy; fe below). Cutting each contact line
// exactly at A and E makes the contact length on the path exact at any N (a whole eps_beta gives
// a constant length, tests/unit/test_pair_helical.cpp); a stiffness per unit face width
// constant across the face, with no coupling between neighbouring slices. The load is shared
// over all slices x pairs by share_load (load_sharing.hpp), the same exact active set.
// Hertz: Palmgren's approach is not per unit width (delta ~ F^0.9 / L^0.8), so a contact that
// carries F_i on w b / N gets the approach of the whole line at the same line load,
// delta(N F_i / w, b): the contact problem is solved scaled by N (stiffnesses w k, force N F,
// line b, ContactPair::line_fraction w). With N > 1 Hertz must be inside the sharing
// (TwoPairHertz::consistent) or none: the thesis' equal split would split over slices.
//
// The finite-element section (sliced_fe_loaded_pair; model.method fe). The FE model of
// fe_tooth_contact.hpp is a plane model of the transverse section per unit face width (plane
// strain, thickness the gear's face width), the same at every slice: each gear is meshed,
// assembled and factored once, and its influence coefficients are read at every slice
// contact's own point (FePairModel::phases_at; every distinct point loaded once). Slice j is
// the plane section over the width b/N, so its contacts' compliance is N times the full-width
// one; a contact covering a fraction w of the slice's width (cut at A or E) carries its force
// uniformly over w b/N and is read as the mean over its part, so within a slice
//     C^j_il = N o_il / (w_i w_l) C_il      (o_il the overlap of the two parts across the slice,
//                                            o_ii = w_i; the section's C_il at their points),
// the tooth pairs of one slice coupled through the rim as in the spur FE, the slices not
// coupled to each other (as the beam and PE slices). The local (Hertz) compliance of each
// contact is the section's at its line load N f_i / w_i on the line b, times N / w_i. The load
// is shared exactly over the block-diagonal problem (share_load_blocks, coupled_load_sharing.hpp)
// inside the fixed point on the force-dependent local term (FePairModel::solve_phase's).
// The loaded teeth of the FE mesh are ceil(eps_alpha + eps_beta) + 1 whatever N (a slice's
// contact lines span at most that many teeth), so the FE model does not change with N.
//
// At beta = 0 without a lead modification the slices would be identical copies: the face is
// then one slice, and the STE is the spur pair's bit for bit (tests/unit/test_pair_helical.cpp).
//
// Double helical: two mirrored halves of width b/2 each (b the contact width without the gap,
// which carries nothing), their contact lines staggered from the apex outwards: slice j at
// |y_j - b/2| tan(beta_b) / p_bt; the overlap ratio (ISO 6336: per helix) eps_beta =
// (b/2) tan(beta_b) / p_bt; each half its own contact line for Hertz (delta(S F_i / w, b/2),
// S = N/2) and its own lead modification (y across its own width); the axial forces cancel.
// N must be even (N/2 slices a half).
//
// Lead modification of one gear (ISO 21771 vocabulary), y across the contact width [0, b]:
//     crowning    C_beta (2 y / b - 1)^2                       (C_beta at both ends),
//     end relief  C_I (L_I - d) / L_I for d = min(y, b - y) < L_I, else 0   (both ends, linear),
// the pair's separation at y the sum of both gears' (their faces aligned over b).
#include <memory>
#include <vector>

#include "gearhb/gears/pair/loaded_pair.hpp"

namespace gearhb {

struct LeadModification {
  double crowning = 0.0;            // C_beta [m] at each end of the face
  double end_relief = 0.0;          // C_I [m] at each end
  double end_relief_length = 0.0;   // L_I [m] from each end (<= b / 2)
  bool any() const { return crowning > 0.0 || end_relief > 0.0; }
};
// The modification at y in [0, b] of a face of width b [m].
double lead_modification_at(const LeadModification& lead, double y, double b);

struct HelicalPair {
  double helix_angle = 0.0;         // beta [rad] on the reference circle, in [0, pi/4]
  double normal_module = 0.0;       // m_n [m]
  double normal_pressure_angle_deg = 20.0;   // alpha_n [deg]
  double shift1 = 0.0, shift2 = 0.0;   // x1, x2: the normal profile shift coefficients
  int slices = 20;                  // N (default; convergence: README "Helical pairs")
  LeadModification lead1, lead2;    // gear 1, gear 2
  bool left_hand = false;           // gear 1's hand (gear 2 the other): recorded, the axial force's direction
  bool double_helical = false;      // two mirrored halves (contact width b = both halves, the gap excluded)

  double base_helix_angle() const;  // beta_b [rad]
  // The face in slices: beta > 0 or a lead modification (else the spur pair, one slice).
  bool sliced() const { return helix_angle > 0.0 || lead1.any() || lead2.any(); }
};

// The transverse section of a gear given in normal terms (module m_n, pressure angle alpha_n,
// addendum, dedendum, shift coefficient x, face width): formulas above.
GearGeometry transverse_section(const GearGeometry& normal, double helix_angle);

// eps_beta = b tan(beta_b) / p_bt of the section pair (b its contact width; b/2 double helical).
double overlap_ratio(const PairSteModel& section, const HelicalPair& h);
// Axial force on each gear [N] for gear 1's torque T1: F_a = (T1 / r_b1) tan(beta_b) (0 double helical).
double axial_force(const PairSteModel& section, const HelicalPair& h, double torque);
// The slices' phase lead over slice 0's section: y_j tan(beta_b) / p_bt [mesh cycles], j < N.
std::vector<double> slice_phase_leads(const PairSteModel& section, const HelicalPair& h);

// The loaded contact ratio of a sliced face: the mean over the slices of each slice's
// loaded_contact_ratio (ste_continuous.hpp), so the transverse eps_alpha without relief; with
// one slice it is loaded_contact_ratio itself.
double sliced_loaded_contact_ratio(const std::vector<PairStePoint>& cycle, const PathOfContact& path, int slices);

// The loaded pair by slices (h.sliced(); one slice otherwise): stiffness empty = the section's
// beams of the model's reading, else that PairStiffnessFn (the potential-energy method).
// PairStePoint::mesh.pairs holds every slice's contacts (PairContact::slice; stiffness and
// force the slice's). std::invalid_argument for N outside [1, 1000], for the node reading
// (positions_per_base_pitch) or a Hertz split other than consistent with N > 1.
std::unique_ptr<LoadedPair> sliced_loaded_pair(const PairSteModel& section, const HelicalPair& h, int samples,
                                               const PairStiffnessFn& stiffness = {});

// The FE section in slices (above): FePairModel(section, 0, options) with enough loaded
// teeth, every slice contact's compliance from it. std::invalid_argument as sliced_loaded_pair
// (but any Hertz reading: the FE has its own) and for a tooth force other than T1 / rb1.
std::unique_ptr<LoadedPair> sliced_fe_loaded_pair(const PairSteModel& section, const HelicalPair& h, int samples,
                                                  const FePairOptions& options = {});

}  // namespace gearhb
