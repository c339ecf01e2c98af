// Helical pairs by slices (lib/gearhb/gears/pair/pair_helical, issue 35) against independent checks:
//  * beta = 0: the spur pair's STE bit for bit (the program must not change spur pairs);
//  * identical slices (beta = 0, N = 20): the spur STE again, up to round-off: the Hertz of a
//    slice is that of the whole line at the same line load (a slice-width Palmgren would move
//    the STE by percents);
//  * theory: with a stiffness per unit contact length that is constant, the total contact
//    length - and so the mesh stiffness - is constant when eps_beta is an integer (to round-off,
//    at any slice count: each slice's contact line is cut exactly at A and E), not otherwise;
//  * ISO 21771's overlap ratio eps_beta = b sin(beta) / (pi m_n) written out (the code uses
//    b tan(beta_b) / p_bt of the transverse section);
//  * lead modifications: crowning and end relief at hand-computed points.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "gearhb/gears/tooth/hertz.hpp"
#include "gearhb/gears/dynamics/mesh_dynamics.hpp"
#include "gearhb/gears/pair/pair_helical.hpp"

using namespace gearhb;

namespace {

constexpr double kHelixDeg = M_PI / 180.0;

// The thesis gear pair (z 50/50, m 3 mm, b 20 mm) in the consistent beam reading; normal terms.
PairSteModel helical_thesis_pair(double helix_angle, HelicalPair& h) {
  GearGeometry g;   // defaults: m 3 mm, z 50, 20 deg, ha 3 mm, hf 3.75 mm, b 20 mm
  h.helix_angle = helix_angle;
  h.normal_module = g.module;
  h.normal_pressure_angle_deg = g.pressure_angle_deg;
  PairSteModel m;
  m.gear1 = m.gear2 = transverse_section(g, helix_angle);
  m.hertz = HertzCount::per_contact;
  m.pair_hertz = TwoPairHertz::consistent;
  m.pair_stiffness = PairStiffness::cantilevers;
  m.tooth_force = ToothForce::over_base_radius;
  m.relief1 = tip_relief(m.gear1, 10e-6, ReliefStart::length, 4e-3, ReliefShape::linear);
  return m;
}

double helical_ptp(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

}  // namespace

TEST(PairHelical, BetaZeroIsTheSpurPairBitForBit) {
  HelicalPair h;
  h.slices = 20;
  const PairSteModel m = helical_thesis_pair(0.0, h);
  ASSERT_FALSE(h.sliced());
  for (bool reliefs : {true, false}) {
    const auto spur = phase_loaded_pair(m, 64)->ste(200.0, reliefs);
    const auto sliced = sliced_loaded_pair(m, h, 64)->ste(200.0, reliefs);
    ASSERT_EQ(spur.size(), sliced.size());
    for (std::size_t k = 0; k < spur.size(); ++k) {
      EXPECT_EQ(spur[k].ste, sliced[k].ste);
      EXPECT_EQ(spur[k].loaded, sliced[k].loaded);
      ASSERT_EQ(spur[k].mesh.pairs.size(), sliced[k].mesh.pairs.size());
      for (std::size_t i = 0; i < spur[k].mesh.pairs.size(); ++i)
        EXPECT_EQ(spur[k].mesh.pairs[i].force, sliced[k].mesh.pairs[i].force);
    }
  }
  // The same for the potential-energy seam (a given pair stiffness).
  const PairStiffnessFn k = [](double r1, double r2, bool) { return 1e8 * (1.0 + 10.0 * (r1 - r2)); };
  PairSteModel linear = m;
  linear.hertz = HertzCount::none;
  const auto a = phase_loaded_pair(linear, 64, k)->ste(200.0), b = sliced_loaded_pair(linear, h, 64, k)->ste(200.0);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].ste, b[i].ste);
}

TEST(PairHelical, IdenticalSlicesCarryTheWholeLinesHertz) {
  HelicalPair h;
  h.slices = 20;
  const PairSteModel m = helical_thesis_pair(0.0, h);
  h.lead1.crowning = 1e-30;   // sliced, the slices identical to 1e-30 m
  ASSERT_TRUE(h.sliced());
  const auto spur = phase_loaded_pair(m, 64)->ste(200.0);
  const auto sliced = sliced_loaded_pair(m, h, 64)->ste(200.0);
  for (std::size_t k = 0; k < spur.size(); ++k) {
    EXPECT_NEAR(sliced[k].ste, spur[k].ste, 1e-12 * spur[k].ste);
    EXPECT_EQ(int(sliced[k].mesh.pairs.size()), 20 * int(spur[k].mesh.pairs.size()));
  }
  // Hertz of the slice width instead (each slice alone with delta(F / N, b / N)) would differ:
  const double F = m.force(200.0), b = m.contact_length();
  EXPECT_GT(std::fabs(palmgren_line_contact_approach(F / 20, b / 20) - palmgren_line_contact_approach(F, b)),
            0.1 * palmgren_line_contact_approach(F, b));
}

TEST(PairHelical, OverlapRatioIsIso21771s) {
  for (double beta : {5.0, 15.8, 30.0, 45.0}) {
    HelicalPair h;
    const PairSteModel m = helical_thesis_pair(beta * kHelixDeg, h);
    EXPECT_NEAR(overlap_ratio(m, h), 0.02 * std::sin(beta * kHelixDeg) / (M_PI * 3e-3), 1e-12);
    // Transverse section (ISO 21771): m_t = m_n / cos(beta), tan(alpha_t) = tan(alpha_n) / cos(beta).
    EXPECT_NEAR(m.gear1.module, 3e-3 / std::cos(beta * kHelixDeg), 1e-15);
    EXPECT_NEAR(std::tan(m.gear1.pressure_angle_rad()), std::tan(20 * kHelixDeg) / std::cos(beta * kHelixDeg), 1e-14);
  }
}

namespace {

// Constant stiffness k0 per contact (k0 / N per slice contact), no relief, no Hertz: the mesh
// stiffness F / STE is k0 / N times the number of slice contacts on the path. Face width b:
// the helix angle is the one of eps_beta = b sin(beta) / (pi m_n).
struct ConstantK {
  std::vector<double> k;
  double eps_alpha = 0.0;   // the transverse section's
};
ConstantK constant_k_stiffness(double eps_beta, int slices, double k0, double b) {
  HelicalPair h;
  h.slices = slices;
  const double beta = std::asin(eps_beta * M_PI * 3e-3 / b);
  PairSteModel m = helical_thesis_pair(beta, h);
  m.gear1.face_width = m.gear2.face_width = b;
  m.relief1.amount = 0.0;
  m.hertz = HertzCount::none;
  const auto c = sliced_loaded_pair(m, h, 128, [k0](double, double, bool) { return k0; })->ste(200.0);
  ConstantK out;
  for (const auto& p : c) out.k.push_back(m.force(200.0) / p.ste);
  out.eps_alpha = m.path().contact_ratio;
  return out;
}

}  // namespace

TEST(PairHelical, IntegerOverlapRatioGivesAConstantMeshStiffness) {
  const double k0 = 4e8;
  // eps_beta = q whole: the contact lines of one tooth pair span q base pitches along the path,
  // so the length of them on the path is q AE whatever the phase; the slices cut each contact
  // line exactly at A and E (pair_helical.hpp), so k = k0 eps_alpha at every phase and any N.
  for (double eps_beta : {1.0, 2.0})
    for (int N : {7, 20, 80}) {
      const ConstantK c = constant_k_stiffness(eps_beta, N, k0, eps_beta * 0.02);
      for (double k : c.k) EXPECT_NEAR(k, k0 * c.eps_alpha, 1e-9 * k0) << "eps_beta " << eps_beta << ", N " << N;
    }
  // eps_beta = 1/2 and 3/2: the length on the path changes over the cycle.
  for (double eps_beta : {0.5, 1.5}) EXPECT_GT(helical_ptp(constant_k_stiffness(eps_beta, 20, k0, 0.02 * eps_beta).k), 0.1 * k0);
  // and spur (eps_beta = 0): one pair more or less, k0.
  EXPECT_NEAR(helical_ptp(constant_k_stiffness(0.0, 1, k0, 0.02).k), k0, 1e-6 * k0);
}

TEST(PairHelical, LeadModificationShapes) {
  LeadModification l;
  l.crowning = 10e-6;
  const double b = 0.1;
  EXPECT_NEAR(lead_modification_at(l, 0.0, b), 10e-6, 1e-18);
  EXPECT_NEAR(lead_modification_at(l, 0.05, b), 0.0, 1e-18);
  EXPECT_NEAR(lead_modification_at(l, 0.075, b), 2.5e-6, 1e-18);   // (2 * 0.75 - 1)^2 = 1/4
  LeadModification e;
  e.end_relief = 20e-6;
  e.end_relief_length = 0.01;
  EXPECT_NEAR(lead_modification_at(e, 0.0, b), 20e-6, 1e-18);
  EXPECT_NEAR(lead_modification_at(e, 0.095, b), 10e-6, 1e-18);    // 5 mm from the end: half
  EXPECT_EQ(lead_modification_at(e, 0.02, b), 0.0);
  EXPECT_EQ(lead_modification_at(e, 0.08, b), 0.0);
}

TEST(PairHelical, RefusesWhatItCannotSlice) {
  HelicalPair h;
  PairSteModel m = helical_thesis_pair(15 * kHelixDeg, h);
  h.slices = 0;
  EXPECT_THROW(sliced_loaded_pair(m, h, 64), std::invalid_argument);
  h.slices = 20;
  m.pair_hertz = TwoPairHertz::equal_split;
  EXPECT_THROW(sliced_loaded_pair(m, h, 64), std::invalid_argument);
}

// ISO 6336-1's K_v of the helical pair through the program's path (pair_iso6336_kv with the
// helix: normal module and angle, eps_gamma = eps_alpha + eps_beta, c' with cos(beta)) against
// ISO/TR 6336-30 Example 01's published K_v = 1.003 at n1 = 360 rpm: the example's tip relief
// C_a = 70 um and its reduced mass (solid discs, ISO 6336-1 eq. (30)), here as the inertia of
// the pinion on a rigid wheel (m_red = I1 / (rb1^2 b) then).
TEST(PairHelical, IsoTr6336_30Example01DynamicFactor) {
  GearGeometry g1, g2;
  for (GearGeometry* g : {&g1, &g2}) {
    g->module = 8e-3;
    g->pressure_angle_deg = 20.0;
    g->addendum = 8e-3;
    g->dedendum = 1.4 * 8e-3;
    g->face_width = 0.1;
  }
  g1.teeth = 17, g2.teeth = 103, g1.profile_shift = 0.145;
  HelicalPair h;
  h.helix_angle = 15.8 * kHelixDeg;
  h.normal_module = 8e-3;
  h.shift1 = 0.145;
  PairSteModel m;
  m.gear1 = transverse_section(g1, h.helix_angle);
  m.gear2 = transverse_section(g2, h.helix_angle);
  m.centre_distance = 0.5;
  m.relief1 = tip_relief(m.gear1, 70e-6, ReliefStart::length, 5e-3, ReliefShape::linear);
  const double d1 = 2e3 * m.gear1.pitch_radius(), d_m1 = 0.5 * (159.66 + d1 - 2.0 * 8.0 * (1.4 - 0.145));
  const double m_red = iso6336_reduced_mass_solid(d_m1, 2e3 * m.gear1.base_radius(), 103.0 / 17.0, 7.83e-6, 7.83e-6);
  const double I1 = m_red * 100.0 * std::pow(m.gear1.base_radius(), 2);
  const PairIsoKv k = pair_iso6336_kv(m, 1.4, 9000.0, I1, 1e12, 5, h);
  EXPECT_NEAR(k.input.eps_gamma, 1.549342 + 1.083369, 2e-6);   // eps_alpha of the unrounded tips + eps_beta
  EXPECT_NEAR(k.input.c_prime, 12.37047, 1e-5);                // ISO/TR 6336-30 Ex. 01
  EXPECT_NEAR(iso6336_dynamic_factor(k.input, 360.0).K_v, 1.003, 0.0005);   // ISO/TR 6336-30 Ex. 01 prints 1.003
  // Without the helix (the same section read as spur: no cos(beta), eps_gamma = eps_alpha) c' moves.
  EXPECT_GT(std::fabs(pair_iso6336_kv(m, 1.4, 9000.0, I1, 1e12, 5).input.c_prime - 12.37047), 0.1);
}

// Double helical: two mirrored halves are two single helical pairs of half the width side by
// side, each carrying half the load: the STE of the double pair of contact width 2 b_h at T
// equals the single pair's of width b_h at T / 2 (with N and N / 2 slices; Hertz of each half
// its own line), with the halves' crowning too; the axial forces cancel.
TEST(PairHelical, DoubleHelicalIsTwoHalvesAtHalfTheLoad) {
  HelicalPair single, twin;
  PairSteModel half = helical_thesis_pair(25.0 * kHelixDeg, single);
  PairSteModel both = helical_thesis_pair(25.0 * kHelixDeg, twin);
  both.gear1.face_width = both.gear2.face_width = 2.0 * half.gear1.face_width;
  twin.double_helical = true;
  single.slices = 10;
  twin.slices = 20;
  single.lead1.crowning = twin.lead1.crowning = 3e-6;
  const auto a = sliced_loaded_pair(half, single, 64)->ste(100.0);
  const auto b = sliced_loaded_pair(both, twin, 64)->ste(200.0);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(b[k].ste, a[k].ste, 1e-10 * a[k].ste);
  EXPECT_NEAR(overlap_ratio(both, twin), overlap_ratio(half, single), 1e-15);
  EXPECT_EQ(axial_force(both, twin, 200.0), 0.0);
  EXPECT_GT(axial_force(half, single, 100.0), 0.0);
  twin.slices = 21;
  EXPECT_THROW(sliced_loaded_pair(both, twin, 64), std::invalid_argument);
}
