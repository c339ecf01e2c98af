#pragma once
// Comparing solution methods for the periodic steady states of one model on the
// same output (thesis ch. 2; the accuracy/cost chart of chapter 2's program):
// the steady states on a fixed frequency grid, each reduced to x_max (largest
// value of a coordinate q' x over the period) and x_h1 (amplitude of its first
// harmonic).
//
//  - branch_on_grid: every solution of a harmonic-balance branch at each grid
//    frequency (each crossing of the branch, Newton-corrected at that frequency
//    from the chord), with its stability (Hill, Floquet of the corrected orbit,
//    or none).
//  - stepped_sweep: direct time integration (GSL, time_integration.hpp) stepped
//    along the grid in the given order, each frequency started from the
//    previous steady state (as a slow sweep on a test rig would be), integrated
//    until the state repeats after a period to opt.periodicity_tol relative to
//    the size of the state the frequency starts from (opt.x_scale is replaced
//    by that size); x_max refined between samples,
//    x_h1 from the uniform samples (the trapezoidal rule is spectrally exact for a
//    periodic signal).
//  - grid_error: how far a method's grid solutions are from the reference's
//    stable ones: for every stable reference solution, the nearest solution of
//    the method at that frequency (relative error of x_max, of x_h1, capped at 1;
//    1 when the method has none there). A solution farther than `found` is also
//    counted as missed: a stepped sweep lands on one attractor and misses a
//    coexisting one, so its error there is the distance between the two.
//  - correct_on_exact_flow: harmonic balance's grid solutions replaced by their exact
//    periodic orbits (the shooting correction on the exact piecewise-linear flow,
//    floquet.hpp, then exact_orbit.hpp's measures): "HB at H + exact-flow correction".
//  - cpu_seconds: CPU time of this process, to time a method.
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

// CPU seconds used by this process so far (CLOCK_PROCESS_CPUTIME_ID).
double cpu_seconds();

struct GridSolution {
  double x_max = 0.0, x_h1 = 0.0;
  bool stable = true;
  Eigen::VectorXd X;             // harmonic-balance coefficients (empty for time integration)
};
// One list of solutions per grid frequency.
using GridSolutions = std::vector<std::vector<GridSolution>>;

struct BranchOnGridReport {
  GridSolutions solutions;
  int newton_failures = 0;       // crossings whose Newton correction did not converge (skipped)
};

// Solutions of branch `b` of `hb` at each omega of `omegas` (q: the coordinate).
// Floquet stability uses opt.floquet; the x_scale for it is s.x[0]'s DOF size.
BranchOnGridReport branch_on_grid(const HarmonicBalance& hb, const Branch& b, const Scaling& s,
                                  const std::vector<double>& omegas, const Eigen::VectorXd& q,
                                  StabilityMethod stability, const FloquetOptions& floquet = {});

// Harmonic balance stepped along `omegas` (in that order) the way a time-integration
// sweep is: Newton at each frequency from the previous solution (the first from the
// linear first guess, frequency_sweep.hpp; after a failure again from it), stability
// by Hill. One solution per frequency at most; failures leave the frequency empty.
GridSolutions newton_stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                   const Eigen::VectorXd& q, const Scaling& s);
// Merge the solutions of several sweeps on the same grid (duplicates dropped).
GridSolutions merge_grid(const std::vector<GridSolutions>& parts, const Scaling& s);

// Every solution of `grid` (at omegas[g]) corrected by shooting on the exact flow
// (floquet_of_hb_orbit, x_scale = s.x[0]): x_max and x_h1 become those of the exact orbit
// (ExactOrbit), `stable` its Floquet label. A solution whose correction does not converge or
// whose orbit is inconsistent (exact_orbit.hpp) is removed: the method has no value there.
// Returns the number removed (all of them for a time-varying contact stiffness: no exact flow).
int correct_on_exact_flow(const HarmonicBalance& hb, const std::vector<double>& omegas, const Eigen::VectorXd& q,
                          const Scaling& s, GridSolutions& grid, const FloquetOptions& floquet = {});

struct SteppedSweepPoint {
  double omega = 0.0;
  bool periodic = false;         // the state repeated within opt.periodicity_tol
  int periods = 0;               // forcing periods integrated at this frequency
  double x_max = 0.0, x_h1 = 0.0;
  Eigen::VectorXd x0, v0;        // state at phase 0 of the last period
};

// Time-integration sweep along `omegas` (in that order), from the linear first
// guess at omegas[0]. Non-periodic frequencies are reported, not thrown.
std::vector<SteppedSweepPoint> stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                             const Eigen::VectorXd& q, const TimeIntegrationOptions& opt);
// The same from the state (x0, v0) at phase 0.
std::vector<SteppedSweepPoint> stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                             const Eigen::VectorXd& q, const TimeIntegrationOptions& opt,
                                             Eigen::VectorXd x0, Eigen::VectorXd v0);

// The periodic points of stepped sweeps on the grid `omegas` as grid solutions
// (all stable: a sweep only settles on attracting orbits).
GridSolutions sweep_on_grid(const std::vector<double>& omegas,
                            const std::vector<std::vector<SteppedSweepPoint>>& sweeps);

struct GridError {
  double x_max = 0.0, x_h1 = 0.0;   // largest relative errors (capped at 1)
  int compared = 0;                 // stable reference solutions
  int missed = 0;                   // of which the method had none within `found`
};

GridError grid_error(const GridSolutions& reference, const GridSolutions& method, double found = 0.05);

}  // namespace gearhb
