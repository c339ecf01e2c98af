#pragma once
// Chapter 6's gear pair as the unit tests, the benchmarks and the scratch probes set it up (the
// chapter's own set-up: chapters/ch06_gear_pair/main.cpp): the thesis' 6-DOF pair with
// kc = 5e8 N/m, the harmonic force F = [1e4, 0, 1e4, 1e4, 0, 1e4] and the static torque Fi
// [N m] (Fig. 40: 1e5; Fig. 41: 1e7), and the chapter's sweep.
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

namespace test_models {

inline gearhb::HarmonicBalance ch06_gear_pair(double Fi, int H = 10) {
  const gearhb::GearPairParameters g;   // thesis values, kc = 5e8 N/m
  Eigen::VectorXd F(6);
  F << 1e4, 0.0, 1e4, 1e4, 0.0, 1e4;
  return gearhb::HarmonicBalance(gearhb::gear_pair_system(g), {gearhb::gear_pair_mesh(g)},
                                 gearhb::Excitation{gearhb::gear_pair_static_torque(g, Fi), F, Eigen::VectorXd::Zero(6)},
                                 H);
}

// The chapter's sweep: 2000-62000 rad/s, ds_max 0.005, Newton tolerance 1e-9, ds_min 1e-8 (12
// corrector iterations, the library's default), with the given stability.
inline gearhb::SweepOptions ch06_sweep(gearhb::StabilityMethod stability = gearhb::StabilityMethod::floquet) {
  gearhb::SweepOptions o;
  o.omega_min = 2000.0;
  o.omega_max = 62000.0;
  o.continuation.ds_max = 0.005;
  o.continuation.tolerance = 1e-9;
  o.continuation.corrector_max_iterations = 12;
  o.continuation.ds_min = 1e-8;
  o.stability = stability;
  return o;
}

}  // namespace test_models
