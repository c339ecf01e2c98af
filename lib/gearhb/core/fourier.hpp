#pragma once
// Real Fourier basis and the alternating frequency/time (AFT) transform
// (thesis §2.3), on FFTW.
//
// A periodic signal of phase theta = omega t is represented by 2H+1 real
// coefficients, static term first:
//
//     x(theta) = a0 + sum_{k=1..H} ( a_k cos(k theta) + b_k sin(k theta) ),
//     coefficient vector [a0, a1, b1, a2, b2, ..., aH, bH].
//
// Time samples are taken at theta_j = 2 pi j / N, j = 0..N-1. The FFTW plans
// are made once in the constructor and reused for every transform.
//
// Product matrix: for a sampled function s(theta) (e.g. the contact stiffness
// dF/dv sampled in time), product_matrix(s) returns the (2H+1)x(2H+1) matrix G
// with  coeffs(s * x) = G coeffs(x),  the discrete Galerkin projection computed
// from one FFT of s and the product-to-sum identities
//   cos k cos l = [cos(k-l) + cos(k+l)]/2 , sin k sin l = [cos(k-l) - cos(k+l)]/2,
//   sin k cos l = [sin(k+l) + sin(k-l)]/2.
// It is the exact derivative of the AFT residual, and needs N >= 4H so that
// harmonics up to 2H of s are resolved.
//
// Not thread-safe: an Aft owns its FFT work buffers. Use one per thread.
#include <memory>
#include <vector>

#include <Eigen/Dense>

namespace gearhb {

class Aft {
 public:
  // H harmonics, N time samples. N = 0 picks default_samples(H, oversampling).
  explicit Aft(int H, int N = 0, double oversampling = 4.0);
  ~Aft();
  Aft(const Aft&) = delete;
  Aft& operator=(const Aft&) = delete;
  Aft(Aft&&) noexcept;
  Aft& operator=(Aft&&) noexcept;

  // Samples per period: oversampling x (2H+1), rounded up to an even number,
  // and at least 4H+2 (what the exact product matrix needs).
  static int default_samples(int H, double oversampling = 4.0);

  int harmonics() const { return H_; }
  int samples() const { return N_; }
  int size() const { return 2 * H_ + 1; }   // number of real coefficients
  double theta(int j) const;                // 2 pi j / N

  // coeffs (2H+1) -> samples (N), and samples (N) -> coeffs (2H+1, truncated at H).
  void to_time(const double* coeffs, double* samples) const;
  void to_frequency(const double* samples, double* coeffs) const;
  Eigen::VectorXd to_time(const Eigen::VectorXd& coeffs) const;
  Eigen::VectorXd to_frequency(const Eigen::VectorXd& samples) const;

  // G with coeffs(s*x) = G coeffs(x) (see above). `G` must be (2H+1)x(2H+1).
  void product_matrix(const double* s_samples, Eigen::Ref<Eigen::MatrixXd> G) const;
  // The same matrix from the mean values Sc[m] = <s cos(m theta)>, Ss[m] = <s sin(m theta)>,
  // m = 0..2H, however they were obtained (sampled sums or exact integrals).
  void product_matrix_from_moments(const double* Sc, const double* Ss,
                                   Eigen::Ref<Eigen::MatrixXd> G) const;

 private:
  struct Plans;
  int H_ = 0, N_ = 0;
  std::unique_ptr<Plans> p_;
};

// Value at theta of the series with coefficients c = [a0, a1, b1, ..., aH, bH]
// (size 2H+1): one sincos, then cos(k theta), sin(k theta) by the angle-addition
// recurrence (rounding error grows like k eps, 1e-13 at k = 340).
double trig_series(const double* c, int H, double theta);
inline double trig_series(const Eigen::VectorXd& c, double theta) {
  return trig_series(c.data(), int(c.size() - 1) / 2, theta);
}

// Coefficients of the reflected series f(psi - theta) from those of f(theta):
// a_k' = a_k cos(k psi) + b_k sin(k psi),  b_k' = a_k sin(k psi) - b_k cos(k psi).
Eigen::VectorXd reflected_series(const Eigen::VectorXd& c, double psi);

// Amplitude sqrt(a_k^2 + b_k^2) of harmonics k = 0..H of a uniformly sampled
// period (k = 0 gives |mean|). Convenience for spectra of measured signals.
std::vector<double> harmonic_amplitudes(const std::vector<double>& period_samples, int H);

// Real Fourier coefficients [a0, a1, b1, ..., aH, bH] of one uniformly sampled
// period, e(phase) = a0 + sum a_k cos(2 pi k phase) + b_k sin(2 pi k phase); the
// harmonics above what the samples carry (N < 2H + 2) are zero.
Eigen::VectorXd periodic_fourier(const std::vector<double>& samples, int H);

}  // namespace gearhb
