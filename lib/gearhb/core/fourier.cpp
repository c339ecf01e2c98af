#include "gearhb/core/fourier.hpp"

#include <cmath>
#include <complex>
#include <mutex>
#include <stdexcept>
#include <string>

#include <fftw3.h>

namespace gearhb {

namespace {
// FFTW's planner is not thread-safe (FFTW manual, "Thread safety": only fftw_execute
// is); creating and destroying plans is serialised here so that Aft objects, and the
// models that own them, can be built on several threads at once.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

struct Aft::Plans {
  int N = 0;
  double* real = nullptr;          // N samples
  fftw_complex* spec = nullptr;    // N/2+1 complex bins
  fftw_plan forward = nullptr;     // r2c: samples -> spectrum
  fftw_plan backward = nullptr;    // c2r: spectrum -> samples
  explicit Plans(int n) : N(n) {
    real = fftw_alloc_real(N);
    spec = fftw_alloc_complex(N / 2 + 1);
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward = fftw_plan_dft_r2c_1d(N, real, spec, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_1d(N, spec, real, FFTW_ESTIMATE);
  }
  ~Plans() {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spec);
  }
};

int Aft::default_samples(int H, double oversampling) {
  // In double: no integer overflow for any H; sizes beyond an int are refused.
  double n = std::max(std::ceil(oversampling * (2.0 * H + 1.0)), 4.0 * H + 2.0);
  if (!(n <= 1 << 30)) throw std::invalid_argument("Aft: H = " + std::to_string(H) + " needs too many samples");
  const int m = int(n);
  return m + (m % 2);
}

Aft::Aft(int H, int N, double oversampling) : H_(H), N_(N ? N : default_samples(H, oversampling)) {
  if (H < 0) throw std::invalid_argument("Aft: H must be >= 0");
  if (N_ < 2 * H_ + 2)
    throw std::invalid_argument("Aft: N = " + std::to_string(N_) + " samples cannot carry H = " +
                                std::to_string(H_) + " harmonics (need N >= 2H+2)");
  p_ = std::make_unique<Plans>(N_);
}

Aft::~Aft() = default;
Aft::Aft(Aft&&) noexcept = default;
Aft& Aft::operator=(Aft&&) noexcept = default;

double Aft::theta(int j) const { return 2.0 * M_PI * j / N_; }

void Aft::to_time(const double* c, double* x) const {
  fftw_complex* s = p_->spec;
  for (int k = 0; k <= N_ / 2; ++k) s[k][0] = s[k][1] = 0.0;
  s[0][0] = c[0];
  for (int k = 1; k <= H_; ++k) {
    s[k][0] = 0.5 * c[2 * k - 1];
    s[k][1] = -0.5 * c[2 * k];
  }
  fftw_execute(p_->backward);   // unnormalised: x_j = sum_k X_k e^{+i k theta_j}
  for (int j = 0; j < N_; ++j) x[j] = p_->real[j];
}

void Aft::to_frequency(const double* x, double* c) const {
  for (int j = 0; j < N_; ++j) p_->real[j] = x[j];
  fftw_execute(p_->forward);    // X_k = sum_j x_j e^{-i k theta_j}
  const fftw_complex* s = p_->spec;
  const double inv = 1.0 / N_;
  c[0] = s[0][0] * inv;
  for (int k = 1; k <= H_; ++k) {
    const double f = (2 * k == N_) ? inv : 2.0 * inv;   // Nyquist bin counted once
    c[2 * k - 1] = f * s[k][0];
    c[2 * k] = -f * s[k][1];
  }
}

Eigen::VectorXd Aft::to_time(const Eigen::VectorXd& coeffs) const {
  if (coeffs.size() != size()) throw std::invalid_argument("Aft::to_time: wrong coefficient count");
  Eigen::VectorXd x(N_);
  to_time(coeffs.data(), x.data());
  return x;
}

Eigen::VectorXd Aft::to_frequency(const Eigen::VectorXd& samples) const {
  if (samples.size() != N_) throw std::invalid_argument("Aft::to_frequency: wrong sample count");
  Eigen::VectorXd c(size());
  to_frequency(samples.data(), c.data());
  return c;
}

void Aft::product_matrix(const double* s_samples, Eigen::Ref<Eigen::MatrixXd> G) const {
  if (N_ < 4 * H_) throw std::logic_error("Aft::product_matrix needs N >= 4H");
  for (int j = 0; j < N_; ++j) p_->real[j] = s_samples[j];
  fftw_execute(p_->forward);
  const fftw_complex* S = p_->spec;
  const double inv = 1.0 / N_;
  // Sc(m) = (1/N) sum_j s_j cos(m theta_j), Ss(m) = (1/N) sum_j s_j sin(m theta_j), m = 0..2H.
  auto bin = [&](int m, double& re, double& im) {
    m %= N_;
    if (m < 0) m += N_;
    if (m <= N_ / 2) { re = S[m][0]; im = S[m][1]; }
    else { re = S[N_ - m][0]; im = -S[N_ - m][1]; }
  };
  std::vector<double> sc(2 * H_ + 1), ss(2 * H_ + 1);
  for (int m = 0; m <= 2 * H_; ++m) {
    double re, im;
    bin(m, re, im);
    sc[m] = re * inv;
    ss[m] = -im * inv;
  }
  product_matrix_from_moments(sc.data(), ss.data(), G);
}

void Aft::product_matrix_from_moments(const double* sc, const double* ss,
                                      Eigen::Ref<Eigen::MatrixXd> G) const {
  // Sc is even and Ss odd in m.
  auto Sc = [&](int m) { return sc[m < 0 ? -m : m]; };
  auto Ss = [&](int m) { return m < 0 ? -ss[-m] : ss[m]; };
  G(0, 0) = Sc(0);
  for (int l = 1; l <= H_; ++l) {
    G(0, 2 * l - 1) = Sc(l);
    G(0, 2 * l) = Ss(l);
  }
  for (int k = 1; k <= H_; ++k) {
    G(2 * k - 1, 0) = 2.0 * Sc(k);
    G(2 * k, 0) = 2.0 * Ss(k);
  }
  // column by column (G is column-major: each column one contiguous run)
  for (int l = 1; l <= H_; ++l) {
    const int al = 2 * l - 1, bl = 2 * l;
    for (int k = 1; k <= H_; ++k) {
      const int ak = 2 * k - 1, bk = 2 * k;
      G(ak, al) = Sc(k - l) + Sc(k + l);
      G(bk, al) = Ss(k + l) + Ss(k - l);
    }
    for (int k = 1; k <= H_; ++k) {
      const int ak = 2 * k - 1, bk = 2 * k;
      G(ak, bl) = Ss(k + l) - Ss(k - l);
      G(bk, bl) = Sc(k - l) - Sc(k + l);
    }
  }
}

double trig_series(const double* c, int H, double theta) {
  const double c1 = std::cos(theta), s1 = std::sin(theta);
  double v = c[0], ck = 1.0, sk = 0.0;
  for (int k = 1; k <= H; ++k) {
    const double cn = ck * c1 - sk * s1;
    sk = sk * c1 + ck * s1;
    ck = cn;
    v += c[2 * k - 1] * ck + c[2 * k] * sk;
  }
  return v;
}

Eigen::VectorXd reflected_series(const Eigen::VectorXd& c, double psi) {
  Eigen::VectorXd r = c;
  for (int k = 1; 2 * k < c.size(); ++k) {
    const double ck = std::cos(k * psi), sk = std::sin(k * psi), a = c[2 * k - 1], b = c[2 * k];
    r[2 * k - 1] = a * ck + b * sk;
    r[2 * k] = a * sk - b * ck;
  }
  return r;
}

std::vector<double> harmonic_amplitudes(const std::vector<double>& period_samples, int H) {
  const int N = int(period_samples.size());
  Aft aft(H, N);
  std::vector<double> c(aft.size());
  aft.to_frequency(period_samples.data(), c.data());
  std::vector<double> amp(H + 1);
  amp[0] = std::fabs(c[0]);
  for (int k = 1; k <= H; ++k) amp[k] = std::hypot(c[2 * k - 1], c[2 * k]);
  return amp;
}

Eigen::VectorXd periodic_fourier(const std::vector<double>& samples, int H) {
  const int N = int(samples.size());
  if (N < 4 || H < 0) throw std::invalid_argument("periodic_fourier: need >= 4 samples and H >= 0");
  const int Hc = std::min(H, (N - 2) / 2);
  Aft aft(Hc, N);
  const Eigen::VectorXd c = aft.to_frequency(Eigen::Map<const Eigen::VectorXd>(samples.data(), N));
  Eigen::VectorXd out = Eigen::VectorXd::Zero(2 * H + 1);
  out.head(c.size()) = c;
  return out;
}

}  // namespace gearhb
