#pragma once
// The parameters of the 1-DOF gear mesh driven by its STE (thesis ch. 8, and ch. 9
// which builds on it), registered once for both chapters: the gear pair (I1, I2,
// zeta), the STE of ch. 7's model (samples, reading), the mesh model (the thesis'
// constant kc with the STE as excitation, or the parametric k(t) = F0 / e(t),
// gears/dynamics/dte_model.hpp) and the mesh-frequency range.
#include <string>

#include "gearhb/app/cli.hpp"
#include "gearhb/app/solver_settings.hpp"
#include "gearhb/gears/dynamics/dte_model.hpp"

namespace gearhb {

struct GearMeshParameters {
  double I1 = 0.0158, I2 = 0.0158;   // wheel inertias [kg m^2] (thesis §8.1)
  double zeta = 0.08;                // damping ratio of the mesh
  int ste_samples = 64;              // phases per mesh cycle of the continuous STE
  int ste_reading = 0;               // 0 load moving continuously, 1 ch. 7's 8 positions per base pitch
  std::string model = "constant";    // constant (thesis §8.1) | parametric (k(t) = F0 / e(t))
  double f_min_hz = 300.0, f_max_hz = 5000.0;   // mesh frequency range [Hz]
};

// The mesh model named by g.model (checked by apply_gear_mesh_parameters).
DteModel mesh_model(const GearMeshParameters& g);

// Groups "gear pair", "static transmission error", "mesh model", "mesh frequency range".
void add_gear_mesh_parameters(ParameterSet& P, GearMeshParameters& g);

// model is constant or parametric; the solver's omega range from f_min_hz, f_max_hz;
// f_min_hz < f_max_hz; omega_min and omega_max not set by hand; then
// check_solver_settings. Throws UsageError.
void apply_gear_mesh_parameters(const ParameterSet& P, const GearMeshParameters& g, SolverSettings& s);

}  // namespace gearhb
