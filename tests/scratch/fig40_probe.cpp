// Probe of ch. 6 Fig. 40's grazing region (issue 34 §3, not a test; built on request:
// `cmake --build build --target fig40_probe_scratch && build/tests/fig40_probe_scratch [omega...]`).
// Fig. 40's diagram by time integration disagrees with the stable HB points at some speeds of
// 7.5-11.2 krad/s. Which view is right? For every HB orbit (H = 10) at a speed (Newton at the
// speed from both ends of every branch segment that brackets it, the chapter's continuation):
//  - hb10:   Delta at phase 0 of the HB orbit and the branch's stability flags at the segment's ends;
//  - shoot:  shooting Newton on the exact piecewise-linear flow from it (floquet_of_hb_orbit):
//            converged?, the critical multiplier of the corrected orbit, the HB orbit's distance to
//            it (hb_orbit_error x sum |T2_i|, in Delta) and the corrected orbit's Delta at phase 0;
//  - H = 14, 20, 30: Newton on the model with H harmonics started from the exact orbit's samples
//            (or the padded H = 10 orbit where the shooting failed), and the same shooting from it;
//  - stay:   GSL rk8pd started on the HB orbit and on the corrected orbit, 2000 periods: the
//            spread of Delta at phase 0 over the last 64 periods and its distance to the orbit's.
// Prints one block per speed.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "gearhb/core/newton.hpp"
#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "../unit/gear_pair_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

const GearPairParameters kGear;

HarmonicBalance fig40(int H) { return test_models::ch06_gear_pair(1e5, H); }

// The chapter's Fig. 40 curve (ch06 main.cpp: sweep(), Corrector): 2-62 krad/s, ds_max 0.005.
FrequencyCurve fig40_curve(const HarmonicBalance& hb) { return sweep_frequency(hb, test_models::ch06_sweep(), "fig40"); }

// Delta at phase 0 of the Poincare points of 64 periods after `transient` from (x0, v0): min, max.
void poincare_range(const HarmonicBalance& hb, const VectorXd& x0, const VectorXd& v0, double w, int transient,
                    double& lo, double& hi) {
  TimeIntegrationOptions o;
  o.x_scale = 1e-5;
  MatrixXd xs, vs;
  TimeIntegrator(hb).poincare(x0, v0, w, transient, 64, o, xs, vs);
  const VectorXd d = xs * gear_pair_T2(kGear);
  lo = d.minCoeff(), hi = d.maxCoeff();
}

// One period of the orbit through (x0, v0), 256 samples.
MatrixXd one_period(const HarmonicBalance& hb, const VectorXd& x0, const VectorXd& v0, double w) {
  TimeIntegrationOptions o;
  o.x_scale = 1e-5;
  o.rel_tol = 1e-12;
  o.abs_tol = 1e-13;
  o.samples_per_period = 256;
  return TimeIntegrator(hb).sample(x0, v0, w, 0, 1, o);
}

void higher_h(const MatrixXd& exact, const VectorXd& X10, bool use_exact, double w) {
  const VectorXd T2 = gear_pair_T2(kGear);
  for (int H : {14, 20, 30}) {
    const HarmonicBalance hb = fig40(H);
    VectorXd X = VectorXd::Zero(hb.size());
    if (use_exact) X = hb_unknowns_of_samples(hb, exact);
    else X.head(X10.size()) = X10;
    const Scaling s = hb.scaling(2000.0, 62000.0);
    const NewtonReport nr = newton_solve(hb, X, w, s, {1e-9, 40});
    if (!nr.converged) {
      std::printf("    H = %d: Newton failed (%s)\n", H, nr.message.c_str());
      continue;
    }
    VectorXd x0, v0;
    hb_initial_state(hb, X, w, x0, v0);
    const FloquetResult f = floquet_of_hb_orbit(hb, X, w, s.x[0]);
    std::printf("    H = %d: Delta0 %.6e, shooting %s, |mu| %.6f arg %.3f, orbit error %.3e, exact Delta0 %.6e\n", H,
                T2.dot(x0), f.corrected ? "ok" : "FAILED", f.modulus, f.angle, T2.cwiseAbs().sum() * f.orbit_error,
                f.corrected ? T2.dot(f.x0) : NAN);
  }
}

void probe(const HarmonicBalance& hb, const FrequencyCurve& c, double w) {
  const VectorXd T2 = gear_pair_T2(kGear);
  const auto& P = c.branch.points;
  std::vector<VectorXd> found;
  std::printf("omega = %g rad/s\n", w);
  for (std::size_t i = 1; i < P.size(); ++i) {
    if ((P[i - 1].omega - w) * (P[i].omega - w) > 0) continue;
    VectorXd X = P[i].X;
    if (!newton_solve(hb, X, w, c.scaling, {1e-9, 30}).converged) {
      X = P[i - 1].X;
      if (!newton_solve(hb, X, w, c.scaling, {1e-9, 30}).converged) continue;
    }
    bool seen = false;
    for (const VectorXd& Y : found) seen = seen || (Y - X).cwiseAbs().maxCoeff() < 1e-6 * c.scaling.x.maxCoeff();
    if (seen) continue;
    found.push_back(X);
    VectorXd x0, v0;
    hb_initial_state(hb, X, w, x0, v0);
    const FloquetResult f = floquet_of_hb_orbit(hb, X, w, c.scaling.x[0]);
    std::printf("  segment %zu-%zu (%.2f-%.2f, flags %d%d): HB Delta0 %.6e; shooting %s, |mu| %.6f arg %.3f, "
                "orbit error %.3e, exact Delta0 %.6e\n",
                i - 1, i, P[i - 1].omega, P[i].omega, int(c.stable[i - 1]), int(c.stable[i]), T2.dot(x0),
                f.corrected ? "ok" : "FAILED", f.modulus, f.angle, T2.cwiseAbs().sum() * f.orbit_error,
                f.corrected ? T2.dot(f.x0) : NAN);
    const MatrixXd exact = f.corrected ? one_period(hb, f.x0, f.v0, w) : MatrixXd();
    higher_h(exact, X, f.corrected, w);
    double lo, hi;
    poincare_range(hb, x0, v0, w, 2000, lo, hi);
    std::printf("    from the HB orbit, after 2000 periods: Delta0 in [%.6e, %.6e]\n", lo, hi);
    if (f.corrected) {
      poincare_range(hb, f.x0, f.v0, w, 2000, lo, hi);
      std::printf("    from the corrected orbit, after 2000 periods: Delta0 in [%.6e, %.6e]\n", lo, hi);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const HarmonicBalance hb = fig40(10);
  const FrequencyCurve c = fig40_curve(hb);
  std::printf("Fig. 40 curve: %zu points\n", c.branch.points.size());
  std::vector<double> speeds;
  for (int k = 1; k < argc; ++k) speeds.push_back(std::atof(argv[k]));
  if (speeds.empty()) speeds = {8150, 8200, 8250, 8650, 8700, 8750, 8800, 9150, 9200, 9300};
  for (double w : speeds) probe(hb, c, w);
  return 0;
}
