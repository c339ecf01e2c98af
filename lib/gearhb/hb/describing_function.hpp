#pragma once
// Describing functions of a piecewise-linear restoring force (thesis §5,
// Comparin & Singh 1989), by GSL adaptive quadrature.
//
// Restoring force of the one-DOF impact pair (linear spring k always acting,
// one-sided contact kc with the law of contact.hpp):
//
//     f(d) = k d + max( kc (g + d), 0 ),    g > 0 preload, g < 0 clearance.
//
// With the single-harmonic trial motion d(phi) = dm + dp cos(phi) (dp >= 0) the
// force has the mean  F0 = (1/pi) int_0^pi f(d(phi)) dphi  and the first
// harmonic  F1 cos(phi),  F1 = (2/pi) int_0^pi f(d(phi)) cos(phi) dphi
// (f(d(phi)) is even in phi, so there is no sin(phi) term). The describing
// functions of the thesis are
//
//     N_fm = F0 / dm,    N_fp = F1 / dp.
//
// (The thesis prints dm in the denominator of N_fp as well: a misprint; with
// dm the "equivalent stiffness" of the oscillating part would not even have
// the units of a stiffness times dp / dp.)
//
// Quadrature: gsl_integration_qagp with a break point at the contact angle
// phi_c (cos phi_c = -(g + dm)/dp), where the integrand has a kink; QAGS when
// the contact is open or closed over the whole period. The closed form of the
// same integrals (used only as an independent check in the unit test) is
//   s = g + dm,  F0 = k dm + (kc/pi) (s phi_c + dp sin phi_c),
//   F1 = k dp + (kc/pi) (2 s sin phi_c + dp (phi_c + sin phi_c cos phi_c)),
// with phi_c = 0 (open) or pi (full contact).

namespace gearhb {

struct PiecewiseLinearForce {
  double k = 0.0;    // linear spring, always acting [N/m]
  double kc = 0.0;   // contact stiffness [N/m]
  double g = 0.0;    // g: > 0 preload, < 0 clearance [m]
  double operator()(double d) const { return k * d + (g + d > 0.0 ? kc * (g + d) : 0.0); }
};

struct DescribingFunction {
  double mean_force = 0.0;    // F0 [N]
  double h1_force = 0.0;      // F1 [N]
  double N_fm = 0.0;          // F0 / dm [N/m] (NaN if dm = 0)
  double N_fp = 0.0;          // F1 / dp [N/m] (NaN if dp = 0)
  double contact_angle = 0.0; // phi_c in [0, pi]: 0 never in contact, pi always
  double abs_error = 0.0;     // GSL error estimates, summed
  int evaluations = 0;        // integrand evaluations
};

// By GSL quadrature (QAGP / QAGS), tolerances epsabs (scaled by the force size) and epsrel.
// Throws std::runtime_error if GSL reports a failure; std::invalid_argument if dp < 0.
DescribingFunction describing_function(const PiecewiseLinearForce& f, double dm, double dp,
                                       double epsrel = 1e-12);

// The same in closed form (for tests and for the classifier's documentation).
DescribingFunction describing_function_closed_form(const PiecewiseLinearForce& f, double dm, double dp);

}  // namespace gearhb
