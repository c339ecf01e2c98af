#include "gearhb/hb/contact.hpp"

namespace gearhb {

const char* to_string(ContactState s) {
  switch (s) {
    case ContactState::open: return "open";
    case ContactState::full: return "full";
    case ContactState::intermittent: return "intermittent";
  }
  return "?";
}

}  // namespace gearhb

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

#include "gearhb/core/fourier.hpp"

namespace gearhb {

namespace {

double trig_poly(double theta, void* params) {
  return trig_series(*static_cast<const Eigen::VectorXd*>(params), theta);
}

// Root of u in [a, b] (u(a), u(b) of opposite sign) by GSL's Brent method.
double crossing(const Eigen::VectorXd& uc, double a, double b) {
  gsl_function F{trig_poly, const_cast<Eigen::VectorXd*>(&uc)};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_set_error_handler_off();
  gsl_root_fsolver_set(s, &F, a, b);
  double r = 0.5 * (a + b);
  for (int it = 0; it < 100; ++it) {
    gsl_root_fsolver_iterate(s);
    r = gsl_root_fsolver_root(s);
    const double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  return r;
}

double minus_trig_poly(double theta, void* params) { return -trig_poly(theta, params); }

// Refine the sampled extremum at theta_j (value us[j]) with GSL's Brent minimiser
// on -sign*u, in a bracket (a, m, b) with f(m) below f(a) and f(b): the sample and
// its two neighbours, or - when a neighbour ties with it (the crest half-way
// between two samples) - the two tied samples and their midpoint. Returns the
// refined value (never worse than the sample).
double refine_extremum(const Eigen::VectorXd& uc, const Eigen::VectorXd& us, int j, double sign) {
  const int N = int(us.size());
  const double dt = 2.0 * M_PI / N;
  Eigen::VectorXd& c = const_cast<Eigen::VectorXd&>(uc);
  auto f = [&](double th) { return -sign * trig_poly(th, &c); };
  double xa = (j - 1) * dt, xm = j * dt, xb = (j + 1) * dt;
  double fa = -sign * us[(j + N - 1) % N], fm = -sign * us[j], fb = -sign * us[(j + 1) % N];
  if (!(fm < fa && fm < fb)) {
    // a tie with a neighbour: try the midpoint between the two tied samples
    const bool right = !(fm < fb);
    const double mid = right ? xm + 0.5 * dt : xm - 0.5 * dt, fmid = f(mid);
    if (right) { xa = xm; fa = fm; xm = mid; fm = fmid; }
    else       { xb = xm; fb = fm; xm = mid; fm = fmid; }
    if (!(fm < fa && fm < fb)) return us[j];   // a plateau: the sample is as good
  }
  gsl_function F{sign > 0 ? minus_trig_poly : trig_poly, &c};
  gsl_min_fminimizer* m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_set_error_handler_off();
  double best = us[j];
  if (gsl_min_fminimizer_set_with_values(m, &F, xm, fm, xa, fa, xb, fb) == GSL_SUCCESS) {
    for (int it = 0; it < 100; ++it) {
      gsl_min_fminimizer_iterate(m);
      const double lo = gsl_min_fminimizer_x_lower(m), hi = gsl_min_fminimizer_x_upper(m);
      if (gsl_min_test_interval(lo, hi, 1e-13, 0.0) == GSL_SUCCESS) break;
    }
    best = -sign * gsl_min_fminimizer_f_minimum(m);
  }
  gsl_min_fminimizer_free(m);
  return sign > 0 ? std::max(best, us[j]) : std::min(best, us[j]);
}

}  // namespace

std::pair<double, double> trig_extremes(const Eigen::VectorXd& c, const Eigen::VectorXd& samples) {
  Eigen::Index jmax = 0, jmin = 0;
  samples.maxCoeff(&jmax);
  samples.minCoeff(&jmin);
  return {refine_extremum(c, samples, int(jmin), -1.0), refine_extremum(c, samples, int(jmax), +1.0)};
}

ContactState contact_state(const Eigen::VectorXd& uc, const Eigen::VectorXd& us) {
  const auto [lo, hi] = trig_extremes(uc, us);
  if (!(hi > 0.0)) return ContactState::open;
  return lo > 0.0 ? ContactState::full : ContactState::intermittent;
}

namespace {

// Bounds on |u'| and |u''| over the period: sum k (|a_k| + |b_k|) and sum k^2 (|a_k| + |b_k|).
double derivative_bound(const Eigen::VectorXd& c, int order) {
  const int H = int(c.size() - 1) / 2;
  double b = 0.0;
  for (int k = 1; k <= H; ++k) b += std::pow(double(k), order) * (std::fabs(c[2 * k - 1]) + std::fabs(c[2 * k]));
  return b;
}

// Every sign change of u on [a, b] (ua = u(a), ub = u(b); "positive" means u > 0),
// appended to `out` as (theta, entering). Rigorous with the bound L2 >= |u''|:
//  - same sign at both ends: u deviates from the chord by at most L2 h^2 / 8, so if
//    the chord stays that far from zero there is no root; otherwise split;
//  - different signs: u' differs from the chord slope by at most L2 h, so if the
//    slope is larger than that u is monotonic and has exactly one root (Brent);
//    otherwise split.
// Intervals narrower than `hmin` are not split further (what is lost there has
// measure below hmin: a contact or a gap of width < hmin, i.e. a grazing touch).
void scan_roots(const Eigen::VectorXd& uc, double L2, double a, double ua, double b, double ub,
                double hmin, std::vector<std::pair<double, bool>>& out) {
  const double h = b - a;
  const bool pa = ua > 0.0, pb = ub > 0.0;
  const double bow = 0.125 * L2 * h * h;
  if (pa == pb) {
    if (pa ? std::min(ua, ub) - bow > 0.0 : std::max(ua, ub) + bow <= 0.0) return;
  } else if (std::fabs(ub - ua) > L2 * h * h) {
    out.emplace_back(crossing(uc, a, b), pb);
    return;
  }
  if (h < hmin) {
    if (pa != pb) out.emplace_back(crossing(uc, a, b), pb);
    return;
  }
  const double m = 0.5 * (a + b), um = trig_poly(m, const_cast<Eigen::VectorXd*>(&uc));
  scan_roots(uc, L2, a, ua, m, um, hmin, out);
  scan_roots(uc, L2, m, um, b, ub, hmin, out);
}

}  // namespace

std::vector<std::pair<double, double>> contact_intervals(const Eigen::VectorXd& uc,
                                                         const Eigen::VectorXd& us) {
  const int N = int(us.size());
  const double dt = 2.0 * M_PI / N;
  const double L2 = derivative_bound(uc, 2);
  std::vector<std::pair<double, bool>> x;   // crossings (theta in [0, 2 pi), entering)
  for (int j = 0; j < N; ++j) scan_roots(uc, L2, j * dt, us[j], (j + 1) * dt, us[(j + 1) % N], 1e-12, x);
  if (x.empty()) {
    if (us[0] > 0.0) return {{0.0, 2.0 * M_PI}};   // u > 0 everywhere (proved by the scan)
    return {};
  }
  // Crossings alternate in direction; start at the first entering one.
  std::size_t first = 0;
  while (first < x.size() && !x[first].second) ++first;
  std::vector<std::pair<double, double>> out;
  if (first == x.size()) return out;   // (cannot happen for a periodic u)
  const std::size_t n = x.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& e = x[(first + i) % n];
    if (!e.second) continue;
    // the next exiting crossing after it, unwrapped past 2 pi if needed
    for (std::size_t k = 1; k <= n; ++k) {
      const std::size_t idx = (first + i + k) % n;
      if (x[idx].second) continue;
      double end = x[idx].first;
      if (end <= e.first) end += 2.0 * M_PI;
      out.emplace_back(e.first, end);
      break;
    }
  }
  return out;
}

void indicator_moments(const std::vector<std::pair<double, double>>& I, int M, double* Sc, double* Ss) {
  const double inv2pi = 0.5 / M_PI;
  for (int m = 0; m <= M; ++m) Sc[m] = Ss[m] = 0.0;
  for (const auto& [a, b] : I) {
    Sc[0] += (b - a) * inv2pi;
    // cos(m a), sin(m a), cos(m b), sin(m b) by the angle-addition recurrence
    const double ca1 = std::cos(a), sa1 = std::sin(a), cb1 = std::cos(b), sb1 = std::sin(b);
    double ca = 1.0, sa = 0.0, cb = 1.0, sb = 0.0;
    for (int m = 1; m <= M; ++m) {
      const double can = ca * ca1 - sa * sa1, cbn = cb * cb1 - sb * sb1;
      sa = sa * ca1 + ca * sa1;
      sb = sb * cb1 + cb * sb1;
      ca = can;
      cb = cbn;
      Sc[m] += (sb - sa) * inv2pi / m;
      Ss[m] += (ca - cb) * inv2pi / m;
    }
  }
}

void weighted_indicator_moments(const std::vector<std::pair<double, double>>& I,
                                const std::function<double(double)>& weight, int M, double max_piece,
                                double* Sc, double* Ss) {
  if (!(max_piece > 0.0)) throw std::invalid_argument("weighted_indicator_moments: max_piece must be > 0");
  // 10-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun 25.4.30).
  static const double x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                              0.8650633666889845, 0.9739065285171717};
  static const double g[5] = {0.2955242247147530, 0.2692667193099965, 0.2190863625159820,
                              0.1494513491505804, 0.0666713443086881};
  const double inv2pi = 0.5 / M_PI;
  for (int m = 0; m <= M; ++m) Sc[m] = Ss[m] = 0.0;
  for (const auto& [a, b] : I) {
    const int pieces = std::max(1, int(std::ceil((b - a) / max_piece)));
    const double h = (b - a) / pieces;
    for (int p = 0; p < pieces; ++p) {
      const double mid = a + (p + 0.5) * h, half = 0.5 * h;
      for (int q = 0; q < 10; ++q) {
        const double t = mid + (q < 5 ? -x[q] : x[q - 5]) * half;
        const double wt = g[q % 5] * half * inv2pi * weight(t);
        // cos(m t), sin(m t) by the angle-addition recurrence
        const double c1 = std::cos(t), s1 = std::sin(t);
        double c = 1.0, s = 0.0;
        for (int m = 0; m <= M; ++m) {
          Sc[m] += wt * c;
          Ss[m] += wt * s;
          const double cn = c * c1 - s * s1;
          s = s * c1 + c * s1;
          c = cn;
        }
      }
    }
  }
}

namespace {
double largest_gap(const UnilateralContact& c) {
  double g = c.gap;
  if (c.gap_harmonics.size() > 0) {
    g += c.gap_harmonics[0];
    for (Eigen::Index k = 1; k + 1 < c.gap_harmonics.size(); k += 2)
      g += std::hypot(c.gap_harmonics[k], c.gap_harmonics[k + 1]);
  }
  return g;
}
}  // namespace

bool contacts_can_close_together(const std::vector<UnilateralContact>& contacts, unsigned long long set) {
  for (std::size_t i = 0; i < contacts.size() && i < 64; ++i) {
    if (!(set >> i & 1ull)) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (!(set >> j & 1ull)) continue;
      const Eigen::VectorXd &a = contacts[i].normal, &b = contacts[j].normal;
      const double na = a.norm(), nb = b.norm();
      if (!(na > 0.0 && nb > 0.0)) continue;
      // opposite normals: b = -c a with c = |b| / |a|
      if ((b / nb + a / na).norm() > 1e-12) continue;
      const double c = nb / na;
      if (!(c * largest_gap(contacts[i]) + largest_gap(contacts[j]) > 0.0)) return false;
    }
  }
  return true;
}

}  // namespace gearhb
