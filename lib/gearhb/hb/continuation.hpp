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
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/core/newton.hpp"

namespace gearhb {

struct ContinuationOptions {
  double omega_start = 0.0, omega_end = 1.0;   // sweep direction = sign(end - start)
  double ds_initial = 0.01;   // scaled arc length
  double ds_min = 1e-6;
  double ds_max = 0.02;
  double max_turn_deg = 30.0; // largest accepted angle between successive tangents
  int max_steps = 20000;      // hard cap; reaching it is reported as a failure
  int corrector_max_iterations = 12;
  double tolerance = 1e-10;   // Newton tolerance (scaled residual and step)
  int natural_points = 400;   // natural continuation only: number of omega steps
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

// Natural (sequential) continuation with `opt.natural_points` fixed omega steps.
Branch natural_continuation(const ParametricProblem& p, const Eigen::VectorXd& X0,
                            const Scaling& s, const ContinuationOptions& opt);

// Between two consecutive converged points a, b of a branch on which the
// predicate `state(X)` differs, locate the omega where it changes: bisection
// along the chord a -> b, each trial point corrected back onto the branch in
// the hyperplane normal to the chord (so a fold between a and b is harmless),
// until the chord fraction is below `tol` (scaled). Used e.g. for contact onset.
double locate_transition(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b,
                         const Scaling& s, const std::function<bool(const Eigen::VectorXd&)>& state,
                         double tol = 1e-11);

}  // namespace gearhb
