// The mesh stiffnesses of a planetary set from its teeth (tools/planetary_stiffness.hpp,
// gears/sets/planetary_mesh.hpp SampledMesh). Each check names its independent truth: a
// closed-form Fourier series, the linear statics of Lin & Parker's model, the geometric
// construction of the path of contact, and ISO 6336-1's formula typed from its table.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/gears/rating/iso6336.hpp"
#include "gearhb/gears/sets/planetary_mesh.hpp"
#include "gearhb/gears/tooth/potential_energy.hpp"
#include "gearhb/tools/planetary_file.hpp"
#include "gearhb/tools/planetary_stiffness.hpp"

using namespace gearhb;

namespace {

// The teeth of programs/gearhb_planetary/examples/gtf_star_five_planets_teeth.json.
const PlanetaryTeeth kGtfTeeth{32, 33, 98, 0.0045, 1.0};
const double kAlpha = 25.0 * M_PI / 180.0;

// The path of contact of the internal pair by construction: the planet's centre at the
// origin, the ring's at (a, 0), a = (z_r - z_p) m / 2; the line of action n.P = r_bp touches
// both base circles with both centres on the same side (n.O_r - r_bp = -r_br: n_x = (r_bp -
// r_br) / a). Along it from the planet's tangent point T_p = r_bp n, P = T_p + s e, the
// contact points are those inside the planet's tip circle and outside the ring's tip circle
// (the ring's teeth reach inwards to it) on the side s > 0 (beyond the planet's tangent
// point), found on a grid of 4e5 points along the line (to 4e-7 m).
double constructed_internal_contact_ratio(const PlanetaryTeeth& t, double alpha) {
  const double m = t.module, a = 0.5 * (t.ring - t.planet) * m;
  const double rbp = 0.5 * t.planet * m * std::cos(alpha), rbr = 0.5 * t.ring * m * std::cos(alpha);
  const double rap = 0.5 * t.planet * m + m, rar = 0.5 * t.ring * m - m;
  const double nx = (rbp - rbr) / a, ny = std::sqrt(1.0 - nx * nx);
  const double Tpx = rbp * nx, Tpy = rbp * ny, ex = -ny, ey = nx;
  double lo = INFINITY, hi = -INFINITY;
  const double step = rap / 2e5;
  for (double s = step; s <= 2.0 * rap; s += step) {
    const double px = Tpx + s * ex, py = Tpy + s * ey;
    if (std::hypot(px, py) <= rap && std::hypot(px - a, py) >= rar) lo = std::min(lo, s), hi = std::max(hi, s);
  }
  return (hi - lo) / (M_PI * m * std::cos(alpha));
}

}  // namespace

// k(theta) samples of 3 + 0.6 cos(2 theta) + 0.3 sin(theta): harmonics / mean are exactly
// [1, 0, 0.1, 0.2, 0, 0, ...] (a trigonometric polynomial is its own Fourier series).
TEST(PlanetaryStiffness, SampledMeshHarmonicsAreTheFourierSeries) {
  SampledMesh k;
  const int J = 16;
  for (int j = 0; j < J; ++j) {
    const double th = 2.0 * M_PI * j / J;
    k.samples.push_back(3.0 + 0.6 * std::cos(2.0 * th) + 0.3 * std::sin(th));
  }
  EXPECT_NEAR(k.mean(), 3.0, 1e-14);
  const Eigen::VectorXd c = k.harmonics(5);
  const double expected[11] = {1.0, 0.0, 0.1, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < 11; ++i) EXPECT_NEAR(c(i), expected[i], 1e-14) << "coefficient " << i;
  EXPECT_THROW(k.harmonics(8), std::invalid_argument);   // 16 samples resolve 7 harmonics
}

// The nominal mesh force from the torque balance against the static solution of the
// linear model (every mesh closed at its mean stiffness, planetary_static_mesh_forces) loaded
// as gearhb_planetary loads it (planetary_response_model: the file's torque on the input),
// the input member free to turn and the other two held: the sun, the carrier or the ring
// driven. Each mesh's static force is F, and positive: the drive flanks carry it.
TEST(PlanetaryStiffness, NominalForceIsTheStaticSolution) {
  const int N = 5;
  PlanetaryFile f;
  f.teeth = kGtfTeeth;
  f.set = lin_parker_1999_set(N);
  f.set.sun_pressure_angle = f.set.ring_pressure_angle = kAlpha;
  f.meshes.sun = {2e9, 1.6, 1.0};
  f.meshes.ring = {2.5e9, 1.8, 1.0};
  f.meshes.phases = mesh_phases(kGtfTeeth, f.set.planet_angles, 0.0);
  f.response.torque = 1000.0;
  f.response.harmonics = 2;
  for (const Body input : {Body::sun, Body::carrier, Body::ring}) {
    f.response.input = input;
    for (Body b : {Body::sun, Body::ring, Body::carrier})
      (b == Body::sun ? f.set.sun : b == Body::ring ? f.set.ring : f.set.carrier).torsional = b == input ? 0.0 : 1e9;
    const std::vector<double> F0 = planetary_static_mesh_forces(planetary_response_model(f), N);
    const double F = nominal_mesh_force(kGtfTeeth, kAlpha, N, input, f.response.torque);
    for (int i = 0; i < 2 * N; ++i) EXPECT_NEAR(F0[std::size_t(i)] / F, 1.0, 1e-9) << "input " << int(input) << " mesh " << i;
  }
}

// The internal pair's contact ratio (closed form) against the path of contact constructed
// on the line of action between the tip circles: the example's ring-planet pair and a
// 20-degree one.
TEST(PlanetaryStiffness, InternalContactRatioIsTheConstructedPath) {
  EXPECT_NEAR(internal_contact_ratio(kGtfTeeth, kAlpha), constructed_internal_contact_ratio(kGtfTeeth, kAlpha), 1e-4);
  const PlanetaryTeeth t20{27, 33, 93, 0.0032, 1.0};
  const double a20 = 20.0 * M_PI / 180.0;
  EXPECT_NEAR(internal_contact_ratio(t20, a20), constructed_internal_contact_ratio(t20, a20), 1e-4);
  EXPECT_GT(internal_contact_ratio(t20, a20), 1.0);
}

// ISO 6336-1:2006 eq. (99), Table 9, for the internal pair (zn2 infinite): by hand for the
// example's planet (z 33, x 0, alpha 25 deg, h_fP = 1.25 m, b = 120 mm, line load >= 100 N/mm):
//   q' = 0.04723 + 0.15551 / 33 = 0.0519424 mm um / N,  c'_th = 19.2521 N/(mm um),
//   C_B = [1 + 0.5 (1.2 - 1.25)] [1 - 0.02 (20 - 25)] = 0.975 x 1.1 = 1.0725,
//   c' = c'_th 0.8 C_B = 16.5183 N/(mm um),  c' b = 1.98220e9 N/m.
TEST(PlanetaryStiffness, InternalIsoStiffnessIsTheStandardsFormula) {
  Iso6336Input in;
  in.z1 = 33;
  in.internal2 = true;
  in.normal_pressure_angle_deg = 25.0;
  in.hfP_over_mn = 1.25;
  in.eps_alpha = 1.7;
  in.face_width_m = 0.12;
  const Iso6336Stiffness s = iso6336_mesh_stiffness(in);
  const double q = 0.04723 + 0.15551 / 33.0, c = 1.0 / q * 0.8 * 0.975 * 1.1;
  EXPECT_NEAR(s.q_prime, q, 1e-15);
  EXPECT_NEAR(s.c_single_total, c * 120.0 * 1e6, 1e-6 * c * 120e6);
  EXPECT_NEAR(s.c_single_total, 1.98220e9, 1e5);
  EXPECT_NEAR(s.c_gamma_alpha_total, s.c_single_total * (0.75 * 1.7 + 0.25), 1.0);
  // an external wheel of many teeth tends to it (the internal gear's limit z2 -> infinity)
  in.internal2 = false;
  in.z2 = 100000000;   // C3 / zn2 = 2.6e-9 of q' = 0.052
  EXPECT_NEAR(iso6336_mesh_stiffness(in).c_single_total / s.c_single_total, 1.0, 1e-7);
}

// The internal tooth (pe_internal_tooth_compliance) against the external one of as many teeth
// loaded at the same height above its root: both tend to the rack's tooth as z grows, so
// their difference must fall as 1/z: a convergence study at z = 400, 1600, 6400, where each
// difference (bending, shear, axial compliance; load angle) shrinks by 4 within 20 % per step.
// (To leading order the two teeth's thicknesses differ by 2 s h / r over a height h: the
// internal tooth thins by s / r per unit height faster than the rack, the external slower;
// about 9 / z of the thickness at the root here, 27 / z in the bending compliance.)
TEST(PlanetaryStiffness, InternalToothTendsToTheExternalAsTeethGrow) {
  PeOptions o;
  o.fillet_foundation = false;
  auto parts = [](const PeToothCompliance& c) { return std::vector<double>{c.bending, c.shear, c.axial}; };
  std::vector<double> diff[3];
  const int teeth[3] = {400, 1600, 6400};
  for (int i = 0; i < 3; ++i) {
    PeGear g;
    g.teeth = teeth[i];
    g.module = 0.004;
    g.pressure_angle = 20.0 * M_PI / 180.0;
    g.face_width = 0.05;
    const double r0 = 0.5 * g.module * g.teeth, h = 0.3 * g.module;   // 0.3 m above the pitch circle
    const PeToothCompliance ext = pe_tooth_compliance(g, r0 + h, o);
    const PeToothCompliance in = pe_internal_tooth_compliance(g, r0 - h, o);
    const std::vector<double> e = parts(ext), n = parts(in);
    for (int k = 0; k < 3; ++k) diff[i].push_back(std::fabs(n[std::size_t(k)] / e[std::size_t(k)] - 1.0));
    diff[i].push_back(std::fabs(in.load_angle - ext.load_angle));
  }
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(diff[i][std::size_t(k)] / diff[i + 1][std::size_t(k)], 4.0, 0.8)
          << "part " << k << ", z " << teeth[i] << " -> " << teeth[i + 1] << ": " << diff[i][std::size_t(k)] << " -> "
          << diff[i + 1][std::size_t(k)];
  EXPECT_NEAR(diff[2][0] * 6400, 27.0, 8.0) << "the leading-order estimate of the bending difference";
}

// The internal tooth against a second implementation: reference/scripts/internal_tooth_pe.py
// integrates the same compliances over the radius by composite Simpson (20 000 intervals; the
// library by Gauss-Legendre in the pressure angle), for the example's ring (z 98, m 4.5 mm,
// 25 deg, b 120 mm, E 206 GPa, nu 0.3) at its tip, its pitch circle and 1.1 m beyond it.
TEST(PlanetaryStiffness, InternalToothIsTheSimpsonIntegral) {
  PeGear g;
  g.teeth = 98;
  g.module = 0.0045;
  g.pressure_angle = 25.0 * M_PI / 180.0;
  g.face_width = 0.12;
  g.youngs_modulus = 206e9;
  g.poisson_ratio = 0.3;
  struct Row {
    double r, bending, shear, axial, load_angle;
  };
  const Row rows[3] = {{0.216000, 1.2700623298e-10, 1.6416092697e-10, 8.3808678551e-12, 0.396246246340},
                       {0.220500, 5.6413810095e-12, 5.8965885927e-11, 4.0616900077e-12, 0.452360846945},
                       {0.225450, 1.0744951582e-12, 5.1046524753e-12, 4.6207893030e-13, 0.508276387327}};
  for (const Row& w : rows) {
    const PeToothCompliance c = pe_internal_tooth_compliance(g, w.r);
    EXPECT_NEAR(c.bending / w.bending, 1.0, 1e-8) << "r " << w.r;
    EXPECT_NEAR(c.shear / w.shear, 1.0, 1e-8) << "r " << w.r;
    EXPECT_NEAR(c.axial / w.axial, 1.0, 1e-8) << "r " << w.r;
    EXPECT_NEAR(c.load_angle, w.load_angle, 1e-11) << "r " << w.r;
    EXPECT_EQ(c.fillet, 0.0);
  }
}

// A mirrored back flank (PlanetaryMeshes::sun_back_mirror, ring_back_mirror): the back
// contact of mesh i takes k(psi - theta_i), theta_i = theta - 2 pi gamma_i its drive flank's
// own phase, where the drive contact takes k(theta_i) (the first H harmonics of the wave,
// evaluated here from the series directly).
TEST(PlanetaryStiffness, MirroredBackFlankIsTheDriveWaveReflected) {
  const int N = 3, H = 6;
  PlanetarySet s = lin_parker_1999_set(N);
  PlanetaryMeshes m;
  m.sun = {2e9, 1.55, 1.4};
  m.ring = {2.5e9, 1.7, 1.3};
  m.phases = mesh_phases(PlanetaryTeeth{27, 33, 93, 0.0032, 1.0}, s.planet_angles, 0.3);
  m.backlash.assign(2 * N, 1e-4);
  m.sun_back_mirror = 2.0;
  m.ring_back_mirror = 4.5;
  const std::vector<UnilateralContact> c = planetary_mesh_contacts(s, m, H);
  const std::vector<int> back = back_flank_contacts(m, N);
  for (int i = 0; i < 2 * N; ++i) {
    const bool ring = i >= N;
    const double gamma = (ring ? m.phases.ring : m.phases.sun)[std::size_t(i % N)];
    const double psi = ring ? m.ring_back_mirror : m.sun_back_mirror;
    const Eigen::VectorXd series = m.harmonics(ring, H);
    for (double theta : {0.0, 0.7, 2.9, 5.1}) {
      const double own = theta - 2.0 * M_PI * gamma;
      EXPECT_NEAR(c[std::size_t(i)].stiffness_profile(theta), trig_series(series, own), 1e-12);
      EXPECT_NEAR(c[std::size_t(back[std::size_t(i)])].stiffness_profile(theta), trig_series(series, psi - own), 1e-12)
          << "mesh " << i << " theta " << theta;
    }
  }
}

// The ring-planet mesh's k(theta) of the example (programs/gearhb_planetary/examples/
// gtf_star_five_planets_teeth.json) at phase 0 rebuilt here: the pairs on the internal line of
// action constructed in the plane (as InternalContactRatioIsTheConstructedPath, the entry A on
// the ring's tip circle refined by bisection), one at A and one a base pitch on, each the
// planet's tooth (pe_tooth_compliance, its fillet foundation at the planet's rim radius 35
// mm), the ring's (pe_internal_tooth_compliance) and the linear Hertz term in series, the two
// pairs in parallel, with the radii measured from the two centres.
TEST(PlanetaryStiffness, RingPlanetStiffnessIsThePairsOnTheConstructedPath) {
  const nlohmann::json pair = {
      {"basic_rack", {{"dedendum", 1.25}, {"root_radius", 0.38}}},
      {"gears", {{{"x", 0}, {"b", 0.12}, {"E", 206e9}, {"nu", 0.3}, {"rim_radius", 0.03}},
                 {{"x", 0}, {"b", 0.12}, {"E", 206e9}, {"nu", 0.3}, {"rim_radius", 0.035}}}},
      {"model", {{"method", "potential_energy"}, {"phases", 64}, {"hertz", "none"}, {"tooth_force", "base_radius"}}}};
  const PlanetaryToothStiffness k =
      planetary_tooth_stiffness(pair, "test", "test", kGtfTeeth, kAlpha, 5, Body::sun, 19100.0, RingPlanetModel::potential_energy);
  // the construction
  const PlanetaryTeeth& t = kGtfTeeth;
  const double m = t.module, a = 0.5 * (t.ring - t.planet) * m;
  const double rbp = 0.5 * t.planet * m * std::cos(kAlpha), rbr = 0.5 * t.ring * m * std::cos(kAlpha);
  const double rap = 0.5 * t.planet * m + m, rar = 0.5 * t.ring * m - m, pb = M_PI * m * std::cos(kAlpha);
  const double nx = (rbp - rbr) / a, ny = std::sqrt(1.0 - nx * nx);
  auto point = [&](double s) { return std::pair<double, double>{rbp * nx - s * ny, rbp * ny + s * nx}; };
  auto outside_ring_tip = [&](double s) { const auto [x, y] = point(s); return std::hypot(x - a, y) - rar; };
  double lo = 0.0, hi = std::sqrt(rap * rap - rbp * rbp);   // inside the ring's tip circle at s = 0
  ASSERT_LT(outside_ring_tip(lo), 0.0);
  ASSERT_GT(outside_ring_tip(hi), 0.0);
  for (int i = 0; i < 200; ++i) (outside_ring_tip(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  PeGear planet;
  planet.teeth = t.planet;
  planet.module = m;
  planet.pressure_angle = kAlpha;
  planet.face_width = 0.12;
  planet.youngs_modulus = 206e9;
  planet.bore_radius = 0.035;
  PeGear ring = planet;
  ring.teeth = t.ring;
  ring.bore_radius = 0.0;
  double sum = 0.0;
  for (double s = hi; s <= std::sqrt(rap * rap - rbp * rbp); s += pb) {
    const auto [x, y] = point(s);
    sum += 1.0 / (pe_tooth_compliance(planet, std::hypot(x, y)).total() +
                  pe_internal_tooth_compliance(ring, std::hypot(x - a, y)).total() + pe_hertz_compliance(planet, ring));
  }
  ASSERT_EQ(k.ring_pe.samples.size(), 64u);
  EXPECT_NEAR(k.ring_pe.samples[0] / sum, 1.0, 1e-9);
}
