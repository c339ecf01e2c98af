// ===========================================================================
// gearhb_frc: the frequency response of your own system, from a model file
// ===========================================================================
//
//     M x'' + C x' + K x + sum_i d_i max(kc_i (g_i(theta) + d_i' x), 0) = f0 + fc cos(omega t) + fs sin(omega t)
//
// Any n-DOF system with unilateral contacts, described in JSON (model_file.hpp,
// README "Your own system from a file"); no C++ needed. The steps: read_model
// (in the study's checks, so a bad file exits 2 before anything is written),
// natural_frequencies, frequency_response (the curve, its period-doubled branches),
// bifurcation_diagram (with orbit_branches: the HB branches through its orbits off every
// branch), quasi_periodic (tori), tables, draw.
//
// Sample runs:
//   build/bin/gearhb_frc programs/gearhb_frc/examples/nlvib_ex03.json --out /tmp/ex03
//   build/bin/gearhb_frc programs/gearhb_frc/examples/mass_wall.json --set contacts.0.gap=-0.8
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "gearhb/app/bifurcation_input.hpp"
#include "gearhb/app/case_table.hpp"
#include "gearhb/app/model_file.hpp"
#include "gearhb/app/orbit_branches.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/quasi_periodic.hpp"
#include "gearhb/hb/response.hpp"

#ifndef GEARHB_FIGURES_DIR
#define GEARHB_FIGURES_DIR ""
#endif

using namespace gearhb;

namespace {

void torus_stability_key_numbers(KeyNumbers& key, const TorusBranch& b, const std::string& id);

// What the steps hand on: the model's HB, the sweep's options and curve, the curve's other
// branches in the order of their table ids 1, 2, ... (the period-doubled ones, then those
// through the diagram's orbits off every branch), the torus branches (ids after those).
struct Response {
  HarmonicBalance hb;
  SweepOptions o;
  FrequencyCurve c;
  std::vector<PeriodDoubledBranch> branches;
  std::vector<TorusBranch> tori;
};

class FrequencyResponseFromFile {
 public:
  explicit FrequencyResponseFromFile(Study& study);
  void run(Run& run);

 private:
  Study& study_;
  bool plot_ = true;
  ModelFile model_;

  void read_model();
  void natural_frequencies(Run& run) const;
  Response frequency_response(Run& run) const;
  void period2_key_numbers(Run& run, const std::vector<PeriodDoubledBranch>& pd) const;
  void curve_key_numbers(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const;
  void bifurcation_diagram(Run& run, Response& r) const;
  void orbit_branches(Run& run, Response& r, const std::vector<DiagramPoint>& off) const;
  void quasi_periodic(Run& run, Response& r) const;
  std::vector<TorusBranch> torus_branches(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c,
                                          const SweepOptions& o, int first_id) const;
  void tables(Run& run, const Response& r) const;
  void draw(Run& run) const;
};

FrequencyResponseFromFile::FrequencyResponseFromFile(Study& study) : study_(study) {
  file_program(study, "MODEL.json", &plot_, [this] { read_model(); });
}

void FrequencyResponseFromFile::run(Run& run) {
  run.write_text("params.json", model_.resolved.dump(2) + "\n");
  natural_frequencies(run);
  Response r = frequency_response(run);
  bifurcation_diagram(run, r);
  quasi_periodic(run, r);
  tables(run, r);
  if (plot_) draw(run);
}

// Step 1 (in the checks, before anything is written): the model file and the overrides.
void FrequencyResponseFromFile::read_model() {
  model_ = read_model_file(study_.positional(), study_.parameters().unregistered());
}

// Step 2: natural frequencies with every contact open, and with each set of contacts
// closed that can be closed at once (contacts_can_close_together: two stops on either
// side of one coordinate never are). modes.csv: mode, omega_open, omega_closed (every
// contact closed, only if possible), omega_set<S> for every other possible set S
// ("1", "2", "1+3", ...; all sets up to 6 contacts, the single contacts beyond).
void FrequencyResponseFromFile::natural_frequencies(Run& run) const {
  const LinearSystem& s = model_.system;
  const std::size_t P = model_.contacts.size();
  const unsigned long long all = P >= 64 ? ~0ull : (1ull << P) - 1ull;
  std::vector<unsigned long long> sets;
  if (P <= 6) {
    for (unsigned long long S = 1; S < all; ++S) sets.push_back(S);
  } else {
    for (std::size_t i = 0; i < P && i < 64; ++i) sets.push_back(1ull << i);
  }
  std::vector<std::string> columns = {"mode", "omega_open"};
  std::vector<Modes> closed;
  std::vector<std::string> names;
  auto closed_modes = [&](unsigned long long S) {
    Eigen::MatrixXd K = s.K;
    for (std::size_t i = 0; i < P && i < 64; ++i)
      if (S >> i & 1ull) K += model_.contacts[i].kc * model_.contacts[i].normal * model_.contacts[i].normal.transpose();
    return modal_analysis(s.M, K);
  };
  const bool all_possible = P > 0 && contacts_can_close_together(model_.contacts, all);
  if (P == 0 || all_possible) {
    columns.push_back("omega_closed");
    closed.push_back(closed_modes(all));
    names.push_back("");
  }
  for (unsigned long long S : sets) {
    if (!contacts_can_close_together(model_.contacts, S)) continue;
    std::string name;
    for (std::size_t i = 0; i < P && i < 64; ++i)
      if (S >> i & 1ull) name += (name.empty() ? "" : "+") + std::to_string(i + 1);
    columns.push_back("omega_set" + name);
    closed.push_back(closed_modes(S));
    names.push_back(name);
  }
  const Modes open = modal_analysis(s.M, s.K);
  Table t(columns);
  for (int i = 0; i < s.dofs(); ++i) {
    const std::string mode = std::to_string(i + 1);
    std::vector<Table::Cell> row;
    row.reserve(2 + closed.size());
    row.emplace_back(long(i + 1));
    row.emplace_back(open.omega[i]);
    run.key_numbers().add("omega_open_" + mode, open.omega[i], "rad/s");
    for (std::size_t k = 0; k < closed.size(); ++k) {
      row.emplace_back(double(closed[k].omega[i]));
      run.key_numbers().add(names[k].empty() ? "omega_closed_" + mode : "omega_set" + names[k] + "_" + mode,
                            closed[k].omega[i], "rad/s");
    }
    t.add_row(std::move(row));
  }
  run.write("modes.csv", t);
}

// Step 3: one arc-length continuation over the range, every point's stability and contact;
// the period-2 (4) branches from its located PDs.
Response FrequencyResponseFromFile::frequency_response(Run& run) const {
  Response r{model_.harmonic_balance(), {}, {}, {}, {}};
  SweepOptions& o = r.o;
  o.omega_min = std::min(model_.omega_from, model_.omega_to);
  o.omega_max = std::max(model_.omega_from, model_.omega_to);
  o.continuation.ds_max = model_.ds_max;
  report_sweep_progress(run, o, model_.name);
  o.direction = model_.omega_from > model_.omega_to ? SweepDirection::down : SweepDirection::up;
  r.c = run.timed("sweep", [&] { return sweep_frequency(r.hb, o, model_.name); });
  const FrequencyCurve& c = r.c;
  // The lowest frequency of the curve where a contact first closes (if any does).
  const double onset = model_.contacts.empty() ? NAN : first_transition(r.hb, c, touches_somewhere(r.hb));
  if (std::isfinite(onset)) run.key_numbers().add("contact_onset_omega", onset, "rad/s");
  run.say(model_.name + ": " + c.branch.summary() +
          (c.branch.points.empty() ? std::string() : std::string("; first point by ") + to_string(c.first_point)));
  if (!c.complete) throw std::runtime_error("the frequency response did not reach omega.to: " + c.failure);
  // Period-2 branches from the located PDs (hb/period_doubling.hpp): each its own branch id
  // (1, 2, ...) in frc.csv and bifurcations.csv; a switch that fails says where and why in
  // one line and the rest of the run stands.
  if (model_.period_doubling_depth >= 1)
    r.branches = run.timed("period-2 branches", [&] { return period_doubling_cascade(r.hb, c, o, model_.period_doubling_depth); });
  for (const auto& b : r.branches) run.say(model_.name + ": " + b.why);
  run.key_numbers().add("bifurcations", double(c.bifurcations.size()), "-");
  if (model_.period_doubling_depth >= 1) period2_key_numbers(run, r.branches);
  curve_key_numbers(run, r.hb, c);
  return r;
}

// How many period-2 branches, how many merged, their points, where each starts and ends, and the
// stretches of each period whose stable labels are unresolved (add_unresolved_branch_ranges).
void FrequencyResponseFromFile::period2_key_numbers(Run& run, const std::vector<PeriodDoubledBranch>& pd) const {
  KeyNumbers& key = run.key_numbers();
  int merged = 0, period2 = 0, period2_points = 0;
  for (const auto& b : pd) merged += b.period == 2 && b.end == PeriodDoubledBranch::End::merged ? 1 : 0;
  for (const auto& b : pd) period2 += b.period == 2 ? 1 : 0;
  for (const auto& b : pd)
    if (b.period == 2 && has_points(b)) period2_points += int(b.curve.branch.points.size());
  key.add("period2_branches", double(period2), "-");
  if (pd.size() > std::size_t(period2)) key.add("period4_branches", double(pd.size() - std::size_t(period2)), "-");
  key.add("period2_branches_merged", double(merged), "-");
  key.add("period2_points", double(period2_points), "-");
  for (std::size_t k = 0; k < pd.size(); ++k) {   // where each branch starts and ends (forcing omega)
    if (pd[k].period != 2) continue;
    const std::string id = std::to_string(k + 1);
    key.add("period2_omega_start_" + id, pd[k].omega_start, "rad/s");
    if (std::isfinite(pd[k].omega_end)) key.add("period2_omega_end_" + id, pd[k].omega_end, "rad/s");
  }
  add_unresolved_branch_ranges(key, pd, "");   // unresolved_period2_* (period 4: unresolved_period4_*)
}

// The period-1 curve's key numbers: points, folds, the peak, the response at either end.
void FrequencyResponseFromFile::curve_key_numbers(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c) const {
  const ResponseEvaluator ev(hb, model_.output);
  double peak = ev.summarize(c.branch.points.front().X).x_max;
  for (const auto& p : c.branch.points) peak = std::max(peak, ev.summarize(p.X).x_max);
  KeyNumbers& key = run.key_numbers();
  key.add("complete", 1.0, "-");
  key.add("points", double(c.branch.points.size()), "-");
  key.add("folds", double(c.branch.folds.size()), "-");
  key.add("x_max_peak", peak, "m");
  // The ranges with no stable period-1 orbit (issue 34 §4; frc.png shades them).
  add_unstable_period1_ranges(key, c, std::min(model_.omega_from, model_.omega_to), std::max(model_.omega_from, model_.omega_to));
  // The response at either end of the range (omega.from, omega.to): the first point and
  // the last, as a time integration from rest would see it where they are stable.
  const auto& P = c.branch.points;
  for (const auto& [name, point, st] : {std::make_tuple("start", &P.front(), c.stable.front()),
                                        std::make_tuple("end", &P.back(), c.stable.back())}) {
    const ResponseSummary r = ev.summarize(point->X);
    key.add(std::string("x_max_") + name, r.x_max, "m");
    key.add(std::string("x_min_") + name, r.x_min, "m");
    key.add(std::string("stable_") + name, st ? 1.0 : 0.0, "-");
  }
}

// Step 4: the diagram by time integration (app/bifurcation_input.hpp), up then down over each
// band of the file's bifurcation_diagram key (down from the stable HB orbit at the band's upper end
// where there is one, on a second thread: set_down_start) - by default each range with no stable period-1
// orbit, padded to show period 1 on both sides; none where every range is stable or the key is
// false, and none, said in one line, where the integration is stiff. Key numbers
// diagram_off_branch_period1, _period2: the speeds (both sweeps) whose orbit of period 1 (2) lies
// on none of the HB branches of its period (the curve; its period-2 branches, none at
// period_doubling depth 0; off_every_branch): HB branches the sweep has not found, continued by
// orbit_branches (step 4b). bifurcation_diagram.csv: omega, band, sweep, x = the output
// coordinate at phase 0 of each period, motion, n, lyapunov; bifurcation_diagram_hb.csv: omega,
// period, branch, x at phase 0 of each forcing period of the orbits of the period-1 branch and of
// every other branch (period-2 (4), orbit branches), stable, point: to draw beneath and check.
void FrequencyResponseFromFile::bifurcation_diagram(Run& run, Response& r) const {
  if (!model_.diagram.on) return;
  const HarmonicBalance& hb = r.hb;
  const FrequencyCurve& c = r.c;
  const double lo = std::min(model_.omega_from, model_.omega_to), hi = std::max(model_.omega_from, model_.omega_to);
  const std::vector<DiagramBand> bands = input_bands(model_.diagram, c, lo, hi, hb.dofs());
  if (bands.empty()) {
    run.say(model_.name + ": no bifurcation diagram: a stable period-1 orbit over the whole range");
    return;
  }
  const std::string stiff = diagram_stiffness(hb, bands.front().omega_lo);
  if (!stiff.empty()) {
    run.say(model_.name + ": " + stiff);
    return;
  }
  auto rad_s = [](double w) { return w; };
  run.say(model_.name + ": " + diagram_bands_text(bands, rad_s, "rad/s"));
  const BifurcationDiagram d = diagram_of_bands(run, hb, c, bands, model_.diagram.options, "bifurcation_diagram", "");
  diagram_key_numbers(run.key_numbers(), d, "");
  run.key_numbers().add("diagram_bands", double(bands.size()), "-");
  const std::vector<DiagramPoint> off = diagram_off_branch_orbits(hb, c, r.branches, d, model_.diagram.options.period_tol);
  off_branch_key_numbers(run.key_numbers(), off, "");
  run.say(model_.name + ": " + diagram_summary(d, rad_s, "rad/s"));
  orbit_branches(run, r, off);
  const std::vector<PeriodDoubledBranch>& pd = r.branches;
  Table t(bifurcation_columns({"omega", "band"}, "x"));
  const SectionOrbits orbits = run.timed("HB orbits at the diagram's speeds", [&] { return section_orbits(hb, c, pd, d); });
  const BifurcationDiagram from_hb = diagram_from_hb_orbits(run, hb, c, pd, orbits, d, model_.diagram.options);
  for (const BifurcationDiagram* e : {&d, &from_hb})
    add_bifurcation_rows(t, *e, model_.output, 1.0, [&](double w) { return std::vector<Table::Cell>{w, band_of(bands, w)}; });
  run.write("bifurcation_diagram.csv", t);
  Table h(hb_section_columns({"omega", "period", "branch"}, "x"));
  add_hb_section_rows(h, hb, c, pd, orbits, model_.output, 1.0,
                      [](double w, int p, int b) { return std::vector<Table::Cell>{w, long(p), long(b)}; });
  run.write("bifurcation_diagram_hb.csv", h);
}

// Step 4b (issue 34): the HB branches through the diagram's periodic orbits of period 1 or 2 that
// lie on none of the run's branches (`off`: those diagram_off_branch_period1, _period2 count, found
// and polished once in step 4: diagram_off_branch_orbits), as ch. 6
// continues Fig. 41's (app/orbit_branches.hpp): from the first such orbit (up sweep, then down)
// branch_from_orbit solves HB from its Fourier coefficients, checks it against the orbit within
// HB's own error and continues it both ways over the range with the sweep's options (stability,
// bifurcations); an orbit on a branch found so far starts none (at most 4 branches). Each takes
// the next branch id in frc.csv and bifurcations.csv; one that starts on a branch the run has is
// not added (known_branch_holding). Key numbers: orbit_branches, off_curve_orbits_left (orbits
// off every branch that started none), off_curve_orbits_on_known (whose branch is one the run
// has: off_every_branch missed it at that speed), and per branch k
// (orbit_branch_*_<k>) orbit_branch_numbers ("x": the output coordinate), orbit_branch_isola, and
// orbit_branch_checks (the diagram's off-branch orbits on it within HB's own error; its stability
// against the GSL monodromy of the integrated orbits and at up to 3 of its unstable points); the
// ranges with no stable period-1 orbit on any period-1 branch, unstable_period1_*_all_branches,
// and their unresolved stretches, unresolved_period1_*_all_branches (period1_ranges).
void FrequencyResponseFromFile::orbit_branches(Run& run, Response& r, const std::vector<DiagramPoint>& off) const {
  const std::vector<OrbitBranch> found = orbit_branches_of_diagram(
      run, model_.name, r.hb, r.c, r.branches, off, r.o, model_.diagram.options.period_tol, model_.output, "x", "");
  add_unstable_period1_ranges(run.key_numbers(), period1_ranges(r.o.omega_min, r.o.omega_max, period1_curves(r.c, found)),
                              "_all_branches");
}

// Step 5 (with the file's torus key): the torus branches, their ids after every other branch's.
void FrequencyResponseFromFile::quasi_periodic(Run& run, Response& r) const {
  if (model_.torus_on) r.tori = torus_branches(run, r.hb, r.c, r.o, int(r.branches.size()) + 1);
}

// Step 6: the tables of every branch. frc.csv (app/tables.hpp dof_response_table): the curve
// (period 1, branch 0), then each other branch with points under its id; bifurcations.csv: each
// branch's events, the branch each PD or NS point starts (starts_branch).
void FrequencyResponseFromFile::tables(Run& run, const Response& r) const {
  std::vector<int> starts = branch_starts(r.c, r.branches);
  if (model_.torus_on) add_torus_starts(starts, r.tori, int(r.branches.size()) + 1);
  Table frc = dof_response_table(r.hb, r.c, model_.output, table_progress(run, r.c, model_.name));
  Table bif = bifurcation_table(r.c, {}, starts);
  for (std::size_t k = 0; k < r.branches.size(); ++k) {
    const PeriodDoubledBranch& b = r.branches[k];
    if (!has_points(b)) continue;
    const BranchLabel label{b.period, int(k) + 1};
    frc.append(dof_response_table(*b.model, b.curve, model_.output, {}, label));
    bif.append(bifurcation_table(b.curve, label, branch_starts(b.curve, r.branches, int(k))));
  }
  run.write("frc.csv", frc);
  run.write("bifurcations.csv", bif);
}

// Step 5, its branches: quasi-periodic motion past each Neimark-Sacker point,
// a torus branch by two-frequency harmonic balance (hb/quasi_periodic.hpp); torus.csv (app/tables.hpp)
// and key numbers per branch: where it starts (the NS point), the Floquet second frequency
// there (alpha omega / 2 pi), its points, where it ends and its omega2 there, each under its
// branch id (first_id, first_id + 1, ...); a branch that fails says where and why.
std::vector<TorusBranch> FrequencyResponseFromFile::torus_branches(Run& run, const HarmonicBalance& hb,
                                                                   const FrequencyCurve& c, const SweepOptions& o,
                                                                   int first_id) const {
  const TorusOptions& to = model_.torus;
  const TorusBalance tb(hb, to.harmonics1, to.harmonics2, to.lines);
  std::vector<TorusBranch> br = run.timed("torus branches", [&] { return gearhb::torus_branches(tb, c, o, to); });
  TorusStabilityOptions so = model_.torus_stability;
  so.integration.x_scale = c.scaling.x.cwiseAbs().maxCoeff();
  // skipped, said in one line, where the explicit integration is stiff (as ch. 6's diagram)
  const double stiff = fastest_rate(hb) * 2.0 * M_PI / std::min(model_.omega_from, model_.omega_to);
  if (stiff > 1e4 && so.every > 0) {
    run.say(model_.name + ": no torus stability: the time integration is stiff (fastest rate x period " +
            std::to_string(stiff) + " > 1e4)");
    so.every = 0;
  }
  run.timed("torus stability", [&] {
    for (TorusBranch& b : br) add_torus_stability(tb, b, so);
    return 0;
  });
  run.write("torus.csv", torus_table(tb, br, model_.output, first_id));
  KeyNumbers& key = run.key_numbers();
  key.add("torus_branches", double(br.size()), "-");
  for (std::size_t k = 0; k < br.size(); ++k) {
    const std::string id = std::to_string(first_id + int(k));
    run.say(model_.name + ": " + br[k].why + " (" + std::to_string(br[k].points.size()) + " points)");
    key.add("torus_omega_ns_" + id, br[k].omega_ns, "rad/s");
    if (std::isfinite(br[k].omega2_ns)) key.add("torus_omega2_floquet_" + id, br[k].omega2_ns, "rad/s");
    key.add("torus_points_" + id, double(br[k].points.size()), "-");
    if (br[k].points.empty()) continue;
    key.add("torus_omega_end_" + id, br[k].omega_end, "rad/s");
    key.add("torus_omega2_end_" + id, br[k].points.back().omega2, "rad/s");
    torus_stability_key_numbers(key, br[k], id);
  }
  return br;
}

// A torus branch's points by the flow's verdict (hb/quasi_periodic.hpp torus_stability):
// torus_stable_points_<id>, torus_unstable_points_<id>, torus_unresolved_points_<id>.
void torus_stability_key_numbers(KeyNumbers& key, const TorusBranch& b, const std::string& id) {
  int count[3] = {0, 0, 0};
  for (const TorusPoint& p : b.points)
    if (p.stability.computed) ++count[int(p.stability.verdict)];
  key.add("torus_stable_points_" + id, count[int(TorusStability::Verdict::stable)], "-");
  key.add("torus_unstable_points_" + id, count[int(TorusStability::Verdict::unstable)], "-");
  key.add("torus_unresolved_points_" + id, count[int(TorusStability::Verdict::unresolved)], "-");
}

// Step 7: DIR/frc.png by figures/frc.py (the project's figure style).
void FrequencyResponseFromFile::draw(Run& run) const {
  draw_with_script(run, std::string(GEARHB_FIGURES_DIR).empty() ? "" : std::string(GEARHB_FIGURES_DIR) + "/frc.py", "frc.png");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("gearhb_frc",
              "gearhb_frc: the frequency response of your own system, from a model file\n"
              "  M x'' + C x' + K x + sum_i d_i max(kc_i (g_i + d_i' x), 0) = f0 + fc cos(omega t) + fs sin(omega t)\n"
              "Writes DIR/frc.csv (with the period-2 and, at period_doubling.depth 2, period-4 branches, and the\n"
              "branches continued from the diagram's orbits off every branch: columns period, branch),\n"
              "bifurcations.csv,\n"
              "modes.csv, key_numbers.json, params.json (the resolved model), timings.csv (wall time per step)\n"
              "and frc.png; where some range has no stable period-1 orbit (or with bifurcation_diagram.range\n"
              "whole) also bifurcation_diagram.csv, bifurcation_diagram_hb.csv and bifurcation_diagram.png;\n"
              "with the torus key also torus.csv (quasi-periodic branches).\n\n" +
                  model_file_help());
  FrequencyResponseFromFile program(study);
  return study.run(argc, argv, [&](Run& run) { program.run(run); });
}
