#include "gearhb/experiments/method_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "gearhb/hb/exact_orbit.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/stability.hpp"

namespace gearhb {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

namespace {
// Two solutions at the same frequency are the same when their coefficients agree to 1e-7 (scaled).
bool same_solution(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const Scaling& s) {
  return ((a - b).cwiseQuotient(s.x)).lpNorm<Eigen::Infinity>() < 1e-7;
}
}  // namespace

BranchOnGridReport branch_on_grid(const HarmonicBalance& hb, const Branch& b, const Scaling& s,
                                  const std::vector<double>& omegas, const Eigen::VectorXd& q,
                                  StabilityMethod stability, const FloquetOptions& floquet) {
  const ResponseEvaluator ev(hb, q);
  const auto& P = b.points;
  BranchOnGridReport out;
  out.solutions.resize(omegas.size());
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  for (std::size_t g = 0; g < omegas.size(); ++g) {
    const double omega = omegas[g];
    for (std::size_t i = 0; i + 1 < P.size(); ++i) {
      const double a = P[i].omega - omega, c = P[i + 1].omega - omega;
      if (a * c > 0.0 || a == c) continue;
      const double t = a == c ? 0.0 : a / (a - c);
      Eigen::VectorXd X = (1.0 - t) * P[i].X + t * P[i + 1].X;
      if (!newton_solve(hb, X, omega, s).converged) {
        ++out.newton_failures;
        continue;
      }
      auto& here = out.solutions[g];
      if (std::any_of(here.begin(), here.end(), [&](const GridSolution& o) { return same_solution(o.X, X, s); }))
        continue;
      GridSolution sol;
      const ResponseSummary r = ev.summarize(X);
      sol.x_max = r.x_max;
      sol.x_h1 = r.x_h1;
      if (stability == StabilityMethod::hill) {
        hb.evaluate(X, omega, R, &J, nullptr);
        sol.stable = hill_stability(J, hb.system().M, hb.system().C, omega, hb.harmonics()).stable;
      } else if (stability == StabilityMethod::floquet) {
        sol.stable = floquet_of_hb_orbit(hb, X, omega, s.x[0], floquet).stable;
      }
      sol.X = std::move(X);
      here.push_back(std::move(sol));
    }
  }
  return out;
}

int correct_on_exact_flow(const HarmonicBalance& hb, const std::vector<double>& omegas, const Eigen::VectorXd& q,
                          const Scaling& s, GridSolutions& grid, const FloquetOptions& floquet) {
  int removed = 0;
  for (std::size_t g = 0; g < grid.size() && g < omegas.size(); ++g) {
    std::vector<GridSolution> kept;
    for (auto& sol : grid[g]) {
      const FloquetResult r = floquet_of_hb_orbit(hb, sol.X, omegas[g], s.x[0], floquet);
      bool ok = r.corrected;
      if (ok) {
        try {
          const ExactOrbit o(hb, sol.X, omegas[g], r.x0, r.v0);
          const ExactMeasures m = o.measures(q);
          ok = o.consistent();
          sol.x_max = m.x_max;
          sol.x_h1 = m.x_h1;
          sol.stable = r.stable;
        } catch (const std::runtime_error&) {
          ok = false;
        }
      }
      if (ok) kept.push_back(std::move(sol));
      else ++removed;
    }
    grid[g] = std::move(kept);
  }
  return removed;
}

GridSolutions newton_stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                   const Eigen::VectorXd& q, const Scaling& s) {
  const ResponseEvaluator ev(hb, q);
  GridSolutions out(omegas.size());
  Eigen::VectorXd X, R;
  Eigen::MatrixXd J;
  bool have = false;
  for (std::size_t g = 0; g < omegas.size(); ++g) {
    const double omega = omegas[g];
    if (!have) X = linear_first_guess(hb, omega);
    have = newton_solve(hb, X, omega, s).converged;
    if (!have) continue;
    GridSolution sol;
    const ResponseSummary r = ev.summarize(X);
    sol.x_max = r.x_max;
    sol.x_h1 = r.x_h1;
    hb.evaluate(X, omega, R, &J, nullptr);
    sol.stable = hill_stability(J, hb.system().M, hb.system().C, omega, hb.harmonics()).stable;
    sol.X = X;
    out[g].push_back(std::move(sol));
  }
  return out;
}

GridSolutions merge_grid(const std::vector<GridSolutions>& parts, const Scaling& s) {
  GridSolutions out;
  for (const auto& part : parts) {
    out.resize(std::max(out.size(), part.size()));
    for (std::size_t g = 0; g < part.size(); ++g)
      for (const auto& sol : part[g])
        if (std::none_of(out[g].begin(), out[g].end(), [&](const GridSolution& o) { return same_solution(o.X, sol.X, s); }))
          out[g].push_back(sol);
  }
  return out;
}

std::vector<SteppedSweepPoint> stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                             const Eigen::VectorXd& q, const TimeIntegrationOptions& opt) {
  if (omegas.empty()) return {};
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, linear_first_guess(hb, omegas.front()), omegas.front(), x0, v0);
  return stepped_sweep(hb, omegas, q, opt, x0, v0);
}

std::vector<SteppedSweepPoint> stepped_sweep(const HarmonicBalance& hb, const std::vector<double>& omegas,
                                             const Eigen::VectorXd& q, const TimeIntegrationOptions& opt,
                                             Eigen::VectorXd x0, Eigen::VectorXd v0) {
  const TimeIntegrator ti(hb);
  std::vector<SteppedSweepPoint> out;
  for (double omega : omegas) {
    // Periodicity (and the absolute tolerance) relative to the size of the state
    // this frequency starts from, so a small response is converged as well as a large one.
    TimeIntegrationOptions o = opt;
    o.x_scale = std::max({x0.lpNorm<Eigen::Infinity>(), v0.lpNorm<Eigen::Infinity>() / omega, 1e-300});
    const SteadyState ss = ti.steady_state(x0, v0, omega, o);
    SteppedSweepPoint p;
    p.omega = omega;
    p.periodic = ss.converged;
    p.periods = ss.periods;
    p.x0 = ss.x0;
    p.v0 = ss.v0;
    const Eigen::VectorXd x = ss.x * q;
    const int N = int(x.size());
    double a1 = 0.0, b1 = 0.0;
    for (int j = 0; j < N; ++j) {
      a1 += x[j] * std::cos(2 * M_PI * j / N);
      b1 += x[j] * std::sin(2 * M_PI * j / N);
    }
    p.x_h1 = 2.0 * std::hypot(a1, b1) / N;
    p.x_max = ti.max_over_period(ss.x0, ss.v0, omega, q, o);
    x0 = ss.x0;
    v0 = ss.v0;
    out.push_back(std::move(p));
  }
  return out;
}

GridSolutions sweep_on_grid(const std::vector<double>& omegas,
                            const std::vector<std::vector<SteppedSweepPoint>>& sweeps) {
  GridSolutions out(omegas.size());
  for (const auto& sw : sweeps)
    for (const auto& p : sw) {
      if (!p.periodic) continue;
      const auto it = std::min_element(omegas.begin(), omegas.end(), [&](double a, double b) {
        return std::fabs(a - p.omega) < std::fabs(b - p.omega);
      });
      GridSolution s;
      s.x_max = p.x_max;
      s.x_h1 = p.x_h1;
      out[std::size_t(it - omegas.begin())].push_back(s);
    }
  return out;
}

GridError grid_error(const GridSolutions& reference, const GridSolutions& method, double found) {
  GridError e;
  for (std::size_t g = 0; g < reference.size(); ++g)
    for (const auto& r : reference[g]) {
      if (!r.stable) continue;
      ++e.compared;
      const auto& m = g < method.size() ? method[g] : std::vector<GridSolution>{};
      // The method's solution nearest the reference one (by x_max).
      const auto best = std::min_element(m.begin(), m.end(), [&](const GridSolution& a, const GridSolution& b) {
        return std::fabs(a.x_max - r.x_max) < std::fabs(b.x_max - r.x_max);
      });
      const double ex = best == m.end() ? INFINITY : std::fabs(best->x_max - r.x_max) / std::fabs(r.x_max);
      if (!(ex <= found)) ++e.missed;
      e.x_max = std::max(e.x_max, std::min(ex, 1.0));
      e.x_h1 = std::max(e.x_h1, best == m.end() ? 1.0 : std::min(1.0, std::fabs(best->x_h1 - r.x_h1) / std::fabs(r.x_h1)));
    }
  return e;
}

}  // namespace gearhb
