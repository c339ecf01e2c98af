// The meshes of a planetary set over time (gears/sets/planetary_mesh.hpp) through the
// harmonic-balance engine. Each check names its independent truth: the first-order
// (linear) forced response to a small stiffness variation, and the mesh-phasing rule of
// Parker (2000, J. Sound Vib. 236:561) and Parker & Lin (2004).
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/floquet.hpp"
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
    const int H = k == 0 ? 8 : 16, n = s.dofs();
    const HarmonicBalance hb = planetary_harmonic_balance(s, m, 0.02, f0, H);
    const Eigen::VectorXd X = pm_solve(hb, omega);
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, X, omega, x0, v0);
    TimeIntegrationOptions o;
    o.x_scale = hb.scaling(omega, omega).x.maxCoeff();
    o.max_periods = 400;
    const SteadyState ss = TimeIntegrator(hb).steady_state(x0, v0, omega, o);
    ASSERT_TRUE(ss.converged) << "H = " << H;
    // the orbit attracts the integration: the program's stability label must say stable
    if (k == 0) {
      EXPECT_TRUE(floquet_of_hb_variational(hb, X, omega).stable);
    }
    err[k] = 0.0;
    double largest = 0.0;
    for (const UnilateralContact& ct : hb.contacts()) {
      const Eigen::VectorXd u = ss.x * ct.normal;
      double hb_max = -INFINITY, hb_min = INFINITY;
      for (int j = 0; j < 1024; ++j) {
        const double th = 2.0 * M_PI * j / 1024;
        double v = ct.normal.dot(X.head(n));
        for (int l = 1; l <= H; ++l)
          v += ct.normal.dot(X.segment((2 * l - 1) * n, n)) * std::cos(l * th) + ct.normal.dot(X.segment(2 * l * n, n)) * std::sin(l * th);
        hb_max = std::max(hb_max, v);
        hb_min = std::min(hb_min, v);
      }
      err[k] = std::max({err[k], std::fabs(hb_max - u.maxCoeff()), std::fabs(hb_min - u.minCoeff())});
      largest = std::max(largest, u.maxCoeff());
      if (k == 0 && u.minCoeff() < 0.0) loss = true;
    }
    err[k] /= largest;
  }
  EXPECT_TRUE(loss) << "no mesh loses contact at H = 8";
  EXPECT_LT(err[0], 2e-3);
  EXPECT_LT(err[1], 0.25 * err[0]);
}
