#pragma once
// A harmonic-balance branch through a periodic orbit found by time integration (issue 34: where
// the continued curve does not reach an orbit the integration settles on, e.g. a coexisting
// stable branch of larger swing; ch. 6 Fig. 41 at 13.65-13.70 krad/s).
//
// branch_from_orbit, the step "orbit -> HB branch":
//  1. the orbit of period p forcing periods (p = 1 or 2) through (x0, v0) at phase 0, sampled
//     over p forcing periods by the time integration (GSL rk8pd, contact switches located);
//  2. its Fourier coefficients on the period-p model (hb itself for p = 1, subharmonic_model(hb,
//     2) for p = 2: base frequency omega / p) by the FFT (hb_unknowns_of_samples), and Newton on
//     that model at the fixed omega from them;
//  3. the check of the HB orbit against the integrated one: max over the p N samples and the DOFs
//     of |x_HB(t) - x(t)| must not exceed HB's own error there, max |x_HB(t) - x_exact(t)| with
//     x_exact its orbit corrected by shooting (floquet_of_hb_orbit: on the exact flow, or for a
//     model without one, a contact with a stiffness profile, on GSL's rk8pd period map at relative
//     tolerance 1e-12; integrated from the corrected state and sampled alike:
//     FloquetResult::orbit_error is the same on the shooting's coarser nodes and may miss the
//     crest), plus `integration_tolerance` x the orbit's largest swing (the integration's own
//     error): i.e. the HB point is the integrated orbit up to HB's truncation;
//  4. the branch continued both ways in omega from that point with the sweep's arc-length
//     continuation (SweepOptions::continuation, its contact regime), first along the tangent
//     there, each way until it leaves [omega_min, omega_max], comes back to its start (an isola:
//     the second way is then not run, and the start is repeated as the last point, closing it),
//     for p = 2 meets the period-1 branch (the point whose odd harmonics of omega / 2 reverse
//     against the point before or vanish, as period_doubling.hpp's merge test; kept, not refined
//     to the period doubling), or fails; the two halves joined into one branch in the order of the first way (down
//     reversed, the start, up);
//  5. the stability of every point and the bifurcations between them: analyse_stability with the
//     same SweepOptions (for p = 2 on the period-2 model, omegas halved, as the period-doubled
//     branches: shooting over two forcing periods).
// A failure (integration, Newton, the check, a half that cannot start) leaves `ok` false and
// says in `why` at which omega and why; a half that stops early keeps its points and says so.
//
// off_every_branch, the rule for a diagram orbit: a periodic Poincare point of a bifurcation
// diagram (period n) lies on none of the given branches of period n if, at its omega, every
// point of every such branch (each chord of the branch that brackets omega, corrected onto the
// branch by Newton at that omega) is farther from it than that point's error bound: the distance
// max |x_HB(0) - x_j| over the DOFs, the smallest over the orbit's n Poincare states x_j (an
// orbit of period n may be met at any of its n phases), against HB's own error at phase 0 there,
// max |x_HB(0) - x_exact(0)| (x_exact: that point's orbit corrected by shooting,
// floquet_of_hb_orbit: on the exact flow, or for a model without one (a contact with a stiffness
// profile) on GSL's rk8pd period map at relative tolerance 1e-12, floquet_of_hb_shooting_gsl, whose
// own error lies far below `tolerance`; infinite where the shooting fails) plus `tolerance`. A
// branch that does not reach omega does not hold it.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/core/newton.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

struct OrbitBranchOptions {
  int samples_per_period = 256;        // samples of the orbit per forcing period (>= 2 H + 1)
  NewtonOptions newton{1e-9, 30};      // step 2
  TimeIntegrationOptions integration;  // step 1 (x_scale: the typical displacement)
  double integration_tolerance = 1e-6; // step 3: the integration's share of the bound, x the swing
};

struct OrbitBranch {
  int period = 1;                // forcing periods of its orbits
  double omega = NAN;            // the forcing frequency of the orbit it starts from [rad/s]
  std::shared_ptr<HarmonicBalance> model;   // subharmonic_model(hb, p) (p = 1: a copy of hb)
  FrequencyCurve curve;          // on the model: point omegas are omega / period
  int start = -1;                // index in curve.branch.points of the point at `omega`
  int newton_iterations = 0;     // step 2
  double distance = NAN;         // step 3: max |x_HB - x| over the period and DOFs [units of x]
  double bound = NAN;            // step 3: what it must not exceed
  double swing = NAN;            // largest peak-to-peak of a DOF of the orbit
  bool isola = false;            // the branch came back to its start
  bool ok = false;               // steps 1-3 passed and the branch has points with stability
  std::string why;               // one line: how each way ended, or where and why it failed
};

OrbitBranch branch_from_orbit(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                              double omega, int period, const SweepOptions& opt,
                              const OrbitBranchOptions& obo = {});

// The branch as a row source of the tables that take a curve's other branches (app/tables.hpp
// frequency_response_table, bifurcation_table: its period, model and curve; no PD of the curve
// starts it: `from` = npos, parent -1), `why` its line.
PeriodDoubledBranch table_branch(const OrbitBranch& b);

// A branch a diagram orbit is compared with: the curve on its model (omegas / period).
struct BranchView {
  const HarmonicBalance* model = nullptr;
  const FrequencyCurve* curve = nullptr;
  int period = 1;
};

// The distance of the orbit with Poincare states xs (rows, the first n used; displacements) at
// forcing frequency omega to branch b (see the top of this file), and that point's bound
// (HB's error at phase 0): of the points of b at omega, the one with the smallest distance - bound;
// distance INFINITY where b does not reach omega.
struct BranchDistance {
  double distance = INFINITY, bound = NAN;
  int chord = -1;   // the point lies between curve points chord and chord + 1
};
BranchDistance distance_to_branch(const BranchView& b, const Eigen::MatrixXd& xs, int n, double omega);

// True if the periodic diagram point p (motion periodic, period n) lies on none of the branches
// of period n in `branches` (every distance above its bound + tolerance).
bool off_every_branch(const DiagramPoint& p, const std::vector<BranchView>& branches, double tolerance);

}  // namespace gearhb
