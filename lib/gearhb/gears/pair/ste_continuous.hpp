#pragma once
// Static transmission error with the load moving continuously along the teeth
// (thesis ch. 7 beam model, refined for the dynamics of ch. 8).
//
// Chapter 7 reads the STE at P positions per base pitch, the load sitting on a
// beam node at each (8 positions, 14 elements: 8 samples of the mesh cycle, so
// at most 3 harmonics). The dynamics of ch. 8 with H = 5 harmonics needs more.
// Here the same beams (tooth_beam: root circle to tip, one EI per element) carry
// the load anywhere along the tooth:
//
//  * kinematics: the contact point runs along the line of action A -> E at
//    constant speed (rb omega), one base pitch pb per mesh cycle. At mesh phase
//    phi in [0, 1) pair A touches at s = phi pb from A, pair B (if s + pb <= AE)
//    at s + pb. Each contact point meets the driving tooth at radius r1(s) and
//    the driven one at r2(s) (gear_geometry.hpp contact_radii); the load height
//    on the beam is r - rf.
//  * a load between nodes: the point force F at height a inside element e
//    (xi = (a - x_e)/L_e) enters as the consistent nodal loads N(xi)^T F, with the
//    cubic Hermite shape functions of the beam element
//        N1 = 1 - 3 xi^2 + 2 xi^3,  N2 = L (xi - 2 xi^2 + xi^3),
//        N3 = 3 xi^2 - 2 xi^3,      N4 = L (xi^3 - xi^2),
//    (a moment M as N'(xi)^T M) and the deflection and rotation at the load
//    point are read the same way, w(a) = N(xi) q_e, theta(a) = N'(xi) q_e.
//    The nodal values are exact for a stepped Euler-Bernoulli beam; inside the
//    loaded element the cubic misses the exact elastic line by O((L_e/a)^3).
//  * each tooth is summarised by its 2x2 flexibility at the load point
//    (w, theta per unit force and moment), root clamped;
//  * one pair: STE_elastic = F (G1_ww + G2_ww), the two deflections (ch. 7 §7.4);
//  * two pairs: each pair is the fused beam of §7.2 (driving root guided,
//    driven root clamped, translation and rotation continuous through the
//    contact, the driven tooth's frame turned by 180 deg: w -> -w, theta -> theta).
//    Cutting at the contact, the interface force and moment v = (V, M) obey
//    (G1 + D G2 D) v = (X, 0), D = diag(1, -1), so the pair stiffness is
//    k = [(G1 + D G2 D)^-1]_00; the pairs share F as k_A : k_B, X = F/(k_A + k_B);
//  * Hertz: as in ch. 7 (SteModel::hertz, two_pair_hertz equal_split or
//    fe_split_mean, or the consistent split of load_sharing.hpp).
// At loads on nodes the result equals ch. 7's FE exactly (unit tests).
//
// Since issue 20 this is one reading of the general pair below (PairSteModel:
// two different gears, each with its own shift, thickness law and tip relief,
// the load shared by the exact contact problem of load_sharing.hpp):
// ste_continuous(SteModel) builds the identical-gear PairSteModel and runs
// pair_ste, the same code the gear-pair program gearhb_gear runs.
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/gears/pair/ste.hpp"

namespace gearhb {

// Flexibility of a tooth (root clamped) at height a above the root circle:
// [[w/F, w/M], [theta/F, theta/M]] by the FE with Hermite shape functions.
Eigen::Matrix2d tooth_flexibility(const ToothBeam& tooth, double a);
// The same with the clamped cantilever's stiffness factorised once (LDLT), for many
// load heights on one tooth: at(a) == tooth_flexibility(tooth, a) up to round-off.
class ToothCompliance {
 public:
  explicit ToothCompliance(const ToothBeam& tooth);
  Eigen::Matrix2d at(double a) const;

 private:
  ToothBeam tooth_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

// Stiffness V/X of the fused pair (driving tooth loaded at a1, driven at a2).
double fused_pair_stiffness(const ToothBeam& tooth, double a1, double a2);
double fused_pair_stiffness(const ToothBeam& driving, double a1, const ToothBeam& driven, double a2);
// The two teeth as cantilevers in series (roots clamped, rotations free at the
// contact): 1 / (G1_ww(a1) + G2_ww(a2)) [N/m] (ch. 7's one-pair model, §7.4).
double cantilever_pair_stiffness(const ToothBeam& driving, double a1, const ToothBeam& driven, double a2);
// Both from the two flexibilities at the load points.
double fused_pair_stiffness(const Eigen::Matrix2d& G1, const Eigen::Matrix2d& G2);
double cantilever_pair_stiffness(const Eigen::Matrix2d& G1, const Eigen::Matrix2d& G2);

// One pair alone touching at the point s from A of the path of contact (0 <= s <= AE):
// the deflections of both teeth (roots clamped) at their load heights under F [m],
// and that plus Hertz (SteModel::hertz contacts at F) [m].
double single_pair_elastic(const SteModel& m, const ToothBeam& tooth, double s, double F);
double single_pair_ste(const SteModel& m, const ToothBeam& tooth, double s, double F);

struct StePoint {
  double phase = 0.0;              // mesh phase in [0, 1)
  int pairs = 1;
  double a1A = 0, a2A = 0;         // load heights of pair A on driving / driven tooth [m]
  double a1B = -1, a2B = -1;       // pair B (-1 when one pair)
  double force_A = 0, force_B = 0; // [N]
  double elastic = 0, hertz = 0, ste = 0;   // [m]
};

// STE at `samples` uniform phases of one mesh cycle for torque T [N m].
std::vector<StePoint> ste_continuous(const SteModel& m, double torque, int samples);

// The STE values of a cycle (ch. 7's positions or the continuous points) [m].
std::vector<double> ste_values(const std::vector<MeshPosition>& cycle);
std::vector<double> ste_values(const std::vector<StePoint>& cycle);

// Mean over the samples of F / e [N/m] (thesis §8.1: k = (T/r)/V, misprinted (T/r) V).
double mean_stiffness(const std::vector<double>& ste, double F);

// ===========================================================================
// A spur gear pair from its drawing (issue 20): gear 1 drives, gear 2 is driven.
//
// Kinematics as above, generalised: the pairs in contact at mesh phase phi touch
// at s_k = (phi + k) pb from A (k = 0, 1, ... while s_k <= AE), pair k + 1 being
// the one k base pitches ahead of the pair nearest A; each contact point P meets
// gear 1 at radius r1 = sqrt(rb1^2 + T1P^2) and gear 2 at r2 = sqrt(rb2^2 + T2P^2),
// the load heights on the two beams (tooth_beam(gear, ...), each gear its own)
// are r_i - rf_i. The separation of a pair is the sum of both tip reliefs at P
// (gear 1's at roll length T1P, gear 2's at T2P). The pair stiffnesses:
//   fused        (thesis): in the geometric multi-pair zone each pair is ch. 7's
//                fused beam [(G1 + D G2 D)^-1]_00 (§7.2), in the one-pair zone the
//                two cantilevers in series 1 / (G1_ww + G2_ww) (§7.4);
//   cantilevers  everywhere the two cantilevers in series (rotations free at the
//                contact: the usual loaded-tooth-contact reading);
//   or any PairStiffnessFn (the seam for another tooth model, e.g. the
//   potential-energy method: it receives the contact radii on both gears and
//   whether the phase has more than one pair geometrically in contact).
// The load is shared by share_load (load_sharing.hpp: the exact contact problem).
// `positions_per_base_pitch` P > 0 reads ch. 7's node positions instead (identical
// gears, no relief: pair A at node j + 1 of the driving tooth and n_e - j of the
// driven one, pair B P nodes further while on the tooth).
// ===========================================================================
enum class PairStiffness : int { fused = 0, cantilevers = 1 };

// Elastic stiffness [N/m] of one pair touching gear 1 at radius r1 and gear 2 at r2.
using PairStiffnessFn = std::function<double(double r1, double r2, bool sharing)>;

struct PairSteModel {
  GearGeometry gear1, gear2;                // driver, driven (shared module and pressure angle)
  double centre_distance = 0.0;             // a [m]; 0 = the one the shifts imply
  double youngs_modulus1 = 207e9, youngs_modulus2 = 207e9;   // E [Pa]
  TipRelief relief1, relief2;               // gear_geometry.hpp; amount 0 = none
  int tooth_elements = 0;                   // per tooth; 0 = floor(8 eps_alpha) (thesis: 14)
  ThicknessAt thickness_at = ThicknessAt::element_root_node;
  HertzCount hertz = HertzCount::per_tooth;
  TwoPairHertz pair_hertz = TwoPairHertz::equal_split;
  PairStiffness pair_stiffness = PairStiffness::fused;
  ToothForce tooth_force = ToothForce::over_pitch_radius;   // T1 / r1 or T1 / rb1
  int positions_per_base_pitch = 0;         // 0 = load moving continuously; P = ch. 7's node reading

  PathOfContact path() const;
  int elements() const;                     // n_e actually used
  double force(double torque) const;        // tooth force [N] for gear 1's torque T1 [N m]
  double contact_length() const;            // Hertz line length: the smaller face width [m]
};

struct PairContact {
  double s = 0.0;              // distance from A along the path [m]
  double r1 = 0.0, r2 = 0.0;   // contact radii on gear 1 and gear 2 [m]
  double separation = 0.0;     // both tip reliefs at this point [m]
  double stiffness = 0.0;      // elastic pair stiffness [N/m]
  double force = 0.0;          // [N] (0 = open; set by pair_ste)
  int slice = 0;               // a helical pair's face-width slice (pair_helical.hpp); 0 for a spur pair
  int tooth = 0;               // a helical pair's tooth pair (0: entering at A in slice 0 at phase 0)
};
struct MeshPhase {
  double phase = 0.0;          // in [0, 1)
  std::vector<PairContact> pairs;   // geometric pairs, nearest A first
};
// The torque-independent part: phases, contact points, separations, stiffnesses.
std::vector<MeshPhase> mesh_phases(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness = {});
std::vector<MeshPhase> mesh_phases(const PairSteModel& m, const ToothBeam& tooth1, const ToothBeam& tooth2,
                                   int samples, const PairStiffnessFn& stiffness = {});

// The same contacts at any phases in [0, 1) (a helical pair's slices, pair_helical.hpp):
// mesh_phases(m, samples) is mesh_phases_at(m, {j / samples}) (std::invalid_argument for a
// phase outside [0, 1)).
std::vector<MeshPhase> mesh_phases_at(const PairSteModel& m, const std::vector<double>& phases,
                                      const PairStiffnessFn& stiffness = {});
// The contact point at s from A (0 <= s <= AE): its radii on both gears and both tip reliefs
// (no stiffness, no force).
PairContact pair_contact_at(const PairSteModel& m, const PathOfContact& path, double s);

// The beams' pair stiffness of m's reading (pair_stiffness), each cantilever factorised once.
PairStiffnessFn beam_pair_stiffness(const PairSteModel& m);

std::vector<MeshPhase> mesh_phases_at(const PairSteModel& m, const ToothBeam& tooth1, const ToothBeam& tooth2,
                                      const std::vector<double>& phases, const PairStiffnessFn& stiffness = {});

struct PairStePoint {
  MeshPhase mesh;              // with each pair's force
  int loaded = 0;              // pairs carrying load
  double approach = 0.0, hertz = 0.0, ste = 0.0;   // [m] (load_sharing.hpp)
};
struct LoadShare;
// A phase's loaded point from its shared load (load_sharing.hpp share_load): each pair's force
// share.force[i] / scale (scale: the helical slices' scaled problem; 1 otherwise), the loaded
// count, the approach, the Hertz part and the STE.
void take_share(PairStePoint& p, const LoadShare& share, double scale = 1.0);
// The STE over the phases for gear 1's torque T1 [N m].
std::vector<PairStePoint> pair_ste(const PairSteModel& m, const std::vector<MeshPhase>& phases, double torque);

// One pair alone touching at s from A (no relief, no neighbour): its STE [m] under
// gear 1's torque T1 (the one-pair stiffness of the model's reading + its Hertz):
// at the pitch point (s = AC) the "single-pair deflection" that sizes a Harris relief.
// With `stiffness` (the seam of mesh_phases) that pair stiffness, sharing = false, in place of the beams.
double single_pair_ste(const PairSteModel& m, double s, double torque, const PairStiffnessFn& stiffness = {});

// Loaded contact ratio: the length of the path of contact A-E along which a pair
// carries load, over the base pitch (= the mean number of loaded pairs over a mesh
// cycle). Over one cycle the pairs' contact points s = (phase + i) pb sweep A-E once,
// so the samples of all pairs, sorted by s, cover the path with spacing pb / samples.
// The ends A and E are exact; where a pair lifts off or comes into load between two
// samples (tip relief), its force is extrapolated linearly from the loaded side to
// zero (the load share of a pair is linear in s near a lift-off), clipped to the
// interval. Without relief the result is the geometric contact ratio exactly (a
// plain count of loaded samples would be off by up to 1 / samples).
double loaded_contact_ratio(const std::vector<PairStePoint>& cycle, const PathOfContact& path);

}  // namespace gearhb
