// 6-DOF gear pair (thesis ch. 6): matrices against the thesis' printed vectors and
// closed forms.
#include <cmath>

#include <gtest/gtest.h>

#include "gearhb/gears/pair/gear_pair.hpp"
#include "gearhb/hb/harmonic_balance.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/newton.hpp"

using namespace gearhb;

TEST(GearPair, T1IsMinusT2TransposedAndKcIsRankOneSymmetric) {
  GearPairParameters p;
  const Eigen::VectorXd T1 = gear_pair_T1(p), T2 = gear_pair_T2(p);
  EXPECT_LT((T1 + T2).norm(), 1e-15);   // thesis §6.1 prints both; T1 = -T2'
  const Eigen::MatrixXd Kc = gear_pair_mesh_stiffness(p);
  EXPECT_LT((Kc - Kc.transpose()).norm(), 1e-6);
  EXPECT_LT((Kc - p.kc * T2 * T2.transpose()).norm(), 1e-6 * p.kc);
  // Rigid rolling (rb1 th1 = rb2 th2, no translation) does not deflect the mesh.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6);
  q[2] = 1e-3;
  q[5] = 1e-3 * p.rb1 / p.rb2;
  EXPECT_NEAR(T2.dot(q), 0.0, 1e-18);
}

TEST(GearPair, OpenNaturalFrequenciesAreUncoupled) {
  GearPairParameters p;
  const Modes m = modal_analysis(gear_pair_mass(p), gear_pair_support_stiffness(p));
  std::vector<double> exact = {std::sqrt(1e8 / 0.66), std::sqrt(1e8 / 0.66), std::sqrt(1e8 / 0.4),
                               std::sqrt(1e8 / 0.4),  std::sqrt(1e9 / 0.61), std::sqrt(1e9 / 0.39)};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(m.omega[i], exact[i], 1e-9 * exact[i]);
}

TEST(GearPair, ClosedNaturalFrequenciesSolveTheSecularEquation) {
  // K + kc T2'T2 with K diagonal: each coupled w^2 solves
  // 1 + kc sum_i T2_i^2 / (k_i - w^2 m_i) = 0 (rank-one update, Golub 1973).
  GearPairParameters p;
  const Eigen::MatrixXd M = gear_pair_mass(p), K = gear_pair_support_stiffness(p);
  const Eigen::VectorXd T2 = gear_pair_T2(p);
  const Modes m = modal_analysis(M, K + gear_pair_mesh_stiffness(p));
  int coupled = 0;
  for (int j = 0; j < 6; ++j) {
    const double w2 = m.omega[j] * m.omega[j];
    double f = 1.0, scale = 1.0;
    bool on_pole = false;
    for (int i = 0; i < 6; ++i) {
      const double d = K(i, i) - w2 * M(i, i);
      if (std::fabs(d) < 1e-6 * K(i, i)) { on_pole = true; break; }
      f += p.kc * T2[i] * T2[i] / d;
      scale += std::fabs(p.kc * T2[i] * T2[i] / d);
    }
    if (on_pole) continue;   // the x-y combination of one gear normal to the line of action
    ++coupled;
    EXPECT_LT(std::fabs(f) / scale, 1e-9) << "mode " << j;
  }
  EXPECT_EQ(coupled, 4);
}

TEST(GearPair, StaticMeshDeflectionMatchesShermanMorrison) {
  // Under the static torque pair in full contact, Delta = T2 K^-1 F0 / (1 + kc T2 K^-1 T2'),
  // and the HB static solution (H = 1, no harmonic forcing) must reproduce it.
  GearPairParameters p;
  const double Fi = 1e7;
  const Eigen::MatrixXd K = gear_pair_support_stiffness(p);
  const Eigen::VectorXd T2 = gear_pair_T2(p), F0 = gear_pair_static_torque(p, Fi);
  const double d0 = T2.dot(K.ldlt().solve(F0));
  const double expect = d0 / (1.0 + p.kc * T2.dot(K.ldlt().solve(T2)));
  HarmonicBalance hb(gear_pair_system(p), {gear_pair_mesh(p)},
                     Excitation{F0, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)}, 1);
  Eigen::VectorXd X = hb.open_contact_solution(1000.0);
  Scaling s;
  s.x = Eigen::VectorXd::Constant(hb.size(), 1e-3);
  s.residual = 1e9 * 1e-3;
  const NewtonReport r = newton_solve(hb, X, 1000.0, s);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(T2.dot(X.head(6)), expect, 1e-9 * std::fabs(expect));
  EXPECT_GT(expect, 0.0);   // a positive Fi presses the teeth together
}
