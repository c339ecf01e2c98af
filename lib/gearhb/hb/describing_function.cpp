#include "gearhb/hb/describing_function.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

namespace gearhb {

namespace {

double contact_angle(double s, double dp) {
  // u(phi) = s + dp cos(phi) > 0 for |phi| < phi_c.
  if (dp <= 0.0) return s > 0.0 ? M_PI : 0.0;
  const double c = -s / dp;
  if (c >= 1.0) return 0.0;
  if (c <= -1.0) return M_PI;
  return std::acos(c);
}

struct Integrand {
  const PiecewiseLinearForce* f;
  double dm, dp;
  bool cosine;   // weight cos(phi)
  int* count;
};

double eval(double phi, void* p) {
  auto* in = static_cast<Integrand*>(p);
  ++*in->count;
  const double v = (*in->f)(in->dm + in->dp * std::cos(phi));
  return in->cosine ? v * std::cos(phi) : v;
}

struct Workspace {
  gsl_integration_workspace* work;
  Workspace() : work(gsl_integration_workspace_alloc(200)) {}
  ~Workspace() { gsl_integration_workspace_free(work); }
};

double integrate(Integrand& in, double phic, double epsabs, double epsrel, double& err) {
  Workspace ws;
  gsl_function F{&eval, &in};
  double result = 0.0, e = 0.0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  int status;
  if (phic > 0.0 && phic < M_PI) {
    double pts[3] = {0.0, phic, M_PI};
    status = gsl_integration_qagp(&F, pts, 3, epsabs, epsrel, 200, ws.work, &result, &e);
  } else {
    status = gsl_integration_qags(&F, 0.0, M_PI, epsabs, epsrel, 200, ws.work, &result, &e);
  }
  gsl_set_error_handler(old);
  if (status) throw std::runtime_error(std::string("describing_function: GSL quadrature failed: ") +
                                       gsl_strerror(status));
  err += e;
  return result;
}

}  // namespace

DescribingFunction describing_function(const PiecewiseLinearForce& f, double dm, double dp,
                                       double epsrel) {
  if (!(dp >= 0.0)) throw std::invalid_argument("describing_function: dp must be >= 0");
  DescribingFunction r;
  r.contact_angle = contact_angle(f.g + dm, dp);
  // Force size for the absolute tolerance.
  const double size = (std::fabs(f.k) + std::fabs(f.kc)) * (std::fabs(dm) + dp + std::fabs(f.g)) + 1e-300;
  const double epsabs = 1e-13 * size;
  Integrand mean{&f, dm, dp, false, &r.evaluations};
  Integrand h1{&f, dm, dp, true, &r.evaluations};
  r.mean_force = integrate(mean, r.contact_angle, epsabs, epsrel, r.abs_error) / M_PI;
  r.h1_force = 2.0 * integrate(h1, r.contact_angle, epsabs, epsrel, r.abs_error) / M_PI;
  r.N_fm = dm != 0.0 ? r.mean_force / dm : NAN;
  r.N_fp = dp != 0.0 ? r.h1_force / dp : NAN;
  return r;
}

DescribingFunction describing_function_closed_form(const PiecewiseLinearForce& f, double dm, double dp) {
  if (!(dp >= 0.0)) throw std::invalid_argument("describing_function: dp must be >= 0");
  DescribingFunction r;
  const double s = f.g + dm, pc = contact_angle(s, dp);
  r.contact_angle = pc;
  const double sn = std::sin(pc), cs = std::cos(pc);
  r.mean_force = f.k * dm + f.kc / M_PI * (s * pc + dp * sn);
  r.h1_force = f.k * dp + f.kc / M_PI * (2.0 * s * sn + dp * (pc + sn * cs));
  r.N_fm = dm != 0.0 ? r.mean_force / dm : NAN;
  r.N_fp = dp != 0.0 ? r.h1_force / dp : NAN;
  return r;
}

}  // namespace gearhb
