#include "gearhb/gears/tooth/hertz.hpp"

#include <cmath>
#include <stdexcept>

namespace gearhb {

namespace {
constexpr double kPalmgren = 3.84e-5;   // mm N^-0.9 mm^0.8
constexpr double kMmPerM = 1e3;
}  // namespace

double palmgren_line_contact_approach(double force_N, double length_m) {
  if (!(length_m > 0.0)) throw std::invalid_argument("palmgren: contact length must be > 0");
  if (force_N < 0.0) throw std::invalid_argument("palmgren: contact force must be >= 0");
  const double length_mm = length_m * kMmPerM;
  const double delta_mm = kPalmgren * std::pow(force_N, 0.9) / std::pow(length_mm, 0.8);
  return delta_mm / kMmPerM;
}

double palmgren_line_contact_compliance(double force_N, double length_m) {
  if (force_N <= 0.0) throw std::invalid_argument("palmgren compliance: force must be > 0");
  return 0.9 * palmgren_line_contact_approach(force_N, length_m) / force_N;
}

}  // namespace gearhb
