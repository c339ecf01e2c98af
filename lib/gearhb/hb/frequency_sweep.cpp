#include "gearhb/hb/frequency_sweep.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

Eigen::VectorXd linear_first_guess(const HarmonicBalance& hb, double omega) {
  Eigen::VectorXd best = hb.open_contact_solution(omega);
  if (hb.contacts().empty()) return best;
  Eigen::VectorXd R;
  hb.evaluate(best, omega, R, nullptr, nullptr);
  const double r_open = R.norm();
  const Eigen::VectorXd closed = hb.closed_contact_solution(omega);
  hb.evaluate(closed, omega, R, nullptr, nullptr);
  return R.norm() < r_open ? closed : best;
}

FrequencyCurve sweep_frequency(const HarmonicBalance& hb, const SweepOptions& opt,
                               const std::string& label) {
  ContinuationOptions co = opt.continuation;
  co.omega_start = opt.omega_min;
  co.omega_end = opt.omega_max;
  FrequencyCurve c;
  c.scaling = hb.scaling(opt.omega_min, opt.omega_max);
  const Eigen::VectorXd X0 = linear_first_guess(hb, opt.omega_min);
  c.branch = opt.natural ? natural_continuation(hb, X0, c.scaling, co)
                         : arc_length_continuation(hb, X0, c.scaling, co);
  if (!c.branch.complete && !opt.natural)
    throw std::runtime_error("case " + label + ": " + c.branch.summary());
  // A natural branch that stopped at a fold is returned as it is (complete = false);
  // the caller reports it.
  c.stable = branch_stability(hb, c.branch);
  return c;
}

namespace {
std::function<bool(const Eigen::VectorXd&)> state_predicate(const HarmonicBalance& hb,
                                                            ContactState not_this) {
  // The state does not depend on the plotted coordinate; 256 samples per period.
  return [&hb, not_this](const Eigen::VectorXd& X) {
    return ResponseEvaluator(hb, Eigen::VectorXd::Zero(hb.dofs()), 256).summarize(X).contact != not_this;
  };
}
}  // namespace

std::function<bool(const Eigen::VectorXd&)> touches_somewhere(const HarmonicBalance& hb) {
  return state_predicate(hb, ContactState::open);
}
std::function<bool(const Eigen::VectorXd&)> opens_somewhere(const HarmonicBalance& hb) {
  return state_predicate(hb, ContactState::full);
}

double first_transition(const HarmonicBalance& hb, const FrequencyCurve& c,
                        const std::function<bool(const Eigen::VectorXd&)>& state) {
  const auto& P = c.branch.points;
  for (std::size_t i = 1; i < P.size(); ++i)
    if (!state(P[i - 1].X) && state(P[i].X))
      return locate_transition(hb, P[i - 1], P[i], c.scaling, state);
  return NAN;
}

TimeIntegrationCheck compare_with_time_integration(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                   const Eigen::VectorXd& q,
                                                   const TimeIntegrationCheckOptions& opt) {
  ResponseEvaluator ev(hb, q);
  const auto& P = c.branch.points;
  // Eligible points: stable, in the requested state, away from every fold.
  std::vector<std::size_t> eligible;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const ResponseSummary r = ev.summarize(P[i].X);
    if (!c.stable[i] || r.contact != opt.state) continue;
    if (r.x_max < opt.min_crest_fraction * 0.5 * (r.x_max - r.x_min)) continue;
    bool near = false;
    for (const auto& f : c.branch.folds) near = near || std::fabs(f.omega - P[i].omega) < opt.fold_margin * f.omega;
    if (near || (opt.accept && !opt.accept(i))) continue;
    eligible.push_back(i);
  }
  TimeIntegrationCheck out;
  if (eligible.empty()) return out;
  // Up to opt.points of them, evenly spread along the branch.
  std::vector<std::size_t> chosen;
  const std::size_t m = std::min<std::size_t>(opt.points, eligible.size());
  for (std::size_t j = 0; j < m; ++j)
    chosen.push_back(eligible[m == 1 ? 0 : j * (eligible.size() - 1) / (m - 1)]);

  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.x_scale = c.scaling.x[0];
  for (std::size_t i : chosen) {
    const auto r = ev.summarize(P[i].X);
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const SteadyState ss = ti.steady_state(x0, v0, P[i].omega, to);
    if (!ss.converged) {
      std::ostringstream os;
      os << "time integration did not reach a periodic state at omega = " << P[i].omega * opt.omega_factor
         << " rad/s after " << ss.periods << " periods (mismatch " << ss.mismatch << ")";
      throw std::runtime_error(os.str());
    }
    const double xm = (ss.x * q).maxCoeff();
    const double rel = std::fabs(r.x_max - xm) / std::fabs(xm);
    out.worst_rel_diff = std::max(out.worst_rel_diff, rel);
    out.rows.push_back({P[i].omega * opt.omega_factor, r.x_max, xm, rel, int(ss.periods), r.contact});
    ++out.points;
  }
  return out;
}

}  // namespace gearhb
