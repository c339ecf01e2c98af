// Unit tests of the real Fourier basis / AFT (lib/fourier).
// Known values: a trigonometric polynomial of degree <= H is sampled exactly by
// N >= 2H+2 points, so transform and inverse are exact to round-off (discrete
// orthogonality of cos/sin on a uniform grid, e.g. Briggs & Henson, "The DFT",
// SIAM 1995, §2.2).
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"

using gearhb::Aft;

TEST(Fourier, DefaultSampleCount) {
  EXPECT_EQ(Aft::default_samples(1, 4.0), 12);   // 4 x 3
  EXPECT_EQ(Aft::default_samples(10, 4.0), 84);  // 4 x 21
  EXPECT_EQ(Aft::default_samples(5, 1.0), 22);   // floor at 4H+2
}

TEST(Fourier, KnownSignalToCoefficientsExact) {
  // x = 0.3 + 2 cos(t) - 0.5 sin(3t): coefficients [0.3, 2, 0, 0, 0, 0, -0.5]
  Aft aft(3, 16);
  Eigen::VectorXd x(16);
  for (int j = 0; j < 16; ++j) {
    const double t = aft.theta(j);
    x[j] = 0.3 + 2 * std::cos(t) - 0.5 * std::sin(3 * t);
  }
  const Eigen::VectorXd c = aft.to_frequency(x);
  const double expect[7] = {0.3, 2, 0, 0, 0, 0, -0.5};
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(c[i], expect[i], 1e-14) << "coefficient " << i;
}

TEST(Fourier, RoundTripExact) {
  Aft aft(5);
  Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(aft.size(), -1.0, 2.0);
  const Eigen::VectorXd back = aft.to_frequency(aft.to_time(c));
  EXPECT_LT((back - c).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Fourier, ToTimeMatchesDirectSum) {
  Aft aft(4, 20);
  Eigen::VectorXd c(9);
  c << 1.0, 0.5, -0.25, 0.0, 0.75, 0.1, 0.0, -0.3, 0.2;
  const Eigen::VectorXd x = aft.to_time(c);
  for (int j = 0; j < 20; ++j) {
    double v = c[0];
    for (int k = 1; k <= 4; ++k)
      v += c[2 * k - 1] * std::cos(k * aft.theta(j)) + c[2 * k] * std::sin(k * aft.theta(j));
    EXPECT_NEAR(x[j], v, 1e-14);
  }
}

TEST(Fourier, ProductMatrixEqualsBruteForceGalerkin) {
  // G must equal  W Gamma^T diag(s) Gamma  built from explicit cos/sin samples.
  const int H = 4, N = 24;
  Aft aft(H, N);
  Eigen::VectorXd s(N);
  for (int j = 0; j < N; ++j) s[j] = std::max(0.0, 0.2 + std::cos(aft.theta(j) - 0.3));  // clipped
  Eigen::MatrixXd G(2 * H + 1, 2 * H + 1);
  aft.product_matrix(s.data(), G);
  Eigen::MatrixXd Gam(N, 2 * H + 1);
  for (int j = 0; j < N; ++j) {
    Gam(j, 0) = 1.0;
    for (int k = 1; k <= H; ++k) {
      Gam(j, 2 * k - 1) = std::cos(k * aft.theta(j));
      Gam(j, 2 * k) = std::sin(k * aft.theta(j));
    }
  }
  Eigen::MatrixXd ref = Gam.transpose() * s.asDiagonal() * Gam / N;
  ref.bottomRows(2 * H) *= 2.0;
  EXPECT_LT((G - ref).cwiseAbs().maxCoeff(), 1e-13);
}

// The symmetry CondensedLinearization (harmonic_balance.cpp, add_row) reads a product matrix's
// rows from its columns by: G(a, b) = G(b, a) for a, b >= 1 and G(a, 0) = 2 G(0, a), bit for bit
// (the same sums, in the same order, of the same moments; doubling exact in binary).
TEST(Fourier, ProductMatrixRowsFromColumns) {
  const int H = 7, N = 64;
  gearhb::Aft aft(H, N);
  std::vector<double> s(N);
  for (int j = 0; j < N; ++j) s[j] = std::max(0.0, 0.3 + std::sin(2.0 * aft.theta(j) + 0.7)) * (1.0 + 0.1 * j);
  Eigen::MatrixXd G(2 * H + 1, 2 * H + 1);
  aft.product_matrix(s.data(), G);
  for (int a = 0; a <= 2 * H; ++a)
    for (int b = 0; b <= 2 * H; ++b) {
      const double from_column = a == 0 ? (b == 0 ? G(0, 0) : 0.5 * G(b, 0)) : (b == 0 ? G(a, 0) : G(b, a));
      EXPECT_EQ(G(a, b), from_column) << "a = " << a << ", b = " << b;
    }
}

TEST(Fourier, HarmonicAmplitudes) {
  std::vector<double> x(32);
  for (int j = 0; j < 32; ++j) {
    const double t = 2 * M_PI * j / 32;
    x[j] = -1.0 + 3 * std::cos(2 * t) + 4 * std::sin(2 * t);   // |2nd| = 5
  }
  const auto a = gearhb::harmonic_amplitudes(x, 3);
  EXPECT_NEAR(a[0], 1.0, 1e-14);
  EXPECT_NEAR(a[1], 0.0, 1e-14);
  EXPECT_NEAR(a[2], 5.0, 1e-14);
  EXPECT_NEAR(a[3], 0.0, 1e-14);
}

TEST(Fourier, RejectsTooFewSamples) {
  EXPECT_THROW(Aft(5, 10), std::invalid_argument);
}
