#pragma once
// The standard tables a frequency sweep is written as (README "Output files"):
// the numerics (hb/) return results; this application-layer module turns them
// into CSV tables.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/core/units.hpp"
#include "gearhb/app/output.hpp"
#include "gearhb/app/schema.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/quasi_periodic.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/period_doubling.hpp"

namespace gearhb {

// The frequency-response table: omega, x_max, x_min, x_rms_ac, x_h1, x_mean,
// stable, contact for the coordinate q' x, one row per point, in continuation order.
Table frequency_response_table(const HarmonicBalance& hb, const Branch& b,
                               const std::vector<bool>& stable, const Eigen::VectorXd& q);

// The `period` and `branch` columns of a table: 1 and 0 for the main (period-1) branch, 2 and
// the branch's id for a period-2 branch (period_doubling.hpp; then hb is its period-2 model,
// c's omegas its base frequency, and omega is written as the forcing frequency, period x that).
struct BranchLabel {
  int period = 1;
  int branch = 0;
};

// The common columns of every frequency-response table of a curve (lib/README "Output
// files"), for the coordinate q' x, one row per point in continuation order:
//   omega, x_max, x_min, x_rms_ac, x_h1, x_mean, stable, contact   (the HB orbit),
//   floquet_modulus, floquet_angle (the critical multiplier |mu|, arg mu), hb_orbit_error
//   (max |x_HB - x_exact| over the period, floquet.hpp),
//   x_max_exact, x_min_exact, x_rms_ac_exact, x_h1_exact, x_mean_exact (the same measures
//   of the exact orbit, exact_orbit.hpp), exact (ok | not_converged | inconsistent |
//   unavailable | lower_period: ExactStatus), period, branch (BranchLabel below: 1, 0 for a period-1 curve);
// cells are empty where a value does not exist (no Floquet stability; no corrected
// orbit for a time-varying stiffness; exact != ok). Each row follows its point's exact
// orbit: `progress` (if given) is called before each row with its point (e.g. to show
// progress, RowProgress).
using RowProgress = std::function<void(std::size_t point)>;
// The frequency columns a table starts with (app/schema.hpp): omega alone, or a gear mesh's
// omega, f_mesh_hz (and speed_rpm of gear 1, z1 = teeth_1).
struct ResponseLayout {
  FrequencyAxis axis = FrequencyAxis::omega;
  double teeth_1 = 0.0;
};
Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& q,
                               const RowProgress& progress = {});
// The same with a program's own columns after the common ones: `extra` names them and
// `extra_row(i)` gives point i's cells; `contact_label(i)`, if given, is point i's `contact`
// in the program's vocabulary (e.g. a gear mesh's full | drive_loss | back_impact | ...);
// `label` the rows' period and branch (a period-2 branch: hb its period-2 model).
Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& q,
                               const std::vector<std::string>& extra,
                               const std::function<std::vector<Table::Cell>(std::size_t)>& extra_row,
                               const std::function<std::string(std::size_t)>& contact_label = {},
                               const RowProgress& progress = {}, const BranchLabel& label = {},
                               const ResponseLayout& layout = {});
// The frequency response of a model file (gearhb_frc): the common columns for the output
// coordinate, then q<i>_max, q<i>_min, q<i>_h1 for every DOF i = 1..n, then
// q<i>_max_exact, q<i>_min_exact, q<i>_h1_exact, then contact_<j> for every contact j =
// 1..P: its own state over the period (open, full, intermittent; `contact` is the summary
// over all of them).
Table dof_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& output,
                         const RowProgress& progress = {}, const BranchLabel& label = {});

// The bifurcations of a curve: type, omega, multiplier_re, multiplier_im, modulus,
// located (1: on the chord; 0: a corrector failed there, the values are the next point's),
// smooth (1: the crossing multiplier is on the unit circle to 1e-2 there; 0: it jumps across),
// period, branch (the branch the event lies on, BranchLabel; omega written as the forcing
// frequency), starts_branch (the id of the branch the event starts: the period-doubled branch of
// a PD, the torus branch of an NS point; starts[i] for bifurcation i, empty where none or
// `starts` is empty).
Table bifurcation_table(const FrequencyCurve& c, const BranchLabel& label = {}, const std::vector<int>& starts = {});

// A curve with the period-doubled branches switched at its period doublings (`pd`,
// hb/period_doubling.hpp period_doubling_cascade): the curve's rows (period 1, branch 0), then
// those of each branch pd[k] with points on its own model (its period, branch k + 1; x_max and
// x_min over its period); the bifurcations of every curve, `starts_branch` naming the branch
// each PD starts.
Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c,
                               const std::vector<PeriodDoubledBranch>& pd, const Eigen::VectorXd& q,
                               const RowProgress& progress = {}, const ResponseLayout& layout = {});
Table bifurcation_table(const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd);

// The harmonic-balance vs time-integration comparison, one row per compared point:
// check_columns(omega, {"x_max"}) (app/schema.hpp).
Table time_integration_table(const TimeIntegrationCheck& check);

// torus.csv (issue 34 §2, hb/quasi_periodic.hpp): one row per point of each torus branch:
// branch (its id, first_id + k for branches[k]: one numbering with frc.csv's branches,
// add_torus_starts), omega_ns (its NS point) [rad/s], omega
// [rad/s], omega2 (the second frequency, in (0, omega/2] up to relabelling) [rad/s], rotation
// (omega2 / omega), x_max, x_min (the output coordinate q'x over the torus), x_qp_rms (RMS of
// its quasi-periodic part, the pairs k2 != 0), section_min, section_max (q'x on the Poincare
// section theta1 = 0 mod 2 pi, the closed curve the once-per-period states lie on), residual
// (scaled, at convergence), stable (1 stable, 0 unstable by the flow's test,
// hb/quasi_periodic.hpp torus_stability; empty where not computed or unresolved), lyapunov1,
// lyapunov2 (the two largest Lyapunov exponents per forcing period) and drift (of the flow's
// Poincare points from the HB section curve, over its half-width), empty where not computed.
Table torus_table(const TorusBalance& tb, const std::vector<TorusBranch>& branches, const Eigen::VectorXd& q,
                  int first_id = 1);

// The gear-mesh chapters (8, 9): a frequency curve of the 1-DOF mesh model: omega,
// f_mesh_hz, then the common columns of the mesh deflection (app/schema.hpp); the rows of
// the period-doubled branches pd after the curve's, as frequency_response_table above.
Table mesh_response_table(const HarmonicBalance& hb, const FrequencyCurve& c,
                          const std::vector<PeriodDoubledBranch>& pd = {});
}  // namespace gearhb
