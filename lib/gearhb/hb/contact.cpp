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

#include <cmath>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

namespace gearhb {

namespace {

double trig_poly(double theta, void* params) {
  const auto& c = *static_cast<const Eigen::VectorXd*>(params);
  double v = c[0];
  const int H = int(c.size() - 1) / 2;
  for (int k = 1; k <= H; ++k) v += c[2 * k - 1] * std::cos(k * theta) + c[2 * k] * std::sin(k * theta);
  return v;
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

std::vector<std::pair<double, double>> contact_intervals(const Eigen::VectorXd& uc,
                                                         const Eigen::VectorXd& us) {
  const int N = int(us.size());
  const double dt = 2.0 * M_PI / N;
  int j0 = -1;
  for (int j = 0; j < N; ++j)
    if (!(us[j] > 0.0)) { j0 = j; break; }
  if (j0 < 0) return {{0.0, 2.0 * M_PI}};        // every sample in contact
  std::vector<std::pair<double, double>> out;
  double start = 0.0;
  bool in = false;
  for (int i = 0; i < N; ++i) {
    const int j = j0 + i;                         // unwrapped index; theta = j dt
    const bool now = us[j % N] > 0.0, next = us[(j + 1) % N] > 0.0;
    if (!now && next) {
      start = crossing(uc, j * dt, (j + 1) * dt);
      in = true;
    } else if (now && !next && in) {
      out.emplace_back(start, crossing(uc, j * dt, (j + 1) * dt));
      in = false;
    }
  }
  return out;
}

void indicator_moments(const std::vector<std::pair<double, double>>& I, int M, double* Sc, double* Ss) {
  const double inv2pi = 0.5 / M_PI;
  for (int m = 0; m <= M; ++m) Sc[m] = Ss[m] = 0.0;
  for (const auto& [a, b] : I) {
    Sc[0] += (b - a) * inv2pi;
    for (int m = 1; m <= M; ++m) {
      Sc[m] += (std::sin(m * b) - std::sin(m * a)) * inv2pi / m;
      Ss[m] += (std::cos(m * a) - std::cos(m * b)) * inv2pi / m;
    }
  }
}

}  // namespace gearhb
