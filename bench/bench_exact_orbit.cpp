// The exact periodic orbit behind an HB point (issue 25): the cost per point of
//  - BM_exact_correction: the shooting correction on the exact piecewise-linear flow with the
//    Floquet multipliers (floquet_of_hb_orbit, what every Floquet-stability point pays);
//  - BM_exact_measures: following the corrected orbit once more and measuring it (ExactOrbit:
//    x_max, x_min, RMS, first harmonic, mean; what the tables add per point);
//  - BM_gsl_monodromy: one GSL rk8pd period of the state and its variations
//    (TimeIntegrator::monodromy, tol 1e-10): the price of one Newton step of a shooting by GSL
//    integration, the alternative where the flow is not piecewise linear.
// Models (arg): 0 mass against the wall (n = 1, H = 10), 1 NLvib ex. 03 (n = 2, H = 10),
// 2 a chain of 6 masses with one contact (n = 6, H = 10), 3 the thesis gear mesh at 300 N m with
// 20 STE harmonics (n = 1, H = 20); each at the point of its curve with the largest x_max
// (in contact). Times go to chapters/ch02_methods/README.md.
#include <benchmark/benchmark.h>

#include <memory>
#include <stdexcept>

#include "gearhb/gears/dynamics/dte_model.hpp"
#include "gearhb/gears/pair/ste.hpp"
#include "gearhb/gears/pair/ste_continuous.hpp"
#include "gearhb/hb/exact_orbit.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

struct Case {
  std::unique_ptr<HarmonicBalance> hb;
  VectorXd X, q;
  double omega = 0.0, x_scale = 1.0;
};

HarmonicBalance chain(int n) {
  MatrixXd K = MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    K(i, i) = 2.0;
    if (i > 0) K(i, i - 1) = K(i - 1, i) = -1.0;
  }
  VectorXd e1 = VectorXd::Zero(n), fc = VectorXd::Zero(n);
  e1[0] = 1.0;
  fc[n - 1] = 0.1;
  return HarmonicBalance(LinearSystem{MatrixXd::Identity(n, n), 0.02 * K, K}, {UnilateralContact{e1, 10.0, -0.5, {}}},
                         Excitation{VectorXd::Zero(n), fc, VectorXd::Zero(n)}, 10);
}

HarmonicBalance model(int which) {
  switch (which) {
    case 0:
      return HarmonicBalance(LinearSystem{MatrixXd::Ones(1, 1), MatrixXd::Constant(1, 1, 0.01), MatrixXd::Ones(1, 1)},
                             {UnilateralContact{VectorXd::Ones(1), 1.0, -0.6, {}}},
                             Excitation{VectorXd::Zero(1), VectorXd::Constant(1, 0.01), VectorXd::Zero(1)}, 10);
    case 1: {
      MatrixXd K(2, 2);
      K << 1, -1, -1, 2;
      VectorXd e1 = VectorXd::Unit(2, 0), fc = 0.1 * VectorXd::Unit(2, 1);
      return HarmonicBalance(LinearSystem{MatrixXd::Identity(2, 2), 0.03 * K, K}, {UnilateralContact{e1, 100.0, -1.0, {}}},
                             Excitation{VectorXd::Zero(2), fc, VectorXd::Zero(2)}, 10);
    }
    case 2: return chain(6);
    default: {
      SteModel m;
      const std::vector<double> e = ste_values(ste_continuous(m, 300.0, 64));
      DteGear g;
      g.F0 = 300.0 / m.gear.pitch_radius();
      g.me = equivalent_mass(0.0158, 0.0158, m.gear.pitch_radius(), m.gear.pitch_radius());
      g.kc = mean_stiffness(e, g.F0);
      g.c = mesh_damping(0.08, g.kc, g.me);
      g.ste = periodic_fourier(e, 20);
      return dte_harmonic_balance(g, 20);
    }
  }
}

// The model's curve (no stability) and its point with the largest x_max.
const Case& the_case(int which) {
  static std::unique_ptr<Case> cases[4];
  if (cases[which]) return *cases[which];
  auto c = std::make_unique<Case>();
  c->hb = std::make_unique<HarmonicBalance>(model(which));
  const double range[4][2] = {{0.5, 2.0}, {0.5, 0.8}, {0.3, 0.6}, {2 * M_PI * 2000, 2 * M_PI * 3600}};
  SweepOptions o;
  o.omega_min = range[which][0];
  o.omega_max = range[which][1];
  o.stability = StabilityMethod::none;
  o.continuation.ds_max = 0.05;
  const FrequencyCurve curve = sweep_frequency(*c->hb, o, "bench");
  c->q = VectorXd::Unit(c->hb->dofs(), 0);
  const ResponseEvaluator ev(*c->hb, c->q);
  double top = -INFINITY;
  for (const auto& p : curve.branch.points) {
    const double x = ev.summarize(p.X).x_max;
    if (x > top) top = x, c->X = p.X, c->omega = p.omega;
  }
  c->x_scale = curve.scaling.x[0];
  cases[which] = std::move(c);
  return *cases[which];
}

}  // namespace

static void BM_exact_correction(benchmark::State& state) {
  const Case& c = the_case(int(state.range(0)));
  for (auto _ : state) {
    const FloquetResult r = floquet_of_hb_orbit(*c.hb, c.X, c.omega, c.x_scale);
    if (!r.corrected) state.SkipWithError("not corrected");
    state.counters["newton_steps"] = r.newton_steps;
    benchmark::DoNotOptimize(r.x0.data());
  }
}
BENCHMARK(BM_exact_correction)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

static void BM_exact_measures(benchmark::State& state) {
  const Case& c = the_case(int(state.range(0)));
  const FloquetResult r = floquet_of_hb_orbit(*c.hb, c.X, c.omega, c.x_scale);
  for (auto _ : state) {
    const ExactOrbit o(*c.hb, c.X, c.omega, r.x0, r.v0);
    const ExactMeasures m = o.measures(c.q);
    benchmark::DoNotOptimize(m.x_max);
    state.counters["pieces"] = double(o.pieces());
    state.counters["pade_states"] = o.pade_states();
  }
}
BENCHMARK(BM_exact_measures)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

static void BM_gsl_monodromy(benchmark::State& state) {
  const Case& c = the_case(int(state.range(0)));
  const FloquetResult r = floquet_of_hb_orbit(*c.hb, c.X, c.omega, c.x_scale);
  const TimeIntegrator ti(*c.hb);
  TimeIntegrationOptions opt;
  opt.x_scale = c.x_scale;
  for (auto _ : state) {
    try {
      const MatrixXd Phi = ti.monodromy(r.x0, r.v0, c.omega, opt);
      benchmark::DoNotOptimize(Phi.data());
    } catch (const std::runtime_error& e) {   // reported, not hidden: GSL gives up on this model
      state.SkipWithError(e.what());
      break;
    }
  }
}
BENCHMARK(BM_gsl_monodromy)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
