#include "gearhb/core/gsl_errors.hpp"

#include <stdexcept>

#include <gsl/gsl_errno.h>

namespace gearhb {

GslErrorsReturned::GslErrorsReturned()
    : previous_(reinterpret_cast<void*>(gsl_set_error_handler_off())) {}

GslErrorsReturned::~GslErrorsReturned() {
  gsl_set_error_handler(reinterpret_cast<gsl_error_handler_t*>(previous_));
}

void gsl_check(int status, const std::string& where) {
  if (status != GSL_SUCCESS) throw std::runtime_error(where + ": GSL error: " + gsl_strerror(status));
}

}  // namespace gearhb
