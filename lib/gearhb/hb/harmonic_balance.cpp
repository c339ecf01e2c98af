#include "gearhb/hb/harmonic_balance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gearhb {

HarmonicBalance::HarmonicBalance(LinearSystem sys, std::vector<UnilateralContact> contacts,
                                 Excitation f, int H, int N, ContactQuadrature quadrature)
    : sys_(std::move(sys)), contacts_(std::move(contacts)), f_(std::move(f)),
      n_(sys_.dofs()), H_(H), aft_(H, N), quad_(quadrature) {
  sys_.check();
  if (H < 1) throw std::invalid_argument("HarmonicBalance: H must be >= 1");
  auto vec = [&](Eigen::VectorXd& v, const char* name) {
    if (v.size() == 0) v = Eigen::VectorXd::Zero(n_);
    if (v.size() != n_) throw std::invalid_argument(std::string("HarmonicBalance: ") + name + " has wrong size");
  };
  vec(f_.f0, "f0");
  vec(f_.fc, "fc");
  vec(f_.fs, "fs");
  for (auto& c : contacts_) {
    if (c.normal.size() != n_) throw std::invalid_argument("HarmonicBalance: contact normal has wrong size");
    if (!(c.kc >= 0.0)) throw std::invalid_argument("HarmonicBalance: contact stiffness must be >= 0");
    if (c.gap_harmonics.size() == 0) c.gap_harmonics = Eigen::VectorXd::Zero(2 * H_ + 1);
    if (c.gap_harmonics.size() < 2 * H_ + 1) {
      // A shorter gap series is padded with zeros (its higher harmonics vanish).
      Eigen::VectorXd g = Eigen::VectorXd::Zero(2 * H_ + 1);
      g.head(c.gap_harmonics.size()) = c.gap_harmonics;
      c.gap_harmonics = g;
    }
    if (c.gap_harmonics.size() > 2 * H_ + 1)
      c.gap_harmonics.conservativeResize(2 * H_ + 1);   // truncated to the H retained
    // Mean stiffness over the period (trapezoid rule on 1024 phases, spectrally
    // accurate for a smooth periodic profile); the profile must stay positive.
    double mean = c.kc;
    if (c.stiffness_profile) {
      const int S = 1024;
      double sum = 0.0;
      for (int j = 0; j < S; ++j) {
        const double s = c.stiffness_profile(2.0 * M_PI * j / S);
        if (!(s > 0.0) || !std::isfinite(s))
          throw std::invalid_argument("HarmonicBalance: contact stiffness profile must be finite and > 0");
        sum += s;
      }
      mean = c.kc * sum / S;
    }
    kc_mean_.push_back(mean);
  }
  const int N_ = aft_.samples(), m = 2 * H_ + 1;
  uc_.resize(m); us_.resize(N_); fs_.resize(N_); ss_.resize(N_); fcoef_.resize(m);
  G_.resize(m, m);
  mc_.resize(2 * m); ms_.resize(2 * m);
}

void HarmonicBalance::evaluate(const Eigen::VectorXd& X, double w, Eigen::VectorXd& R,
                               Eigen::MatrixXd* J, Eigen::VectorXd* dRdw) const {
  const int n = n_, m = 2 * H_ + 1, N = aft_.samples();
  R.resize(size());
  const auto& M = sys_.M;
  const auto& C = sys_.C;
  const auto& K = sys_.K;
  // --- linear part -------------------------------------------------------
  R.segment(0, n) = K * X.segment(0, n) - f_.f0;
  for (int k = 1; k <= H_; ++k) {
    const double kw = k * w;
    const auto c = X.segment(index(2 * k - 1, 0), n);
    const auto s = X.segment(index(2 * k, 0), n);
    R.segment(index(2 * k - 1, 0), n) = K * c - kw * kw * (M * c) + kw * (C * s);
    R.segment(index(2 * k, 0), n) = K * s - kw * kw * (M * s) - kw * (C * c);
  }
  R.segment(index(1, 0), n) -= f_.fc;
  R.segment(index(2, 0), n) -= f_.fs;
  if (J) {
    J->setZero(size(), size());
    J->block(0, 0, n, n) = K;
    for (int k = 1; k <= H_; ++k) {
      const double kw = k * w;
      const int ic = index(2 * k - 1, 0), is = index(2 * k, 0);
      const Eigen::MatrixXd D = K - kw * kw * M;
      J->block(ic, ic, n, n) = D;
      J->block(ic, is, n, n) = kw * C;
      J->block(is, is, n, n) = D;
      J->block(is, ic, n, n) = -kw * C;
    }
  }
  if (dRdw) {
    dRdw->setZero(size());
    for (int k = 1; k <= H_; ++k) {
      const auto c = X.segment(index(2 * k - 1, 0), n);
      const auto s = X.segment(index(2 * k, 0), n);
      dRdw->segment(index(2 * k - 1, 0), n) = -2.0 * k * k * w * (M * c) + k * (C * s);
      dRdw->segment(index(2 * k, 0), n) = -2.0 * k * k * w * (M * s) - k * (C * c);
    }
  }
  // --- contacts by AFT ------------------------------------------------------
  for (const auto& ct : contacts_) {
    // u(theta) = g(theta) + n' x(theta): coefficients, then samples.
    for (int a = 0; a < m; ++a) uc_[a] = ct.normal.dot(X.segment(a * n, n)) + ct.gap_harmonics[a];
    uc_[0] += ct.gap;
    aft_.to_time(uc_.data(), us_.data());
    if (quad_ == ContactQuadrature::exact) {
      // the moments of the indicator of the contact intervals, weighted by the
      // stiffness profile if any (pieces of at most one sample spacing)
      if (ct.stiffness_profile)
        weighted_indicator_moments(contact_intervals(uc_, us_), ct.stiffness_profile, 2 * H_, 2.0 * M_PI / N,
                                   mc_.data(), ms_.data());
      else
        indicator_moments(contact_intervals(uc_, us_), 2 * H_, mc_.data(), ms_.data());
      aft_.product_matrix_from_moments(mc_.data(), ms_.data(), G_);
      G_ *= ct.kc;
      fcoef_.noalias() = G_ * uc_;
    } else {
      for (int j = 0; j < N; ++j) {
        const double k = stiffness_at(ct, 2.0 * M_PI * j / N);
        fs_[j] = contact_force(k, us_[j]);
        ss_[j] = contact_stiffness(k, us_[j]);
      }
      aft_.to_frequency(fs_.data(), fcoef_.data());
      if (J) aft_.product_matrix(ss_.data(), G_);
    }
    for (int a = 0; a < m; ++a) R.segment(a * n, n) += fcoef_[a] * ct.normal;
    if (J) {
      const Eigen::MatrixXd nn = ct.normal * ct.normal.transpose();
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b)
          if (G_(a, b) != 0.0) J->block(a * n, b * n, n, n) += G_(a, b) * nn;
    }
  }
}

Eigen::VectorXd HarmonicBalance::project(const Eigen::VectorXd& X, const Eigen::VectorXd& q) const {
  Eigen::VectorXd c(2 * H_ + 1);
  for (int a = 0; a < 2 * H_ + 1; ++a) c[a] = q.dot(X.segment(a * n_, n_));
  return c;
}

Eigen::VectorXd HarmonicBalance::penetration(const Eigen::VectorXd& X, std::size_t i) const {
  const auto& ct = contacts_.at(i);
  Eigen::VectorXd u = project(X, ct.normal) + ct.gap_harmonics;
  u[0] += ct.gap;
  return u;
}

Eigen::VectorXd HarmonicBalance::linear_solution(double w, bool closed) const {
  Eigen::MatrixXd K = sys_.K;
  Eigen::VectorXd f0 = f_.f0;
  if (closed)
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
      const auto& ct = contacts_[i];
      // a stiffness profile enters with its mean (then this is a first guess only)
      K += kc_mean_[i] * ct.normal * ct.normal.transpose();
      f0 -= kc_mean_[i] * ct.gap * ct.normal;   // constant part of kc (g + n'x) moved to the right
    }
  Eigen::VectorXd X = Eigen::VectorXd::Zero(size());
  // K singular (a free rigid-body mode, e.g. gears with rigid shafts and the mesh
  // open) under a static load that K cannot hold: no static equilibrium, the
  // static part is NaN (linear_first_guess then skips this solution).
  Eigen::VectorXd X0 = K.partialPivLu().solve(f0);
  if (!X0.allFinite() || (K * X0 - f0).norm() > 1e-8 * f0.norm()) X0.setConstant(NAN);
  X.segment(0, n_) = X0;
  LinearSystem s{sys_.M, sys_.C, K};
  const std::complex<double> i(0.0, 1.0);
  // fc cos + fs sin = Re((fc - i fs) e^{i theta})
  const Eigen::VectorXcd F = f_.fc.cast<std::complex<double>>() - i * f_.fs.cast<std::complex<double>>();
  const Eigen::VectorXcd Z = frequency_response(s, F, w);
  X.segment(index(1, 0), n_) = Z.real();
  X.segment(index(2, 0), n_) = -Z.imag();
  return X;
}

Eigen::VectorXd HarmonicBalance::open_contact_solution(double w) const { return linear_solution(w, false); }
Eigen::VectorXd HarmonicBalance::closed_contact_solution(double w) const { return linear_solution(w, true); }

Scaling HarmonicBalance::scaling(double wmin, double wmax) const {
  // The oscillating part of a gap (a transmission error) forces the system as a
  // displacement does; a constant gap, like a static offset, only counts when
  // nothing oscillates.
  double xref = 0.0, xstatic = 0.0;
  for (const auto& ct : contacts_) {
    const double wn = ct.normal.lpNorm<Eigen::Infinity>();
    if (wn > 0) {
      xref = std::max(xref, ct.gap_harmonics.cwiseAbs().sum() / wn);
      xstatic = std::max(xstatic, std::fabs(ct.gap) / wn);
    }
  }
  // Linear response amplitudes (open and closed) over a fine scan of the range.
  // Only the oscillating part sets the scale: the solvers see differences of X
  // (arc length, Newton steps), and along a frequency sweep the static offset
  // changes by no more than the oscillation does. A large static offset (a gear
  // pair under torque: 1e-2 rad of twist beside 1e-5 of vibration) must not
  // swamp the resonance peaks in the arc length.
  const int scan = 400;
  for (int i = 0; i <= scan; ++i) {
    const double w = wmin + (wmax - wmin) * i / scan;
    for (bool closed : {false, true}) {
      if (closed && contacts_.empty()) continue;
      const Eigen::VectorXd X = linear_solution(w, closed);
      for (int d = 0; d < n_; ++d) {
        const double a = std::hypot(X[index(1, d)], X[index(2, d)]);
        if (std::isfinite(a)) xref = std::max(xref, a);
        if (std::isfinite(X[d])) xstatic = std::max(xstatic, std::fabs(X[d]));   // NaN: no static equilibrium
      }
    }
  }
  if (!(xref > 0.0)) xref = xstatic;  // no oscillating input: the static size
  if (!(xref > 0.0)) xref = 1.0;      // nothing forces the system: any unit will do
  double kref = sys_.K.diagonal().cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < contacts_.size(); ++i) kref += kc_mean_[i] * contacts_[i].normal.squaredNorm();
  Scaling s;
  s.x = Eigen::VectorXd::Constant(size(), xref);
  s.omega = std::max(std::fabs(wmax), std::fabs(wmin));
  s.residual = kref * xref;
  return s;
}

}  // namespace gearhb
