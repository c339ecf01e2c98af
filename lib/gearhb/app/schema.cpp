#include "gearhb/app/schema.hpp"

#include "gearhb/core/units.hpp"

namespace gearhb {

std::vector<std::string> frequency_columns(FrequencyAxis axis) {
  switch (axis) {
    case FrequencyAxis::omega: return {"omega"};
    case FrequencyAxis::mesh: return {"omega", "f_mesh_hz"};
    case FrequencyAxis::gear: return {"omega", "f_mesh_hz", "speed_rpm"};
  }
  return {};
}

std::vector<Table::Cell> frequency_cells(FrequencyAxis axis, double omega, double teeth_1) {
  const int n = axis == FrequencyAxis::omega ? 1 : axis == FrequencyAxis::mesh ? 2 : 3;
  const double values[3] = {omega, hz(omega), teeth_1 > 0.0 ? 60.0 * hz(omega) / teeth_1 : 0.0};
  return std::vector<Table::Cell>(values, values + n);
}

const std::vector<std::string>& response_columns() {
  static const std::vector<std::string> c{"x_max", "x_min", "x_rms_ac", "x_h1", "x_mean", "stable", "contact",
                                          "floquet_modulus", "floquet_angle", "hb_orbit_error",
                                          "x_max_exact", "x_min_exact", "x_rms_ac_exact", "x_h1_exact", "x_mean_exact",
                                          "exact", "period", "branch"};
  return c;
}

std::vector<std::string> check_columns(FrequencyAxis axis, const std::vector<std::string>& measures,
                                       const std::vector<std::string>& extras) {
  std::vector<std::string> c = frequency_columns(axis);
  c.push_back("contact");
  for (const auto& m : measures) {
    c.push_back(m + "_hb");
    c.push_back(m + "_time_integration");
  }
  c.push_back("rel_diff");
  c.push_back("periods");
  c.insert(c.end(), extras.begin(), extras.end());
  return c;
}

std::vector<std::string> columns_of(std::vector<std::string> head, const std::vector<std::string>& tail,
                                    const std::vector<std::string>& extras) {
  head.insert(head.end(), tail.begin(), tail.end());
  head.insert(head.end(), extras.begin(), extras.end());
  return head;
}

}  // namespace gearhb
