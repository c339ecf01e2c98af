#include "gearhb/hb/time_integration.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_odeiv2.h>

#include "gearhb/core/gsl_errors.hpp"

namespace gearhb {

namespace {

double gap_at(const UnilateralContact& c, double theta) {
  return c.gap + trig_series(c.gap_harmonics, theta);
}

struct OdeContext {
  const TimeIntegrator* ti;
  const HarmonicBalance* hb;
  double omega;
  int n;
  bool variational;
  Eigen::MatrixXd Minv;
  Eigen::VectorXd r = Eigen::VectorXd();   // work buffer of the right-hand side (no allocation per call)
};

// The integration runs in the forcing phase theta = omega t, not in t: the state is
// y = [x (n), x_theta (n)] with x_theta = dx/dtheta = v / omega, so both halves are
// displacements and one absolute tolerance fits both, whatever the time unit of the
// model (a gear mesh at 1e4 rad/s and a unit oscillator alike):
//   dx/dtheta = x_theta,   dx_theta/dtheta = a(t = theta/omega, x, omega x_theta) / omega^2.
// With variational equations Phi (2n x 2n, column-major) follows dPhi/dtheta = A_theta Phi,
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
  c->r.resize(n);
  c->r = f.f0 + f.fc * std::cos(theta) + f.fs * std::sin(theta);
  c->r.noalias() -= omega * (sys.C * x_theta);
  c->r.noalias() -= sys.K * x;
  for (const auto& ct : c->hb->contacts())
    c->r -= contact_force(stiffness_at(ct, theta), gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal;
  std::copy(y + n, y + 2 * n, dydt);
  Eigen::Map<Eigen::VectorXd>(dydt + n, n).noalias() = c->Minv * c->r / (omega * omega);
  if (c->variational) {
    Eigen::MatrixXd Kt = sys.K;
    for (const auto& ct : c->hb->contacts())
      Kt += contact_stiffness(stiffness_at(ct, theta), gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal * ct.normal.transpose();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -c->Minv * Kt / (omega * omega);
    A.bottomRightCorner(n, n) = -c->Minv * sys.C / omega;
    Eigen::Map<const Eigen::MatrixXd> Phi(y + 2 * n, 2 * n, 2 * n);
    Eigen::Map<Eigen::MatrixXd> dPhi(dydt + 2 * n, 2 * n, 2 * n);
    dPhi = A * Phi;
  }
  return GSL_SUCCESS;
}

struct Driver {
  gsl_odeiv2_system sys;
  gsl_odeiv2_driver* d;
  Driver(OdeContext& ctx, std::size_t dim, double h0, double abs_tol, double rel_tol,
         OdeStepper stepper = OdeStepper::rk8pd) {
    sys = {rhs, nullptr, dim, &ctx};
    const gsl_odeiv2_step_type* type = stepper == OdeStepper::rkf45 ? gsl_odeiv2_step_rkf45 : gsl_odeiv2_step_rk8pd;
    d = gsl_odeiv2_driver_alloc_y_new(&sys, type, h0, abs_tol, rel_tol);
  }
  ~Driver() { gsl_odeiv2_driver_free(d); }
  // Advance the phase theta to theta1.
  void advance(double& theta, double theta1, double* y, double omega) {
    const int status = gsl_odeiv2_driver_apply(d, &theta, theta1, y);
    if (status != GSL_SUCCESS)
      throw std::runtime_error("time integration (GSL " + std::string(gsl_odeiv2_step_name(d->s)) + ") failed at omega = " + std::to_string(omega) +
                               ", period " + std::to_string(int(theta / (2.0 * M_PI)) + 1) + ": " +
                               gsl_strerror(status));
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

}  // namespace

Eigen::VectorXd TimeIntegrator::acceleration(double t, const Eigen::VectorXd& x,
                                             const Eigen::VectorXd& v, double omega) const {
  const auto& sys = hb_.system();
  const auto& f = hb_.excitation();
  const double theta = omega * t;
  Eigen::VectorXd rhs = f.f0 + f.fc * std::cos(theta) + f.fs * std::sin(theta) - sys.C * v - sys.K * x;
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
  const int n = hb_.dofs(), N = opt.samples_per_period;
  const GslErrorsReturned gsl_errors;
  OdeContext ctx{this, &hb_, omega, n, false, Minv_};
  const double P = 2.0 * M_PI;   // one forcing period in theta
  Driver drv(ctx, 2 * n, P / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper);
  std::vector<double> y = phase_state(x0, v0, omega);
  double theta = 0.0;
  for (int p = 1; p <= transient; ++p) drv.advance(theta, p * P, y.data(), omega);
  Eigen::MatrixXd xs(Eigen::Index(periods) * N, n);
  const double theta0 = theta;
  for (Eigen::Index j = 0; j < xs.rows(); ++j) {
    drv.advance(theta, theta0 + P * double(j) / N, y.data(), omega);
    for (int i = 0; i < n; ++i) xs(j, i) = y[i];
  }
  return xs;
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

}  // namespace gearhb
