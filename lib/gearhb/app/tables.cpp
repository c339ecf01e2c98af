#include "gearhb/app/tables.hpp"

#include <cmath>
#include <complex>
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

Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& q) {
  ResponseEvaluator ev(hb, q);
  Table t({"omega", "x_max", "x_min", "x_rms_ac", "x_h1", "x_mean", "stable", "contact", "floquet_modulus",
           "floquet_angle", "hb_orbit_error"});
  const auto& P = c.branch.points;
  const bool fl = c.floquet.size() == P.size();
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto r = ev.summarize(P[i].X);
    t.add_row({P[i].omega, r.x_max, r.x_min, r.x_rms_ac, r.x_h1, r.x_mean, long(c.stable[i] ? 1 : 0),
               std::string(to_string(r.contact)), fl ? c.floquet[i].modulus : NAN, fl ? c.floquet[i].angle : NAN,
               fl ? c.floquet[i].orbit_error : NAN});
  }
  return t;
}

Table bifurcation_table(const FrequencyCurve& c) {
  Table t({"type", "omega", "multiplier_re", "multiplier_im", "modulus"});
  for (const auto& b : c.bifurcations)
    t.add_row({std::string(to_string(b.type)), b.omega, b.multiplier.real(), b.multiplier.imag(), std::abs(b.multiplier)});
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
