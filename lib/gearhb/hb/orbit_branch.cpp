#include "gearhb/hb/orbit_branch.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"

namespace gearhb {

namespace {

struct Failed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The time history of every DOF of X over the model's period at `samples` points (columns: DOFs).
Eigen::MatrixXd histories(const HarmonicBalance& model, const Eigen::VectorXd& X, int samples) {
  Eigen::MatrixXd h(samples, model.dofs());
  for (int d = 0; d < model.dofs(); ++d)
    h.col(d) = ResponseEvaluator(model, Eigen::VectorXd::Unit(model.dofs(), d), samples).history(X);
  return h;
}

// The scaling of the period-p model: hb's over the range, as the period-doubled branches take it.
Scaling model_scaling(const HarmonicBalance& hb, const HarmonicBalance& model, int p, const SweepOptions& opt) {
  Scaling s = hb.scaling(opt.omega_min, opt.omega_max);
  if (p == 1) return s;
  s.x = Eigen::VectorXd::Constant(model.size(), s.x[0]);
  s.omega /= p;
  return s;
}

// Steps 1-3: the HB orbit on the model at Omega from the integrated orbit, checked against it.
Eigen::VectorXd orbit_point(OrbitBranch& r, const HarmonicBalance& hb, const Eigen::VectorXd& x0,
                            const Eigen::VectorXd& v0, const SweepOptions& opt, const OrbitBranchOptions& obo) {
  const HarmonicBalance& model = *r.model;
  const int p = r.period, spp = obo.samples_per_period, N = p * spp;
  if (N < 2 * model.harmonics() + 1) throw Failed("samples_per_period too small for the model's harmonics");
  TimeIntegrationOptions to = obo.integration;
  to.samples_per_period = spp;
  const Eigen::MatrixXd x = TimeIntegrator(hb).sample(x0, v0, r.omega, 0, p, to);
  r.swing = (x.colwise().maxCoeff() - x.colwise().minCoeff()).maxCoeff();
  Eigen::VectorXd X = hb_unknowns_of_samples(model, x);
  const double Omega = r.omega / p;
  r.curve.scaling = model_scaling(hb, model, p, opt);
  const NewtonReport nr = newton_solve(model, X, Omega, r.curve.scaling, obo.newton);
  r.newton_iterations = nr.iterations;
  if (!nr.converged) throw Failed("Newton from the orbit's Fourier coefficients did not converge: " + nr.message);
  r.distance = (histories(model, X, N) - x).cwiseAbs().maxCoeff();
  // HB's own error on the same samples: against its orbit corrected by shooting (on the exact flow,
  // or without one on GSL's period map)
  FloquetOptions fo = opt.floquet;
  fo.correct_orbit = true;
  const FloquetResult fr = floquet_of_hb_orbit(model, X, Omega, r.curve.scaling.x[0], fo);
  if (!fr.corrected) throw Failed("the shooting correction of the HB orbit did not converge (no error bound)");
  const Eigen::MatrixXd exact = TimeIntegrator(hb).sample(fr.x0, fr.v0, r.omega, 0, p, to);
  r.bound = (histories(model, X, N) - exact).cwiseAbs().maxCoeff() + obo.integration_tolerance * r.swing;
  if (!(r.distance <= r.bound)) {
    std::ostringstream os;
    os << "the HB orbit is " << r.distance << " from the integrated one, beyond its bound " << r.bound
       << " (Newton landed on another orbit, or the orbit is not periodic with period " << p << ")";
    throw Failed(os.str());
  }
  return X;
}

// The unit tangent (scaled) of the model's branch at (X, Omega), its omega component positive.
Eigen::VectorXd omega_tangent(const HarmonicBalance& model, const Eigen::VectorXd& X, double Omega, const Scaling& s) {
  Eigen::VectorXd R, dRdw;
  Eigen::MatrixXd J;
  model.evaluate(X, Omega, R, &J, &dRdw);
  const Eigen::VectorXd dXdw = J.partialPivLu().solve(-dRdw);
  Eigen::VectorXd d(X.size() + 1);
  d.head(X.size()) = dXdw.array() * s.omega / s.x.array();
  d[X.size()] = 1.0;
  if (!d.allFinite()) throw Failed("singular Jacobian at the orbit: no tangent to start along");
  return d.normalized();
}

// One way of step 4 from (X, Omega) along d; `back` is set if it came back to the start.
Branch one_way(const HarmonicBalance& model, const Eigen::VectorXd& X, double Omega, const Eigen::VectorXd& d,
               const Scaling& s, const SweepOptions& opt, int p, bool& back, bool& met) {
  ContinuationOptions co = opt.continuation;
  if (!co.regime && !model.contacts().empty()) co.regime = contact_regime(model);
  ContinuationEnd end;
  end.omega_min = opt.omega_min / p;
  end.omega_max = opt.omega_max / p;
  double far = 0.0, largest = 0.0;
  Eigen::VectorXd prev_odd = p == 2 ? subharmonic_part(model, 2, X) : Eigen::VectorXd();
  back = false;
  met = false;
  end.stop = [&](const Eigen::VectorXd& Y, double w) {
    const double dw = (w - Omega) / s.omega;
    const double dist = std::sqrt(((Y - X).array() / s.x.array()).square().sum() + dw * dw);
    far = std::max(far, dist);
    back = far > 5.0 * co.ds_max && dist < 1.5 * co.ds_max;
    if (p == 2) {   // the odd part reversed or vanished: the branch met the period-1 branch
      const Eigen::VectorXd odd = subharmonic_part(model, 2, Y);
      largest = std::max(largest, prev_odd.norm());
      met = odd.dot(prev_odd) < 0.0 || odd.norm() <= 1e-8 * largest;
      prev_odd = odd;
    }
    return met ? EndAt::past_branch_point : back ? EndAt::here : EndAt::no;
  };
  return arc_length_continuation_from(model, X, Omega, d, co.ds_initial, s, co, end);
}

std::string way_end(const Branch& b, bool back, bool met, int p, const char* way) {
  std::ostringstream os;
  os << way << ": ";
  if (b.points.empty()) os << "no point";
  else if (back) os << "back at its start (an isola)";
  else if (met) os << "meets the period-1 branch (its odd harmonics reverse or vanish) at omega = " << p * b.points.back().omega;
  else if (b.complete) os << "leaves the range at omega = " << p * b.points.back().omega;
  else os << "failed at omega = " << p * b.failures.back().omega << ": " << b.failures.back().what;
  os << " (" << b.points.size() << " points)";
  return os.str();
}

// Step 4: both ways joined (down reversed, the start, up), folds renumbered.
void continue_both_ways(OrbitBranch& r, const Eigen::VectorXd& X, const SweepOptions& opt) {
  const HarmonicBalance& model = *r.model;
  const double Omega = r.omega / r.period;
  const Scaling& s = r.curve.scaling;
  const Eigen::VectorXd d = omega_tangent(model, X, Omega, s);
  bool back_up = false, back_down = false, met_up = false, met_down = false;
  const Branch up = one_way(model, X, Omega, d, s, opt, r.period, back_up, met_up);
  Branch down;
  if (!back_up) down = one_way(model, X, Omega, -d, s, opt, r.period, back_down, met_down);
  r.isola = back_up;
  Branch& b = r.curve.branch;
  const int m = int(down.points.size());
  b.points.assign(down.points.rbegin(), down.points.rend());
  b.points.push_back(BranchPoint{X, Omega, r.newton_iterations, 0.0, 0.0, d[X.size()]});
  b.points.insert(b.points.end(), up.points.begin(), up.points.end());
  if (back_up) b.points.push_back(b.points[std::size_t(m)]);   // an isola: closed at its start
  r.start = m;
  for (const Fold& f : down.folds) b.folds.push_back(Fold{f.omega, f.X, m - 2 - f.after_point});
  std::reverse(b.folds.begin(), b.folds.end());
  for (const Fold& f : up.folds) b.folds.push_back(Fold{f.omega, f.X, m + 1 + f.after_point});
  b.failures = down.failures;
  b.failures.insert(b.failures.end(), up.failures.begin(), up.failures.end());
  b.rejected_steps = up.rejected_steps + down.rejected_steps;
  b.complete = up.complete && (back_up || down.complete);
  r.curve.complete = b.complete;
  r.why = way_end(up, back_up, met_up, r.period, "up") +
          (back_up ? "" : "; " + way_end(down, back_down, met_down, r.period, "down"));
  if (!b.complete) r.curve.failure = r.why;
}

}  // namespace

OrbitBranch branch_from_orbit(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                              double omega, int period, const SweepOptions& opt, const OrbitBranchOptions& obo) {
  OrbitBranch r;
  r.period = period;
  r.omega = omega;
  std::ostringstream head;
  head << "period-" << period << " branch from the integrated orbit at omega = " << omega << ": ";
  try {
    if (period != 1 && period != 2) throw Failed("the period must be 1 or 2");
    r.model = subharmonic_model(hb, period);   // p = 1: a copy of hb
    const Eigen::VectorXd X = orbit_point(r, hb, x0, v0, opt, obo);
    continue_both_ways(r, X, opt);
    SweepOptions o = opt;
    o.omega_min /= period;
    o.omega_max /= period;
    r.curve.stability = opt.stability;
    analyse_stability(*r.model, o, r.curve);
    r.ok = true;
    r.why = head.str() + r.why;
  } catch (const std::exception& e) {
    r.ok = false;
    r.why = head.str() + "failed: " + e.what();
  }
  return r;
}

PeriodDoubledBranch table_branch(const OrbitBranch& b) {
  PeriodDoubledBranch r;
  r.period = b.period;
  r.from = std::size_t(-1);
  r.omega_start = b.omega;
  r.model = b.model;
  r.curve = b.curve;
  r.end = b.curve.complete ? PeriodDoubledBranch::End::left_range : PeriodDoubledBranch::End::failed;
  r.why = b.why;
  return r;
}

BranchDistance distance_to_branch(const BranchView& b, const Eigen::MatrixXd& xs, int n, double omega) {
  BranchDistance best;
  const auto& P = b.curve->branch.points;
  const Scaling& s = b.curve->scaling;
  const double Omega = omega / b.period;
  for (std::size_t k = 0; k + 1 < P.size(); ++k) {
    const double a = P[k].omega - Omega, z = P[k + 1].omega - Omega;
    if (a * z > 0.0 || a == z) continue;
    const double t = a / (a - z);
    const Eigen::VectorXd guess = (1.0 - t) * P[k].X + t * P[k + 1].X;
    Eigen::VectorXd X = guess;
    if (!newton_solve(*b.model, X, Omega, s, {1e-9, 30}).converged) continue;
    // a Newton that left the chord's neighbourhood found another orbit, not this branch's
    const double chord = ((P[k + 1].X - P[k].X).array() / s.x.array()).matrix().norm();
    if (((X - guess).array() / s.x.array()).matrix().norm() > std::max(chord, 1e-6)) continue;
    Eigen::VectorXd xh, vh;
    hb_initial_state(*b.model, X, Omega, xh, vh);
    double dist = INFINITY;
    for (int j = 0; j < std::min<int>(n, int(xs.rows())); ++j)
      dist = std::min(dist, (xs.row(j).transpose() - xh).cwiseAbs().maxCoeff());
    // HB's error at phase 0: against its orbit corrected by shooting (on the exact flow, or on GSL's)
    const FloquetResult fr = floquet_of_hb_orbit(*b.model, X, Omega, s.x[0]);
    const double bound = fr.corrected ? (fr.x0 - xh).cwiseAbs().maxCoeff() : INFINITY;
    if (std::isfinite(best.distance) && dist - bound >= best.distance - best.bound) continue;
    best.distance = dist;
    best.bound = bound;
    best.chord = int(k);
  }
  return best;
}

bool off_every_branch(const DiagramPoint& p, const std::vector<BranchView>& branches, double tolerance) {
  if (p.motion != Motion::periodic || p.n < 1) return false;
  for (const BranchView& b : branches) {
    if (b.period != p.n) continue;
    const BranchDistance d = distance_to_branch(b, p.x, p.n, p.omega);
    if (d.distance <= d.bound + tolerance) return false;
  }
  return true;
}

}  // namespace gearhb
