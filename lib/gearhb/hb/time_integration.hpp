#pragma once
// Direct time integration of the same equation the harmonic balance solves,
//
//   M x'' + C x' + K x + sum_i n_i max(kc_i (g_i(omega t) + n_i' x), 0) = f0 + fc cos(omega t) + fs sin(omega t),
//
// with GSL's adaptive embedded Runge-Kutta Prince-Dormand 8(9) driver
// (gsl_odeiv2_step_rk8pd), the contact switches located as events (each step keeps the
// contact state of its start; time_integration.cpp Driver). It is the independent check of
// harmonic balance:
// integrate from a given state, period after period, until the state at the
// start of a period repeats (a periodic steady state), then sample that last
// period. Also computes the monodromy matrix (state-transition matrix over one
// period, from the variational equations) whose eigenvalues, the Floquet
// multipliers, check Hill's method independently.
//
// The integration runs in the forcing phase theta = omega t with the state
// (x, dx/dtheta = v/omega): both halves are displacements, so the tolerances
// (abs_tol x x_scale) suit any time unit, and a stiff gear model (omega ~ 1e4
// rad/s) needs no rescaling by its caller. Inputs and outputs stay in (x, v).
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// GSL's embedded Runge-Kutta pairs: Prince-Dormand 8(9) (the default, the
// project's reference) and the cheaper Runge-Kutta-Fehlberg 4(5).
enum class OdeStepper { rk8pd, rkf45 };

struct TimeIntegrationOptions {
  OdeStepper stepper = OdeStepper::rk8pd;
  double rel_tol = 1e-10, abs_tol = 1e-12;  // GSL driver tolerances (abs_tol scaled by x_scale)
  double x_scale = 1.0;                     // typical displacement, for abs_tol
  int max_periods = 20000;
  double periodicity_tol = 1e-9;            // max |x(T) - x(0)|, |v(T) - v(0)|/omega over x_scale
  int samples_per_period = 512;
  // Called after every period steady_state integrates (e.g. to show progress; the numerics
  // never print): the periods so far and the last period's mismatch.
  std::function<void(int period, double mismatch)> progress;
};

struct SteadyState {
  bool converged = false;
  int periods = 0;                 // periods integrated
  double mismatch = 0.0;           // last |state(T)-state(0)| / x_scale
  Eigen::VectorXd x0, v0;          // state at the start of the last period
  Eigen::MatrixXd x;               // samples (samples_per_period x n) over the last period
};

class TimeIntegrator {
 public:
  // Uses the model (M, C, K, contacts, forcing) of `hb`; H and N of hb are irrelevant here.
  explicit TimeIntegrator(const HarmonicBalance& hb)
      : hb_(hb), Minv_(hb.system().M.inverse()) {}

  // Integrate from (x0, v0) at phase 0 until periodic, then sample the last period.
  SteadyState steady_state(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                           const TimeIntegrationOptions& opt) const;

  // Largest value over one period of the coordinate q' x on the orbit through
  // (x0, v0) at phase 0: the largest of opt.samples_per_period uniform samples,
  // refined by GSL's Brent minimiser between its neighbours (each trial time
  // integrated from the neighbour's state), so a crest between samples is found.
  // Integrate from (x0, v0) at phase 0 over `transient` forcing periods, then sample x
  // over `periods` more (samples_per_period each, starting at phase 0): a
  // (periods x samples_per_period) x n matrix. For orbits that are not 1-periodic
  // (period doubling, quasi-periodic), where steady_state's periodicity test fails.
  Eigen::MatrixXd sample(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, int transient,
                         int periods, const TimeIntegrationOptions& opt) const;
  // The Poincare section theta = 0 (mod 2 pi): integrate from (x0, v0) at phase 0 over
  // `transient` forcing periods, then over `periods` more; row j of xs, vs is the state
  // (x, v) after transient + j periods, j = 0..periods (periods + 1 rows, the last the final
  // state). If `settled` is given, the transient ends early, after at least 1 period, at the
  // first period whose state settled(x, v) accepts (called with the state after every
  // transient period); `transient_used` (if not null) receives the periods discarded.
  void poincare(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, int transient, int periods,
                const TimeIntegrationOptions& opt, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs,
                const std::function<bool(const Eigen::VectorXd&, const Eigen::VectorXd&)>& settled = {},
                int* transient_used = nullptr) const;
  double max_over_period(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                         const Eigen::VectorXd& q, const TimeIntegrationOptions& opt) const;

  // Monodromy matrix (2n x 2n) about the orbit through (x0, v0) at phase 0.
  Eigen::MatrixXd monodromy(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                            const TimeIntegrationOptions& opt) const;

  // The period map: the state (xT, vT) one forcing period after (x0, v0) at phase 0 and
  // the monodromy matrix Phi = d(xT, vT)/d(x0, v0) (2n x 2n, variational equations); xs
  // (if not null) receives x at the phases 2 pi j / samples, j = 0..samples-1 (columns).
  // The shooting correction of a parametric model's orbit (floquet.hpp) runs on it.
  void period_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                  const TimeIntegrationOptions& opt, Eigen::VectorXd& xT, Eigen::VectorXd& vT,
                  Eigen::MatrixXd& Phi, int samples = 0, Eigen::MatrixXd* xs = nullptr) const;

  // The same map carrying k tangent vectors instead of the whole monodromy (k of the 2n
  // columns' work): W (2n x k, in (x, v / omega)) becomes Phi W, with (xT, vT) the state one
  // forcing period after (x0, v0). The Lyapunov exponents (bifurcation_diagram.hpp) need only these.
  void tangent_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                   const TimeIntegrationOptions& opt, Eigen::MatrixXd& W, Eigen::VectorXd& xT,
                   Eigen::VectorXd& vT) const;

  // Right-hand side: acceleration for state (x, v) at time t.
  Eigen::VectorXd acceleration(double t, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                               double omega) const;

 private:
  const HarmonicBalance& hb_;
  Eigen::MatrixXd Minv_;
};

// Initial state (x, x') at phase 0 of a harmonic-balance solution X.
void hb_initial_state(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                      Eigen::VectorXd& x0, Eigen::VectorXd& v0);

// The harmonic-balance unknowns of an orbit sampled over one period of hb's base frequency:
// x (N x n, as TimeIntegrator::sample returns it: row j at phase 2 pi j / N, N >= 2H + 1)
// projected on hb's H harmonics by the FFT (an integrated orbit as a start for Newton's method).
Eigen::VectorXd hb_unknowns_of_samples(const HarmonicBalance& hb, const Eigen::MatrixXd& x);

// The fastest rate of the model's linear dynamics [1/s]: the largest |lambda| of the
// first-order matrix [0 I; -M^-1 K_c, -M^-1 C], K_c the stiffness with every contact closed at
// its kc. An explicit integrator (rk8pd) takes of the order of (this rate x the period) / 5
// steps a period whatever the accuracy asked: the cost a caller can weigh before integrating
// (rayleigh_beta = 1 s on ch. 6's pair: supports' modes decaying at ~1e9/s).
double fastest_rate(const HarmonicBalance& hb);

}  // namespace gearhb
