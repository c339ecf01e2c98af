#pragma once
// The output tables' columns, declared once (README "Output files"). Every frequency-response
// table and every time-integration check is laid out as
//
//   frequency columns | common columns | the program's extras
//
// frequency columns: `omega` [rad/s] for any model; a gear mesh adds `f_mesh_hz` [Hz] =
//   omega / (2 pi), and a gear pair from its drawing `speed_rpm` [1/min] of gear 1 = 60 f_mesh / z1.
// common columns of a frequency response (response_columns): x_max, x_min, x_rms_ac, x_h1, x_mean
//   [the output coordinate's unit], stable, contact, floquet_modulus, floquet_angle, hb_orbit_error,
//   the exact twins x_*_exact and their status `exact`, period, branch.
// common columns of a time-integration check (check_columns): contact, then for each compared
//   measure m the pair m_hb, m_time_integration, then rel_diff (the largest relative difference
//   of the row) and periods (forcing periods integrated to the periodic steady state).
#include <string>
#include <vector>

#include "gearhb/app/output.hpp"

namespace gearhb {

enum class FrequencyAxis {
  omega,   // omega
  mesh,    // omega, f_mesh_hz
  gear,    // omega, f_mesh_hz, speed_rpm
};

std::vector<std::string> frequency_columns(FrequencyAxis axis);
// The frequency cells of a row at omega; `teeth_1` (z1) is used by FrequencyAxis::gear only.
std::vector<Table::Cell> frequency_cells(FrequencyAxis axis, double omega, double teeth_1 = 0.0);

// The common columns of a frequency response (after the frequency columns).
const std::vector<std::string>& response_columns();

// The columns of a time-integration check comparing `measures` (e.g. {"x_max"}).
std::vector<std::string> check_columns(FrequencyAxis axis, const std::vector<std::string>& measures,
                                       const std::vector<std::string>& extras = {});

// Concatenation: a table's columns from its parts.
std::vector<std::string> columns_of(std::vector<std::string> head, const std::vector<std::string>& tail,
                                    const std::vector<std::string>& extras = {});

}  // namespace gearhb
