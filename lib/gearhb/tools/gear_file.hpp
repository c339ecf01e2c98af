#pragma once
// A gear-pair file: a spur or helical gear pair from its drawing, in the terms of ISO 21771
// (and of KISSsoft / MASTA), SI units, for gearhb_gear (README "A gear pair from
// its drawing"). Gear 1 drives (its torque is given), gear 2 is driven.
//
//   {
//     "name": "thesis gear pair",
//     "module": 0.003,                         m [m] (helical: the normal module m_n)
//     "pressure_angle_deg": 20,                alpha [deg] (helical: the normal alpha_n)
//     "helix_angle_deg": 0, "hand": "right",   beta [deg] (0: spur), gear 1's hand (pair_helical.hpp)
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
//        "lead": {"crowning": 0, "end_relief": {"amount": 0, "length": 0}}   lead modification [m]
//       }, {...} ],
//     "model": {...},                          method beam | potential_energy | fe, the reading
//                                              of the beam model, the FE mesh (gear_file_help)
//     "harris": {"from": 50, "to": 500, "points": 19}   torques of the Harris map [N m]
//     "speed": {"unit": "mesh_hz", "from": 300, "to": 5000},
//                                              optional: the speed range of the dynamics, in mesh
//                                              frequency [Hz] or in rpm of gear 1 ("rpm"); absent:
//                                              no dynamics (geometry and STE only)
//     "dynamics": {"model": "one_dof", "mesh": "constant", "zeta": 0.08, "harmonics": 5, ...}
//                                              the mesh model a scene needs (gear_file_help)
//   }
//
// Every key is validated before anything runs: a bad file is one UsageError naming
// the file and the key (unknown keys, wrong types, values out of range, and the
// geometric checks of gear_pair_problem: pointed tip, clearance, interference,
// contact ratio < 1, a relief longer than the path).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/pair/fe_tooth_contact.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/gears/pair/loaded_pair.hpp"
#include "gearhb/gears/pair/pair_helical.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

namespace gearhb {

struct GearFileGear {
  double poisson_ratio = 0.3;      // nu
  double inertia = 0.0;            // [kg m^2]
  double rim_radius = 0.0;         // [m], 0 = solid
  double thickness_allowance = 0.0;   // A_sn [m] <= 0 on the reference circle
  double mass = 0.0;               // [kg] (six_dof dynamics)
  double bearing_stiffness = 0.0;  // isotropic bearing stiffness [N/m] (six_dof dynamics)
  double axial_bearing_stiffness = 0.0;   // axial bearing stiffness [N/m] (six_dof, single helical)
};

// The dynamics over the speed range (`speed`, `dynamics`; README of gearhb_gear).
struct GearDynamicsInput {
  bool present = false;            // the file has a speed range
  bool speed_in_rpm = false;       // speed.unit: rpm of gear 1, or mesh_hz
  double f_min_hz = 0.0, f_max_hz = 0.0;   // the range as mesh frequencies [Hz]
  MeshDofs dofs = MeshDofs::one_dof;           // dynamics.model one_dof | six_dof
  DteModel mesh = DteModel::constant;          // dynamics.mesh constant | parametric
  double zeta = 0.08;              // mesh damping ratio (chapter 8)
  double bearing_zeta = 0.02;      // damping ratio of each bearing mode (six_dof)
  int harmonics = 5;               // H
  SweepDirection direction = SweepDirection::up;
  bool back_flank = true;          // model the back flank (with the file's backlash)
  int time_check_points = 8;       // stable points per curve checked by time integration
  int iso_quality_grade = 5;       // ISO 1328-1 grade for ISO 6336-1's K_v
};

// The tooth model of the pair stiffness (`model.method`; loaded_pair.hpp): chapter 7's
// beams (the thesis), the potential-energy method (potential_energy.hpp, through the
// PairStiffnessFn seam of mesh_phases; its linear Hertz is inside the pair stiffness), or
// tooth contact by finite elements (fe_tooth_contact.hpp; contact inside, force T1 / rb1).
enum class ToothModel : int { beam = 0, potential_energy = 1, fe = 2 };

struct GearFile {
  std::string name;
  ToothModel method = ToothModel::beam;
  PeGear pe[2];                    // the gears in the PE vocabulary (method potential_energy)
  bool pe_coupling = false;        // The bearings of the file's six-DOF model (dynamics.model six_dof; gears[i].mass,
// bearing_stiffness, axial_bearing_stiffness, dynamics.bearing_zeta, the pressure angle and
// base helix of the pair): gearhb_gear's BearingSupport.
BearingSupport gear_file_bearings(const GearFile& f);
// model.pe_coupling body_torsion: the bodies' structural coupling
  FePairOptions fe;                // the FE models of both gears (method fe: model.fe_mesh, rim_radius)
  PairSteModel pair;               // geometry (the transverse section of a helical pair), materials, reliefs, reading
  HelicalPair helical;             // helix angle, normal module and shifts, slices, lead modifications
  GearFileGear gear[2];
  double dedendum_coefficient = 1.25, root_radius_coefficient = 0.38;   // hf*, rho_f*
  double backlash = 0.0;           // j_n [m], given or from the thickness allowances
  std::vector<double> torques;     // T1 [N m]
  int phases = 64;                 // phases per mesh cycle (continuous reading)
  double harris_from = 0, harris_to = 0;   // [N m]
  int harris_points = 0;
  GearDynamicsInput dynamics;
  BifurcationDiagramInput diagram;  // bifurcation_diagram (app/bifurcation_input.hpp): over the unstable ranges if absent
  int period_doubling_depth = 1;    // period_doubling.depth (app/bifurcation_input.hpp): 0 | 1
  nlohmann::json resolved;         // the file after overrides (params.json)
};

// Read, override (`--set path=value`, numbers only) and check a gear-pair file.
GearFile read_gear_file(const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides);
// The same checks on a gear pair given as JSON (e.g. inside a planetary-set file): every
// error names `file` and the key as read_gear_file does.
GearFile read_gear_json(const nlohmann::json& j, const std::string& file);
// The top-level keys of a gear-pair file.
const std::vector<std::string>& gear_file_keys();

// The loaded pair of the file's tooth model (model.method; loaded_pair.hpp): beam, the
// potential-energy pair stiffness (with model.pe_coupling's structural coupling), or the
// finite elements; sliced for a helical pair (pair_helical.hpp). gearhb_gear's model, built
// once per file.
std::unique_ptr<LoadedPair> gear_file_loaded_pair(const GearFile& f);
// The bearings of the file's six-DOF model (dynamics.model six_dof; gears[i].mass,
// bearing_stiffness, axial_bearing_stiffness, dynamics.bearing_zeta, the pressure angle and
// base helix of the pair): gearhb_gear's BearingSupport.
BearingSupport gear_file_bearings(const GearFile& f);
// model.pe_coupling body_torsion: pe_body_coupling of both gears [m/N] (0 otherwise).
double gear_file_pe_coupling(const GearFile& f);

// Text for --help: every key, its unit and meaning.
std::string gear_file_help();

}  // namespace gearhb
