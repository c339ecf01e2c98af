// The bordered solves of continuation (core/newton.hpp Linearization): the
// condensed HarmonicBalance solve (harmonic_balance.cpp) against the dense LU of
// the same (n+1) x (n+1) matrix, on states with open, intermittent and full
// contact, two contacts, a free rigid-body mode a contact holds and a fold.
#include <gtest/gtest.h>

#include <random>

#include "gearhb/core/fourier.hpp"
#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "test_models.hpp"

using namespace gearhb;

namespace {

// max |dy_condensed - dy_dense| / max |dy_dense| for a random border row and right-hand side
double condensed_vs_dense(const HarmonicBalance& hb, const Eigen::VectorXd& X, double w, const Scaling& s,
                          unsigned seed, bool expect_condensed = true) {
  Eigen::VectorXd R, dRdomega, R2;
  const auto lin = hb.linearize(X, w, s, R, dRdomega);
  Eigen::MatrixXd J;
  hb.evaluate(X, w, R2, &J, nullptr);
  EXPECT_LE((R - R2).cwiseAbs().maxCoeff(), 1e-14 * (1.0 + R.cwiseAbs().maxCoeff()));
  const DenseLinearization dense(J, dRdomega, s);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd row(hb.size() + 1), rhs(hb.size() + 1), a, b;
  for (Eigen::Index i = 0; i <= hb.size(); ++i) row[i] = u(gen), rhs[i] = u(gen);
  EXPECT_TRUE(lin->solve_bordered(row, rhs, a));
  EXPECT_EQ(lin->last_solve_structured(), expect_condensed);
  EXPECT_TRUE(dense.solve_bordered(row, rhs, b));
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

HarmonicBalance two_contacts(int H, bool rigid) {
  // three masses in a chain, a gap contact on mass 1 and one between masses 2 and 3;
  // rigid: no spring to ground (a free rigid-body mode, K singular)
  Eigen::MatrixXd K(3, 3);
  K << 2, -1, 0, -1, 2, -1, 0, -1, 1;
  if (rigid) K(0, 0) = 1;
  const Eigen::MatrixXd M = Eigen::Vector3d(1.0, 2.0, 0.5).asDiagonal();
  LinearSystem sys{M, 0.02 * K + 0.01 * M, K};
  UnilateralContact c1{Eigen::Vector3d(1, 0, 0), 50.0, -0.5, {}}, c2{Eigen::Vector3d(0, 1, -1), 20.0, -0.2, {}};
  Excitation f{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d(0.1, 0, 0)};
  return HarmonicBalance(sys, {c1, c2}, f, H);
}

}  // namespace

// Along NLvib ex. 03's branch (open, grazing, intermittent, near its folds) the two
// solves agree to round-off (1e-9 relative: the dense LU's own error grows with the
// condition number near the folds).
TEST(Linearization, CondensedMatchesDenseAlongNlvibEx03) {
  const HarmonicBalance hb = test_models::nlvib_ex03(21);
  SweepOptions o = test_models::nlvib_ex03_sweep(StabilityMethod::none);
  const FrequencyCurve c = sweep_frequency(hb, o, "ex03");
  ASSERT_TRUE(c.complete) << c.failure;
  double worst = 0.0;
  for (std::size_t i = 0; i < c.branch.points.size(); i += 5)
    worst = std::max(worst, condensed_vs_dense(hb, c.branch.points[i].X, c.branch.points[i].omega, c.scaling, unsigned(i)));
  EXPECT_LT(worst, 1e-9);
}

// Two contacts (P = 2, n = 3): the condensed system has 2 (2H+1) + 1 rows.
TEST(Linearization, CondensedMatchesDenseWithTwoContacts) {
  const HarmonicBalance hb = two_contacts(7, false);
  const Scaling s = hb.scaling(0.2, 2.0);
  for (double w : {0.3, 0.9, 1.4}) {
    Eigen::VectorXd X = linear_first_guess(hb, w);
    X *= 3.0;   // both contacts intermittent
    EXPECT_LT(condensed_vs_dense(hb, X, w, s, 7), 1e-10) << "omega = " << w;
  }
}

// One contact open over the whole period (its product matrix zero: the condensed solve drops
// it) and the other intermittent or shut, at states scaled from the closed-contact one; and
// both open. The condensed solve agrees with the dense LU of the full system.
TEST(Linearization, CondensedDropsAContactOpenAllPeriod) {
  const HarmonicBalance hb = two_contacts(6, false);
  const Scaling s = hb.scaling(0.2, 2.0);
  int open_states = 0;
  for (double w : {0.3, 0.9, 1.4})
    for (double scale : {0.0, 0.2, 1.0, 3.0}) {
      const Eigen::VectorXd X = scale * linear_first_guess(hb, w);
      int open = 0;
      for (std::size_t i = 0; i < 2; ++i) {
        const Eigen::VectorXd u = hb.penetration(X, i);
        double top = -INFINITY;
        for (int j = 0; j < 512; ++j) top = std::max(top, trig_series(u, 2.0 * M_PI * j / 512));
        open += top < 0.0 ? 1 : 0;
      }
      open_states += open > 0 ? 1 : 0;
      EXPECT_LT(condensed_vs_dense(hb, X, w, s, 11), 1e-10) << "omega = " << w << ", scale " << scale;
    }
  EXPECT_GE(open_states, 3) << "the check needs states with an open contact";
}

// K singular (a rigid-body mode that contact 1 holds: the transmission error of a gear pair
// on bearings): the static block of L cannot be factored until the contacts' mean stiffness
// is moved into it (and out of their product matrices); the solve stays condensed and
// agrees with the dense LU.
TEST(Linearization, RigidBodyModeHeldByAContactStaysCondensed) {
  const HarmonicBalance hb = two_contacts(5, true);
  const Scaling s = hb.scaling(0.2, 2.0);
  Eigen::VectorXd X = hb.closed_contact_solution(0.7);
  ASSERT_TRUE(X.allFinite());
  EXPECT_LT(condensed_vs_dense(hb, X, 0.7, s, 3), 1e-10);
  X *= 3.0;   // another state of the contacts
  EXPECT_LT(condensed_vs_dense(hb, X, 0.7, s, 4), 1e-10);
}

// No contact at all (a linear model, P = 0): the condensed system is the border row
// alone, L is solved block by block.
TEST(Linearization, NoContactIsSolvedByBlocks) {
  Eigen::MatrixXd K(2, 2);
  K << 2, -1, -1, 2;
  const LinearSystem sys{Eigen::MatrixXd::Identity(2, 2), 0.05 * K, K};
  const HarmonicBalance hb(sys, {}, Excitation{Eigen::Vector2d(0.1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 0)}, 4);
  const Scaling s = hb.scaling(0.5, 2.0);
  EXPECT_LT(condensed_vs_dense(hb, hb.open_contact_solution(1.1), 1.1, s, 11), 1e-12);
}
