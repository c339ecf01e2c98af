#include "gearhb/core/gsl_errors.hpp"

#include <stdexcept>

#include <cmath>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

namespace gearhb {

GslErrorsReturned::GslErrorsReturned()
    : previous_(reinterpret_cast<void*>(gsl_set_error_handler_off())) {}

GslErrorsReturned::~GslErrorsReturned() {
  gsl_set_error_handler(reinterpret_cast<gsl_error_handler_t*>(previous_));
}

void gsl_check(int status, const std::string& where) {
  if (status != GSL_SUCCESS) throw std::runtime_error(where + ": GSL error: " + gsl_strerror(status));
}

namespace {
double call(double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); }
}  // namespace

double brent_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol,
                  const std::string& where, int max_iter) {
  const double flo = f(lo), fhi = f(hi);
  if (!std::isfinite(flo) || !std::isfinite(fhi))
    throw std::runtime_error(where + ": the function is not finite at the ends of the bracket");
  if (flo == 0.0) return lo;
  if (fhi == 0.0) return hi;
  if ((flo < 0.0) == (fhi < 0.0)) throw std::runtime_error(where + ": the root is not bracketed");
  const GslErrorsReturned policy;
  gsl_function fn{&call, const_cast<std::function<double(double)>*>(&f)};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!s) throw std::runtime_error(where + ": GSL could not allocate the Brent solver");
  double root = 0.5 * (lo + hi);
  bool converged = false;
  int status = gsl_root_fsolver_set(s, &fn, lo, hi);
  for (int it = 0; it < max_iter && status == GSL_SUCCESS && !converged; ++it) {
    status = gsl_root_fsolver_iterate(s);
    if (status != GSL_SUCCESS) break;
    root = gsl_root_fsolver_root(s);
    const int test = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, rel_tol);
    converged = test == GSL_SUCCESS;
    if (!converged && test != GSL_CONTINUE) status = test;
  }
  gsl_root_fsolver_free(s);
  gsl_check(status, where);
  if (!converged)
    throw std::runtime_error(where + ": Brent did not narrow the root to " + std::to_string(rel_tol) + " relative in " +
                             std::to_string(max_iter) + " iterations");
  return root;
}

}  // namespace gearhb
