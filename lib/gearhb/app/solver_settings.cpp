#include "gearhb/app/solver_settings.hpp"

#include "gearhb/app/bifurcation_input.hpp"   // max_period_doubling_depth

namespace gearhb {

int max_harmonics(int dofs) { return (max_hb_unknowns / (dofs > 0 ? dofs : 1) - 1) / 2; }

void add_solver_parameters(ParameterSet& params, SolverSettings& s, int dofs) {
  params.group("solver");
  params.add("H", &s.H, "-", "number of harmonics (time per point grows as H^3: README 'Cost of a run')", Range::between(1, max_harmonics(dofs)));
  params.add("N", &s.N, "-", "AFT time samples per period (0 = 4(2H+1); else >= 4H+2)",
             Range::between(0, max_aft_samples));
  params.add("exact_contact", &s.exact_contact, "-", "1 exact projection of the contact law, 0 sampled AFT");
  params.add("natural", &s.natural, "-", "1 natural continuation (stops at a fold), 0 arc-length");
  params.add("omega_min", &s.omega_min, "rad/s", "start of the frequency range", Range::positive());
  params.add("omega_max", &s.omega_max, "rad/s", "end of the frequency range", Range::positive());
  params.add("ds_max", &s.ds_max, "-", "largest arc-length step (scaled unknowns)", Range::between(1e-6, 1.0));
  params.add("period_doubling_depth", &s.period_doubling_depth, "-",
             "period-doubled branches from the located period doublings: 0 none, 1 period 2, 2 also period 4",
             Range::between(0, max_period_doubling_depth));
}

void check_solver_settings(const SolverSettings& s) {
  ParameterSet::require(s.omega_min < s.omega_max, "parameter 'omega_min' must be < omega_max");
  const long min_samples = 4L * s.H + 2;   // H is already bounded, no overflow
  ParameterSet::require(s.N == 0 || s.N >= min_samples,
                        "parameter 'N' must be 0 or >= 4H+2 (" + std::to_string(min_samples) + ")");
}

SweepOptions sweep_options(const SolverSettings& s) {
  SweepOptions o;
  o.omega_min = s.omega_min;
  o.omega_max = s.omega_max;
  o.natural = s.natural;
  o.continuation.ds_max = s.ds_max;
  return o;
}

ContactQuadrature contact_quadrature(const SolverSettings& s) {
  return s.exact_contact ? ContactQuadrature::exact : ContactQuadrature::sampled;
}

}  // namespace gearhb
