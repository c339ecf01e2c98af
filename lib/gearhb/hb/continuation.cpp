#include "gearhb/hb/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "gearhb/hb/chord_trials.hpp"

namespace gearhb {

std::string Branch::summary() const {
  std::ostringstream os;
  os << points.size() << " points, " << folds.size() << " folds, " << rejected_steps
     << " rejected steps, " << (complete ? "complete" : "INCOMPLETE");
  for (const auto& f : failures)
    os << "; failure at omega = " << f.omega << " (residual " << f.residual << ", ds " << f.ds
       << "): " << f.what;
  return os.str();
}

namespace {

// The scaled augmented system for the corrector and the tangent: the problem's
// linearisation at the last evaluated point y (ParametricProblem::linearize).
struct Scaled {
  const ParametricProblem& p;
  const Scaling& s;
  int n;
  Eigen::VectorXd R, dRdomega;
  std::unique_ptr<Linearization> lin;
  Scaled(const ParametricProblem& prob, const Scaling& sc) : p(prob), s(sc), n(prob.size()), R(n), dRdomega(n) {}
  Eigen::VectorXd X(const Eigen::VectorXd& y) const { return s.x.cwiseProduct(y.head(n)); }
  double omega(const Eigen::VectorXd& y) const { return y[n] * s.omega; }
  Eigen::VectorXd y(const Eigen::VectorXd& X, double omega) const {
    Eigen::VectorXd out(n + 1);
    out.head(n) = X.cwiseQuotient(s.x);
    out[n] = omega / s.omega;
    return out;
  }
  // Linearises at y (the linearization before lends its factorization: Linearization::reuse);
  // returns max|R|/r.
  double eval(const Eigen::VectorXd& y) {
    std::unique_ptr<Linearization> before = std::move(lin);
    lin = p.linearize(X(y), omega(y), s, R, dRdomega);
    if (before) lin->reuse(*before);
    return R.cwiseAbs().maxCoeff() / s.residual;
  }
  // R at y alone (the linearization kept); returns max|R|/r.
  double residual_at(const Eigen::VectorXd& y) {
    p.evaluate(X(y), omega(y), R, nullptr, nullptr);
    return R.cwiseAbs().maxCoeff() / s.residual;
  }
};

// Unit tangent at the last evaluated point, oriented along `previous`: [A; previous'] t = [0; 1].
bool tangent_here(Scaled& S, const Eigen::VectorXd& previous, Eigen::VectorXd& t) {
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(S.n + 1);
  rhs[S.n] = 1.0;
  if (!S.lin->solve_bordered(previous, rhs, t) || t.norm() == 0.0) return false;
  t.normalize();
  if (t.dot(previous) < 0) t = -t;
  return true;
}

// The same at y.
bool tangent(Scaled& S, const Eigen::VectorXd& y, const Eigen::VectorXd& previous, Eigen::VectorXd& t) {
  S.eval(y);
  return tangent_here(S, previous, t);
}

// The error left after a Newton step of (scaled, largest entry) length `step`, the step before it
// `before`: the step itself, or, once the steps contract (theta = step / before <= 1/2) and the
// step is below sqrt(tolerance) (so the iterate it reached lies in the quadratic range and the
// linearization before it, which the tangent reuses, is that close), theta / (1 - theta) step:
// the a-posteriori bound of Deuflhard (Newton Methods for Nonlinear Problems, 2004, sec. 2.1.2),
// exact for a linear contraction theta and an overestimate once the convergence is quadratic.
double error_after_step(double step, double before, double tolerance) {
  if (!std::isfinite(before) || step > std::sqrt(tolerance)) return step;
  const double theta = step / before;
  return theta <= 0.5 ? std::min(step, theta / (1.0 - theta) * step) : step;
}

// Corrector: Newton on { R(y) = 0 ; normal' (y - y_p) = 0 }, from y = y_p (in place).
// Returns true on convergence (residual, and the error after the last step, below the
// tolerance); reports iterations and final scaled residual. Once the error after a step is below
// the tolerance (the step itself, or its bound error_after_step) the residual after it is
// evaluated alone: if it converged, S keeps the linearization at the iterate before, one step
// away, with its factorization for the row `normal`, and tangent_here reuses both (a tangent with
// that row costs a back-substitution; before, the converged point was linearised and factored
// once more, a fifth of a contact model's period-2 corrector: ex. 03). Where the bound stopped it,
// `iters` counts the step it stands for, so that the step control (ContinuationOptions::
// fast_iterations, slow_iterations) reads the same count as when that step was taken: ex. 03's
// period-2 points stepped 1.8e-5, 2.6e-6, 2.2e-9 and then 1.4e-14 only to see that 2.2e-9 had
// converged (theta = 8.5e-4: bound 1.9e-12); now they stop after 2.2e-9, 4 iterations as before.
// A step longer than max_step (scaled) stops it as failed: the start lies outside Newton's basin
// (the first point off a branch point: ex. 03's period-2 switch at ds0 = 0.02 stepped 0.54, 1.5,
// 1.3, ... and failed after its 12 iterations; no step of a point that converges there exceeds 0.003).
bool correct(Scaled& S, Eigen::VectorXd& y, const Eigen::VectorXd& normal, int max_iterations,
             double tolerance, int& iters, double& res, double max_step = INFINITY) {
  const int n = S.n;
  const Eigen::VectorXd yp = y;
  Eigen::VectorXd F(n + 1), dy;
  double last_step = INFINITY, step_before = INFINITY;
  for (iters = 0; iters <= max_iterations; ++iters) {
    if (iters > 0 && error_after_step(last_step, step_before, tolerance) < tolerance) {
      res = S.residual_at(y);
      if (!std::isfinite(res)) return false;
      if (res < tolerance) {
        if (last_step >= tolerance) ++iters;   // the step the bound stands for
        return true;
      }
    }
    res = S.eval(y);
    if (!std::isfinite(res)) return false;
    if (iters == max_iterations) return false;
    F.head(n) = -S.R / S.s.residual;
    F[n] = -normal.dot(y - yp);
    if (!S.lin->solve_bordered(normal, F, dy)) return false;
    step_before = last_step;
    last_step = dy.cwiseAbs().maxCoeff();
    if (!(last_step <= max_step)) return false;
    y += dy;
  }
  return false;
}

// The fold between two converged points ya, yb whose tangents ta, tb have omega
// components of opposite sign: regula falsi (Illinois: the end kept twice in a row has its
// value halved; the trial kept inside the bracket's inner 98 %) on the chord fraction, on the
// omega component of the tangent (smooth, through zero at the fold), each trial point
// corrected back onto the branch in the hyperplane normal to the chord, until the bracket
// is below 1e-8 of the chord (as the bisection it replaced: 27 trials a fold; ex. 03 at H = 40:
// 11 and 8 for the period-1 folds, 7 and 2 for the period-2 branch's)
// or that component is zero to 1e-14. Omega is stationary at a fold, so this gives the
// fold frequency to round-off. If a corrector fails (it should not on a short chord) the
// linear interpolation of the omega-tangent is kept.
Eigen::VectorXd locate_fold(Scaled& S, const Eigen::VectorXd& ya, const Eigen::VectorXd& ta,
                            const Eigen::VectorXd& yb, const Eigen::VectorXd& tb, double tolerance,
                            int corrector_iterations) {
  const int n = S.n;
  const double a_lin = ta[n] / (ta[n] - tb[n]);
  Eigen::VectorXd best = (1.0 - a_lin) * ya + a_lin * yb;
  const Eigen::VectorXd normal = (yb - ya).normalized();
  const bool sign_a = ta[n] > 0;
  double lo = 0.0, hi = 1.0, h_lo = ta[n], h_hi = tb[n];
  int side = 0;
  for (int trial = 0; trial < 60 && hi - lo > 1e-8; ++trial) {
    const double mid = std::clamp(lo + (hi - lo) * h_lo / (h_lo - h_hi), lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo));
    Eigen::VectorXd y = (1.0 - mid) * ya + mid * yb, tm;
    int iters = 0;
    double res = 0.0;
    if (!correct(S, y, normal, corrector_iterations, tolerance, iters, res) || !tangent_here(S, ta, tm)) return best;
    best = y;
    if (std::fabs(tm[n]) <= 1e-14) break;
    if ((tm[n] > 0) == sign_a) {
      lo = mid, h_lo = tm[n];
      if (side == -1) h_hi *= 0.5;
      side = -1;
    } else {
      hi = mid, h_hi = tm[n];
      if (side == 1) h_lo *= 0.5;
      side = 1;
    }
  }
  return best;
}

}  // namespace

namespace {

// One predictor-corrector step from (y, t): the predictor y + ds t corrected in the
// hyperplane normal to t, halving ds (by opt.cut) until the corrector converges, the
// tangent turns by less than max_turn_deg and the contact regime holds (or ds is short
// enough to walk up to its change). False with the reason in `failure` if ds falls below
// ds_min.
struct Step {
  Eigen::VectorXd y, t;
  int iterations = 0;
  double residual = 0.0;
  std::uint64_t regime = 0;
};
bool predict_correct(Scaled& S, const ContinuationOptions& opt, const Eigen::VectorXd& y, const Eigen::VectorXd& t,
                     const Eigen::VectorXd& curvature, std::uint64_t regime, double& ds, Branch& b, Step& out,
                     Failure& failure) {
  const double cos_turn = std::cos(opt.max_turn_deg * M_PI / 180.0);
  for (;;) {
    out.y = y + ds * t;
    if (curvature.size() == y.size()) out.y += 0.5 * ds * ds * curvature;
    bool converged = correct(S, out.y, t, opt.corrector_max_iterations, opt.tolerance, out.iterations, out.residual);
    std::string why = converged ? "" : "corrector did not converge";
    if (converged) {
      out.regime = regime;
      if (!tangent_here(S, t, out.t)) {
        converged = false;
        why = "singular augmented Jacobian";
      } else if (out.t.dot(t) < cos_turn && ds > opt.turn_floor * opt.ds_min) {
        converged = false;   // the branch turns too fast for this step: refine
        why = "tangent turned too sharply";
      } else if (opt.regime && (out.regime = opt.regime(S.X(out.y))) != regime && ds > opt.ds_regime_change) {
        converged = false;   // walk up to the regime change (grazing) with short steps
        why = "regime change";
      }
    }
    if (converged) return true;
    ++b.rejected_steps;
    ds *= opt.cut;
    if (ds < opt.ds_min) {
      failure = {S.omega(y), out.residual, ds, why + " with ds below ds_min"};
      return false;
    }
  }
}

// The next step length after an accepted one (ContinuationOptions: iteration count, then
// the curvature control if set), within [ds_min, ds_max].
double next_step(const ContinuationOptions& opt, double ds, int iterations, const Eigen::VectorXd& t,
                 const Eigen::VectorXd& tn) {
  double next = ds;
  if (iterations <= opt.fast_iterations) next = ds * opt.grow;
  else if (iterations >= opt.slow_iterations) next = ds * opt.shrink;
  if (opt.target_turn_deg > 0.0) {
    const double turn = std::acos(std::clamp(tn.dot(t), -1.0, 1.0)) * 180.0 / M_PI;
    next = std::min(next, ds * std::clamp(opt.target_turn_deg / std::max(turn, 1e-12), 0.5, 2.0));
  }
  return std::clamp(next, opt.ds_min, opt.ds_max);
}

}  // namespace

namespace {

// Steps 2-5 of arc_length_continuation from the converged point y with tangent t (scaled),
// appending to b. With `end` (arc_length_continuation_from): the branch ends, complete, at
// the first point outside [end->omega_min, end->omega_max] or where end->stop says so (kept);
// without it at omega_end (Newton exactly there) or turned back beyond omega_start, as a sweep.
void march(Scaled& S, const ContinuationOptions& opt, Eigen::VectorXd y, Eigen::VectorXd t, double dir, Branch& b,
           const ContinuationEnd* end) {
  const int n = S.n;
  const ParametricProblem& p = S.p;
  const Scaling& s = S.s;
  NewtonOptions nopt{opt.tolerance, opt.endpoint_iterations};
  double ds = std::min(opt.ds_initial, opt.ds_max);
  std::uint64_t regime = opt.regime ? opt.regime(S.X(y)) : 0;
  Eigen::VectorXd curvature;   // ContinuationOptions::curvature_predictor: empty until the second point
  for (int step = 0;; ++step) {
    if (step >= opt.max_steps) {
      b.failures.push_back({S.omega(y), 0.0, ds, "step cap reached (max_steps = " +
                                                     std::to_string(opt.max_steps) + ")"});
      return;
    }
    // 2. Predictor and corrector (predict_correct).
    Step st;
    Failure failure;
    if (!predict_correct(S, opt, y, t, curvature, regime, ds, b, st, failure)) {
      b.failures.push_back(failure);
      return;
    }
    // 3. Accept; locate a fold between the two points (not at a branch point `end` stops past).
    const double w_new = S.omega(st.y);
    BranchPoint pt{S.X(st.y), w_new, st.iterations, st.residual, ds, st.t[n]};
    EndAt at = EndAt::no;
    if (end) {
      if (w_new < end->omega_min || w_new > end->omega_max) at = EndAt::here;
      else if (end->stop) at = end->stop(pt.X, pt.omega);
    }
    if ((t[n] > 0) != (st.t[n] > 0) && t[n] != 0.0 && at != EndAt::past_branch_point) {
      const Eigen::VectorXd yf = locate_fold(S, y, t, st.y, st.t, opt.tolerance, opt.locate_iterations);
      b.folds.push_back({S.omega(yf), S.X(yf), int(b.points.size()) - 1});
    }
    // 4. Reached the end of the range: finish with a Newton solve exactly at omega_end.
    if (end) {
      if (at != EndAt::no) {
        b.points.push_back(pt);
        b.complete = true;
        return;
      }
    } else if ((w_new - opt.omega_end) * dir >= 0.0) {
      const double w0 = S.omega(y);
      const double a = (opt.omega_end - w0) / (w_new - w0);
      Eigen::VectorXd Xe = (1.0 - a) * S.X(y) + a * pt.X;
      NewtonReport er = newton_solve(p, Xe, opt.omega_end, s, nopt);
      if (er.converged) b.points.push_back({Xe, opt.omega_end, er.iterations, er.residual, ds, st.t[n]});
      else b.points.push_back(pt);
      b.complete = true;
      return;
    }
    if (!end && (w_new - opt.omega_start) * dir < -opt.start_excursion && b.points.size() > 2) {
      b.points.push_back(pt);
      b.failures.push_back({w_new, st.residual, ds, "branch turned back out of the range at its start"});
      return;
    }
    b.points.push_back(pt);
    if (opt.progress) opt.progress({int(b.points.size()) - 1, w_new, ds});
    // 5. The next step.
    ds = next_step(opt, ds, st.iterations, t, st.t);
    if (opt.curvature_predictor) {
      const double h = (st.y - y).norm();
      if (h > 0.0) curvature = (st.t - t) / h;
    }
    y = st.y;
    t = st.t;
    regime = st.regime;
  }
}

}  // namespace

Branch arc_length_continuation(const ParametricProblem& p, const Eigen::VectorXd& X0,
                               const Scaling& s, const ContinuationOptions& opt) {
  Branch b;
  const int n = p.size();
  const double dir = opt.omega_end >= opt.omega_start ? 1.0 : -1.0;
  Scaled S(p, s);

  // 1. First point: Newton at omega_start, and its tangent along the sweep direction.
  Eigen::VectorXd X = X0;
  NewtonOptions nopt{opt.tolerance, opt.endpoint_iterations};
  NewtonReport nr = newton_solve(p, X, opt.omega_start, s, nopt);
  if (!nr.converged) {
    b.failures.push_back({opt.omega_start, nr.residual, 0.0, "first point: " + nr.message});
    return b;
  }
  Eigen::VectorXd y = S.y(X, opt.omega_start);
  Eigen::VectorXd t0 = Eigen::VectorXd::Zero(n + 1);
  t0[n] = dir;
  Eigen::VectorXd t;
  if (!tangent(S, y, t0, t)) {
    b.failures.push_back({opt.omega_start, nr.residual, 0.0, "singular Jacobian at the first point"});
    return b;
  }
  b.points.push_back({X, opt.omega_start, nr.iterations, nr.residual, 0.0, t[n]});
  if (opt.progress) opt.progress({0, opt.omega_start, 0.0});

  march(S, opt, y, t, dir, b, nullptr);
  return b;
}

// The first point off a start: a corrector step longer than this many times ds0 (scaled, largest
// entry) fails it at once (the chord test of the period-2 branches, period_doubling.cpp
// end_before_jump, calls a chord five times its step a jump).
constexpr double kFirstStepBasin = 5.0;

Branch arc_length_continuation_from(const ParametricProblem& p, const Eigen::VectorXd& X, double omega,
                                    const Eigen::VectorXd& direction, double ds0, const Scaling& s,
                                    const ContinuationOptions& opt, const ContinuationEnd& end) {
  Branch b;
  const int n = p.size();
  Scaled S(p, s);
  const Eigen::VectorXd d = direction.normalized();
  // the first point: the predictor ds0 d corrected in the hyperplane normal to d
  Eigen::VectorXd y = S.y(X, omega) + ds0 * d, t;
  int iters = 0;
  double res = 0.0;
  if (!correct(S, y, d, opt.corrector_max_iterations, opt.tolerance, iters, res, kFirstStepBasin * ds0)) {
    b.failures.push_back({omega, res, ds0, "first point off the start: corrector did not converge"});
    return b;
  }
  if (!tangent_here(S, d, t)) {
    b.failures.push_back({S.omega(y), res, ds0, "singular augmented Jacobian at the first point"});
    return b;
  }
  b.points.push_back({S.X(y), S.omega(y), iters, res, ds0, t[n]});
  if (opt.progress) opt.progress({0, S.omega(y), ds0});
  march(S, opt, y, t, t[n] >= 0.0 ? 1.0 : -1.0, b, &end);
  return b;
}

Branch natural_continuation(const ParametricProblem& p, const Eigen::VectorXd& X0,
                            const Scaling& s, const ContinuationOptions& opt) {
  Branch b;
  Eigen::VectorXd X = X0;
  NewtonOptions nopt{opt.tolerance, opt.corrector_max_iterations};
  const int steps = std::max(1, opt.natural_points);
  Eigen::VectorXd last_good = X0;
  for (int i = 0; i <= steps; ++i) {
    const double omega = opt.omega_start + (opt.omega_end - opt.omega_start) * i / steps;
    X = last_good;
    NewtonReport r = newton_solve(p, X, omega, s, nopt);
    if (!r.converged) {
      // Stop here: the point of this method is to show where it gives up.
      b.failures.push_back({omega, r.residual, 0.0, "Newton: " + r.message});
      break;
    }
    b.points.push_back({X, omega, r.iterations, r.residual, 0.0, 0.0});
    last_good = X;
  }
  b.complete = b.failures.empty();
  return b;
}

double locate_transition(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b,
                         const Scaling& s, const std::function<bool(const Eigen::VectorXd&)>& state,
                         const TransitionOptions& opt) {
  const bool sa = state(a.X);
  if (sa == state(b.X)) throw std::invalid_argument("locate_transition: no change of state between the points");
  Scaled S(p, s);
  const Eigen::VectorXd ya = S.y(a.X, a.omega), yb = S.y(b.X, b.omega);
  const Eigen::VectorXd normal = (yb - ya).normalized();
  // Bisection on the fraction f of the chord a -> b; each trial point is pulled back
  // onto the branch in the hyperplane normal to the chord, so a fold between a and
  // b does no harm.
  double lo = 0.0, hi = 1.0, omega = a.omega;
  while ((hi - lo) * (yb - ya).norm() * s.omega > opt.tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;   // the chord's resolution in double precision (omega ~ 1e100)
    Eigen::VectorXd y = (1 - mid) * ya + mid * yb;
    int iters = 0;
    double res = 0.0;
    if (!correct(S, y, normal, opt.corrector_iterations, opt.corrector_tolerance, iters, res))
      throw std::runtime_error("locate_transition: corrector failed near omega = " +
                               std::to_string(S.omega(y)) + " (scaled residual " + std::to_string(res) + " after " +
                               std::to_string(iters) + " iterations; tolerance " +
                               std::to_string(opt.corrector_tolerance) + ")");
    omega = S.omega(y);
    (state(S.X(y)) == sa ? lo : hi) = mid;
  }
  return omega;
}

// The chord corrector's iteration limit (a trial point lies on a short chord between two
// converged points: 30 is ample, as for ContinuationOptions::locate_iterations).
constexpr int kChordCorrectorIterations = 30;

BranchPoint point_on_chord(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b, const Scaling& s,
                           double t, double corrector_tolerance) {
  Scaled S(p, s);
  const Eigen::VectorXd ya = S.y(a.X, a.omega), yb = S.y(b.X, b.omega);
  Eigen::VectorXd y = (1 - t) * ya + t * yb;
  int iters = 0;
  double res = 0.0;
  if (!correct(S, y, (yb - ya).normalized(), kChordCorrectorIterations, corrector_tolerance, iters, res))
    throw std::runtime_error("point_on_chord: corrector failed near omega = " + std::to_string(S.omega(y)) +
                             " (residual " + std::to_string(res) + ")");
  return {S.X(y), S.omega(y), iters, res, 0.0, 0.0};
}

ChordTrials::ChordTrials(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b, const Scaling& s,
                         double corrector_tolerance)
    : p_(p), s_(s), tolerance_(corrector_tolerance) {
  Scaled S(p, s);
  ya_ = S.y(a.X, a.omega);
  chord_ = S.y(b.X, b.omega) - ya_;
  done_.emplace_back(0.0, ya_);
  done_.emplace_back(1.0, ya_ + chord_);
}

BranchPoint ChordTrials::at(double t) {
  std::size_t near = 0;
  for (std::size_t j = 1; j < done_.size(); ++j)
    if (std::fabs(done_[j].first - t) < std::fabs(done_[near].first - t)) near = j;
  Scaled S(p_, s_);
  S.lin = std::move(last_);   // the last trial's linearization lends its factorization
  Eigen::VectorXd y = done_[near].second + (t - done_[near].first) * chord_;
  int iters = 0;
  double res = 0.0;
  const bool converged = correct(S, y, chord_.normalized(), kChordCorrectorIterations, tolerance_, iters, res);
  last_ = std::move(S.lin);
  if (!converged)
    throw std::runtime_error("point_on_chord: corrector failed near omega = " + std::to_string(S.omega(y)) +
                             " (residual " + std::to_string(res) + ")");
  done_.emplace_back(t, y);
  return {S.X(y), S.omega(y), iters, res, 0.0, 0.0};
}

// A jump of locate_state_change's indicator: the bracket is below kJumpBracket (chord
// fraction) and the indicator at its ends has opposite signs, both still kJumpIndicator or
// more from zero (an indicator continuous there would have a slope above 1e4 per chord). A
// Floquet multiplier leaps across the unit circle so where the orbit of a stiff contact
// grazes (the parametric clearance oscillator with contact direction 2047: every crossing,
// each bisected to 1e-9 at one shooting of about a second a trial); the omega of such a
// crossing is then known to 1e-7 of the chord's omega span (1e-8 relative where the chord
// spans a tenth of omega), 23 trials instead of 30.
constexpr double kJumpBracket = 1e-7, kJumpIndicator = 1e-3;

BranchPoint locate_state_change(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b,
                                const Scaling& s,
                                const std::function<StateProbe(const Eigen::VectorXd&, double)>& probe,
                                double tol, double corrector_tolerance, double indicator_tol) {
  const StateProbe pa = probe(a.X, a.omega), pb = probe(b.X, b.omega);
  if (pa.state == pb.state) throw std::invalid_argument("locate_state_change: no change of state between the points");
  double lo = 0.0, hi = 1.0, h_lo = pa.indicator, h_hi = pb.indicator;
  double raw_lo = h_lo, raw_hi = h_hi;   // the indicator at the bracket's ends (h_lo, h_hi: as Illinois scales them)
  int last_side = 0;   // Illinois: halve the value kept twice in a row
  BranchPoint found = b;
  ChordTrials trials(p, a, b, s, corrector_tolerance);
  while (hi - lo > tol) {
    if (hi - lo <= kJumpBracket && raw_lo * raw_hi < 0.0 && std::fabs(raw_lo) >= kJumpIndicator &&
        std::fabs(raw_hi) >= kJumpIndicator)
      break;   // the indicator jumps across zero here: more trials would only narrow where
    const bool secant = std::isfinite(h_lo) && std::isfinite(h_hi) && h_lo * h_hi < 0.0;
    double mid = secant ? lo + (hi - lo) * h_lo / (h_lo - h_hi) : 0.5 * (lo + hi);
    mid = std::clamp(mid, lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo));   // keep the bracket shrinking
    const BranchPoint q = trials.at(mid);
    const StateProbe pm = probe(q.X, q.omega);
    if (pm.state == pa.state) {
      lo = mid;
      h_lo = raw_lo = pm.indicator;
      if (last_side == -1) h_hi *= 0.5;
      last_side = -1;
    } else {
      hi = mid;
      h_hi = raw_hi = pm.indicator;
      found = q;
      if (last_side == 1) h_lo *= 0.5;
      last_side = 1;
    }
    if (std::isfinite(pm.indicator) && std::fabs(pm.indicator) < indicator_tol) {
      if (pm.state != pa.state) break;
      found = q;   // on the circle to indicator_tol: the change itself
      break;
    }
  }
  return found;
}

}  // namespace gearhb
