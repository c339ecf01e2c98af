// Quasi-periodic motion by two-frequency harmonic balance (issue 34 §2,
// hb/quasi_periodic.hpp) on programs/gearhb_frc/examples/nlvib_ex03_torus.json's model
// (NLvib example 03, C = 0.06 K, forcing 0.06; the period-1 sweep 0.59 -> 0.63 outside the
// timing): one residual with its Jacobian (H1 = 21, H2 = 4: 774 unknowns, 36 lines), and the
// whole torus branch from the upper NS point to where it ends, and the flow's stability test of
// one torus point. Times go to
// programs/gearhb_frc/README.md.
#include <benchmark/benchmark.h>

#include "gearhb/hb/quasi_periodic.hpp"

using namespace gearhb;

namespace {
HarmonicBalance model() {
  Eigen::MatrixXd K(2, 2);
  K << 1, -1, -1, 2;
  Eigen::VectorXd e1 = Eigen::VectorXd::Zero(2), fc = Eigen::VectorXd::Zero(2);
  e1[0] = 1.0;
  fc[1] = 0.06;
  return HarmonicBalance({Eigen::MatrixXd::Identity(2, 2), 0.06 * K, K}, {{e1, 100.0, -1.0, {}}},
                         {Eigen::VectorXd::Zero(2), fc, Eigen::VectorXd::Zero(2)}, 21);
}
SweepOptions range() {
  SweepOptions o;
  o.omega_min = 0.59;
  o.omega_max = 0.63;
  return o;
}
// The model, its period-1 curve (outside the timing), the upper NS point (0.6147), H1 = 21.
struct Ex03 {
  HarmonicBalance hb = model();
  SweepOptions o = range();
  FrequencyCurve c = sweep_frequency(hb, o, "bench");
  std::size_t upper = 0;
  TorusOptions to;
  Ex03() {
    for (std::size_t i = 0; i < c.bifurcations.size(); ++i)
      if (c.bifurcations[i].type == BifurcationType::neimark_sacker && c.bifurcations[i].omega > 0.61) upper = i;
    to.harmonics1 = 21;
  }
};
}  // namespace

static void BM_torus_residual_and_jacobian(benchmark::State& state) {
  const HarmonicBalance hb = model();
  const TorusBalance tb(hb, 21, 4);
  const FrequencyCurve c = sweep_frequency(hb, range(), "bench");
  Eigen::VectorXd X = tb.from_periodic(c.branch.points[c.branch.points.size() / 2].X), R, dw, dw2;
  for (int i = 0; i < X.size(); ++i) X[i] += 0.01 * std::sin(1.3 * i);
  Eigen::MatrixXd J;
  for (auto _ : state) tb.evaluate(X, 0.612, 0.14, R, &J, &dw, &dw2);
  state.counters["unknowns"] = double(tb.size());
}
BENCHMARK(BM_torus_residual_and_jacobian)->Unit(benchmark::kMillisecond);

static void BM_torus_branch_ex03(benchmark::State& state) {
  const Ex03 e;
  const TorusBalance tb(e.hb, e.to.harmonics1, e.to.harmonics2);
  std::size_t points = 0;
  for (auto _ : state) points = torus_branch(tb, e.c, e.upper, e.o, e.to).points.size();
  state.counters["points"] = double(points);
}
BENCHMARK(BM_torus_branch_ex03)->Unit(benchmark::kSecond)->Iterations(1);

// The flow's stability test of one torus point (torus_stability: the two largest Lyapunov
// exponents over 400 forcing periods of variational equations, rk8pd at 1e-10): the 11th point
// of the upper branch (omega 0.6141, stable), the branch outside the timing.
static void BM_torus_stability_point_ex03(benchmark::State& state) {
  Ex03 e;
  e.to.max_points = 11;
  const TorusBalance tb(e.hb, e.to.harmonics1, e.to.harmonics2);
  const TorusBranch b = torus_branch(tb, e.c, e.upper, e.o, e.to);
  TorusStabilityOptions so;
  so.integration.x_scale = e.c.scaling.x.cwiseAbs().maxCoeff();
  TorusStability s;
  for (auto _ : state) s = torus_stability(tb, b.points.back(), so);
  state.counters["omega"] = b.points.back().omega;
  state.counters["stable"] = s.verdict == TorusStability::Verdict::stable ? 1.0 : 0.0;
}
BENCHMARK(BM_torus_stability_point_ex03)->Unit(benchmark::kMillisecond);
