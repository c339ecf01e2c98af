// ===========================================================================
// gearhb_frc: the frequency response of your own system, from a model file
// ===========================================================================
//
//     M x'' + C x' + K x + sum_i d_i max(kc_i (g_i(theta) + d_i' x), 0) = f0 + fc cos(w t) + fs sin(w t)
//
// Any n-DOF system with unilateral contacts, described in JSON (model_file.hpp,
// README "Your own system from a file"); no C++ needed. The steps: read_model
// (in the study's checks, so a bad file exits 2 before anything is written),
// natural_frequencies, frequency_response, draw.
//
// Sample runs:
//   build/bin/gearhb_frc chapters/gearhb_frc/examples/nlvib_ex03.json --out /tmp/ex03
//   build/bin/gearhb_frc chapters/gearhb_frc/examples/mass_wall.json --set contacts.0.gap=-0.8
// ===========================================================================
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gearhb/app/model_file.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/app/tables.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"

#ifndef GEARHB_FIGURES_DIR
#define GEARHB_FIGURES_DIR ""
#endif

using namespace gearhb;

namespace {

class FrequencyResponseFromFile {
 public:
  explicit FrequencyResponseFromFile(Study& study);
  void run(Run& run);

 private:
  Study& study_;
  int plot_ = 1;
  ModelFile model_;

  void read_model();
  void natural_frequencies(Run& run) const;
  void frequency_response(Run& run) const;
  void draw(Run& run) const;
};

FrequencyResponseFromFile::FrequencyResponseFromFile(Study& study) : study_(study) {
  file_program(study, "MODEL.json", &plot_, [this] { read_model(); });
}

void FrequencyResponseFromFile::run(Run& run) {
  run.write_text("params.json", model_.resolved.dump(2) + "\n");
  natural_frequencies(run);
  frequency_response(run);
  if (plot_) draw(run);
}

// Step 1 (in the checks, before anything is written): the model file and the overrides.
void FrequencyResponseFromFile::read_model() {
  model_ = read_model_file(study_.positional(), study_.parameters().unregistered());
}

// Step 2: natural frequencies with every contact open and every contact closed.
void FrequencyResponseFromFile::natural_frequencies(Run& run) const {
  const LinearSystem& s = model_.system;
  Eigen::MatrixXd K_closed = s.K;
  for (const auto& c : model_.contacts) K_closed += c.kc * c.normal * c.normal.transpose();
  const Modes open = modal_analysis(s.M, s.K), closed = modal_analysis(s.M, K_closed);
  Table t({"mode", "omega_open", "omega_closed"});
  for (int i = 0; i < s.dofs(); ++i) {
    t.add_row({long(i + 1), open.omega[i], closed.omega[i]});
    run.key_numbers().add("omega_open_" + std::to_string(i + 1), open.omega[i], "rad/s");
    run.key_numbers().add("omega_closed_" + std::to_string(i + 1), closed.omega[i], "rad/s");
  }
  run.write("modes.csv", t);
}

// Step 3: one arc-length continuation over the range, every point's stability and contact.
void FrequencyResponseFromFile::frequency_response(Run& run) const {
  const HarmonicBalance hb = model_.harmonic_balance();
  SweepOptions o;
  o.omega_min = std::min(model_.omega_from, model_.omega_to);
  o.omega_max = std::max(model_.omega_from, model_.omega_to);
  o.continuation.ds_max = model_.ds_max;
  o.continuation.progress = run.progress_of(model_.name);
  o.direction = model_.omega_from > model_.omega_to ? SweepDirection::down : SweepDirection::up;
  const FrequencyCurve c = run.timed("sweep", [&] { return sweep_frequency(hb, o, model_.name); });
  // The lowest frequency of the curve where a contact first closes (if any does).
  const double onset = model_.contacts.empty() ? NAN : first_transition(hb, c, touches_somewhere(hb));
  if (std::isfinite(onset)) run.key_numbers().add("contact_onset_omega", onset, "rad/s");
  run.say(model_.name + ": " + c.branch.summary());
  if (!c.complete) throw std::runtime_error("the frequency response did not reach omega.to: " + c.failure);
  run.write("frc.csv", dof_response_table(hb, c.branch, c.stable, model_.output));
  run.write("bifurcations.csv", bifurcation_table(c));
  run.key_numbers().add("bifurcations", double(c.bifurcations.size()), "-");
  const ResponseEvaluator ev(hb, model_.output);
  double peak = ev.summarize(c.branch.points.front().X).x_max;
  for (const auto& p : c.branch.points) peak = std::max(peak, ev.summarize(p.X).x_max);
  KeyNumbers& key = run.key_numbers();
  key.add("complete", 1.0, "-");
  key.add("points", double(c.branch.points.size()), "-");
  key.add("folds", double(c.branch.folds.size()), "-");
  key.add("x_max_peak", peak, "m");
}

// Step 4: DIR/frc.png by figures/frc.py (the project's figure style).
void FrequencyResponseFromFile::draw(Run& run) const {
  draw_with_script(run, std::string(GEARHB_FIGURES_DIR).empty() ? "" : std::string(GEARHB_FIGURES_DIR) + "/frc.py", "frc.png");
}

}  // namespace

int main(int argc, char** argv) {
  Study study("gearhb_frc",
              "gearhb_frc: the frequency response of your own system, from a model file\n"
              "  M x'' + C x' + K x + sum_i d_i max(kc_i (g_i + d_i' x), 0) = f0 + fc cos(w t) + fs sin(w t)\n"
              "Writes DIR/frc.csv, modes.csv, key_numbers.json, params.json (the resolved model), frc.png.\n\n" +
                  model_file_help());
  FrequencyResponseFromFile program(study);
  return study.run(argc, argv, [&](Run& run) { program.run(run); });
}
