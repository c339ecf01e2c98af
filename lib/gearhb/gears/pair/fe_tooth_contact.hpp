#pragma once
// Loaded tooth contact analysis (LTCA) of a spur pair by finite elements on the
// generated tooth form (issue 33 §2): the influence-coefficient method of Conry &
// Seireg (J. Eng. Ind. 93:1115, 1971) and Vijayakar (IJNME 31:525, 1991), in the plane
// (plane strain, quadratic triangles: lib/gearhb/fe/).
//
// 1. One gear, one FE model (FeGearModel). The tooth form of tooth_form.hpp (involute +
//    generated trochoidal fillet; the tip relief is NOT meshed: a relief of some 10 um
//    changes the compliance negligibly and enters the contact as a separation g_i, so one
//    model serves every relief), the whole gear (default) or a sector of n teeth, down to
//    the bore radius r_i (the file's rim_radius; 0: max(rf - 3 m, 0.5 rf)).
//    Boundary conditions: the bore fixed in both directions (a rigid shaft). A sector's
//    radial cut faces are fixed (CutFaces::fixed) or free (CutFaces::free); the sector
//    study (reference/fe_tooth_contact.md) finds that the cut condition is NOT negligible
//    at 5 teeth (fixed +2.5 %, free -3.5 % against the whole gear for the thesis gear,
//    +7 / -10 % for FZG C, and a factor 2 for ROSS's 17.5 mm bore, whose web twists), so
//    the default is the whole gear; the teeth away from the loaded ones are meshed coarsely.
//    Meshed by Gmsh (gmsh_mesher.hpp), graded: `contact_size` along the loaded flanks of
//    the loaded teeth (down to the depth w), `tooth_size` on every other boundary of the
//    loaded teeth and their neighbours, `far_tooth_size` on the other teeth, `body_size`
//    in the body. Stiffness (plane strain, thickness b: forces for the whole face width)
//    assembled with the 6-point rule (curved boundary elements) and factored once
//    (linear_solver.hpp, CHOLMOD).
//
// 2. Influence coefficients. K loaded teeth (pair k = 0..K-1 of a mesh phase touches
//    loaded tooth k; by the gear's rotational symmetry the label is free, and the loaded
//    teeth sit in the middle of the sector). A contact point on tooth k's loaded flank is
//    given by its roll length xi (the involute point whose normal is the line of action).
//    The unit load is a Hertzian pressure of a fixed reference half-width w (default
//    0.1 m) centred at the point, along the flank normal,
//        p(t) = (2 / (pi w b)) sqrt(1 - t^2 / w^2),   |t| < w,   t along the flank,
//    integrated on the P2 flank edges with 8 x 3 Gauss points per edge and normalised to a
//    unit force along -n exactly. The mesh resolves w (contact_size = w / 4 by default).
//    The coefficient C_ij is the displacement of point j along its inward normal -n_j,
//    read AT the surface point (the centre of the pressure for i = j: the point where
//    the two undeformed profiles touch, so the approach of the bodies is the sum of the
//    two centre displacements; the pressure-weighted mean would be smaller by about
//    a^2 / (8 R) per unit compliance). Symmetrised, (C + C^T) / 2 (Maxwell-Betti; the
//    asymmetry is reported). One solve per distinct point, in blocks of 64 columns.
//
//    From the reference width w to the true Hertz half-width a: on a half-plane (plane
//    strain) the surface displacement under the centre of a Hertzian pressure of
//    resultant P per unit length, relative to a point at depth d on its axis, is
//    (integrating eps_z of Johnson, Contact Mechanics, 1985, eq. 4.49 along the axis;
//    for d >> a it is Weber's 1949 formula, the Weber-Banaschek local deformation):
//        delta(d; a) = 2 P / (pi E) [ (1 - nu^2) asinh(d / a)
//                                     - nu (1 + nu) (d sqrt(a^2 + d^2) - d^2) / a^2 ]
//                   -> 2 P (1 - nu^2) / (pi E) [ ln(2 d / a) - nu / (2 (1 - nu)) ],
//    so two widths with the same resultant differ at the centre by
//        u(a) - u(w) = 2 P (1 - nu^2) / (pi E) ln(w / a),
//    exact on the half-plane and correct to O(w / rho) on a flank of curvature radius rho.
//    The contact compliance of pair i at force F_i is therefore
//        C_ii(F_i) = C1_ii(w1) + C2_ii(w2) + sum_gears 2 (1 - nu^2) / (pi E b) ln(w / a(F_i)),
//        a(F) = sqrt(4 F R / (pi L E*)),  1/R = 1/xi1 + 1/xi2 (involute curvature radii),
//        1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  L the smaller face width.
//    Checked against a resolved case: the FE with w = a itself (mesh h = a / 4 there).
//
// 3. The pair (FePairModel): the phases and contact points of mesh_phases (ste_continuous
//    .hpp: pairs at s_k = (phi + k) pb from A, radii r1, r2, separations from both reliefs),
//    per phase C = C_gear1 + C_gear2 (K x K) (optionally interpolated in the phase,
//    FePairOptions::knots_per_base_pitch) and the contact problem of
//    coupled_load_sharing.hpp with the load-dependent diagonal above: fixed point on the
//    secant C_ii(F_i) (a weak, logarithmic dependence; converged to 1e-12 F relative, at
//    most 100 passes), each pass the exact active-set solution. Tooth force F = T1 / rb1
//    along the line of action. Output per phase: STE = X (the rigid-body approach of the
//    gears along the line of action, bores fixed: it contains the bodies' torsion between
//    bore and teeth), the forces, the mesh stiffness F / X.
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/fe/linear_solver.hpp"
#include "gearhb/fe/mesh.hpp"
#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"

namespace gearhb {

// Element sizes in units of the module m (all multiplied by `scale`, the refinement knob
// of the convergence studies; the load width w is not).
struct FeMeshDensity {
  double contact_size = 0.025;  // along the loaded flanks of the loaded teeth: w / 4 at the default w
  double tooth_size = 0.1;      // other boundaries of the loaded teeth and their neighbours
  double far_tooth_size = 0.25; // the boundary of the other teeth (never above 0.25 m: fillet curvature)
  double body_size = 1.0;       // the body (rim and web)
  double scale = 1.0;
};

enum class CutFaces { fixed, free };

struct FeGearOptions {
  int sector_teeth = 0;                  // 0: the whole gear (default, section 1); n: a sector of n teeth
  int loaded_teeth = 2;                  // K: the teeth carrying contact points
  double rim_radius = 0.0;               // bore radius [m]; 0: max(rf - 3 m, 0.5 rf)
  CutFaces cut_faces = CutFaces::fixed;  // a sector's radial cuts (whole gear: none)
  double root_radius_coefficient = 0.38; // rho_f* of the basic rack
  double load_width = 0.1;               // w / m: half-width of the reference unit pressure
  FeMeshDensity density;
  double max_nodes = 1e6;                // refused before meshing above this (gmsh_mesher.hpp)
};

// Tooth k (0..K-1) of the loaded teeth and roll length xi [m] on its loaded flank.
struct FlankPoint {
  int tooth = 0;
  double roll = 0.0;
};

// A point of the root fillet of a loaded tooth where its surface stress is read
// (section 4): every node of the fillet's boundary edges, both sides of the tooth.
struct FilletStation {
  int tooth = 0;               // loaded tooth k
  bool loaded_side = true;     // the fillet below the loaded flank (in tension) or the other
  Eigen::Vector2d x;           // position [m]
  double radius = 0.0;         // |x| [m]
  double tangent_deg = 0.0;    // angle between the fillet's tangent and the tooth's centre line:
                               // ISO 6336-3's critical section is where it is 30 degrees
};

class FeGearModel {
 public:
  struct Impl;
  // Meshes, assembles and factors. Throws std::invalid_argument for a sector too small
  // for the loaded teeth (n < K), a bore radius not below rf - m, a mesh above max_nodes.
  FeGearModel(const GearGeometry& gear, double youngs_modulus, double poisson_ratio,
              const FeGearOptions& options = {});
  ~FeGearModel();
  FeGearModel(FeGearModel&&) noexcept;
  FeGearModel& operator=(FeGearModel&&) noexcept;

  // C (n x n) [m/N] of each set of points at the reference width w; every distinct point
  // loaded once. Points outside the flank are refused (std::invalid_argument).
  std::vector<Eigen::MatrixXd> compliance(const std::vector<std::vector<FlankPoint>>& sets) const;
  Eigen::MatrixXd compliance(const std::vector<FlankPoint>& points) const;
  // The same before symmetrisation (row i: the load at point i).
  Eigen::MatrixXd raw_compliance(const std::vector<FlankPoint>& points) const;

  // The tangential surface stress sigma_tt [Pa] at every fillet station (rows, in the order
  // of fillet_stations()) for a unit load (1 N over the face width, the reference pressure
  // of section 2) at each point (columns). Read from the displacement fields that
  // compliance() solves anyway (cached per point); a point not solved yet is solved here.
  // At a free surface sigma_tt is the only non-zero in-plane stress: the root stress.
  Eigen::MatrixXd fillet_stress(const std::vector<FlankPoint>& loads) const;
  const std::vector<FilletStation>& fillet_stations() const;

  // 2 (1 - nu^2) / (pi E b) ln(w / a) [m/N]: from width w to a (section 2).
  double width_correction(double half_width) const;

  // Rotation of the root circle (mean u_theta / r over the nodes of the root arcs between
  // the teeth) per unit torque [rad / (N m)], with all teeth loaded equally at their
  // pitch points along the line of action. Whole-gear models only (std::logic_error).
  double body_torsion_compliance() const;

  Eigen::Vector2d flank_point(const FlankPoint& p) const;     // position [m]
  Eigen::Vector2d flank_normal(const FlankPoint& p) const;    // outward unit normal
  double load_half_width() const;     // w [m]
  double bore_radius() const;         // r_i [m]
  double form_roll() const;           // xi at the form circle (lowest flank point) [m]
  double tip_roll() const;            // xi at the tip circle [m]
  const fe::P2Mesh& mesh() const;
  const fe::FactorStats& factor_stats() const;
  const GearGeometry& gear() const;
  const FeGearOptions& options() const;

 private:
  std::unique_ptr<Impl> impl_;
};

// The P2 node count FeGearModel(gear, ..., options) would mesh, estimated from the size
// field before Gmsh runs (fe::estimate_node_count: an upper bound, up to about 17x high for
// the strongly graded gear meshes; reference/fe_tooth_contact.md). Throws
// std::invalid_argument where the constructor would (a bore not below rf - m).
double fe_gear_node_estimate(const GearGeometry& gear, const FeGearOptions& options);

struct FePairOptions {
  FeGearOptions gear1, gear2;
  double poisson_ratio1 = 0.3, poisson_ratio2 = 0.3;
  // 0 (default): every phase's contact points loaded themselves (exact at each phase).
  // N > 0: the compliances at N + 1 phase knots per mesh cycle (plus where a pair reaches
  // E), interpolated (piecewise cubic) to the phases asked for: about 1.8 (N + 1) loads
  // per gear instead of 1.8 x samples. Not the default: within w of a tip the unit load
  // is cut off by the tip corner, a kink in the compliance that the cubic does not follow
  // (FZG C, N = 16: STE 2e-3 off there, 1.2e-4 elsewhere, below the mesh's own 4e-4).
  int knots_per_base_pitch = 0;
};

struct FePhase {
  double phase = 0.0;
  std::vector<PairContact> pairs;   // s, r1, r2, separation (mesh_phases); force set by ste()
  Eigen::MatrixXd compliance;       // C_gear1 + C_gear2 at the reference widths [m/N]
  Eigen::VectorXd local;            // per pair: the two width corrections' factor 2(1-nu^2)/(pi E b), summed
  Eigen::VectorXd local_log;        // per pair: sum_gears coefficient * ln(w_gear) ...
  Eigen::VectorXd contact_radius;   // R per pair [m]
};

// The root stress of one tooth in mesh (section 4): the largest tensile sigma_tt over the
// fillet below its loaded flank while it carries pair k at s = (phase + k) pb from A, all
// pairs' forces of that phase superposed (the neighbours' loads reach it through the rim).
struct FeRootStressPoint {
  double s = 0.0;              // contact position of the tooth's pair, from A [m]
  double stress = 0.0;         // [Pa]
  int station = 0;             // where (FeGearModel::fillet_stations())
  // sigma_tt [Pa] at every station of this tooth (both fillets), in the order of
  // fillet_stations(): the stress along the fillet at this contact position.
  std::vector<std::pair<int, double>> fillet;
};

// Hertz at each loaded pair of each phase for the forces of the FE contact problem (the
// contact's near field is Hertz's by construction, section 2): half-width a and peak
// pressure p0 = 2 F / (pi a L) of two cylinders of the flanks' curvature radii.
struct FeContactPressure {
  double s = 0.0;              // from A [m]
  double force = 0.0;          // [N]
  double half_width = 0.0;     // a [m]
  double peak_pressure = 0.0;  // p0 [Pa]
};

struct FeStePoint {
  double phase = 0.0;
  Eigen::VectorXd force;       // per pair [N]
  int loaded = 0;
  double ste = 0.0;            // X [m]
  double stiffness = 0.0;      // F / X [N/m]
};

class FePairModel {
 public:
  // The FE models of both gears (one shared when the gears, materials and options are the
  // same) and the compliances of `samples` uniform phases of one mesh cycle (samples 0: none,
  // the models only, for phases_at).
  FePairModel(const PairSteModel& pair, int samples, const FePairOptions& options = {});

  double force(double torque) const;   // T1 / rb1 [N]
  std::vector<FeStePoint> ste(double torque) const;
  // The same as ste_continuous.hpp's PairStePoint (what gearhb_gear's tables, Harris map
  // and dynamics take): forces in mesh.pairs, approach = ste = X, hertz = 0 (the contact
  // compliance is inside X). reliefs false: the same pair without its tip reliefs (every
  // separation 0; the Harris map's unmodified curve).
  std::vector<PairStePoint> pair_ste(double torque, bool reliefs = true) const;
  // The contact problem at one phase for tooth force F [N] (section 3).
  FeStePoint solve_phase(const FePhase& phase, double force) const;
  // Phases of any contact points: each set the pairs (s from A, nearest A first) on
  // consecutive loaded teeth 0, 1, ... (at most the options' loaded_teeth), their compliances
  // read from the same FE models, every distinct point loaded once (a helical pair's slices,
  // pair_helical.hpp). FePhase::phase 0, pairs as given.
  std::vector<FePhase> phases_at(const std::vector<std::vector<PairContact>>& sets) const;
  // The local (Hertz) compliance of pair k of p at its force F [N]: the width correction of
  // section 2 from the reference widths to a(F) [m/N].
  double contact_compliance(int pair_in_phase, const FePhase& p, double F) const;
  // New tip reliefs without rebuilding the FE models (the FE geometry has none, section
  // 1): only the separations g_i of the phases change.
  void set_reliefs(const TipRelief& relief1, const TipRelief& relief2);
  // The root stress of gear 1's (gear = 1) or gear 2's teeth over the path of contact at
  // T1, sorted by s; and Hertz's contact of every loaded pair (sorted by s).
  std::vector<FeRootStressPoint> root_stress(double torque, int gear) const;
  std::vector<FeContactPressure> contact_pressure(double torque) const;
  // One pair alone at s from A (no neighbour loaded): its stiffness F / X at tooth force F.
  double single_pair_stiffness(double s, double force) const;

  const std::vector<FePhase>& phases() const { return phases_; }
  const FeGearModel& gear1() const { return *gear1_; }
  const FeGearModel& gear2() const { return gear2_ ? *gear2_ : *gear1_; }
  const PathOfContact& path() const { return path_; }

 private:
  FePhase make_phase(double phase, const std::vector<PairContact>& pairs, const Eigen::MatrixXd& c1,
                     const Eigen::MatrixXd& c2, const std::vector<FlankPoint>& points1,
                     const std::vector<FlankPoint>& points2) const;
  void compliances(const std::vector<std::vector<FlankPoint>>& sets1, const std::vector<std::vector<FlankPoint>>& sets2,
                   bool shared, std::vector<Eigen::MatrixXd>& c1, std::vector<Eigen::MatrixXd>& c2) const;
  PairSteModel pair_;
  FePairOptions options_;
  PathOfContact path_;
  std::unique_ptr<FeGearModel> gear1_, gear2_;   // gear2_ empty: gear 2 = gear 1
  std::vector<FePhase> phases_;
  double estar_inverse_ = 0, length_ = 0;
};

// Mean of F / X over the points [N/m].
double fe_mean_stiffness(const std::vector<FeStePoint>& points, double force);

}  // namespace gearhb
