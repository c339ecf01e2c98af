#pragma once
// The solver parameters every harmonic-balance chapter shares, registered once
// (README "Running a chapter"): harmonics, time samples, contact quadrature,
// continuation kind, frequency range and arc-length step cap.
//
// Size bounds. The harmonic-balance Jacobian has n(2H+1) rows and Hill's
// eigenproblem twice that; n(2H+1) is capped at 4096 (Jacobian 128 MiB, Hill's
// dense eigenproblem about 2 GiB), so H <= (4096/n - 1)/2. The AFT samples are
// capped at 2^20 per period (8 MiB per FFT buffer). Both are checked before
// anything is allocated.
#include <string>

#include "gearhb/app/cli.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct SolverSettings {
  int H = 10;                // harmonics
  int N = 0;                 // AFT time samples per period (0 = 4 (2H+1))
  bool exact_contact = true; // exact projection of the contact law, else sampled AFT
  bool natural = false;      // natural continuation (teaching: stops at a fold), else arc-length
  double omega_min = 0.5;    // start of the frequency range [rad/s]
  double omega_max = 2.0;    // end of the frequency range [rad/s]
  double ds_max = 0.02;      // largest arc-length step (scaled)
  // Period-doubled branches switched at the located period doublings of every curve
  // (hb/period_doubling.hpp): 0 none, 1 period 2, 2 also period 4.
  int period_doubling_depth = 1;
};

constexpr int max_hb_unknowns = 4096;   // n (2H+1)
constexpr int max_aft_samples = 1 << 20;

// Largest admissible H for a model with `dofs` degrees of freedom.
int max_harmonics(int dofs);

// Register the settings under the names H, N, exact_contact, natural, omega_min,
// omega_max, ds_max, period_doubling_depth (with bounds for a model of `dofs` DOFs) in a group "solver".
void add_solver_parameters(ParameterSet& params, SolverSettings& s, int dofs);

// Cross-parameter checks: omega_min < omega_max, N = 0 or 4H+2 <= N. Throws UsageError.
void check_solver_settings(const SolverSettings& s);

SweepOptions sweep_options(const SolverSettings& s);
ContactQuadrature contact_quadrature(const SolverSettings& s);

}  // namespace gearhb
