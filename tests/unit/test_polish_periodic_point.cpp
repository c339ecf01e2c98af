// polish_periodic_point (hb/bifurcation_diagram.hpp): a diagram's periodic point as the orbit it
// approaches, not its last recorded states. The Kahraman & Singh clearance oscillator at F_a = 0.1
// (gearhb_frc's examples/clearance_oscillator.json) at omega = 0.337519, 7e-5 past the period
// doubling at 0.337447 where the stable period-2 orbit is born: one speed of the diagram, started
// from the period-1 orbit of the speed before (0.331836, as the example's up sweep arrives), is
// classified period 2 while its states still carry the slowly decaying transient (a multiplier of
// the two-period map near +1). Checked by a second method, the exact piecewise-linear flow
// (matrix exponentials, floquet.hpp PiecewiseLinearFlow; not the GSL integration that polishes):
//  - the polished state returns onto itself after two forcing periods of the exact flow within
//    1e-8 (its shooting converged to 1e-2 x period_tol x_scale = 1e-8 on GSL's map);
//  - the last recorded state does not: it lies farther from the polished one than the
//    classifier's tolerance (measured 3.2e-6 against period_tol x_scale = 1.05e-6, after the
//    full 400 transient periods: that is what polishing removes);
//  - the polished cycle has least period 2 (its two states differ), and its two-period
//    monodromy on the exact flow has every multiplier inside the unit circle (it attracts).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/hb/bifurcation_diagram.hpp"
#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/time_integration.hpp"
#include "test_models.hpp"

using namespace gearhb;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// The exact flow's map over two forcing periods from (x, v): its end state and monodromy.
void exact_two_periods(const HarmonicBalance& hb, double omega, VectorXd& x, VectorXd& v, MatrixXd& M) {
  const PiecewiseLinearFlow flow(hb);
  const double T = 2.0 * M_PI / omega;
  std::vector<double> nodes;
  for (int k = 0; k < 256; ++k) nodes.push_back(T * k / 256.0);
  M = MatrixXd::Identity(2 * x.size(), 2 * x.size());
  for (int k = 0; k < 2; ++k) {
    VectorXd xT, vT;
    MatrixXd Phi;
    flow.period_map(x, v, omega, nodes, xT, vT, Phi);
    M = Phi * M;
    x = xT, v = vT;
  }
}

}  // namespace

TEST(PolishPeriodicPoint, SlowPeriod2TransientPastAPeriodDoubling) {
  const HarmonicBalance hb = test_models::kahraman_singh(0.1);
  const double omega = 0.337519, below = 0.331836;   // the example's up sweep: its speed before
  BifurcationDiagramOptions o;
  // the example's x_scale: its sweep's scaling over omega 0.3-2 (diagram_of_curve's, off_branch_orbits')
  o.integration.x_scale = hb.scaling(0.3, 2.0).x.cwiseAbs().maxCoeff();
  const double tol = o.period_tol * o.integration.x_scale;
  const TimeIntegrator ti(hb);
  const DiagramPoint before = diagram_point(hb, below, VectorXd::Constant(1, 1.1), VectorXd::Zero(1), o);
  ASSERT_EQ(before.motion, Motion::periodic);
  ASSERT_EQ(before.n, 1);
  DiagramPoint p = diagram_point(hb, omega, before.x.bottomRows(1).transpose(), before.v.bottomRows(1).transpose(), o);
  ASSERT_EQ(p.motion, Motion::periodic);
  ASSERT_EQ(p.n, 2);
  const VectorXd last_x = p.x.bottomRows(1).transpose(), last_v = p.v.bottomRows(1).transpose();
  DiagramPoint q = p;
  ASSERT_TRUE(polish_periodic_point(ti, q, tol, o.integration));
  ASSERT_EQ(q.x.rows(), 2);
  // a fixed point of the exact two-period map
  VectorXd x = q.x.row(0).transpose(), v = q.v.row(0).transpose();
  MatrixXd M;
  exact_two_periods(hb, omega, x, v, M);
  EXPECT_LT(std::max((x - q.x.row(0).transpose()).cwiseAbs().maxCoeff(),
                     (v - q.v.row(0).transpose()).cwiseAbs().maxCoeff() / omega), 1e-8);
  EXPECT_LT(M.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
  // of least period 2, and not where the recording stopped
  EXPECT_GT((q.x.row(1) - q.x.row(0)).cwiseAbs().maxCoeff(), 100.0 * tol);
  const double moved = std::max((last_x - q.x.row(0).transpose()).cwiseAbs().maxCoeff(),
                                (last_v - q.v.row(0).transpose()).cwiseAbs().maxCoeff() / omega);
  EXPECT_GT(moved, tol);
  std::printf("omega %.6f: transient %d periods, polished state moved %.3e from the last recorded (tol %.3e)\n", omega,
              p.transient, moved, tol);
}
