// Unit tests of the describing functions N_fm, N_fp (lib/describing_function),
// thesis §5 / Comparin & Singh (1989), computed by GSL quadrature.
// Known values (closed forms, derived by hand, independent of the quadrature):
//  - never in contact: f = k d is linear, N_fm = N_fp = k exactly;
//  - always in contact: f = (k + kc) d + kc g, N_fp = k + kc, N_fm = k + kc + kc g / dm;
//  - g = 0, dm = 0 (contact for half of every period), k = 0: f = kc dp max(cos phi, 0),
//    mean F0 = kc dp / pi, first harmonic F1 = kc dp / 2 (half-wave rectified cosine:
//    e.g. Abramowitz & Stegun-level Fourier series, a0/2 = 1/pi, a1 = 1/2);
//  - any intermittent case: the closed form of describing_function.hpp.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "gearhb/hb/describing_function.hpp"

using gearhb::describing_function;
using gearhb::describing_function_closed_form;
using gearhb::PiecewiseLinearForce;

TEST(DescribingFunction, NeverInContactIsTheLinearSpring) {
  const PiecewiseLinearForce f{1.0, 1.0, -20.0};
  const auto r = describing_function(f, 4.1, 2.5);   // g + dm + dp = -13.4 < 0
  EXPECT_EQ(r.contact_angle, 0.0);
  EXPECT_NEAR(r.N_fm, 1.0, 1e-13);
  EXPECT_NEAR(r.N_fp, 1.0, 1e-13);
}

TEST(DescribingFunction, AlwaysInContactIsTheClosedSpring) {
  const PiecewiseLinearForce f{1.0, 1.0, 6.0};
  const double dm = -0.95, dp = 1.2;                 // g + dm - dp = 3.85 > 0
  const auto r = describing_function(f, dm, dp);
  EXPECT_EQ(r.contact_angle, M_PI);
  EXPECT_NEAR(r.N_fp, 2.0, 1e-13);
  EXPECT_NEAR(r.N_fm, 2.0 + 6.0 / dm, 1e-12);
  EXPECT_NEAR(r.mean_force, 2.0 * dm + 6.0, 1e-12);
}

TEST(DescribingFunction, HalfPeriodContactHalfWaveRectifiedCosine) {
  const double kc = 3.0, dp = 0.7;
  const PiecewiseLinearForce f{0.0, kc, 0.0};
  const auto r = describing_function(f, 0.0, dp);
  EXPECT_NEAR(r.contact_angle, M_PI / 2, 1e-15);
  EXPECT_NEAR(r.mean_force, kc * dp / M_PI, 1e-14);
  EXPECT_NEAR(r.N_fp, kc / 2.0, 1e-14);
  EXPECT_TRUE(std::isnan(r.N_fm));                   // dm = 0: N_fm undefined
}

TEST(DescribingFunction, IntermittentMatchesClosedForm) {
  // A spread of contact angles, clearance and preload, including grazing ones.
  const double cases[][5] = {  // k, kc, g, dm, dp
      {1.0, 1.0, -1.0, 2.55, 1.9},   {1.0, 1.0, -15.0, 4.1, 12.0}, {1.0, 1.0, 6.0, -2.0, 4.5},
      {5.0, 2.0, -0.5, 0.1, 0.41},   {1.0, 1.0, -1.0, 2.55, 1.5500001}, {1.0, 10.0, 0.3, 0.0, 0.30001}};
  for (const auto& c : cases) {
    const PiecewiseLinearForce f{c[0], c[1], c[2]};
    const auto q = describing_function(f, c[3], c[4]);
    const auto e = describing_function_closed_form(f, c[3], c[4]);
    EXPECT_GT(q.contact_angle, 0.0);
    EXPECT_LT(q.contact_angle, M_PI);
    const double scale = (c[0] + c[1]) * (std::fabs(c[3]) + c[4]);
    EXPECT_NEAR(q.mean_force, e.mean_force, 1e-13 * scale) << "g = " << c[2] << " dm = " << c[3];
    EXPECT_NEAR(q.h1_force, e.h1_force, 1e-13 * scale) << "g = " << c[2] << " dm = " << c[3];
  }
}

TEST(DescribingFunction, ContinuousAtTheContactBoundaries) {
  // Grazing from outside and inside: the mean force is continuous in dp.
  const PiecewiseLinearForce f{1.0, 1.0, -3.0};
  const double dm = 1.0;   // s = g + dm = -2: contact starts at dp = 2
  const auto a = describing_function(f, dm, 2.0 - 1e-9), b = describing_function(f, dm, 2.0 + 1e-9);
  EXPECT_NEAR(a.mean_force, b.mean_force, 1e-12);
  EXPECT_NEAR(a.N_fp, b.N_fp, 1e-6);
}

TEST(DescribingFunction, NegativeAmplitudeRejected) {
  EXPECT_THROW(describing_function(PiecewiseLinearForce{1, 1, 0}, 1.0, -0.1), std::invalid_argument);
}
