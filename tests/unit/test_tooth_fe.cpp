// Unit tests of lib/tooth_fe (Euler-Bernoulli beams, assembly, constraints)
// and lib/hertz. Exact references: cubic Hermite elements reproduce the elastic
// line of a beam loaded by nodal forces exactly (the exact solution is a cubic
// between loads), so every nodal value below must match to round-off.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/gears/tooth/hertz.hpp"
#include "gearhb/gears/tooth/tooth_fe.hpp"

using namespace gearhb;

namespace {
std::vector<double> uniform(int ne, double L) {
  std::vector<double> x;
  for (int i = 0; i <= ne; ++i) x.push_back(L * i / ne);
  return x;
}
constexpr double EI = 74.52;       // 207 GPa x 20 mm x (6 mm)^3 / 12
constexpr double H = 6.75e-3;      // tooth height
}  // namespace

TEST(ToothFE, ElementStiffnessSymmetricWithRigidBodyModes) {
  const double L = 0.3;
  const Eigen::Matrix4d k = beam_element_stiffness(2.0, L);
  EXPECT_LT((k - k.transpose()).norm(), 1e-14);
  // Translation [1 0 1 0] and rotation about node 1 [0 1 L 1] produce no force.
  EXPECT_LT((k * Eigen::Vector4d(1, 0, 1, 0)).norm(), 1e-12);
  EXPECT_LT((k * Eigen::Vector4d(0, 1, L, 1)).norm(), 1e-12);
  EXPECT_NEAR(k(0, 0), 12 * 2.0 / (L * L * L), 1e-12);
  EXPECT_THROW(beam_element_stiffness(0.0, L), std::invalid_argument);
}

TEST(ToothFE, CantileverInteriorLoadExactElasticLine) {
  // Force at node 6 of 10 elements: nodal values equal y(x) = F x^2 (3a - x)/(6EI)
  // for x <= a and F a^2 (3x - a)/(6EI) beyond (Roark table 8.1 case 1a).
  BeamModel m;
  const auto x = uniform(10, H);
  m.add_beam(x, std::vector<double>(10, EI));
  m.clamp(0);
  const double F = 4000;
  m.add_force(6, F);
  const auto s = m.solve();
  for (int i = 0; i <= 10; ++i) {
    const double exact = cantilever_point_load_deflection(F, x[6], x[i], EI);
    EXPECT_NEAR(s.Q[BeamModel::w_dof(i)], exact, 1e-12 * std::fabs(exact) + 1e-20) << "node " << i;
  }
  // Reactions at the clamp: -F and -F a.
  EXPECT_NEAR(s.reactions[0], -F, 1e-8);
  EXPECT_NEAR(s.reactions[1], -F * x[6], 1e-10);
}

TEST(ToothFE, NonUniformSteppedCantileverMatchesClosedForm) {
  // Element lengths and EI all different: the FE is still exact at the nodes.
  const std::vector<double> x = {0, 1e-3, 1.5e-3, 3.2e-3, 4e-3, 6.75e-3};
  const std::vector<double> ei = {90, 70, 55, 40, 20};
  for (int k = 1; k < int(x.size()); ++k) {
    BeamModel m;
    m.add_beam(x, ei);
    m.clamp(0);
    m.add_force(k, 1.0);
    const double w = m.solve().Q[BeamModel::w_dof(k)];
    EXPECT_NEAR(w, stepped_cantilever_compliance(x, ei, x[k]), 1e-12 * w) << "load at node " << k;
  }
}

TEST(ToothFE, AssemblyOfTwoBeamsHasIndependentBlocks) {
  BeamModel m;
  m.add_beam(uniform(3, 1.0), {1, 2, 3});
  m.add_beam(uniform(2, 1.0), {4, 5});
  EXPECT_EQ(m.nodes(), 7);
  EXPECT_EQ(m.node(1, 0), 4);
  const Eigen::MatrixXd K = m.stiffness();
  EXPECT_EQ(K.rows(), 14);
  EXPECT_LT(K.block(0, 8, 8, 6).norm(), 1e-15);      // no coupling between beams
  EXPECT_LT((K - K.transpose()).norm(), 1e-12);
  // Interior node diagonal = sum of the two elements' contributions: 12(EI1 + EI2)/L^3
  // with L = 1/3: 12 x 3 x 27 = 972.
  EXPECT_NEAR(K(2, 2), 972.0, 1e-10);
}

TEST(ToothFE, FusedTeethAreAClampedGuidedBeam) {
  // Thesis §7.4: beam 1 guided at its root with imposed X, beam 2 clamped, node
  // 2 of beam 1 (1 element from its root) fused with the tip of beam 2
  // (translation opposite, rotation equal): a clamped-guided beam of 11
  // elements, stiffness 12 EI / L^3 with L = 11 H/10, root moments V L / 2.
  BeamModel m;
  const auto x = uniform(10, H);
  m.add_beam(x, std::vector<double>(10, EI));
  m.add_beam(x, std::vector<double>(10, EI));
  const double X = 1e-6;
  m.guide(m.node(0, 0), -X);
  m.clamp(m.node(1, 0));
  m.fuse(m.node(0, 1), m.node(1, 10), -1.0, true);
  const auto s = m.solve();
  const double L = 1.1 * H, V = 12 * EI / (L * L * L) * X;
  EXPECT_NEAR(-s.reactions[BeamModel::w_dof(0)], V, 1e-9 * V);
  EXPECT_NEAR(s.reactions[BeamModel::theta_dof(0)], -V * L / 2, 1e-9 * V * L);
  EXPECT_NEAR(s.reactions[BeamModel::theta_dof(m.node(1, 0))], -V * L / 2, 1e-9 * V * L);
  // Fused DOFs obey the constraint.
  EXPECT_NEAR(s.Q[BeamModel::w_dof(m.node(1, 10))], -s.Q[BeamModel::w_dof(1)], 1e-18);
  EXPECT_NEAR(s.Q[BeamModel::theta_dof(m.node(1, 10))], s.Q[BeamModel::theta_dof(1)], 1e-15);
  // Closed form of the stepped clamped-guided beam agrees.
  EXPECT_NEAR(stepped_clamped_guided_stiffness(uniform(11, L), std::vector<double>(11, EI)),
              12 * EI / (L * L * L), 1e-12 * 12 * EI / (L * L * L));
}

TEST(ToothFE, TranslationOnlyFusionIsTwoCantileversInSeries) {
  // Fusing translations only transmits a force, no moment: X = F (c1 + c2) with
  // c_i = a_i^3 / (3 EI) the tip compliances at the contact heights.
  BeamModel m;
  const auto x = uniform(10, H);
  m.add_beam(x, std::vector<double>(10, EI));
  m.add_beam(x, std::vector<double>(10, EI));
  const double X = 1e-6;
  m.guide(m.node(0, 0), -X);
  m.clamp(m.node(1, 0));
  m.fuse(m.node(0, 4), m.node(1, 7), -1.0, false);
  const auto s = m.solve();
  const double F = -s.reactions[0];
  const double c = (std::pow(x[4], 3) + std::pow(x[7], 3)) / (3 * EI);
  EXPECT_NEAR(F * c, X, 1e-9 * X);
}

TEST(ToothFE, UnheldBeamIsReportedAndDoubleConstraintRefused) {
  BeamModel m;
  m.add_beam(uniform(4, 1.0), std::vector<double>(4, 1.0));
  m.add_force(4, 1.0);
  EXPECT_THROW(m.solve(), std::runtime_error);
  m.clamp(0);
  EXPECT_THROW(m.clamp(0), std::logic_error);
  EXPECT_NO_THROW(m.solve());
  // A second beam held nowhere: the message names it (beam 2, global nodes 6-10).
  m.add_beam(uniform(4, 1.0), std::vector<double>(4, 1.0));
  try {
    m.solve();
    ADD_FAILURE() << "an unheld beam must throw";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("(beam 2,"), std::string::npos) << what;
    EXPECT_NE(what.find("clamp or guide its root"), std::string::npos) << what;
  }
}

TEST(ToothFE, ElementEndForcesGiveTheMomentLine) {
  // Cantilever with tip force F: internal moment at the start of element e is
  // -M1 = -F (L - x_e) in the sign convention of K^(e) (end moments applied on the element).
  BeamModel m;
  const auto x = uniform(5, 1.0);
  m.add_beam(x, std::vector<double>(5, 3.0));
  m.clamp(0);
  m.add_force(5, 2.0);
  const auto s = m.solve();
  for (int e = 0; e < 5; ++e) {
    const Eigen::Vector4d f = m.element_end_forces(s, 0, e);
    EXPECT_NEAR(f[0], -2.0, 1e-12);
    EXPECT_NEAR(f[1], -2.0 * (1.0 - x[e]), 1e-12);
    EXPECT_NEAR(f[3], 2.0 * (1.0 - x[e + 1]), 1e-12);
  }
}

TEST(Hertz, PalmgrenUnitsAndScaling) {
  // 3.84e-5 * 4000^0.9 / 20^0.8 = 3.84e-5 * 1747.46 / 10.9856 = 6.10044e-3 mm.
  EXPECT_NEAR(palmgren_line_contact_approach(4000, 0.02), 6.1004408426824815e-6, 1e-18);
  EXPECT_NEAR(palmgren_line_contact_approach(8000, 0.02) / palmgren_line_contact_approach(4000, 0.02),
              std::pow(2.0, 0.9), 1e-14);
  EXPECT_NEAR(palmgren_line_contact_approach(4000, 0.04) / palmgren_line_contact_approach(4000, 0.02),
              std::pow(2.0, -0.8), 1e-14);
  EXPECT_EQ(palmgren_line_contact_approach(0, 0.02), 0.0);
  EXPECT_THROW(palmgren_line_contact_approach(-1, 0.02), std::invalid_argument);
  // Compliance is the derivative: central difference.
  const double h = 1e-3;
  const double fd = (palmgren_line_contact_approach(2000 + h, 0.02) -
                     palmgren_line_contact_approach(2000 - h, 0.02)) / (2 * h);
  EXPECT_NEAR(palmgren_line_contact_compliance(2000, 0.02), fd, 1e-9 * fd);
}
