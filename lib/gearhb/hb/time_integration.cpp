#include "gearhb/hb/time_integration.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_odeiv2.h>

namespace gearhb {

namespace {

double gap_at(const UnilateralContact& c, double theta) {
  double g = c.gap + c.gap_harmonics[0];
  const int H = int(c.gap_harmonics.size() - 1) / 2;
  for (int k = 1; k <= H; ++k)
    if (c.gap_harmonics[2 * k - 1] != 0.0 || c.gap_harmonics[2 * k] != 0.0)   // padded zeros cost nothing
      g += c.gap_harmonics[2 * k - 1] * std::cos(k * theta) + c.gap_harmonics[2 * k] * std::sin(k * theta);
  return g;
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

// State y = [x (n), v (n)] and, with variational equations, Phi (2n x 2n, column-major).
int rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<OdeContext*>(params);
  const int n = c->n;
  Eigen::Map<const Eigen::VectorXd> x(y, n), v(y + n, n);
  // The acceleration of TimeIntegrator::acceleration, into the work buffer.
  const auto& sys = c->hb->system();
  const auto& f = c->hb->excitation();
  const double theta = c->omega * t;
  c->r.resize(n);
  c->r = f.f0 + f.fc * std::cos(theta) + f.fs * std::sin(theta);
  c->r.noalias() -= sys.C * v;
  c->r.noalias() -= sys.K * x;
  for (const auto& ct : c->hb->contacts())
    c->r -= contact_force(ct.kc, gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal;
  std::copy(y + n, y + 2 * n, dydt);
  Eigen::Map<Eigen::VectorXd>(dydt + n, n).noalias() = c->Minv * c->r;
  if (c->variational) {
    // d/dt Phi = A(t) Phi,  A = [0 I; -Minv (K + sum s_i n n') , -Minv C]
    const auto& sys = c->hb->system();
    Eigen::MatrixXd Kt = sys.K;
    const double theta = c->omega * t;
    for (const auto& ct : c->hb->contacts())
      Kt += contact_stiffness(ct.kc, gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal * ct.normal.transpose();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -c->Minv * Kt;
    A.bottomRightCorner(n, n) = -c->Minv * sys.C;
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
  void advance(double& t, double t1, double* y) {
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, y);
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("GSL ODE driver failed at t = ") + std::to_string(t) +
                               ": " + gsl_strerror(status));
  }
};

}  // namespace

Eigen::VectorXd TimeIntegrator::acceleration(double t, const Eigen::VectorXd& x,
                                             const Eigen::VectorXd& v, double omega) const {
  const auto& sys = hb_.system();
  const auto& f = hb_.excitation();
  const double theta = omega * t;
  Eigen::VectorXd rhs = f.f0 + f.fc * std::cos(theta) + f.fs * std::sin(theta) - sys.C * v - sys.K * x;
  for (const auto& ct : hb_.contacts())
    rhs -= contact_force(ct.kc, gap_at(ct, theta) + ct.normal.dot(x)) * ct.normal;
  return Minv_ * rhs;
}

SteadyState TimeIntegrator::steady_state(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                         double omega, const TimeIntegrationOptions& opt) const {
  const int n = hb_.dofs();
  gsl_set_error_handler_off();
  OdeContext ctx{this, &hb_, omega, n, false, Minv_};
  const double T = 2.0 * M_PI / omega;
  Driver drv(ctx, 2 * n, T / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper);
  std::vector<double> y(2 * n);
  for (int i = 0; i < n; ++i) {
    y[i] = x0[i];
    y[n + i] = v0[i];
  }
  SteadyState ss;
  double t = 0.0;
  const double vscale = opt.x_scale * omega;
  for (int p = 1; p <= opt.max_periods; ++p) {
    std::vector<double> start = y;
    drv.advance(t, p * T, y.data());
    double mis = 0.0;
    for (int i = 0; i < n; ++i) {
      mis = std::max(mis, std::fabs(y[i] - start[i]) / opt.x_scale);
      mis = std::max(mis, std::fabs(y[n + i] - start[n + i]) / vscale);
    }
    ss.periods = p;
    ss.mismatch = mis;
    if (mis < opt.periodicity_tol) {
      ss.converged = true;
      break;
    }
  }
  // Sample the last period.
  ss.x0 = Eigen::Map<Eigen::VectorXd>(y.data(), n);
  ss.v0 = Eigen::Map<Eigen::VectorXd>(y.data() + n, n);
  ss.x.resize(opt.samples_per_period, n);
  const double t0 = t;
  for (int j = 0; j < opt.samples_per_period; ++j) {
    drv.advance(t, t0 + T * j / opt.samples_per_period, y.data());
    for (int i = 0; i < n; ++i) ss.x(j, i) = y[i];
  }
  return ss;
}

namespace {
struct CrestSearch {
  OdeContext* ctx;
  const TimeIntegrationOptions* opt;
  const Eigen::VectorXd* q;
  double t_start;
  std::vector<double> y_start;
  double step0;
};
// -q'x(t), integrated from the state at t_start (the minimiser's objective).
double minus_coordinate(double t, void* params) {
  auto* c = static_cast<CrestSearch*>(params);
  const int n = c->ctx->n;
  std::vector<double> y = c->y_start;
  double t0 = c->t_start;
  if (t > t0) {
    Driver drv(*c->ctx, 2 * n, c->step0, c->opt->abs_tol * c->opt->x_scale, c->opt->rel_tol, c->opt->stepper);
    drv.advance(t0, t, y.data());
  }
  return -c->q->dot(Eigen::Map<const Eigen::VectorXd>(y.data(), n));
}
}  // namespace

double TimeIntegrator::max_over_period(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                       const Eigen::VectorXd& q, const TimeIntegrationOptions& opt) const {
  const int n = hb_.dofs(), N = opt.samples_per_period;
  gsl_set_error_handler_off();
  OdeContext ctx{this, &hb_, omega, n, false, Minv_};
  const double T = 2.0 * M_PI / omega;
  Driver drv(ctx, 2 * n, T / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol, opt.stepper);
  std::vector<std::vector<double>> states(N);
  std::vector<double> y(2 * n);
  for (int i = 0; i < n; ++i) {
    y[i] = x0[i];
    y[n + i] = v0[i];
  }
  double t = 0.0;
  int best = 0;
  double best_value = -INFINITY;
  for (int j = 0; j < N; ++j) {
    drv.advance(t, T * j / N, y.data());
    states[j] = y;
    const double value = q.dot(Eigen::Map<const Eigen::VectorXd>(y.data(), n));
    if (value > best_value) { best_value = value; best = j; }
  }
  // Bracket [t_{j-1}, t_{j+1}] around the best sample (the flow is T-periodic in t).
  const int prev = (best + N - 1) % N;
  CrestSearch cs{&ctx, &opt, &q, T * (best - 1) / N, states[prev], T / N / 16};
  gsl_function f{minus_coordinate, &cs};
  const double a = cs.t_start, b = T * (best + 1) / N, m = T * best / N;
  if (!(minus_coordinate(m, &cs) < std::min(minus_coordinate(a, &cs), minus_coordinate(b, &cs))))
    return best_value;   // flat crest: no interior minimum to bracket
  gsl_min_fminimizer* s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_min_fminimizer_set(s, &f, m, a, b);
  double fmin = -best_value;
  for (int it = 0; it < 100; ++it) {
    if (gsl_min_fminimizer_iterate(s) != GSL_SUCCESS) break;
    fmin = std::min(fmin, gsl_min_fminimizer_f_minimum(s));
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(s), gsl_min_fminimizer_x_upper(s), 1e-9 * T / N, 0.0) == GSL_SUCCESS)
      break;
  }
  gsl_min_fminimizer_free(s);
  return std::max(best_value, -fmin);
}

Eigen::MatrixXd TimeIntegrator::monodromy(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                          double omega, const TimeIntegrationOptions& opt) const {
  const int n = hb_.dofs(), d = 2 * n;
  gsl_set_error_handler_off();
  OdeContext ctx{this, &hb_, omega, n, true, Minv_};
  const double T = 2.0 * M_PI / omega;
  Driver drv(ctx, d + d * d, T / 1000.0, opt.abs_tol * opt.x_scale, opt.rel_tol);
  std::vector<double> y(d + d * d, 0.0);
  for (int i = 0; i < n; ++i) {
    y[i] = x0[i];
    y[n + i] = v0[i];
  }
  for (int i = 0; i < d; ++i) y[d + i * d + i] = 1.0;
  double t = 0.0;
  drv.advance(t, T, y.data());
  return Eigen::Map<Eigen::MatrixXd>(y.data() + d, d, d);
}

void hb_initial_state(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                      Eigen::VectorXd& x0, Eigen::VectorXd& v0) {
  const int n = hb.dofs(), H = hb.harmonics();
  x0 = X.segment(hb.index(0, 0), n);
  v0 = Eigen::VectorXd::Zero(n);
  for (int k = 1; k <= H; ++k) {
    x0 += X.segment(hb.index(2 * k - 1, 0), n);                  // cos(0) = 1
    v0 += k * omega * X.segment(hb.index(2 * k, 0), n);           // d/dt sin = k w cos
  }
}

}  // namespace gearhb
