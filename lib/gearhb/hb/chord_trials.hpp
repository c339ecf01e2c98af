#pragma once
// Trial points on one chord of a branch (continuation.hpp point_on_chord), warm-started.
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/continuation.hpp"

namespace gearhb {

// The trial points of a search on one chord a -> b (locate_state_change, the period-2 branch
// point and merge searches): the point at chord fraction t as point_on_chord gives it (the same
// hyperplane, normal to the chord through the chord point), its corrector started from the
// converged trial nearest in t shifted along the chord, y_j + (t - t_j)(y_b - y_a), which lies
// in that hyperplane. From a (t_j = 0) or b (t_j = 1) that is the chord point itself, so the
// first trial is point_on_chord's; inside a bracket narrowed to w the start is off the branch by
// about w (not the chord's sag), and the corrector needs fewer iterations.
class ChordTrials {
 public:
  ChordTrials(const ParametricProblem& p, const BranchPoint& a, const BranchPoint& b, const Scaling& s,
              double corrector_tolerance = 1e-10);
  BranchPoint at(double t);   // throws if the corrector fails, as point_on_chord
 private:
  const ParametricProblem& p_;
  const Scaling& s_;
  double tolerance_;
  Eigen::VectorXd ya_, chord_;
  std::vector<std::pair<double, Eigen::VectorXd>> done_;   // converged trials: (t, scaled y)
  std::unique_ptr<Linearization> last_;   // the last trial's last linearization (Linearization::reuse)
};

}  // namespace gearhb
