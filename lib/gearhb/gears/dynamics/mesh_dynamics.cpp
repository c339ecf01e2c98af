#include "gearhb/gears/dynamics/mesh_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/units.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

double back_flank_phase(const PairSteModel& m) {
  const PathOfContact p = m.path();
  const GearGeometry& g = m.gear1;
  const double alpha = g.pressure_angle_rad();
  const double s1 = g.module * (0.5 * M_PI + 2.0 * g.profile_shift * std::tan(alpha));
  const double rb = g.base_radius();
  const double s_b = rb * (s1 / g.pitch_radius() + 2.0 * involute(alpha));
  const double phi = (s_b + 2.0 * p.mesh.pressure_angle * rb - 2.0 * p.T1A) / p.base_pitch;
  return 2.0 * M_PI * (phi - std::floor(phi));
}

Iso6336Input pair_iso6336_input(const PairSteModel& m, const HelicalPair& h, double hfP_over_mn, double line_load_N_per_mm) {
  const bool helical = h.helix_angle > 0.0;
  Iso6336Input in;
  in.z1 = m.gear1.teeth;
  in.z2 = m.gear2.teeth;
  in.x1 = helical ? h.shift1 : m.gear1.profile_shift;
  in.x2 = helical ? h.shift2 : m.gear2.profile_shift;
  in.normal_pressure_angle_deg = helical ? h.normal_pressure_angle_deg : m.gear1.pressure_angle_deg;
  in.helix_angle_deg = h.helix_angle * 180.0 / M_PI;
  in.hfP_over_mn = hfP_over_mn;
  in.eps_alpha = m.path().contact_ratio;
  in.face_width_m = m.contact_length();
  in.line_load_N_per_mm = line_load_N_per_mm;
  return in;
}

PairIsoKv pair_iso6336_kv(const PairSteModel& m, double hfP_over_m, double torque, double I1, double I2, int grade,
                          const HelicalPair& h) {
  const GearGeometry* g[2] = {&m.gear1, &m.gear2};
  const bool helical = h.helix_angle > 0.0;
  PairIsoKv k;
  for (const GearGeometry* gi : g) {
    const double m_n = helical ? h.normal_module : gi->module;
    const Iso1328Tolerances t = iso1328_tolerances(grade, m_n * 1e3, 2.0 * gi->pitch_radius() * 1e3);
    k.f_pb = std::max(k.f_pb, t.f_pt * std::cos(gi->pressure_angle_rad()));
    k.f_f_alpha = std::max(k.f_f_alpha, t.f_f_alpha);
  }
  const double b_mm = m.contact_length() * 1e3;
  Iso6336KvInput& in = k.input;
  in.z1 = m.gear1.teeth;
  in.eps_gamma = m.path().contact_ratio + (helical ? overlap_ratio(m, h) : 0.0);
  in.line_load = torque / m.gear1.pitch_radius() / b_mm;
  const Iso6336Stiffness s = iso6336_mesh_stiffness(pair_iso6336_input(m, h, hfP_over_m, in.line_load));
  in.c_prime = s.c_single;
  in.c_gamma_alpha = s.c_gamma_alpha;
  in.m_red = equivalent_mass(I1, I2, m.gear1.base_radius(), m.gear2.base_radius()) / b_mm;
  in.f_pb_eff = k.f_pb - iso6336_running_in_case_hardened(k.f_pb);
  in.f_f_alpha_eff = k.f_f_alpha - iso6336_running_in_case_hardened(k.f_f_alpha);
  in.C_a = 1e6 * std::max(m.relief1.amount, m.relief2.amount);
  k.relief_from_running_in = !(in.C_a > 0.0);
  if (k.relief_from_running_in) in.C_a = iso6336_running_in_relief(1500.0);
  return k;
}

DteGear gear_pair_mesh(const PairSteModel& m, const std::vector<PairStePoint>& ste, double torque, double I1,
                       double I2, double zeta, double backlash, int harmonics) {
  std::vector<double> e, g, elastic;
  DteGear G;
  G.F0 = m.force(torque);
  for (const auto& p : ste) {
    double sep = INFINITY;
    for (const auto& k : p.mesh.pairs) sep = std::min(sep, k.separation);
    e.push_back(p.ste);
    g.push_back(sep);
    if (!(p.ste - sep > 0.0))
      throw std::runtime_error("the elastic STE (STE - no-load TE) is not positive at mesh phase " +
                               std::to_string(p.mesh.phase));
    elastic.push_back(G.F0 / (p.ste - sep));
  }
  const double r1 = torque / G.F0, r2 = r1 * m.gear2.teeth / m.gear1.teeth;
  G.me = equivalent_mass(I1, I2, r1, r2);
  G.kc = std::accumulate(elastic.begin(), elastic.end(), 0.0) / double(elastic.size());
  G.c = mesh_damping(zeta, G.kc, G.me);
  G.ste = periodic_fourier(e, harmonics);
  G.nlte = periodic_fourier(g, harmonics);
  G.backlash = backlash;
  G.back_phase = back_flank_phase(m);
  return G;
}

MeshContact mesh_contact(ContactState drive, ContactState back) {
  const bool loss = drive != ContactState::full, impact = back != ContactState::open;
  if (loss && impact) return MeshContact::drive_loss_back_impact;
  if (impact) return MeshContact::back_impact;
  return loss ? MeshContact::drive_loss : MeshContact::full;
}

const char* to_string(MeshDofs d) { return d == MeshDofs::bearings ? "six_dof" : "one_dof"; }

const char* to_string(MeshContact c) {
  switch (c) {
    case MeshContact::full: return "full";
    case MeshContact::drive_loss: return "drive_loss";
    case MeshContact::back_impact: return "back_impact";
    case MeshContact::drive_loss_back_impact: return "drive_loss+back_impact";
  }
  return "?";
}

namespace {

// The mesh-deflection direction over q = [x1, y1, x2, y2, p], or [x1, y1, x2, y2, z1, z2, p] (header).
Eigen::VectorXd bearing_normal(const BearingSupport& b) {
  const double ca = std::cos(b.pressure_angle), sa = std::sin(b.pressure_angle);
  Eigen::VectorXd n(b.dofs());
  if (b.axial())
    n << ca, -sa, -ca, sa, b.helix_tan, -b.helix_tan, 1.0;
  else
    n << ca, -sa, -ca, sa, 1.0;
  return n;
}

LinearSystem bearing_system(const DteGear& g, const BearingSupport& b) {
  const int n = b.dofs();
  Eigen::VectorXd m(n), k(n), c(n);
  for (int i = 0; i < 2; ++i) {
    if (!(b.mass[i] > 0.0 && b.stiffness[i] > 0.0))
      throw std::invalid_argument("bearing model: gear " + std::to_string(i + 1) + " needs a mass and a bearing stiffness > 0");
    const double ci = 2.0 * b.zeta * std::sqrt(b.stiffness[i] * b.mass[i]);
    m.segment(2 * i, 2).setConstant(b.mass[i]);
    k.segment(2 * i, 2).setConstant(b.stiffness[i]);
    c.segment(2 * i, 2).setConstant(ci);
    if (!b.axial()) continue;
    if (!(b.axial_stiffness[i] > 0.0))
      throw std::invalid_argument("bearing model: gear " + std::to_string(i + 1) + " needs an axial bearing stiffness > 0");
    m[4 + i] = b.mass[i], k[4 + i] = b.axial_stiffness[i];
    c[4 + i] = 2.0 * b.zeta * std::sqrt(b.axial_stiffness[i] * b.mass[i]);
  }
  m[n - 1] = g.me, k[n - 1] = 0.0, c[n - 1] = g.c;
  return LinearSystem{m.asDiagonal(), c.asDiagonal(), k.asDiagonal()};
}

// Largest value over the period of contact i's force (exact for a constant kc).
double largest_contact_force(const HarmonicBalance& hb, const ResponseEvaluator& ev, const Eigen::VectorXd& X,
                             std::size_t i, const Aft& fine) {
  const UnilateralContact& ct = hb.contacts()[i];
  if (!ct.stiffness_profile) {
    const Eigen::VectorXd u = hb.penetration(X, i);
    return contact_force(ct.kc, trig_extremes(u, fine.to_time(u)).second);
  }
  (void)fine;
  return ev.contact_force_history(X, i).maxCoeff();
}


bool near(const std::vector<double>& at, double omega, double margin) {
  for (double a : at)
    if (std::fabs(a - omega) < margin * a) return true;
  return false;
}

}  // namespace

HarmonicBalance gear_mesh_model(const DteGear& g, MeshDofs dofs, const BearingSupport& b, int H, int N,
                                DteModel model) {
  if (dofs == MeshDofs::one_dof) return dte_harmonic_balance(g, H, N, ContactQuadrature::exact, model);
  const int n = b.dofs();
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(n);
  f0[n - 1] = g.F0;
  const Excitation f{f0, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  return HarmonicBalance(bearing_system(g, b), dte_mesh_contacts(g, H, model, bearing_normal(b)), f, H, N,
                         ContactQuadrature::exact);
}

Eigen::VectorXd dte_coordinate(MeshDofs dofs, const BearingSupport& b) {
  if (dofs == MeshDofs::one_dof) return Eigen::VectorXd::Constant(1, 1.0);
  return Eigen::VectorXd::Unit(b.dofs(), b.dofs() - 1);
}

double mean_axial_bearing_force(const HarmonicBalance& hb, const BearingSupport& b, const Eigen::VectorXd& X, int i) {
  if (!b.axial()) return 0.0;
  return -b.axial_stiffness[i] * hb.project(X, Eigen::VectorXd::Unit(b.dofs(), 4 + i))[0];
}

std::vector<double> closed_contact_frequencies(const DteGear& g, MeshDofs dofs, const BearingSupport& b) {
  if (dofs == MeshDofs::one_dof) return {hz(std::sqrt(g.kc / g.me))};
  const LinearSystem s = bearing_system(g, b);
  const Eigen::VectorXd n = bearing_normal(b);
  const Modes modes = modal_analysis(s.M, s.K + g.kc * n * n.transpose());
  std::vector<double> f;
  for (Eigen::Index i = 0; i < modes.omega.size(); ++i) f.push_back(hz(modes.omega[i]));
  return f;
}

MeshOrbitMeasures mesh_orbit_measures(const HarmonicBalance& hb, const Eigen::VectorXd& X, double F0,
                                      const Eigen::VectorXd& q) {
  const ResponseEvaluator ev(hb, q, 4096);
  const Aft fine(hb.harmonics(), 4096);
  const ResponseSummary s = ev.summarize(X);
  MeshOrbitMeasures m;
  m.dte_rms = s.x_rms_ac;
  m.dte_ptp = s.x_max - s.x_min;
  m.drive = s.contact_states.at(0);
  m.back = s.contact_states.size() > 1 ? s.contact_states[1] : ContactState::open;
  m.contact = mesh_contact(m.drive, m.back);
  // N = F_drive - F_back: the flanks never load together (b_n + g_b >= 0), so N is largest
  // where the drive flank is, and smallest where the back flank is (or where the drive force is
  // least if the back flank never touches).
  m.force_max = largest_contact_force(hb, ev, X, 0, fine);
  if (m.back != ContactState::open) {
    m.force_min = -largest_contact_force(hb, ev, X, 1, fine);
  } else {
    m.force_min = ev.contact_force_history(X, 0).minCoeff();
    if (!hb.contacts()[0].stiffness_profile) {
      const Eigen::VectorXd u = hb.penetration(X, 0);
      m.force_min = contact_force(hb.contacts()[0].kc, trig_extremes(u, fine.to_time(u)).first);
    }
  }
  m.dynamic_factor = std::max(m.force_max, -m.force_min) / F0;
  return m;
}

namespace {

// The smallest and largest mesh force N = drive - back over time samples (rows of xs, `per_period`
// uniform samples a forcing period from phase 0), with the model's own contact law.
std::pair<double, double> sampled_mesh_force_range(const HarmonicBalance& hb, const Eigen::MatrixXd& xs, int per_period) {
  double Nmax = -INFINITY, Nmin = INFINITY;
  for (Eigen::Index j = 0; j < xs.rows(); ++j) {
    const double th = 2.0 * M_PI * double(j % per_period) / double(per_period);
    double N = 0.0;
    for (std::size_t k = 0; k < hb.contacts().size(); ++k) {
      const UnilateralContact& ct = hb.contacts()[k];
      double u = ct.gap + ct.normal.dot(xs.row(j).transpose());
      if (ct.gap_harmonics.size() > 0) u += trig_series(ct.gap_harmonics, th);
      N += (k == 0 ? 1.0 : -1.0) * contact_force(stiffness_at(ct, th), u);
    }
    Nmax = std::max(Nmax, N), Nmin = std::min(Nmin, N);
  }
  return {Nmin, Nmax};
}

}  // namespace

MeshCurveSummary mesh_curve_summary(const HarmonicBalance& hb, const FrequencyCurve& c, double F0,
                                    const Eigen::VectorXd& q) {
  MeshCurveSummary s;
  const auto& P = c.branch.points;
  const std::vector<bool> stable = resolved_stable(c);
  for (std::size_t i = 0; i < P.size(); ++i) {
    s.points.push_back(mesh_orbit_measures(hb, P[i].X, F0, q));
    const MeshOrbitMeasures& m = s.points.back();
    if (stable[i] && m.dte_rms > s.dte_rms_peak) s.dte_rms_peak = m.dte_rms, s.dte_rms_peak_omega = P[i].omega;
    if (stable[i] && m.dynamic_factor > s.dynamic_factor_peak)
      s.dynamic_factor_peak = m.dynamic_factor, s.dynamic_factor_peak_omega = P[i].omega;
    s.mean_force_rel_dev = std::max(s.mean_force_rel_dev, std::fabs(dte_mean_contact_force(hb, P[i].X) - F0) / F0);
  }
  s.drive_loss_first_omega = first_transition(hb, c, opens_somewhere(hb, 0));
  if (hb.contacts().size() > 1) s.back_impact_first_omega = first_transition(hb, c, touches_somewhere(hb, 1));
  return s;
}

std::vector<MeshTimeComparison> mesh_time_integration_check(
    const HarmonicBalance& hb, const FrequencyCurve& c, const MeshCurveSummary& s, double F0, const Eigen::VectorXd& q,
    int points, const std::function<void(std::size_t point, int period, double mismatch)>& progress) {
  const auto& P = c.branch.points;
  std::vector<double> special;
  for (const auto& f : c.branch.folds) special.push_back(f.omega);
  for (const auto& b : c.bifurcations) special.push_back(b.omega);
  std::vector<std::size_t> impact, loss, full;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!c.stable[i] || near(special, P[i].omega, 5e-3)) continue;
    if (!c.floquet.empty() && c.floquet[i].modulus > 0.99) continue;   // too slow to settle (|mu|^periods)
    if (!c.floquet.empty() && !c.floquet[i].corrected) continue;         // no exact period-1 orbit to settle on
    const MeshContact k = s.points[i].contact;
    (k == MeshContact::full ? full : k == MeshContact::drive_loss ? loss : impact).push_back(i);
  }
  // quotas: a third each for impacts and losses (as far as there are), the rest full
  // contact, a shortfall anywhere filled from the other categories
  const std::size_t n = std::size_t(points), third = n / 3;
  std::size_t qi = std::min(third, impact.size()), ql = std::min(third, loss.size());
  const std::size_t qf = std::min(n - qi - ql, full.size());
  std::size_t left = n - qi - ql - qf;
  const std::size_t more_i = std::min(left, impact.size() - qi);
  qi += more_i, left -= more_i;
  ql += std::min(left, loss.size() - ql);
  std::vector<std::size_t> chosen;
  auto spread = [&](const std::vector<std::size_t>& v, std::size_t k) {   // k points spread evenly over v
    for (std::size_t j = 0; j < k; ++j) chosen.push_back(v[(2 * j + 1) * v.size() / (2 * k)]);
  };
  spread(impact, qi);
  spread(loss, ql);
  spread(full, qf);
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());

  const TimeIntegrator ti(hb);
  std::vector<MeshTimeComparison> out;
  for (std::size_t i : chosen) {
    TimeIntegrationOptions opt;
    opt.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
    opt.samples_per_period = 4096;
    if (progress) opt.progress = [&progress, i](int period, double mismatch) { progress(i, period, mismatch); };
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const SteadyState st = ti.steady_state(x0, v0, P[i].omega, opt);
    if (!st.converged) {
      // A start one displacement scale from the corrected orbit closes on it like |mu|^periods.
      const double mu = c.floquet.empty() ? NAN : c.floquet[i].modulus;
      const double settle = std::ceil(std::log(opt.periodicity_tol) / std::log(mu));
      char what[480];
      std::snprintf(what, sizeof what,
                    "time integration not periodic at f_mesh = %g Hz (branch point %zu) after %d periods (mismatch %.3g "
                    "of the displacement scale), where the corrected orbit, |mu| = %.3g, attracts a start one scale away "
                    "within %.0f periods: the integration from the harmonic-balance state settles elsewhere",
                    hz(P[i].omega), i, st.periods, st.mismatch, mu, settle);
      throw std::runtime_error(what);
    }
    // DTE and mesh force on the integrated period, with the model's own contact law
    const Eigen::VectorXd x = st.x * q;
    const auto [Nmin, Nmax] = sampled_mesh_force_range(hb, st.x, int(st.x.rows()));
    MeshTimeComparison r;
    r.omega = P[i].omega;
    r.contact = s.points[i].contact;
    r.dte_rms_hb = s.points[i].dte_rms;
    r.dte_rms_ti = std::sqrt((x.array() - x.mean()).square().mean());
    r.dynamic_factor_hb = s.points[i].dynamic_factor;
    r.dynamic_factor_ti = std::max(Nmax, -Nmin) / F0;
    r.rel_diff = std::max(std::fabs(r.dte_rms_hb - r.dte_rms_ti) / r.dte_rms_ti,
                          std::fabs(r.dynamic_factor_hb - r.dynamic_factor_ti) / r.dynamic_factor_ti);
    r.periods = st.periods;
    out.push_back(r);
  }
  return out;
}

MeshMotionMeasures mesh_motion_measures(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                        double omega, int periods, int samples, double F0, const Eigen::VectorXd& q,
                                        double x_scale) {
  TimeIntegrationOptions opt;
  opt.x_scale = x_scale;
  opt.samples_per_period = samples;
  const Eigen::MatrixXd xs = TimeIntegrator(hb).sample(x0, v0, omega, 0, periods, opt);
  const Eigen::VectorXd x = xs * q;
  const auto [Nmin, Nmax] = sampled_mesh_force_range(hb, xs, samples);
  MeshMotionMeasures m;
  m.dte_rms = std::sqrt((x.array() - x.mean()).square().mean());
  m.dynamic_factor = std::max(Nmax, -Nmin) / F0;
  return m;
}

}  // namespace gearhb
