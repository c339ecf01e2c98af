#include "gearhb/app/bifurcation_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gearhb/app/json_file.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

BifurcationDiagramInput read_bifurcation_diagram(const nlohmann::json& root, const std::string& file) {
  BifurcationDiagramInput in;
  if (!root.is_object() || !root.contains("bifurcation_diagram")) return in;
  const nlohmann::json& j = root["bifurcation_diagram"];
  const std::string where = "bifurcation_diagram";
  in.given = true;
  if (j.is_boolean()) {
    in.on = j.get<bool>();
    return in;
  }
  if (!j.is_object()) fail_key(file, where, "must be true, false or an object of options ({} for the defaults)");
  only_keys(j, file, where,
            {"range", "margin", "speeds", "transient_periods", "periods", "max_period", "period_tol",
             "lyapunov_periods", "lyapunov_threshold"});
  if (j.contains("range")) {
    const nlohmann::json& r = j["range"];
    if (!r.is_string() || (r.get<std::string>() != "unstable" && r.get<std::string>() != "whole"))
      fail_key(file, where + ".range", "must be \"unstable\" or \"whole\"");
    in.whole_range = r.get<std::string>() == "whole";
  }
  if (j.contains("margin")) {
    in.bands.margin = json_number(j["margin"], file, where + ".margin");
    if (!(in.bands.margin >= 0.0 && in.bands.margin <= 10.0))
      fail_key(file, where + ".margin", "must be in [0, 10] (a fraction of each range's width)");
  }
  BifurcationDiagramOptions& o = in.options;
  auto whole = [&](const char* key, int& v, int lo, int hi) {   // the ranges of check_bifurcation_options
    if (j.contains(key)) v = json_whole(j[key], file, where + "." + key, lo, hi);
  };
  auto number = [&](const char* key, double& v) {
    if (j.contains(key)) v = json_number(j[key], file, where + "." + key);
  };
  whole("speeds", o.speeds, 2, 100000);
  if (j.contains("speeds")) in.speeds = o.speeds;
  whole("transient_periods", o.transient_periods, 0, 1000000);
  whole("periods", o.periods, 2, 100000);
  whole("max_period", o.max_period, 1, 64);
  number("period_tol", o.period_tol);
  whole("lyapunov_periods", o.lyapunov_periods, 10, 1000000);
  number("lyapunov_threshold", o.lyapunov_threshold);
  std::string why;
  const std::string bad = check_bifurcation_options(o, &why);
  if (!bad.empty()) fail_key(file, where + "." + bad, why);
  return in;
}

int diagram_speed_cap(const DiagramBandOptions& o, int dofs) {
  return std::max(1, int(o.budget_s / (o.speed_s + o.speed_dof_s * std::max(dofs, 1))));
}

std::vector<DiagramBand> diagram_bands(const FrequencyCurve& c, double omega_min, double omega_max, int dofs,
                                       const DiagramBandOptions& o, int speeds) {
  const int n = std::max(dofs, 1), floor = std::max(o.least, o.floor / n);
  const double cap = diagram_speed_cap(o, n);
  const double full = omega_max - omega_min;
  std::vector<DiagramBand> bands;
  for (const auto& [a, b] : period1_ranges(omega_min, omega_max, {&c}).no_stable) {
    const double pad = std::max(o.margin * (b - a), o.min_margin * full);
    const double lo = std::max(omega_min, a - pad), hi = std::min(omega_max, b + pad);
    if (!bands.empty() && lo <= bands.back().omega_hi)
      bands.back().omega_hi = std::max(bands.back().omega_hi, hi);
    else
      bands.push_back({lo, hi, 0});
  }
  long total = 0;
  for (DiagramBand& d : bands) {
    d.speeds = speeds > 0 ? speeds : std::max(floor, int(std::ceil(o.density * (d.omega_hi - d.omega_lo) / full)));
    total += d.speeds;
  }
  if (speeds <= 0 && double(total) > cap)
    for (DiagramBand& d : bands) d.speeds = std::max(floor, int(double(d.speeds) * cap / double(total)));
  return bands;
}

long band_of(const std::vector<DiagramBand>& bands, double omega) {
  for (std::size_t k = 0; k < bands.size(); ++k)
    if (bands[k].omega_lo <= omega && omega <= bands[k].omega_hi) return long(k + 1);
  return 0;
}

std::vector<DiagramBand> input_bands(const BifurcationDiagramInput& in, const FrequencyCurve& c, double omega_min,
                                     double omega_max, int dofs) {
  if (!in.on) return {};
  if (in.whole_range) return {{omega_min, omega_max, in.options.speeds}};
  return diagram_bands(c, omega_min, omega_max, dofs, in.bands, in.speeds);
}

std::string diagram_stiffness(const HarmonicBalance& hb, double omega_lo) {
  const double stiff = fastest_rate(hb) * 2.0 * M_PI / omega_lo;
  if (!(stiff > 1e4)) return "";
  char line[160];
  std::snprintf(line, sizeof line, "no bifurcation diagram: the time integration is stiff (fastest rate x period %.3g > 1e4)",
                stiff);
  return line;
}

std::string bifurcation_diagram_help() {
  const BifurcationDiagramOptions d;
  const DiagramBandOptions b;
  auto num = [](double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return std::string(s);
  };
  return "  bifurcation_diagram   optional: the diagram by time integration. Absent or true: over each range with no\n"
         "                        stable period-1 orbit, padded by margin (" + num(b.margin) + ") x its width (at least " +
         num(b.min_margin) + " x the whole range)\n"
         "                        on either side, clipped to the range, overlapping bands merged; speeds per sweep " +
         num(b.density) + " x band / range,\n"
         "                        at least " + std::to_string(b.floor) + " / n a band (n the DOFs; at least " +
         std::to_string(b.least) + "), at most " + num(b.budget_s) + " s / (" + num(b.speed_s) + " + " +
         num(b.speed_dof_s) + " n) s\n"
         "                        over all bands (a CPU budget over one speed's cost: " + std::to_string(diagram_speed_cap(b, 1)) +
         " speeds for one DOF, " + std::to_string(diagram_speed_cap(b, 6)) + " for six),\n"
         "                        and in each range with no stable period-1 orbit that the grid misses its middle; none\n"
         "                        where every range is stable.\n"
         "                        false: none. An object: range (\"unstable\": those bands, default; \"whole\": the whole range, speeds " +
         std::to_string(d.speeds) + "), margin,\n"
         "                        speeds (per sweep of each band, up then down), transient_periods (" +
         std::to_string(d.transient_periods) + ", at most), periods (" + std::to_string(d.periods) +
         " Poincare points),\n"
         "                        max_period (" + std::to_string(d.max_period) + "), period_tol (" + num(d.period_tol) +
         " of the typical displacement), lyapunov_periods (" + std::to_string(d.lyapunov_periods) +
         "),\n"
         "                        lyapunov_threshold (" + num(d.lyapunov_threshold) + " per forcing period); skipped, said in one "
         "line, where the integration is stiff;\n"
         "                        writes bifurcation_diagram.csv (column band: 1, 2, ...), bifurcation_diagram_hb.csv and "
         "bifurcation_diagram.png\n";
}

int read_period_doubling_depth(const nlohmann::json& root, const std::string& file) {
  if (!root.is_object() || !root.contains("period_doubling")) return 1;
  const nlohmann::json& j = root["period_doubling"];
  if (!j.is_object()) fail_key(file, "period_doubling", "must be an object ({\"depth\": 0 | 1 | 2})");
  only_keys(j, file, "period_doubling", {"depth"});
  return j.contains("depth") ? json_whole(j["depth"], file, "period_doubling.depth", 0, max_period_doubling_depth) : 1;
}

std::string period_doubling_help() {
  return "  period_doubling.depth 0: none; 1 (default): a period-2 branch by harmonic balance (base frequency\n"
         "                        omega/2, 2H harmonics) from each located period doubling of the curve;\n"
         "                        2: also a period-4 branch (omega/4, 4H harmonics) from each located period\n"
         "                        doubling of every period-2 branch (rows of period 2 and 4 in the tables)\n";
}

namespace {

// The stable orbits of one branch (on its model hb, of `period` forcing periods; its omegas base
// frequencies omega / period) at the speeds of the diagram's up sweep: on every segment stable
// at both ends that brackets the speed, Newton from the segment's end. Where the model has an
// exact piecewise-linear flow, each is then corrected by shooting at the speed itself (floquet.hpp):
// kept if the correction converges to a stable orbit of its period (not lower_period), with its
// own orbit error - a segment's ends do not bound the error inside it (ch. 6 Fig. 40's period-2
// branch at 10650 rad/s, 2.8 rad/s from its end at HB's branch point: twice the ends' error).
// Without that correction the orbit's stability is its segment's: both ends stable with resolved
// labels (resolved_stable; an unresolved stretch starts no integration as a stable orbit).
std::vector<SpeedOrbit> speed_orbits(const HarmonicBalance& hb, const FrequencyCurve& c, int period,
                                     const BifurcationDiagram& d) {
  bool profile = false;
  for (const auto& ct : hb.contacts()) profile = profile || bool(ct.stiffness_profile);
  const bool shoot = !profile && c.stability == StabilityMethod::floquet;   // each orbit's own correction
  // Without it, a segment counts stable only where its ends' labels are resolved (resolved_stable).
  const std::vector<bool> stable = shoot ? c.stable : resolved_stable(c);
  const auto& P = c.branch.points;
  std::vector<SpeedOrbit> out;
  for (const DiagramPoint& p : d.points) {
    if (!p.up || p.from_orbit) continue;
    const double Omega = p.omega / period;
    for (std::size_t i = 1; i < P.size() && i < stable.size(); ++i) {
      if ((P[i - 1].omega - Omega) * (P[i].omega - Omega) > 0 || !stable[i - 1] || !stable[i]) continue;
      Eigen::VectorXd X = P[i].X;
      if (!newton_solve(hb, X, Omega, c.scaling).converged) continue;
      double error = NAN;
      if (shoot) {
        const FloquetResult f = floquet_of_hb_orbit(hb, X, Omega, c.scaling.x[0]);
        if (!f.corrected || !f.stable || f.lower_period) continue;
        error = f.orbit_error;
      }
      out.push_back({Omega, std::move(X), error});
    }
  }
  return out;
}


// The rows of one branch: at each point, then at each of its orbits at the diagram's speeds
// (speed_orbits), its `period` values at phase 0 of its forcing periods (phase_states).
void add_branch_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c, int period,
                     const std::vector<SpeedOrbit>& orbits, const Eigen::VectorXd& q, double scale,
                     const std::function<std::vector<Table::Cell>(double)>& lead) {
  auto add = [&](double Omega, const Eigen::VectorXd& X, bool stable, const char* point, double error) {
    const Eigen::MatrixXd x = phase_states(hb, X, period);
    for (int j = 0; j < period; ++j) {
      std::vector<Table::Cell> row = lead(period * Omega);
      row.emplace_back(scale * q.dot(x.col(j)));
      row.emplace_back(long(stable ? 1 : 0));
      row.emplace_back(std::string(point));
      row.push_back(cell(std::isfinite(error), scale * q.cwiseAbs().sum() * error));
      t.add_row(std::move(row));
    }
  };
  const auto& P = c.branch.points;
  for (std::size_t i = 0; i < P.size(); ++i) add(P[i].omega, P[i].X, i < c.stable.size() && c.stable[i], "branch", NAN);
  for (const SpeedOrbit& o : orbits) add(o.Omega, o.X, true, "speed", o.error);
}

// Whether a sweep at the orbit's speed is on it: periodic with its period, each of its phase
// states within the orbit's error plus period_tol x_scale of one of the sweep's states.
bool reached(const BifurcationDiagram& d, double omega, const Eigen::MatrixXd& x, double bound) {
  for (const DiagramPoint& p : d.points) {
    if (std::fabs(p.omega - omega) > 1e-12 * omega || p.motion != Motion::periodic || p.n != x.cols()) continue;
    bool all = true;
    for (Eigen::Index j = 0; j < x.cols() && all; ++j) {
      bool one = false;
      for (Eigen::Index r = 0; r < p.n && r < p.x.rows() && !one; ++r)
        one = (p.x.row(r).transpose() - x.col(j)).cwiseAbs().maxCoeff() <= bound;
      all = one;
    }
    if (all) return true;
  }
  return false;
}

// The points, integrated on the forced model, from the stable orbits of one branch (on its model
// hb, of `period` forcing periods: speed_orbits) that no sweep at their speed is on (reached).
void add_points_from_orbits(BifurcationDiagram& out, const HarmonicBalance& forced, const HarmonicBalance& hb,
                            int period, const std::vector<SpeedOrbit>& orbits, const BifurcationDiagram& d,
                            const BifurcationDiagramOptions& o) {
  for (const SpeedOrbit& orbit : orbits) {
    const double omega = period * orbit.Omega;
    const double error = std::isfinite(orbit.error) ? orbit.error : HUGE_VAL;   // no exact flow: its period alone
    if (reached(d, omega, phase_states(hb, orbit.X, period), error + o.period_tol * o.integration.x_scale)) continue;
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, orbit.X, orbit.Omega, x0, v0);
    out.points.push_back(diagram_point(forced, omega, x0, v0, o));
  }
}

}  // namespace

Eigen::MatrixXd phase_states(const HarmonicBalance& hb, const Eigen::VectorXd& X, int period) {
  const int n = hb.dofs(), H = hb.harmonics();
  Eigen::MatrixXd x(n, period);
  for (int j = 0; j < period; ++j) {
    const double phi = 2.0 * M_PI * j / period;
    x.col(j) = X.segment(hb.index(0, 0), n);
    for (int l = 1; l <= H; ++l)
      x.col(j) += std::cos(l * phi) * X.segment(hb.index(2 * l - 1, 0), n) + std::sin(l * phi) * X.segment(hb.index(2 * l, 0), n);
  }
  return x;
}

SectionOrbits section_orbits(const HarmonicBalance& hb, const FrequencyCurve& c,
                             const std::vector<PeriodDoubledBranch>& pd, const BifurcationDiagram& d) {
  SectionOrbits s;
  s.of_branch.push_back(speed_orbits(hb, c, 1, d));
  for (const auto& b : pd)
    s.of_branch.push_back(has_points(b) ? speed_orbits(*b.model, b.curve, b.period, d) : std::vector<SpeedOrbit>{});
  return s;
}

BifurcationDiagram diagram_from_hb_orbits(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c,
                                          const std::vector<PeriodDoubledBranch>& pd, const SectionOrbits& orbits,
                                          const BifurcationDiagram& d, BifurcationDiagramOptions o) {
  o.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  return run.timed("diagram from the HB orbits", [&] {
    BifurcationDiagram out;
    add_points_from_orbits(out, hb, hb, 1, orbits.of_branch.at(0), d, o);
    for (std::size_t k = 0; k < pd.size(); ++k)
      if (has_points(pd[k])) add_points_from_orbits(out, hb, *pd[k].model, pd[k].period, orbits.of_branch.at(k + 1), d, o);
    return out;
  });
}

void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c, const BifurcationDiagram& d,
                         const Eigen::VectorXd& q, double scale,
                         const std::function<std::vector<Table::Cell>(double)>& lead) {
  add_branch_rows(t, hb, c, 1, speed_orbits(hb, c, 1, d), q, scale, lead);
}

void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c,
                         const std::vector<PeriodDoubledBranch>& pd, const BifurcationDiagram& d,
                         const Eigen::VectorXd& q, double scale, const SectionLead& lead) {
  add_hb_section_rows(t, hb, c, pd, section_orbits(hb, c, pd, d), q, scale, lead);
}

void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c,
                         const std::vector<PeriodDoubledBranch>& pd, const SectionOrbits& orbits,
                         const Eigen::VectorXd& q, double scale, const SectionLead& lead) {
  add_branch_rows(t, hb, c, 1, orbits.of_branch.at(0), q, scale, [&](double w) { return lead(w, 1, 0); });
  for (std::size_t k = 0; k < pd.size(); ++k)
    if (has_points(pd[k]))
      add_branch_rows(t, *pd[k].model, pd[k].curve, pd[k].period, orbits.of_branch.at(k + 1), q, scale,
                      [&](double w) { return lead(w, pd[k].period, int(k) + 1); });
}

std::vector<std::string> hb_section_columns(std::vector<std::string> lead, const std::string& value) {
  lead.push_back(value);
  lead.emplace_back("stable");
  lead.emplace_back("point");
  lead.emplace_back("hb_orbit_error");
  return lead;
}

namespace {

// The diagram over [lo, hi] from the HB orbit of point `start` of c, progress lines per speed; each
// sweep visits the grid's speeds and, in every range of [lo, hi] with no stable period-1 orbit on c
// (period1_ranges) that holds none of them, its middle (speeds_missed).
BifurcationDiagram diagram_from(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t start,
                                double lo, double hi, BifurcationDiagramOptions o, const std::string& label) {
  o.added_speeds = speeds_missed(lo, hi, o.speeds, period1_ranges(lo, hi, {&c}).no_stable);
  const auto& p0 = c.branch.points[start];
  Eigen::VectorXd x0, v0;
  hb_initial_state(hb, p0.X, p0.omega, x0, v0);
  return bifurcation_diagram(hb, lo, hi, x0, v0, o, [&](const DiagramPoint& p, int k) {
    run.progress(label + "bifurcation diagram, sweep " + (p.up ? "up, " : "down, ") + to_string(p.motion), long(k),
                 p.omega, (hi - lo) / (o.speeds - 1));
  });
}

}  // namespace

bool set_down_start(const HarmonicBalance& hb, const FrequencyCurve& c, double hi, BifurcationDiagramOptions& o) {
  o.down_x0.resize(0);
  o.down_v0.resize(0);
  const auto& P = c.branch.points;
  const std::vector<bool> stable = resolved_stable(c);
  for (std::size_t i = std::min(P.size(), stable.size()); i-- > 1;) {
    if ((P[i - 1].omega - hi) * (P[i].omega - hi) > 0 || !stable[i - 1] || !stable[i]) continue;
    Eigen::VectorXd X = std::abs(P[i].omega - hi) <= std::abs(P[i - 1].omega - hi) ? P[i].X : P[i - 1].X;
    if (!newton_solve(hb, X, hi, c.scaling).converged) continue;
    hb_initial_state(hb, X, hi, o.down_x0, o.down_v0);
    return true;
  }
  return false;
}

std::size_t diagram_start(const FrequencyCurve& c, double omega) {
  const auto& P = c.branch.points;
  const std::vector<bool> stable = resolved_stable(c);
  std::size_t start = 0;
  auto better = [&](std::size_t i, std::size_t j) {
    const bool si = i < stable.size() && stable[i], sj = j < stable.size() && stable[j];
    if (si != sj) return si;
    return std::abs(P[i].omega - omega) < std::abs(P[j].omega - omega);
  };
  for (std::size_t i = 1; i < P.size(); ++i)
    if (better(i, start)) start = i;
  return start;
}

BifurcationDiagram diagram_of_bands(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c,
                                    const std::vector<DiagramBand>& bands, BifurcationDiagramOptions o,
                                    const std::string& step, const std::string& label) {
  o.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  const auto& P = c.branch.points;
  return run.timed(step, [&] {
    BifurcationDiagram all;
    for (const DiagramBand& b : bands) {
      const std::size_t start = diagram_start(c, b.omega_lo);
      o.speeds = b.speeds;
      set_down_start(hb, c, b.omega_hi, o);
      BifurcationDiagram d = diagram_from(run, hb, c, start, b.omega_lo, b.omega_hi, o, label);
      all.points.insert(all.points.end(), std::make_move_iterator(d.points.begin()),
                        std::make_move_iterator(d.points.end()));
    }
    return all;
  });
}

BifurcationDiagram diagram_of_curve(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, double lo, double hi,
                                    BifurcationDiagramOptions o, const std::string& step, const std::string& label,
                                    std::size_t start) {
  o.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  const auto& P = c.branch.points;
  if (start >= P.size())
    start = std::size_t(std::min_element(P.begin(), P.end(), [](const auto& a, const auto& b) { return a.omega < b.omega; }) -
                        P.begin());
  return run.timed(step, [&] { return diagram_from(run, hb, c, start, lo, hi, o, label); });
}

std::vector<BranchView> branch_views(const HarmonicBalance& hb, const FrequencyCurve& c,
                                     const std::vector<PeriodDoubledBranch>& pd) {
  std::vector<BranchView> v{{&hb, &c, 1}};
  for (const auto& b : pd)
    if (has_points(b)) v.push_back({b.model.get(), &b.curve, b.period});
  return v;
}

std::vector<DiagramPoint> off_branch_orbits(const HarmonicBalance& hb, const BifurcationDiagram& d,
                                            const std::vector<BranchView>& views, double period_tol, double x_scale) {
  const double tol = period_tol * x_scale;
  TimeIntegrationOptions o;
  o.x_scale = x_scale;
  const TimeIntegrator ti(hb);
  std::vector<DiagramPoint> off;
  for (const DiagramPoint& p : d.points) {
    if (!off_every_branch(p, views, tol)) continue;
    DiagramPoint q = p;
    if (polish_periodic_point(ti, q, tol, o) && !off_every_branch(q, views, tol)) continue;
    off.push_back(std::move(q));
  }
  return off;
}

std::vector<DiagramPoint> diagram_off_branch_orbits(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                    const std::vector<PeriodDoubledBranch>& pd,
                                                    const BifurcationDiagram& d, double period_tol) {
  const double xs = c.scaling.x.cwiseAbs().maxCoeff();   // diagram_of_bands' x_scale
  return off_branch_orbits(hb, d, branch_views(hb, c, pd), period_tol, xs);
}

void off_branch_key_numbers(KeyNumbers& key, const std::vector<DiagramPoint>& off, const std::string& suffix) {
  double off1 = 0.0, off2 = 0.0;
  for (const DiagramPoint& p : off) (p.n == 1 ? off1 : off2) += p.n <= 2 ? 1.0 : 0.0;
  key.add("diagram_off_branch_period1" + suffix, off1, "-");
  key.add("diagram_off_branch_period2" + suffix, off2, "-");
}

std::string diagram_bands_text(const std::vector<DiagramBand>& bands, const std::function<double(double)>& speed,
                               const std::string& unit) {
  std::string text = "bifurcation diagram over " + std::to_string(bands.size()) + (bands.size() == 1 ? " band: " : " bands: ");
  auto num = [](double v) {   // 4 digits, whole numbers from 1000 up (no exponent)
    char s[40];
    std::snprintf(s, sizeof s, std::abs(v) >= 1000.0 ? "%.0f" : "%.4g", v);
    return std::string(s);
  };
  for (std::size_t k = 0; k < bands.size(); ++k)
    text += (k ? ", " : "") + num(speed(bands[k].omega_lo)) + "-" + num(speed(bands[k].omega_hi)) + " " + unit + " (" +
            std::to_string(bands[k].speeds) + " speeds)";
  return text;
}

void diagram_key_numbers(KeyNumbers& key, const BifurcationDiagram& d, const std::string& suffix) {
  int max_period = 0;
  for (Motion m : {Motion::periodic, Motion::quasi_periodic, Motion::chaotic, Motion::unsettled, Motion::failed}) {
    long count = 0;
    for (const DiagramPoint& p : d.points) {
      count += p.motion == m ? 1 : 0;
      max_period = std::max(max_period, p.n);
    }
    key.add(std::string("diagram_") + to_string(m) + "_speeds" + suffix, double(count), "-");
  }
  key.add("diagram_max_period" + suffix, double(max_period), "-");
  const auto added = std::count_if(d.points.begin(), d.points.end(), [](const DiagramPoint& p) { return p.added && p.up; });
  key.add("diagram_added_speeds" + suffix, double(added), "-");
}

std::string diagram_summary(const BifurcationDiagram& d, const std::function<double(double)>& speed,
                            const std::string& unit) {
  long count[5] = {0, 0, 0, 0, 0}, period1 = 0;
  int max_period = 0;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const DiagramPoint& p : d.points) {
    ++count[int(p.motion)];
    max_period = std::max(max_period, p.n);
    period1 += p.n == 1 ? 1 : 0;
    if (p.n != 1) {
      const double s = speed(p.omega);
      lo[p.up ? 0 : 1] = std::min(lo[p.up ? 0 : 1], s), hi[p.up ? 0 : 1] = std::max(hi[p.up ? 0 : 1], s);
    }
  }
  char line[400];
  std::snprintf(line, sizeof line,
                "bifurcation diagram, %zu speeds x 2 sweeps: period 1 at %ld, period n >= 2 at %ld (largest n %d), "
                "quasi-periodic %ld, chaotic %ld, unsettled %ld, failed %ld",
                d.points.size() / 2, period1, count[int(Motion::periodic)] - period1, max_period,
                count[int(Motion::quasi_periodic)], count[int(Motion::chaotic)], count[int(Motion::unsettled)],
                count[int(Motion::failed)]);
  std::string text = line;
  for (int k = 0; k < 2; ++k)
    if (std::isfinite(lo[k])) {
      std::snprintf(line, sizeof line, "; not period 1 from %.4g to %.4g %s (sweep %s)", lo[k], hi[k], unit.c_str(),
                    k == 0 ? "up" : "down");
      text += line;
    }
  return text;
}

std::vector<std::string> bifurcation_columns(std::vector<std::string> lead, const std::string& value) {
  for (const char* c : {"sweep"}) lead.emplace_back(c);
  lead.push_back(value);
  for (const char* c : {"motion", "n", "lyapunov"}) lead.emplace_back(c);
  return lead;
}

void add_bifurcation_rows(Table& t, const BifurcationDiagram& d, const Eigen::VectorXd& q, double scale,
                          const std::function<std::vector<Table::Cell>(double)>& lead) {
  for (const DiagramPoint& p : d.points) {
    const Eigen::Index rows = p.motion == Motion::periodic ? p.n : std::max<Eigen::Index>(p.x.rows() - 1, 0);
    for (Eigen::Index j = 0; j < rows; ++j) {
      std::vector<Table::Cell> row = lead(p.omega);
      row.emplace_back(std::string(p.from_orbit ? "from_hb" : p.up ? "up" : "down"));
      row.emplace_back(scale * q.dot(p.x.row(j).transpose()));
      row.emplace_back(std::string(to_string(p.motion)));
      row.emplace_back(long(p.n));
      row.push_back(cell(std::isfinite(p.lyapunov), p.lyapunov));
      t.add_row(std::move(row));
    }
  }
}

}  // namespace gearhb
