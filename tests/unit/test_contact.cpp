// Unit tests of lib/contact: crossings, contact intervals and moments, refined
// extremes and the contact state, each against a closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/hb/contact.hpp"
#include "gearhb/core/fourier.hpp"

using namespace gearhb;

namespace {
// u(theta) = m + a cos(theta - phi) + 0.3 a cos(2 (theta - phi)), coefficients for H = 2.
Eigen::VectorXd two_harmonic(double m, double a, double phi) {
  Eigen::VectorXd c(5);
  c << m, a * std::cos(phi), a * std::sin(phi), 0.3 * a * std::cos(2 * phi), 0.3 * a * std::sin(2 * phi);
  return c;
}
}  // namespace

TEST(Contact, IntervalsOfAShiftedCosineAreExact) {
  // u = -0.5 + cos(theta - phi): contact where |theta - phi| < acos(0.5) = pi/3.
  const double phi = 0.731;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(3);
  c << -0.5, std::cos(phi), std::sin(phi);
  Aft aft(1, 32);
  const auto I = contact_intervals(c, aft.to_time(c));
  ASSERT_EQ(I.size(), 1u);
  // (intervals may be reported shifted by 2 pi: they start at the first entry after a gap)
  const double shift = I[0].first > phi ? 2 * M_PI : 0.0;
  EXPECT_NEAR(I[0].first, phi - M_PI / 3 + shift, 1e-13);
  EXPECT_NEAR(I[0].second, phi + M_PI / 3 + shift, 1e-13);
  // Moments (1/2pi) int_I cos(m theta), sin(m theta) over |theta - phi| < pi/3, closed form.
  double Sc[2], Ss[2];
  indicator_moments(I, 1, Sc, Ss);
  EXPECT_NEAR(Sc[0], 1.0 / 3.0, 1e-13);                                   // 2pi/3 out of 2pi
  EXPECT_NEAR(Sc[1], std::sin(M_PI / 3) / M_PI * std::cos(phi), 1e-13);
  EXPECT_NEAR(Ss[1], std::sin(M_PI / 3) / M_PI * std::sin(phi), 1e-13);
}

TEST(Contact, ExtremesBetweenSamplesAreRefined) {
  // With 16 samples and the crest half-way between two of them, the sampled
  // maximum misses the crest by a (1 - cos(pi/16)) ~ 2 %; the refined one must not.
  // Closed form of the extremes of m + a cos(s) + 0.3 a cos(2 s): s = 0 gives
  // m + 1.3 a (max); the minimum is at cos(s) = -1/1.2: m - a/1.2 + 0.3 a (2/1.44 - 1).
  const double m = 0.1, a = 1.0, phi = M_PI / 16;   // crest between samples 0 and 1
  const Eigen::VectorXd c = two_harmonic(m, a, phi);
  Aft aft(2, 16);
  const Eigen::VectorXd us = aft.to_time(c);
  EXPECT_LT(us.maxCoeff(), m + 1.3 * a - 1e-2);     // the sampled crest is visibly low
  const auto [lo, hi] = trig_extremes(c, us);
  EXPECT_NEAR(hi, m + 1.3 * a, 1e-12);
  EXPECT_NEAR(lo, m - a / 1.2 + 0.3 * a * (2.0 / 1.44 - 1.0), 1e-12);
}

TEST(Contact, StateOfAGrazingCrestIsDecidedByTheRefinedCrest) {
  // Crest 1e-4 above zero, between samples: every sample is negative, yet the
  // body touches; 1e-4 below zero: open.
  Aft aft(2, 16);
  for (double eps : {1e-4, -1e-4}) {
    const Eigen::VectorXd c = two_harmonic(eps - 1.3, 1.0, M_PI / 16);
    const Eigen::VectorXd us = aft.to_time(c);
    EXPECT_LT(us.maxCoeff(), 0.0);
    EXPECT_EQ(contact_state(c, us), eps > 0 ? ContactState::intermittent : ContactState::open);
  }
  const Eigen::VectorXd full = two_harmonic(2.0, 1.0, 0.2);
  EXPECT_EQ(contact_state(full, aft.to_time(full)), ContactState::full);
}
