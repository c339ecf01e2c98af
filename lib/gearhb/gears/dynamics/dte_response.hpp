#pragma once
// What a frequency curve of the 1-DOF gear mesh (dte_model.hpp, thesis ch. 8-9)
// shows and how it is checked; the numerics chapters 8 and 9 share.
//
//  - dte_gear: the model of a gear pair from its STE samples over one mesh cycle:
//    F0 = T / r, me = I1 I2 / (I1 r^2 + I2 r^2), kc = mean of F0 / e, c = 2 zeta sqrt(kc me),
//    the STE harmonics up to `ste_harmonics`.
//  - dte_curve_report: the contact-loss bands (runs of points not in full contact,
//    first to last frequency of each run), the first loss refined on the branch, the
//    peak RMS of the oscillating part of x, and two checks at every point: the mean
//    contact force against F0 (the static balance, thesis §8.1; for either model,
//    dte_mean_contact_force) and, constant model only, at every full-contact point the
//    closed-form linear response (the parametric model has none: k(t) varies).
//  - dte_linear_rms: the RMS of the closed-contact closed form over a frequency grid.
//  - dte_time_integration_check: x_rms_ac by harmonic balance against GSL rk8pd
//    integrated to the periodic state of the same equation, at up to `points` stable
//    points away from folds, up to `lost_points` of them with contact loss, spread
//    evenly over the branch, the rest in full contact. The integrator follows the
//    model's contact law, the time-varying k(theta) of the parametric model included.
//  - dte_peak_below_fold_point, dte_time_integration_point with another model: the
//    near-peak point of a curve integrated with more STE harmonics (truncation error).
//  - dte_floquet_check: the multipliers of the curve (Floquet of the HB orbit; for
//    the parametric model from the variational equation about it) against GSL's
//    variational equation integrated along the orbit (TimeIntegrator::monodromy).
#include <utility>
#include <vector>

#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

namespace gearhb {

// F0 = torque / r, me from I1, I2 and r (both wheels of pitch radius r), kc the mean
// of F0 / e over the samples, c = 2 zeta sqrt(kc me), STE harmonics 0..ste_harmonics.
DteGear dte_gear(const std::vector<double>& ste, double torque, double r, double I1, double I2, double zeta,
                 int ste_harmonics = 20);

struct DteCurveReport {
  std::vector<std::pair<double, double>> loss_bands;   // [omega_lo, omega_hi] of each run [rad/s]
  double first_loss_omega = 0.0;    // first loss along the branch, refined; NaN if never
  double peak_rms = 0.0, peak_omega = 0.0;   // largest x_rms_ac and where [m, rad/s]
  double mean_force_rel_dev = 0.0;  // max |mean contact force - F0| / F0 over the points
  double closed_form_rel_diff = 0.0;   // max |X - X_closed|_inf / |X_closed,ac|_inf, full-contact points
  long closed_points = 0;           // full-contact points compared
};
DteCurveReport dte_curve_report(const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c,
                                DteModel model = DteModel::constant);

// sqrt(sum_k |X_k|^2 / 2) of dte_closed_contact(g, H, omega) at each omega [m].
std::vector<double> dte_linear_rms(const DteGear& g, int H, const std::vector<double>& omegas);

struct DteTimeComparison {
  double omega = 0.0;
  ContactState contact = ContactState::full;
  double rms_hb = 0.0, rms_time_integration = 0.0, rel_diff = 0.0;
  int periods = 0;
};
struct DteTimeCheck {
  std::vector<DteTimeComparison> rows;
  double worst_rel_diff = 0.0;
};
// The comparison at point i of the curve. Throws std::runtime_error naming the
// frequency if the integration does not become periodic.
DteTimeComparison dte_time_integration_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i);
// The same with the model `integrated` (e.g. more STE harmonics) started from the HB
// state of point i of hb's curve c; rms_hb is hb's.
DteTimeComparison dte_time_integration_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i,
                                             const HarmonicBalance& integrated);
// Index of the stable point of largest x_rms_ac at least 0.5 % (in omega) away from
// every fold: the peak as far as time integration can reach it (a solution at a
// fold attracts arbitrarily slowly). c.branch.points.size() if there is none.
std::size_t dte_near_peak_point(const FrequencyCurve& c);
// Index of the stable point of largest x_rms_ac at least `margin` (relative, in omega)
// below the first fold (the peak of a softening overhang; at the fold itself the
// orbit attracts too slowly); c.branch.points.size() if there is none.
std::size_t dte_peak_below_fold_point(const FrequencyCurve& c, double margin = 3e-3);
// Throws std::runtime_error naming the frequency if the integration does not become periodic.
DteTimeCheck dte_time_integration_check(const HarmonicBalance& hb, const FrequencyCurve& c, int points = 8,
                                        int lost_points = 5);

struct DteFloquetComparison {
  double omega = 0.0;
  ContactState contact = ContactState::full;
  bool stable = true;
  double modulus_curve = 0.0, modulus_time_integration = 0.0, abs_diff = 0.0;   // largest |mu|
};
struct DteFloquetCheck {
  std::vector<DteFloquetComparison> rows;
  double worst_abs_diff = 0.0;
  long unstable_points = 0;   // of the whole curve
};
// At the stable full-contact point of largest x_rms_ac, the stable contact-loss point
// of largest x_rms_ac and the unstable point of largest |mu| (those present), all
// `fold_margin` (relative, in omega) away from every fold (a multiplier near +1 is
// slow to resolve there).
DteFloquetCheck dte_floquet_check(const HarmonicBalance& hb, const FrequencyCurve& c, double fold_margin = 1e-2);

}  // namespace gearhb
