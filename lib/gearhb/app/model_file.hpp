#pragma once
// A model file: any n-DOF system with unilateral contacts that the library can
// solve, described in JSON (README "Your own system from a file"):
//
//   {
//     "name":      "two masses, unilateral spring",
//     "mass":      [[1, 0], [0, 1]],                      n x n, symmetric positive definite
//     "stiffness": [[1, -1], [-1, 2]],                    n x n
//     "damping":   [[0.03, -0.03], [-0.03, 0.06]],        n x n, or instead
//     "rayleigh":  {"alpha": a, "beta": b},               C = a M + b K
//     "contacts":  [ {"direction": [1, 0], "kc": 100, "gap": -1,
//                     "gap_file": "gap.csv",               optional periodic gap (phase,gap)
//                     "kc_file": "k.csv"} ],               optional stiffness factor (phase,factor)
//     "forcing":   {"static": [0, 0], "cos": [0, 0.1], "sin": [0, 0]},
//     "harmonics": 21,
//     "samples":   0,                                     AFT samples (0 = 4 (2H+1))
//     "omega":     {"from": 0.8, "to": 0.5},              [rad/s], either direction
//     "output":    {"direction": [1, 0]},                 the plotted coordinate q' x
//     "solver":    {"exact_contact": 1, "ds_max": 0.02},
//     "bifurcation_diagram": {"range": "whole"}           optional (app/bifurcation_input.hpp)
//     "torus": {"harmonics1": 10, "harmonics2": 4,           optional (hb/quasi_periodic.hpp)
//               "stability_every": 5, "stability_periods": 400}
//   }
//
// Contact law of the library: F = max(kc (g + direction' x), 0); gap g < 0 a
// clearance, g > 0 a preload. A gap file is a CSV with header `phase,gap`: one
// period, uniform phases in [0, 1) starting at 0, gap in m, at least 2H+1 rows;
// its first H harmonics are added to the constant `gap`. A relative gap_file path
// is taken relative to the model file. A kc_file (header `phase,factor`, same rules)
// makes the contact stiffness kc s(theta), s its first H harmonics, which must stay > 0
// (UnilateralContact::stiffness_profile).
//
// Overrides: `--set path=value` replaces a number at a dotted path
// (`harmonics=10`, `omega.to=0.4`, `contacts.0.kc=50`, `mass.1.1=2`).
// Every error is a UsageError naming the key (and the row of a gap file).
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/json_file.hpp"   // read_json_file, max_json_depth

#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/hb/quasi_periodic.hpp"

namespace gearhb {

struct ModelFile {
  std::string name;
  LinearSystem system;
  std::vector<UnilateralContact> contacts;
  Excitation forcing;
  int harmonics = 0, samples = 0;
  double omega_from = 0.0, omega_to = 0.0;   // [rad/s]
  Eigen::VectorXd output;                    // the plotted coordinate
  bool exact_contact = true;
  double ds_max = 0.02;
  BifurcationDiagramInput diagram;           // the bifurcation diagram by time integration (over the unstable ranges if absent)
  // period_doubling.depth: 0 = none, 1 = a period-2 branch from each located PD of the
  // period-1 branch (the default; period-4 branches from their PDs are not computed yet)
  int period_doubling_depth = 1;
  // torus (optional object; absent = off): a torus branch by two-frequency HB from each NS point
  bool torus_on = false;
  TorusOptions torus;
  TorusStabilityOptions torus_stability;     // torus.stability_every, torus.stability_periods
  nlohmann::json resolved;                   // the model after overrides (echoed as params.json)

  HarmonicBalance harmonic_balance() const;
};

// Read, override and check a model file. Throws UsageError with one line naming
// the file and the key.
ModelFile read_model_file(const std::string& path,
                          const std::vector<std::pair<std::string, std::string>>& overrides);

// Text for --help: every key, its unit and meaning.
std::string model_file_help();

}  // namespace gearhb
