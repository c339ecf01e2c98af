#pragma once
// The standard tables a frequency sweep is written as (README "Output files"):
// the numerics (hb/) return results; this application-layer module turns them
// into CSV tables.
#include <vector>

#include <Eigen/Dense>

#include "gearhb/app/output.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// The frequency-response table: omega, x_max, x_min, x_rms_ac, x_h1, x_mean,
// stable, contact for the coordinate q' x, one row per point, in continuation order.
Table frequency_response_table(const HarmonicBalance& hb, const Branch& b,
                               const std::vector<bool>& stable, const Eigen::VectorXd& q);

// The frequency response of a model file (gearhb_frc): the columns of
// frequency_response_table for the output coordinate (omega, x_max, x_min, x_rms_ac,
// x_h1, x_mean, stable, contact), then q<i>_max, q<i>_min, q<i>_h1 for every DOF i = 1..n.
Table dof_response_table(const HarmonicBalance& hb, const Branch& b, const std::vector<bool>& stable,
                         const Eigen::VectorXd& output);

// The harmonic-balance vs time-integration comparison, one row per compared point.
Table time_integration_table(const TimeIntegrationCheck& check);

}  // namespace gearhb
