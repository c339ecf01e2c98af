#pragma once
// Continuation of the periodic solutions R(X, omega) = 0 over a frequency range
// (thesis §2.2).
//
// Pseudo-arc-length (the default). Unknowns Y = (X, omega), in scaled form
// y = (X / x_scale, omega / omega_scale). From a converged point y_n with unit
// tangent t_n:
//   predictor   y_p = y_n + ds t_n
//   corrector   Newton on  { R(y) = 0 ;  t_n' (y - y_p) = 0 }   (orthogonal to t_n)
//   tangent     [dR/dy ; t_n'] t_{n+1} = [0 ; 1], normalised (keeps the direction)
// Step control: ds grows by 1.5 after an easy corrector (<= 3 iterations),
// shrinks by 0.7 after a hard one (>= 7), is halved after a failure or after a
// turn of the tangent sharper than `max_turn_deg`; below ds_min the branch stops
// and the failure is reported with omega, residual and step (never a silently
// truncated branch). Folds (turning points) are where the omega component of
// the tangent changes sign; between the two points that bracket one, the fold is
// located by bisection on the chord with the corrector (omega to round-off).
//
// Natural continuation (kept for teaching, thesis §2.2): omega marches with a
// fixed step, Newton restarts from the previous solution. It cannot pass a
// fold: it stops at the first omega where Newton fails and reports it.
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/core/newton.hpp"

namespace gearhb {

// Reported to ContinuationOptions::progress after every accepted point.
struct ContinuationProgress {
  int point = 0;        // index of the accepted point in Branch::points
  double omega = 0.0;   // its omega
  double ds = 0.0;      // the (scaled) arc-length step that led to it
};

struct ContinuationOptions {
  double omega_start = 0.0, omega_end = 1.0;   // sweep direction = sign(end - start)
  double ds_initial = 0.01;   // scaled arc length
  double ds_min = 1e-6;
  double ds_max = 0.02;
  double max_turn_deg = 30.0; // largest accepted angle between successive tangents
  int max_steps = 20000;      // hard cap; reaching it is reported as a failure
  int corrector_max_iterations = 12;
  double tolerance = 1e-10;   // Newton tolerance (scaled residual and step)
  // Step-length control by the corrector's iteration count (the rule of Seydel, Practical
  // Bifurcation and Stability Analysis, 3rd ed., ch. 4 "step length control"; NLvib adapts
  // its step the same way): after an accepted point that took <= fast_iterations corrector
  // iterations ds *= grow, >= slow_iterations ds *= shrink; a rejected step (corrector
  // failure, a turn above max_turn_deg, a regime change) is retried with ds *= cut. The
  // turn test is waived once ds <= turn_floor * ds_min (a true corner must be passable).
  int fast_iterations = 3, slow_iterations = 7;
  double grow = 1.5, shrink = 0.7, cut = 0.5;
  double turn_floor = 4.0;
  int endpoint_iterations = 50;   // Newton at omega_start and at omega_end (from a predictor far away)
  int locate_iterations = 30;     // corrector of each bisection trial locating a fold
  int natural_points = 400;   // natural continuation only: number of omega steps
  // Curvature step control (off at 0): after each accepted step, ds is scaled by
  // target_turn_deg / (angle between the two tangents), within [0.5, 2] and ds_max,
  // so the points crowd where the curve bends and spread where it is straight.
  double target_turn_deg = 0.0;
  // A second-order predictor (off by default): y_p = y_n + ds t_n + ds^2 / 2 k_n, k_n = (t_n -
  // t_n-1) / |y_n - y_n-1| the branch's curvature vector from the last two tangents (the
  // corrector's hyperplane stays normal to t_n, through y_p). The corrector's first step is then
  // about ten times shorter where the branch bends smoothly (the period-2 branch of ex. 03:
  // 6.5e-6 at ds = 0.008 against 6e-5 at ds = 0.006 with the tangent predictor, scaled, largest
  // entry), but a contact model's corrector still takes 4 iterations
  // (its second step stays near the first: 2.3e-6, 1.7e-6, 4e-10, 5e-15).
  bool curvature_predictor = false;
  // Regime of a solution (e.g. its contact state; empty: not used). A step that ends
  // in another regime than it started in is accepted only with ds <= ds_regime_change;
  // a longer one is halved. So the branch walks up to a grazing point instead of
  // stepping across it: there the solution is only C1, and a long step may let the
  // corrector land on another part of the branch (a small fold pair beside a
  // grazing point is then skipped, or traversed backwards).
  std::function<std::uint64_t(const Eigen::VectorXd&)> regime;
  double ds_regime_change = 2e-4;
  // How far [rad/s] the branch may turn back beyond omega_start (a fold pair next to the
  // start: the branch from the first point folds, leaves the range at its start, turns
  // at a second fold outside and comes back through it); beyond, the continuation
  // stops with "branch turned back out of the range at its start". 0: not at all.
  double start_excursion = 0.0;
  // Called after every accepted point (e.g. to show progress); the numerics never print.
  std::function<void(const ContinuationProgress&)> progress;
};

struct BranchPoint {
  Eigen::VectorXd X;
  double omega = 0.0;
  int iterations = 0;         // corrector iterations
  double residual = 0.0;      // scaled residual at convergence
  double ds = 0.0;            // step that led here
  double tangent_omega = 0.0; // omega component of the (scaled) tangent
};

struct Fold {
  double omega = 0.0;
  Eigen::VectorXd X;          // interpolated solution at the fold
  int after_point = 0;        // the fold lies between points after_point and after_point+1
};

struct Failure {
  double omega = 0.0;
  double residual = 0.0;
  double ds = 0.0;
  std::string what;
};

struct Branch {
  std::vector<BranchPoint> points;    // in continuation order
  std::vector<Fold> folds;
  std::vector<Failure> failures;      // empty for a complete branch
  bool complete = false;              // reached omega_end
  int rejected_steps = 0;
  std::string summary() const;        // one line: points, folds, failures
};

// Pseudo-arc-length continuation from X0 (a first guess at omega_start, refined by Newton).
Branch arc_length_continuation(const ParametricProblem& p, const Eigen::VectorXd& X0,
                               const Scaling& s, const ContinuationOptions& opt);

// Where arc_length_continuation_from ends a branch (complete): at the first point outside
// [omega_min, omega_max], or at the first point where stop(X, omega) says so; both kept.
// `past_branch_point`: the branch ends there because the chord to it passed a branch point (a
// period-2 branch meeting the period-1 branch: its odd part reversed or vanished). Omega is
// stationary at such a branch point (the vertex of the pitchfork's parabola), which is no fold
// of the branch: no fold is located on that chord.
enum class EndAt { no, here, past_branch_point };
struct ContinuationEnd {
  double omega_min = -INFINITY, omega_max = INFINITY;
  std::function<EndAt(const Eigen::VectorXd&, double)> stop;
};

// Pseudo-arc-length continuation off the solution (X, omega) along `direction` (scaled,
// y = (X / x_scale, omega / omega_scale), n + 1 entries; e.g. the critical direction at a
// branch point): the first point is the predictor y + ds0 d (d = direction normalised)
// corrected in the hyperplane normal to d (at most corrector_max_iterations, as any step; a
// first step too long for the branch point's basin fails at the first corrector step longer
// than 5 ds0 (scaled, largest entry), not after those 12 iterations), its tangent
// oriented along d; then the steps of arc_length_continuation (opt.omega_start / omega_end
// unused) until `end` says so.
Branch arc_length_continuation_from(const ParametricProblem& p, const Eigen::VectorXd& X, double omega,
                                    const Eigen::VectorXd& direction, double ds0, const Scaling& s,
                                    const ContinuationOptions& opt, const ContinuationEnd& end);

// Natural (sequential) continuation with `opt.natural_points` fixed omega steps.
Branch natural_continuation(const ParametricProblem& p, const Eigen::VectorXd& X0,
                            const Scaling& s, const ContinuationOptions& opt);

// How a transition is located (locate_transition, first_transition).
struct TransitionOptions {
  double tolerance = 1e-11;           // stop when the chord fraction x chord length (scaled) is below
  int corrector_iterations = 30;      // Newton iterations of each trial point
  double corrector_tolerance = 1e-12; // Newton tolerance (scaled residual and step) of each trial point
};

// Between two consecutive converged points a, b of a branch on which the
// predicate `state(X)` differs, locate the omega where it changes: bisection
// along the chord a -> b, each trial point corrected back onto the branch in
// the hyperplane normal to the chord (so a fold between a and b is harmless),
// until the chord fraction is below `opt.tolerance` (scaled). Used e.g. for
// contact onset. A model whose residual cannot reach 1e-12 at grazing (the
// contact force is only C1 there) passes its own corrector tolerance.
double locate_transition(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b,
                         const Scaling& s, const std::function<bool(const Eigen::VectorXd&)>& state,
                         const TransitionOptions& opt = {});

// What a probe of the branch reports: an integer state (e.g. the number of Floquet
// multipliers outside the unit circle) and, optionally, a smooth indicator that changes
// sign where the state changes (e.g. log |mu| of the crossing multiplier; NaN if none).
struct StateProbe {
  int state = 0;
  double indicator = NAN;
};

// The point on the branch at chord fraction t in [0, 1] between a and b: the chord point
// corrected back onto the branch in the hyperplane normal to the chord (as every trial of
// locate_state_change). Throws if the corrector fails.
BranchPoint point_on_chord(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b, const Scaling& s,
                           double t, double corrector_tolerance = 1e-10);

// The point on the branch between a and b where the state of `probe` changes: each trial
// point on the chord a -> b is corrected back onto the branch in the hyperplane normal to
// the chord. With a finite indicator of opposite signs at the bracket ends the trial is
// the Illinois (modified regula falsi) estimate of its zero, otherwise the midpoint;
// stops when the bracket is below `tol` (chord fraction) or |indicator| < indicator_tol, or
// below 1e-7 where the indicator jumps across zero by 1e-3 or more at either side (a Floquet
// multiplier that leaps across the unit circle, as where the orbit of a stiff contact grazes:
// more trials would only narrow where, each a shooting of seconds).
// Returns the last trial point whose state differs from a's (b if none). Throws if a
// corrector fails. `corrector_tolerance` is the corrector's Newton tolerance.
BranchPoint locate_state_change(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b,
                                const Scaling& s,
                                const std::function<StateProbe(const Eigen::VectorXd&, double)>& probe,
                                double tol = 1e-9, double corrector_tolerance = 1e-10,
                                double indicator_tol = 1e-10);

}  // namespace gearhb
