#pragma once
// The `bifurcation_diagram` key that gearhb_frc's model file and gearhb_gear's gear file
// share (issue 34 §3): absent, the diagram is not computed (existing runs unchanged);
// present, an object of the options of hb/bifurcation_diagram.hpp, each optional with the
// library's default:
//
//   "bifurcation_diagram": {"speeds": 200, "transient_periods": 400, "periods": 64,
//                           "max_period": 8, "period_tol": 1e-6,
//                           "lyapunov_periods": 200, "lyapunov_threshold": 0.02}
//
// An option out of range is a UsageError naming the key (exit 2). And the table both
// programs write, bifurcation_diagram.csv: one row per Poincare point.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gearhb/app/output.hpp"
#include "gearhb/app/study.hpp"
#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/frequency_sweep.hpp"

namespace gearhb {

struct BifurcationDiagramInput {
  bool on = false;
  BifurcationDiagramOptions options;
};

BifurcationDiagramInput read_bifurcation_diagram(const nlohmann::json& root, const std::string& file);

// --help text of the key.
std::string bifurcation_diagram_help();

// The `period_doubling` key both programs share (issue 34 §1): {"depth": 0 | 1 | 2}, absent or
// without depth: 1. 0: no branch switching; 1: a period-2 branch by harmonic balance from each
// located period doubling of every period-1 curve; 2: also a period-4 branch from each located
// period doubling of every period-2 branch (hb/period_doubling.hpp period_doubling_cascade). A
// depth out of range or another key is a UsageError naming the key (exit 2).
constexpr int max_period_doubling_depth = 2;
int read_period_doubling_depth(const nlohmann::json& root, const std::string& file);
std::string period_doubling_help();

// The rows of one diagram: the cells `lead(omega)` (the program's frequency columns), then
// sweep (up | down), the value scale q' x of each Poincare point, motion, n and lyapunov
// (empty where not computed). A period-n point writes its n distinct points (the others repeat
// them within period_tol), any other all its recorded points, a failed one none.
void add_bifurcation_rows(Table& t, const BifurcationDiagram& d, const Eigen::VectorXd& q, double scale,
                          const std::function<std::vector<Table::Cell>(double)>& lead);
// The HB branch at the same section (phase 0), to draw under the Poincare points and to check
// them (bifurcation_diagram_hb.csv): the cells `lead(omega)`, then scale q' x(phase 0), its
// Floquet stability (1 | 0) and point: `branch` for every point of the branch (in continuation
// order), then `speed` for the HB orbit at each speed of the diagram's grid on every segment of
// the branch stable at both ends that brackets it (solved by Newton at that speed);
// hb_section_columns: the lead columns, `value`, stable, point.
void add_hb_section_rows(Table& t, const HarmonicBalance& hb, const FrequencyCurve& c, const BifurcationDiagram& d,
                         const Eigen::VectorXd& q, double scale,
                         const std::function<std::vector<Table::Cell>(double)>& lead);
std::vector<std::string> hb_section_columns(std::vector<std::string> lead, const std::string& value);

// The diagram over [lo, hi] as a step of a program run: from the HB orbit at the curve's lowest
// frequency, x_scale the curve's largest DOF scale, timed as `step`, progress lines beginning
// with `label`.
BifurcationDiagram diagram_of_curve(Run& run, const HarmonicBalance& hb, const FrequencyCurve& c, double lo, double hi,
                                    BifurcationDiagramOptions o, const std::string& step, const std::string& label);

// Key numbers of a diagram, each name ending in `suffix` ("" or "_<i>"): the speeds (both
// sweeps counted) of each motion, diagram_<motion>_speeds, and the largest period seen,
// diagram_max_period.
void diagram_key_numbers(KeyNumbers& key, const BifurcationDiagram& d, const std::string& suffix);

// One line for the console: the speeds of each motion over both sweeps, the largest period,
// and per sweep the span of speeds that are not period 1 (first to last), in the program's
// unit: `speed(omega)` and `unit` (e.g. rpm).
std::string diagram_summary(const BifurcationDiagram& d, const std::function<double(double)>& speed,
                            const std::string& unit);

// The column names after the lead ones, the value column named `value`.
std::vector<std::string> bifurcation_columns(std::vector<std::string> lead, const std::string& value);

}  // namespace gearhb
