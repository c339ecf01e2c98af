#pragma once
// The tables and checks of the gear-mesh chapters (8, 9): the application layer's gear
// pieces, kept apart from tables.hpp and case_table.hpp so that the chapters without a
// gear do not compile gear code.
#include <string>
#include <utility>
#include <vector>

#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/gears/dynamics/dte_response.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

namespace gearhb {

// Contact-loss bands of labelled curves: label, band (1, 2, ...), f_lo_hz, f_hi_hz.
Table loss_band_table(const std::vector<std::pair<std::string, DteCurveReport>>& reports);
// HB vs time integration of labelled curves: label, f_mesh_hz, contact, x_rms_ac_hb,
// x_rms_ac_ti, rel_diff, periods.
Table dte_time_integration_table(const std::vector<std::pair<std::string, DteTimeCheck>>& checks);
// The multipliers of a labelled curve against time integration (dte_floquet_check):
// label, f_mesh_hz, contact, stable, modulus_variational (the curve's), modulus_time_integration, abs_diff.
Table dte_floquet_table(const std::string& label, const DteFloquetCheck& check);
// The linear closed-contact curve (dte_linear_rms) at `points` + 1 uniform omegas of
// [omega_min, omega_max]: f_mesh_hz, x_rms_ac.
Table linear_mesh_table(const DteGear& g, int H, double omega_min, double omega_max, int points = 800);

// The gear-mesh chapters' HB vs time-integration check of one curve
// (dte_time_integration_check), timed as "time integration <label>", a failure named
// by the label, its count and worst difference as key numbers ti_points_<label>,
// ti_rms_rel_diff_<label>.
DteTimeCheck timed_dte_time_check(Run& run, const std::string& label, const HarmonicBalance& hb,
                                  const FrequencyCurve& c);

}  // namespace gearhb
