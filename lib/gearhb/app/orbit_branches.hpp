#pragma once
// The HB branches through a bifurcation diagram's periodic orbits that lie on none of a run's
// branches (issue 34; hb/orbit_branch.hpp branch_from_orbit, off_every_branch): found, described
// in key numbers and checked against the time integration. Chapter 6 (Fig. 41) and gearhb_frc.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/app/output.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/orbit_branch.hpp"
#include "gearhb/hb/period_doubling.hpp"

namespace gearhb {

// The largest Floquet multiplier modulus of the integrated orbit of period p through (x0, v0) at
// phase 0: the product of p GSL period maps' monodromy matrices (the variational equations on the
// integrator, not the HB orbit's shooting on the exact flow).
double integrated_multiplier(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                             double omega, int p, double x_scale);

// The index in `known` of a branch of b's period that b holds: two of its points in b's span (of
// up to 16 spread over it, those whose orbit was corrected by shooting) lie on b, each of their
// p states at phase 0 (phase_states) within distance_to_branch's bound (b's HB error at phase 0
// there) plus the point's own HB error (PointFloquet::orbit_error) plus tol: two HB orbits of one
// exact orbit differ by no more than their two errors, and two branches of one period that share
// two orbits are one branch (one shared orbit could be a crossing). Both ways are tried because
// distance_to_branch corrects at one omega from a chord, which near a fold may land on the other
// sheet: b, continued from the orbit with short steps, has short chords. -1: none.
int known_branch_holding(const OrbitBranch& b, const std::vector<BranchView>& known, double tol);

// From each orbit of `off` (in order) that lies on none of the branches found so far,
// branch_from_orbit with the sweep's options o (at most 4 branches, 6 attempts), each a timed step
// "orbit branch <label>" and its `why` said as "<label>: why"; `left`: the orbits off every branch
// that started none (a failed attempt, or past the limits). A branch that starts on one of `known`
// (the run's branches, those off_branch_orbits compared `off` with; known_branch_holding) is not
// returned, said in one line and counted in `on_known`: off_every_branch missed that branch at
// the orbit's speed (e.g. where it folds within one chord), and the orbits on it start no other.
// tol: off_every_branch's tolerance.
std::vector<OrbitBranch> branches_from_orbits(Run& run, const std::string& label, const HarmonicBalance& hb,
                                              const std::vector<DiagramPoint>& off,
                                              const std::vector<BranchView>& known, const SweepOptions& o, double tol,
                                              int& left, int& on_known);

// Key numbers of orbit branch b (table id `id`, suffix `tag`): orbit_branch_id, _period, _omega
// (the orbit it starts from), _from_omega, _to_omega (its span within [o.omega_min, o.omega_max],
// forcing omega), orbit_branch_<quantity>_min, _max (of the coordinate q over the span), _swing
// (largest max - min), _stable_swing (the same on its stable points), _stable_ranges and each
// stretch _stable_from_omega_<j>, _stable_to_omega_<j>, its check against the orbit it starts from
// (_hb_vs_time_integration within _hb_error_bound), _folds, _bifurcations. Stable means stable with
// a resolved label (hb/period_doubling.hpp resolved_stable: resolved_stable_intervals, as
// period1_ranges counts): a run of stable labels none of whose shooting corrections converged is
// not counted stable but listed apart, _unresolved_ranges and each stretch
// _unresolved_from_omega_<j>, _unresolved_to_omega_<j> (unresolved_stable_stretches; 0 ranges:
// every stable label resolved).
void orbit_branch_numbers(KeyNumbers& key, const OrbitBranch& b, int id, const Eigen::VectorXd& q,
                          const std::string& quantity, const SweepOptions& o, const std::string& tag);

// The check of orbit branch b against the time integration (suffix `tag`):
// orbit_branch_diagram_speeds (the orbits of `off` on b within HB's own error), and
// orbit_branch_stability_agrees: at each of them b's Floquet stability (both ends of its chord; a
// chord at a stability change skipped) is that of the integrated orbit's GSL monodromy, and at
// orbit_branch_unstable_checked (up to 3) unstable points spread over its unstable stretches
// (both neighbours unstable), the GSL monodromy from the orbit corrected by shooting has a
// multiplier outside the unit circle too. xs: the integration's x_scale.
void orbit_branch_checks(KeyNumbers& key, const HarmonicBalance& hb, const OrbitBranch& b,
                         const std::vector<DiagramPoint>& off, double tol, double xs, const std::string& tag);

// The step a program runs after its bifurcation diagram (gearhb_frc step 4b, gearhb_gear per
// torque; ch. 6 step 3c does the same with its own keys): the HB branches through the diagram's
// periodic orbits of period 1 or 2 that lie on none of the run's branches (`off`: those of the
// diagram's orbits off the curve c of hb and `branches` as they were when the diagram's key numbers
// were written, diagram_off_branch_orbits: found and polished once per run), by branches_from_orbits
// with the sweep's options o, tolerance period_tol x the curve's largest DOF scale; each new branch
// appended to `branches` (table_branch: the next branch id in the program's tables, its section
// in bifurcation_diagram_hb.csv) and returned. Key numbers, each name ending in `suffix` ("" or
// "_<i>"): orbit_branches, off_curve_orbits_left, off_curve_orbits_on_known, and per branch k
// (tag suffix_k) orbit_branch_numbers (coordinate q named `quantity`), orbit_branch_isola,
// orbit_branch_checks. label: the program's name for the curve, heading its lines.
std::vector<OrbitBranch> orbit_branches_of_diagram(Run& run, const std::string& label, const HarmonicBalance& hb,
                                                   const FrequencyCurve& c, std::vector<PeriodDoubledBranch>& branches,
                                                   const std::vector<DiagramPoint>& off, const SweepOptions& o,
                                                   double period_tol, const Eigen::VectorXd& q,
                                                   const std::string& quantity, const std::string& suffix);

// The curve c and every period-1 branch of `found`: period1_ranges of them are the ranges with no
// stable period-1 orbit on any branch.
std::vector<const FrequencyCurve*> period1_curves(const FrequencyCurve& c, const std::vector<OrbitBranch>& found);

}  // namespace gearhb
