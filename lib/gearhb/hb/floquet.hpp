#pragma once
// Floquet multipliers of a harmonic-balance orbit on the exact flow.
//
// The equation (harmonic_balance.hpp) is linear between contact switches:
// with S the set of closed contacts,
//   M x'' + C x' + (K + sum_{i in S} kc_i n_i n_i') x
//       = f0 + fc cos(omega t) + fs sin(omega t) - sum_{i in S} kc_i n_i g_i(omega t).
// Augmenting the state with the oscillators [1, cos k omega t, sin k omega t] of the
// forcing (k = 1) and of the gap harmonics that are present, z = [x, v, 1, c_k, s_k],
// gives z' = A_S z with A_S constant, so the flow over a time h is exactly
// exp(A_S h) z (Eigen's MatrixFunctions). The switch times are the roots of
// u_i(t) = r_i' exp(A_S t) z (u_i = g_i + n_i' x), found by a safeguarded Newton
// iteration on that exact solution. The vector field is continuous (max(kc u, 0)
// is continuous in x), so no saltation matrix is needed: the monodromy matrix is
// the product of the (x, v) blocks exp(A_S^xv h) of the segments (A_S is block upper
// triangular, so that block of the augmented exponential is the exponential of the
// (x, v) block).
//
// The HB state at finite H is not the true orbit. floquet_of_hb_orbit first
// corrects it by Newton's method on the shooting equations P(y) - y = 0 (P the
// exact period map, dP/dy = the monodromy matrix), then takes the multipliers of
// the corrected orbit. The largest distance between the HB and the corrected orbit
// over the period is an a-posteriori error of the HB point.
//
// For a smooth time-varying stiffness (a parametric model) there is no exact flow:
// floquet_of_hb_shooting_gsl corrects the orbit the same way on GSL's rk8pd period map.
// `monodromy_linear_periodic` integrates the variational equation Phi' = A(t) Phi over
// one period, segment by segment between optional breakpoints where A may jump.
#include <complex>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct FloquetOptions {
  int max_newton = 8;          // shooting Newton steps
  double tolerance = 1e-10;    // on |P(y) - y|: displacements / x_scale, velocities / (omega x_scale)
  int steps = 0;               // uniform grid steps per period (0: max(64, 2 (2H+1)))
  double stability_margin = 0.0;   // stable iff max |multiplier| < 1 - margin
  // false: floquet_of_hb_orbit takes the multipliers of the variational equation about the
  // HB orbit itself (floquet_of_hb_variational, not corrected), where a corrected orbit costs
  // too much at every point of a sweep (a planetary set's 24 DOFs on GSL's period map: about
  // 3 s a point against 0.08 s; programs/gearhb_planetary).
  bool correct_orbit = true;
  // The absolute and relative error per step of GSL's rk8pd on the monodromy matrix of that
  // variational equation (it starts at the identity: its entries are O(1)). 1e-6, measured
  // against 1e-11: the star set's (programs/gearhb_planetary/examples/gtf_star_five_planets.json)
  // largest multiplier moduli move by at most 6e-10 on all 134 points (stability 2.4 -> 1.4 s);
  // on the loaded Lin-Parker set over 1800-2350 Hz (70 points, 13 bifurcations: folds, branch
  // points, Neimark-Sacker) the moduli by at most 2.1e-6, every point's stability and every
  // bifurcation's type the same, located within 2e-4 rad/s of 14 000 (105 -> 53 s).
  double variational_tolerance = 1e-6;
};

struct FloquetResult {
  Eigen::VectorXcd multipliers;      // the 2n Floquet multipliers, largest modulus first
  std::complex<double> critical;     // the largest in modulus
  double modulus = 0.0, angle = 0.0; // |critical|, arg(critical) in (-pi, pi]
  bool stable = false;
  bool corrected = false;            // the shooting Newton converged
  // a shooting Newton ran (false: the multipliers of the variational equation about the HB
  // orbit, FloquetOptions::correct_orbit = false, no correction tried)
  bool shooting = false;
  int newton_steps = 0;
  double shooting_residual = 0.0;    // scaled |P(y) - y| of the orbit whose multipliers are returned
  double orbit_error = 0.0;          // max over the period and DOFs of |x_HB - x_exact| [units of x]
  Eigen::VectorXd x0, v0;            // corrected state at phase 0
  Eigen::MatrixXd monodromy;         // 2n x 2n
  // A period-p model's orbit (Excitation::harmonic p > 1: p forcing periods) whose corrected
  // orbit repeats after one forcing period: max_t |x(t + T/p) - x(t)| below 1e-2 of the HB
  // orbit's own (on the uniform nodes, M a multiple of p; the HB orbit's above 1e-9 of
  // x_scale). No exact orbit of period p lies there - the shooting found the period-1 orbit
  // (ch. 6 Fig. 43's period-2 branch between the PD of the exact orbit, 10968.6 rad/s, and
  // HB's own branch point beside it, 10976.2): the multipliers are that orbit's, and `stable`
  // is false (this is no stable orbit of period p). The exact-flow path only.
  bool lower_period = false;
};

// The exact piecewise-linear flow of an HB model (see above).
//
// Propagators. Each contact state's generator A_S is diagonalised once per
// omega (A_S = V diag(lambda) V^-1, Eigen's EigenSolver) when its eigenvector
// matrix is well conditioned (cond_1(V) <= 1e4, so exp(A_S s) = V diag(e^{lambda s}) V^-1
// is good to ~1e-12): a step costs a matrix-vector product, a switch function
// r' exp(A_S s) z = sum_j (r'V)_j (V^-1 z)_j e^{lambda_j s} costs O(dim) per Newton
// iteration. Otherwise (a defective or nearly defective A_S: an undamped resonance
// with a forcing harmonic, a free rigid-body mode) every exponential is Eigen's
// scaling-and-squaring Pade (MatrixFunctions), as with spectral = false. Both work
// on the balanced generator (core balance()): a gear pair's generator mixes
// stiffness/mass ~1e9 with unit entries, and unbalanced the Pade exponential of one
// step loses 1e-7 relative (balanced: 1e-15, against a long-double Taylor product).
// One piece of an orbit on the exact flow: z(t0 + s) = exp(A_state s) z0 for 0 <= s <= h
// (z the augmented state [x, v, 1, c_k, s_k] of floquet.hpp's header).
struct FlowSegment {
  double t0 = 0.0, h = 0.0;
  unsigned state = 0;   // bit i set: contact i closed
  Eigen::VectorXd z0;
};

class PiecewiseLinearFlow {
 public:
  explicit PiecewiseLinearFlow(const HarmonicBalance& hb, bool spectral = true);
  // Period map from (x0, v0) at phase 0 over one forcing period 2 pi / omega,
  // with the monodromy matrix. `nodes` are the times (in [0, T), ascending, 0
  // first) at which the flow is restarted and its contact state checked;
  // `xs` (if not null) receives x at every node (columns).
  // `segments` (if not null) receives the orbit piece by piece (between nodes and
  // contact switches, in time order).
  void period_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                  const std::vector<double>& nodes, Eigen::VectorXd& xT, Eigen::VectorXd& vT,
                  Eigen::MatrixXd& Phi, Eigen::MatrixXd* xs = nullptr,
                  std::vector<FlowSegment>* segments = nullptr) const;
  // The same orbit without the monodromy matrix (no matrix exponential where the propagator
  // is diagonalised: each step is two matrix-vector products): `segments` as above.
  void follow(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, const std::vector<double>& nodes,
              Eigen::VectorXd& xT, Eigen::VectorXd& vT, std::vector<FlowSegment>& segments) const;
  // The flow of contact state `state` over a time s: exp(A_state s) z, and exp(A_state s) itself.
  Eigen::VectorXd advance(unsigned state, double omega, double s, const Eigen::VectorXd& z) const;
  Eigen::MatrixXd exponential(unsigned state, double omega, double s) const;
  // Whether state `state`'s propagator is diagonalised (advance costs two matrix-vector
  // products) or uses Pade exponentials (advance costs an exponential).
  bool spectral(unsigned state, double omega) const;
  // The (x, v) rows of exp(A_state s_j) z for several s_j at once (columns): for a
  // diagonalised propagator one product V_xv (e^{lambda s_j} o V^-1 z), else one exponential
  // per s_j. (The other rows of z are the oscillators [1, cos k omega t, sin k omega t]: known.)
  Eigen::MatrixXd advance_xv(unsigned state, double omega, const Eigen::VectorXd& s, const Eigen::VectorXd& z) const;
  // The harmonics k of the oscillator states (the forcing harmonic first, Excitation::harmonic; floquet.hpp's header).
  const std::vector<int>& oscillator_harmonics() const { return harmonics_; }
  // The generator A_state (its rows n..2n-1 give the acceleration).
  const Eigen::MatrixXd& generator_matrix(unsigned state, double omega) const;
  // The fastest rate of state `state`: max |lambda| of A_state (spectral), else the
  // 1-norm of the balanced generator; h x rate bounds the exponent of a step h.
  double rate(unsigned state, double omega) const;
  // The eigenvalues lambda of A_state where its propagator is diagonalised (spectral), else
  // empty (a Pade propagator has no modes to tell apart).
  Eigen::VectorXcd eigenvalues(unsigned state, double omega) const;
  // Penetration u_i = g_i + n_i' x of contact i at augmented state z.
  double penetration(std::size_t i, const Eigen::VectorXd& z) const { return rows_[i].dot(z); }
  std::size_t contacts() const { return rows_.size(); }
  double stiffness(std::size_t i) const { return hb_.contacts()[i].kc; }
  int dofs() const { return n_; }
  int dimension() const { return dim_; }
  // States of the last omega whose propagator is diagonalised / uses Pade exponentials.
  int spectral_states() const;
  int pade_states() const;

 private:
  class Propagator;
  const HarmonicBalance& hb_;
  int n_, dim_;
  bool spectral_;
  std::vector<int> harmonics_;       // oscillator harmonics k (the forcing harmonic first)
  std::vector<Eigen::RowVectorXd> rows_;   // u_i = r_i' z
  Eigen::MatrixXd Minv_;
  mutable std::vector<std::pair<unsigned, std::shared_ptr<Propagator>>> cache_;   // (contact state, its propagator) at cache_omega_
  mutable double cache_omega_ = NAN;
  Eigen::MatrixXd generator(unsigned state, double omega) const;   // A_S
  Eigen::RowVectorXd contact_row(std::size_t i) const;            // u_i = r_i' z
  const Propagator& propagator(unsigned state, double omega) const;
  // period_map and follow: Phi null skips the monodromy (and its matrix exponentials).
  void march(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, const std::vector<double>& nodes,
             Eigen::VectorXd& xT, Eigen::VectorXd& vT, Eigen::MatrixXd* Phi, Eigen::MatrixXd* xs,
             std::vector<FlowSegment>* segments) const;
};

// The nodes of the shooting on the exact flow of the HB point (X, omega): a uniform grid
// of `steps` points per period (0: max(64, 2 (2H+1))), plus the midpoint of every HB
// contact interval or gap shorter than two steps (so that a short touch of the true
// orbit near it is seen), ascending, 0 first, times in [0, 2 pi / omega).
std::vector<double> shooting_nodes(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega, int steps = 0);

// Multipliers of the HB point (X, omega) after correcting the orbit by shooting.
// x_scale: characteristic displacement (HarmonicBalance::scaling).
// A model with a time-varying contact stiffness (contact.hpp stiffness_profile)
// has no piecewise-constant generator: it goes to floquet_of_hb_shooting_gsl.
// opt.correct_orbit = false: floquet_of_hb_variational instead (no correction).
FloquetResult floquet_of_hb_orbit(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                  double x_scale, const FloquetOptions& opt = {});

// The same correction for any model, on GSL's rk8pd period map with its variational
// equations (TimeIntegrator::period_map, relative tolerance 1e-12, absolute 1e-13 x_scale):
// the path of a time-varying contact stiffness, where no exact flow exists. The vector
// field is continuous in x, so the contact switches need no saltation; the integration
// locates them as events (time_integration.cpp Driver), so no step straddles a kink.
// orbit_error: the largest |x_HB - x| over opt.steps (or max(64, 2(2H+1))) uniform samples.
// Costs one integration of 2n + 4n^2 equations per Newton step: about 3 ms a point for n = 1
// with contact switches (the parametric clearance oscillator of gearhb_frc: its 494-point
// sweep takes 2.5 s, 1.7 s with the uncorrected variational multipliers), against 0.1-0.3 ms
// for the exact flow. The steps follow the fastest closed-contact mode, so the cost of a
// period grows with its periods per forcing period, omega_c / omega (the same oscillator
// with a contact normal of 2047, omega_c = 2047 rad/s: about 1 s a period map at omega = 0.3).
FloquetResult floquet_of_hb_shooting_gsl(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                         double x_scale, const FloquetOptions& opt = {});

// Multipliers from the variational equation about the HB orbit itself (not
// corrected; orbit_error = NaN, corrected = false):
//   d/dt [dx; dv] = [0 I; -M^-1 (K + sum_i kc_i(t) [u_i(t) > 0] n_i n_i'), -M^-1 C] [dx; dv],
// u_i the HB penetration, integrated by monodromy_linear_periodic with its contact
// switches as breakpoints (the vector field is continuous in x, so no saltation).
// For a parametric contact this is the only path; for a constant kc it is an
// approximation of floquet_of_hb_orbit good to the HB truncation error.
FloquetResult floquet_of_hb_variational(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                        const FloquetOptions& opt = {});

// One solution of that variational equation about the HB orbit (X, omega): from y0 = (dx0,
// dv0) at phase 0, dx at the times `nodes` (ascending, in [0, 2 pi / omega), 0 first; columns,
// n x nodes), GSL rk8pd at relative and absolute tolerance `tol`, restarted at every contact
// switch and node. The eigen-solution of a multiplier where no exact flow exists (a
// time-varying contact stiffness; period_doubling.hpp's switch).
Eigen::MatrixXd variational_solution(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                     const Eigen::VectorXd& y0, const std::vector<double>& nodes, double tol);

// Monodromy matrix of y' = A(t) y over [0, T] (dimension dim), from the identity,
// by GSL rk8pd (relative and absolute tolerance `tol`), restarted at every
// breakpoint in (0, T) where A(t) may be discontinuous. A(t, out) fills out (dim x dim).
Eigen::MatrixXd monodromy_linear_periodic(const std::function<void(double, Eigen::MatrixXd&)>& A, int dim,
                                          double T, const std::vector<double>& breakpoints = {},
                                          double tol = 1e-12);

}  // namespace gearhb
