// ===========================================================================
// ch06_gear_pair: a spur-gear pair with 6 DOFs and external forcing
// (thesis ch. 6, Figs. 40-45)
// ===========================================================================
//
//     q = [x1, y1, th1, x2, y2, th2]
//     M q'' + C q' + K q = F0 + F cos(omega t) + T1 max(kc Delta, 0),   Delta = T2 q
//     T2 = [cos a, -sin a, rb1, -cos a, sin a, -rb2],  T1 = -T2'
//     closed mesh: K + Kc,  Kc = kc T2' T2;   C = alpha M + beta K (K: supports)
//     F0 = [0, 0, Fi, 0, 0, -Fi rb2/rb1],  F = Fa [1, 0, 1, 1, 0, 1]
//
// Delta > 0: teeth pressed together (mesh force kc Delta); Delta < 0: teeth apart.
// The plotted coordinate is Delta (the thesis' "moto relativo"). Matrices in
// lib/gearhb/gears/pair/gear_pair.hpp; harmonic balance with exact contact intervals,
// pseudo-arc-length continuation, Floquet stability of the corrected orbit and
// the bifurcations along each curve (lib/gearhb/hb).
//
// The steps, in order (chapter README "Steps"): normal_modes, linear_responses,
// frequency_responses (per case of the table: its curve, contact summary and
// what it measures; its bifurcation diagram, bifurcation_diagram, and the branches through
// the diagram's orbits off the curve, orbit_branches), time_integration_check, harmonic_convergence; own_case for
// --case own.
//
// Sample runs:
//   build/bin/ch06_gear_pair                                   every figure's data
//   build/bin/ch06_gear_pair --case quick --out /tmp/q         the regression subset
//   build/bin/ch06_gear_pair --case own --set Fi=1e6 --set Fa=1e5 --out /tmp/mine
//   build/bin/ch06_gear_pair --case fig43 --set H=16           one curve of the table
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/case_table.hpp"
#include "gearhb/app/orbit_branches.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/orbit_branch.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// --- parameters: one struct per concern, thesis defaults (§6.2) -------------
// The gear pair itself: GearPairParameters (gear_pair.hpp), the thesis' table except
// kc (printed 5e2 N/m; 5e8 N/m reproduces its text: chapter README "The kc question").
struct MeshStudy {
  double kc_alt = 5e2;         // the printed mesh stiffness, the other curves of the kc study [N/m]
  double ds_max_alt = 0.02;    // arc-length step cap of the kc_alt curves (no folds there)
  bool damping_on_mesh = false;   // beta multiplies K + Kc (else K, the supports, only)
};
struct Loading {
  double Fi = -1e6;            // static torque on gear 1 [N m] (gear 2: -Fi rb2/rb1)
  double Fa = 1e4;             // amplitude of every nonzero entry of F [N or N m]
};
struct Corrector {
  double tolerance = 1e-9;     // Newton tolerance (scaled) of the continuation and transitions
  int iterations = 12;         // Newton iterations per step
  double ds_min = 1e-8;        // smallest arc-length step: the branch has C1 corners at grazing (README)
};
struct Checks {
  Loading load{-1e6, 1e4};          // the checked curve: Fig. 43's loading, mesh stiffness kc
  int H_check = 16;                 // harmonics of the HB vs time-integration sweep
  int check_points = 8;             // compared points (--case quick: 6)
  double check_omega_min = 10000;   // its range [rad/s]: Fig. 43's intermittent band
  double check_omega_max = 20000;
  double check_omega_max_quick = 12600;   // --case quick: the first stable part of the band
  int pd_transient = 3000;          // forcing periods integrated before the period-2 orbit is sampled
};

enum class Mesh { kc, kc_alt };          // which mesh stiffness a case uses
std::string name(Mesh m) { return m == Mesh::kc ? "kc" : "kc_alt"; }   // file stems, cases.csv
enum class Measure {
  separation,    // first loss of full contact (a curve starting in full contact)
  first_touch,   // first contact (a curve starting open)
};

// A bifurcation diagram's band [rad/s] and speeds (each sweep), or the case whose diagram this
// one is by the model's homogeneity in the loads (chapter README): that case's Poincare points
// times the load ratio, if it ran before in the same run (else computed).
struct CaseDiagram {
  double lo = 0.0, hi = 0.0;
  int speeds = 0;
  const char* scaled_from = nullptr;
  const CaseDiagram* next = nullptr;   // a further band of the case (its points follow this band's)
  // Continue an HB branch from each periodic orbit of the diagram that lies on none of the
  // curve's branches (step 3c, hb/orbit_branch.hpp).
  bool orbit_branches = false;
  // The classifier's period_tol in this band (0: BifurcationDiagramOptions' 1e-6): its
  // resolution is period_tol x x_scale (the curve's largest DOF scale).
  double period_tol = 0.0;
};

// Fig. 40's bands above 12 krad/s, one per unstable stretch from 12.7 krad/s up (the two at
// 35.1-38.3 and 39.0-41.8 krad/s share one), each with the stable orbit on either side (the
// last ends at the range's end, unstable there: its down sweep follows the up sweep). Speeds
// by cost and width (README step 3b): 50 rad/s steps over the narrow 17.8-18.2 krad/s stretch,
// 100-200 rad/s over the others, 500 over the last (14 krad/s wide). period_tol 1e-8: HB's own
// error on these branches is down to 1e-9 m (59-62 krad/s), below the default resolution
// 1e-6 x 7.1 mm, where the sweeps' slowly settling period-2 points (|mu| 0.98) stop 3e-9 m off.
const CaseDiagram kFig40Top = {47500.0, 62000.0, 30, nullptr, nullptr, false, 1e-8};
const CaseDiagram kFig40Pd43 = {42600.0, 46500.0, 27, nullptr, &kFig40Top, false, 1e-8};
const CaseDiagram kFig40Pd35 = {34800.0, 42200.0, 38, nullptr, &kFig40Pd43, false, 1e-8};
const CaseDiagram kFig40Pd26 = {26200.0, 27600.0, 15, nullptr, &kFig40Pd35, false, 1e-8};
const CaseDiagram kFig40Pd18 = {17600.0, 18400.0, 17, nullptr, &kFig40Pd26, false, 1e-8};
const CaseDiagram kFig40Pd13 = {12400.0, 15500.0, 32, nullptr, &kFig40Pd18, false, 1e-8};
// Fig. 40's second band: its first unstable stretch above 11.6 krad/s (the Neimark-Sacker band
// 11.63-11.87 krad/s) with the stable orbit on either side.
const CaseDiagram kFig40Above = {11500.0, 12000.0, 21, nullptr, &kFig40Pd13};

// Fig. 43's second band: its Neimark-Sacker stretch 16.02-17.04 krad/s with the stable orbit on
// either side, in 100 rad/s steps (its quasi-periodic speeds each run the 200-period Lyapunov estimate).
const CaseDiagram kFig43Ns = {15800.0, 17300.0, 16, nullptr};

struct Case {
  std::string label;       // --case LABEL; data file frc_<label>.csv
  std::string figure;      // thesis figure
  Mesh mesh;
  Loading load;
  bool quick;              // part of the regression subset
  double quick_omega_max;  // end of its range in --case quick [rad/s]: just past the first change
  std::vector<Measure> measures;
  // Its bifurcation diagram by time integration (issue 34 §3: the speeds with no stable
  // period-1 orbit and what the gear does there; speeds 0: none). The whole chapter only: not
  // in --case quick.
  CaseDiagram diagram = {};
};

// Figs. 40-43: Fa = 1e4 and four static torques; 44-45: Fa = 1e6 (= 40 and 43 x 100,
// chapter README); every figure again with the printed kc (suffix _kc_alt).
// Diagram bands: every range with no stable period-1 orbit of Figs. 40, 41 and 43 (an unresolved
// stretch included: period1_ranges) lies in a band, with the stable orbit on either side (Fig. 40:
// the seven of 7.8-11.1 krad/s, one with the unresolved stretch at 8.46-8.50, in the first band, the one at
// 11.6-11.9 in a second, the seven from 12.7 to 62 krad/s in six more; Fig. 43: its two
// period-doubling stretches, and its Neimark-Sacker stretch in a second band); 44 and 45 are 40
// and 43 scaled. Speeds by cost (README, step 3b): fine steps where the motion changes fast
// (the grazing region), coarser where a stretch is wide.
const std::vector<Case> kCases = {
    {"fig40", "40", Mesh::kc, {1e5, 1e4}, false, 0, {Measure::separation}, {7500.0, 11200.0, 75, nullptr, &kFig40Above}},
    {"fig41", "41", Mesh::kc, {1e7, 1e4}, true, 13570, {Measure::separation}, {13400.0, 14000.0, 41, nullptr, nullptr, true}},
    {"fig42", "42", Mesh::kc, {-1e8, 1e4}, false, 0, {}},
    {"fig43", "43", Mesh::kc, {-1e6, 1e4}, true, 11000, {Measure::first_touch}, {10000.0, 15000.0, 150, nullptr, &kFig43Ns}},
    {"fig44", "44", Mesh::kc, {1e7, 1e6}, false, 0, {Measure::separation}, {7500.0, 11200.0, 75, "fig40", &kFig40Above}},
    {"fig45", "45", Mesh::kc, {-1e8, 1e6}, false, 0, {Measure::first_touch}, {10000.0, 15000.0, 150, "fig43", &kFig43Ns}},
    {"fig40_kc_alt", "40", Mesh::kc_alt, {1e5, 1e4}, false, 0, {}},
    {"fig41_kc_alt", "41", Mesh::kc_alt, {1e7, 1e4}, false, 0, {}},
    {"fig42_kc_alt", "42", Mesh::kc_alt, {-1e8, 1e4}, false, 0, {}},
    {"fig43_kc_alt", "43", Mesh::kc_alt, {-1e6, 1e4}, false, 0, {}},
    {"fig44_kc_alt", "44", Mesh::kc_alt, {1e7, 1e6}, false, 0, {}},
    {"fig45_kc_alt", "45", Mesh::kc_alt, {-1e8, 1e6}, false, 0, {}},
};

VectorXd harmonic_shape(double Fa) {
  VectorXd f(6);
  f << Fa, 0.0, Fa, Fa, 0.0, Fa;
  return f;
}

// Every uncoupled frequency sqrt(k/m), sqrt(kth/I) must be a finite number (a
// stiffness of 1e308 over a mass of 1e-300 is not a gear): names the pair.
void check_finite_frequencies(const GearPairParameters& g) {
  const struct { const char* k; double kv; const char* m; double mv; } pairs[] = {
      {"kx1", g.kx1, "m1", g.m1}, {"ky1", g.ky1, "m1", g.m1}, {"kth1", g.kth1, "I1", g.I1},
      {"kx2", g.kx2, "m2", g.m2}, {"ky2", g.ky2, "m2", g.m2}, {"kth2", g.kth2, "I2", g.I2}};
  for (const auto& p : pairs)
    ParameterSet::require(std::isfinite(p.kv / p.mv) && p.kv / p.mv > 0.0,
                          std::string("parameters '") + p.k + "' / '" + p.m + "' give no finite natural frequency");
  ParameterSet::require(std::isfinite(g.kc * (g.rb1 * g.rb1 + g.rb2 * g.rb2 + 1.0)),
                        "parameter 'kc' times the base radii squared overflows");
}

// The load ratio of case `cs` to case `label` when both loads scale alike (cs = ratio x that
// case, same mesh), else 0 (none, or not a scaling).
double load_ratio(const Case& cs, const char* label) {
  if (!label) return 0.0;
  for (const Case& o : kCases)
    if (o.label == label && o.mesh == cs.mesh && o.load.Fa != 0.0 && o.load.Fi != 0.0) {
      const double r = cs.load.Fa / o.load.Fa;
      return std::abs(cs.load.Fi / o.load.Fi - r) <= 1e-12 * std::abs(r) && r > 0.0 ? r : 0.0;
    }
  return 0.0;
}

// The down sweep's start (BifurcationDiagramOptions::down_x0, down_v0): the orbit of the
// curve's point nearest the band's upper end hi, if it lies within one speed step of hi and
// is stable with a resolved label (resolved_stable); else none (the down sweep then follows the
// up sweep).
void down_start(const HarmonicBalance& hb, const FrequencyCurve& c, double hi, double step, BifurcationDiagramOptions& o) {
  const auto& P = c.branch.points;
  std::size_t best = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (best == P.size() || std::abs(P[i].omega - hi) < std::abs(P[best].omega - hi)) best = i;
  const std::vector<bool> stable = resolved_stable(c);
  if (best == P.size() || std::abs(P[best].omega - hi) > step || best >= stable.size() || !stable[best]) return;
  hb_initial_state(hb, P[best].X, P[best].omega, o.down_x0, o.down_v0);
}

// The diagram of every band of the case (cs.diagram, then its `next` bands), the points of each
// after the last: each band's sweeps as step 3b says (the down sweep from down_start, the
// sequential Lyapunov stop from 50 periods: bifurcation_diagram.hpp).
BifurcationDiagram case_diagram(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) {
  BifurcationDiagram all;
  for (const CaseDiagram* b = &cs.diagram; b; b = b->next) {
    BifurcationDiagramOptions o;
    o.speeds = b->speeds;
    o.lyapunov_min_periods = 50;
    if (b->period_tol > 0.0) o.period_tol = b->period_tol;
    down_start(hb, c, b->hi, (b->hi - b->lo) / (b->speeds - 1), o);
    std::ostringstream step;
    step << "bifurcation diagram " << cs.label;
    if (b != &cs.diagram) step << " " << b->lo << "-" << b->hi;
    const BifurcationDiagram d = diagram_of_curve(run, hb, c, b->lo, b->hi, o, step.str(), cs.label + ": ");
    all.points.insert(all.points.end(), d.points.begin(), d.points.end());
  }
  return all;
}

class GearPairChapter {
 public:
  explicit GearPairChapter(Study& study);
  void run(Run& run);

 private:
  GearPairParameters gear_;
  MeshStudy mesh_;
  Loading own_;
  Corrector corrector_;
  Checks checks_;
  SolverSettings sol_;

  GearPairParameters gear(Mesh m) const;
  HarmonicBalance model(Mesh m, const Loading& l, int H) const;
  SweepOptions sweep(Mesh m, double omega_min, double omega_max) const;
  void normal_modes(Run& run) const;
  void linear_responses(Run& run) const;
  void frequency_responses(Run& run) const;
  void measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void bifurcation_diagram(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                           const std::vector<PeriodDoubledBranch>& pd, std::map<std::string, BifurcationDiagram>& diagrams) const;
  BifurcationDiagram starts_on_hb(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                                  const std::vector<PeriodDoubledBranch>& pd, const SectionOrbits& orbits,
                                  const BifurcationDiagram& d) const;
  void orbit_branches(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                      const BifurcationDiagram& d, std::vector<PeriodDoubledBranch>& branches) const;
  void time_integration_check(Run& run) const;
  void period_doubled_orbit(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void period2_branch_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t pd, double omega,
                            const MatrixXd& q, double half) const;
  void harmonic_convergence(Run& run) const;
  void own_case(Run& run) const;
};

// Physical bounds of the gear pair's data (SI units): wide enough for any gear, narrow
// enough that M, K and the mesh terms stay finite in double precision.
const Range kMass = Range::mass();                     // [kg], [kg m^2]
const Range kLength = Range::between(1e-6, 1e3);      // [m]
const Range kStiffness = Range::between(1e-6, 1e15);  // [N/m], [N m/rad]

GearPairChapter::GearPairChapter(Study& study) {
  ParameterSet& P = study.parameters();
  P.group("gear pair (thesis §6.2)");
  P.add("pressure_angle_deg", &gear_.pressure_angle_deg, "deg", "pressure angle", Range::between(1.0, 45.0));
  P.add("I1", &gear_.I1, "kg m^2", "gear 1 polar inertia", kMass);
  P.add("m1", &gear_.m1, "kg", "gear 1 mass", kMass);
  P.add("rb1", &gear_.rb1, "m", "gear 1 base radius", kLength);
  P.add("I2", &gear_.I2, "kg m^2", "gear 2 polar inertia", kMass);
  P.add("m2", &gear_.m2, "kg", "gear 2 mass", kMass);
  P.add("rb2", &gear_.rb2, "m", "gear 2 base radius", kLength);
  P.add("kx1", &gear_.kx1, "N/m", "gear 1 support stiffness along x", kStiffness);
  P.add("ky1", &gear_.ky1, "N/m", "gear 1 support stiffness along y", kStiffness);
  P.add("kth1", &gear_.kth1, "N m/rad", "gear 1 torsional support stiffness (thesis prints 'N')", kStiffness);
  P.add("kx2", &gear_.kx2, "N/m", "gear 2 support stiffness along x", kStiffness);
  P.add("ky2", &gear_.ky2, "N/m", "gear 2 support stiffness along y", kStiffness);
  P.add("kth2", &gear_.kth2, "N m/rad", "gear 2 torsional support stiffness (thesis prints 'N')", kStiffness);
  P.add("kc", &gear_.kc, "N/m", "mesh stiffness (thesis prints 5e2; 5e8 reproduces its text)", kStiffness);
  P.add("rayleigh_alpha", &gear_.rayleigh_alpha, "1/s", "Rayleigh damping C = alpha M + beta K, mass-proportional",
        Range::between(0.0, 1e6));
  P.add("rayleigh_beta", &gear_.rayleigh_beta, "s", "Rayleigh damping C = alpha M + beta K, stiffness-proportional",
        Range::between(0.0, 1.0));
  P.renamed("ray_alpha", "rayleigh_alpha");
  P.renamed("ray_beta", "rayleigh_beta");
  P.group("kc study");
  P.add("kc_alt", &mesh_.kc_alt, "N/m", "the other mesh stiffness (cases *_kc_alt)", kStiffness);
  P.add("ds_max_alt", &mesh_.ds_max_alt, "-", "arc-length step cap of the kc_alt curves", Range::between(1e-6, 1.0));
  P.add("damp_mesh", &mesh_.damping_on_mesh, "-", "1: beta multiplies K + Kc, 0: K (supports) only");
  P.group("own case (--case own)", true);
  P.add("Fi", &own_.Fi, "N m", "static torque on gear 1; gear 2 gets -Fi rb2/rb1", Range::between(-1e12, 1e12));
  P.add("Fa", &own_.Fa, "N, N m", "harmonic amplitude of F = Fa [1,0,1,1,0,1]", Range::between(0.0, 1e12));
  sol_.omega_min = 2000.0;    // ~0.16 x the lowest natural frequency
  sol_.omega_max = 62000.0;   // ~1.2 x the highest closed one
  sol_.ds_max = 0.005;        // resolves the small fold pairs near 7.5-8.4 krad/s (README)
  add_solver_parameters(P, sol_, 6);
  P.group("corrector");
  P.add("tolerance", &corrector_.tolerance, "-", "Newton tolerance (scaled residual and step)", Range::between(1e-14, 1e-3));
  P.add("corrector_max_iterations", &corrector_.iterations, "-", "Newton iterations per continuation step",
        Range::between(1, 100));
  P.renamed("corr_iter", "corrector_max_iterations");
  P.add("ds_min", &corrector_.ds_min, "-", "smallest scaled arc-length step before a sweep gives up", Range::between(1e-14, 1e-3));
  P.group("checks");
  P.add("H_check", &checks_.H_check, "-", "harmonics of the HB vs time-integration check",
        Range::between(1, max_harmonics(6)));
  P.add("check_points", &checks_.check_points, "-", "HB vs time-integration comparisons", Range::between(1, 50));
  register_cases(study, kCases);
  study.check([this](const Selection& s) {
    check_solver_settings(sol_);
    check_finite_frequencies(gear_);
    const double w_low = modal_analysis(gear_pair_mass(gear_), gear_pair_support_stiffness(gear_)).omega.minCoeff();
    ParameterSet::require(sol_.omega_min >= 0.01 * w_low,
                          "parameter 'omega_min' must be >= 1 % of the lowest natural frequency (" +
                              std::to_string(0.01 * w_low) + " rad/s): below it the response is static");
    const bool check = s.kind == Selection::Kind::all || s.kind == Selection::Kind::quick;
    ParameterSet::require(!check || (sol_.omega_min <= checks_.check_omega_min && sol_.omega_max >= checks_.check_omega_max),
                          "parameters 'omega_min'/'omega_max' must contain 10-20 krad/s (the time-integration check)");
  });
}

void GearPairChapter::run(Run& run) {
  if (run.own()) return own_case(run);
  if (run.whole_chapter()) normal_modes(run), linear_responses(run);
  frequency_responses(run);
  if (run.whole_chapter()) time_integration_check(run);
  if (run.whole_chapter() && !run.quick()) harmonic_convergence(run);
}

GearPairParameters GearPairChapter::gear(Mesh m) const {
  GearPairParameters g = gear_;
  g.kc = m == Mesh::kc ? gear_.kc : mesh_.kc_alt;
  g.damping_on_mesh = mesh_.damping_on_mesh;
  return g;
}

// The model in physical units (s, rad/s): the library scales the unknowns, the
// residual and the time of its integrations itself.
HarmonicBalance GearPairChapter::model(Mesh m, const Loading& l, int H) const {
  const GearPairParameters g = gear(m);
  Excitation f{gear_pair_static_torque(g, l.Fi), harmonic_shape(l.Fa), VectorXd::Zero(6)};
  return HarmonicBalance(gear_pair_system(g), {gear_pair_mesh(g)}, f, H, H == sol_.H ? sol_.N : 0,
                         contact_quadrature(sol_));
}

SweepOptions GearPairChapter::sweep(Mesh m, double omega_min, double omega_max) const {
  SweepOptions o = sweep_options(sol_);
  o.omega_min = omega_min;
  o.omega_max = omega_max;
  o.continuation.ds_max = m == Mesh::kc ? sol_.ds_max : mesh_.ds_max_alt;
  o.continuation.tolerance = corrector_.tolerance;
  o.continuation.corrector_max_iterations = corrector_.iterations;
  o.continuation.ds_min = corrector_.ds_min;
  return o;
}

// Step 1 (thesis §6.2): natural frequencies, mesh open and closed, for both kc.
void GearPairChapter::normal_modes(Run& run) const {
  Table t({"mesh", "kc", "mode", "omega_open", "omega_closed"});
  for (Mesh m : {Mesh::kc, Mesh::kc_alt}) {
    const GearPairParameters g = gear(m);
    const MatrixXd M = gear_pair_mass(g), K = gear_pair_support_stiffness(g);
    const Modes open = modal_analysis(M, K), closed = modal_analysis(M, K + gear_pair_mesh_stiffness(g));
    const std::string tag = m == Mesh::kc ? "" : "_kc_alt";   // key-number suffix
    for (int i = 0; i < 6; ++i) {
      t.add_row({name(m), g.kc, long(i + 1), open.omega[i], closed.omega[i]});
      if (m == Mesh::kc) run.key_numbers().add("omega_open_" + std::to_string(i + 1), open.omega[i], "rad/s");
      run.key_numbers().add("omega_closed_" + std::to_string(i + 1) + tag, closed.omega[i], "rad/s");
    }
  }
  run.write("modes.csv", t);
}

// Step 2: the linear |Delta| of the open and the closed system under F (Fa = 1e4),
// the background of every figure.
void GearPairChapter::linear_responses(Run& run) const {
  for (Mesh m : {Mesh::kc, Mesh::kc_alt}) {
    const GearPairParameters g = gear(m);
    LinearSystem open = gear_pair_system(g), closed = open;
    closed.K += gear_pair_mesh_stiffness(g);
    const VectorXd T2 = gear_pair_T2(g);
    const Eigen::VectorXcd F = harmonic_shape(1e4).cast<std::complex<double>>();
    Table t({"omega", "delta_open", "delta_closed"});
    for (int i = 0; i <= 3000; ++i) {
      const double omega = sol_.omega_min + (sol_.omega_max - sol_.omega_min) * i / 3000.0;
      t.add_row({omega, std::abs(T2.dot(frequency_response(open, F, omega))),
                 std::abs(T2.dot(frequency_response(closed, F, omega)))});
    }
    run.write("linear_" + name(m) + ".csv", t);
  }
}

// Step 3 (Figs. 40-45): one continuation per case of the table; its curve, its
// bifurcations, its contact summary (cases.csv) and what it measures.
void GearPairChapter::frequency_responses(Run& run) const {
  Table index({"label", "figure", "mesh", "kc", "Fi", "Fa", "static_delta_open", "static_delta_closed", "points",
               "folds", "unstable_points", "bifurcations", "rejected_steps", "transitions", "start", "end",
               "changed_lo", "changed_hi", "delta_max", "delta_min"});
  std::map<std::string, BifurcationDiagram> diagrams;   // by case label, and "<label> from_hb": for the scaled ones
  for (const Case& cs : kCases) {
    if (!run.wants(cs.label, cs.quick)) continue;
    const HarmonicBalance hb = model(cs.mesh, cs.load, sol_.H);
    const double w_end = run.quick() ? cs.quick_omega_max : sol_.omega_max;
    const SweptCurve s =
        timed_sweep_with_branches(run, hb, sweep(cs.mesh, sol_.omega_min, w_end), cs.label, sol_.period_doubling_depth);
    const FrequencyCurve& c = s.curve;
    const GearPairParameters g = gear(cs.mesh);
    const VectorXd T2 = gear_pair_T2(g);
    std::vector<PeriodDoubledBranch> branches = s.doubled;   // and those through the diagram's off-curve orbits
    if (cs.diagram.speeds > 0 && !run.quick()) {
      bifurcation_diagram(run, cs, hb, c, s.doubled, diagrams);
      if (cs.diagram.orbit_branches && diagrams.count(cs.label)) orbit_branches(run, cs, hb, c, diagrams[cs.label], branches);
    }
    run.write("frc_" + cs.label + ".csv", frequency_response_table(hb, c, branches, T2, table_progress(run, c, cs.label)));
    run.write("bifurcations_" + cs.label + ".csv", bifurcation_table(c, branches));
    const ContactHistory h = contact_history(hb, c.branch, T2);
    const VectorXd F0 = gear_pair_static_torque(g, cs.load.Fi);
    const MatrixXd K = gear_pair_support_stiffness(g);
    long unstable = 0;
    for (bool st : c.stable) unstable += st ? 0 : 1;
    index.add_row({cs.label, cs.figure, name(cs.mesh), g.kc, cs.load.Fi,
                   cs.load.Fa, T2.dot(K.ldlt().solve(F0)), T2.dot((K + gear_pair_mesh_stiffness(g)).ldlt().solve(F0)),
                   long(c.branch.points.size()), long(c.branch.folds.size()), unstable, long(c.bifurcations.size()),
                   long(c.branch.rejected_steps), long(h.transitions), std::string(to_string(h.start)),
                   std::string(to_string(h.end)), cell(std::isfinite(h.changed_lo), h.changed_lo),
                   cell(std::isfinite(h.changed_hi), h.changed_hi), h.x_max, h.x_min});
    run.key_numbers().add("transitions_" + cs.label, h.transitions, "-");
    measure(run, cs, hb, c);
  }
  run.write("cases.csv", index);
}

// The first contact change along a curve (which one: the case table), located on
// the branch by bisection with the chapter's corrector tolerance.
void GearPairChapter::measure(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  TransitionOptions to;
  to.corrector_tolerance = corrector_.tolerance;
  for (Measure m : cs.measures) {
    const double omega = first_transition(hb, c, m == Measure::separation ? opens_somewhere(hb) : touches_somewhere(hb), to);
    if (std::isfinite(omega)) run.key_numbers().add("first_change_omega_" + cs.label, omega, "rad/s");
    else run.say(cs.label + ": the contact state never changes in the frequency range");
  }
}

// Step 3b (issue 34 §3): the case's bifurcation diagram by time integration over its band, up
// from the HB orbit at the band's lower end, down from the stable HB orbit at its upper end,
// the two sweeps on two threads (hb/bifurcation_diagram.hpp: GSL rk8pd with the contact
// switches located, 400 transient periods, 64 Poincare points per speed, the Lyapunov
// estimate's sequential stop from 50 periods);
// bifurcation_diagram_<label>.csv, Delta at phase 0 of each forcing period;
// bifurcation_diagram_hb_<label>.csv, the HB branch at the same section (its stable stretches
// under the Poincare points; tests/diagram_vs_hb.py compares the two views). A band
// scaled_from a case that ran before: that diagram's points times the load ratio (the model
// is homogeneous in the loads: zero gap, contact force kc max(Delta, 0)), its own HB table.
// Skipped, said in one line, where the explicit integration would be stiff: the fastest rate
// times the longest period above 1e4 (about 2000 rk8pd steps a period, hours for the diagram;
// Fig. 43 at the thesis values: 32; with rayleigh_beta = 1 s: 1.6e6).
void GearPairChapter::bifurcation_diagram(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                                          const std::vector<PeriodDoubledBranch>& pd,
                                          std::map<std::string, BifurcationDiagram>& diagrams) const {
  const CaseDiagram& b = cs.diagram;
  const double stiff = fastest_rate(hb) * 2.0 * M_PI / b.lo;
  if (stiff > 1e4) {
    std::ostringstream os;
    os << cs.label << ": no bifurcation diagram: the time integration is stiff (fastest rate x period " << stiff
       << " > 1e4)";
    run.say(os.str());
    return;
  }
  const double scale = load_ratio(cs, b.scaled_from);
  const auto from = b.scaled_from ? diagrams.find(b.scaled_from) : diagrams.end();
  if (from == diagrams.end() || !(scale > 0.0)) {
    diagrams[cs.label] = case_diagram(run, cs, hb, c);
  } else {
    diagrams[cs.label] = from->second;
    run.key_numbers().add("diagram_scaled_by_" + cs.label, scale, "-");
    std::ostringstream os;
    os << cs.label << ": bifurcation diagram: " << b.scaled_from << "'s, Delta times " << scale
       << " (homogeneous in the loads)";
    run.say(os.str());
  }
  const BifurcationDiagram& d = diagrams[cs.label];
  const double times = from == diagrams.end() || !(scale > 0.0) ? 1.0 : scale;
  const VectorXd T2 = gear_pair_T2(gear(cs.mesh));
  auto lead = [](double w) { return std::vector<Table::Cell>{w}; };
  Table t(bifurcation_columns({"omega"}, "delta")), h(hb_section_columns({"omega", "period", "branch"}, "delta"));
  add_bifurcation_rows(t, d, T2, times, lead);
  // the starts on HB's orbits (a scaled diagram: those of the case it is scaled from, times the ratio)
  // (HB's stable orbits at the diagram's speeds, solved once for the starts and the HB rows)
  const SectionOrbits orbits = section_orbits(hb, c, pd, d);
  const std::string starts = (times == 1.0 ? cs.label : std::string(b.scaled_from)) + " from_hb";
  if (times == 1.0) diagrams[starts] = starts_on_hb(run, cs, hb, c, pd, orbits, d);
  add_bifurcation_rows(t, diagrams[starts], T2, times, lead);
  add_hb_section_rows(h, hb, c, pd, orbits, T2, 1.0,
                      [](double w, int p, int br) { return std::vector<Table::Cell>{w, long(p), long(br)}; });
  run.write("bifurcation_diagram_" + cs.label + ".csv", t);
  run.write("bifurcation_diagram_hb_" + cs.label + ".csv", h);
  diagram_key_numbers(run.key_numbers(), d, "_" + cs.label);
  run.say(cs.label + ": " + diagram_summary(d, [](double w) { return w; }, "rad/s"));
}

// Step 3b, its check from HB (every computed diagram): the time integration started on every stable HB orbit (period
// 1 and the period-2 (4) branches) at a speed of the grid that no sweep reached, classified as the
// sweeps' speeds (app diagram_from_hb_orbits): in Fig. 40's grazing region a stable period-1 orbit coexists
// with the chaotic attractor the sweeps follow (README step 3b; tests/unit/test_fig40_grazing.cpp).
// Rows `from_hb` of bifurcation_diagram_<label>.csv; key number diagram_hb_starts_<label>.
BifurcationDiagram GearPairChapter::starts_on_hb(Run& run, const Case& cs, const HarmonicBalance& hb,
                                                 const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd,
                                                 const SectionOrbits& orbits, const BifurcationDiagram& d) const {
  BifurcationDiagramOptions o;
  o.lyapunov_min_periods = 50;   // as the sweeps
  const BifurcationDiagram s = diagram_from_hb_orbits(run, hb, c, pd, orbits, d, o);
  long periodic = 0;
  std::ostringstream os;
  for (const DiagramPoint& p : s.points) {
    periodic += p.motion == Motion::periodic ? 1 : 0;
    os << (os.tellp() > 0 ? ", " : "") << p.omega;
  }
  run.key_numbers().add("diagram_hb_starts_" + cs.label, double(s.points.size()), "-");
  run.say(cs.label + ": stable HB orbits no sweep reached: " + std::to_string(s.points.size()) + " (" + os.str() +
          " rad/s); integrated from them: periodic at " + std::to_string(periodic));
  return s;
}

// The continued curve's largest swing Delta_max - Delta_min (to compare the orbit branches with).
double curve_swing(const HarmonicBalance& hb, const FrequencyCurve& c, const VectorXd& T2) {
  const ResponseEvaluator ev(hb, T2, 256);
  double swing = 0.0;
  for (const auto& q : c.branch.points) {
    const ResponseSummary r = ev.summarize(q.X);
    swing = std::max(swing, r.x_max - r.x_min);
  }
  return swing;
}

// Step 3c (issue 34): the HB branches through the diagram's periodic orbits that lie on none of
// the curve's branches (the period-1 curve and its period-doubled branches; hb/orbit_branch.hpp
// off_every_branch, tolerance the classifier's resolution period_tol x x_scale). From the first
// such orbit (up sweep, then down, in speed order) branch_from_orbit solves HB from its Fourier
// coefficients, checks it against the orbit within HB's own error and continues it both ways over
// the sweep's range with the curve's SweepOptions (stability, bifurcations); an orbit on a branch
// found so far starts none (at most 4 branches, 6 attempts). Each branch takes the next branch id in
// frc_<label>.csv and bifurcations_<label>.csv. Key numbers (suffix _<label>; _<label>_<k> for
// branch k): off_curve_orbits (diagram speeds of both sweeps off every branch of the curve),
// off_curve_orbits_left (of those, off every branch with the new ones too, that started none),
// off_curve_orbits_on_known (of those, whose branch is one of the curve's: known_branch_holding), orbit_branches,
// curve_swing (the continued curve's largest Delta_max - Delta_min, to compare), the
// numbers of orbit_branch_numbers, orbit_branch_diagram_speeds (off-curve diagram speeds on
// branch k: the time integration agrees with it there within HB's own error),
// orbit_branch_stability_agrees (1 if at each of those speeds the branch's Floquet stability,
// both ends of its chord, is that of the integrated orbit's GSL monodromy, a chord at a stability
// change skipped, and at orbit_branch_unstable_checked (up to 3) unstable points spread over its
// unstable stretches, which no sweep visits, the GSL monodromy from the orbit corrected by
// shooting has a multiplier outside the unit circle too), and the ranges with no stable period-1 orbit on any period-1 branch,
// unstable_period1_*_all_branches_<label>, and their unresolved stretches, unresolved_period1_*_all_branches_<label>. A period-1 branch k also writes its section at phase 0
// as bifurcation_diagram_hb_<label>.csv does the curve's: orbit_branch_section_<label>_<k>.csv.
void GearPairChapter::orbit_branches(Run& run, const Case& cs, const HarmonicBalance& hb, const FrequencyCurve& c,
                                     const BifurcationDiagram& d, std::vector<PeriodDoubledBranch>& branches) const {
  const SweepOptions o = sweep(cs.mesh, sol_.omega_min, sol_.omega_max);
  const double xs = c.scaling.x.cwiseAbs().maxCoeff(), tol = BifurcationDiagramOptions{}.period_tol * xs;
  const VectorXd T2 = gear_pair_T2(gear(cs.mesh));
  const std::vector<BranchView> known = branch_views(hb, c, branches);
  const std::vector<DiagramPoint> off = off_branch_orbits(hb, d, known, BifurcationDiagramOptions{}.period_tol, xs);
  int left = 0, on_known = 0;
  const std::vector<OrbitBranch> found = branches_from_orbits(run, cs.label, hb, off, known, o, tol, left, on_known);
  KeyNumbers& key = run.key_numbers();
  key.add("off_curve_orbits_" + cs.label, double(off.size()), "-");
  key.add("off_curve_orbits_left_" + cs.label, double(left), "-");
  key.add("off_curve_orbits_on_known_" + cs.label, double(on_known), "-");
  key.add("orbit_branches_" + cs.label, double(found.size()), "-");
  key.add("curve_swing_" + cs.label, curve_swing(hb, c, T2), "m");
  std::vector<const FrequencyCurve*> period1{&c};
  for (std::size_t k = 0; k < found.size(); ++k) {
    const OrbitBranch& b = found[k];
    const std::string tag = "_" + cs.label + "_" + std::to_string(k + 1);
    branches.push_back(table_branch(b));
    orbit_branch_numbers(key, b, int(branches.size()), T2, "delta", o, tag);
    orbit_branch_checks(key, hb, b, off, tol, xs, tag);
    if (b.period == 1) {
      period1.push_back(&b.curve);
      // its section at phase 0, to draw under the diagram's Poincare points
      Table h(hb_section_columns({"omega"}, "delta"));
      add_hb_section_rows(h, *b.model, b.curve, d, T2, 1.0, [](double w) { return std::vector<Table::Cell>{w}; });
      run.write("orbit_branch_section_" + cs.label + "_" + std::to_string(k + 1) + ".csv", h);
    }
  }
  add_unstable_period1_ranges(key, period1_ranges(o.omega_min, o.omega_max, period1), "_all_branches_" + cs.label);
}

// Step 4: harmonic balance (H_check harmonics) against GSL rk8pd integrated to the
// periodic steady state, at stable intermittent points of Fig. 43's band whose
// crest does not graze (Delta_max >= 10 % of the amplitude).
void GearPairChapter::time_integration_check(Run& run) const {
  const HarmonicBalance hb = model(Mesh::kc, checks_.load, checks_.H_check);
  const double w_end = run.quick() ? checks_.check_omega_max_quick : checks_.check_omega_max;
  SweepOptions o = sweep(Mesh::kc, checks_.check_omega_min, w_end);
  o.continuation.ds_max = 0.02;   // the library default: 10-20 krad/s has no fold pair it steps over
  const FrequencyCurve c = timed_sweep(run, hb, o, "check (Fig. 43, H = " + std::to_string(checks_.H_check) + ")");
  TimeIntegrationCheckOptions to;
  to.points = run.quick() ? 6 : checks_.check_points;
  to.min_crest_fraction = 0.1;
  const TimeIntegrationCheck chk = run.timed("time integration", [&] {
    return compare_with_time_integration(hb, c, gear_pair_T2(gear(Mesh::kc)), to);
  });
  run.write("check_time_integration.csv", time_integration_table(chk));
  run.key_numbers().add("xmax_rel_diff_hb_vs_time_integration", chk.worst_rel_diff, "-");
  run.key_numbers().add("time_integration_points", double(chk.points), "-");
  run.say("time-integration check (Fig. 43): " + std::to_string(chk.points) + " points, worst relative difference " +
          std::to_string(chk.worst_rel_diff));
  period_doubled_orbit(run, hb, c);
}

// Step 4b (issue "Stability and contact you can trust"): beyond the first period doubling
// of the check curve the period-1 orbit is unstable with a multiplier below -1. GSL rk8pd
// started on it leaves it and settles on a period-2 orbit: Delta repeats after two forcing
// periods, not after one (period2_fig43.csv: 4 periods of both orbits).
void GearPairChapter::period_doubled_orbit(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const auto& B = c.bifurcations;
  const auto pd = std::find_if(B.begin(), B.end(), [](const Bifurcation& b) {
    return b.type == BifurcationType::period_doubling && b.located;
  });
  if (pd == B.end() || pd + 1 == B.end()) throw std::runtime_error("the check curve has no period-doubling band");
  const auto& P = c.branch.points;
  const double w_mid = 0.5 * (pd->omega + (pd + 1)->omega);
  std::size_t k = std::size_t(pd->after_point) + 1;   // the point of the band nearest its middle
  for (std::size_t i = k; i <= std::size_t((pd + 1)->after_point); ++i)
    if (std::fabs(P[i].omega - w_mid) < std::fabs(P[k].omega - w_mid)) k = i;
  const VectorXd T2 = gear_pair_T2(gear(Mesh::kc));
  TimeIntegrator ti(hb);
  TimeIntegrationOptions o;
  o.x_scale = c.scaling.x[0];
  o.samples_per_period = 256;
  VectorXd x0, v0;
  hb_initial_state(hb, P[k].X, P[k].omega, x0, v0);
  const MatrixXd q = run.timed("period-2 orbit", [&] { return ti.sample(x0, v0, P[k].omega, checks_.pd_transient, 4, o); });
  const VectorXd d = q * T2;
  const VectorXd d_hb = ResponseEvaluator(hb, T2, 256).history(P[k].X);
  const int N = 256;
  const double half = 0.5 * (d.maxCoeff() - d.minCoeff());
  double after_one = 0.0, after_two = 0.0;   // max |Delta(t + T) - Delta(t)|, |Delta(t + 2T) - Delta(t)| / half
  for (int j = 0; j < 2 * N; ++j) {
    after_one = std::max(after_one, std::fabs(d[j + N] - d[j]) / half);
    after_two = std::max(after_two, std::fabs(d[j + 2 * N] - d[j]) / half);
  }
  Table t({"periods", "delta_time_integration", "delta_hb_period_one"});
  for (int j = 0; j < 4 * N; ++j) t.add_row({double(j) / N, d[j], d_hb[j % N]});
  run.write("period2_fig43.csv", t);
  KeyNumbers& key = run.key_numbers();
  key.add("period2_omega_fig43", P[k].omega, "rad/s");
  key.add("period2_multiplier_fig43", c.floquet[k].modulus * std::cos(c.floquet[k].angle), "-");
  key.add("period2_repeat_after_one_period", after_one, "-");
  key.add("period2_repeat_after_two_periods", after_two, "-");
  key.add("period2_orbit_fig43", after_two < 1e-6 && after_one > 1e-2 ? 1.0 : 0.0, "-");
  run.say("beyond the period doubling at " + std::to_string(pd->omega) + " rad/s: time integration at " +
          std::to_string(P[k].omega) + " rad/s repeats after 2 periods to " + std::to_string(after_two) +
          ", after 1 period only to " + std::to_string(after_one));
  period2_branch_check(run, hb, c, std::size_t(pd - B.begin()), P[k].omega, q, half);
}

// Step 4c (issue 34 §1): the period-2 model by harmonic balance (H_check harmonics on omega,
// twice as many on omega/2) at the same omega, against the time-integrated orbit q (4 periods,
// 256 samples each): Newton's method started from the integrated orbit's own Fourier
// coefficients over its first two periods (hb_unknowns_of_samples), then the largest
// |Delta_HB - Delta_ti| over two periods / half amplitude. Its bound: the HB orbit's own
// distance to the exact orbit on the flow (hb_orbit_error of the shooting over two periods: the
// largest over the DOFs), as Delta = T2' q, times sum |T2_i|, / half amplitude, since the time
// integration follows the exact flow (to its tolerance, 1e-10 of the amplitude). The start is
// the integrated orbit, not the branch switched at the period doubling: on this curve that
// branch leaves the period doubling downwards and turns back to it (its range is said, and
// written as period2_branch_from/to_omega_fig43), never reaching this omega.
void GearPairChapter::period2_branch_check(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t pd,
                                           double omega, const MatrixXd& q, double half) const {
  SweepOptions o = sweep(Mesh::kc, checks_.check_omega_min, checks_.check_omega_max);
  FrequencyCurve one = c;   // the curve with only that period doubling to switch at
  one.bifurcations = {c.bifurcations[pd]};
  const std::vector<PeriodDoubledBranch> br = run.timed("period-2 branch check", [&] { return period_doubled_branches(hb, one, o); });
  if (br.empty() || !has_points(br[0])) throw std::runtime_error("the check curve's period-2 switch failed: " + br.at(0).why);
  const HarmonicBalance& hb2 = *br[0].model;
  const int N = 256;
  VectorXd X = hb_unknowns_of_samples(hb2, q.topRows(2 * N));
  Scaling s = br[0].curve.scaling;
  if (!newton_solve(hb2, X, omega / 2.0, s, {corrector_.tolerance, 30}).converged)
    throw std::runtime_error("the period-2 orbit did not converge at omega = " + std::to_string(omega));
  const VectorXd T2 = gear_pair_T2(gear(Mesh::kc));
  const VectorXd h = ResponseEvaluator(hb2, T2, 2 * N).history(X), d = q * T2;
  double worst = 0.0;
  for (int j = 0; j < 2 * N; ++j) worst = std::max(worst, std::fabs(h[j] - d[j]) / half);
  const double bound =
      T2.cwiseAbs().sum() * floquet_of_hb_orbit(hb2, X, omega / 2.0, s.x[0], o.floquet).orbit_error / half + 1e-9;
  double from = INFINITY, to = -INFINITY;   // the switched branch's range in omega
  for (const auto& p : br[0].curve.branch.points) from = std::min(from, 2.0 * p.omega), to = std::max(to, 2.0 * p.omega);
  KeyNumbers& key = run.key_numbers();
  key.add("period2_hb_vs_time_integration_fig43", worst, "-");
  key.add("period2_hb_orbit_error_fig43", bound, "-");
  key.add("period2_hb_within_orbit_error_fig43", worst <= bound ? 1.0 : 0.0, "-");
  key.add("period2_branch_from_omega_fig43", from, "rad/s");
  key.add("period2_branch_to_omega_fig43", to, "rad/s");
  run.say("the period-2 model by harmonic balance (H = " + std::to_string(hb2.harmonics()) + " on omega/2) at " +
          std::to_string(omega) + " rad/s from the integrated orbit: largest difference to the time integration " +
          std::to_string(worst) + " of the half amplitude (bound by its own orbit error " + std::to_string(bound) +
          "); the branch switched at the period doubling spans " + std::to_string(from) + "-" + std::to_string(to) +
          " rad/s");
}

// Step 5: convergence in H of the peak Delta_max / Delta_min of Fig. 43 over 10-20 krad/s.
void GearPairChapter::harmonic_convergence(Run& run) const {
  Table t({"H", "points", "folds", "delta_max_peak", "delta_min_peak"});
  for (int H : {3, 5, 8, 10, 14, 20}) {
    const HarmonicBalance hb = model(Mesh::kc, checks_.load, H);
    SweepOptions o = sweep(Mesh::kc, checks_.check_omega_min, checks_.check_omega_max);
    o.stability = StabilityMethod::none;   // only the peaks are compared
    const FrequencyCurve c = timed_sweep(run, hb, o, "H study H = " + std::to_string(H));
    const ContactHistory h = contact_history(hb, c.branch, gear_pair_T2(gear(Mesh::kc)));
    t.add_row({long(H), long(c.branch.points.size()), long(c.branch.folds.size()), h.x_max, h.x_min});
  }
  run.write("h_study.csv", t);
}

// --case own: one curve with the user's static torque and forcing (kc).
void GearPairChapter::own_case(Run& run) const {
  const HarmonicBalance hb = model(Mesh::kc, own_, sol_.H);
  const SweptCurve s =
      timed_sweep_with_branches(run, hb, sweep(Mesh::kc, sol_.omega_min, sol_.omega_max), "own", sol_.period_doubling_depth);
  const FrequencyCurve& c = s.curve;
  const VectorXd T2 = gear_pair_T2(gear(Mesh::kc));
  run.write("frc.csv", frequency_response_table(hb, c, s.doubled, T2, table_progress(run, c, "own")));
  run.write("bifurcations.csv", bifurcation_table(c, s.doubled));
  const ContactHistory h = contact_history(hb, c.branch, T2);
  run.key_numbers().add("complete", c.branch.complete ? 1.0 : 0.0, "-");   // 0: natural continuation stopped at a fold
  run.key_numbers().add("points", double(c.branch.points.size()), "-");
  run.key_numbers().add("transitions", h.transitions, "-");
  run.key_numbers().add("folds", double(c.branch.folds.size()), "-");
  run.key_numbers().add("delta_max", h.x_max, "m");
  run.key_numbers().add("delta_min", h.x_min, "m");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("ch06_gear_pair",
              "ch06_gear_pair: 6-DOF spur-gear pair (thesis ch. 6, Figs. 40-45)\n"
              "  M q'' + C q' + K q = F0 + F cos(omega t) + T1 max(kc T2 q, 0),  Delta = T2 q the mesh deflection");
  GearPairChapter chapter(study);
  return study.run(argc, argv, [&](Run& run) { chapter.run(run); });
}
