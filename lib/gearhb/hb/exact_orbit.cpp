#include "gearhb/hb/exact_orbit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <stdexcept>
#include <string>

namespace gearhb {

namespace {

// The 8-point Gauss-Legendre rule on [-1, 1] (nodes +-x_j, weights w_j; Abramowitz & Stegun
// table 25.4): exact for polynomials of degree 15, so on a piece with |lambda| h <= 1 (and
// <= 2 for a product of two coordinates) its error is below 1e-16 of the integrand.
constexpr std::array<double, 4> kGaussX{0.1834346424956498049, 0.5255324099163289858, 0.7966664774136267396,
                                        0.9602898564975362317};
constexpr std::array<double, 4> kGaussW{0.3626837833783619830, 0.3137066458778872873, 0.2223810344533744706,
                                        0.1012285362903762591};

// The rule's nodes on [0, 1], ascending, and their weights.
std::array<std::pair<double, double>, 8> unit_rule() {
  std::array<std::pair<double, double>, 8> r;
  for (int j = 0; j < 4; ++j) {
    r[3 - j] = {0.5 * (1.0 - kGaussX[j]), 0.5 * kGaussW[j]};
    r[4 + j] = {0.5 * (1.0 + kGaussX[j]), 0.5 * kGaussW[j]};
  }
  return r;
}

// The most sub-pieces of one piece (the rule is then no longer exact; a piece needs more only
// for a fast mode that the damping does not remove).
constexpr int kMaxSubPieces = 1000;

// A mode with Re lambda s below this has decayed under the rounding of the state a time s into
// a piece: its part of z is at most cond(V) |z| e^{Re lambda s}, cond(V) <= 1e4 for a
// diagonalised propagator (floquet.hpp), and ln(2.2e-16 / 1e4) = -45.2.
constexpr double kModeGone = -45.2;

// The longest sub-piece starting a time `a` into a piece with modes `lambda` (the eigenvalues
// of a diagonalised propagator). The 8-point rule's error on e^{lambda s} over [a, a + h']
// scales as |e^{lambda a}| (|lambda| h')^16 (the Gauss-Legendre remainder holds the 16th
// derivative, lambda^16 e^{lambda s}); keeping it at most that of h' |lambda| = 1 at a = 0
// (the rule's exact case) allows h' = e^{-Re lambda a / 16} / |lambda|: a damped mode lets the
// sub-pieces grow as it decays, and a mode gone (kModeGone) no longer limits them.
double sub_piece(const Eigen::VectorXcd& lambda, double a) {
  double h = INFINITY;
  for (Eigen::Index j = 0; j < lambda.size(); ++j) {
    const double re = lambda[j].real(), size = std::abs(lambda[j]);
    if (re * a > kModeGone && size > 0.0) h = std::min(h, std::exp(-re * a / 16.0) / size);
  }
  return h;
}

// The starts (offsets in [0, h), 0 first) of the sub-pieces of a piece of length h whose
// propagator is diagonalised, each as long as sub_piece allows. A heavily damped mode
// (Rayleigh beta = 1 s on a gear's supports: lambda = -beta omega_n^2 ~ -1e9/s) costs the ~17
// sub-pieces in which it decays, not h |lambda| ~ 1e5 of them. If more than kMaxSubPieces are
// needed (a fast mode that does not decay), kMaxSubPieces equal ones.
std::vector<double> sub_piece_starts(const Eigen::VectorXcd& lambda, double h) {
  std::vector<double> starts{0.0};
  for (double a = 0.0; int(starts.size()) < kMaxSubPieces;) {
    a += sub_piece(lambda, a);
    if (!(a < h)) return starts;
    starts.push_back(a);
  }
  starts.clear();
  for (int j = 0; j < kMaxSubPieces; ++j) starts.push_back(h * j / kMaxSubPieces);
  return starts;
}

}  // namespace

ExactOrbit::ExactOrbit(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega, const Eigen::VectorXd& x0,
                       const Eigen::VectorXd& v0, int steps)
    : flow_(hb), omega_(omega), T_(2.0 * M_PI / omega), n_(hb.dofs()) {
  if (!(std::isfinite(T_) && T_ > 0.0 && x0.allFinite() && v0.allFinite()))
    throw std::runtime_error("ExactOrbit: no finite period or state at omega = " + std::to_string(omega));
  // 1. the orbit piece by piece on the exact flow
  std::vector<FlowSegment> segments;
  Eigen::VectorXd xT, vT;
  flow_.follow(x0, v0, omega, shooting_nodes(hb, X, omega, steps), xT, vT, segments);
  // 2. sub-pieces with h x rate <= 1, and the quadrature nodes on them
  split_into_pieces(segments);
  if (pieces_.empty()) throw std::runtime_error("ExactOrbit: no piece of the orbit at omega = " + std::to_string(omega));
  place_nodes();
  if (!z_.allFinite()) throw std::runtime_error("ExactOrbit: the orbit is not finite at omega = " + std::to_string(omega));
  // 3. how periodic, and whether every node lies in its piece's contact state
  check(hb, x0, v0, xT, vT);
}

// Step 2a: for a diagonalised propagator sub-pieces that grow as its damped modes decay
// (sub_piece_starts); for a Pade propagator uniform sub-pieces, each started by the map
// exp(A_S h / m), kept per (S, h / m) (the uniform steps share them).
void ExactOrbit::split_into_pieces(const std::vector<FlowSegment>& segments) {
  std::map<std::pair<unsigned, double>, Eigen::MatrixXd> step_maps;
  auto step_of = [&](unsigned S, double h) -> const Eigen::MatrixXd& {
    auto it = step_maps.find({S, h});
    if (it == step_maps.end()) it = step_maps.emplace(std::make_pair(S, h), flow_.exponential(S, omega_, h)).first;
    return it->second;
  };
  for (const auto& sg : segments) {
    if (flow_.spectral(sg.state, omega_)) {
      const std::vector<double> s = sub_piece_starts(flow_.eigenvalues(sg.state, omega_), sg.h);
      for (std::size_t j = 0; j < s.size(); ++j) {
        const double end = j + 1 < s.size() ? s[j + 1] : sg.h;
        pieces_.push_back({sg.t0 + s[j], end - s[j], sg.state, j == 0 ? sg.z0 : flow_.advance(sg.state, omega_, s[j], sg.z0)});
      }
      continue;
    }
    const int m = std::clamp(int(std::ceil(sg.h * flow_.rate(sg.state, omega_))), 1, kMaxSubPieces);
    Eigen::VectorXd z = sg.z0;
    for (int j = 0; j < m; ++j) {
      if (j > 0) z = step_of(sg.state, sg.h / m) * z;
      pieces_.push_back({sg.t0 + sg.h * j / m, sg.h / m, sg.state, z});
    }
  }
}

// Step 2b: the state at the Gauss nodes of every piece: a diagonalised propagator gives all
// nodes of a piece in one product V (e^{lambda s_j} o V^-1 z0); a Pade one the maps
// exp(A_S x_j h), kept per (S, h). The oscillator rows [1, cos k omega t, sin k omega t] in
// closed form.
void ExactOrbit::place_nodes() {
  const auto rule = unit_rule();
  std::map<std::pair<unsigned, double>, std::vector<Eigen::MatrixXd>> maps;
  auto maps_of = [&](unsigned S, double h) -> const std::vector<Eigen::MatrixXd>& {
    auto it = maps.find({S, h});
    if (it != maps.end()) return it->second;
    std::vector<Eigen::MatrixXd> E;
    for (const auto& node : rule) E.push_back(flow_.exponential(S, omega_, node.first * h).topRows(2 * n_));
    return maps.emplace(std::make_pair(S, h), std::move(E)).first->second;
  };
  const Eigen::Index R = Eigen::Index(rule.size()), N = Eigen::Index(pieces_.size()) * R;
  z_.resize(flow_.dimension(), N);
  t_.resize(N);
  w_.resize(N);
  Eigen::VectorXd s(R);
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const Piece& p = pieces_[k];
    const Eigen::Index c0 = Eigen::Index(k) * R;
    for (Eigen::Index j = 0; j < R; ++j) {
      s[j] = rule[std::size_t(j)].first * p.h;
      t_[c0 + j] = p.t0 + s[j];
      w_[c0 + j] = rule[std::size_t(j)].second * p.h;
      state_.push_back(p.state);
    }
    if (flow_.spectral(p.state, omega_)) {
      z_.block(0, c0, 2 * n_, R) = flow_.advance_xv(p.state, omega_, s, p.z0);
    } else {
      const auto& E = maps_of(p.state, p.h);
      for (Eigen::Index j = 0; j < R; ++j) z_.block(0, c0 + j, 2 * n_, 1).noalias() = E[std::size_t(j)] * p.z0;
    }
  }
  const auto& harmonics = flow_.oscillator_harmonics();
  z_.row(2 * n_).setOnes();
  for (std::size_t j = 0; j < harmonics.size(); ++j) {
    const Eigen::ArrayXd th = harmonics[j] * omega_ * t_.array();
    z_.row(2 * n_ + 1 + 2 * Eigen::Index(j)) = th.cos().matrix().transpose();
    z_.row(2 * n_ + 2 + 2 * Eigen::Index(j)) = th.sin().matrix().transpose();
  }
}

// Step 3: the period mismatch (scaled as the shooting residual: displacements by max |x|,
// velocities by omega max |x|) and whether every node's penetration has its piece's sign.
void ExactOrbit::check(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                       const Eigen::VectorXd& xT, const Eigen::VectorXd& vT) {
  const double xs = z_.topRows(n_).cwiseAbs().maxCoeff();
  // scaled as the shooting residual: displacements by max |x|, velocities by omega max |x|
  mismatch_ = std::max((xT - x0).cwiseAbs().maxCoeff(), (vT - v0).cwiseAbs().maxCoeff() / omega_) / std::max(xs, 1e-300);
  for (std::size_t i = 0; i < hb.contacts().size(); ++i) {
    double scale = 0.0, wrong = 0.0;
    for (Eigen::Index j = 0; j < z_.cols(); ++j) {
      const double u = flow_.penetration(i, z_.col(j));
      scale = std::max(scale, std::fabs(u));
      const bool closed = state_[std::size_t(j)] >> i & 1u;
      if ((u > 0.0) != closed) wrong = std::max(wrong, std::fabs(u));
    }
    consistent_ = consistent_ && wrong <= 1e-8 * scale;
  }
}

Eigen::VectorXd ExactOrbit::x_at(double t) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t, [](double a, const Piece& p) { return a < p.t0; });
  const Piece& p = it == pieces_.begin() ? pieces_.front() : *std::prev(it);
  return flow_.advance(p.state, omega_, t - p.t0, p.z0).head(n_);
}

// The zero of y' = q' v in (lo, hi) of piece p (y' changes sign there): Newton with
// y'' = q' (A z)_v, kept in the bracket; returns y there.
double ExactOrbit::extremum(const Piece& p, const Eigen::VectorXd& q, double lo, double hi) const {
  const Eigen::MatrixXd& A = flow_.generator_matrix(p.state, omega_);
  auto slope = [&](double s, double& y, double& dy, double& ddy) {
    const Eigen::VectorXd z = flow_.advance(p.state, omega_, s, p.z0);
    y = q.dot(z.head(n_));
    dy = q.dot(z.segment(n_, n_));
    ddy = q.dot(A.middleRows(n_, n_) * z);
  };
  double y = 0.0, dy = 0.0, ddy = 0.0;
  slope(lo, y, dy, ddy);
  const bool rising_lo = dy > 0.0;
  double s = 0.5 * (lo + hi);
  for (int it = 0; it < 60; ++it) {
    slope(s, y, dy, ddy);
    ((dy > 0.0) == rising_lo ? lo : hi) = s;
    double next = s - dy / ddy;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::fabs(next - s) <= 1e-15 * T_ || hi - lo <= 1e-15 * T_;
    s = next;
    if (done) break;
  }
  slope(s, y, dy, ddy);
  return y;
}

ExactMeasures ExactOrbit::measures(const Eigen::VectorXd& q) const {
  const Eigen::VectorXd y = z_.topRows(n_).transpose() * q;
  const Eigen::VectorXd dy = z_.middleRows(n_, n_).transpose() * q;
  ExactMeasures r;
  r.x_mean = w_.dot(y) / T_;
  r.x_rms_ac = std::sqrt(w_.dot((y.array() - r.x_mean).square().matrix()) / T_);
  const double a1 = 2.0 / T_ * w_.dot((y.array() * (omega_ * t_.array()).cos()).matrix());
  const double b1 = 2.0 / T_ * w_.dot((y.array() * (omega_ * t_.array()).sin()).matrix());
  r.x_h1 = std::hypot(a1, b1);
  // extremes: the piece ends, and the zeros of y' bracketed on [start, nodes, end] of each piece
  const std::size_t per = 8;
  double hi = -INFINITY, lo = INFINITY;
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    const Piece& p = pieces_[k];
    const Piece& next = pieces_[(k + 1) % pieces_.size()];
    const double y0 = q.dot(p.z0.head(n_));
    hi = std::max(hi, y0);
    lo = std::min(lo, y0);
    std::vector<std::pair<double, double>> slope{{0.0, q.dot(p.z0.segment(n_, n_))}};
    for (std::size_t j = 0; j < per; ++j) {
      const auto c = Eigen::Index(k * per + j);
      slope.push_back({t_[c] - p.t0, dy[c]});
    }
    slope.push_back({p.h, q.dot(next.z0.segment(n_, n_))});
    for (std::size_t j = 0; j + 1 < slope.size(); ++j) {
      if ((slope[j].second > 0.0) == (slope[j + 1].second > 0.0)) continue;
      if (slope[j].second == 0.0 || slope[j + 1].second == 0.0) continue;   // the node value is the extremum
      const double ye = extremum(p, q, slope[j].first, slope[j + 1].first);
      hi = std::max(hi, ye);
      lo = std::min(lo, ye);
    }
  }
  hi = std::max(hi, y.maxCoeff());
  lo = std::min(lo, y.minCoeff());
  r.x_max = hi;
  r.x_min = lo;
  return r;
}

double ExactOrbit::mean_contact_force(std::size_t i) const {
  if (i >= flow_.contacts())
    throw std::invalid_argument("ExactOrbit::mean_contact_force: no contact " + std::to_string(i));
  double sum = 0.0;
  for (Eigen::Index j = 0; j < z_.cols(); ++j)
    if (state_[std::size_t(j)] >> i & 1u) sum += w_[j] * flow_.penetration(i, z_.col(j));
  return flow_.stiffness(i) * sum / T_;
}

const char* to_string(ExactStatus s) {
  switch (s) {
    case ExactStatus::ok: return "ok";
    case ExactStatus::not_converged: return "not_converged";
    case ExactStatus::inconsistent: return "inconsistent";
    case ExactStatus::unavailable: return "unavailable";
    case ExactStatus::lower_period: return "lower_period";
  }
  return "?";
}

ExactPoint exact_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i,
                       const std::vector<Eigen::VectorXd>& qs) {
  ExactPoint e;
  e.measures.assign(qs.size(), ExactMeasures{});
  bool profile = false;
  for (const auto& ct : hb.contacts()) profile = profile || bool(ct.stiffness_profile);
  if (profile || c.floquet.size() != c.branch.points.size() || i >= c.floquet.size()) return e;
  const PointFloquet& f = c.floquet[i];
  if (!f.corrected) {
    e.status = ExactStatus::not_converged;
    return e;
  }
  if (f.lower_period) {
    e.status = ExactStatus::lower_period;
    return e;
  }
  e.status = ExactStatus::inconsistent;
  try {
    const ExactOrbit o(hb, c.branch.points[i].X, c.branch.points[i].omega, f.x0, f.v0);
    if (!o.consistent()) return e;
    for (std::size_t k = 0; k < qs.size(); ++k) e.measures[k] = o.measures(qs[k]);
    e.status = ExactStatus::ok;
  } catch (const std::runtime_error&) {
    // following the orbit failed (too many contact switches in one step): stays inconsistent
  }
  return e;
}

}  // namespace gearhb
