#pragma once
// One GSL error policy for the whole library. GSL's default error handler
// aborts the process (e.g. Brent's solver given a non-finite function value);
// gearhb never lets it: every GSL call site runs with the handler switched off
// and turns a non-zero status into an exception that says where and why.
#include <functional>
#include <string>

namespace gearhb {

// While alive, GSL errors are returned (handler off); the previous handler is
// restored on destruction. Nests safely.
class GslErrorsReturned {
 public:
  GslErrorsReturned();
  ~GslErrorsReturned();
  GslErrorsReturned(const GslErrorsReturned&) = delete;
  GslErrorsReturned& operator=(const GslErrorsReturned&) = delete;

 private:
  void* previous_;
};

// Throws std::runtime_error("<where>: GSL error: <gsl_strerror(status)>") if status != 0.
void gsl_check(int status, const std::string& where);

// Root of f on [lo, hi] by GSL's Brent solver under this policy: f(lo) and f(hi)
// must be finite and of opposite signs (an end where f = 0 is returned as is);
// iterates until the bracket is within `rel_tol` relative (gsl_root_test_interval,
// absolute 0), at most `max_iter` times. Throws std::runtime_error naming `where`
// when the root is not bracketed, GSL fails or the bracket does not shrink enough.
double brent_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol,
                  const std::string& where, int max_iter = 300);

}  // namespace gearhb
