#pragma once
// A gear-pair file: a spur gear pair from its drawing, in the terms of ISO 21771
// (and of KISSsoft / MASTA), SI units, for gearhb_gear (README "A gear pair from
// its drawing"). Gear 1 drives (its torque is given), gear 2 is driven.
//
//   {
//     "name": "thesis gear pair",
//     "module": 0.003,                         m [m]
//     "pressure_angle_deg": 20,                alpha [deg]
//     "basic_rack": {"addendum": 1.0, "dedendum": 1.25, "root_radius": 0.38},
//                                              ha*, hf*, rho_f* (units of m)
//     "centre_distance": 0.15,                 a [m]; absent or 0: the one the shifts imply
//     "backlash": 0,                           normal backlash j_n [m] (recorded; the STE has none),
//                                              or from "thickness_allowance" A_sn [m] per gear
//     "torques": [100, 200, 300],              T1 [N m], one or several
//     "gears": [ {                             gear 1 (driver), then gear 2
//        "z": 50, "x": 0, "b": 0.02,           teeth, profile shift coefficient, face width [m]
//        "E": 207e9, "nu": 0.3,                material [Pa, -]
//        "inertia": 0.0158,                    polar moment of inertia [kg m^2]
//        "rim_radius": 0,                      optional rim / bore radius [m] (0: solid)
//        "tip_relief": {"amount": 0, "start": {"length": 0.0089}, "shape": "linear"}
//                                              Ca [m]; start as one of "roll_angle_deg",
//                                              "diameter" [m], "length" [m] along the path
//                                              from the tip; shape linear | parabolic
//       }, {...} ],
//     "model": {...},                          the reading of the beam model (gear_file_help)
//     "harris": {"from": 50, "to": 500, "points": 19}   torques of the Harris map [N m]
//   }
//
// Every key is validated before anything runs: a bad file is one UsageError naming
// the file and the key (unknown keys, wrong types, values out of range, and the
// geometric checks of gear_pair_problem: pointed tip, clearance, interference,
// contact ratio < 1, a relief longer than the path).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "gearhb/gears/ste_continuous.hpp"

namespace gearhb {

struct GearFileGear {
  double poisson_ratio = 0.3;      // nu
  double inertia = 0.0;            // [kg m^2]
  double rim_radius = 0.0;         // [m], 0 = solid
  double thickness_allowance = 0.0;   // A_sn [m] <= 0 on the reference circle
};

struct GearFile {
  std::string name;
  PairSteModel pair;               // geometry, materials, reliefs, the model's reading
  GearFileGear gear[2];
  double dedendum_coefficient = 1.25, root_radius_coefficient = 0.38;   // hf*, rho_f*
  double backlash = 0.0;           // j_n [m], given or from the thickness allowances
  std::vector<double> torques;     // T1 [N m]
  int phases = 64;                 // phases per mesh cycle (continuous reading)
  double harris_from = 0, harris_to = 0;   // [N m]
  int harris_points = 0;
  nlohmann::json resolved;         // the file after overrides (params.json)
};

// Read, override (`--set path=value`, numbers only) and check a gear-pair file.
GearFile read_gear_file(const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides);

// Text for --help: every key, its unit and meaning.
std::string gear_file_help();

}  // namespace gearhb
