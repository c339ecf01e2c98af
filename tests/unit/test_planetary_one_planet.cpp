// A planetary set with one planet (issue 36 §3: "a set with one planet equals the pair model
// with the same bearings"), nonlinear: its sun-planet and ring-planet meshes lose contact.
//
// What maps to what. The pair model of gearhb_gear (gears/dynamics/mesh_dynamics.hpp,
// six_dof: q = [x1, y1, x2, y2, p], each gear on its bearing to ground, p the relative
// rotation along the line of action) is not the one-planet set: the planet sits on a bearing
// to a carrier that moves (three DOFs of its own), it meshes with the ring as well, and the
// sun and the planet rotate independently (u_s, u_p: two rotations, the pair has one
// relative one). No choice of the set's numbers removes the carrier and the ring exactly
// (only a limit of infinite stiffnesses would), so the one-planet set is checked as the
// brief allows where the mapping is not exact: against a GSL time integration of the same
// equations, written here again from Lin & Parker (1999, J. Vib. Acoust. 121:316, eqs.
// (1)-(3)) and not taken from gears/sets/planetary.cpp: the mass matrix, the bearings (the
// planet's to the moving carrier), the two mesh directions, the modal damping of the mean
// set and the torque on the sun. Taken from the library are only the meshes' stiffness waves
// and gaps (RectangularMesh and mesh_phases, checked in test_planetary_mesh.cpp) and the
// integrator (TimeIntegrator, GSL rk8pd, checked against closed forms in its own tests).
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;

namespace {

// Lin & Parker's set with one planet, the carrier held by an output shaft of 1e8 N/m, the
// mesh stiffness a rectangular wave k_double / k_single = 1.5, 100 N m on the sun.
struct OnePlanet {
  PlanetarySet s = lin_parker_1999_set(1);
  PlanetaryMeshes m;
  double torque = 100.0, r_sun = 0.5 * 27 * 0.0032 * std::cos(24.6 * M_PI / 180.0);
  OnePlanet() {
    s.carrier.torsional = 1e8;
    m.sun = {5e8, 1.6, 1.5};
    m.ring = {5e8, 1.8, 1.5};
    m.phases = mesh_phases(PlanetaryTeeth{27, 33, 93, 0.0032, 1.0}, s.planet_angles, 0.3);
  }
  HarmonicBalance library_model(int H) const {
    Eigen::VectorXd f0 = Eigen::VectorXd::Zero(s.dofs());
    f0(coordinate(Body::sun, 2)) = torque / r_sun;
    return planetary_harmonic_balance(s, m, 0.02, f0, H);
  }
};

// The equations of motion written out for one planet at psi = 0: q = [x_c, y_c, u_c, x_r,
// y_r, u_r, x_s, y_s, u_s, zeta, eta, u_p] (the library's order, so that the states compare).
HarmonicBalance hand_written_model(const OnePlanet& op, const HarmonicBalance& library, int H) {
  const PlanetarySet& s = op.s;
  const double as = s.sun_pressure_angle, ar = s.ring_pressure_angle;
  Eigen::VectorXd mass(12);
  mass << s.carrier.mass, s.carrier.mass, s.carrier.inertia_r2, s.ring.mass, s.ring.mass, s.ring.inertia_r2,
      s.sun.mass, s.sun.mass, s.sun.inertia_r2, s.planet_mass, s.planet_mass, s.planet_inertia_r2;
  Eigen::VectorXd ground(12);   // the central members' bearings and torsional stiffnesses; the planet has none to ground
  ground << s.carrier.bearing, s.carrier.bearing, s.carrier.torsional, s.ring.bearing, s.ring.bearing, s.ring.torsional,
      s.sun.bearing, s.sun.bearing, s.sun.torsional, 0.0, 0.0, 0.0;
  Eigen::MatrixXd K = ground.asDiagonal();
  // the planet bearing (psi = 0): radial x_c - zeta, tangential y_c + u_c - eta
  Eigen::VectorXd radial = Eigen::VectorXd::Zero(12), tangential = Eigen::VectorXd::Zero(12);
  radial(0) = 1.0, radial(9) = -1.0;
  tangential(1) = 1.0, tangential(2) = 1.0, tangential(10) = -1.0;
  K += s.planet_bearing * (radial * radial.transpose() + tangential * tangential.transpose());
  // the mesh deflections (psi_s = -alpha_s, psi_r = alpha_r)
  Eigen::VectorXd ds = Eigen::VectorXd::Zero(12), dr = Eigen::VectorXd::Zero(12);
  ds(6) = std::sin(as), ds(7) = std::cos(as), ds(8) = 1.0, ds(9) = -std::sin(as), ds(10) = -std::cos(as), ds(11) = 1.0;
  dr(3) = -std::sin(ar), dr(4) = std::cos(ar), dr(5) = 1.0, dr(9) = std::sin(ar), dr(10) = -std::cos(ar), dr(11) = -1.0;
  // modal damping of the mean set (every mesh closed at its mean stiffness): C = M Phi diag(2 zeta w) Phi' M
  const Eigen::MatrixXd M = mass.asDiagonal();
  const Eigen::MatrixXd Kmean = K + op.m.sun.mean * ds * ds.transpose() + op.m.ring.mean * dr * dr.transpose();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(Kmean, M);
  const Eigen::MatrixXd& Phi = modes.eigenvectors();
  const Eigen::VectorXd w = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::MatrixXd C = M * Phi * (2.0 * 0.02 * w).asDiagonal() * Phi.transpose() * M;
  // the drive flanks along ds and dr, with the library's stiffness waves and gaps
  std::vector<UnilateralContact> contacts = library.contacts();
  EXPECT_EQ(contacts.size(), 2u);
  contacts[0].normal = ds;
  contacts[1].normal = dr;
  Excitation f;
  f.f0 = Eigen::VectorXd::Zero(12);
  f.f0(8) = op.torque / op.r_sun;
  f.fc = f.fs = Eigen::VectorXd::Zero(12);
  return HarmonicBalance(LinearSystem{M, C, K}, contacts, f, H);
}

// The largest difference of the two meshes' deflections over the period, HB orbit X against
// the integrated orbit of `other`, over the largest deflection; and the smallest integrated
// sun-mesh deflection (< 0: the mesh has lost contact).
struct MeshComparison {
  double err = 0.0, sun_min = INFINITY;
};
MeshComparison against_integration(const HarmonicBalance& hb, const Eigen::VectorXd& X, const HarmonicBalance& other,
                                   double omega) {
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, X, omega, x0, v0);
  TimeIntegrationOptions o;
  o.x_scale = hb.scaling(omega, omega).x.maxCoeff();
  o.max_periods = 600;
  o.periodicity_tol = 1e-9;
  const SteadyState ss = TimeIntegrator(other).steady_state(x0, v0, omega, o);
  EXPECT_TRUE(ss.converged) << "the integration did not settle at " << omega / (2.0 * M_PI) << " Hz";
  MeshComparison r;
  double largest = 0.0;
  for (std::size_t c = 0; c < 2; ++c) {
    const Eigen::VectorXd uc = hb.penetration(X, c);
    const Eigen::VectorXd u = (ss.x * other.contacts()[c].normal).array() + other.contacts()[c].gap;
    double hb_max = -INFINITY, hb_min = INFINITY;
    for (int j = 0; j < 1024; ++j) {
      const double v = trig_series(uc, 2.0 * M_PI * j / 1024);
      hb_max = std::max(hb_max, v), hb_min = std::min(hb_min, v);
    }
    r.err = std::max({r.err, std::fabs(hb_max - u.maxCoeff()), std::fabs(hb_min - u.minCoeff())});
    largest = std::max(largest, u.maxCoeff());
    if (c == 0) r.sun_min = u.minCoeff();
  }
  r.err /= largest;
  return r;
}

}  // namespace

// The library's one-planet set (planetary_harmonic_balance) swept over 300-3000 Hz at H = 8;
// at the stable point (variational Floquet, as gearhb_planetary labels it) of deepest
// contact loss of the sun-planet mesh, the hand-written equations integrated by rk8pd from
// the HB orbit settle on an orbit that loses contact too, and the HB orbit converges to it at
// the rate of the HB truncation error: the contact force has a kink, so the orbit's harmonics
// decay as k^-4 and the error of its extremes as H^-3 (doubling H divides it by 8; checked:
// by at least 3 at each doubling, H = 8, 16, 32). A wrong mass, bearing, direction or damping
// in either model would leave a difference that does not shrink with H. (Measured: 1.1e-2,
// 1.5e-3 at H = 8, 16 at 2182 Hz; a first bound of 1e-2 at H = 8 alone, guessed before the
// run, failed at 1.1e-2 and was replaced by this convergence check.)
TEST(PlanetaryOnePlanet, LosesContactAsTheHandWrittenEquationsIntegrated) {
  const OnePlanet op;
  const HarmonicBalance hb8 = op.library_model(8);
  SweepOptions o;
  o.omega_min = 2.0 * M_PI * 300.0;
  o.omega_max = 2.0 * M_PI * 3000.0;
  o.stability = StabilityMethod::none;
  const FrequencyCurve c = require_complete(sweep_frequency(hb8, o, "one planet"), "one planet");
  // the stable point whose sun mesh opens deepest (its smallest HB deflection)
  double deepest = 0.0, omega = 0.0;
  Eigen::VectorXd X8;
  const Aft aft(8);
  for (const BranchPoint& p : c.branch.points) {
    const double lowest = aft.to_time(hb8.penetration(p.X, 0)).minCoeff();
    if (lowest < deepest && floquet_of_hb_variational(hb8, p.X, p.omega).stable) deepest = lowest, omega = p.omega, X8 = p.X;
  }
  ASSERT_LT(deepest, 0.0) << "no stable point of the one-planet set loses contact on its sun mesh";
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const int H = 8 << k;
    const HarmonicBalance hb = op.library_model(H);
    Eigen::VectorXd X = Eigen::VectorXd::Zero(hb.size());   // H = 16 from the H = 8 orbit, its higher harmonics 0
    X.head(X8.size()) = X8;
    const NewtonReport r = newton_solve(hb, X, omega, hb.scaling(omega, omega));
    ASSERT_TRUE(r.converged) << "H = " << H << ": " << r.message;
    const MeshComparison cmp = against_integration(hb, X, hand_written_model(op, hb, H), omega);
    err[k] = cmp.err;
    EXPECT_LT(cmp.sun_min, 0.0) << "H = " << H << ": the integrated sun mesh does not lose contact";
    std::printf("one planet at %.1f Hz, H = %d: mesh deflections HB vs hand-written equations integrated: %.3e\n",
                omega / (2.0 * M_PI), H, err[k]);
  }
  EXPECT_LT(err[1], err[0] / 3.0);
  EXPECT_LT(err[2], err[1] / 3.0);
}
