#include "gearhb/tools/gear_tables.hpp"

#include <cmath>
#include <stdexcept>

namespace gearhb {

Table loss_band_table(const std::vector<std::pair<std::string, DteCurveReport>>& reports) {
  Table t({"label", "band", "f_lo_hz", "f_hi_hz"});
  for (const auto& [label, r] : reports)
    for (std::size_t b = 0; b < r.loss_bands.size(); ++b)
      t.add_row({label, long(b + 1), hz(r.loss_bands[b].first), hz(r.loss_bands[b].second)});
  return t;
}

Table dte_time_integration_table(const std::vector<std::pair<std::string, DteTimeCheck>>& checks) {
  Table t(check_columns(FrequencyAxis::mesh, {"x_rms_ac"}, {"label"}));
  for (const auto& [label, chk] : checks)
    for (const auto& r : chk.rows)
      t.add_row({r.omega, hz(r.omega), std::string(to_string(r.contact)), r.rms_hb, r.rms_time_integration, r.rel_diff,
                 long(r.periods), label});
  return t;
}

Table dte_floquet_table(const std::string& label, const DteFloquetCheck& check) {
  Table t(columns_of(frequency_columns(FrequencyAxis::mesh),
                     {"contact", "stable", "modulus_variational", "modulus_time_integration", "abs_diff", "label"}));
  for (const auto& r : check.rows)
    t.add_row({r.omega, hz(r.omega), std::string(to_string(r.contact)), long(r.stable ? 1 : 0), r.modulus_curve,
               r.modulus_time_integration, r.abs_diff, label});
  return t;
}

Table linear_mesh_table(const DteGear& g, int H, double omega_min, double omega_max, int points) {
  std::vector<double> omegas;
  for (int i = 0; i <= points; ++i) omegas.push_back(omega_min + (omega_max - omega_min) * i / double(points));
  const std::vector<double> rms = dte_linear_rms(g, H, omegas);
  Table t({"f_mesh_hz", "x_rms_ac"});
  for (std::size_t i = 0; i < omegas.size(); ++i) t.add_row({hz(omegas[i]), rms[i]});
  return t;
}

DteTimeCheck timed_dte_time_check(Run& run, const std::string& label, const HarmonicBalance& hb,
                                  const FrequencyCurve& c) {
  const DteTimeCheck chk = run.timed("time integration " + label, [&] {
    try {
      return dte_time_integration_check(hb, c);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(label + ": " + e.what());
    }
  });
  run.key_numbers().add("ti_points_" + label, double(chk.rows.size()), "-");
  run.key_numbers().add("ti_rms_rel_diff_" + label, chk.worst_rel_diff, "-");
  return chk;
}

}  // namespace gearhb
