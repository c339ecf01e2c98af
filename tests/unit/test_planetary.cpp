// The planetary set of Lin & Parker 1999 (gears/sets/planetary.hpp). Each check names its
// independent truth: the published natural frequencies (reference/lin_parker_1999.md) and
// the mode structure Lin & Parker prove for equally spaced planets.
#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/gears/sets/planetary.hpp"

using namespace gearhb;

namespace {

double lp_hz(double omega) { return omega / (2.0 * M_PI); }

}  // namespace

// Lin & Parker 1999 Table 1, N = 3: the rotational modes at 0, 1475.7, 1930.3, 2658.3, 7462.8
// and 11775.3 Hz (printed to 0.1 Hz, so within 0.05 Hz).
TEST(Planetary, LinParkerRotationalFrequenciesOfThreePlanets) {
  const std::vector<double> published = {0.0, 1475.7, 1930.3, 2658.3, 7462.8, 11775.3};
  std::vector<double> rotational;
  for (const PlanetaryMode& m : planetary_modes(lin_parker_1999_set(3)))
    if (m.type == ModeType::rotational) rotational.push_back(lp_hz(m.omega));
  ASSERT_EQ(rotational.size(), published.size());
  for (std::size_t i = 0; i < published.size(); ++i) EXPECT_NEAR(rotational[i], published[i], 0.05) << i;
}

// Lin & Parker's theorem for N equally spaced planets: 6 rotational modes (multiplicity 1),
// 6 pairs of translational modes (multiplicity 2), 3 planet modes of multiplicity N - 3, and
// nothing else (3 (N + 3) DOFs = 6 + 12 + 3 (N - 3)).
TEST(Planetary, ModeTypesAndMultiplicitiesForThreeToSixPlanets) {
  for (int N = 3; N <= 6; ++N) {
    const std::vector<PlanetaryMode> modes = planetary_modes(lin_parker_1999_set(N));
    ASSERT_EQ(int(modes.size()), 3 * (N + 3));
    std::map<ModeType, std::map<int, int>> groups;   // type -> multiplicity -> groups
    int last_group = -1;
    for (const PlanetaryMode& m : modes) {
      if (m.group == last_group) continue;
      last_group = m.group;
      ++groups[m.type][m.multiplicity];
    }
    std::map<ModeType, std::map<int, int>> theorem = {{ModeType::rotational, {{1, 6}}},
                                                      {ModeType::translational, {{2, 6}}}};
    if (N > 3) theorem[ModeType::planet] = {{N - 3, 3}};
    EXPECT_EQ(groups, theorem) << "N = " << N;
  }
}

// Unequally spaced planets (0, 80, 180, 270 deg) break the structure the theorem needs:
// no frequency stays double (the translational pairs split) and some modes move the
// central members in rotation and translation at once.
TEST(Planetary, UnequalSpacingMixesTheModeTypes) {
  PlanetarySet s = lin_parker_1999_set(4);
  s.planet_angles = {0.0, 80.0 * M_PI / 180.0, M_PI, 270.0 * M_PI / 180.0};
  int mixed = 0, pairs = 0;
  for (const PlanetaryMode& m : planetary_modes(s)) {
    mixed += m.type == ModeType::mixed ? 1 : 0;
    pairs += m.multiplicity == 2 ? 1 : 0;
  }
  EXPECT_GT(mixed, 0);
  EXPECT_EQ(pairs, 0);
}

// The gyroscopic eigenproblem at carrier speed 0 is the symmetric one by another method
// (first-order form, general Schur eigenvalues vs the generalised self-adjoint solver).
TEST(Planetary, FirstOrderFormAtRestIsTheSymmetricProblem) {
  const PlanetarySet s = lin_parker_1999_set(5);
  const std::vector<PlanetaryMode> modes = planetary_modes(s);
  const Eigen::VectorXd omega = natural_frequencies_at_speed(s, 0.0);
  ASSERT_EQ(omega.size(), Eigen::Index(modes.size()));
  for (std::size_t i = 1; i < modes.size(); ++i)
    EXPECT_NEAR(omega(Eigen::Index(i)), modes[i].omega, 1e-8 * modes.back().omega) << i;
}

// The rotating frame (gyroscopic G, centripetal K_Omega): a body on isotropic bearings,
// seen from a frame turning at Omega, vibrates at |omega_0 +- Omega| (x'' - 2 Omega y' +
// (omega_0^2 - Omega^2) x = 0 and its twin, solved in closed form). With the meshes nearly
// cut (1e-6 N/m) the sun is such a body: omega_0 = sqrt(k_s / m_s).
TEST(Planetary, IsolatedSunInTheRotatingFrameSplitsByTheCarrierSpeed) {
  PlanetarySet s = lin_parker_1999_set(3);
  s.sun_mesh = s.ring_mesh = 1e-6;
  const double omega0 = std::sqrt(s.sun.bearing / s.sun.mass), Omega = 2000.0;
  const Eigen::VectorXd omega = natural_frequencies_at_speed(s, Omega);
  for (double expected : {omega0 - Omega, omega0 + Omega}) {
    double nearest = INFINITY;
    for (Eigen::Index i = 0; i < omega.size(); ++i) nearest = std::min(nearest, std::fabs(omega(i) - expected));
    EXPECT_LT(nearest, 1e-6 * omega0) << expected;
  }
}

// A set with one planet whose carrier is held rigidly (1e16 N/m) and whose ring is cut off
// (ring mesh 1e-6 N/m) is the sun-planet pair on bearings: its natural frequencies contain
// those of chapter 6's six-DOF pair model (gears/pair/gear_pair.hpp, built there from the
// thesis' own line-of-action projection T2) with the same masses, inertias, bearings and mesh
// (planet torsion free, as a planet is: kth2 = 0). Frame and rotation senses differ; the
// frequencies do not.
TEST(Planetary, OnePlanetIsTheSixDofPairModel) {
  GearPairParameters p;
  p.kth2 = 0.0;
  const Modes pair = modal_analysis(gear_pair_mass(p), gear_pair_support_stiffness(p) + gear_pair_mesh_stiffness(p));
  PlanetarySet s = lin_parker_1999_set(1);
  s.sun = {p.m1, p.I1 / (p.rb1 * p.rb1), p.kx1, p.kth1 / (p.rb1 * p.rb1)};
  s.planet_mass = p.m2;
  s.planet_inertia_r2 = p.I2 / (p.rb2 * p.rb2);
  s.planet_bearing = p.kx2;
  s.carrier.bearing = s.carrier.torsional = 1e16;
  s.sun_mesh = p.kc;
  s.ring_mesh = 1e-6;
  s.sun_pressure_angle = p.pressure_angle_deg * M_PI / 180.0;
  const std::vector<PlanetaryMode> set = planetary_modes(s);
  for (Eigen::Index i = 0; i < pair.omega.size(); ++i) {
    double nearest = INFINITY;
    for (const PlanetaryMode& m : set) nearest = std::min(nearest, std::fabs(m.omega - pair.omega(i)));
    EXPECT_LT(nearest, 1e-6 * pair.omega.maxCoeff()) << "pair mode " << i << " at " << pair.omega(i) << " rad/s";
  }
}
