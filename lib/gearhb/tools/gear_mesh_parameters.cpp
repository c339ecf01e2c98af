#include "gearhb/tools/gear_mesh_parameters.hpp"

#include <cmath>

namespace gearhb {

DteModel mesh_model(const GearMeshParameters& g) {
  return g.model == "parametric" ? DteModel::parametric : DteModel::constant;
}

void add_gear_mesh_parameters(ParameterSet& P, GearMeshParameters& g) {
  P.group("gear pair (thesis §8.1)");
  P.add("I1", &g.I1, "kg m^2", "inertia of wheel 1", Range::mass());
  P.add("I2", &g.I2, "kg m^2", "inertia of wheel 2", Range::mass());
  P.add("zeta", &g.zeta, "-", "damping ratio, c = 2 zeta sqrt(kc me)", Range::between(1e-4, 1.0));
  P.group("static transmission error (thesis ch. 7 model)");
  P.add("ste_samples", &g.ste_samples, "-", "phases per mesh cycle of the continuous STE", Range::between(16, 4096));
  P.add("ste_reading", &g.ste_reading, "-", "0 load moving continuously, 1 ch. 7's 8 positions per base pitch",
        Range::between(0, 1));
  P.group("mesh model");
  P.add("model", &g.model, "-", "constant (thesis §8.1: kc, STE as excitation) or parametric (k(t) = F0/e(t))");
  P.group("mesh frequency range");
  P.add("f_min_hz", &g.f_min_hz, "Hz", "start of the sweep", Range::between(1.0, 1e6));
  P.add("f_max_hz", &g.f_max_hz, "Hz", "end of the sweep", Range::between(1.0, 1e6));
}

void apply_gear_mesh_parameters(const ParameterSet& P, const GearMeshParameters& g, SolverSettings& s) {
  ParameterSet::require(g.model == "constant" || g.model == "parametric",
                        "parameter 'model' must be 'constant' or 'parametric'");
  ParameterSet::require(!P.was_set("omega_min") && !P.was_set("omega_max"),
                        "set the mesh-frequency range with f_min_hz / f_max_hz [Hz], not omega_min / omega_max");
  s.omega_min = 2 * M_PI * g.f_min_hz;
  s.omega_max = 2 * M_PI * g.f_max_hz;
  ParameterSet::require(g.f_min_hz < g.f_max_hz, "parameter 'f_min_hz' must be < f_max_hz");
  check_solver_settings(s);
}

}  // namespace gearhb
