#pragma once
// Period-doubled branches by harmonic balance, switched at the located period-doubling
// (PD) points of a period-1 frequency curve (issue 34 §1).
//
// The model. A period-2 orbit of a system forced at omega is periodic with the base
// frequency Omega = omega / 2. subharmonic_model(hb, 2) is the same equations as an
// ordinary HarmonicBalance on Omega: H2 harmonics (2H for the switch: then every period-1
// HB point, harmonic k -> 2k, solves it exactly; with more harmonics it does not, and the
// branch point is lost - ex. 03 at H = 21 in H2 = 80), the forcing on harmonic
// 2 of Omega (Excitation::harmonic), every periodic coefficient moved k -> 2k (the gaps'
// harmonics) or composed with theta -> 2 theta (a stiffness profile). Why a model of its
// own rather than a `period` flag inside HarmonicBalance: every consumer of a model (the
// exact flow, the shooting, the time integration, the response, the bifurcation location)
// then works unchanged on the period-2 orbit, its period 2 pi / Omega being two forcing
// periods, with no second meaning of omega to get wrong. Its frequency parameter is
// Omega: a FrequencyCurve of the period-2 model holds Omega (forcing omega = 2 Omega). The
// continuation's scaled parameter Omega / (omega_scale / 2) equals omega / omega_scale, so
// the arc length, steps and tolerances are those of a continuation in the forcing
// frequency.
//
// The switch at a PD of the period-1 curve c (located omega_pd, between two points):
//  1. the PD point: the point the location found (Bifurcation::X; the multiplier crossed -1
//     there to a chord fraction of 1e-9), not one re-derived from omega_pd on the chord
//     (linear in omega, that missed the PDs beside a fold of the branch: 3 of 10 switches of
//     the light-load gear at depth 2 failed);
//  2. its Floquet multipliers on the corrected orbit (floquet.hpp) and the real eigenvector
//     e = (dx0, dv0) of the multiplier nearest -1;
//  3. the eigen-solution dx(t) over one forcing period, by central differences of the
//     exact flow (PiecewiseLinearFlow) from the corrected state +- delta e, or, where the
//     orbit is not corrected (a time-varying contact stiffness has no exact flow; or the
//     sweep's FloquetOptions::correct_orbit is false, as gearhb_planetary's), steps 2-3 on
//     the variational equation about the HB orbit (floquet.hpp floquet_of_hb_variational,
//     variational_solution): the direction only starts step 4's inverse iteration; it is
//     antiperiodic (dx(t + T) = -dx(t) for mu = -1), so it lives on the odd harmonics of
//     Omega, and its coefficients are the trapezoid sums over one period (spectrally
//     accurate: the integrand dx(t) cos(k Omega t), k odd, is T-periodic);
//  4. a period-1 point re-expressed on the period-2 basis (harmonic k -> 2k) is a solution
//     of the period-2 model with zero odd harmonics; the period-2 HB branch crosses the
//     period-1 branch where the odd block of the period-2 Jacobian is singular (its own
//     branch point, beside the PD by the truncation error; located by bisection on the
//     sign of its determinant), and leaves it along that block's null vector. The Floquet
//     eigen-solution picks that null vector (one inverse iteration from it; their cosine is
//     reported: 0.9986 for ex. 03) and cannot replace it: 5 % of a direction off the null
//     vector leaves a residual that the nearly singular corrector turns into an O(1) step
//     (tried: Newton diverged from the PD with the Floquet direction itself). The first
//     point is the branch point plus `step` (scaled arc length) along the null vector,
//     corrected in the hyperplane normal to it (so it cannot fall back onto the period-1
//     orbit), and the branch is continued with the existing arc length
//     (arc_length_continuation_from);
//  5. it ends where its odd harmonics change sign (it crossed the period-1 branch: it
//     merged at another PD; the crossing is refined by secant iterations on the chord to
//     |odd| ~ 0, which says on which chord of c it met c, and the branch ends at the period-2
//     model's branch point beside the PD there - the refined crossing itself may lie anywhere
//     on the period-1 branch near it, where |odd| = 0 too), or where its odd harmonics vanish (below 1e-8 of the branch's largest: the
//     corrector turned onto the period-1 branch, a solution of the period-2 model too; that
//     point is dropped and the branch ends at the period-2 model's branch point beside the PD
//     it joined at), where it leaves the range (complete), or where the continuation fails
//     (the reason kept; the rest of the run stands). The PD a merge ends at is the one located
//     on the chord of c (or a chord next to it) nearest the merge point in the scaled
//     unknowns: the HB branch point lies beside the PD of the exact orbit by the truncation
//     error (ch. 6 Fig. 40 at H = 10: 8654.8 against 8674.3 rad/s; 8673.5 at H = 14), and a
//     branch with folds passes one omega several times, so a window in omega alone missed it or
//     could pick a PD of another pass. Where no PD lies there the line says between which
//     points of c and what their Floquet data show (shooting not converged; no multiplier
//     crossing -1); a PD located on orbits whose shooting did not converge is said so too.
//     The Floquet direction of steps 2-3 only starts step 4's inverse iteration. Where the
//     shooting correction of the PD orbit does not converge it comes from the variational
//     equation about the HB orbit; at a non-smooth PD (smooth = 0: a multiplier jumps across -1,
//     as at a grazing orbit, with no eigenvector at -1) from the eigenvector of the real multiplier farthest beyond -1 (else the real negative one nearest -1). The
//     inverse iteration then runs to convergence, the branch line says which
//     (SwitchPoint::direction), and the switch stands or fails on the HB model's own branch point
//     as at a smooth PD; its points' stability is the period-2 shooting's, as everywhere.
// The two directions +-e from the PD give the same orbits shifted by one forcing period
// (x(t) -> x(t + T) flips the sign of the odd harmonics), so one direction is continued;
// a PD where an earlier branch merged is not switched again.
//
// Stability of the period-2 points: analyse_stability on the period-2 model, i.e. Floquet
// multipliers of the orbit corrected by shooting over two forcing periods, and its own
// bifurcations (its PDs start period-4 branches: period_doubling_cascade, the same switch on
// the period-2 model as hb, PeriodDoublingOptions::period = 2).
// Models with a time-varying contact stiffness (a planetary set's meshes) take the variational
// path of step 3; their period-2 points' multipliers are those of the sweep's FloquetOptions.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// The period-p model of hb (p >= 1): base frequency omega / p, H2 harmonics (0: p H).
std::shared_ptr<HarmonicBalance> subharmonic_model(const HarmonicBalance& hb, int p, int H2 = 0);

// X of hb (H harmonics) on the basis of the period-p model hbp: harmonic k -> p k (those
// beyond hbp's harmonics dropped).
Eigen::VectorXd to_subharmonic_basis(const HarmonicBalance& hb, const HarmonicBalance& hbp, int p,
                                     const Eigen::VectorXd& X);

// X of hbp with the coefficients of the harmonics that are multiples of p zeroed: the part
// that a period-1 orbit does not have (p = 2: the odd harmonics of Omega).
Eigen::VectorXd subharmonic_part(const HarmonicBalance& hbp, int p, const Eigen::VectorXd& X);

struct PeriodDoublingOptions {
  double step = 0.02;    // scaled arc length of the first point off the PD
  int samples = 512;     // samples of the eigen-solution over one period of hb
  // hb's period in forcing periods: 1 for the forced model, 2 for a period-2 model (its
  // branches are period 4; period_doubling_cascade). The branches' omegas and messages are
  // forcing frequencies, period x hb's.
  int period = 1;
  // The step growth of the branch's continuation: ContinuationOptions::fast_iterations (the
  // step grows by `grow` after a corrector of at most this many iterations). A contact model's
  // period-2 corrector takes 4 Newton iterations at almost any step, however good the predictor
  // (ex. 03 with the curvature predictor: steps 2.3e-6, 1.7e-6, 4e-10, 5e-15 - the second as long
  // as the first, then quadratic), so at the sweep's 3 the step would grow only after the odd
  // 3-iteration point (ex. 03: 87 points, 345 ms with stability); at 4 it grows (33 points).
  // It was kept at 3 while ch. 6's period2_hb_within_orbit_error_fig43 started its HB orbit from
  // the switched branch (a Newton solve 105 rad/s from its nearest point, landing elsewhere at
  // other step patterns); that check now starts from the integrated orbit.
  int fast_iterations = 4;
  // ContinuationOptions::curvature_predictor for the branch (on by default): ex. 03's branch with
  // fast_iterations 4 takes 34 points and then took about 195 ms with stability (the tangent
  // predictor: 33 points, 210 ms; fast_iterations 3 and the tangent predictor: 87 points, 345 ms;
  // the first today about 120 ms, bench_nlvib_ex03.cpp BM_Ex03Period2Branch), with the same
  // ends, stable stretches and bifurcations (PeriodDoubling.Ex03BranchWithTheCurvaturePredictor...).
  bool curvature_predictor = true;
};

// Steps 1-3 of the switch at the PD bf of c (throws std::runtime_error with the reason).
struct SwitchPoint {
  BranchPoint at;                // the PD point on hb's branch (Floquet-located omega)
  Eigen::VectorXd phi_floquet;   // odd-harmonic coefficients (hbp's basis, unit norm) of the
                                 // critical Floquet eigen-solution of its corrected orbit
  BranchPoint branch_point;      // the period-2 model's own branch point on hb's branch
  Eigen::VectorXd phi;           // the null vector there of the odd block of hbp's Jacobian
                                 // (inverse iteration from phi_floquet), on hbp's basis
  double agreement = NAN;        // |phi' phi_floquet|: 1 when both see the same eigen-solution
  std::string direction;         // empty, or where phi_floquet came from when not from the
                                 // corrected orbit's eigenvector at -1 (see critical_direction)
};
SwitchPoint critical_direction(const HarmonicBalance& hb, const FrequencyCurve& c, const Bifurcation& bf,
                               const SweepOptions& opt, const PeriodDoublingOptions& pdo, const HarmonicBalance& hbp);

struct PeriodDoubledBranch {
  int period = 2;                // forcing periods of its orbits (2 x PeriodDoublingOptions::period)
  int parent = -1;               // period_doubling_cascade: the index of the branch whose PD starts it (-1: c)
  std::size_t from = 0;          // index in c.bifurcations of the PD it starts at
  double omega_start = NAN;      // forcing frequency of that PD [rad/s]
  double omega_branch_point = NAN;   // the period-2 model's branch point there (SwitchPoint) [rad/s]
  double direction_agreement = NAN;  // SwitchPoint::agreement
  std::shared_ptr<HarmonicBalance> model;   // the period-2 model
  FrequencyCurve curve;          // on the model: point omegas are Omega = omega / 2
  // How it ends: merged (at another PD of c: `to`, its index in c.bifurcations, and
  // omega_end the refined crossing [forcing rad/s]), left the range, or failed (why).
  enum class End { merged, left_range, failed } end = End::failed;
  int to = -1;
  double omega_end = NAN;
  std::string why;               // one line: where and why it ended
};

// One period-2 branch per PD of c not already reached by an earlier branch (opt: the
// options of the period-1 sweep, whose range bounds the branches). A PD outside that range (on
// a stretch the curve took beyond its start, start_excursion) is not switched: its entry says
// so, left_range, with no points (a five-planet set with teeth spent 75 s on two such branches).
std::vector<PeriodDoubledBranch> period_doubled_branches(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                         const SweepOptions& opt,
                                                         const PeriodDoublingOptions& pdo = {});

// Period-doubled branches up to period 2^depth (issue 34 §1: depth 1 period 2, 2 also period 4):
// the period-2 branches of c, then the branches from the period doublings of each branch with
// points (its model doubled again: 2^d H harmonics), level by level; `parent` the index in the
// list of the branch a PD of which starts it (-1: c); omegas are forcing frequencies. depth < 1:
// none.
std::vector<PeriodDoubledBranch> period_doubling_cascade(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                         const SweepOptions& opt, int depth,
                                                         PeriodDoublingOptions pdo = {});

// The branches of pd that have rows to write: points, each with its stability.
bool has_points(const PeriodDoubledBranch& b);
// For each bifurcation of c (the curve of pd[parent], or the period-1 curve for -1), the id
// (k + 1) of the branch pd[k] with points that it starts, -1 where none (the `starts_branch`
// column of the bifurcation table).
std::vector<int> branch_starts(const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd, int parent = -1);

// Where a curve has a stable orbit (issue 34 §4: the ranges with no stable period-1 orbit are
// the gaps of its period-1 curve's intervals). Forcing-frequency intervals, merged, in increasing
// omega: each stretch between two consecutive stable points, and where the stability changes
// between two points, from the stable one to the bifurcation located between them (the chord's
// midpoint if none is listed there); `period`: the curve's omegas are omega / period.
using Intervals = std::vector<std::pair<double, double>>;
Intervals stable_intervals(const FrequencyCurve& c, int period = 1);
// Which stable labels are resolved: c.stable, false at every point of an unresolved stretch - a
// run of consecutive stable points none of which has a converged shooting correction
// (PointFloquet::corrected; the tables' `exact` = not_converged), each point's shooting tried
// (PointFloquet::shooting: a curve whose multipliers are the variational equation's about the
// HB orbit by choice, gearhb_planetary's, tried none and keeps its labels): their multipliers are those of
// the best uncorrected iterate, so "stable" there is not established (the light-load gear's
// period-4 branch at 2088 rpm: |mu| 0.41, yet the time integration from HB's orbit is chaotic).
// A stretch with one corrected point keeps its label. A curve without Floquet data: c.stable.
std::vector<bool> resolved_stable(const FrequencyCurve& c);
// stable_intervals on the resolved labels: what a program reports as "stable at".
Intervals resolved_stable_intervals(const FrequencyCurve& c, int period = 1);
// The unresolved stretches [first, last point's omega] x period, in increasing omega.
Intervals unresolved_stable_stretches(const FrequencyCurve& c, int period = 1);
// The union of iv: overlapping or touching intervals joined, in increasing omega.
Intervals merged(Intervals iv);
// [lo, hi] less the union of `covered`: the gaps, in increasing omega (none narrower than
// 1e-9 (hi - lo)).
Intervals uncovered(double lo, double hi, Intervals covered);

// The period-1 ranges of [lo, hi] (issue 34 §4) over the period-1 curves `curves` together (one
// curve, or the continued curve and the branches through the diagram's orbits). no_stable: where
// none of them has a stable orbit whose label is resolved, the gaps of their
// resolved_stable_intervals - an unresolved stretch is not known stable, so it lies in such a
// range; unresolved: the parts of those ranges that the labels taken at face value call stable
// (stable_intervals less resolved_stable_intervals: each unresolved stretch, to the chord
// midpoints or bifurcations beside it, where no other curve is resolved-stable), reported apart.
// no_stable less unresolved are the gaps of the face-value stable_intervals.
struct Period1Ranges {
  Intervals no_stable, unresolved;
};
Period1Ranges period1_ranges(double lo, double hi, const std::vector<const FrequencyCurve*>& curves);

}  // namespace gearhb
