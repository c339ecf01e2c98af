#pragma once
// Quasi-periodic motion past a Neimark-Sacker (NS) point by a two-frequency harmonic
// balance (issue 34 §2).
//
// Past an NS point of a period-1 branch the motion lies (near it) on a torus: x(t) =
// x(theta1, theta2) with theta1 = omega t (the forcing) and theta2 = omega2 t, omega2 the
// second frequency, unknown. The torus is a real Fourier series in both angles,
//
//   x = X_0 + sum_(k1, k2) X_c(k1,k2) cos(k1 theta1 + k2 theta2) + X_s(k1,k2) sin(...),
//
// over the half plane of pairs (k1, k2): k1 = 0 with k2 = 1..H2, and k1 = 1..H1 with k2 =
// -H2..H2 (P = H2 + H1 (2 H2 + 1) pairs; each pair's frequency w = k1 omega + k2 omega2),
// stored pair-major as HarmonicBalance stores harmonics: X = [X_0 (n), X_c1 (n), X_s1 (n),
// ...]. The pairs with k2 = 0 are the period-1 orbit's harmonics: a period-1 HB point with
// H1 harmonics is a torus of zero amplitude. The residual is the Galerkin projection on the
// same basis: per pair (K - w^2 M) X_c + w C X_s + F_c - f, (K - w^2 M) X_s - w C X_c + F_s.
//
// The contact forces (AFT on the 2-D grid, as on the 1-D grid): on each of N2 uniform lines
// theta2 = theta2_j the torus restricted to the line is a 1-D series in theta1 with H1
// harmonics; its contact intervals and the projection of the piecewise-linear law are
// computed exactly on it (contact.hpp: the crossings located on the trigonometric
// polynomial, the indicator's moments in closed form), and the lines are averaged (the
// trapezoid rule in theta2, spectrally accurate for the smooth part; the lines sample the
// second angle as the classic AFT samples the first). The Jacobian is exact for this
// residual: the mean over the lines of S_j' D^-1 kc G_j S_j (S_j the restriction to line j,
// G_j that line's product matrix of the contact indicator).
//
// The torus is invariant under a shift of theta2; the phase condition
// (d X_ref / d theta2)' X = 0 fixes it (X_ref the predictor), and omega2 is an unknown.
//
// The switch at an NS point of the curve c (torus_branch):
//  1. the NS point: the chord point at the located omega corrected onto the period-1 branch;
//  2. its Floquet multipliers on the corrected orbit (floquet.hpp) and the complex eigenvector
//     e of the critical multiplier mu = exp(i alpha), 0 < alpha < pi;
//  3. the eigen-solution dx(t) over one forcing period (central differences of the exact
//     flow from the corrected state +- delta Re e, +- delta Im e): dx(t + T) = mu dx(t), so
//     p(t) = exp(-i alpha t / T) dx(t) is T-periodic, and Re(exp(i theta2) p(theta1)) with
//     omega2 = alpha omega / (2 pi) is the torus' first-order shape (pairs (k1, +-1));
//  4. the first point: period-1 point + eps times that shape (eps: a fraction `amplitude` of
//     the orbit's size), corrected with omega and omega2 free and the amplitude held (its
//     projection on the shape); the second at 2 eps (if these fail, again at eps / 5 and eps /
//     25: at an NS point where the orbit grazes the contact - the example's lower NS point at
//     0.59939, contact onset at 0.59936, the orbit 1e-4 of the gap into contact - the
//     first-order shape, the linearisation about an orbit that barely touches, holds only for
//     tori that do not reach far past the contact's edge; there eps = 0.005 fails and eps / 5
//     converges); then pseudo-arc-length continuation in
//     the scaled unknowns [X / x_scale, omega2 / omega_scale, omega / omega_scale] with a
//     secant predictor (a corrected point farther than half the step from its predictor is
//     refused and the step halved: it jumped to another part of the solution set);
//  5. it ends where the torus shrinks back onto the period-1 orbit (its quasi-periodic part
//     below a quarter of the first point's or a tenth of the largest so far: it merged at
//     another NS), where it leaves the
//     range, or where the corrector fails (the torus breaks down or phase-locks: HB cannot
//     follow it; the reason kept, the rest of the run stands).
// Omega2 at the first point is not set from alpha: the corrector finds it from the 2-D
// equations, so omega2 at small amplitude against alpha omega / (2 pi) checks both (tests).
// Stability of the torus (torus_stability, the section "Stability" below): by the flow, not by
// HB. Models with a time-varying contact stiffness or a
// forcing on another harmonic than the first are refused (the reason says so).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

// The two-frequency harmonic-balance model of hb's equations.
class TorusBalance {
 public:
  // H1 harmonics of omega (1..hb's H), H2 of omega2 (>= 1), N2 lines in theta2 (0: 4 (2 H2 + 1)).
  TorusBalance(const HarmonicBalance& hb, int H1, int H2, int N2 = 0);
  int size() const { return n_ * basis(); }
  int basis() const { return 2 * pairs() + 1; }   // 1 + 2 P
  int pairs() const { return H2_ + H1_ * (2 * H2_ + 1); }
  int dofs() const { return n_; }
  int harmonics1() const { return H1_; }
  int harmonics2() const { return H2_; }
  int lines() const { return N2_; }
  int k1(int pair) const;   // pair 1..P (0: the static term)
  int k2(int pair) const;
  const HarmonicBalance& model() const { return hb_; }

  // R(X, omega, omega2), and if asked its Jacobian in X and derivatives in omega, omega2.
  void evaluate(const Eigen::VectorXd& X, double omega, double omega2, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX,
                Eigen::VectorXd* dRdomega, Eigen::VectorXd* dRdomega2) const;
  // d X / d theta2 (the phase condition's row).
  Eigen::VectorXd theta2_derivative(const Eigen::VectorXd& X) const;
  // A period-1 point of hb (its harmonics up to H1) as a torus of zero amplitude.
  Eigen::VectorXd from_periodic(const Eigen::VectorXd& X1) const;
  // X with the pairs k2 = 0 zeroed: the quasi-periodic part.
  Eigen::VectorXd quasi_periodic_part(const Eigen::VectorXd& X) const;
  // The 1-D coefficients (2 H1 + 1) in theta1 of the coordinate q' x on the line theta2.
  Eigen::VectorXd line(const Eigen::VectorXd& X, const Eigen::VectorXd& q, double theta2) const;
  // q' x at (theta1, theta2).
  double value(const Eigen::VectorXd& X, const Eigen::VectorXd& q, double theta1, double theta2) const;

 private:
  const HarmonicBalance& hb_;
  int n_, H1_, H2_, N2_;
  std::vector<Eigen::MatrixXd> S_;   // per line: (2 H1 + 1) x basis restriction
  Eigen::MatrixXd restriction(double theta2) const;
  void add_sandwich(int j, const Eigen::MatrixXd& DG, Eigen::MatrixXd& J) const;
  void linear_terms(const Eigen::VectorXd& X, double omega, double omega2, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX,
                    Eigen::VectorXd* dRdomega, Eigen::VectorXd* dRdomega2) const;
  void contact_terms(const Eigen::VectorXd& X, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX) const;
};

// Measures of a torus point on the output coordinate q' x.
struct TorusMeasures {
  double x_max = NAN, x_min = NAN;   // over the torus (exact along theta1, `lines` lines in theta2)
  double x_qp_rms = NAN;             // RMS over the torus of the quasi-periodic part (pairs k2 != 0)
  // q'x on the Poincare section theta1 = 0 (the states once per forcing period lie on this
  // closed curve): its least and largest value over theta2 (`lines` samples)
  double section_min = NAN, section_max = NAN;
};
TorusMeasures torus_measures(const TorusBalance& tb, const Eigen::VectorXd& X, const Eigen::VectorXd& q,
                             int lines = 256);

struct TorusOptions {
  int harmonics1 = 10;       // H1 (at most the model's H)
  int harmonics2 = 4;        // H2
  int lines = 0;             // N2 (0: 4 (2 H2 + 1))
  double amplitude = 0.005;  // eps of the first point: its quasi-periodic part over the orbit's size
  double ds_max = 0.05;      // scaled arc length per step, at most
  double ds_min = 1e-6;
  int max_points = 200;
  double tolerance = 1e-9;   // Newton: max |R| / r_scale and max scaled step
  int max_iterations = 12;
};

// Stability. The test is the flow's, independent of HB: the two largest Lyapunov exponents
// (per forcing period; bifurcation_diagram.hpp lyapunov_exponents: variational equations,
// GSL rk8pd with exact contact switching, Gram-Schmidt re-orthonormalisation every period) of
// the orbit started on the HB torus at (theta1, theta2) = (0, 0), and the drift of its Poincare
// points from the HB torus' section curve. On the Poincare map an attracting torus is an
// attracting invariant circle: lambda1 = 0 (along the circle) and lambda2 < 0; a tangent
// vector that grows (lambda1 > 0) says the orbit from the torus is not attracted onto it. The
// verdict, from the exponents of either half of the periods (lambda_j^a over the first, ^b over
// the second; a verdict needs both halves to agree, so a transient - e.g. a chaotic one that
// ends on a cycle - is not read as a torus):
//  - unstable if lambda1^a and lambda1^b > threshold (a tangent vector keeps growing: a saddle
//    torus, or the orbit left it for chaos);
//  - stable if lambda1^a, lambda1^b <= threshold, lambda2^a, lambda2^b < -threshold and the
//    drift is at most drift_tol (the orbit stays on the HB torus and its neighbourhood contracts
//    onto it; lambda1 < -threshold as well: the flow on the torus locks onto a cycle on it);
//  - unresolved otherwise: the halves disagree (a transient: measured on the example at omega
//    0.6083, lambda1 0.12 over the first 200 periods and -0.14 over the next 200, where the
//    bifurcation diagram's sweep sees chaos), lambda2 >= -threshold (a second neutral direction
//    within the finite-time error: near the NS point, where the torus attracts weakly), or a
//    drift above drift_tol (the flow settles, but not on the HB torus: near the NS point the HB
//    torus' own error, e.g. its NS point off the exact one by 2.3e-4 rad/s at H1 = 21 on the
//    example, is of the order of the torus' size).
// Finite-time error: the estimate of a zero exponent along the circle is O(1 / periods) (the
// log of the ratio of tangent lengths at two points of the circle over the periods; measured on
// the example's torus at omega 0.6124: lambda1 = 0.0156, 6.3e-3, 4.6e-3, 1.4e-3 at 200, 400, 800,
// 1600 periods, lambda2 -0.435, -0.430, -0.432, -0.433), that of a nonzero one converges as
// O(1 / sqrt(periods)) where the motion is chaotic. 400 periods put the example's tori within a
// third of the threshold 0.02 (the bifurcation diagram's lyapunov_threshold).
struct TorusStabilityOptions {
  int every = 5;              // every k-th point of a branch (0, k, 2k, ...) and its last; 0: none
  int periods = 400;          // forcing periods of the variational integration (gearhb_frc: 10..10000)
  double threshold = 0.02;    // per forcing period; stated, not derived (see above)
  // the drift: the largest distance (max norm in (x, v / omega)) of the orbit's Poincare points
  // from the HB section curve (sampled at 256 values of theta2), over that curve's half-width
  // (its largest distance from its mean point). 0.5: the orbit stays within half the torus' size
  // of the HB torus; HB's own error (H1 = 21, H2 = 4) on the example's stable tori gives 0.11
  // and 0.17 (test_quasi_periodic), a margin of 3
  double drift_tol = 0.5;
  TimeIntegrationOptions integration;   // tolerances; x_scale: the curve's displacement scale
};

struct TorusStability {
  bool computed = false;
  enum class Verdict { stable, unstable, unresolved } verdict = Verdict::unresolved;
  double lyapunov1 = NAN, lyapunov2 = NAN;   // per forcing period
  Eigen::Vector2d half1 = Eigen::Vector2d::Constant(NAN), half2 = Eigen::Vector2d::Constant(NAN);   // per half
  double drift = NAN;                         // over the section curve's half-width
  std::string failure;                        // the integration failed: why (verdict unresolved)
};

struct TorusPoint {
  double omega = 0.0, omega2 = 0.0;   // [rad/s]
  Eigen::VectorXd X;
  int iterations = 0;
  double residual = 0.0;              // scaled, at convergence
  TorusStability stability;           // computed on a subset (add_torus_stability)
};

struct TorusBranch {
  std::size_t from = 0;        // index in c.bifurcations of its NS point
  double omega_ns = NAN;       // that NS point's omega [rad/s]
  double alpha = NAN;          // angle of its critical multiplier, in (0, pi)
  double omega2_ns = NAN;      // alpha omega_ns / (2 pi): the Floquet second frequency [rad/s]
  std::vector<TorusPoint> points;
  enum class End { merged, left_range, failed, max_points } end = End::failed;
  double omega_end = NAN;      // last point's omega
  int to = -1;                 // merged: index in c.bifurcations of the NS nearest to omega_end
                               // (-1 if its own NS point is nearer: it came back to where it began)
  std::string why;             // one line: where and why it ended
};

// The torus branch from the NS point c.bifurcations[index] of hb's curve c (opt: the sweep's
// options: range, scaling). tb: the torus model (H1, H2, lines of `to`). Never throws for a
// failed switch: `why` says where and why, points may be empty.
TorusBranch torus_branch(const TorusBalance& tb, const FrequencyCurve& c, std::size_t index, const SweepOptions& opt,
                         const TorusOptions& to);

// The torus at a given omega, corrected by Newton (omega fixed, omega2 free, phase condition)
// from a nearby point of a branch (guess); s: the scaling of the curve it came from. Throws
// std::runtime_error if Newton does not converge.
TorusPoint torus_point_at(const TorusBalance& tb, const TorusPoint& guess, double omega, const Scaling& s,
                          const TorusOptions& to = {});

// Every NS point of c (located, smooth) with its torus branch, in curve order; an NS point
// where an earlier branch merged (`to`) is not switched again (the same torus).
std::vector<TorusBranch> torus_branches(const TorusBalance& tb, const FrequencyCurve& c, const SweepOptions& opt,
                                        const TorusOptions& to);

// The state (x, v) of the torus X at the angles (theta1, theta2): v = omega dx/dtheta1 +
// omega2 dx/dtheta2.
void torus_state(const TorusBalance& tb, const Eigen::VectorXd& X, double omega, double omega2, double theta1,
                 double theta2, Eigen::VectorXd& x, Eigen::VectorXd& v);

// The stability of the torus point p (the section "Stability" above). Never throws for a
// failed integration: failure says why, the verdict stays unresolved.
TorusStability torus_stability(const TorusBalance& tb, const TorusPoint& p, const TorusStabilityOptions& so);

// torus_stability at the points 0, every, 2 every, ... and the last of b (none if every = 0).
void add_torus_stability(const TorusBalance& tb, TorusBranch& b, const TorusStabilityOptions& so);

// Branch ids (one numbering with the period-doubled branches: frc.csv's and bifurcations.csv's
// `branch`): the torus branch br[k] is branch first_id + k (gearhb_frc: first_id = the number of
// period-doubled branches + 1, so 0 is the period-1 curve, 1..P the period-doubled branches in
// their order, P + 1, ... the torus branches in the order of their NS points). starts: per
// bifurcation of the curve the id of the branch it starts (-1: none, as branch_starts gives it);
// each NS point whose torus branch has points gets that branch's id.
void add_torus_starts(std::vector<int>& starts, const std::vector<TorusBranch>& br, int first_id);

// The option out of range ("harmonics1", "harmonics2", "lines", "amplitude", "max_points") for
// a model of H harmonics, with why; "" if none.
std::string check_torus_options(const TorusOptions& to, int H, std::string* why = nullptr);

}  // namespace gearhb
