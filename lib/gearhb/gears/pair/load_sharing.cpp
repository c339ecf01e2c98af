#include "gearhb/gears/pair/load_sharing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "gearhb/core/gsl_errors.hpp"
#include "gearhb/gears/tooth/hertz.hpp"

namespace gearhb {

namespace {

void check_pairs(const std::vector<ContactPair>& pairs, double F) {
  if (pairs.empty()) throw std::invalid_argument("share_load: no pair in contact");
  if (!(F > 0.0) || !std::isfinite(F)) throw std::invalid_argument("share_load: the tooth force must be > 0");
  for (const auto& p : pairs)
    if (!(p.stiffness > 0.0) || !(p.separation >= 0.0) || !std::isfinite(p.stiffness) || !std::isfinite(p.separation) ||
        !(p.line_fraction > 0.0 && p.line_fraction <= 1.0))
      throw std::invalid_argument("share_load: pair stiffness must be > 0, separation >= 0, line fraction in (0, 1]");
}

// Pairs in the order their gaps close (stable: equal gaps keep the pair order).
std::vector<int> closing_order(const std::vector<ContactPair>& pairs) {
  std::vector<int> order(pairs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pairs[a].separation < pairs[b].separation; });
  return order;
}

// Linear springs: fill the gaps in closing order until the next one stays open
// (X = (F + sum k_j g_j) / sum k_j over the m loaded pairs); Hertz added after.
LoadShare share_linear(const std::vector<ContactPair>& pairs, const std::vector<int>& order, double F, double nh,
                       TwoPairHertz split, double contact_length) {
  const int n = int(pairs.size());
  LoadShare r;
  r.force.assign(n, 0.0);
  double X = 0.0;
  int m = 1;
  for (; m <= n; ++m) {
    double num = F, den = 0.0;
    for (int j = 0; j < m; ++j) {
      num += pairs[order[j]].stiffness * pairs[order[j]].separation;
      den += pairs[order[j]].stiffness;
    }
    X = num / den;
    if (m == n || X <= pairs[order[m]].separation) break;
  }
  for (int j = 0; j < m; ++j) {
    const int i = order[j];
    r.force[i] = pairs[i].stiffness * (X - pairs[i].separation);
  }
  r.loaded = m;
  r.approach = X;
  if (nh > 0.0) {
    if (split == TwoPairHertz::fe_split_mean) {
      double sum = 0.0;
      for (int j = 0; j < m; ++j) sum += palmgren_line_contact_approach(r.force[order[j]], contact_length);
      r.hertz = nh * sum / m;
    } else {
      r.hertz = nh * palmgren_line_contact_approach(F / m, contact_length);
    }
  }
  r.ste = r.approach + r.hertz;
  return r;
}

// Consistent: F_i(X) from F_i / k_i + n_H delta(F_i / w_i) = X - g_i, and sum F_i(X) = F.
LoadShare share_consistent(const std::vector<ContactPair>& pairs, const std::vector<int>& order, double F, double nh,
                           double contact_length) {
  const int n = int(pairs.size());
  auto pair_force = [&](int i, double X) {
    const double d = X - pairs[i].separation;
    if (!(d > 0.0)) return 0.0;
    const double k = pairs[i].stiffness, w = pairs[i].line_fraction;
    return brent_root([&](double f) { return f / k + nh * palmgren_line_contact_approach(f / w, contact_length) - d; },
                      0.0, k * d, 1e-14, "share_load: the force of one pair");
  };
  auto total = [&](double X) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += pair_force(i, X);
    return s - F;
  };
  // Bracket: at X = g_min nothing is loaded; at X = g_min + F/k + n_H delta(F) the
  // first pair alone carries F (1 % more, so round-off in the inner solve cannot
  // leave the bracket's upper end a hair below F).
  const ContactPair& first = pairs[order[0]];
  const double lo = first.separation;
  const double hi = first.separation + 1.01 * (F / first.stiffness +
                                               nh * palmgren_line_contact_approach(F / first.line_fraction, contact_length));
  const double X = brent_root(total, lo, hi, 1e-14, "share_load: the approach of the gear bodies");
  LoadShare r;
  r.force.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    r.force[i] = pair_force(i, X);
    r.loaded += r.force[i] > 0.0;
  }
  // Hertz part: that of the most loaded pair (its approach is X = g + F/k + n_H delta).
  const int most = int(std::max_element(r.force.begin(), r.force.end()) - r.force.begin());
  r.hertz = nh * palmgren_line_contact_approach(r.force[most] / pairs[std::size_t(most)].line_fraction, contact_length);
  r.approach = X;
  r.ste = X;
  return r;
}

}  // namespace

LoadShare share_load(const std::vector<ContactPair>& pairs, double F, HertzCount hertz_count, TwoPairHertz split,
                     double contact_length) {
  check_pairs(pairs, F);
  const double nh = double(int(hertz_count));
  const std::vector<int> order = closing_order(pairs);
  if (split != TwoPairHertz::consistent || nh == 0.0)
    return share_linear(pairs, order, F, nh, split, contact_length);
  return share_consistent(pairs, order, F, nh, contact_length);
}

}  // namespace gearhb
