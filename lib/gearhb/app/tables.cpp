#include "gearhb/app/tables.hpp"

#include <string>

#include "gearhb/hb/response.hpp"

namespace gearhb {

Table frequency_response_table(const HarmonicBalance& hb, const Branch& b,
                               const std::vector<bool>& stable, const Eigen::VectorXd& q) {
  ResponseEvaluator ev(hb, q);
  Table t({"omega", "x_max", "x_min", "x_rms_ac", "x_h1", "x_mean", "stable", "contact"});
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const auto r = ev.summarize(b.points[i].X);
    t.add_row({b.points[i].omega, r.x_max, r.x_min, r.x_rms_ac, r.x_h1, r.x_mean,
               long(stable[i] ? 1 : 0), std::string(to_string(r.contact))});
  }
  return t;
}

Table time_integration_table(const TimeIntegrationCheck& check) {
  Table t({"omega", "x_max_hb", "x_max_time_integration", "rel_diff", "periods", "contact"});
  for (const auto& r : check.rows)
    t.add_row({r.omega, r.x_max_hb, r.x_max_time_integration, r.rel_diff, long(r.periods),
               std::string(to_string(r.contact))});
  return t;
}

}  // namespace gearhb
