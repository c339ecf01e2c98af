// Unit tests of lib/contact: crossings, contact intervals and moments, refined
// extremes and the contact state, each against a closed form.
#include <algorithm>
#include <cmath>
#include <vector>

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

// --- every contact interval, wherever the samples fall -------------------------

namespace {
// u = cos(m (theta - phi)) - cos(m delta), in the H = m basis: m intervals of
// width 2 delta centred on phi + 2 pi j / m (closed form).
Eigen::VectorXd cosine_comb(int m, double phi, double delta, int H) {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(2 * H + 1);
  c[0] = -std::cos(m * delta);
  c[2 * m - 1] = std::cos(m * phi);
  c[2 * m] = std::sin(m * phi);
  return c;
}
// Sorted interval centres and widths, centres reduced to [0, 2 pi).
std::vector<std::pair<double, double>> centres_widths(const std::vector<std::pair<double, double>>& I) {
  std::vector<std::pair<double, double>> out;
  for (const auto& [a, b] : I) out.emplace_back(std::fmod(0.5 * (a + b) + 4 * M_PI, 2 * M_PI), b - a);
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST(Contact, IntervalNarrowerThanTheSampleSpacingIsFound) {
  // 32 samples (spacing 0.196 rad); contact of half-width 0.01 rad centred between
  // samples 3 and 4: no sample is in contact, the interval must still be found.
  const int N = 32;
  const double dt = 2 * M_PI / N, phi = 3.5 * dt, delta = 0.01;
  const Eigen::VectorXd c = cosine_comb(1, phi, delta, 1);
  Aft aft(1, N);
  const Eigen::VectorXd us = aft.to_time(c);
  ASSERT_LT(us.maxCoeff(), 0.0);   // every sample is out of contact
  const auto I = contact_intervals(c, us);
  ASSERT_EQ(I.size(), 1u);
  EXPECT_NEAR(I[0].first, phi - delta, 1e-13);
  EXPECT_NEAR(I[0].second, phi + delta, 1e-13);
  // and the moments carry it: mean of the indicator = 2 delta / 2 pi
  double Sc[1], Ss[1];
  indicator_moments(I, 0, Sc, Ss);
  EXPECT_NEAR(Sc[0], delta / M_PI, 1e-14);
}

TEST(Contact, ResultDoesNotDependOnTheNumberOfSamples) {
  // H = 7, seven intervals of half-width 0.02 rad: any grid from 4 to 1024 samples
  // gives the same intervals (closed form) to round-off.
  const int m = 7, H = 7;
  const double phi = 0.123, delta = 0.02;
  const Eigen::VectorXd c = cosine_comb(m, phi, delta, H);
  for (int N : {4, 8, 30, 64, 128, 1024}) {
    Aft aft(H, std::max(N, 4 * H + 2));
    // seed with a coarser grid of N samples (the function accepts any grid)
    Eigen::VectorXd us(N);
    for (int j = 0; j < N; ++j) {
      double v = c[0];
      for (int k = 1; k <= H; ++k) v += c[2 * k - 1] * std::cos(k * 2 * M_PI * j / N) + c[2 * k] * std::sin(k * 2 * M_PI * j / N);
      us[j] = v;
    }
    const auto cw = centres_widths(contact_intervals(c, us));
    ASSERT_EQ(cw.size(), std::size_t(m)) << "N = " << N;
    for (int j = 0; j < m; ++j) {
      const double centre = std::fmod(phi + 2 * M_PI * j / m, 2 * M_PI);
      EXPECT_NEAR(cw[std::size_t(j)].first, centre, 1e-12) << "N = " << N << ", interval " << j;
      EXPECT_NEAR(cw[std::size_t(j)].second, 2 * delta, 1e-12) << "N = " << N;
    }
  }
}

TEST(Contact, ManyIntervalsPerPeriod) {
  // u = cos(20 theta) - cos(20 * 0.05): 20 intervals of width 0.1 rad on a grid of 82 samples.
  const int m = 20, H = 20;
  const double delta = 0.05;
  const Eigen::VectorXd c = cosine_comb(m, 0.0, delta, H);
  Aft aft(H);
  const auto I = contact_intervals(c, aft.to_time(c));
  ASSERT_EQ(I.size(), std::size_t(m));
  for (const auto& [a, b] : I) EXPECT_NEAR(b - a, 2 * delta, 1e-12);
  double Sc[1], Ss[1];
  indicator_moments(I, 0, Sc, Ss);
  EXPECT_NEAR(Sc[0], m * 2 * delta / (2 * M_PI), 1e-12);
}

TEST(Contact, TangentialGrazeHasNoMeasureAndNearGrazeHasItsClosedFormWidth) {
  // u = cos(theta - phi) - 1 touches zero at theta = phi only: no contact measure.
  // u = cos(theta - phi) - cos(delta) for delta = 1e-6: interval of width 2e-6.
  const int N = 16;
  const double phi = 0.5 * 2 * M_PI / N;   // between samples 0 and 1
  Aft aft(1, N);
  {
    const Eigen::VectorXd c = cosine_comb(1, phi, 0.0, 1);
    const auto I = contact_intervals(c, aft.to_time(c));
    double w = 0.0;
    for (const auto& [a, b] : I) w += b - a;
    EXPECT_LT(w, 1e-7);   // a touch, not an interval (round-off of cos at its crest: ~1e-8 rad)
  }
  {
    const double delta = 1e-6;
    const Eigen::VectorXd c = cosine_comb(1, phi, delta, 1);
    const auto I = contact_intervals(c, aft.to_time(c));
    ASSERT_EQ(I.size(), 1u);
    // u'(theta) ~ delta near the roots, so the root error is ~ eps / delta ~ 1e-10
    EXPECT_NEAR(I[0].second - I[0].first, 2 * delta, 1e-9);
    EXPECT_NEAR(0.5 * (I[0].first + I[0].second), phi, 1e-9);
  }
}

// Which contact sets can be closed at once (contacts_can_close_together): a stop on each
// side of one coordinate, x > 1 (drive, gap -1) and x < -1 (back, gap -1), never both
// (the Kahraman-Singh clearance); with preloads g1 = 0.5, g2 = -0.2 both close for
// -0.5 < x < -0.2; a normal of length 2 scales the pair test (2x > 1.5 and x < 0.5: no);
// a periodic gap counts with its largest value (gap -1 + amplitude 1.5 reaches 0.5).
TEST(Contact, SetsThatCanCloseTogether) {
  auto stop = [](double n, double g) {
    UnilateralContact c;
    c.normal = Eigen::VectorXd::Constant(1, n);
    c.kc = 1.0;
    c.gap = g;
    return c;
  };
  EXPECT_FALSE(contacts_can_close_together({stop(1, -1), stop(-1, -1)}, 3));
  EXPECT_TRUE(contacts_can_close_together({stop(1, -1), stop(-1, -1)}, 1));
  EXPECT_TRUE(contacts_can_close_together({stop(1, -1), stop(-1, -1)}, 2));
  EXPECT_TRUE(contacts_can_close_together({stop(1, 0.5), stop(-1, -0.2)}, 3));
  EXPECT_FALSE(contacts_can_close_together({stop(2, -1.5), stop(-1, 0.5)}, 3));   // x > 0.75 and x < 0.5
  EXPECT_TRUE(contacts_can_close_together({stop(2, -0.5), stop(-1, 0.5)}, 3));    // x > 0.25 and x < 0.5
  UnilateralContact wavy = stop(1, -1);
  wavy.gap_harmonics = Eigen::VectorXd::Zero(3);
  wavy.gap_harmonics[1] = 0.9;
  wavy.gap_harmonics[2] = 1.2;   // amplitude 1.5
  EXPECT_TRUE(contacts_can_close_together({wavy, stop(-1, 0.0)}, 3));           // x > -0.5 and x < 0
  // two DOFs, normals not opposite: the pair test cannot rule them out
  UnilateralContact a = stop(1, -1), b = stop(1, -1);
  a.normal = Eigen::Vector2d(1, 0);
  b.normal = Eigen::Vector2d(0, -1);
  EXPECT_TRUE(contacts_can_close_together({a, b}, 3));
}
