#include "gearhb/app/orbit_branches.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/case_table.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

using Eigen::MatrixXd;
using Eigen::VectorXd;

double integrated_multiplier(const HarmonicBalance& hb, const VectorXd& x0, const VectorXd& v0, double omega, int p,
                             double x_scale) {
  TimeIntegrationOptions o;
  o.x_scale = x_scale;
  VectorXd x = x0, v = v0, xT, vT;
  MatrixXd M = MatrixXd::Identity(2 * x0.size(), 2 * x0.size()), Phi;
  for (int k = 0; k < p; ++k) {
    TimeIntegrator(hb).period_map(x, v, omega, o, xT, vT, Phi);
    M = Phi * M;
    x = xT, v = vT;
  }
  return M.eigenvalues().cwiseAbs().maxCoeff();
}

void orbit_branch_numbers(KeyNumbers& key, const OrbitBranch& b, int id, const VectorXd& q, const std::string& quantity,
                          const SweepOptions& o, const std::string& tag) {
  const ResponseEvaluator ev(*b.model, q, 256);
  const std::vector<bool> stable = resolved_stable(b.curve);   // a stable label on no converged shooting: not stable
  double from = INFINITY, to = -INFINITY, lo = INFINITY, hi = -INFINITY, swing = 0.0, stable_swing = 0.0;
  const auto& P = b.curve.branch.points;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double w = b.period * P[i].omega;
    if (w < o.omega_min || w > o.omega_max) continue;
    const ResponseSummary r = ev.summarize(P[i].X);
    from = std::min(from, w), to = std::max(to, w);
    lo = std::min(lo, r.x_min), hi = std::max(hi, r.x_max), swing = std::max(swing, r.x_max - r.x_min);
    if (stable[i]) stable_swing = std::max(stable_swing, r.x_max - r.x_min);
  }
  add_range_key_numbers(key, "orbit_branch_stable", resolved_stable_intervals(b.curve, b.period), tag);
  add_range_key_numbers(key, "orbit_branch_unresolved", unresolved_stable_stretches(b.curve, b.period), tag);
  key.add("orbit_branch_stable_swing" + tag, stable_swing, "m");
  key.add("orbit_branch_id" + tag, id, "-");
  key.add("orbit_branch_period" + tag, b.period, "-");
  key.add("orbit_branch_omega" + tag, b.omega, "rad/s");
  key.add("orbit_branch_from_omega" + tag, from, "rad/s");
  key.add("orbit_branch_to_omega" + tag, to, "rad/s");
  key.add("orbit_branch_" + quantity + "_min" + tag, lo, "m");
  key.add("orbit_branch_" + quantity + "_max" + tag, hi, "m");
  key.add("orbit_branch_swing" + tag, swing, "m");
  key.add("orbit_branch_hb_vs_time_integration" + tag, b.distance, "m");
  key.add("orbit_branch_hb_error_bound" + tag, b.bound, "m");
  key.add("orbit_branch_folds" + tag, double(b.curve.branch.folds.size()), "-");
  key.add("orbit_branch_bifurcations" + tag, double(b.curve.bifurcations.size()), "-");
}

int known_branch_holding(const OrbitBranch& b, const std::vector<BranchView>& known, double tol) {
  const BranchView mine{b.model.get(), &b.curve, b.period};
  double lo = INFINITY, hi = -INFINITY;   // b's span in its base frequency
  for (const auto& q : b.curve.branch.points) lo = std::min(lo, q.omega), hi = std::max(hi, q.omega);
  for (std::size_t i = 0; i < known.size(); ++i) {
    if (known[i].period != b.period) continue;
    const FrequencyCurve& c = *known[i].curve;
    std::vector<std::size_t> inside;   // its points in b's span whose HB error is known
    for (std::size_t j = 0; j < c.branch.points.size() && j < c.floquet.size(); ++j)
      if (c.branch.points[j].omega >= lo && c.branch.points[j].omega <= hi && c.floquet[j].corrected) inside.push_back(j);
    const std::size_t n = std::min<std::size_t>(16, inside.size());
    int on = 0;
    for (std::size_t k = 0; k < n && on < 2; ++k) {
      const std::size_t j = inside[inside.size() * k / n];
      const Eigen::MatrixXd xs = phase_states(*known[i].model, c.branch.points[j].X, b.period).transpose();
      const BranchDistance d = distance_to_branch(mine, xs, b.period, b.period * c.branch.points[j].omega);
      on += d.distance <= d.bound + c.floquet[j].orbit_error + tol ? 1 : 0;
    }
    if (on >= 2) return int(i);
  }
  return -1;
}

std::vector<OrbitBranch> branches_from_orbits(Run& run, const std::string& label, const HarmonicBalance& hb,
                                              const std::vector<DiagramPoint>& off,
                                              const std::vector<BranchView>& known, const SweepOptions& o, double tol,
                                              int& left, int& on_known) {
  std::vector<OrbitBranch> found, held;   // held: the branches found to be known ones
  std::vector<BranchView> mine;
  int attempts = 0;
  left = 0, on_known = 0;
  for (const DiagramPoint& p : off) {
    if (!off_every_branch(p, mine, tol)) continue;
    if (found.size() >= 4 || attempts >= 6) {
      ++left;
      continue;
    }
    ++attempts;
    OrbitBranch b = run.timed("orbit branch " + label, [&] {
      return branch_from_orbit(hb, p.x.row(0).transpose(), p.v.row(0).transpose(), p.omega, p.n, o);
    });
    run.say(label + ": " + b.why);
    if (!b.ok) {
      ++left;
      continue;
    }
    if (known_branch_holding(b, known, tol) >= 0) {
      run.say(label + ": the period-" + std::to_string(b.period) + " branch from the integrated orbit at omega = " +
              std::to_string(b.omega) + " is one the run has (its HB start lies on it within both HB errors): not added");
      ++on_known;
      held.push_back(std::move(b));
    } else {
      found.push_back(std::move(b));
    }
    mine.clear();
    for (const auto* v : {&found, &held})
      for (const auto& f : *v) mine.push_back({f.model.get(), &f.curve, f.period});
  }
  return found;
}

void orbit_branch_checks(KeyNumbers& key, const HarmonicBalance& hb, const OrbitBranch& b,
                         const std::vector<DiagramPoint>& off, double tol, double xs, const std::string& tag) {
  int on = 0, agree = 1;
  const auto& st = b.curve.stable;
  for (const DiagramPoint& p : off) {
    if (p.n != b.period) continue;
    const BranchDistance bd = distance_to_branch({b.model.get(), &b.curve, b.period}, p.x, p.n, p.omega);
    if (!(bd.distance <= bd.bound + tol)) continue;
    ++on;
    if (st[std::size_t(bd.chord)] != st[std::size_t(bd.chord) + 1]) continue;
    const bool attracts = integrated_multiplier(hb, p.x.row(0).transpose(), p.v.row(0).transpose(), p.omega, p.n, xs) < 1.0;
    agree = agree && attracts == st[std::size_t(bd.chord)];
  }
  std::vector<std::size_t> unstable;
  for (std::size_t i = 1; i + 1 < st.size(); ++i)
    if (!st[i - 1] && !st[i] && !st[i + 1] && b.curve.floquet[i].corrected) unstable.push_back(i);
  for (int j = 0; j < 3 && !unstable.empty(); ++j) {
    const std::size_t i = unstable[unstable.size() * std::size_t(2 * j + 1) / 6];
    const PointFloquet& f = b.curve.floquet[i];
    agree = agree && integrated_multiplier(hb, f.x0, f.v0, b.period * b.curve.branch.points[i].omega, b.period, xs) > 1.0;
  }
  key.add("orbit_branch_unstable_checked" + tag, double(std::min<std::size_t>(3, unstable.size())), "-");
  key.add("orbit_branch_diagram_speeds" + tag, on, "-");
  key.add("orbit_branch_stability_agrees" + tag, agree, "-");
}

std::vector<OrbitBranch> orbit_branches_of_diagram(Run& run, const std::string& label, const HarmonicBalance& hb,
                                                   const FrequencyCurve& c, std::vector<PeriodDoubledBranch>& branches,
                                                   const std::vector<DiagramPoint>& off_all, const SweepOptions& o,
                                                   double period_tol, const VectorXd& q, const std::string& quantity,
                                                   const std::string& suffix) {
  const double xs = c.scaling.x.cwiseAbs().maxCoeff(), tol = period_tol * xs;
  const std::vector<BranchView> known = branch_views(hb, c, branches);
  std::vector<DiagramPoint> off;
  std::copy_if(off_all.begin(), off_all.end(), std::back_inserter(off), [](const DiagramPoint& p) { return p.n <= 2; });
  int left = 0, on_known = 0;
  std::vector<OrbitBranch> found = branches_from_orbits(run, label, hb, off, known, o, tol, left, on_known);
  KeyNumbers& key = run.key_numbers();
  key.add("orbit_branches" + suffix, double(found.size()), "-");
  key.add("off_curve_orbits_left" + suffix, double(left), "-");
  key.add("off_curve_orbits_on_known" + suffix, double(on_known), "-");
  for (std::size_t k = 0; k < found.size(); ++k) {
    const OrbitBranch& b = found[k];
    const std::string tag = suffix + "_" + std::to_string(k + 1);
    branches.push_back(table_branch(b));
    orbit_branch_numbers(key, b, int(branches.size()), q, quantity, o, tag);
    key.add("orbit_branch_isola" + tag, b.isola ? 1.0 : 0.0, "-");
    orbit_branch_checks(key, hb, b, off, tol, xs, tag);
  }
  return found;
}

std::vector<const FrequencyCurve*> period1_curves(const FrequencyCurve& c, const std::vector<OrbitBranch>& found) {
  std::vector<const FrequencyCurve*> curves{&c};
  for (const OrbitBranch& b : found)
    if (b.period == 1) curves.push_back(&b.curve);
  return curves;
}

}  // namespace gearhb
