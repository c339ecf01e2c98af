#include "gearhb/gears/dynamics/dte_response.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

namespace {
const Eigen::VectorXd kX = Eigen::VectorXd::Constant(1, 1.0);
// The drive flank (contact 0) is closed all period; the back flank, if any, plays no part.
bool drive_closed(const ResponseEvaluator& ev, const Eigen::VectorXd& X) {
  return ev.summarize(X).contact_states.front() == ContactState::full;
}
}  // namespace

DteGear dte_gear(const std::vector<double>& ste, double torque, double r, double I1, double I2, double zeta,
                 int ste_harmonics) {
  DteGear g;
  g.F0 = torque / r;
  g.me = equivalent_mass(I1, I2, r, r);
  for (std::size_t j = 0; j < ste.size(); ++j)
    if (!(ste[j] > 0.0))
      throw std::runtime_error("the static transmission error is " + std::to_string(ste[j] * 1e6) +
                               " um at mesh phase " + std::to_string(double(j) / double(ste.size())) +
                               ": the mesh stiffness F / STE does not exist (a backlash of 0 clips the STE to 0?)");
  g.kc = mean_stiffness(ste, g.F0);
  g.c = mesh_damping(zeta, g.kc, g.me);
  g.ste = periodic_fourier(ste, ste_harmonics);
  return g;
}

DteCurveReport dte_curve_report(const DteGear& g, const HarmonicBalance& hb, const FrequencyCurve& c,
                                DteModel model) {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  DteCurveReport r;
  bool in_band = false;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const bool lost = !drive_closed(ev, P[i].X);
    if (lost && !in_band) r.loss_bands.push_back({P[i].omega, P[i].omega});
    if (lost) {
      auto& b = r.loss_bands.back();
      b.first = std::min(b.first, P[i].omega);
      b.second = std::max(b.second, P[i].omega);
    }
    in_band = lost;
    r.mean_force_rel_dev =
        std::max(r.mean_force_rel_dev, std::fabs(dte_mean_contact_force(hb, P[i].X) - g.F0) / g.F0);
    if (!lost && model == DteModel::constant) {
      const Eigen::VectorXd Xc = dte_closed_contact(g, hb.harmonics(), P[i].omega);
      r.closed_form_rel_diff = std::max(r.closed_form_rel_diff, (P[i].X - Xc).lpNorm<Eigen::Infinity>() /
                                                                    Xc.tail(Xc.size() - 1).lpNorm<Eigen::Infinity>());
      ++r.closed_points;
    }
    if (rms_ac(P[i].X) > r.peak_rms) {
      r.peak_rms = rms_ac(P[i].X);
      r.peak_omega = P[i].omega;
    }
  }
  r.first_loss_omega = first_transition(hb, c, opens_somewhere(hb, 0));
  return r;
}

std::vector<double> dte_linear_rms(const DteGear& g, int H, const std::vector<double>& omegas) {
  std::vector<double> out;
  for (double omega : omegas) out.push_back(rms_ac(dte_closed_contact(g, H, omega)));
  return out;
}

namespace {
bool near_fold(const FrequencyCurve& c, double omega, double margin = 5e-3) {
  for (const auto& f : c.branch.folds)
    if (std::fabs(f.omega - omega) < margin * f.omega) return true;
  return false;
}
}  // namespace

DteTimeComparison dte_time_integration_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i) {
  return dte_time_integration_point(hb, c, i, hb);
}

DteTimeComparison dte_time_integration_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i,
                                             const HarmonicBalance& integrated) {
  const ResponseEvaluator ev(hb, kX);
  const auto& p = c.branch.points.at(i);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, p.X, p.omega, x0, v0);
  const SteadyState s = TimeIntegrator(integrated).steady_state(x0, v0, p.omega, opt);
  if (!s.converged)
    throw std::runtime_error("time integration not periodic at omega = " + std::to_string(p.omega) + " rad/s after " +
                             std::to_string(s.periods) + " periods");
  const Eigen::VectorXd x = s.x.col(0);
  DteTimeComparison row;
  row.omega = p.omega;
  row.contact = ev.summarize(p.X).contact;
  row.rms_time_integration = std::sqrt((x.array() - x.mean()).square().mean());
  row.rms_hb = ev.summarize(p.X).x_rms_ac;
  row.rel_diff = std::fabs(row.rms_hb - row.rms_time_integration) / row.rms_time_integration;
  row.periods = s.periods;
  return row;
}

std::size_t dte_near_peak_point(const FrequencyCurve& c) {
  const auto& P = c.branch.points;
  std::size_t best = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (c.stable[i] && !near_fold(c, P[i].omega) && (best == P.size() || rms_ac(P[i].X) > rms_ac(P[best].X))) best = i;
  return best;
}

std::size_t dte_peak_below_fold_point(const FrequencyCurve& c, double margin) {
  const auto& P = c.branch.points;
  const double w_fold = c.branch.folds.empty() ? INFINITY : c.branch.folds.front().omega;
  std::size_t best = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (c.stable[i] && P[i].omega < (1.0 - margin) * w_fold && (best == P.size() || rms_ac(P[i].X) > rms_ac(P[best].X)))
      best = i;
  return best;
}

DteTimeCheck dte_time_integration_check(const HarmonicBalance& hb, const FrequencyCurve& c, int points,
                                        int lost_points) {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  std::vector<std::size_t> lost, full;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!c.stable[i] || near_fold(c, P[i].omega)) continue;
    (drive_closed(ev, P[i].X) ? full : lost).push_back(i);
  }
  std::vector<std::size_t> chosen;
  auto spread = [&](const std::vector<std::size_t>& v, std::size_t n) {
    for (std::size_t k = 0; k < n && !v.empty(); ++k) chosen.push_back(v[(2 * k + 1) * v.size() / (2 * n)]);
  };
  const std::size_t n_lost = std::min<std::size_t>(std::size_t(lost_points), lost.size());
  spread(lost, n_lost);
  spread(full, std::size_t(points) - n_lost);
  DteTimeCheck out;
  for (std::size_t i : chosen) {
    out.rows.push_back(dte_time_integration_point(hb, c, i));
    out.worst_rel_diff = std::max(out.worst_rel_diff, out.rows.back().rel_diff);
  }
  return out;
}

DteFloquetCheck dte_floquet_check(const HarmonicBalance& hb, const FrequencyCurve& c, double fold_margin) {
  const ResponseEvaluator ev(hb, kX);
  const auto& P = c.branch.points;
  // the point of largest value(i) among those with ok(i)
  auto pick = [&](auto ok, auto value) {
    std::size_t best = P.size();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (ok(i) && (best == P.size() || value(i) > value(best))) best = i;
    return best;
  };
  auto closed = [&](std::size_t i) { return drive_closed(ev, P[i].X); };
  auto rms = [&](std::size_t i) { return rms_ac(P[i].X); };
  auto away = [&](std::size_t i) { return !near_fold(c, P[i].omega, fold_margin); };
  const std::size_t full = pick([&](std::size_t i) { return c.stable[i] && closed(i) && away(i); }, rms);
  const std::size_t lost = pick([&](std::size_t i) { return c.stable[i] && !closed(i) && away(i); }, rms);
  const std::size_t unstable = pick([&](std::size_t i) { return !c.stable[i] && away(i); },
                                    [&](std::size_t i) { return c.floquet[i].modulus; });
  const TimeIntegrator ti(hb);
  TimeIntegrationOptions opt;
  opt.x_scale = c.scaling.x[0];
  DteFloquetCheck out;
  for (std::size_t i : {full, lost, unstable}) {
    if (i == P.size()) continue;
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const Eigen::VectorXcd mu = general_eigenvalues(ti.monodromy(x0, v0, P[i].omega, opt),
                                                    "monodromy by time integration at omega = " +
                                                        std::to_string(P[i].omega) + " rad/s");
    DteFloquetComparison row;
    row.omega = P[i].omega;
    row.contact = ev.summarize(P[i].X).contact;
    row.stable = c.stable[i];
    row.modulus_curve = c.floquet[i].modulus;
    row.modulus_time_integration = mu.cwiseAbs().maxCoeff();
    row.abs_diff = std::fabs(row.modulus_time_integration - row.modulus_curve);
    out.worst_abs_diff = std::max(out.worst_abs_diff, row.abs_diff);
    out.rows.push_back(row);
  }
  for (bool st : c.stable) out.unstable_points += st ? 0 : 1;
  return out;
}

}  // namespace gearhb
