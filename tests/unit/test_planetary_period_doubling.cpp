// The period-2 branch of a planetary set (issue 34 §1 for gearhb_planetary): the loaded
// Lin-Parker set of programs/gearhb_planetary/examples/lin_parker_1999_loaded_pd.json (five
// planets, rectangular-wave meshes, H = 8), its band widened to 1500 Hz so the branch passes its
// first folds, switched at the period doubling as the program switches it (the meshes' stiffness
// varies, so the switch takes the variational equation about the HB orbit; before, it stopped
// with "a time-varying contact stiffness has no exact flow" and the branch had no points). The
// branch's own multipliers are not computed here (their cost is not the check).
//
// The independent check is GSL rk8pd time integration of the ORIGINAL (period-1) set at the
// forcing mesh frequency, no harmonic balance in its answer: Newton shooting over two mesh
// periods, P(P(y)) = y with P the integrated one-period map (TimeIntegrator::poincare; its
// Jacobian from TimeIntegrator::monodromy at a looser tolerance, which only slows Newton), from
// the HB period-2 state at the branch's point farthest from period 1 (largest odd part, 1 Hz or
// more from the branch's turns). The orbit it finds (i) repeats after two mesh periods and not
// after one, by HB's own half-period jump to within a factor 2 (HB's error at H = 8 is ~15 % of
// the orbit), and (ii) is the HB period-2 orbit within HB's own error: their distance falls by
// more than half when H doubles (8 -> 16, the H = 16 period-2 orbit solved by Newton at the same
// frequency from the H = 8 one; each H against the integration of its own model, whose mesh
// waves are cut to H harmonics), as a truncation error does and a wrong period-2 model would
// not. Measured: 1.5e-1 at H = 8, 1.8e-3 at H = 16, at 1484.4 Hz; one-period mismatch 8.4e-3
// against HB's jump 7.9e-3. About 12 s of CPU (the curve's first point inside contact loss and
// the 47-point branch take most of it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/newton.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/period_doubling.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "gearhb/tools/planetary_file.hpp"
#include "gearhb/tools/planetary_sweep.hpp"

using namespace gearhb;

namespace {

// The shooting over two forcing periods of hb (the period-1 set) at omega from the period-2
// HB point (X2, Omega = omega / 2) of hb2. Returns the converged state y = (x0, v0), its
// mismatch after two periods (scaled by xs; velocities / omega) and its displacement's after one.
struct TwoPeriodOrbit {
  bool converged = false;
  Eigen::VectorXd x0, v0;
  double one_period = 0.0, two_periods = 0.0;
};
TwoPeriodOrbit shoot_two_periods(const HarmonicBalance& hb, const HarmonicBalance& hb2, const Eigen::VectorXd& X2,
                                 double omega, double xs) {
  const int n = hb.dofs();
  const TimeIntegrator ti(hb);
  TimeIntegrationOptions to, coarse;
  to.x_scale = coarse.x_scale = xs;
  coarse.rel_tol = 1e-7;   // the Jacobian only: its error slows Newton, never moves the answer
  coarse.abs_tol = 1e-9;
  TwoPeriodOrbit r;
  hb_initial_state(hb2, X2, omega / 2.0, r.x0, r.v0);
  for (int it = 0; it < 8; ++it) {
    Eigen::MatrixXd xp, vp;
    ti.poincare(r.x0, r.v0, omega, 0, 2, to, xp, vp);
    Eigen::VectorXd F(2 * n);
    F << xp.row(2).transpose() - r.x0, vp.row(2).transpose() - r.v0;
    r.two_periods = std::max(F.head(n).cwiseAbs().maxCoeff(), F.tail(n).cwiseAbs().maxCoeff() / omega) / xs;
    r.one_period = (xp.row(1).transpose() - r.x0).cwiseAbs().maxCoeff() / xs;
    if (r.two_periods < 1e-9) {
      r.converged = true;
      break;
    }
    const Eigen::MatrixXd Phi = ti.monodromy(xp.row(1).transpose(), vp.row(1).transpose(), omega, coarse) *
                                ti.monodromy(r.x0, r.v0, omega, coarse);
    const Eigen::VectorXd dy = (Phi - Eigen::MatrixXd::Identity(2 * n, 2 * n)).partialPivLu().solve(-F);
    r.x0 += dy.head(n);
    r.v0 += dy.tail(n);
  }
  return r;
}

// The largest distance over two mesh periods between the HB period-2 orbit and the integrated
// orbit through (x0, v0), over the HB orbit's largest oscillation (AC amplitude of any DOF).
double orbit_distance(const HarmonicBalance& hb, const HarmonicBalance& hb2, const Eigen::VectorXd& X2, double omega,
                      const TwoPeriodOrbit& o, double xs) {
  const int n = hb.dofs(), S = 256;
  TimeIntegrationOptions to;
  to.x_scale = xs;
  to.samples_per_period = S;
  const Eigen::MatrixXd x = TimeIntegrator(hb).sample(o.x0, o.v0, omega, 0, 2, to);   // 2 S x n
  double err = 0.0, amp = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd c = hb2.project(X2, Eigen::VectorXd::Unit(n, i));
    double lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < 2 * S; ++j) {
      const double v = trig_series(c, M_PI * j / S);   // Omega t = pi j / S over two mesh periods
      err = std::max(err, std::fabs(v - x(j, i)));
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    amp = std::max(amp, 0.5 * (hi - lo));
  }
  return err / amp;
}

}  // namespace

TEST(PlanetaryPeriodDoubling, PeriodTwoBranchIsATwoPeriodOrbitOfTheIntegratedSet) {
  PlanetaryFile f = read_planetary_file(
      std::string(GEARHB_SOURCE_DIR) + "/programs/gearhb_planetary/examples/lin_parker_1999_loaded_pd.json", {});
  f.response.f_mesh_hz_to = 1500.0;   // beyond the branch's first fold (1496.2 Hz), where its odd part grows
  const HarmonicBalance hb = planetary_response_model(f);
  const SweepOptions o = planetary_sweep_options(f);
  const FrequencyCurve c = planetary_response_with_stability(hb, o, "band");
  ASSERT_TRUE(std::any_of(c.bifurcations.begin(), c.bifurcations.end(),
                          [](const Bifurcation& b) { return b.type == BifurcationType::period_doubling; }))
      << "no period doubling located in the example's band";
  // the branch without its points' multipliers (the program's switch; their cost is not the check)
  SweepOptions ob = planetary_stability_options(o);
  ob.stability = StabilityMethod::none;
  const std::vector<PeriodDoubledBranch> br = period_doubled_branches(hb, c, ob);
  ASSERT_FALSE(br.empty());
  const PeriodDoubledBranch& b = br.front();
  ASSERT_TRUE(has_points(b)) << b.why;
  EXPECT_EQ(b.period, 2);
  // the point of the branch farthest from period 1 (largest odd part) at least 1 Hz of mesh
  // frequency from each of its turning points (where the H = 16 orbit, solved at the same
  // frequency, could lie beyond the turn)
  const auto& P = b.curve.branch.points;
  std::vector<double> turns;
  for (std::size_t i = 1; i + 1 < P.size(); ++i)
    if ((P[i].omega - P[i - 1].omega) * (P[i + 1].omega - P[i].omega) < 0.0) turns.push_back(P[i].omega);
  std::size_t at = 0;
  double largest = 0.0;
  for (std::size_t i = 1; i < P.size(); ++i) {
    bool clear = true;
    for (double w : turns) clear = clear && std::fabs(2.0 * (P[i].omega - w)) > 2.0 * M_PI * 1.0;
    const double odd = subharmonic_part(*b.model, 2, P[i].X).norm();
    if (clear && odd > largest) largest = odd, at = i;
  }
  ASSERT_GT(largest, 0.0) << "no point of the branch away from its folds";
  const double omega = 2.0 * P[at].omega, xs = c.scaling.x[0];
  // HB's own jump over one mesh period: x(T) - x(0) of the period-2 orbit
  const Eigen::VectorXd X8 = P[at].X;
  double jump = 0.0;
  for (int i = 0; i < hb.dofs(); ++i) {
    const Eigen::VectorXd ci = b.model->project(X8, Eigen::VectorXd::Unit(hb.dofs(), i));
    jump = std::max(jump, std::fabs(trig_series(ci, M_PI) - trig_series(ci, 0.0)));
  }
  jump /= xs;
  // H = 8, and H = 16 solved at the same frequency from it
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int H = 8 << k;
    PlanetaryFile fk = f;
    fk.response.harmonics = H;
    const HarmonicBalance hbk = planetary_response_model(fk);
    const std::shared_ptr<HarmonicBalance> hb2 = subharmonic_model(hbk, 2);
    Eigen::VectorXd X = Eigen::VectorXd::Zero(hb2->size());
    X.head(X8.size()) = X8;
    if (k > 0) {
      const NewtonReport nr = newton_solve(*hb2, X, omega / 2.0, hb2->scaling(omega / 2.0, omega / 2.0));
      ASSERT_TRUE(nr.converged) << "H = " << H << ": " << nr.message;
      EXPECT_GT(subharmonic_part(*hb2, 2, X).norm(), 0.5 * subharmonic_part(*b.model, 2, X8).norm())
          << "H = 16 fell back to the period-1 orbit";
    }
    const TwoPeriodOrbit orbit = shoot_two_periods(hbk, *hb2, X, omega, xs);
    ASSERT_TRUE(orbit.converged) << "H = " << H << ": the two-period shooting did not converge (" << orbit.two_periods << ")";
    // period 2, not 1: the integrated orbit's one-period mismatch is HB's jump, to HB's error
    EXPECT_GT(orbit.one_period, 0.5 * jump) << "H = " << H;
    EXPECT_LT(orbit.one_period, 2.0 * jump) << "H = " << H;
    err[k] = orbit_distance(hbk, *hb2, X, omega, orbit, xs);
    std::printf("period 2 at %.2f Hz, H = %d: one-period mismatch %.3e (HB's jump %.3e), HB vs integrated orbit %.3e\n",
                omega / (2.0 * M_PI), H, orbit.one_period, jump, err[k]);
  }
  EXPECT_LT(err[1], err[0] / 2.0);
}
