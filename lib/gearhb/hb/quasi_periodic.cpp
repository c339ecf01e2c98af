#include "gearhb/hb/quasi_periodic.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/hb/floquet.hpp"

namespace gearhb {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace

TorusBalance::TorusBalance(const HarmonicBalance& hb, int H1, int H2, int N2)
    : hb_(hb), n_(hb.dofs()), H1_(H1), H2_(H2), N2_(N2 > 0 ? N2 : 4 * (2 * H2 + 1)) {
  if (H1 < 1 || H1 > hb.harmonics()) throw std::invalid_argument("torus: harmonics1 must be 1..H of the model");
  if (H2 < 1) throw std::invalid_argument("torus: harmonics2 must be >= 1");
  if (N2_ < 2 * H2 + 1) throw std::invalid_argument("torus: lines must be at least 2 harmonics2 + 1");
  for (const auto& ct : hb.contacts())
    if (ct.stiffness_profile)
      throw std::invalid_argument("torus: a time-varying contact stiffness (kc_file) has no two-frequency model here");
  if (hb.excitation().harmonic != 1) throw std::invalid_argument("torus: the forcing must be on the first harmonic");
  S_.reserve(N2_);
  for (int j = 0; j < N2_; ++j) S_.push_back(restriction(2.0 * M_PI * j / N2_));
}

int TorusBalance::k1(int pair) const { return pair <= H2_ ? 0 : 1 + (pair - H2_ - 1) / (2 * H2_ + 1); }
int TorusBalance::k2(int pair) const { return pair <= H2_ ? pair : (pair - H2_ - 1) % (2 * H2_ + 1) - H2_; }

// Row m of S: coefficient m of the 1-D series in theta1 (static, cos k, sin k) of basis
// function b restricted to theta2: cos(k1 t1 + beta) = cos beta cos k1 t1 - sin beta sin k1 t1,
// sin(k1 t1 + beta) = sin beta cos k1 t1 + cos beta sin k1 t1, beta = k2 theta2.
Eigen::MatrixXd TorusBalance::restriction(double theta2) const {
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(2 * H1_ + 1, basis());
  S(0, 0) = 1.0;
  for (int p = 1; p <= pairs(); ++p) {
    const int a = k1(p);
    const double cb = std::cos(k2(p) * theta2), sb = std::sin(k2(p) * theta2);
    if (a == 0) {
      S(0, 2 * p - 1) = cb;
      S(0, 2 * p) = sb;
    } else {
      S(2 * a - 1, 2 * p - 1) = cb;
      S(2 * a, 2 * p - 1) = -sb;
      S(2 * a - 1, 2 * p) = sb;
      S(2 * a, 2 * p) = cb;
    }
  }
  return S;
}

void TorusBalance::evaluate(const Eigen::VectorXd& X, double omega, double omega2, Eigen::VectorXd& R,
                            Eigen::MatrixXd* dRdX, Eigen::VectorXd* dRdomega, Eigen::VectorXd* dRdomega2) const {
  linear_terms(X, omega, omega2, R, dRdX, dRdomega, dRdomega2);
  contact_terms(X, R, dRdX);
}

// The linear terms, pair by pair (harmonic_balance.hpp with k omega -> w), and the forcing.
void TorusBalance::linear_terms(const Eigen::VectorXd& X, double omega, double omega2, Eigen::VectorXd& R,
                                Eigen::MatrixXd* dRdX, Eigen::VectorXd* dRdomega, Eigen::VectorXd* dRdomega2) const {
  const int n = n_;
  const LinearSystem& s = hb_.system();
  const Excitation& f = hb_.excitation();
  R = Eigen::VectorXd::Zero(size());
  if (dRdX) *dRdX = Eigen::MatrixXd::Zero(size(), size());
  if (dRdomega) *dRdomega = Eigen::VectorXd::Zero(size());
  if (dRdomega2) *dRdomega2 = Eigen::VectorXd::Zero(size());
  R.head(n) = s.K * X.head(n) - f.f0;
  if (dRdX) dRdX->topLeftCorner(n, n) = s.K;
  for (int p = 1; p <= pairs(); ++p) {
    const double w = k1(p) * omega + k2(p) * omega2;
    const int c = (2 * p - 1) * n, sn = 2 * p * n;
    const Eigen::VectorXd a = X.segment(c, n), b = X.segment(sn, n);
    const Eigen::MatrixXd D = s.K - w * w * s.M;
    R.segment(c, n) = D * a + w * (s.C * b);
    R.segment(sn, n) = D * b - w * (s.C * a);
    if (k1(p) == 1 && k2(p) == 0) {
      R.segment(c, n) -= f.fc;
      R.segment(sn, n) -= f.fs;
    }
    if (dRdX) {
      dRdX->block(c, c, n, n) = D;
      dRdX->block(c, sn, n, n) = w * s.C;
      dRdX->block(sn, c, n, n) = -w * s.C;
      dRdX->block(sn, sn, n, n) = D;
    }
    const Eigen::VectorXd dc = -2.0 * w * (s.M * a) + s.C * b, ds = -2.0 * w * (s.M * b) - s.C * a;
    if (dRdomega) {
      dRdomega->segment(c, n) = k1(p) * dc;
      dRdomega->segment(sn, n) = k1(p) * ds;
    }
    if (dRdomega2) {
      dRdomega2->segment(c, n) = k2(p) * dc;
      dRdomega2->segment(sn, n) = k2(p) * ds;
    }
  }
}

// The contact forces, line by line in theta2 (the header), added to R and dR/dX.
void TorusBalance::contact_terms(const Eigen::VectorXd& X, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX) const {
  const int n = n_, Nb = basis();
  const int m = 2 * H1_ + 1;
  Aft aft(H1_);
  Eigen::VectorXd Dinv = Eigen::VectorXd::Constant(m, 0.5), Cw = Eigen::VectorXd::Constant(Nb, 2.0);
  Dinv[0] = 1.0;
  Cw[0] = 1.0;
  Eigen::VectorXd mc(2 * H1_ + 1), ms(2 * H1_ + 1);
  Eigen::MatrixXd G(m, m);
  for (const auto& ct : hb_.contacts()) {
    Eigen::VectorXd U(Nb), g = Eigen::VectorXd::Zero(m);
    for (int b = 0; b < Nb; ++b) U[b] = ct.normal.dot(X.segment(b * n, n));
    for (int a = 0; a < m && a < ct.gap_harmonics.size(); ++a) g[a] = ct.gap_harmonics[a];
    g[0] += ct.gap;
    Eigen::VectorXd F = Eigen::VectorXd::Zero(Nb);
    Eigen::MatrixXd J = dRdX ? Eigen::MatrixXd::Zero(Nb, Nb) : Eigen::MatrixXd();
    for (int j = 0; j < N2_; ++j) {
      const Eigen::VectorXd uc = S_[j] * U + g;
      const Eigen::VectorXd us = aft.to_time(uc);
      indicator_moments(contact_intervals(uc, us), 2 * H1_, mc.data(), ms.data());
      aft.product_matrix_from_moments(mc.data(), ms.data(), G);
      const Eigen::MatrixXd DG = Dinv.asDiagonal() * (ct.kc * G);
      F.noalias() += S_[j].transpose() * (DG * uc);
      if (dRdX) add_sandwich(j, DG, J);
    }
    F = Cw.cwiseProduct(F) / N2_;
    for (int b = 0; b < Nb; ++b) R.segment(b * n, n) += F[b] * ct.normal;
    if (dRdX) {
      J = Cw.asDiagonal() * J / N2_;
      const Eigen::MatrixXd nn = ct.normal * ct.normal.transpose();
      for (int a = 0; a < Nb; ++a)
        for (int b = 0; b < Nb; ++b)
          if (J(a, b) != 0.0) dRdX->block(a * n, b * n, n, n) += J(a, b) * nn;
    }
  }
}

// J += S_j' DG S_j, using that each column of S_j has at most two non-zeros (the rows
// 2 k1 - 1, 2 k1 of its pair's k1, or row 0): 4 products per entry instead of a dense sandwich.
void TorusBalance::add_sandwich(int j, const Eigen::MatrixXd& DG, Eigen::MatrixXd& J) const {
  const int Nb = basis();
  const Eigen::MatrixXd& S = S_[j];
  std::vector<int> r0(Nb), r1(Nb);
  for (int b = 0; b < Nb; ++b) {
    const int p = (b + 1) / 2, a = b == 0 ? 0 : k1(p);
    r0[b] = a == 0 ? 0 : 2 * a - 1;
    r1[b] = a == 0 ? -1 : 2 * a;
  }
  for (int b = 0; b < Nb; ++b) {
    // column b of DG S_j: DG.col(r0) S(r0, b) + DG.col(r1) S(r1, b)
    Eigen::VectorXd col = DG.col(r0[b]) * S(r0[b], b);
    if (r1[b] >= 0) col += DG.col(r1[b]) * S(r1[b], b);
    for (int a = 0; a < Nb; ++a) {
      double v = S(r0[a], a) * col[r0[a]];
      if (r1[a] >= 0) v += S(r1[a], a) * col[r1[a]];
      J(a, b) += v;
    }
  }
}

Eigen::VectorXd TorusBalance::theta2_derivative(const Eigen::VectorXd& X) const {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(size());
  for (int p = 1; p <= pairs(); ++p) {
    const int c = (2 * p - 1) * n_, s = 2 * p * n_;
    d.segment(c, n_) = k2(p) * X.segment(s, n_);
    d.segment(s, n_) = -k2(p) * X.segment(c, n_);
  }
  return d;
}

Eigen::VectorXd TorusBalance::from_periodic(const Eigen::VectorXd& X1) const {
  Eigen::VectorXd X = Eigen::VectorXd::Zero(size());
  X.head(n_) = X1.head(n_);
  for (int k = 1; k <= H1_; ++k) {
    const int p = H2_ + (k - 1) * (2 * H2_ + 1) + H2_ + 1;   // the pair (k, 0)
    X.segment((2 * p - 1) * n_, n_) = X1.segment(hb_.index(2 * k - 1, 0), n_);
    X.segment(2 * p * n_, n_) = X1.segment(hb_.index(2 * k, 0), n_);
  }
  return X;
}

Eigen::VectorXd TorusBalance::quasi_periodic_part(const Eigen::VectorXd& X) const {
  Eigen::VectorXd Y = X;
  Y.head(n_).setZero();
  for (int p = 1; p <= pairs(); ++p)
    if (k2(p) == 0) Y.segment((2 * p - 1) * n_, 2 * n_).setZero();
  return Y;
}

Eigen::VectorXd TorusBalance::line(const Eigen::VectorXd& X, const Eigen::VectorXd& q, double theta2) const {
  Eigen::VectorXd Q(basis());
  for (int b = 0; b < basis(); ++b) Q[b] = q.dot(X.segment(b * n_, n_));
  return restriction(theta2) * Q;
}

double TorusBalance::value(const Eigen::VectorXd& X, const Eigen::VectorXd& q, double theta1, double theta2) const {
  return trig_series(line(X, q, theta2), theta1);
}

TorusMeasures torus_measures(const TorusBalance& tb, const Eigen::VectorXd& X, const Eigen::VectorXd& q, int lines) {
  TorusMeasures r;
  Aft aft(tb.harmonics1());
  r.x_max = r.section_max = -INFINITY;
  r.x_min = r.section_min = INFINITY;
  for (int l = 0; l < lines; ++l) {
    const Eigen::VectorXd c = tb.line(X, q, 2.0 * M_PI * l / lines);
    const Eigen::VectorXd samples = aft.to_time(c);
    const auto [lo, hi] = trig_extremes(c, samples);
    r.x_max = std::max(r.x_max, hi);
    r.x_min = std::min(r.x_min, lo);
    r.section_max = std::max(r.section_max, samples[0]);   // theta1 = 0
    r.section_min = std::min(r.section_min, samples[0]);
  }
  const Eigen::VectorXd Y = tb.quasi_periodic_part(X);
  double sum = 0.0;
  for (int b = 1; b < tb.basis(); ++b) sum += std::pow(q.dot(Y.segment(b * tb.dofs(), tb.dofs())), 2);
  r.x_qp_rms = std::sqrt(sum / 2.0);
  return r;
}

void torus_state(const TorusBalance& tb, const Eigen::VectorXd& X, double omega, double omega2, double theta1,
                 double theta2, Eigen::VectorXd& x, Eigen::VectorXd& v) {
  const int n = tb.dofs();
  x = X.head(n);
  v = Eigen::VectorXd::Zero(n);
  for (int p = 1; p <= tb.pairs(); ++p) {
    const double phi = tb.k1(p) * theta1 + tb.k2(p) * theta2, w = tb.k1(p) * omega + tb.k2(p) * omega2;
    const auto c = X.segment((2 * p - 1) * n, n), s = X.segment(2 * p * n, n);
    x += std::cos(phi) * c + std::sin(phi) * s;
    v += w * (std::cos(phi) * s - std::sin(phi) * c);
  }
}

TorusStability torus_stability(const TorusBalance& tb, const TorusPoint& p, const TorusStabilityOptions& so) {
  TorusStability r;
  r.computed = true;
  const int n = tb.dofs(), samples = 256;
  // the HB section curve theta1 = 0 in (x, v / omega), its mean point and half-width
  Eigen::MatrixXd curve(2 * n, samples);
  Eigen::VectorXd x, v;
  for (int l = 0; l < samples; ++l) {
    torus_state(tb, p.X, p.omega, p.omega2, 0.0, 2.0 * M_PI * l / samples, x, v);
    curve.col(l) << x, v / p.omega;
  }
  const Eigen::VectorXd mean = curve.rowwise().mean();
  const double width = (curve.colwise() - mean).cwiseAbs().maxCoeff();
  double drift = 0.0;
  auto section = [&](const Eigen::VectorXd& xk, const Eigen::VectorXd& vk) {
    Eigen::VectorXd S(2 * n);
    S << xk, vk / p.omega;
    drift = std::max(drift, (curve.colwise() - S).cwiseAbs().colwise().maxCoeff().minCoeff());
  };
  torus_state(tb, p.X, p.omega, p.omega2, 0.0, 0.0, x, v);
  try {
    const TimeIntegrator ti(tb.model());
    Eigen::MatrixXd logs;
    const std::vector<double> l = lyapunov_exponents(ti, x, v, p.omega, so.periods, 2, so.integration, nullptr,
                                                     nullptr, section, &logs);
    r.lyapunov1 = l[0], r.lyapunov2 = l[1];
    const int h = so.periods / 2;   // the two halves' estimates
    r.half1 = logs.topRows(h).colwise().mean().transpose();
    r.half2 = logs.bottomRows(so.periods - h).colwise().mean().transpose();
  } catch (const std::runtime_error& e) {
    r.failure = e.what();
    return r;
  }
  r.drift = width > 0.0 ? drift / width : INFINITY;
  using V = TorusStability::Verdict;
  const double t = so.threshold;
  if (r.half1[0] > t && r.half2[0] > t) r.verdict = V::unstable;
  else if (std::max(r.half1[0], r.half2[0]) <= t && std::max(r.half1[1], r.half2[1]) < -t && r.drift <= so.drift_tol)
    r.verdict = V::stable;
  else r.verdict = V::unresolved;
  return r;
}

void add_torus_stability(const TorusBalance& tb, TorusBranch& b, const TorusStabilityOptions& so) {
  if (so.every <= 0) return;
  for (std::size_t i = 0; i < b.points.size(); ++i)
    if (i % std::size_t(so.every) == 0 || i + 1 == b.points.size())
      b.points[i].stability = torus_stability(tb, b.points[i], so);
}

void add_torus_starts(std::vector<int>& starts, const std::vector<TorusBranch>& br, int first_id) {
  for (std::size_t k = 0; k < br.size(); ++k)
    if (!br[k].points.empty() && br[k].from < starts.size()) starts[br[k].from] = first_id + int(k);
}

std::string check_torus_options(const TorusOptions& to, int H, std::string* why) {
  auto bad = [&](const char* key, const std::string& w) {
    if (why) *why = w;
    return std::string(key);
  };
  if (to.harmonics1 < 1 || to.harmonics1 > H) return bad("harmonics1", "must be 1.." + std::to_string(H) + " (the model's harmonics)");
  if (to.harmonics2 < 1 || to.harmonics2 > 20) return bad("harmonics2", "must be 1..20");
  if (to.lines != 0 && (to.lines < 2 * to.harmonics2 + 1 || to.lines > 1024))
    return bad("lines", "must be 0 (4 (2 harmonics2 + 1)) or 2 harmonics2 + 1..1024");
  if (!(to.amplitude > 0.0 && to.amplitude <= 0.5)) return bad("amplitude", "must be in (0, 0.5]");
  if (to.max_points < 2 || to.max_points > 10000) return bad("max_points", "must be 2..10000");
  return "";
}

namespace {

// The continuation of one torus branch in the scaled unknowns Y = [X / xs, omega2 / ws, omega / ws].
class TorusContinuation {
 public:
  TorusContinuation(const TorusBalance& tb, const Scaling& s, const TorusOptions& to)
      : tb_(tb), N_(tb.size()), xs_(s.x.maxCoeff()), ws_(s.omega), rs_(s.residual), to_(to) {}
  int size() const { return N_ + 2; }
  Eigen::VectorXd scaled(const Eigen::VectorXd& X, double omega2, double omega) const {
    Eigen::VectorXd Y(N_ + 2);
    Y << X / xs_, omega2 / ws_, omega / ws_;
    return Y;
  }
  TorusPoint point(const Eigen::VectorXd& Y, int iterations, double residual) const {
    return {Y[N_ + 1] * ws_, Y[N_] * ws_, Y.head(N_) * xs_, iterations, residual, {}};
  }
  // Newton on [R = 0; phase; row' Y = b]; false if it does not converge.
  bool correct(Eigen::VectorXd& Y, const Eigen::VectorXd& row, double b, int& iterations, double& residual) const {
    const Eigen::VectorXd phase = tb_.theta2_derivative(Y.head(N_));
    Eigen::VectorXd R, dw, dw2;
    Eigen::MatrixXd J;
    double step = INFINITY;
    for (iterations = 0; iterations <= to_.max_iterations; ++iterations) {
      tb_.evaluate(Y.head(N_) * xs_, Y[N_ + 1] * ws_, Y[N_] * ws_, R, &J, &dw, &dw2);
      Eigen::VectorXd E(N_ + 2);
      E << R / rs_, phase.dot(Y.head(N_)), row.dot(Y) - b;
      residual = E.head(N_).cwiseAbs().maxCoeff();
      if (!std::isfinite(residual)) return false;
      if (residual <= to_.tolerance && step <= 1e-6) return true;
      Eigen::MatrixXd A(N_ + 2, N_ + 2);
      A.topLeftCorner(N_, N_) = J * (xs_ / rs_);
      A.block(0, N_, N_, 1) = dw2 * (ws_ / rs_);
      A.block(0, N_ + 1, N_, 1) = dw * (ws_ / rs_);
      A.row(N_).setZero();
      A.row(N_).head(N_) = phase.transpose();
      A.row(N_ + 1) = row.transpose();
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
      const Eigen::VectorXd d = lu.solve(E);
      if (!d.allFinite()) return false;
      Y -= d;
      step = d.cwiseAbs().maxCoeff();
      if (step > 1.0) return false;   // a step the size of the solution: diverging
    }
    return false;
  }
  double qp_size(const Eigen::VectorXd& Y) const { return tb_.quasi_periodic_part(Y.head(N_)).norm(); }

 private:
  const TorusBalance& tb_;
  int N_;
  double xs_, ws_, rs_;
  const TorusOptions& to_;
};

// The NS point corrected onto hb's branch, its Floquet result and the torus' first-order
// shape E (unit norm in scaled units) with alpha (steps 1-3 of the header).
struct NsStart {
  Eigen::VectorXd X1;   // period-1 HB point at omega
  double omega = 0.0, alpha = 0.0;
  Eigen::VectorXd shape;   // on tb's basis
};

NsStart ns_start(const TorusBalance& tb, const FrequencyCurve& c, const Bifurcation& bf) {
  const HarmonicBalance& hb = tb.model();
  const auto& P = c.branch.points;
  const int a = std::clamp(bf.after_point, 0, int(P.size()) - 2);
  NsStart s;
  s.omega = bf.omega;
  const double t = (bf.omega - P[a].omega) / (P[a + 1].omega - P[a].omega);
  s.X1 = P[a].X + (std::isfinite(t) ? t : 0.0) * (P[a + 1].X - P[a].X);
  const NewtonReport nr = newton_solve(hb, s.X1, s.omega, c.scaling);
  if (!nr.converged) throw std::runtime_error("the NS point did not correct onto the period-1 branch: " + nr.message);
  const double xs = c.scaling.x.maxCoeff();
  const FloquetResult fr = floquet_of_hb_orbit(hb, s.X1, s.omega, xs);
  if (!fr.corrected) throw std::runtime_error("the shooting correction of the NS orbit did not converge");
  const Eigen::EigenSolver<Eigen::MatrixXd> es(fr.monodromy);
  int best = -1;
  for (int i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> mu = es.eigenvalues()[i];
    if (mu.imag() <= 1e-9) continue;
    if (best < 0 || std::abs(std::abs(mu) - 1.0) < std::abs(std::abs(es.eigenvalues()[best]) - 1.0)) best = i;
  }
  if (best < 0) throw std::runtime_error("no complex multiplier at the NS point");
  s.alpha = std::arg(es.eigenvalues()[best]);
  const Eigen::VectorXcd e = es.eigenvectors().col(best);
  // The eigen-solution over one period by central differences of the exact flow.
  const int n = hb.dofs(), N = 4 * (2 * tb.harmonics1() + 1) + 64;
  const double T = 2.0 * M_PI / s.omega, delta = 1e-6 * xs;
  std::vector<double> nodes(N);
  for (int j = 0; j < N; ++j) nodes[j] = T * j / N;
  const PiecewiseLinearFlow flow(hb);
  const double escale = std::max(e.head(n).cwiseAbs().maxCoeff(), e.tail(n).cwiseAbs().maxCoeff() / s.omega);
  auto eigen_part = [&](const Eigen::VectorXd& d) {
    Eigen::VectorXd xT, vT;
    Eigen::MatrixXd Phi, xp, xm;
    flow.period_map(fr.x0 + delta * d.head(n), fr.v0 + delta * d.tail(n), s.omega, nodes, xT, vT, Phi, &xp);
    flow.period_map(fr.x0 - delta * d.head(n), fr.v0 - delta * d.tail(n), s.omega, nodes, xT, vT, Phi, &xm);
    return Eigen::MatrixXd((xp - xm) / (2.0 * delta));
  };
  const Eigen::MatrixXd dr = eigen_part(e.real() / escale), di = eigen_part(e.imag() / escale);
  // p(t) = exp(-i alpha t / T) dx(t), its coefficients c_m, m = -H1..H1, then Re(exp(i theta2) p).
  const int H1 = tb.harmonics1(), H2 = tb.harmonics2();
  s.shape = Eigen::VectorXd::Zero(tb.size());
  for (int m = -H1; m <= H1; ++m) {
    Eigen::VectorXcd cm = Eigen::VectorXcd::Zero(n);
    for (int j = 0; j < N; ++j) {
      const std::complex<double> rot = std::polar(1.0, -s.alpha * j / N - 2.0 * M_PI * m * j / N);
      cm += rot * (dr.col(j).cast<std::complex<double>>() + std::complex<double>(0, 1) * di.col(j)) / double(N);
    }
    const int k = std::abs(m), k2 = m >= 0 ? 1 : -1;
    const int p = k == 0 ? 1 : H2 + (k - 1) * (2 * H2 + 1) + k2 + H2 + 1;
    s.shape.segment((2 * p - 1) * n, n) += cm.real();
    s.shape.segment(2 * p * n, n) += (m >= 0 ? -1.0 : 1.0) * cm.imag();
  }
  s.shape /= s.shape.norm();
  return s;
}

// Step 4 of the header: the first two points, at amplitudes eps and 2 eps along the shape
// (omega and omega2 free, the amplitude held), appended to out.points; their scaled unknowns.
std::vector<Eigen::VectorXd> first_points(const TorusContinuation& tc, const NsStart& s, const Eigen::VectorXd& Yns,
                                          double amplitude, TorusBranch& out) {
  const int N = int(s.shape.size());
  const double eps = amplitude * Yns.head(N).norm();
  Eigen::VectorXd row = Eigen::VectorXd::Zero(N + 2);
  row.head(N) = s.shape;
  std::vector<Eigen::VectorXd> Ys;
  for (double a : {eps, 2.0 * eps}) {
    Eigen::VectorXd Y = Ys.empty() ? Yns : Ys.back();
    Y.head(N) += (a - row.dot(Y - Yns)) * s.shape;
    int it = 0;
    double res = 0.0;
    if (!tc.correct(Y, row, row.dot(Yns) + a, it, res))
      throw std::runtime_error("the first torus points (amplitude held at " + number(a / Yns.head(N).norm()) +
                               " of the orbit's size) did not converge");
    Ys.push_back(Y);
    out.points.push_back(tc.point(Y, it, res));
  }
  return Ys;
}

// first_points at amplitude, else at amplitude / 5 and / 25 (step 4 of the header: near a
// grazing NS point the first-order shape holds only at amplitudes of the orbit's penetration).
std::vector<Eigen::VectorXd> first_points_retried(const TorusContinuation& tc, const NsStart& s,
                                                  const Eigen::VectorXd& Yns, double amplitude, TorusBranch& out) {
  std::string first;
  for (int k = 0; k < 3; ++k) {
    try {
      return first_points(tc, s, Yns, amplitude / std::pow(5.0, k), out);
    } catch (const std::runtime_error& e) {
      out.points.clear();
      if (k == 0) first = e.what();
    }
  }
  throw std::runtime_error(first + ", nor at a fifth and a 25th of that");
}

// Steps 4-5: the pseudo-arc-length continuation from the first two points until the branch
// ends (out.end, out.why).
void continue_torus(const TorusContinuation& tc, std::vector<Eigen::VectorXd> Ys, const SweepOptions& opt,
                    const TorusOptions& to, const std::string& where, TorusBranch& out) {
  const double qp_first = tc.qp_size(Ys[0]);
  double qp_max = tc.qp_size(Ys[1]);
  double ds = (Ys[1] - Ys[0]).norm();
  auto stop = [&](TorusBranch::End end, const std::string& why) {
    out.end = end;
    out.why = where + why;
  };
  while (true) {
    if (int(out.points.size()) >= to.max_points)
      return stop(TorusBranch::End::max_points, "stopped after max_points = " + std::to_string(to.max_points) + " points");
    const Eigen::VectorXd& Y1 = Ys.back();
    const Eigen::VectorXd t = (Y1 - Ys[Ys.size() - 2]).normalized();
    Eigen::VectorXd Y = Y1 + ds * t;
    int it = 0;
    double res = 0.0;
    // a corrector that moves the point farther than half the step from the predictor has
    // jumped to another part of the solution set: refused like a failed corrector
    const Eigen::VectorXd predicted = Y;
    const bool converged = tc.correct(Y, t, t.dot(Y1) + ds, it, res);
    if (!converged || (Y - predicted).norm() > 0.5 * ds) {
      ds /= 2.0;
      if (ds >= to.ds_min) continue;
      return stop(TorusBranch::End::failed, "failed at omega = " + number(out.points.back().omega) +
                                                ": the corrector did not converge with ds below ds_min (the torus "
                                                "breaks down or locks)");
    }
    Ys.push_back(Y);
    out.points.push_back(tc.point(Y, it, res));
    if (it <= 4) ds = std::min(1.5 * ds, to.ds_max);
    const double w = out.points.back().omega;
    if (w < opt.omega_min || w > opt.omega_max) return stop(TorusBranch::End::left_range, "left the range at omega = " + number(w));
    qp_max = std::max(qp_max, tc.qp_size(Y));
    if (tc.qp_size(Y) < std::max(0.25 * qp_first, 0.1 * qp_max))
      return stop(TorusBranch::End::merged, "shrank onto the period-1 orbit at omega = " + number(w));
    if (out.points.back().omega2 <= 0.0) return stop(TorusBranch::End::failed, "omega2 reached 0 at omega = " + number(w));
  }
}

}  // namespace

TorusBranch torus_branch(const TorusBalance& tb, const FrequencyCurve& c, std::size_t index, const SweepOptions& opt,
                         const TorusOptions& to) {
  TorusBranch out;
  out.from = index;
  const Bifurcation& bf = c.bifurcations.at(index);
  out.omega_ns = bf.omega;
  const std::string where = "torus branch from the NS point at omega = " + number(bf.omega) + ": ";
  try {
    const NsStart s = ns_start(tb, c, bf);
    out.alpha = s.alpha;
    out.omega2_ns = s.alpha * s.omega / (2.0 * M_PI);
    const TorusContinuation tc(tb, c.scaling, to);
    const Eigen::VectorXd Yns = tc.scaled(tb.from_periodic(s.X1), out.omega2_ns, s.omega);
    continue_torus(tc, first_points_retried(tc, s, Yns, to.amplitude, out), opt, to, where, out);
  } catch (const std::exception& e) {
    out.end = TorusBranch::End::failed;
    out.why = where + "failed: " + e.what();
  }
  if (!out.points.empty()) out.omega_end = out.points.back().omega;
  return out;
}

TorusPoint torus_point_at(const TorusBalance& tb, const TorusPoint& guess, double omega, const Scaling& s,
                          const TorusOptions& to) {
  const TorusContinuation tc(tb, s, to);
  Eigen::VectorXd Y = tc.scaled(guess.X, guess.omega2, omega);
  Eigen::VectorXd row = Eigen::VectorXd::Zero(tc.size());
  row[tc.size() - 1] = 1.0;
  int it = 0;
  double res = 0.0;
  if (!tc.correct(Y, row, Y[tc.size() - 1], it, res))
    throw std::runtime_error("the torus at omega = " + number(omega) + " did not converge from the point at " +
                             number(guess.omega));
  return tc.point(Y, it, res);
}

std::vector<TorusBranch> torus_branches(const TorusBalance& tb, const FrequencyCurve& c, const SweepOptions& opt,
                                        const TorusOptions& to) {
  std::vector<TorusBranch> out;
  std::vector<bool> reached(c.bifurcations.size(), false);
  auto ns = [&](std::size_t i) {
    const Bifurcation& bf = c.bifurcations[i];
    return bf.type == BifurcationType::neimark_sacker && bf.located && bf.smooth;
  };
  for (std::size_t i = 0; i < c.bifurcations.size(); ++i) {
    if (!ns(i) || reached[i]) continue;
    TorusBranch b = torus_branch(tb, c, i, opt, to);
    // merged at the NS point nearest its end, if that is not its own
    if (b.end == TorusBranch::End::merged)
      for (std::size_t j = 0; j < c.bifurcations.size(); ++j)
        if (j != i && ns(j) && std::abs(c.bifurcations[j].omega - b.omega_end) < std::abs(b.omega_ns - b.omega_end) &&
            (b.to < 0 || std::abs(c.bifurcations[j].omega - b.omega_end) <
                             std::abs(c.bifurcations[std::size_t(b.to)].omega - b.omega_end)))
          b.to = int(j);
    if (b.to >= 0) {
      reached[std::size_t(b.to)] = true;
      b.why += " (merged at the NS point at omega = " + number(c.bifurcations[std::size_t(b.to)].omega) + ")";
    }
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace gearhb
