#pragma once
// One GSL error policy for the whole library. GSL's default error handler
// aborts the process (e.g. Brent's solver given a non-finite function value);
// gearhb never lets it: every GSL call site runs with the handler switched off
// and turns a non-zero status into an exception that says where and why.
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

}  // namespace gearhb
