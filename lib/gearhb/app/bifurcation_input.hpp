#pragma once
// The `bifurcation_diagram` key that gearhb_frc's model file and gearhb_gear's gear file
// share (issue 34 §3, §4): the diagram by time integration is drawn by default under every
// frequency response with a stretch where no period-1 orbit is stable.
//
//   absent or true   the automatic bands (diagram_bands): each range with no stable period-1
//                    orbit, padded by a margin, speeds from a density with a floor and a cap;
//                    no diagram where every range is stable
//   false            no diagram
//   an object        the options of hb/bifurcation_diagram.hpp, each optional with the
//                    library's default, and two of its own:
//
//   "bifurcation_diagram": {"range": "unstable" | "whole", "margin": 0.25, "speeds": 200,
//                           "transient_periods": 400, "periods": 64, "max_period": 8,
//                           "period_tol": 1e-6, "lyapunov_periods": 200, "lyapunov_threshold": 0.02}
//
//   range   "unstable" (default): the automatic bands; "whole": one band over the file's whole
//           range (speeds default 200), with or without unstable stretches
//   margin  the bands' margin as a fraction of each range's width (DiagramBandOptions)
//   speeds  per sweep of each band (given: instead of the density rule)
//
// An option out of range is a UsageError naming the key (exit 2). And the table both
// programs write, bifurcation_diagram.csv: one row per Poincare point.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gearhb/app/output.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/orbit_branch.hpp"
#include "gearhb/hb/period_doubling.hpp"

namespace gearhb {

// How the automatic bands are laid out (diagram_bands). Each range [a, b] with no stable
// period-1 orbit is padded by max(margin (b - a), min_margin (omega_max - omega_min)) on either
// side, so that the diagram shows the period-1 motion on both sides, and clipped to [omega_min,
// omega_max]; padded ranges that overlap become one band. Speeds per sweep of a band: density x
// its width / (omega_max - omega_min), at least floor / n (n the model's DOFs, and at least
// `least`); where the bands together would take more than the cost cap, each is scaled down to
// its share of it, still at least that floor (so bands x floor bounds the cost when there are
// many). The cost cap (speeds per sweep over all bands) is a time budget over the cost of one
// speed: budget_s / (speed_s + speed_dof_s n). One speed of one sweep (the transient, 64 Poincare
// points, 200 Lyapunov periods with one tangent vector where not periodic; the library's
// defaults) cost 27.5 ms of CPU for the one-DOF light-load gear and 55 ms for its five-DOF
// bearing model (gearhb_bench --benchmark_filter=speed_cost, 2468-6000 rpm at 20 N m, 8 speeds
// a sweep, the loaded 2-core machine): about 20 ms + 7 ms a DOF, far from the old 300 ms for six
// DOFs (when the Lyapunov exponent carried the whole monodromy), so the cap no longer falls as
// 1 / n. The budget, 1.1 s of one core a sweep (the two sweeps run at once on two threads where
// the down sweep starts from HB: set_down_start), keeps the one-DOF cap at the 40 speeds it had
// and gives five DOFs 19 instead of 8, six 16 instead of 6.7.
struct DiagramBandOptions {
  double margin = 0.25;       // of the range's width, on either side
  double min_margin = 0.02;   // of the whole range, on either side (a narrow range still shows its sides)
  double density = 300.0;     // speeds per sweep over the whole range's width
  int floor = 12;             // fewest speeds per sweep of a band, for one DOF (divided by n)
  int least = 4;              // ... and never fewer
  double budget_s = 1.1;      // CPU seconds per sweep of all bands together: the cost cap
  double speed_s = 0.020;     // one speed's cost: speed_s + speed_dof_s n [s] (measured, above)
  double speed_dof_s = 0.0075;
};
// The cost cap of a model of `dofs` DOFs: most speeds per sweep over all bands (at least 1).
int diagram_speed_cap(const DiagramBandOptions& o, int dofs);

struct DiagramBand {
  double omega_lo = 0.0, omega_hi = 0.0;   // rad/s
  int speeds = 0;                          // per sweep
};

// The bands of the diagram over the curve c's ranges with no stable period-1 orbit within
// [omega_min, omega_max] (period1_ranges(omega_min, omega_max, {&c}).no_stable, as
// add_unstable_period1_ranges counts them: an unresolved stretch lies in one, so a band covers
// every stretch whose stability is not resolved), in increasing omega; empty where every range is
// stable. dofs: the model's n. speeds > 0: every band gets that many speeds instead of the density rule.
std::vector<DiagramBand> diagram_bands(const FrequencyCurve& c, double omega_min, double omega_max, int dofs,
                                       const DiagramBandOptions& o = {}, int speeds = 0);
// The band (1-based) that holds omega, 0 if none.
long band_of(const std::vector<DiagramBand>& bands, double omega);

struct BifurcationDiagramInput {
  bool on = true;               // false: "bifurcation_diagram": false
  bool given = false;           // the key is in the file (true, false or an object)
  bool whole_range = false;     // "range": "whole"
  int speeds = 0;               // the object's speeds (0: not given; then the density rule)
  DiagramBandOptions bands;     // margin from the object; the rest as stated
  BifurcationDiagramOptions options;
};

BifurcationDiagramInput read_bifurcation_diagram(const nlohmann::json& root, const std::string& file);

// --help text of the key.
std::string bifurcation_diagram_help();

// The `period_doubling` key both programs share (issue 34 §1): {"depth": 0 | 1 | 2}, absent or
// without depth: 1. 0: no branch switching; 1: a period-2 branch by harmonic balance from each
// located period doubling of every period-1 curve; 2: also a period-4 branch from each located
// period doubling of every period-2 branch (hb/period_doubling.hpp period_doubling_cascade). A
// depth out of range or another key is a UsageError naming the key (exit 2).
constexpr int max_period_doubling_depth = 2;
int read_period_doubling_depth(const nlohmann::json& root, const std::string& file);
std::string period_doubling_help();

// The rows of one diagram: the cells `lead(omega)` (the program's frequency columns), then
// sweep (up | down | from_hb: diagram_from_hb_orbits), the value scale q' x of each Poincare point, motion, n and lyapunov
// (empty where not computed). A period-n point writes its n distinct points (the others repeat
// them within period_tol), any other all its recorded points, a failed one none.
void add_bifurcation_rows(Table& t, const BifurcationDiagram& d, const Eigen::VectorXd& q, double scale,
                          const std::function<std::vector<Table::Cell>(double)>& lead);
// A stable orbit of a branch at a speed of the diagram: its base frequency Omega, unknowns X and
// its own distance to the exact orbit (hb_orbit_error; NaN where the model has no exact flow).
struct SpeedOrbit {
  double Omega;
  Eigen::VectorXd X;
  double error;
};
// The stable orbits of every branch at the speeds of a diagram's up sweep, as add_hb_section_rows
// solves them (Newton on every segment stable at both ends that brackets the speed; where the
// model has an exact flow, each corrected by shooting at the speed and kept only if stable and of
// its period): of_branch[0] the period-1 curve's, of_branch[k + 1] those of branch k of pd (empty
// for a branch without points). Computed once (section_orbits) for both add_hb_section_rows and
// diagram_from_hb_orbits: each shooting is paid once.
struct SectionOrbits {
  std::vector<std::vector<SpeedOrbit>> of_branch;
};
SectionOrbits section_orbits(const HarmonicBalance& hb, const FrequencyCurve& c,
                             const std::vector<PeriodDoubledBranch>& pd, const BifurcationDiagram& d);

// The states x at phase 0 of each of the `period` forcing periods of the orbit X of hb (hb's base
// frequency omega / period): column j at base phase 2 pi j / period, the Poincare points of a
// period-`period` motion.
Eigen::MatrixXd phase_states(const HarmonicBalance& hb, const Eigen::VectorXd& X, int period);

// The HB branch at the same section (phase 0), to draw under the Poincare points and to check
// them (bifurcation_diagram_hb.csv): the cells `lead(omega)`, then scale q' x(phase 0), its
// Floquet stability (1 | 0) and point: `branch` for every point of the branch (in continuation
// order), then `speed` for the HB orbit at each speed of the diagram's grid on every segment of
// the branch stable at both ends that brackets it (solved by Newton at that speed; where the
// model has an exact flow, corrected there by shooting and kept only if that orbit is stable and
// of its period), and hb_orbit_error: at a `speed` row, that orbit's own distance to the exact
// orbit as a bound on the value, scale sum|q_i| max_t,i |x_HB - x_exact| (empty on `branch` rows
// and without an exact flow); hb_section_columns: the lead columns, `value`, stable, point,
// hb_orbit_error.
void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c, const BifurcationDiagram& d,
                         const Eigen::VectorXd& q, double scale,
                         const std::function<std::vector<Table::Cell>(double)>& lead);
// Every branch at the same section: the period-1 curve c (period 1, branch 0), then each branch
// of pd with points (its period p, branch k + 1: the ids of the frequency-response table), the
// cells lead(omega, period, branch) first; a period-p orbit writes p rows per point and speed,
// its values at phase 0 of its p forcing periods (the Poincare points a period-p motion of the
// diagram has). The columns: hb_section_columns({<frequency columns>, "period", "branch"}, value).
using SectionLead = std::function<std::vector<Table::Cell>(double omega, int period, int branch)>;
void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c,
                         const std::vector<PeriodDoubledBranch>& pd, const BifurcationDiagram& d,
                         const Eigen::VectorXd& q, double scale, const SectionLead& lead);
// The same with the orbits at the diagram's speeds already solved (section_orbits(hb, c, pd, d)).
void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c,
                         const std::vector<PeriodDoubledBranch>& pd, const SectionOrbits& orbits,
                         const Eigen::VectorXd& q, double scale, const SectionLead& lead);
std::vector<std::string> hb_section_columns(std::vector<std::string> lead, const std::string& value);

// The diagram checked from the HB side: at every speed of d's up sweep where no sweep is on a
// stable HB orbit of period p (of c, or of a branch of pd: as add_hb_section_rows solves them;
// on it: periodic with period p, each of the orbit's p states at phase 0 within its
// hb_orbit_error (the larger of its segment's ends) plus period_tol x_scale of a sweep's state),
// one more speed started on that orbit (hb/bifurcation_diagram.hpp
// diagram_point, the sweeps' options o): does the integration stay on it (an attractor the
// sweeps did not reach: coexisting) or leave it (HB's stability is not the integration's)? The
// points, from_orbit, for add_bifurcation_rows (sweep `from_hb`); kept out of d so that its
// counts and key numbers stay the sweeps'. One timed step. `orbits`: section_orbits(hb, c, pd, d),
// solved once for this and add_hb_section_rows.
BifurcationDiagram diagram_from_hb_orbits(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c,
                                          const std::vector<PeriodDoubledBranch>& pd, const SectionOrbits& orbits,
                                          const BifurcationDiagram& d, BifurcationDiagramOptions o);

// The bands a program draws its diagram over for the curve c on [omega_min, omega_max]: the one
// band of the whole range ("range": "whole": speeds given or the library's 200), else
// diagram_bands; none when the input is off.
std::vector<DiagramBand> input_bands(const BifurcationDiagramInput& in, const FrequencyCurve& c, double omega_min,
                                     double omega_max, int dofs);

// The one line saying why no diagram is computed where the explicit time integration would be
// stiff, "" where it is not: fastest_rate(hb) x the longest period 2 pi / omega_lo above 1e4
// (about 2000 rk8pd steps a period; chapter 6's rule).
std::string diagram_stiffness(const HarmonicBalance& hb, double omega_lo);

// The down sweep's start at a band's upper end hi (BifurcationDiagramOptions::down_x0, down_v0:
// the down sweep then runs on a second thread, from the attractor that exists above): the HB
// orbit at hi on the last segment of c, in continuation order, that brackets hi and is stable
// at both ends with resolved labels (resolved_stable: a stretch labelled stable on no converged
// shooting correction is not taken for the attractor that exists above) (solved at hi by Newton from the segment's end, as add_hb_section_rows does; the
// last: where stable orbits coexist, the part of the curve that goes on toward the range's upper
// end, whence a sweep down comes). None (both emptied) where no stable segment brackets hi or
// Newton fails: the down sweep then follows the up sweep, as before. True if set.
bool set_down_start(const HarmonicBalance& hb, const FrequencyCurve& c, double hi, BifurcationDiagramOptions& o);

// The up sweep's start near omega: the index of the point of c nearest omega among those stable
// with a resolved label (resolved_stable), the nearest of all if none is.
std::size_t diagram_start(const FrequencyCurve& c, double omega);

// The diagram of every band (their points concatenated: band 1 up and down, band 2 up and down,
// ...), each band swept up from the HB orbit of c nearest its lower end among the stable points
// (diagram_start: stable with a resolved label; the nearest of all if none is) and down from
// set_down_start's orbit at its upper end where there is one, as one timed step; each band's
// sweeps with the added speeds of diagram_of_curve.
BifurcationDiagram diagram_of_bands(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c,
                                    const std::vector<DiagramBand>& bands, BifurcationDiagramOptions o,
                                    const std::string& step, const std::string& label);

// The branches a diagram orbit is compared with (hb/orbit_branch.hpp): the curve c of hb (period
// 1) and each branch of pd with points (its model, its period).
std::vector<BranchView> branch_views(const HarmonicBalance& hb, const FrequencyCurve& c,
                                     const std::vector<PeriodDoubledBranch>& pd);
// The periodic points of d that lie on none of `views` (off_every_branch), in d's order, each
// compared as the orbit it approaches: a point off every branch as recorded is polished
// (hb/bifurcation_diagram.hpp polish_periodic_point: shooting on the integration's n-period map
// from its last state, the cycle kept where it attracts and has the point's least period) and
// compared again; returned polished where that succeeded (then still off), as recorded where not.
// tol = period_tol x x_scale: the classifier's resolution (x_scale diagram_of_curve's: the curve's
// largest DOF scale).
std::vector<DiagramPoint> off_branch_orbits(const HarmonicBalance& hb, const BifurcationDiagram& d,
                                            const std::vector<BranchView>& views, double period_tol, double x_scale);
// The periodic points of d that lie on none of the branches of a run (the curve c of hb and each
// branch of pd with points: branch_views), by off_branch_orbits with tol = period_tol x the curve's
// largest DOF scale (diagram_of_bands' x_scale): found and polished once per run, for
// off_branch_key_numbers and for the branches through them (app/orbit_branches.hpp
// orbit_branches_of_diagram).
std::vector<DiagramPoint> diagram_off_branch_orbits(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                    const std::vector<PeriodDoubledBranch>& pd,
                                                    const BifurcationDiagram& d, double period_tol);
// Key numbers diagram_off_branch_period1<suffix>, diagram_off_branch_period2<suffix>: the speeds
// (both sweeps) of the diagram whose orbit of period 1 (2) lies on none of the HB branches of its
// period (`off`: diagram_off_branch_orbits, polished) with the diagram's period_tol: an HB branch
// the run has not found (gearhb_frc, gearhb_gear; ch. 6 continues Fig. 41's, hb/orbit_branch.hpp
// branch_from_orbit).
void off_branch_key_numbers(KeyNumbers& key, const std::vector<DiagramPoint>& off, const std::string& suffix);

// The diagram over [lo, hi] as a step of a program run: up from the HB orbit of c's point `start`
// (an index; out of range, the default: the curve's lowest frequency), x_scale the curve's largest
// DOF scale, timed as `step`, progress lines beginning with `label`. Each sweep visits o.speeds
// uniform speeds and, inside each range of [lo, hi] with no stable period-1 orbit on c
// (period1_ranges: an unresolved stretch in it) that holds none of them, the range's middle
// (hb/bifurcation_diagram.hpp speeds_missed), so that no such range, however narrow, goes without
// a diagram speed; diagram_of_bands does the same per band.
BifurcationDiagram diagram_of_curve(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, double lo, double hi,
                                    BifurcationDiagramOptions o, const std::string& step, const std::string& label,
                                    std::size_t start = std::size_t(-1));

// One line for the console: "bifurcation diagram over N band(s): lo-hi unit (n speeds), ...",
// in the program's unit (speed(omega)).
std::string diagram_bands_text(const std::vector<DiagramBand>& bands, const std::function<double(double)>& speed,
                               const std::string& unit);

// Key numbers of a diagram, each name ending in `suffix` ("" or "_<i>"): the speeds (both
// sweeps counted) of each motion, diagram_<motion>_speeds, the largest period seen,
// diagram_max_period, and the speeds each sweep visits beside its grid's, diagram_added_speeds (one in
// each range with no stable period-1 orbit that the grid misses: diagram_of_curve).
void diagram_key_numbers(KeyNumbers& key, const BifurcationDiagram& d, const std::string& suffix);

// One line for the console: the speeds of each motion over both sweeps, the largest period,
// and per sweep the span of speeds that are not period 1 (first to last), in the program's
// unit: `speed(omega)` and `unit` (e.g. rpm).
std::string diagram_summary(const BifurcationDiagram& d, const std::function<double(double)>& speed,
                            const std::string& unit);

// The column names after the lead ones, the value column named `value`.
std::vector<std::string> bifurcation_columns(std::vector<std::string> lead, const std::string& value);

}  // namespace gearhb
