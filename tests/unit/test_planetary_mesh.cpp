// The meshes of a planetary set over time (gears/sets/planetary_mesh.hpp) through the
// harmonic-balance engine. Each check names its independent truth: the first-order
// (linear) forced response to a small stiffness variation, and the mesh-phasing rule of
// Parker (2000, J. Sound Vib. 236:561) and Parker & Lin (2004).
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;

namespace {

// Lin & Parker 1999's set (reference/lin_parker_1999.md) with its output held: ring
// torsion 1e9 N/m as theirs, the carrier on an output shaft of 1e8 N/m (theirs is free),
// so that the loaded set has a static equilibrium. Teeth of the example file.
PlanetarySet pm_held_set(int planets) {
  PlanetarySet s = lin_parker_1999_set(planets);
  s.carrier.torsional = 1e8;
  return s;
}

const PlanetaryTeeth kPmTeeth{27, 33, 93, 0.0032, 1.0};

PlanetaryMeshes pm_meshes(const PlanetarySet& s, double ratio) {
  PlanetaryMeshes m;
  m.sun = {5e8, 1.6, ratio};
  m.ring = {5e8, 1.8, ratio};
  m.phases = mesh_phases(kPmTeeth, s.planet_angles, 0.3);
  return m;
}

// The static load: 100 N m on the sun, as a force on u_s (base radius 38.7 mm).
Eigen::VectorXd pm_sun_torque(const PlanetarySet& s) {
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
  f0(coordinate(Body::sun, 2)) = 100.0 / 0.0387;
  return f0;
}

// The harmonic-balance solution at mesh frequency omega, by Newton from the closed-contact one.
Eigen::VectorXd pm_solve(const HarmonicBalance& hb, double omega) {
  Eigen::VectorXd X = hb.closed_contact_solution(omega);
  const NewtonReport r = newton_solve(hb, X, omega, hb.scaling(omega, omega));
  EXPECT_TRUE(r.converged) << r.message;
  return X;
}

// Harmonic l of coordinate i as a complex amplitude X_c - i X_s.
std::complex<double> pm_harmonic(const Eigen::VectorXd& X, int n, int l, int i) {
  return {X((2 * l - 1) * n + i), -X(2 * l * n + i)};
}

// GSL rk8pd time integration of the same model from the HB orbit's initial state, to its
// periodic steady state (by default |x(T) - x(0)| below 1e-9 of the displacement scale).
SteadyState pm_integrate(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                         double periodicity_tol = 1e-9, int max_periods = 400) {
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, X, omega, x0, v0);
  TimeIntegrationOptions o;
  o.x_scale = hb.scaling(omega, omega).x.maxCoeff();
  o.max_periods = max_periods;
  o.periodicity_tol = periodicity_tol;
  return TimeIntegrator(hb).steady_state(x0, v0, omega, o);
}

// The HB orbit's extreme penetrations of every contact (1024 phases) against the integrated
// orbit's: the largest difference over the largest drive-flank penetration; the smallest
// drive-flank and the largest back-flank penetration of the integrated orbit (contacts past
// the first `drive` are back flanks).
struct TiComparison {
  double err = 0.0, drive_min = INFINITY, back_max = -INFINITY;
};
TiComparison pm_against_time_integration(const HarmonicBalance& hb, const Eigen::VectorXd& X, const SteadyState& ss,
                                         std::size_t drive = 0) {
  TiComparison r;
  if (drive == 0) drive = hb.contacts().size();
  double largest = 0.0;
  for (std::size_t c = 0; c < hb.contacts().size(); ++c) {
    const Eigen::VectorXd uc = hb.penetration(X, c);
    const Eigen::VectorXd u = (ss.x * hb.contacts()[c].normal).array() + hb.contacts()[c].gap;
    double hb_max = -INFINITY, hb_min = INFINITY;
    for (int j = 0; j < 1024; ++j) {
      const double v = trig_series(uc, 2.0 * M_PI * j / 1024);
      hb_max = std::max(hb_max, v);
      hb_min = std::min(hb_min, v);
    }
    r.err = std::max({r.err, std::fabs(hb_max - u.maxCoeff()), std::fabs(hb_min - u.minCoeff())});
    if (c < drive) largest = std::max(largest, u.maxCoeff()), r.drive_min = std::min(r.drive_min, u.minCoeff());
    else r.back_max = std::max(r.back_max, u.maxCoeff());
  }
  r.err /= largest;
  return r;
}

}  // namespace

// A small stiffness variation (k_double / k_single = 1 + eps): the harmonic-balance response
// is x0 + x1 + O(eps^2), x1 the linear forced response of the mean system to -dK(theta) x0
// (x0 its static deflection), harmonic by harmonic (core frequency_response). The relative
// difference is O(eps): checked at two eps ten apart (a convergence study), below 3 eps.
TEST(PlanetaryMesh, SmallVariationIsTheLinearForcedResponse) {
  const PlanetarySet s = pm_held_set(4);
  const double omega = 2.0 * M_PI * 1000.0;
  const int H = 6, n = s.dofs();
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const double eps = k == 0 ? 1e-3 : 1e-4;
    const PlanetaryMeshes m = pm_meshes(s, 1.0 + eps);
    const HarmonicBalance hb = planetary_harmonic_balance(s, m, 0.02, pm_sun_torque(s), H);
    const Eigen::VectorXd X = pm_solve(hb, omega);
    const PlanetaryMatrices mat = planetary_matrices(s);
    const LinearSystem mean{mat.M, hb.system().C, mat.K_bearing + mat.K_mesh};
    const Eigen::VectorXd x0 = mean.K.ldlt().solve(pm_sun_torque(s));
    double diff = 0.0, size = 0.0;
    for (int l = 1; l <= 3; ++l) {
      Eigen::VectorXcd F = Eigen::VectorXcd::Zero(n);
      for (std::size_t c = 0; c < hb.contacts().size(); ++c) {
        const UnilateralContact& ct = hb.contacts()[c];
        // harmonic l of kc s(theta): (1/pi) int kc s cos(l theta), by the trapezoidal rule (exact)
        std::complex<double> kl = 0.0;
        const int J = 256;
        for (int j = 0; j < J; ++j) {
          const double th = 2.0 * M_PI * j / J;
          kl += stiffness_at(ct, th) * std::complex<double>(std::cos(l * th), -std::sin(l * th)) * (2.0 / J);
        }
        F -= kl * ct.normal * ct.normal.dot(x0);
      }
      const Eigen::VectorXcd x1 = frequency_response(mean, F, l * omega);
      for (int i = 0; i < n; ++i) {
        diff += std::norm(pm_harmonic(X, n, l, i) - x1(i));
        size += std::norm(x1(i));
      }
    }
    err[k] = std::sqrt(diff / size);
    EXPECT_LT(err[k], 3.0 * eps) << "eps = " << eps;
  }
  EXPECT_NEAR(err[1] / err[0], 0.1, 0.03);   // first order in eps
}

// Mesh phasing (Parker 2000; Parker & Lin 2004): with N equally spaced planets the l-th
// mesh harmonic moves the sun in rotation only if l z_s / N is whole, in translation only
// if (l z_s +- 1) / N is whole, else not at all. z_s = 27: N = 5 is a phased set (l = 1, 4:
// neither; 2, 3: translation; 5: rotation), N = 3 an in-phase one (every l: rotation).
TEST(PlanetaryMesh, PhasingSelectsTheHarmonicsOfTheSun) {
  for (int N : {3, 5}) {
    const PlanetarySet s = pm_held_set(N);
    const int H = 10, n = s.dofs();
    const HarmonicBalance hb = planetary_harmonic_balance(s, pm_meshes(s, 1.5), 0.02, pm_sun_torque(s), H);
    const Eigen::VectorXd X = pm_solve(hb, 2.0 * M_PI * 300.0);
    double rot[H + 1], tra[H + 1], largest = 0.0;
    for (int l = 1; l <= H; ++l) {
      rot[l] = std::abs(pm_harmonic(X, n, l, coordinate(Body::sun, 2)));
      tra[l] = std::hypot(std::abs(pm_harmonic(X, n, l, coordinate(Body::sun, 0))),
                          std::abs(pm_harmonic(X, n, l, coordinate(Body::sun, 1))));
      largest = std::max({largest, rot[l], tra[l]});
    }
    for (int l = 1; l <= H; ++l) {
      const int r = (l * kPmTeeth.sun) % N;
      const bool rotational = r == 0, translational = r == 1 || r == N - 1;
      if (rotational) EXPECT_GT(rot[l], 1e-6 * largest) << "N " << N << " l " << l;
      else EXPECT_LT(rot[l], 1e-10 * largest) << "N " << N << " l " << l;
      if (translational) EXPECT_GT(tra[l], 1e-6 * largest) << "N " << N << " l " << l;
      else EXPECT_LT(tra[l], 1e-10 * largest) << "N " << N << " l " << l;
    }
  }
}

// A stable point with contact loss (the example lin_parker_1999_loaded.json at 2583 Hz mesh
// frequency: five planets, k_double / k_single = 1.5) against GSL's rk8pd time integration of
// the same model from the HB orbit's initial state: the orbit it settles on has the HB's
// extreme mesh deflections, to 2e-3 of the largest with the example's H = 8, and closer with
// H = 16 by the rate of the HB truncation error: the contact force has a kink, so the
// orbit's harmonics decay as k^-4 and the error of its extremes as H^-3 (doubling H: / 8;
// checked: at least / 4). The stiffness wave is cut to H harmonics in both, so each H is its
// own model.
TEST(PlanetaryMesh, StablePointWithContactLossIsTheTimeIntegratedOrbit) {
  PlanetarySet s = pm_held_set(5);
  PlanetaryMeshes m = pm_meshes(s, 1.5);
  m.phases = mesh_phases(kPmTeeth, s.planet_angles, 0.0);
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
  f0(coordinate(Body::sun, 2)) = 100.0 / (0.5 * 27 * 0.0032 * std::cos(s.sun_pressure_angle));
  const double omega = 2.0 * M_PI * 2583.0;
  double err[2];
  bool loss = false;
  for (int k = 0; k < 2; ++k) {
    const int H = k == 0 ? 8 : 16;
    const HarmonicBalance hb = planetary_harmonic_balance(s, m, 0.02, f0, H);
    const Eigen::VectorXd X = pm_solve(hb, omega);
    const SteadyState ss = pm_integrate(hb, X, omega);
    ASSERT_TRUE(ss.converged) << "H = " << H;
    // the orbit attracts the integration: the program's stability label must say stable
    if (k == 0) {
      EXPECT_TRUE(floquet_of_hb_variational(hb, X, omega).stable);
    }
    const TiComparison cmp = pm_against_time_integration(hb, X, ss);
    err[k] = cmp.err;
    if (k == 0 && cmp.drive_min < 0.0) loss = true;
  }
  EXPECT_TRUE(loss) << "no mesh loses contact at H = 8";
  EXPECT_LT(err[0], 2e-3);
  EXPECT_LT(err[1], 0.25 * err[0]);
}

// The loaded five-planet set of the test above with a back flank on every mesh (20 contacts).
// A backlash far larger than any deflection (1 mm against about 3 um) leaves the back flanks
// open, and the orbit is the drive-flank-only one: checked where the drive flanks lose
// contact (2583 Hz) and at the largest K_v (1995 Hz), every coefficient to 1e-9 of the
// largest. A back flank whose gap had the wrong sign would be shut and change the orbit.
TEST(PlanetaryMesh, LargeBacklashIsTheDriveFlankOnlyResponse) {
  const PlanetarySet s = pm_held_set(5);
  PlanetaryMeshes m = pm_meshes(s, 1.5);
  const HarmonicBalance drive_only = planetary_harmonic_balance(s, m, 0.02, pm_sun_torque(s), 8);
  m.backlash.assign(10, 1e-3);
  const HarmonicBalance both = planetary_harmonic_balance(s, m, 0.02, pm_sun_torque(s), 8);
  ASSERT_EQ(both.contacts().size(), 20u);
  for (double hz : {2583.0, 1995.0}) {
    const double omega = 2.0 * M_PI * hz;
    const Eigen::VectorXd X1 = pm_solve(drive_only, omega);
    Eigen::VectorXd X2 = X1;   // Newton on the model with back flanks, from the drive-only orbit
    const NewtonReport r = newton_solve(both, X2, omega, both.scaling(omega, omega));
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_LT((X2 - X1).lpNorm<Eigen::Infinity>(), 1e-9 * X1.lpNorm<Eigen::Infinity>()) << hz << " Hz";
    bool loss = false;
    for (std::size_t c = 0; c < 10; ++c) {
      const Eigen::VectorXd u = drive_only.penetration(X1, c);
      for (int j = 0; j < 256; ++j) loss = loss || trig_series(u, 2.0 * M_PI * j / 256) < 0.0;
    }
    if (hz == 2583.0) {
      EXPECT_TRUE(loss) << "the check needs a drive flank that opens";
    }
  }
}

// Planet load sharing (planet_load_sharing) under pin position errors, at a mesh frequency of
// 1 Hz (quasi-static: inertia is (1 Hz / 1 kHz)^2 = 1e-6 of the stiffness) and constant mesh
// stiffness: the HB orbit's L_n against the static solution of the closed set solved here
// directly, (K_b + sum k d d') x = f0 - sum k g d with g = -e_n cos(alpha) on both meshes of
// planet n, F_sn = k (d_sn' x + g_sn), L_n = N F_sn / sum F_sm. Errors of 1 and -0.5 um keep
// every mesh closed and move the shares by about 2 % (the sun floats on its bearings and
// evens them out; the check asks for more than 1 %, so that it compares a real spread).
// Without errors every L_n is 1.
TEST(PlanetaryMesh, LoadSharingWithPinErrorsIsTheStaticSolution) {
  const PlanetarySet s = pm_held_set(4);
  const int N = 4;
  PlanetaryMeshes m = pm_meshes(s, 1.0);
  const double omega = 2.0 * M_PI * 1.0;
  for (int errors = 0; errors < 2; ++errors) {
    m.pin_errors = errors ? std::vector<double>{1e-6, 0.0, -0.5e-6, 0.0} : std::vector<double>{};
    const HarmonicBalance hb = planetary_harmonic_balance(s, m, 0.02, pm_sun_torque(s), 4);
    const Eigen::VectorXd X = pm_solve(hb, omega);
    const std::vector<double> F0 = planetary_static_mesh_forces(hb, N);
    std::vector<PlanetaryMeshOrbit> o;
    for (int i = 0; i < 2 * N; ++i) o.push_back(planetary_mesh_orbit(hb, back_flank_contacts(m, N), X, i, F0[std::size_t(i)]));
    const std::vector<double> L = planet_load_sharing(o, N);
    // the static solution, assembled here
    const PlanetaryMatrices mat = planetary_matrices(s);
    Eigen::MatrixXd K = mat.K_bearing;
    Eigen::VectorXd f = pm_sun_torque(s);
    std::vector<Eigen::VectorXd> d;
    std::vector<double> g;
    for (int i = 0; i < 2 * N; ++i) {
      d.push_back(i < N ? sun_mesh_direction(s, i) : ring_mesh_direction(s, i - N));
      const double e = m.pin_errors.empty() ? 0.0 : m.pin_errors[std::size_t(i % N)];
      g.push_back(-e * std::cos(s.sun_pressure_angle));   // alpha_s = alpha_r here
      K += 5e8 * d.back() * d.back().transpose();
      f -= 5e8 * g.back() * d.back();
    }
    const Eigen::VectorXd x = K.ldlt().solve(f);
    double sum = 0.0, Fs[4];
    for (int n = 0; n < N; ++n) {
      Fs[n] = 5e8 * (d[std::size_t(n)].dot(x) + g[std::size_t(n)]);
      sum += Fs[n];
      for (int i : {n, n + N}) ASSERT_GT(5e8 * (d[std::size_t(i)].dot(x) + g[std::size_t(i)]), 0.0) << "mesh " << i << " opens";
    }
    double spread = 0.0;
    for (int n = 0; n < N; ++n) {
      EXPECT_NEAR(L[std::size_t(n)], N * Fs[n] / sum, 1e-5) << "planet " << n + 1 << (errors ? " with errors" : "");
      spread = std::max(spread, std::fabs(N * Fs[n] / sum - 1.0));
    }
    if (errors) EXPECT_GT(spread, 0.01) << "the errors should move the shares";
    else EXPECT_LT(spread, 1e-9);
  }
}

// A stable point with back-flank impacts against GSL's rk8pd time integration: the loaded
// five-planet set of the tests above (gamma_rs = 0, the example's loading) with a back flank
// at 1 um backlash on every mesh (the static mesh deflection is about 1 um, so the teeth
// cross the backlash near the resonances). Its branch over 2050-2400 Hz mesh frequency (arc
// length; it folds twice near 2330 and 2130 Hz) has its back impacts on the segment between
// the folds and after, where Newton from a linear guess does not reach them; the last point
// of the curve (past both folds) whose HB orbit hits a back flank and is stable by the
// variational Floquet multipliers is integrated from its initial state: the integration settles on it, the
// extreme penetrations of all 20 contacts within 3e-3 of the largest drive-flank penetration
// (H = 8, as the drive-flank check above), and the integrated orbit itself hits a back flank.
TEST(PlanetaryMesh, StablePointWithBackImpactsIsTheTimeIntegratedOrbit) {
  PlanetarySet s = pm_held_set(5);
  PlanetaryMeshes m = pm_meshes(s, 1.5);
  m.phases = mesh_phases(kPmTeeth, s.planet_angles, 0.0);
  m.backlash.assign(10, 1e-6);
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
  f0(coordinate(Body::sun, 2)) = 100.0 / (0.5 * 27 * 0.0032 * std::cos(s.sun_pressure_angle));
  const HarmonicBalance hb = planetary_harmonic_balance(s, m, 0.02, f0, 8);
  ASSERT_EQ(hb.contacts().size(), 20u);
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 2050.0;
  o.omega_max = 2.0 * M_PI * 2400.0;
  o.stability = StabilityMethod::none;
  const FrequencyCurve c = sweep_frequency(hb, o, "back flanks");
  ASSERT_TRUE(c.complete) << c.failure;
  const BranchPoint* hit = nullptr;
  for (auto it = c.branch.points.rbegin(); it != c.branch.points.rend(); ++it) {   // from the end: past the folds
    const BranchPoint& p = *it;
    double back = -INFINITY;
    for (std::size_t k = 10; k < 20; ++k) {
      const Eigen::VectorXd u = hb.penetration(p.X, k);
      for (int j = 0; j < 256; ++j) back = std::max(back, trig_series(u, 2.0 * M_PI * j / 256));
    }
    if (back > 0.0 && floquet_of_hb_variational(hb, p.X, p.omega).stable) {
      hit = &p;
      break;
    }
  }
  ASSERT_NE(hit, nullptr) << "no stable point with back impacts on the curve";
  // Its critical multiplier is about 0.98 (a lightly damped mode): periodic to 1e-7 of the
  // displacement scale, far below the 3e-3 compared, within 1000 periods.
  const SteadyState ss = pm_integrate(hb, hit->X, hit->omega, 1e-7, 1000);
  ASSERT_TRUE(ss.converged) << hit->omega / (2.0 * M_PI) << " Hz, mismatch " << ss.mismatch;
  const TiComparison cmp = pm_against_time_integration(hb, hit->X, ss, 10);
  EXPECT_GT(cmp.back_max, 0.0) << "no back flank touches in the integrated orbit";
  EXPECT_LT(cmp.drive_min, 0.0) << "no drive flank opens in the integrated orbit";
  EXPECT_LT(cmp.err, 3e-3) << hit->omega / (2.0 * M_PI) << " Hz";
}
