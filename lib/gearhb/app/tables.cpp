#include "gearhb/app/tables.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "gearhb/hb/exact_orbit.hpp"
#include "gearhb/hb/response.hpp"

namespace gearhb {

Table frequency_response_table(const HarmonicBalance& hb, const Branch& b,
                               const std::vector<bool>& stable, const Eigen::VectorXd& q) {
  ResponseEvaluator ev(hb, q);
  Table t({"omega", "x_max", "x_min", "x_rms_ac", "x_h1", "x_mean", "stable", "contact"});
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const auto r = ev.summarize(b.points[i].X);
    t.add_row({b.points[i].omega, r.x_max, r.x_min, r.x_rms_ac, r.x_h1, r.x_mean,
               long(stable[i] ? 1 : 0), std::string(to_string(r.contact))});
  }
  return t;
}

namespace {

// The exact twins of x_max, x_min, x_rms_ac, x_h1, x_mean: empty unless status ok.
std::vector<Table::Cell> exact_cells(const ExactPoint& e, std::size_t k, bool with_rms_mean = true) {
  const bool ok = e.status == ExactStatus::ok;
  const ExactMeasures& m = e.measures[k];
  std::vector<Table::Cell> r{cell(ok, m.x_max), cell(ok, m.x_min)};
  if (with_rms_mean) r.push_back(cell(ok, m.x_rms_ac));
  r.push_back(cell(ok, m.x_h1));
  if (with_rms_mean) r.push_back(cell(ok, m.x_mean));
  return r;
}

// Point i's frequency and common cells (app/schema.hpp); `e` holds the exact measures of q
// first. omega is written as the forcing frequency: label.period x the point's (the base
// frequency of a period-p model).
std::vector<Table::Cell> common_row(const ResponseEvaluator& ev, const FrequencyCurve& c, std::size_t i,
                                    const ExactPoint& e, const std::string& contact, const BranchLabel& label = {},
                                    const ResponseLayout& layout = {}) {
  const auto& P = c.branch.points;
  const auto r = ev.summarize(P[i].X);
  const bool fl = c.floquet.size() == P.size();
  std::vector<Table::Cell> row = frequency_cells(layout.axis, label.period * P[i].omega, layout.teeth_1);
  // stable: empty where the curve has no stability (StabilityMethod::none: all flags true)
  const Table::Cell stable =
      c.stability == StabilityMethod::none ? Table::Cell(std::string()) : Table::Cell(long(c.stable[i] ? 1 : 0));
  row.insert(row.end(), {r.x_max, r.x_min, r.x_rms_ac, r.x_h1, r.x_mean, stable,
                               contact.empty() ? std::string(to_string(r.contact)) : contact,
                               cell(fl, fl ? c.floquet[i].modulus : 0.0), cell(fl, fl ? c.floquet[i].angle : 0.0),
                               // NaN where no corrected orbit exists (a time-varying stiffness)
                               cell(fl && std::isfinite(c.floquet[i].orbit_error), fl ? c.floquet[i].orbit_error : 0.0)});
  const auto ex = exact_cells(e, 0);
  row.insert(row.end(), ex.begin(), ex.end());
  row.push_back(std::string(to_string(e.status)));
  row.insert(row.end(), {long(label.period), long(label.branch)});
  return row;
}

}  // namespace

Table dof_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& output,
                         const RowProgress& progress, const BranchLabel& label) {
  const int n = hb.dofs();
  std::vector<std::string> columns = columns_of(frequency_columns(FrequencyAxis::omega), response_columns());
  std::vector<ResponseEvaluator> dof;
  std::vector<Eigen::VectorXd> qs{output};
  for (int i = 0; i < n; ++i) {
    for (const char* what : {"_max", "_min", "_h1"}) columns.push_back("q" + std::to_string(i + 1) + what);
    dof.emplace_back(hb, Eigen::VectorXd::Unit(n, i));
    qs.push_back(Eigen::VectorXd::Unit(n, i));
  }
  for (int i = 0; i < n; ++i)
    for (const char* what : {"_max_exact", "_min_exact", "_h1_exact"}) columns.push_back("q" + std::to_string(i + 1) + what);
  const std::size_t P = hb.contacts().size();
  for (std::size_t i = 0; i < P; ++i) columns.push_back("contact_" + std::to_string(i + 1));
  const ResponseEvaluator ev(hb, output);
  Table t(columns);
  for (std::size_t p = 0; p < c.branch.points.size(); ++p) {
    if (progress) progress(p);
    const ExactPoint e = exact_point(hb, c, p, qs);
    std::vector<Table::Cell> row = common_row(ev, c, p, e, "", label);
    for (int i = 0; i < n; ++i) {
      const auto q = dof[i].summarize(c.branch.points[p].X);
      row.insert(row.end(), {q.x_max, q.x_min, q.x_h1});
    }
    for (int i = 0; i < n; ++i) {
      const auto ex = exact_cells(e, std::size_t(i) + 1, false);
      row.insert(row.end(), ex.begin(), ex.end());
    }
    const auto r = ev.summarize(c.branch.points[p].X);
    for (std::size_t i = 0; i < P; ++i) row.push_back(std::string(to_string(r.contact_states[i])));
    t.add_row(std::move(row));
  }
  return t;
}

Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& q,
                               const RowProgress& progress) {
  return frequency_response_table(hb, c, q, {}, {}, {}, progress, {});
}

Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const Eigen::VectorXd& q,
                               const std::vector<std::string>& extra,
                               const std::function<std::vector<Table::Cell>(std::size_t)>& extra_row,
                               const std::function<std::string(std::size_t)>& contact_label,
                               const RowProgress& progress, const BranchLabel& label, const ResponseLayout& layout) {
  ResponseEvaluator ev(hb, q);
  Table t(columns_of(frequency_columns(layout.axis), response_columns(), extra));
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    if (progress) progress(i);
    std::vector<Table::Cell> row =
        common_row(ev, c, i, exact_point(hb, c, i, {q}), contact_label ? contact_label(i) : "", label, layout);
    if (!extra.empty()) {
      const std::vector<Table::Cell> more = extra_row(i);
      row.insert(row.end(), more.begin(), more.end());
    }
    t.add_row(std::move(row));
  }
  return t;
}

Table bifurcation_table(const FrequencyCurve& c, const BranchLabel& label, const std::vector<int>& starts) {
  Table t({"type", "omega", "multiplier_re", "multiplier_im", "modulus", "located", "smooth", "period", "branch",
           "starts_branch"});
  for (std::size_t i = 0; i < c.bifurcations.size(); ++i) {
    const Bifurcation& b = c.bifurcations[i];
    const bool starts_one = i < starts.size() && starts[i] >= 0;
    t.add_row({std::string(to_string(b.type)), label.period * b.omega, b.multiplier.real(), b.multiplier.imag(),
               std::abs(b.multiplier), long(b.located ? 1 : 0), long(b.smooth ? 1 : 0), long(label.period),
               long(label.branch), starts_one ? Table::Cell(long(starts[i])) : Table::Cell(std::string())});
  }
  return t;
}

Table frequency_response_table(const HarmonicBalance& hb, const FrequencyCurve& c,
                               const std::vector<PeriodDoubledBranch>& pd, const Eigen::VectorXd& q,
                               const RowProgress& progress, const ResponseLayout& layout) {
  Table t = frequency_response_table(hb, c, q, {}, {}, {}, progress, {}, layout);
  for (std::size_t k = 0; k < pd.size(); ++k)
    if (has_points(pd[k]))
      t.append(frequency_response_table(*pd[k].model, pd[k].curve, q, {}, {}, {}, {},
                                        BranchLabel{pd[k].period, int(k) + 1}, layout));
  return t;
}

Table bifurcation_table(const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd) {
  Table t = bifurcation_table(c, {}, branch_starts(c, pd));
  for (std::size_t k = 0; k < pd.size(); ++k)
    if (has_points(pd[k]))
      t.append(bifurcation_table(pd[k].curve, BranchLabel{pd[k].period, int(k) + 1}, branch_starts(pd[k].curve, pd, int(k))));
  return t;
}

Table time_integration_table(const TimeIntegrationCheck& check) {
  Table t(check_columns(FrequencyAxis::omega, {"x_max"}));
  for (const auto& r : check.rows)
    t.add_row({r.omega, std::string(to_string(r.contact)), r.x_max_hb, r.x_max_time_integration, r.rel_diff,
               long(r.periods)});
  return t;
}

Table torus_table(const TorusBalance& tb, const std::vector<TorusBranch>& branches, const Eigen::VectorXd& q,
                  int first_id) {
  Table t({"branch", "omega_ns", "omega", "omega2", "rotation", "x_max", "x_min", "x_qp_rms", "section_min",
           "section_max", "residual", "stable", "lyapunov1", "lyapunov2", "drift"});
  for (std::size_t k = 0; k < branches.size(); ++k)
    for (const TorusPoint& p : branches[k].points) {
      const TorusMeasures m = torus_measures(tb, p.X, q);
      const TorusStability& st = p.stability;
      const bool verdict = st.computed && st.verdict != TorusStability::Verdict::unresolved;
      t.add_row({long(first_id) + long(k), branches[k].omega_ns, p.omega, p.omega2, p.omega2 / p.omega, m.x_max, m.x_min,
                 m.x_qp_rms, m.section_min, m.section_max, p.residual,
                 verdict ? Table::Cell(long(st.verdict == TorusStability::Verdict::stable ? 1 : 0)) : Table::Cell(std::string()),
                 cell(std::isfinite(st.lyapunov1), st.lyapunov1), cell(std::isfinite(st.lyapunov2), st.lyapunov2),
                 cell(std::isfinite(st.drift), st.drift)});
    }
  return t;
}

Table mesh_response_table(const HarmonicBalance& hb, const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd) {
  return frequency_response_table(hb, c, pd, Eigen::VectorXd::Constant(1, 1.0), {}, {FrequencyAxis::mesh});
}

}  // namespace gearhb
