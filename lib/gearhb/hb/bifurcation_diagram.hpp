#pragma once
// The bifurcation diagram by time integration (issue 34 §3): an independent view of the
// model the harmonic balance solves. The forcing frequency omega steps over a grid of
// `speeds` values, up from omega_min to omega_max, then down again; at each the equations
// of the HarmonicBalance model are integrated (TimeIntegrator: GSL rk8pd, the contact
// switches located exactly) from the previous speed's final state - continuation in time,
// so up and down sweeps differ where attractors coexist - a transient is discarded and the
// state at phase 0 of every forcing period (the Poincare section theta = 0 mod 2 pi) is
// recorded over `periods` periods.
//
// Classification of each speed (classify_poincare, motion_of):
//  - period-n: the smallest n <= max_period with |S_{j+n} - S_j| <= period_tol x_scale for
//    every recorded pair (S = (x, v / omega), the max norm: both halves displacements);
//  - otherwise by the largest Lyapunov exponent lambda (per forcing period, i.e. ln of the
//    mean growth factor of a tangent vector over one period), from the variational
//    equations TimeIntegrator::period_map integrates for Floquet shooting, over
//    lyapunov_periods periods from the last recorded state (fewer where it is clearly chaotic:
//    the sequential stop, lyapunov_min_periods): chaotic if lambda >
//    lyapunov_threshold; quasi-periodic if |lambda| <= lyapunov_threshold (a torus has
//    lambda = 0; a finite-time estimate scatters about it by O(1 / lyapunov_periods));
//    "unsettled" if lambda < -lyapunov_threshold (an attracting orbit the classifier did not
//    see repeat: a period above max_period or a transient longer than transient_periods);
//  - a speed not chaotic by lambda is then tried as a slowly approached cycle (beside a
//    period doubling or a fold a multiplier near the unit circle makes the approach take
//    thousands of periods): Newton shooting on the n-period map from the last state, n the
//    period with the smallest repetition error at the end of the recording (attracting_cycle).
//    If it converges (to period_tol / 100), the cycle's multipliers lie inside the unit circle
//    and the integration is approaching it, the speed is period-n (by_shooting; x, v then hold
//    the cycle's n points, lambda stays as computed).
// The library returns the states; only lib/gearhb/app writes them.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

enum class Motion { periodic, quasi_periodic, chaotic, unsettled, failed };
const char* to_string(Motion m);

struct BifurcationDiagramOptions {
  // Grid points of each sweep (up and down), uniform in omega, both ends included: 200
  // resolves a period-doubling window 1 % of the range wide by two points.
  int speeds = 200;
  // Most forcing periods discarded at each speed before the recording. The transient ends
  // earlier once the Poincare point repeats within period_tol / 100 after n <= max_period
  // periods (bifurcation_diagram.cpp says why the factor)
  // (the start is the previous speed's attractor, so a few tens of periods suffice off a
  // jump); 400 lets a mode of damping ratio 0.03 at the forcing frequency decay by
  // exp(-2 pi 0.03 400) ~ 1e-33 after a jump, and one of 0.005 by 1e-5.
  int transient_periods = 400;
  // Poincare points recorded per speed: 64 shows a period up to 8 repeating 8 times and a
  // torus or a strange attractor as a cloud of 64 points.
  int periods = 64;
  // Largest period n recognised: 8 covers the period-doubling cascade to period 8 and the
  // subharmonics of order up to 8 reported for the clearance oscillator (Kahraman & Singh 1990).
  int max_period = 8;
  // |S_{j+n} - S_j| / x_scale below which the Poincare points repeat: 1e-6 is 1e4 times the
  // integration's accuracy over a period (rel_tol 1e-10) and small enough that a torus (whose
  // points never repeat) or a slowly decaying transient is not taken for a period.
  double period_tol = 1e-6;
  // Periods of the variational integration for lambda: 200 puts the finite-time scatter of
  // a torus' lambda (~ ln(growth spread) / periods) under lyapunov_threshold.
  int lyapunov_periods = 200;
  // lambda (per forcing period) above which the motion is chaotic: 0.02 (a tangent vector
  // growing by e^4 = 55 over 200 periods); a stated, not derived, threshold.
  double lyapunov_threshold = 0.02;
  // The sequential stop, off by default (0: every estimate over lyapunov_periods, the results
  // of every program unchanged); else from this many periods on (>= 30) the estimate ends
  // early as chaotic once it clearly is: at the end of each block of 10 periods, the mean lambda' of the block means
  // (the first block left out: the tangent vector still aligning with the most unstable
  // direction) exceeds lyapunov_threshold by more than 3 standard errors of that mean (sd of
  // the block means / sqrt(their number): the batch-means error of a correlated series,
  // valid while the stretching decorrelates within a block, i.e. lambda >~ 0.1, so that a
  // clear stop is the strong chaos the classification would call chaotic after
  // lyapunov_periods anyway; near the threshold the stop is not clear and the estimate runs
  // its lyapunov_periods). Not chaotic: always lyapunov_periods. A stopped estimate's orbit is
  // integrated on without the variational equations to lyapunov_periods, so every speed's
  // dwell (what the next speed starts from) is the same as without the stop; if the last
  // 2 max_period + 1 Poincare points of that dwell repeat with a period n (a chaotic transient
  // that settled: an orbit the fixed-length estimate would have averaged down), the speed is
  // period-n with those points, else chaotic. The stopped lambda is the mean over the periods
  // done: its precision is that of the stop (3 standard errors, larger than over
  // lyapunov_periods), enough to say chaotic, not to quote to 0.05. 50 (4 block means after the
  // first) is the fewest periods at which 3 standard errors of 4 means (t, 3 degrees of
  // freedom: one-sided ~ 97.1 %) still mean something (ch. 6 uses 50). Not the default: a
  // chaotic speed's end state then differs at round-off level from the fixed-length run's (the
  // rest of its dwell is integrated without the tangent), and where the next speed has a
  // long chaotic transient (the Kahraman-Singh oscillator's period-3 window at 1.25 reached
  // from 1.3) whether it settles within the dwell changes with it. Source: batch means, e.g. Law & Kelton, Simulation Modeling and
  // Analysis, ch. 9; the torus' linear tangent growth (lambda_k ~ ln k / k, block means
  // falling) inflates the scatter and does not stop.
  int lyapunov_min_periods = 0;
  // Speeds added to each sweep's grid [rad/s], visited in increasing omega with the grid's (those
  // outside (omega_min, omega_max), on a grid speed or not finite are ignored). Empty (the default):
  // the grid alone. The rule for callers holding an HB curve (app/bifurcation_input.hpp
  // diagram_of_bands, diagram_of_curve): speeds_missed over its ranges with no stable period-1
  // orbit, so that the diagram says what the motion is in every such range, however narrow.
  std::vector<double> added_speeds;
  // The integration (tolerances; x_scale: the typical displacement, the unit of period_tol).
  TimeIntegrationOptions integration;
  // The down sweep's start at omega_max (x, v at phase 0; one value per dof each), or empty
  // (the default). Empty: the down sweep starts from the up sweep's end state, after it (one
  // thread). Given: from this state, the two sweeps on two threads (std::thread) at once. The
  // rule for callers holding an HB curve: the orbit of its stable point at the band's upper end
  // (hb_initial_state), if the curve has one there; else empty. Either way the view stays a
  // hysteresis view: the up sweep follows the attractor reached from below, the down sweep the
  // one that exists above (an attractor at omega_max, by the integration's own transient).
  Eigen::VectorXd down_x0, down_v0;
};

struct DiagramPoint {
  double omega = 0.0;
  bool up = true;                  // the sweep: up (omega rising) or down
  bool from_orbit = false;         // not a sweep's: one speed started on a given orbit (diagram_point)
  bool added = false;              // a speed of added_speeds, not of the grid
  Motion motion = Motion::failed;
  int n = 0;                       // the period (periodic), else 0
  double lyapunov = NAN;           // per forcing period (computed if not periodic), else NaN
  int lyapunov_periods = 0;        // periods lambda took (<= the options' lyapunov_periods: the sequential stop)
  int transient = 0;               // periods discarded
  bool by_shooting = false;        // periodic by attracting_cycle (a slow approach), not by repetition
  Eigen::MatrixXd x, v;            // Poincare states: (periods + 1) x dofs (a settled chaotic transient: 2 max_period + 1)
  std::string failure;             // why, if motion == failed
};

struct BifurcationDiagram {
  std::vector<DiagramPoint> points;   // the up sweep, then the down sweep
};

// The sweep up from (x0, v0) at phase 0 and omega_min over sweep_speeds (the grid and
// opt.added_speeds: N speeds); the sweep down from opt.down_x0, down_v0
// at omega_max on a second thread if given, else from the up sweep's end after it. progress
// (optional) is called after every speed with the point and its index (0-based, over both
// sweeps: up 0 .. N - 1, down N .. 2 N - 1), from either thread, one call at a
// time. Throws std::invalid_argument for options out of range
// (check_bifurcation_options).
BifurcationDiagram bifurcation_diagram(const HarmonicBalance& hb, double omega_min, double omega_max,
                                       const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                       const BifurcationDiagramOptions& opt,
                                       const std::function<void(const DiagramPoint&, int)>& progress = {});

// The speeds of one sweep: the grid of `speeds` values uniform over [omega_min, omega_max], both
// ends included, and added_speeds as BifurcationDiagramOptions says, in increasing omega.
std::vector<double> sweep_speeds(double omega_min, double omega_max, int speeds, const std::vector<double>& added);

// The speeds that a grid of `speeds` uniform values over [omega_min, omega_max] (both ends
// included) leaves out of `ranges` (forcing-frequency intervals [a, b]): for each range, clipped
// to [omega_min, omega_max], that holds no grid speed, its middle (a + b) / 2; in the ranges' order.
std::vector<double> speeds_missed(double omega_min, double omega_max, int speeds,
                                  const std::vector<std::pair<double, double>>& ranges);

// One speed classified as a sweep's (the same transient, recording, classification and
// Lyapunov estimate), started from (x0, v0) at phase 0 rather than from the previous speed's
// attractor: started on a stable HB orbit that neither sweep reached, it says whether that
// orbit attracts the integration (a coexisting attractor) or not. from_orbit is set.
DiagramPoint diagram_point(const HarmonicBalance& hb, double omega, const Eigen::VectorXd& x0,
                           const Eigen::VectorXd& v0, const BifurcationDiagramOptions& opt);

// The option out of range, by its key ("speeds", "transient_periods", "periods",
// "max_period", "period_tol", "lyapunov_periods", "lyapunov_min_periods", "lyapunov_threshold"),
// and why; "" if none.
std::string check_bifurcation_options(const BifurcationDiagramOptions& opt, std::string* why = nullptr);

// The smallest n in 1..max_period with |S_{j+n} - S_j| <= tol for all recorded pairs (S = (x,
// v / omega), rows of xs, vs; max norm), else 0.
int poincare_period(const Eigen::MatrixXd& xs, const Eigen::MatrixXd& vs, double omega, int max_period, double tol);

// The attracting cycle that the recorded Poincare states of p (and the later state x_end,
// v_end) approach, by Newton shooting on the n-period map (see the top of this file): its
// least period n, its n states in cx, cv (rows; the first the one nearest the end state); 0 if
// there is none. tol: period_tol x_scale.
int attracting_cycle(const TimeIntegrator& ti, const DiagramPoint& p, const Eigen::VectorXd& x_end,
                     const Eigen::VectorXd& v_end, int max_period, double tol, const TimeIntegrationOptions& opt,
                     Eigen::MatrixXd& cx, Eigen::MatrixXd& cv);

// Newton shooting on the n-period map (TimeIntegrator::period_map with its monodromy, n times)
// from (x, v) at phase 0, at most 12 steps, until the state repeats after n periods within
// 1e-2 tol in (x, v / omega): true if it converged, (x, v) then the fixed point, the rows of xs,
// vs the states after 1..n periods from it and `modulus` the largest multiplier modulus of its
// n-period monodromy. attracting_cycle's shooting.
bool shoot_cycle(const TimeIntegrator& ti, double omega, int n, double tol, const TimeIntegrationOptions& opt,
                 Eigen::VectorXd& x, Eigen::VectorXd& v, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs, double& modulus);

// A periodic point of a diagram (motion periodic, period n) as the orbit it approaches rather
// than its last recorded states: the classifier takes a speed as period n once its Poincare
// states repeat within tol, but where a multiplier lies near the unit circle (beside a period
// doubling or a fold) the transient decays slowly and the recorded states may still lie many tol
// from the orbit (gearhb_frc's examples/clearance_oscillator.json at omega 0.337519, just past
// its period doubling: tests/unit/test_polish_periodic_point.cpp). shoot_cycle from its
// last recorded state; where it converges to a cycle that attracts (every multiplier inside the
// unit circle) and whose least period is n, p.x and p.v become that cycle's n states (the first
// the fixed point near the last recorded state) and the call returns true; otherwise p is left
// as it was (false). tol: period_tol x x_scale, as the classifier's.
bool polish_periodic_point(const TimeIntegrator& ti, DiagramPoint& p, double tol, const TimeIntegrationOptions& opt);

// The largest Lyapunov exponent per forcing period of the orbit through (x0, v0) at phase 0:
// (1 / periods) sum_k ln |Phi_k w_k| with w_k the tangent vector renormalised every period (in
// (x, v / omega)), Phi_k the period map's monodromy, applied to w_k alone
// (TimeIntegrator::tangent_map: 2n variational equations, not the monodromy's 4n^2). x_end,
// v_end (if not null) receive the state after the periods.
double largest_lyapunov_exponent(const TimeIntegrator& ti, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                 double omega, int periods, const TimeIntegrationOptions& opt,
                                 Eigen::VectorXd* x_end = nullptr, Eigen::VectorXd* v_end = nullptr);

// The `count` (1..2 dofs) largest Lyapunov exponents per forcing period of the same orbit,
// largest first, by the variational equations with re-orthonormalisation every period
// (Benettin, Galgani, Giorgilli & Strelcyn, Meccanica 15 (1980) 9): the tangent vectors W (in
// (x, v / omega)) mapped by Phi_k and made orthonormal again by modified Gram-Schmidt (W =
// QR), lambda_j = (1 / periods) sum_k ln R_jj; the count tangent vectors are carried by
// TimeIntegrator::tangent_map (2n x count variational equations). The first tangent vector
// starts as the one above (count = 1 is largest_lyapunov_exponent; with more vectors the step
// control sees more equations, so on a chaotic orbit the two estimates are two samples, not the
// same number); the others start along the unit vectors. section (if given) is called with the state after every period; logs (if not null)
// receives ln R_jj of every period (periods done x count), to judge the estimate's convergence.
// stop (if given) is called after every period with that period's ln R_jj; true ends the
// estimate there (the exponents then average the periods done, periods_done receives their
// number).
std::vector<double> lyapunov_exponents(
    const TimeIntegrator& ti, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, int periods,
    int count, const TimeIntegrationOptions& opt, Eigen::VectorXd* x_end = nullptr, Eigen::VectorXd* v_end = nullptr,
    const std::function<void(const Eigen::VectorXd&, const Eigen::VectorXd&)>& section = {},
    Eigen::MatrixXd* logs = nullptr, const std::function<bool(const Eigen::VectorXd&)>& stop = {},
    int* periods_done = nullptr);

}  // namespace gearhb
