#include "gearhb/hb/time_integration.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_odeiv2.h>

#include "gearhb/core/gsl_errors.hpp"

namespace gearhb {

namespace {

double gap_at(const UnilateralContact& c, double theta) {
  return c.gap + trig_series(c.gap_harmonics, theta);
}

// The harmonics a series [a0, a1, b1, ...] holds: the highest k with a nonzero a_k or b_k.
// Its trailing zeros add exactly nothing, and a constant gap's series is 2H+1 zeros, which
// the integration would otherwise evaluate at every stage of every step.
int held_harmonics(const Eigen::VectorXd& c) {
  int H = int(c.size() - 1) / 2;
  while (H > 0 && c[2 * H - 1] == 0.0 && c[2 * H] == 0.0) --H;
  return H;
}

std::vector<int> held_gap_harmonics(const HarmonicBalance& hb) {
  std::vector<int> h;
  for (const auto& ct : hb.contacts()) h.push_back(held_harmonics(ct.gap_harmonics));
  return h;
}

struct OdeContext {
  const TimeIntegrator* ti;
  const HarmonicBalance* hb;
  double omega;
  int n;
  bool variational;
  Eigen::MatrixXd Minv;
  Eigen::VectorXd r = Eigen::VectorXd();   // work buffer of the right-hand side (no allocation per call)
  Eigen::VectorXd a = Eigen::VectorXd(), w = Eigen::VectorXd();   // work buffers: Minv r, kc_k n_k
  Eigen::MatrixXd Kt = Eigen::MatrixXd(), A = Eigen::MatrixXd(), P = Eigen::MatrixXd();   // of the variational equations
  std::vector<double> kc = {};   // the closed contacts' stiffness at the call's phase (each profile evaluated once)
  unsigned closed = 0;   // the contact state the right-hand side uses (bit k: contact k closed; Driver)
  int cols = 0;          // columns of the variational state carried (2n: the monodromy; k: k tangent vectors)
  std::vector<int> gap_h = held_gap_harmonics(*hb);   // the harmonics each contact's gap holds
};

// Penetration u_k = g_k(theta) + n_k' x of contact k at phase theta (x: the first n entries of y).
double penetration(const OdeContext& c, std::size_t k, double theta, const double* y) {
  const UnilateralContact& ct = c.hb->contacts()[k];
  return ct.gap + trig_series(ct.gap_harmonics.data(), c.gap_h[k], theta) +
         ct.normal.dot(Eigen::Map<const Eigen::VectorXd>(y, c.n));
}

// The contacts whose penetration at (theta, y) disagrees with the state `closed` (u < 0 for
// a closed one, u > 0 for an open one; u = 0 agrees with both): bit k set.
unsigned disagreeing(const OdeContext& c, unsigned closed, double theta, const double* y) {
  unsigned wrong = 0;
  const auto& contacts = c.hb->contacts();
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const double u = penetration(c, k, theta, y);
    if ((closed >> k & 1u) ? u < 0.0 : u > 0.0) wrong |= 1u << k;
  }
  return wrong;
}

// The integration runs in the forcing phase theta = omega t, not in t: the state is
// y = [x (n), x_theta (n)] with x_theta = dx/dtheta = v / omega, so both halves are
// displacements and one absolute tolerance fits both, whatever the time unit of the
// model (a gear mesh at 1e4 rad/s and a unit oscillator alike):
//   dx/dtheta = x_theta,   dx_theta/dtheta = a(t = theta/omega, x, omega x_theta) / omega^2.
// The contacts act in the state c->closed (a closed contact pushes with kc (g + n'x), an open
// one not at all): smooth between the switches, which Driver locates.
// With variational equations Phi (2n x cols, column-major) follows dPhi/dtheta = A_theta Phi,
// A_theta = [0 I; -Minv Kt / omega^2, -Minv C / omega]; it is the monodromy matrix in
// (x, x_theta), similar to the one in (x, v) by D = diag(I, omega I).
int rhs(double theta, const double y[], double dydt[], void* params) {
  auto* c = static_cast<OdeContext*>(params);
  const int n = c->n;
  const double omega = c->omega;
  Eigen::Map<const Eigen::VectorXd> x(y, n), x_theta(y + n, n);
  // The acceleration of TimeIntegrator::acceleration at t = theta / omega, v = omega x_theta,
  // into the work buffer (no allocation per call), divided by omega^2.
  const auto& sys = c->hb->system();
  const auto& f = c->hb->excitation();
  const auto& contacts = c->hb->contacts();
  c->r.resize(n);
  c->r = f.f0 + f.fc * std::cos(f.harmonic * theta) + f.fs * std::sin(f.harmonic * theta);
  c->r.noalias() -= omega * (sys.C * x_theta);
  c->r.noalias() -= sys.K * x;
  c->kc.resize(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k)
    if (c->closed >> k & 1u) {
      c->kc[k] = stiffness_at(contacts[k], theta);
      c->r -= c->kc[k] * penetration(*c, k, theta, y) * contacts[k].normal;
    }
  std::copy(y + n, y + 2 * n, dydt);
  // Each product into a work buffer, then scaled: the arithmetic of the expressions
  // Minv r / omega^2, -Minv Kt / omega^2, -Minv C / omega and (kc n) n', whose temporaries
  // were a heap allocation each, every call.
  c->a.noalias() = c->Minv * c->r;
  Eigen::Map<Eigen::VectorXd>(dydt + n, n) = c->a / (omega * omega);
  if (c->variational) {
    Eigen::MatrixXd& Kt = c->Kt;
    Kt = sys.K;
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (c->closed >> k & 1u) {
        c->w = c->kc[k] * contacts[k].normal;
        Kt.noalias() += c->w * contacts[k].normal.transpose();
      }
    Eigen::MatrixXd& A = c->A;
    A.setZero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    c->P.noalias() = -c->Minv * Kt;
    A.bottomLeftCorner(n, n) = c->P / (omega * omega);
    c->P.noalias() = -c->Minv * sys.C;
    A.bottomRightCorner(n, n) = c->P / omega;
    Eigen::Map<const Eigen::MatrixXd> Phi(y + 2 * n, 2 * n, c->cols);
    Eigen::Map<Eigen::MatrixXd> dPhi(dydt + 2 * n, 2 * n, c->cols);
    dPhi.noalias() = A * Phi;
  }
  return GSL_SUCCESS;
}

// The root of g in (lo, hi] (g(lo), g(hi) of opposite signs, g(lo) may be 0) by regula falsi
// with the Illinois modification, to hi - lo <= tol: returns the end on hi's side.
template <class G>
double illinois(const G& g, double lo, double g_lo, double hi, double g_hi, double tol) {
  int kept = 0;   // which end the last two iterates replaced: -1 hi, +1 lo
  for (int it = 0; it < 100 && hi - lo > tol; ++it) {
    double x = hi - g_hi * (hi - lo) / (g_hi - g_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double gx = g(x);
    if ((gx > 0.0) == (g_hi > 0.0) && gx != 0.0) {
      hi = x, g_hi = gx;
      if (kept == -1) g_lo *= 0.5;
      kept = -1;
    } else {
      lo = x, g_lo = gx;
      if (kept == 1) g_hi *= 0.5;
      kept = 1;
    }
  }
  return hi;
}

// GSL's adaptive stepper with the contact switches located. The force max(kc u, 0) has a kink
// where u = 0 (and the variational equations a jump in Kt): a step across it has a large error
// estimate whatever its length, so the step control shrinks the step until the state cannot
// move by a rounding (the orbit of the parametric clearance oscillator with a contact normal
// 30 sat at u = 0 for minutes at steps of 3e-13 rad). So the right-hand side keeps the contact
// state of the step's start (smooth within a step), and after each accepted step every contact
// is checked: with f = +u for a closed contact, -u for an open one (f >= 0: the state agrees),
// a switch lies in the step where f < 0 at its end, or where f falls at its start and rises at
// its end with f < 0 at the minimum between (a touch, or a separation, shorter than the step).
// The switch is located by regula falsi (Illinois) on the length of one step of the same
// stepper from the step's start (the state fixed, so as accurate as the accepted step); the
// integration lands just past the first one, the contact state changes and the integration
// goes on from there. The vector field is continuous at a switch (kc u = 0), so the state and
// Phi need no jump.
class Driver {
 public:
  Driver(const OdeContext& ctx, std::size_t dim, double h0, double abs_tol, double rel_tol,
         OdeStepper stepper = OdeStepper::rk8pd)
      : ctx_(ctx), y0_(dim), y_trial_(dim), y_err_(dim) {
    sys_ = {rhs, nullptr, dim, &ctx_};
    const gsl_odeiv2_step_type* type = stepper == OdeStepper::rkf45 ? gsl_odeiv2_step_rkf45 : gsl_odeiv2_step_rk8pd;
    d_ = gsl_odeiv2_driver_alloc_y_new(&sys_, type, h0, abs_tol, rel_tol);
    for (const auto& ct : ctx_.hb->contacts()) gap_slopes_.push_back(derivative(ct.gap_harmonics));
  }
  ~Driver() { gsl_odeiv2_driver_free(d_); }
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;

  // Advance the phase theta to theta1.
  void advance(double& theta, double theta1, double* y, double omega) {
    if (!started_) {   // the contact state of the initial state (u > 0: closed)
      ctx_.closed = disagreeing(ctx_, 0u, theta, y);
      started_ = true;
    }
    while (theta < theta1) {
      const double t0 = theta;
      std::copy(y, y + y0_.size(), y0_.begin());
      check(gsl_odeiv2_evolve_apply(d_->e, d_->c, d_->s, &sys_, &theta, theta1, &d_->h, y), theta, omega);
      const double h = theta - t0, tau = first_switch(t0, h, y, omega);
      if (!(tau < h)) continue;
      theta = t0 + tau;
      ctx_.closed ^= disagreeing(ctx_, ctx_.closed, theta, y);
      gsl_odeiv2_evolve_reset(d_->e);
      gsl_odeiv2_step_reset(d_->s);
    }
  }

 private:
  OdeContext ctx_;
  gsl_odeiv2_system sys_;
  gsl_odeiv2_driver* d_ = nullptr;
  bool started_ = false;
  std::vector<double> y0_, y_trial_, y_err_;   // the step's start, a trial step, its error estimate
  std::vector<Eigen::VectorXd> gap_slopes_;     // dg_k/dtheta of every contact (series coefficients)

  static Eigen::VectorXd derivative(const Eigen::VectorXd& c) {   // of a series [a0, a1, b1, ...]
    Eigen::VectorXd d = Eigen::VectorXd::Zero(c.size());
    for (Eigen::Index k = 1; 2 * k < c.size(); ++k) d[2 * k - 1] = double(k) * c[2 * k], d[2 * k] = -double(k) * c[2 * k - 1];
    return d;
  }
  void check(int status, double theta, double omega) const {
    if (status != GSL_SUCCESS)
      throw std::runtime_error("time integration (GSL " + std::string(gsl_odeiv2_step_name(d_->s)) +
                               ") failed at omega = " + std::to_string(omega) + ", period " +
                               std::to_string(int(theta / (2.0 * M_PI)) + 1) + ": " + gsl_strerror(status));
  }
  // f_k (>= 0: contact k's penetration agrees with its state) and df_k/dtheta at (theta, y).
  double agreement(std::size_t k, double theta, const double* y) const {
    const double u = penetration(ctx_, k, theta, y);
    return (ctx_.closed >> k & 1u) ? u : -u;
  }
  double agreement_slope(std::size_t k, double theta, const double* y) const {
    const auto& ct = ctx_.hb->contacts()[k];
    // (the slope series holds the harmonics the gap holds)
    const double du = trig_series(gap_slopes_[k].data(), ctx_.gap_h[k], theta) +
                      ct.normal.dot(Eigen::Map<const Eigen::VectorXd>(y + ctx_.n, ctx_.n));
    return (ctx_.closed >> k & 1u) ? du : -du;
  }
  // One step of length tau from the step's start (t0, y0_) into y_trial_, the contact state unchanged.
  const double* trial(double t0, double tau, double omega) {
    std::copy(y0_.begin(), y0_.end(), y_trial_.begin());
    gsl_odeiv2_step_reset(d_->s);
    check(gsl_odeiv2_step_apply(d_->s, t0, tau, y_trial_.data(), y_err_.data(), nullptr, nullptr, &sys_), t0, omega);
    return y_trial_.data();
  }
  // Where contact k is first seen to disagree in the step (0, h] (y: its end): h if f_k < 0
  // there; else the minimum of f_k inside, if f_k falls at the start, rises at the end and is
  // < 0 there; else NaN. f_end receives f_k at the returned offset.
  double disagreement_end(std::size_t k, double t0, double h, const double* y, double omega, double& f_end) {
    f_end = agreement(k, t0 + h, y);
    if (f_end < 0.0) return h;
    const double s0 = agreement_slope(k, t0, y0_.data()), s1 = agreement_slope(k, t0 + h, y);
    if (!(s0 < 0.0 && s1 > 0.0)) return NAN;
    const double m = illinois([&](double tau) { return agreement_slope(k, t0 + tau, trial(t0, tau, omega)); }, 0.0, s0,
                              h, s1, 1e-12 * h);
    f_end = agreement(k, t0 + m, trial(t0, m, omega));
    return f_end < 0.0 ? m : NAN;
  }
  // The first switch in the accepted step (t0, t0 + h] (y: its end): the earliest over the
  // contacts, each located in (0, end] (f_k >= 0 at 0, < 0 at end). If there is one, leaves y
  // just past it and returns its offset from t0; else returns h.
  double first_switch(double t0, double h, double* y, double omega) {
    double first = h;
    bool found = false;
    for (std::size_t k = 0; k < ctx_.hb->contacts().size(); ++k) {
      double f_end = 0.0, end = disagreement_end(k, t0, h, y, omega, f_end);
      if (std::isnan(end)) continue;
      if (found && end > first) {   // after an earlier contact's switch: already past its own there?
        f_end = agreement(k, t0 + first, trial(t0, first, omega));
        if (!(f_end < 0.0)) continue;
        end = first;
      }
      const double f0 = std::max(agreement(k, t0, y0_.data()), 0.0);
      first = illinois([&](double tau) { return agreement(k, t0 + tau, trial(t0, tau, omega)); }, 0.0, f0, end, f_end,
                       1e-12 * h);
      found = true;
    }
    if (!found) return h;
    trial(t0, first, omega);
    std::copy(y_trial_.begin(), y_trial_.end(), y);
    return first;
  }
};

// The integrator's state (x, dx/dtheta = v / omega) from (x, v).
std::vector<double> phase_state(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega) {
  const auto n = x0.size();
  std::vector<double> y(std::size_t(2 * n));
  for (Eigen::Index i = 0; i < n; ++i) {
    y[std::size_t(i)] = x0[i];
    y[std::size_t(n + i)] = v0[i] / omega;
  }
  return y;
}

// One integration of the state (no variational equations) from (x0, v0) at phase 0, forcing
// period after period: GSL errors returned, the driver at its first step P / 1000.
struct PhaseIntegration {
  static constexpr double P = 2.0 * M_PI;   // one forcing period in theta
  const GslErrorsReturned gsl_errors;
  OdeContext ctx;
  Driver drv;
  std::vector<double> y;
  double theta = 0.0;
  PhaseIntegration(const TimeIntegrator* ti, const HarmonicBalance& hb, const Eigen::MatrixXd& Minv,
                   const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, const TimeIntegrationOptions& opt)
      : ctx{ti, &hb, omega, hb.dofs(), false, Minv},
        drv(ctx, std::size_t(2 * hb.dofs()), P / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper),
        y(phase_state(x0, v0, omega)) {}
  void advance(double theta1) { drv.advance(theta, theta1, y.data(), ctx.omega); }
  Eigen::Map<const Eigen::VectorXd> x() const { return {y.data(), ctx.n}; }
  Eigen::VectorXd v() const { return ctx.omega * Eigen::Map<const Eigen::VectorXd>(y.data() + ctx.n, ctx.n); }
};

}  // namespace

Eigen::VectorXd TimeIntegrator::acceleration(double t, const Eigen::VectorXd& x,
                                             const Eigen::VectorXd& v, double omega) const {
  const auto& sys = hb_.system();
  const auto& f = hb_.excitation();
  const double theta = omega * t;
  Eigen::VectorXd rhs = f.f0 + f.fc * std::cos(f.harmonic * theta) + f.fs * std::sin(f.harmonic * theta) - sys.C * v - sys.K * x;
  for (const auto& ct : hb_.contacts())
    rhs -= contact_force(stiffness_at(ct, theta), gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal;
  return Minv_ * rhs;
}

SteadyState TimeIntegrator::steady_state(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                         double omega, const TimeIntegrationOptions& opt) const {
  const int n = hb_.dofs();
  const GslErrorsReturned gsl_errors;
  OdeContext ctx{this, &hb_, omega, n, false, Minv_};
  const double P = 2.0 * M_PI;   // one forcing period in theta
  Driver drv(ctx, 2 * n, P / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper);
  std::vector<double> y = phase_state(x0, v0, omega);
  SteadyState ss;
  double theta = 0.0;
  for (int p = 1; p <= opt.max_periods; ++p) {
    std::vector<double> start = y;
    drv.advance(theta, p * P, y.data(), omega);
    double mis = 0.0;   // displacements and x_theta = v / omega, both relative to x_scale
    for (int i = 0; i < 2 * n; ++i) mis = std::max(mis, std::fabs(y[i] - start[i]) / opt.x_scale);
    ss.periods = p;
    ss.mismatch = mis;
    if (opt.progress) opt.progress(p, mis);
    if (mis < opt.periodicity_tol) {
      ss.converged = true;
      break;
    }
  }
  // Sample the last period.
  ss.x0 = Eigen::Map<Eigen::VectorXd>(y.data(), n);
  ss.v0 = omega * Eigen::Map<Eigen::VectorXd>(y.data() + n, n);
  ss.x.resize(opt.samples_per_period, n);
  const double theta0 = theta;
  for (int j = 0; j < opt.samples_per_period; ++j) {
    drv.advance(theta, theta0 + P * j / opt.samples_per_period, y.data(), omega);
    for (int i = 0; i < n; ++i) ss.x(j, i) = y[i];
  }
  return ss;
}

Eigen::MatrixXd TimeIntegrator::sample(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                       int transient, int periods, const TimeIntegrationOptions& opt) const {
  const int N = opt.samples_per_period;
  PhaseIntegration in(this, hb_, Minv_, x0, v0, omega, opt);
  for (int p = 1; p <= transient; ++p) in.advance(p * in.P);
  Eigen::MatrixXd xs(Eigen::Index(periods) * N, hb_.dofs());
  const double theta0 = in.theta;
  for (Eigen::Index j = 0; j < xs.rows(); ++j) {
    in.advance(theta0 + in.P * double(j) / N);
    xs.row(j) = in.x().transpose();
  }
  return xs;
}

void TimeIntegrator::poincare(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, int transient,
                              int periods, const TimeIntegrationOptions& opt, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs,
                              const std::function<bool(const Eigen::VectorXd&, const Eigen::VectorXd&)>& settled,
                              int* transient_used) const {
  PhaseIntegration in(this, hb_, Minv_, x0, v0, omega, opt);
  int p = 0;
  while (p < transient) {
    in.advance(++p * in.P);
    if (settled && settled(in.x(), in.v())) break;
  }
  if (transient_used) *transient_used = p;
  xs.resize(periods + 1, hb_.dofs());
  vs.resize(periods + 1, hb_.dofs());
  for (int j = 0; j <= periods; ++j) {
    if (j > 0) in.advance((p + j) * in.P);
    xs.row(j) = in.x().transpose();
    vs.row(j) = in.v().transpose();
  }
}

namespace {
struct CrestSearch {
  OdeContext* ctx;
  const TimeIntegrationOptions* opt;
  const Eigen::VectorXd* q;
  double theta_start;
  std::vector<double> y_start;
  double step0;
};
// -q'x at the phase theta, integrated from the state at theta_start (the minimiser's objective).
double minus_coordinate(double theta, void* params) {
  auto* c = static_cast<CrestSearch*>(params);
  const int n = c->ctx->n;
  std::vector<double> y = c->y_start;
  double th0 = c->theta_start;
  if (theta > th0) {
    Driver drv(*c->ctx, 2 * n, c->step0, c->opt->abs_tol * c->opt->x_scale, c->opt->rel_tol, c->opt->stepper);
    drv.advance(th0, theta, y.data(), c->ctx->omega);
  }
  return -c->q->dot(Eigen::Map<const Eigen::VectorXd>(y.data(), n));
}
}  // namespace

double TimeIntegrator::max_over_period(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                       const Eigen::VectorXd& q, const TimeIntegrationOptions& opt) const {
  const int n = hb_.dofs(), N = opt.samples_per_period;
  const GslErrorsReturned gsl_errors;
  OdeContext ctx{this, &hb_, omega, n, false, Minv_};
  const double P = 2.0 * M_PI;   // one forcing period in theta
  Driver drv(ctx, 2 * n, P / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper);
  std::vector<std::vector<double>> states(N);
  std::vector<double> y = phase_state(x0, v0, omega);
  double theta = 0.0;
  int best = 0;
  double best_value = -INFINITY;
  for (int j = 0; j < N; ++j) {
    drv.advance(theta, P * j / N, y.data(), omega);
    states[j] = y;
    const double value = q.dot(Eigen::Map<const Eigen::VectorXd>(y.data(), n));
    if (value > best_value) { best_value = value; best = j; }
  }
  // Bracket [theta_{j-1}, theta_{j+1}] around the best sample (the flow is 2 pi-periodic in theta).
  const int prev = (best + N - 1) % N;
  CrestSearch cs{&ctx, &opt, &q, P * (best - 1) / N, states[prev], P / N / 16};
  gsl_function f{minus_coordinate, &cs};
  const double a = cs.theta_start, b = P * (best + 1) / N, m = P * best / N;
  if (!(minus_coordinate(m, &cs) < std::min(minus_coordinate(a, &cs), minus_coordinate(b, &cs))))
    return best_value;   // flat crest: no interior minimum to bracket
  gsl_min_fminimizer* s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_min_fminimizer_set(s, &f, m, a, b);
  double fmin = -best_value;
  for (int it = 0; it < 100; ++it) {
    if (gsl_min_fminimizer_iterate(s) != GSL_SUCCESS) break;
    fmin = std::min(fmin, gsl_min_fminimizer_f_minimum(s));
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(s), gsl_min_fminimizer_x_upper(s), 1e-9 * P / N, 0.0) == GSL_SUCCESS)
      break;
  }
  gsl_min_fminimizer_free(s);
  return std::max(best_value, -fmin);
}

Eigen::MatrixXd TimeIntegrator::monodromy(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                          double omega, const TimeIntegrationOptions& opt) const {
  Eigen::VectorXd xT, vT;
  Eigen::MatrixXd Phi;
  period_map(x0, v0, omega, opt, xT, vT, Phi);
  return Phi;
}

void TimeIntegrator::period_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                const TimeIntegrationOptions& opt, Eigen::VectorXd& xT, Eigen::VectorXd& vT,
                                Eigen::MatrixXd& Phi, int samples, Eigen::MatrixXd* xs) const {
  const int n = hb_.dofs(), d = 2 * n;
  const GslErrorsReturned gsl_errors;
  OdeContext ctx{this, &hb_, omega, n, true, Minv_};
  ctx.cols = d;
  Driver drv(ctx, d + d * d, 2.0 * M_PI / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol);
  std::vector<double> y = phase_state(x0, v0, omega);
  y.resize(std::size_t(d + d * d), 0.0);
  for (int i = 0; i < d; ++i) y[std::size_t(d + i * d + i)] = 1.0;
  double theta = 0.0;
  if (xs) xs->resize(n, std::max(samples, 0));
  for (int j = 0; j < samples && xs; ++j) {
    drv.advance(theta, 2.0 * M_PI * j / samples, y.data(), omega);
    xs->col(j) = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  }
  drv.advance(theta, 2.0 * M_PI, y.data(), omega);
  xT = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  vT = omega * Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
  // Back to (x, v): Phi_v = D Phi_theta D^-1, D = diag(I, omega I).
  Phi = Eigen::Map<Eigen::MatrixXd>(y.data() + d, d, d);
  Phi.bottomRows(n) *= omega;
  Phi.rightCols(n) /= omega;
}

void TimeIntegrator::tangent_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                 const TimeIntegrationOptions& opt, Eigen::MatrixXd& W, Eigen::VectorXd& xT,
                                 Eigen::VectorXd& vT) const {
  const int n = hb_.dofs(), d = 2 * n, k = int(W.cols());
  if (W.rows() != d) throw std::invalid_argument("tangent_map: W must have 2 dofs rows");
  const GslErrorsReturned gsl_errors;
  OdeContext ctx{this, &hb_, omega, n, true, Minv_};
  ctx.cols = k;
  Driver drv(ctx, std::size_t(d + d * k), 2.0 * M_PI / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol);
  std::vector<double> y = phase_state(x0, v0, omega);
  y.resize(std::size_t(d + d * k));
  Eigen::Map<Eigen::MatrixXd>(y.data() + d, d, k) = W;   // (x, v / omega) = (x, dx/dtheta): the phase coordinates
  double theta = 0.0;
  drv.advance(theta, 2.0 * M_PI, y.data(), omega);
  xT = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  vT = omega * Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
  W = Eigen::Map<const Eigen::MatrixXd>(y.data() + d, d, k);
}

void hb_initial_state(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                      Eigen::VectorXd& x0, Eigen::VectorXd& v0) {
  const int n = hb.dofs(), H = hb.harmonics();
  x0 = X.segment(hb.index(0, 0), n);
  v0 = Eigen::VectorXd::Zero(n);
  for (int k = 1; k <= H; ++k) {
    x0 += X.segment(hb.index(2 * k - 1, 0), n);                  // cos(0) = 1
    v0 += k * omega * X.segment(hb.index(2 * k, 0), n);           // d/dt sin = k omega cos
  }
}

Eigen::VectorXd hb_unknowns_of_samples(const HarmonicBalance& hb, const Eigen::MatrixXd& x) {
  const int n = hb.dofs(), H = hb.harmonics(), N = int(x.rows());
  if (x.cols() != n || N < 2 * H + 1)
    throw std::invalid_argument("hb_unknowns_of_samples: need N >= 2H + 1 rows of n columns");
  const Aft aft(H, N);
  Eigen::VectorXd X(hb.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd c = aft.to_frequency(Eigen::VectorXd(x.col(i)));
    for (int b = 0; b < 2 * H + 1; ++b) X[hb.index(b, i)] = c[b];
  }
  return X;
}

double fastest_rate(const HarmonicBalance& hb) {
  const auto& sys = hb.system();
  const int n = int(sys.M.rows());
  Eigen::MatrixXd K = sys.K;
  for (const auto& c : hb.contacts()) K += c.kc * c.normal * c.normal.transpose();
  const Eigen::MatrixXd Minv = sys.M.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -Minv * K;
  A.bottomRightCorner(n, n) = -Minv * sys.C;
  return Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace gearhb
