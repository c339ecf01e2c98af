#include "gearhb/hb/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <unsupported/Eigen/MatrixFunctions>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

PiecewiseLinearFlow::PiecewiseLinearFlow(const HarmonicBalance& hb, bool spectral)
    : hb_(hb), n_(hb.dofs()), spectral_(spectral), Minv_(hb.system().M.inverse()) {
  // the forcing's harmonic first (its oscillator drives fc, fs), then the gaps' others
  const int p = hb.excitation().harmonic;
  harmonics_.push_back(p);
  const int H = hb.harmonics();
  for (int k = 1; k <= H; ++k) {
    if (k == p) continue;
    bool used = false;
    for (const auto& ct : hb.contacts())
      used = used || ct.gap_harmonics[2 * k - 1] != 0.0 || ct.gap_harmonics[2 * k] != 0.0;
    if (used) harmonics_.push_back(k);
  }
  dim_ = 2 * n_ + 1 + 2 * int(harmonics_.size());
  if (hb.contacts().size() > std::size_t(kMaxContacts))
    throw std::invalid_argument("PiecewiseLinearFlow: at most " + std::to_string(kMaxContacts) + " contacts");
  for (const auto& ct : hb.contacts())
    if (ct.stiffness_profile)
      throw std::invalid_argument("PiecewiseLinearFlow: a time-varying contact stiffness has no piecewise-constant flow");
  for (std::size_t i = 0; i < hb.contacts().size(); ++i) rows_.push_back(contact_row(i));
}

Eigen::RowVectorXd PiecewiseLinearFlow::contact_row(std::size_t i) const {
  const auto& ct = hb_.contacts()[i];
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(dim_);
  r.head(n_) = ct.normal.transpose();
  r[2 * n_] = ct.gap + ct.gap_harmonics[0];
  for (std::size_t j = 0; j < harmonics_.size(); ++j) {
    const int k = harmonics_[j];
    r[2 * n_ + 1 + 2 * int(j)] = ct.gap_harmonics[2 * k - 1];
    r[2 * n_ + 2 + 2 * int(j)] = ct.gap_harmonics[2 * k];
  }
  return r;
}

Eigen::MatrixXd PiecewiseLinearFlow::generator(unsigned S, double omega) const {
  const int n = n_, o = 2 * n_;
  const auto& sys = hb_.system();
  const auto& f = hb_.excitation();
  Eigen::MatrixXd Ks = sys.K;
  // forcing over the oscillator states (before Minv)
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, dim_ - o);
  B.col(0) = f.f0;
  B.col(1) = f.fc;
  B.col(2) = f.fs;
  for (std::size_t i = 0; i < hb_.contacts().size(); ++i) {
    if (!(S >> i & 1u)) continue;
    const auto& ct = hb_.contacts()[i];
    Ks += ct.kc * ct.normal * ct.normal.transpose();
    const Eigen::RowVectorXd r = contact_row(i);
    B -= ct.kc * ct.normal * r.tail(dim_ - o);
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(dim_, dim_);
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = -Minv_ * Ks;
  A.block(n, n, n, n) = -Minv_ * sys.C;
  A.block(n, o, n, dim_ - o) = Minv_ * B;
  for (std::size_t j = 0; j < harmonics_.size(); ++j) {
    const double kw = harmonics_[j] * omega;
    const int ic = o + 1 + 2 * int(j), is = ic + 1;
    A(ic, is) = -kw;   // (cos k omega t)' = -k omega sin
    A(is, ic) = kw;    // (sin k omega t)' =  k omega cos
  }
  return A;
}

// The flow of one contact state: z(s) = exp(A s) z(0) (see floquet.hpp).
class PiecewiseLinearFlow::Propagator {
 public:
  Propagator(Eigen::MatrixXd A, const std::vector<Eigen::RowVectorXd>& rows, bool try_spectral) : A_(std::move(A)) {
    // A = D B D^-1 with B balanced (generators mix metres, metres per second and unit
    // oscillators: unbalanced, the Pade exponential of a gear pair's loses 1e-7)
    B_ = A_;
    d_ = balance(B_);
    if (!try_spectral || !A_.allFinite()) return;
    // B = W diag(lambda) W^-1: V = D W, V^-1 = W^-1 D^-1
    EigenDecomposition es;
    if (!eigen_decomposition(B_, es)) return;
    const Eigen::MatrixXcd& W = es.vectors;
    const Eigen::MatrixXcd& Winv = es.inverse_vectors;
    const double cond = W.cwiseAbs().colwise().sum().maxCoeff() * Winv.cwiseAbs().colwise().sum().maxCoeff();
    if (!(cond <= 1e4) || !Winv.allFinite()) return;
    spectral_ = true;
    lambda_ = es.values;
    V_ = d_.cast<std::complex<double>>().asDiagonal() * W;
    Vinv_ = Winv * d_.cwiseInverse().cast<std::complex<double>>().asDiagonal();
    for (const auto& r : rows) rV_.push_back(r.cast<std::complex<double>>() * V_);
  }
  bool spectral() const { return spectral_; }

  const Eigen::MatrixXd& generator() const { return A_; }
  double rate() const { return spectral_ ? lambda_.cwiseAbs().maxCoeff() : B_.cwiseAbs().colwise().sum().maxCoeff(); }
  const Eigen::VectorXcd& eigenvalues() const { return lambda_; }   // empty unless spectral
  // The first `rows` rows of exp(A s_j) z for every s_j (columns)
  Eigen::MatrixXd apply_all(const Eigen::VectorXd& s, const Eigen::VectorXd& z, int rows) const {
    Eigen::MatrixXd out(rows, s.size());
    if (!spectral_) {
      for (Eigen::Index j = 0; j < s.size(); ++j) out.col(j) = exponential(s[j]).topRows(rows) * z;
      return out;
    }
    const Eigen::VectorXcd omega = Vinv_ * z.cast<std::complex<double>>();
    Eigen::MatrixXcd M(omega.size(), s.size());
    for (Eigen::Index j = 0; j < s.size(); ++j) M.col(j) = exps(s[j]).cwiseProduct(omega);
    out = (V_.topRows(rows) * M).real();
    return out;
  }
  // exp(A s) z
  Eigen::VectorXd apply(double s, const Eigen::VectorXd& z) const {
    if (spectral_) return (V_ * exps(s).cwiseProduct(Vinv_ * z.cast<std::complex<double>>())).real();
    return exponential(s) * z;
  }
  // exp(A s)
  Eigen::MatrixXd exponential(double s) const {
    if (spectral_) return (V_ * exps(s).asDiagonal() * Vinv_).real();
    return d_.asDiagonal() * Eigen::MatrixXd((B_ * s).exp()) * d_.cwiseInverse().asDiagonal();
  }
  // The same, kept for the next call with the same s (the uniform steps of a period).
  const Eigen::MatrixXd& step_exponential(double s) const {
    if (!(std::fabs(s - s_cached_) <= 1e-12 * s)) {
      s_cached_ = s;
      E_cached_ = exponential(s);
    }
    return E_cached_;
  }
  // Root in (0, h] of u_i(s) = r_i' exp(A s) z where the sign leaves `inside`
  // (u_i > 0 == inside at s -> 0+, not at s = h; fh = u_i(h)): safeguarded
  // Newton with u_i'(s) = r_i' A exp(A s) z, the bracket kept by the sign test.
  double switch_time(std::size_t i, const Eigen::RowVectorXd& r, const Eigen::VectorXd& z, double h, bool inside,
                     double fh, double tol) const {
    Eigen::VectorXcd alpha;
    if (spectral_) alpha = rV_[i].transpose().cwiseProduct(Vinv_ * z.cast<std::complex<double>>());
    auto value = [&](double s, double& f, double& df) {
      if (spectral_) {
        const Eigen::VectorXcd e = alpha.cwiseProduct(exps(s));
        f = e.sum().real();
        df = e.cwiseProduct(lambda_).sum().real();
      } else {
        const Eigen::VectorXd zs = exponential(s) * z;
        f = r.dot(zs);
        df = r.dot(A_ * zs);
      }
    };
    double lo = 0.0, hi = h, s = h;
    const double f0 = r.dot(z);
    // secant-like first guess from f(0) and f(h)
    if ((f0 > 0.0) == inside && fh != f0) s = std::clamp(h * f0 / (f0 - fh), 0.0, h);
    else s = 0.5 * h;
    for (int it = 0; it < 100 && hi - lo > tol; ++it) {
      double fs = 0.0, dfs = 0.0;
      value(s, fs, dfs);
      ((fs > 0.0) == inside ? lo : hi) = s;
      double next = s - fs / dfs;
      if (!(next > lo && next < hi) || !std::isfinite(next)) next = 0.5 * (lo + hi);
      if (std::fabs(next - s) < 0.25 * tol) {
        s = next;
        break;
      }
      s = next;
    }
    return std::clamp(s, lo, hi);
  }

 private:
  Eigen::MatrixXd A_, B_;   // generator, balanced generator D^-1 A D
  Eigen::VectorXd d_;       // D
  bool spectral_ = false;
  Eigen::VectorXcd lambda_;
  Eigen::MatrixXcd V_, Vinv_;
  std::vector<Eigen::RowVectorXcd> rV_;
  mutable double s_cached_ = NAN;
  mutable Eigen::MatrixXd E_cached_;
  Eigen::VectorXcd exps(double s) const { return (lambda_ * s).array().exp().matrix(); }
};

const PiecewiseLinearFlow::Propagator& PiecewiseLinearFlow::propagator(unsigned S, double omega) const {
  if (!(omega == cache_omega_)) {
    cache_.clear();
    cache_omega_ = omega;
  }
  // the states met in one period: a handful of the 2^P possible ones
  for (const auto& [state, p] : cache_)
    if (state == S) return *p;
  cache_.emplace_back(S, std::make_shared<Propagator>(generator(S, omega), rows_, spectral_));
  return *cache_.back().second;
}

Eigen::VectorXd PiecewiseLinearFlow::advance(unsigned state, double omega, double s, const Eigen::VectorXd& z) const {
  return propagator(state, omega).apply(s, z);
}

Eigen::MatrixXd PiecewiseLinearFlow::advance_xv(unsigned state, double omega, const Eigen::VectorXd& s,
                                                const Eigen::VectorXd& z) const {
  return propagator(state, omega).apply_all(s, z, 2 * n_);
}

bool PiecewiseLinearFlow::spectral(unsigned state, double omega) const { return propagator(state, omega).spectral(); }

Eigen::MatrixXd PiecewiseLinearFlow::exponential(unsigned state, double omega, double s) const {
  return propagator(state, omega).exponential(s);
}

const Eigen::MatrixXd& PiecewiseLinearFlow::generator_matrix(unsigned state, double omega) const {
  return propagator(state, omega).generator();
}

double PiecewiseLinearFlow::rate(unsigned state, double omega) const { return propagator(state, omega).rate(); }

Eigen::VectorXcd PiecewiseLinearFlow::eigenvalues(unsigned state, double omega) const {
  return propagator(state, omega).eigenvalues();
}

int PiecewiseLinearFlow::spectral_states() const {
  int k = 0;
  for (const auto& [state, p] : cache_) k += p->spectral();
  return k;
}

int PiecewiseLinearFlow::pade_states() const {
  int k = 0;
  for (const auto& [state, p] : cache_) k += !p->spectral();
  return k;
}

void PiecewiseLinearFlow::period_map(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                     const std::vector<double>& nodes, Eigen::VectorXd& xT,
                                     Eigen::VectorXd& vT, Eigen::MatrixXd& Phi, Eigen::MatrixXd* xs,
                                     std::vector<FlowSegment>* segments) const {
  march(x0, v0, omega, nodes, xT, vT, &Phi, xs, segments);
}

void PiecewiseLinearFlow::follow(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                 const std::vector<double>& nodes, Eigen::VectorXd& xT, Eigen::VectorXd& vT,
                                 std::vector<FlowSegment>& segments) const {
  march(x0, v0, omega, nodes, xT, vT, nullptr, nullptr, &segments);
}

void PiecewiseLinearFlow::march(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega,
                                const std::vector<double>& nodes, Eigen::VectorXd& xT, Eigen::VectorXd& vT,
                                Eigen::MatrixXd* Phi, Eigen::MatrixXd* xs, std::vector<FlowSegment>* segments) const {
  const int n = n_, m = 2 * n_;
  const double T = 2.0 * M_PI / omega;
  const std::size_t nc = hb_.contacts().size();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(dim_);
  z.head(n) = x0;
  z.segment(n, n) = v0;
  z[m] = 1.0;
  for (std::size_t j = 0; j < harmonics_.size(); ++j) z[m + 1 + 2 * int(j)] = 1.0;   // cos(0)
  unsigned S = 0;
  for (std::size_t i = 0; i < nc; ++i)
    if (rows_[i].dot(z) > 0.0) S |= 1u << i;
  if (Phi) *Phi = Eigen::MatrixXd::Identity(m, m);
  if (xs) xs->resize(n, Eigen::Index(nodes.size()));
  if (segments) segments->clear();
  const double tol = 1e-14 * T;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (xs) xs->col(Eigen::Index(k)) = z.head(n);
    double h = (k + 1 < nodes.size() ? nodes[k + 1] : T) - nodes[k];
    double t = nodes[k];
    int guard = 0;
    while (h > 0.0) {
      if (++guard > 1000) throw std::runtime_error("PiecewiseLinearFlow: too many contact switches in one step");
      const Propagator& P = propagator(S, omega);
      // without the monodromy a diagonalised propagator steps by two products; a Pade one by its kept step
      const Eigen::MatrixXd* E = Phi || !P.spectral() ? &P.step_exponential(h) : nullptr;
      const Eigen::VectorXd zb = E ? Eigen::VectorXd(*E * z) : P.apply(h, z);
      // contacts whose state at the end of the step differs from S: the earliest switch
      double s_first = h;
      std::size_t i_first = nc;
      for (std::size_t i = 0; i < nc; ++i) {
        const bool inside = S >> i & 1u;
        const double fb = rows_[i].dot(zb);
        if ((fb > 0.0) == inside) continue;
        const double s = P.switch_time(i, rows_[i], z, h, inside, fb, tol);
        if (s < s_first || i_first == nc) { s_first = s; i_first = i; }
      }
      if (i_first == nc) {
        if (segments) segments->push_back({t, h, S, z});
        z = zb;
        if (Phi) *Phi = E->topLeftCorner(m, m) * *Phi;
        break;
      }
      if (segments) segments->push_back({t, s_first, S, z});
      t += s_first;
      if (Phi) {
        const Eigen::MatrixXd Es = P.exponential(s_first);
        z = Es * z;
        *Phi = Es.topLeftCorner(m, m) * *Phi;
      } else {
        z = P.apply(s_first, z);
      }
      S ^= 1u << i_first;
      h -= s_first;
      if (h <= tol) break;
    }
  }
  xT = z.head(n);
  vT = z.segment(n, n);
}

namespace {

// Multipliers of a monodromy matrix into r (largest modulus first) and the stable flag.
void set_multipliers(FloquetResult& r, const Eigen::MatrixXd& Phi, const FloquetOptions& opt, double omega) {
  const Eigen::VectorXcd mu = general_eigenvalues(Phi, "Floquet multipliers at omega = " + std::to_string(omega));
  std::vector<std::complex<double>> v(mu.data(), mu.data() + mu.size());
  std::sort(v.begin(), v.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  r.multipliers = Eigen::Map<Eigen::VectorXcd>(v.data(), Eigen::Index(v.size()));
  r.critical = v.front();
  r.modulus = std::abs(r.critical);
  r.angle = std::arg(r.critical);
  r.stable = r.modulus < 1.0 - opt.stability_margin;
}

bool has_stiffness_profile(const HarmonicBalance& hb) {
  for (const auto& ct : hb.contacts())
    if (ct.stiffness_profile) return true;
  return false;
}

}  // namespace

namespace {
// B(t, mid, out): B at t of the segment whose midpoint is mid (see second_order_march).
using SegmentMatrix = std::function<void(double, double, Eigen::MatrixXd&)>;
struct SecondOrderContext {
  const SegmentMatrix* B;
  const Eigen::MatrixXd* C;
  int n;
  Eigen::MatrixXd Bt;
  int cols = 0;     // columns of the state Y carried
  double mid = 0;   // the midpoint of the segment being integrated
};
// Y = [X; V] (2n x cols, column-major): X' = V, V' = -B(t) X - C V.
int second_order_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<SecondOrderContext*>(params);
  (*c->B)(t, c->mid, c->Bt);
  const int n = c->n;
  Eigen::Map<const Eigen::MatrixXd> Y(y, 2 * n, c->cols);
  Eigen::Map<Eigen::MatrixXd> dY(dydt, 2 * n, c->cols);
  dY.topRows(n) = Y.bottomRows(n);
  dY.bottomRows(n).noalias() = -c->Bt * Y.topRows(n);
  dY.bottomRows(n).noalias() -= *c->C * Y.bottomRows(n);
  return GSL_SUCCESS;
}

// Y0 (2n x cols, the state [x; v] of each column) carried over [0, T] by the second-order
// variational equation x'' = -B(t) x - C x' (GSL rk8pd, relative and absolute tolerance tol;
// a fresh driver at every breakpoint, where B may jump, and at every sample time), half the
// cost of a first-order step on A = [0 I; -B -C]: its zero and identity blocks are not
// multiplied. `samples` (ascending, in [0, T)): the x rows of Y there, side by side into *xs.
// B receives the midpoint of the segment it is evaluated on: a jump of B at a breakpoint is
// the model's to place by it (GSL evaluates the first stage of a step at the breakpoint itself,
// where a pointwise test of the switching function meets rounding: a stage on the wrong side
// made every segment's first step shrink to 1e-11 of a period, 18 rejections a segment).
Eigen::MatrixXd second_order_march(const SegmentMatrix& B, const Eigen::MatrixXd& C,
                                   Eigen::MatrixXd Y, double T, const std::vector<double>& breakpoints, double tol,
                                   const std::vector<double>& samples = {}, Eigen::MatrixXd* xs = nullptr) {
  const int n = int(C.rows()), cols = int(Y.cols());
  SecondOrderContext ctx{&B, &C, n, Eigen::MatrixXd::Zero(n, n), cols};
  std::vector<double> ends;
  for (double b : breakpoints)
    if (b > 0.0 && b < T) ends.push_back(b);
  for (double s : samples)
    if (s > 0.0 && s < T) ends.push_back(s);
  std::sort(ends.begin(), ends.end());
  ends.push_back(T);
  if (xs) xs->resize(n, Eigen::Index(samples.size()) * cols);
  std::size_t next = 0;   // the next sample to record
  auto record = [&](double t) {
    for (; xs && next < samples.size() && samples[next] <= t; ++next)
      xs->middleCols(Eigen::Index(next) * cols, cols) = Y.topRows(n);
  };
  gsl_odeiv2_system sys{second_order_rhs, nullptr, std::size_t(2 * n) * std::size_t(cols), &ctx};
  double t = 0.0;
  record(t);
  for (double t1 : ends) {
    // equal breakpoints (contacts that switch at the same instant, e.g. the in-phase meshes
    // of a planetary set) leave no segment between them: GSL refuses a zero first step
    if (!(t1 > t)) continue;
    ctx.mid = 0.5 * (t + t1);
    // a fresh driver per segment: the step history must not straddle a jump of B
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * (t1 - t), tol, tol);
    if (d == nullptr) throw std::runtime_error("second_order_march: GSL could not allocate the driver");
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, Y.data());
    gsl_odeiv2_driver_free(d);
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("second_order_march: GSL driver failed at t = ") + std::to_string(t) +
                               ": " + gsl_strerror(status));
    record(t);
  }
  return Y;
}

// The variational equation about the HB orbit (X, omega) itself: B(t) = M^-1 (K + sum_i
// kc_i(t) [u_i(t) > 0] n_i n_i'), u_i the HB penetration, its contact switches as breakpoints
// (the vector field is continuous in x, so no saltation); between two breakpoints no contact
// switches, so [u_i > 0] is taken at the segment's midpoint.
struct HbVariationalEquation {
  double T;
  Eigen::MatrixXd MinvK, MinvC;
  std::vector<Eigen::VectorXd> u, Minv_n;
  std::vector<double> breakpoints;
  const HarmonicBalance& hb;
  double omega;

  HbVariationalEquation(const HarmonicBalance& hb_, const Eigen::VectorXd& X, double omega_)
      : T(2.0 * M_PI / omega_), hb(hb_), omega(omega_) {
    const auto& sys = hb.system();
    const Eigen::MatrixXd Minv = sys.M.inverse();
    // penetration coefficients of every contact on the HB orbit, and its switch times
    for (std::size_t i = 0; i < hb.contacts().size(); ++i) {
      Eigen::VectorXd uc = hb.penetration(X, i);
      for (const auto& [a, b] : hb.contact_intervals(X, i))
        if (b - a < 2.0 * M_PI)
          for (double th : {a, b}) breakpoints.push_back(std::fmod(th, 2.0 * M_PI) / omega);
      u.push_back(std::move(uc));
    }
    // M^-1 K and M^-1 n_i once, the closed contacts' rank-one terms at each t
    MinvK = Minv * sys.K;
    MinvC = Minv * sys.C;
    for (const auto& ct : hb.contacts()) Minv_n.push_back(Minv * ct.normal);
  }
  void B(double t, double mid, Eigen::MatrixXd& out) const {
    const double th = omega * t;
    out = MinvK;
    for (std::size_t i = 0; i < u.size(); ++i) {
      if (!(trig_series(u[i], omega * mid) > 0.0)) continue;   // open: contact_stiffness 0
      const auto& ct = hb.contacts()[i];
      out.noalias() += stiffness_at(ct, th) * Minv_n[i] * ct.normal.transpose();
    }
  }
  Eigen::MatrixXd march(const Eigen::MatrixXd& Y0, double tol, const std::vector<double>& samples = {},
                        Eigen::MatrixXd* xs = nullptr) const {
    return second_order_march([this](double t, double mid, Eigen::MatrixXd& out) { B(t, mid, out); }, MinvC, Y0, T,
                              breakpoints, tol,
                              samples, xs);
  }
};

}  // namespace

FloquetResult floquet_of_hb_variational(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                        const FloquetOptions& opt) {
  const HbVariationalEquation eq(hb, X, omega);
  FloquetResult r;
  r.monodromy = eq.march(Eigen::MatrixXd::Identity(2 * hb.dofs(), 2 * hb.dofs()), opt.variational_tolerance);
  r.orbit_error = NAN;   // the HB orbit is not corrected on this path
  hb_initial_state(hb, X, omega, r.x0, r.v0);
  set_multipliers(r, r.monodromy, opt, omega);
  return r;
}

Eigen::MatrixXd variational_solution(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                     const Eigen::VectorXd& y0, const std::vector<double>& nodes, double tol) {
  Eigen::MatrixXd xs;
  HbVariationalEquation(hb, X, omega).march(y0, tol, nodes, &xs);
  return xs;
}

namespace {

// x of the HB orbit at the phases 2 pi j / M (columns): each DOF's Fourier series
// (HarmonicBalance::project) sampled by the FFT (core Aft) on M r phases, r the least integer
// with M r >= 2H + 2 (what an Aft needs), every r-th kept. Before, a sum per sample (core
// trig_series): 3 % of ex. 03's period-2 branch (M = 322, H = 80).
Eigen::MatrixXd hb_orbit_samples(const HarmonicBalance& hb, const Eigen::VectorXd& X, int M) {
  const int n = hb.dofs(), H = hb.harmonics(), r = (2 * H + 2 + M - 1) / M;
  const Aft aft(H, M * r);
  Eigen::MatrixXd xhb(n, M);
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd x = aft.to_time(hb.project(X, Eigen::VectorXd::Unit(n, i)));
    for (int j = 0; j < M; ++j) xhb(i, j) = x[Eigen::Index(j) * r];
  }
  return xhb;
}

// A period map on the shooting variable y = (x0, v0) at phase 0: y(T), the monodromy
// matrix, and x at the map's sampling nodes (columns).
using ShootingMap = std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& yT, Eigen::MatrixXd& Phi,
                                       Eigen::MatrixXd& xs)>;

// Newton's method on the shooting equations P(y) - y = 0 from the HB state (dP/dy the
// monodromy matrix; Seydel, Practical Bifurcation and Stability Analysis, 3rd ed., §7.3),
// residual scaled by sc, keeping the best iterate (a step that does not lower the
// residual ends the iteration). Fills r (state, monodromy, residual, corrected, steps,
// multipliers) and returns x at the nodes on the best orbit.
Eigen::MatrixXd shooting_newton(const ShootingMap& P, const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                const Eigen::VectorXd& sc, const FloquetOptions& opt, FloquetResult& r) {
  const int n = hb.dofs(), m = 2 * n;
  Eigen::VectorXd x0, v0, yT;
  hb_initial_state(hb, X, omega, x0, v0);
  Eigen::VectorXd y(m), ybest;
  y << x0, v0;
  Eigen::MatrixXd Phi, xs, Phi_best, xs_best;
  double best = INFINITY;
  r.shooting = true;
  for (int it = 0; it <= opt.max_newton; ++it) {
    P(y, yT, Phi, xs);
    const Eigen::VectorXd F = yT - y;
    const double res = F.cwiseQuotient(sc).cwiseAbs().maxCoeff();
    if (!(res < best)) break;   // no progress (or NaN): keep the best orbit
    best = res;
    ybest = y;
    Phi_best = Phi;
    xs_best = xs;
    r.newton_steps = it;
    if (res < opt.tolerance) {
      r.corrected = true;
      break;
    }
    if (it == opt.max_newton) break;
    const Eigen::VectorXd dy = (Phi - Eigen::MatrixXd::Identity(m, m)).partialPivLu().solve(-F);
    if (!dy.allFinite()) break;
    y += dy;
  }
  if (ybest.size() == 0 || Phi_best.size() == 0)   // the first residual was already not finite
    throw std::runtime_error("Floquet: the period map of the harmonic-balance orbit is not finite at omega = " +
                             std::to_string(omega) + " rad/s (a parameter far outside the model's scale?)");
  r.shooting_residual = best;
  r.x0 = ybest.head(n);
  r.v0 = ybest.tail(n);
  r.monodromy = Phi_best;
  set_multipliers(r, Phi_best, opt, omega);
  return xs_best;
}

Eigen::VectorXd shooting_scale(int n, double omega, double x_scale) {
  Eigen::VectorXd sc(2 * n);
  sc.head(n).setConstant(x_scale);
  sc.tail(n).setConstant(omega * x_scale);
  return sc;
}

}  // namespace

FloquetResult floquet_of_hb_shooting_gsl(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega,
                                         double x_scale, const FloquetOptions& opt) {
  const int n = hb.dofs(), H = hb.harmonics();
  const int M = opt.steps > 0 ? opt.steps : std::max(64, 2 * (2 * H + 1));
  const TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.rel_tol = 1e-12;
  to.abs_tol = 1e-13;
  to.x_scale = x_scale;
  const ShootingMap P = [&](const Eigen::VectorXd& y, Eigen::VectorXd& yT, Eigen::MatrixXd& Phi, Eigen::MatrixXd& xs) {
    Eigen::VectorXd xT, vT;
    ti.period_map(y.head(n), y.tail(n), omega, to, xT, vT, Phi, M, &xs);
    yT.resize(2 * n);
    yT << xT, vT;
  };
  FloquetResult r;
  const Eigen::MatrixXd xs = shooting_newton(P, hb, X, omega, shooting_scale(n, omega, x_scale), opt, r);
  r.orbit_error = (xs - hb_orbit_samples(hb, X, M)).cwiseAbs().maxCoeff();
  return r;
}

std::vector<double> shooting_nodes(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega, int steps) {
  const int H = hb.harmonics();
  const int M = steps > 0 ? steps : std::max(64, 2 * (2 * H + 1));
  const double T = 2.0 * M_PI / omega;
  std::vector<double> nodes;
  for (int j = 0; j < M; ++j) nodes.push_back(T * j / M);
  for (std::size_t c = 0; c < hb.contacts().size(); ++c) {
    const auto I = hb.contact_intervals(X, c);
    for (std::size_t i = 0; i < I.size(); ++i) {
      const double a = I[i].first, b = I[i].second;
      if (b - a < 4.0 * M_PI / M) nodes.push_back(std::fmod(0.5 * (a + b), 2.0 * M_PI) / omega);
      const double a2 = I[(i + 1) % I.size()].first + (i + 1 == I.size() ? 2.0 * M_PI : 0.0);
      if (a2 - b < 4.0 * M_PI / M) nodes.push_back(std::fmod(0.5 * (b + a2), 2.0 * M_PI) / omega);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

FloquetResult floquet_of_hb_orbit(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega, double x_scale,
                                  const FloquetOptions& opt) {
  if (!opt.correct_orbit) return floquet_of_hb_variational(hb, X, omega, opt);
  if (has_stiffness_profile(hb)) return floquet_of_hb_shooting_gsl(hb, X, omega, x_scale, opt);
  const int n = hb.dofs(), H = hb.harmonics();
  const double T = 2.0 * M_PI / omega;
  const int M = opt.steps > 0 ? opt.steps : std::max(64, 2 * (2 * H + 1));
  const std::vector<double> nodes = shooting_nodes(hb, X, omega, M);
  PiecewiseLinearFlow flow(hb);
  const ShootingMap P = [&](const Eigen::VectorXd& y, Eigen::VectorXd& yT, Eigen::MatrixXd& Phi, Eigen::MatrixXd& xs) {
    Eigen::VectorXd xT, vT;
    flow.period_map(y.head(n), y.tail(n), omega, nodes, xT, vT, Phi, &xs);
    yT.resize(2 * n);
    yT << xT, vT;
  };
  FloquetResult r;
  const Eigen::MatrixXd xs = shooting_newton(P, hb, X, omega, shooting_scale(n, omega, x_scale), opt, r);
  // orbit error over the uniform nodes (their columns in the node list)
  const Eigen::MatrixXd xhb = hb_orbit_samples(hb, X, M);
  Eigen::MatrixXd xex(n, M);   // the corrected orbit at the uniform nodes
  double e = 0.0;
  std::size_t col = 0;
  for (int j = 0; j < M; ++j) {
    const double t = T * j / M;
    while (col < nodes.size() && nodes[col] < t - 1e-12 * T) ++col;
    xex.col(j) = xs.col(Eigen::Index(col));
    e = std::max(e, (xex.col(j) - xhb.col(j)).cwiseAbs().maxCoeff());
  }
  r.orbit_error = e;
  const int p = hb.excitation().harmonic;
  if (p > 1 && M % p == 0 && r.corrected) {
    auto repeat_gap = [M, p](const Eigen::MatrixXd& x) {   // max_t |x(t + T/p) - x(t)|
      double g = 0.0;
      for (int j = 0; j < M; ++j) g = std::max(g, (x.col((j + M / p) % M) - x.col(j)).cwiseAbs().maxCoeff());
      return g;
    };
    const double g_hb = repeat_gap(xhb);
    if (g_hb > 1e-9 * x_scale && repeat_gap(xex) < 1e-2 * g_hb) {
      r.lower_period = true;
      r.stable = false;
    }
  }
  return r;
}

// --- variational equation of a linear periodic system (GSL) --------------------

namespace {
struct LinearContext {
  const std::function<void(double, Eigen::MatrixXd&)>* A;
  int dim;
  Eigen::MatrixXd At;
};
int linear_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<LinearContext*>(params);
  (*c->A)(t, c->At);
  Eigen::Map<const Eigen::MatrixXd> Y(y, c->dim, c->dim);
  Eigen::Map<Eigen::MatrixXd> dY(dydt, c->dim, c->dim);
  dY.noalias() = c->At * Y;
  return GSL_SUCCESS;
}
}  // namespace

Eigen::MatrixXd monodromy_linear_periodic(const std::function<void(double, Eigen::MatrixXd&)>& A, int dim,
                                          double T, const std::vector<double>& breakpoints, double tol) {
  LinearContext ctx{&A, dim, Eigen::MatrixXd::Zero(dim, dim)};
  Eigen::MatrixXd Y = Eigen::MatrixXd::Identity(dim, dim);
  std::vector<double> ends;
  for (double b : breakpoints)
    if (b > 0.0 && b < T) ends.push_back(b);
  std::sort(ends.begin(), ends.end());
  ends.push_back(T);
  gsl_odeiv2_system sys{linear_rhs, nullptr, std::size_t(dim) * std::size_t(dim), &ctx};
  double t = 0.0;
  for (double t1 : ends) {
    // equal breakpoints (contacts that switch at the same instant, e.g. the in-phase meshes
    // of a planetary set) leave no segment between them: GSL refuses a zero first step
    if (!(t1 > t)) continue;
    // a fresh driver per segment: the step history must not straddle a jump of A
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * (t1 - t), tol, tol);
    if (d == nullptr) throw std::runtime_error("monodromy_linear_periodic: GSL could not allocate the driver");
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, Y.data());
    gsl_odeiv2_driver_free(d);
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("monodromy_linear_periodic: GSL driver failed at t = ") +
                               std::to_string(t) + ": " + gsl_strerror(status));
  }
  return Y;
}


}  // namespace gearhb
