#include "gearhb/hb/response.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "gearhb/core/fourier.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/hb/stability.hpp"

namespace gearhb {

ResponseEvaluator::ResponseEvaluator(const HarmonicBalance& hb, Eigen::VectorXd q, int fine)
    : hb_(hb), q_(std::move(q)), fine_(hb.harmonics(), std::max(fine, 2 * hb.harmonics() + 2)) {}

Eigen::VectorXd ResponseEvaluator::history(const Eigen::VectorXd& X) const {
  return fine_.to_time(hb_.project(X, q_));
}

Eigen::VectorXd ResponseEvaluator::contact_force_history(const Eigen::VectorXd& X, std::size_t i) const {
  const auto& ct = hb_.contacts().at(i);
  const Eigen::VectorXd u = fine_.to_time(hb_.penetration(X, i));
  Eigen::VectorXd f(u.size());
  for (Eigen::Index j = 0; j < u.size(); ++j)
    f[j] = contact_force(stiffness_at(ct, 2.0 * M_PI * double(j) / double(u.size())), u[j]);
  return f;
}

double mean_contact_force(const HarmonicBalance& hb, const Eigen::VectorXd& X, std::size_t i) {
  const UnilateralContact& ct = hb.contacts().at(i);
  const Eigen::VectorXd u = hb.penetration(X, i);
  const int H = int(u.size() - 1) / 2;
  const Aft aft(H, std::max(Aft::default_samples(H), 64));
  const auto intervals = contact_intervals(u, aft.to_time(u));
  if (ct.stiffness_profile) {
    double Sc = 0.0, Ss = 0.0;
    weighted_indicator_moments(intervals, [&](double th) { return stiffness_at(ct, th) * trig_series(u, th); }, 0,
                               2.0 * M_PI / aft.samples(), &Sc, &Ss);
    return Sc;
  }
  double sum = 0.0;   // int_I u dtheta in closed form
  for (const auto& [a, b] : intervals) {
    sum += u[0] * (b - a);
    for (int k = 1; k <= H; ++k)
      sum += (u[2 * k - 1] * (std::sin(k * b) - std::sin(k * a)) - u[2 * k] * (std::cos(k * b) - std::cos(k * a))) / k;
  }
  return ct.kc * sum / (2.0 * M_PI);
}

ResponseSummary ResponseEvaluator::summarize(const Eigen::VectorXd& X) const {
  const int H = hb_.harmonics();
  const Eigen::VectorXd c = hb_.project(X, q_);
  const Eigen::VectorXd x = fine_.to_time(c);
  ResponseSummary r;
  std::tie(r.x_min, r.x_max) = trig_extremes(c, x);
  r.x_mean = c[0];
  double ss = 0.0;
  for (int k = 1; k <= H; ++k) ss += 0.5 * (c[2 * k - 1] * c[2 * k - 1] + c[2 * k] * c[2 * k]);
  r.x_rms_ac = std::sqrt(ss);
  r.x_h1 = std::hypot(c[1], c[2]);
  // Contact state: penetration u = g + n'x of every contact on the fine grid.
  bool any_open = false, any_closed = false;
  for (std::size_t i = 0; i < hb_.contacts().size(); ++i) {
    const Eigen::VectorXd uc = hb_.penetration(X, i);
    const auto [lo, hi] = trig_extremes(uc, fine_.to_time(uc));   // contact_state's reading
    any_closed = any_closed || hi > 0.0;
    any_open = any_open || !(lo > 0.0);
    r.contact_states.push_back(hi > 0.0 ? (lo > 0.0 ? ContactState::full : ContactState::intermittent) : ContactState::open);
    const double half = 0.5 * (hi - lo);
    if (half > 0.0) r.grazing_distance = std::min(r.grazing_distance, std::min(std::fabs(hi), std::fabs(lo)) / half);
  }
  r.contact = any_closed ? (any_open ? ContactState::intermittent : ContactState::full)
                         : ContactState::open;
  return r;
}

ContactHistory contact_history(const HarmonicBalance& hb, const Branch& b, const Eigen::VectorXd& q) {
  const ResponseEvaluator ev(hb, q);
  ContactHistory h;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const ResponseSummary r = ev.summarize(b.points[i].X);
    const double omega = b.points[i].omega;
    if (i == 0) {
      h.start = r.contact;
      h.x_max = r.x_max;
      h.x_min = r.x_min;
    } else if (r.contact != h.end) {
      ++h.transitions;
    }
    if (r.contact != h.start) {
      h.changed_lo = std::isnan(h.changed_lo) ? omega : std::min(h.changed_lo, omega);
      h.changed_hi = std::isnan(h.changed_hi) ? omega : std::max(h.changed_hi, omega);
    }
    h.x_max = std::max(h.x_max, r.x_max);
    h.x_min = std::min(h.x_min, r.x_min);
    ++h.points[static_cast<int>(r.contact)];
    h.end = r.contact;
  }
  return h;
}

std::vector<bool> branch_stability(const HarmonicBalance& hb, const Branch& b) {
  std::vector<bool> st;
  st.reserve(b.points.size());
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  for (const auto& p : b.points) {
    hb.evaluate(p.X, p.omega, R, &J, nullptr);
    st.push_back(hill_stability(J, hb.system().M, hb.system().C, p.omega, hb.harmonics()).stable);
  }
  return st;
}

}  // namespace gearhb
