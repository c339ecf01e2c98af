// Unit tests of lib/gearhb/fe (P2 plane elasticity, Gmsh meshes, sparse Cholesky) against
// closed forms:
//   - patch tests: a linear displacement field (constant strain) reproduced to rounding on
//     a distorted mesh with curved interior edges, by prescribed displacements and by
//     tractions;
//   - Lame's thick cylinder under internal pressure (plane strain, quarter ring meshed by
//     Gmsh with curved P2 edges): u(r), hoop stress, energy-norm error and their orders;
//   - the plane-strain cantilever under a parabolic end shear (Timoshenko & Goodier §21):
//     tip deflection with the shear term, energy-norm error and their orders;
//   - Flamant's line load on a half-plane (a quarter disc with the exact traction on its
//     arc): stresses away from the load over three refinements;
//   - the solver: backends agree, many right-hand sides equal single solves, rigid motions
//     and oversized meshes refused.
// Orders are least-squares slopes of log(error) over log(h) on three or four meshes; each
// test states the expected order (P2: energy norm ~h^2, displacement ~h^3) and checks the
// observed one, and checks the finest error against a bound stated with its mesh.
#include <cmath>
#include <cstdio>
#include <string>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "gearhb/fe/elasticity.hpp"
#include "gearhb/fe/gmsh_mesher.hpp"
#include "gearhb/fe/linear_solver.hpp"
#include "gearhb/fe/mesh.hpp"
#include "gearhb/fe/p2_element.hpp"

using namespace gearhb::fe;
using Eigen::Vector2d;

namespace {

constexpr double pi = 3.14159265358979323846;

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3e", v);
  return b;
}

// The least-squares slope of log(e) over log(h).
double observed_order(const std::vector<double>& h, const std::vector<double>& e) {
  const int n = int(h.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    const double x = std::log(h[i]), y = std::log(e[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

using StressField = std::function<Eigen::Vector3d(const Vector2d&)>;   // (s_xx, s_yy, s_xy)

// The energy norm of the error, ||u - u_h||_E = sqrt(int (s - s_h)^T D^-1 (s - s_h) dA)
// (per unit thickness), by the 6-point rule of degree 4 in every element.
double energy_error(const P2Mesh& mesh, const Material& m, const Eigen::VectorXd& u, const StressField& exact) {
  const Eigen::Matrix3d compliance = elasticity_matrix(m).inverse();
  double sum = 0;
  for (int e = 0; e < int(mesh.triangles.size()); ++e) {
    P2Coordinates x;
    for (int i = 0; i < 6; ++i) x.col(i) = mesh.nodes[mesh.triangles[e][i]];
    for (const auto& q : triangle_rule(4)) {
      const double det_j = p2_jacobian(x, p2_reference_gradients(q.xi, q.eta)).determinant();
      const Eigen::Vector3d diff = exact(x * p2_shape(q.xi, q.eta)) - element_stress(mesh, m, u, e, q.xi, q.eta).head<3>();
      sum += q.weight * det_j * diff.dot(compliance * diff);
    }
  }
  return std::sqrt(sum);
}

// The energy norm of the exact solution, same rule.
double energy_norm(const P2Mesh& mesh, const Material& m, const StressField& exact) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(mesh.dof_count());
  return energy_error(mesh, m, zero, exact);
}

// A structured mesh of the unit square with its interior corners moved at random by up to
// 0.2 of the cell and its interior edge nodes moved off the chords by 5 % of their
// length (curved edges).
P2Mesh distorted_square(int n, unsigned seed) {
  P2Mesh m = rectangle_mesh(0, 0, 1, 1, n, n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.2 / n, 0.2 / n);
  const int g = 2 * n + 1;
  for (int j = 1; j < g - 1; ++j)
    for (int i = 1; i < g - 1; ++i)
      if (i % 2 == 0 && j % 2 == 0) m.nodes[j * g + i] += Vector2d(shift(rng), shift(rng));
  // Edge nodes: midway between their corners, then pushed off the chord.
  for (auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3], mid = t[3 + k];
      m.nodes[mid] = 0.5 * (m.nodes[a] + m.nodes[b]);
    }
  std::vector<bool> boundary(m.nodes.size(), false);
  for (const auto& e : m.edges)
    for (int v : e) boundary[v] = true;
  std::vector<bool> moved(m.nodes.size(), false);
  for (auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int mid = t[3 + k];
      if (boundary[mid] || moved[mid]) continue;
      const Vector2d chord = m.nodes[t[(k + 1) % 3]] - m.nodes[t[k]];
      m.nodes[mid] += 0.05 * Vector2d(-chord.y(), chord.x());
      moved[mid] = true;
    }
  check_mesh(m);
  return m;
}

// The linear field of the patch tests and its constant stress.
Vector2d patch_field(const Vector2d& x) {
  return {1e-3 * x.x() + 2e-4 * x.y() + 1e-5, -5e-4 * x.x() + 7e-4 * x.y() - 2e-5};
}

}  // namespace

TEST(FeElement, QuadratureRulesIntegratePolynomialsExactly) {
  // int over the reference triangle of xi^a eta^b = a! b! / (a + b + 2)!.
  const auto exact = [](int a, int b) { return std::tgamma(a + 1) * std::tgamma(b + 1) / std::tgamma(a + b + 3); };
  for (int degree : {2, 4})
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b) {
        double sum = 0;
        for (const auto& q : triangle_rule(degree)) sum += q.weight * std::pow(q.xi, a) * std::pow(q.eta, b);
        EXPECT_NEAR(sum, exact(a, b), 1e-14) << "degree " << degree << ", xi^" << a << " eta^" << b;
      }
  EXPECT_THROW(triangle_rule(3), std::invalid_argument);
  // The shape functions are a partition of unity and 1 at their own node.
  const double nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int i = 0; i < 6; ++i) {
    const P2Values n = p2_shape(nodes[i][0], nodes[i][1]);
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(n(j), i == j ? 1.0 : 0.0, 1e-15);
  }
  EXPECT_NEAR(p2_reference_gradients(0.2, 0.3).rowwise().sum().norm(), 0.0, 1e-14);
}

TEST(FeElasticity, PatchTestByPrescribedDisplacements) {
  // Every boundary node carries the linear field; the interior nodes of a distorted mesh
  // with curved edges must reproduce it, and the stress must be D eps everywhere.
  const P2Mesh mesh = distorted_square(4, 1);
  const Material m{210e9, 0.3};
  const auto k = assemble_stiffness(mesh, m);
  Constraints c;
  for (int tag = 1; tag <= 4; ++tag)
    for (int n : tagged_nodes(mesh, tag)) {
      c.fix(2 * n, patch_field(mesh.nodes[n]).x());
      c.fix(2 * n + 1, patch_field(mesh.nodes[n]).y());
    }
  const Eigen::VectorXd u = solve_elastic(k, Eigen::VectorXd::Zero(mesh.dof_count()), c);
  double worst = 0;
  for (int n = 0; n < mesh.node_count(); ++n) worst = std::max(worst, (u.segment<2>(2 * n) - patch_field(mesh.nodes[n])).norm());
  EXPECT_LT(worst, 1e-10 * 1e-3);   // rounding: the field is ~1e-3
  const Eigen::Vector3d strain(1e-3, 7e-4, 2e-4 - 5e-4);
  const Eigen::Vector3d stress = elasticity_matrix(m) * strain;
  for (const auto& p : gauss_point_stresses(mesh, m, u))
    EXPECT_LT((p.stress.head<3>() - stress).norm(), 1e-9 * stress.norm());
}

TEST(FeElasticity, PatchTestByTractions) {
  // The constant stress of the patch field applied as tractions s.n on the four sides,
  // rigid motions stopped at two corners (3 DOFs): the field returns up to a rigid motion,
  // and the stress exactly.
  const P2Mesh mesh = distorted_square(4, 2);
  const Material m{210e9, 0.3};
  const Eigen::Vector3d strain(1e-3, 7e-4, -3e-4);
  const Eigen::Vector3d s = elasticity_matrix(m) * strain;
  Eigen::Matrix2d sigma;
  sigma << s(0), s(2), s(2), s(1);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int tag = 1; tag <= 4; ++tag)
    add_edge_traction(mesh, m, tag, [&](const Vector2d&, const Vector2d& n) -> Vector2d { return sigma * n; }, f);
  const int origin = 0, right = 2 * 4;   // nodes (0, 0) and (1, 0) of the 9 x 9 grid
  Constraints c;
  c.fix(2 * origin, patch_field(mesh.nodes[origin]).x());
  c.fix(2 * origin + 1, patch_field(mesh.nodes[origin]).y());
  c.fix(2 * right + 1, patch_field(mesh.nodes[right]).y());
  const ElasticSolver solver(assemble_stiffness(mesh, m), c.dofs());
  const Eigen::VectorXd u = solver.solve(f, c.values());
  // The three conditions are the field's own values, so they fix its rigid motion too.
  double worst = 0;
  for (int n = 0; n < mesh.node_count(); ++n) worst = std::max(worst, (u.segment<2>(2 * n) - patch_field(mesh.nodes[n])).norm());
  EXPECT_LT(worst, 1e-10 * 1e-3);   // rounding: the field is ~1e-3
  for (const auto& p : gauss_point_stresses(mesh, m, u)) EXPECT_LT((p.stress.head<3>() - s).norm(), 1e-9 * s.norm());
  // Reactions balance the tractions: K u - f vanishes at the free DOFs.
  const Eigen::VectorXd r = solver.reactions(u, f);
  double free_residual = 0;
  for (int d = 0; d < mesh.dof_count(); ++d)
    if (!std::binary_search(c.dofs().begin(), c.dofs().end(), d)) free_residual = std::max(free_residual, std::abs(r(d)));
  EXPECT_LT(free_residual, 1e-9 * f.cwiseAbs().maxCoeff());
}

namespace {

// Lame's thick cylinder, inner radius a, outer b, internal pressure p, plane strain
// (Timoshenko & Goodier §28; Barber, Elasticity, 3rd ed., §8.3.1):
//   s_r = A - B / r^2,  s_t = A + B / r^2,  A = p a^2 / (b^2 - a^2),  B = A b^2,
//   u(r) = (1 + nu) / E * [(1 - 2 nu) A r + B / r].
struct Lame {
  double a = 0.05, b = 0.1, p = 100e6;
  Material m{210e9, 0.3};
  double coef_a() const { return p * a * a / (b * b - a * a); }
  double coef_b() const { return coef_a() * b * b; }
  double u(double r) const {
    const double nu = m.poisson_ratio;
    return (1 + nu) / m.youngs_modulus * ((1 - 2 * nu) * coef_a() * r + coef_b() / r);
  }
  double hoop(double r) const { return coef_a() + coef_b() / (r * r); }
  Eigen::Vector3d stress(const Vector2d& x) const {   // Cartesian (s_xx, s_yy, s_xy)
    const double r2 = x.squaredNorm(), sr = coef_a() - coef_b() / r2, st = coef_a() + coef_b() / r2;
    const double c = x.x() * x.x() / r2, s = x.y() * x.y() / r2, cs = x.x() * x.y() / r2;
    return {sr * c + st * s, sr * s + st * c, (sr - st) * cs};
  }
  // The quarter ring: tag 1 the x axis (u_y = 0), 2 the outer arc (free), 3 the y axis
  // (u_x = 0), 4 the inner arc (pressure).
  MeshSpec spec(double size) const {
    const Vector2d o(0, 0);
    BoundaryLoop loop{{CurveKind::polyline, {Vector2d(a, 0), Vector2d(b, 0)}, 1},
                      {CurveKind::circle_arc, {Vector2d(b, 0), o, Vector2d(0, b)}, 2},
                      {CurveKind::polyline, {Vector2d(0, b), Vector2d(0, a)}, 3},
                      {CurveKind::circle_arc, {Vector2d(0, a), o, Vector2d(a, 0)}, 4}};
    MeshSpec s;
    s.loops = {loop};
    s.size = size;
    return s;
  }
};

struct LameErrors {
  double u_max = 0, hoop_max = 0, hoop_gauss = 0, energy = 0;   // relative to u(a), s_t(a), ||u||_E
  int nodes = 0;
};

LameErrors solve_lame(const Lame& c, double size) {
  const P2Mesh mesh = mesh_with_gmsh(c.spec(size));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_pressure(mesh, c.m, 4, c.p, f);
  Constraints fix;
  fix_tagged(mesh, 1, 1, 0.0, fix);
  fix_tagged(mesh, 3, 0, 0.0, fix);
  const Eigen::VectorXd u = solve_elastic(assemble_stiffness(mesh, c.m), f, fix);
  const Eigen::MatrixX4d s = nodal_stresses(mesh, c.m, u);
  LameErrors e;
  e.nodes = mesh.node_count();
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Vector2d x = mesh.nodes[n];
    const double r = x.norm();
    const Vector2d er = x / r;
    e.u_max = std::max(e.u_max, std::abs(er.dot(u.segment<2>(2 * n)) - c.u(r)) / c.u(c.a));
    const Vector2d et(-er.y(), er.x());
    const double hoop = et.x() * et.x() * s(n, 0) + et.y() * et.y() * s(n, 1) + 2 * et.x() * et.y() * s(n, 2);
    e.hoop_max = std::max(e.hoop_max, std::abs(hoop - c.hoop(r)) / c.hoop(c.a));
  }
  for (const auto& q : gauss_point_stresses(mesh, c.m, u)) {
    const Vector2d et = Vector2d(-q.x.y(), q.x.x()) / q.x.norm();
    const double hoop = et.x() * et.x() * q.stress(0) + et.y() * et.y() * q.stress(1) + 2 * et.x() * et.y() * q.stress(2);
    e.hoop_gauss = std::max(e.hoop_gauss, std::abs(hoop - c.hoop(q.x.norm())) / c.hoop(c.a));
  }
  const auto exact = [&c](const Vector2d& x) { return c.stress(x); };
  e.energy = energy_error(mesh, c.m, u, exact) / energy_norm(mesh, c.m, exact);
  return e;
}

}  // namespace

namespace {

struct LameStudy {
  std::vector<double> h, u, hoop, hoop_gauss, energy;
  double order(const std::vector<double>& e) const { return observed_order(h, e); }
};

// Lame on meshes of size (b - a) / k for each k, each level recorded as a test property.
LameStudy lame_study(const std::vector<int>& ks) {
  const Lame c;
  LameStudy st;
  for (int k : ks) {
    const LameErrors e = solve_lame(c, (c.b - c.a) / k);
    st.h.push_back((c.b - c.a) / k);
    st.u.push_back(e.u_max);
    st.hoop.push_back(e.hoop_max);
    st.hoop_gauss.push_back(e.hoop_gauss);
    st.energy.push_back(e.energy);
    ::testing::Test::RecordProperty("lame_h" + std::to_string(k),
                   std::to_string(e.nodes) + " nodes, u " + sci(e.u_max) + ", hoop " +
                       sci(e.hoop_max) + ", hoop at Gauss points " + sci(e.hoop_gauss) +
                       ", energy " + sci(e.energy));
  }
  ::testing::Test::RecordProperty("lame_orders", "u " + sci(st.order(st.u)) + ", hoop " +
                                                     sci(st.order(st.hoop)) + ", hoop at Gauss points " +
                                                     sci(st.order(st.hoop_gauss)) + ", energy " +
                                                     sci(st.order(st.energy)));
  return st;
}

}  // namespace

TEST(FeElasticity, LameThickCylinderConvergesAtP2Orders) {
  // Quarter ring a = 50 mm, b = 100 mm, p = 100 MPa, meshed by Gmsh at h = (b - a) / 4,
  // /8, /16, /32 (237 to 11541 nodes, 0.6 s). Errors: max over the nodes of the radial
  // displacement (relative to u(a)) and of the recovered hoop stress (relative to
  // s_t(a)), and the energy norm (relative to ||u||_E). Expected orders for P2 on a
  // smooth solution with the boundary curved by quadratic edges: energy 2, nodal
  // displacement 3. Measured here: 1.89, 2.89.
  const LameStudy st = lame_study({4, 8, 16, 32});
  EXPECT_GT(st.order(st.energy), 1.8);
  EXPECT_GT(st.order(st.u), 2.7);
  // The max-norm stress reaches its order 2 only on finer meshes (unstructured meshes,
  // the worst node on the inner boundary): 1.57 here, 1.9 between 45k and 180k nodes
  // (FeConvergenceStudy.DISABLED_LameFine). Here: better than first order.
  EXPECT_GT(st.order(st.hoop), 1.5);
  // Finest mesh (h = 1.56 mm, 11541 nodes): bounds at twice the measured errors
  // (2.5e-6, 6.6e-4, 2.2e-4).
  EXPECT_LT(st.u.back(), 5e-6) << "u";
  EXPECT_LT(st.hoop.back(), 1.3e-3) << "hoop";
  EXPECT_LT(st.energy.back(), 4.5e-4) << "energy";
}

// The fine end of the study (11.5k, 45k and 180k nodes, ~40 s): not run by default;
// build/bin/gearhb_tests --gtest_also_run_disabled_tests --gtest_filter='FeConvergenceStudy.*'
// Measured: the order between the two finest meshes, energy 1.99, hoop stress 1.93 at the
// nodes and 1.96 at the Gauss points (the fit over all three: 1.98, 1.78, 1.86).
TEST(FeConvergenceStudy, DISABLED_LameFine) {
  const LameStudy st = lame_study({32, 64, 128});
  const auto last_order = [&st](const std::vector<double>& e) { return std::log(e[1] / e[2]) / std::log(st.h[1] / st.h[2]); };
  EXPECT_GT(last_order(st.energy), 1.9);
  EXPECT_GT(last_order(st.hoop), 1.85);
  EXPECT_GT(last_order(st.hoop_gauss), 1.85);
}

namespace {

// The plane-strain cantilever of Timoshenko & Goodier (3rd ed., §21): length L, depth 2c,
// unit thickness, free end x = 0 loaded by the parabolic shear traction of resultant P
// (+y), clamped at x = L. Stresses s_xx = -P x y / I, s_yy = 0, s_xy = -P (c^2 - y^2) / (2I),
// I = 2c^3/3. Displacements with the clamp u = v = 0 and du/dy = 0 at (L, 0) (the
// section's vertical element fixed):
//   u = -P x^2 y / (2E'I) - nu' P y^3 / (6E'I) + P y^3 / (6IG) + P L^2 y / (2E'I),
//   v = nu' P x y^2 / (2E'I) + P x^3 / (6E'I) + d x + h,
//   d = -P c^2 / (2IG) - P L^2 / (2E'I),  h = v(0, 0) = P L^3 / (3E'I) + P c^2 L / (2IG),
// plane strain with E' = E / (1 - nu^2), nu' = nu / (1 - nu). The tip deflection h is
// Timoshenko beam theory, PL^3/(3EI) + P L / (kappa G A), with kappa = 2/3 for this clamp
// (3/2 = the peak over the mean of the parabolic shear). The FE clamp prescribes this
// field on x = L, so the FE solution converges to it everywhere.
struct Cantilever {
  double length = 1.0, c = 0.05, load = 1e5;   // P [N per m of thickness]
  Material m{210e9, 0.3};
  double inertia() const { return 2 * c * c * c / 3; }
  double e_prime() const { return m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio); }
  double nu_prime() const { return m.poisson_ratio / (1 - m.poisson_ratio); }
  double shear_modulus() const { return m.youngs_modulus / (2 * (1 + m.poisson_ratio)); }
  double tip() const {
    return load * std::pow(length, 3) / (3 * e_prime() * inertia()) + load * c * c * length / (2 * inertia() * shear_modulus());
  }
  Vector2d displacement(const Vector2d& p) const {
    const double x = p.x(), y = p.y(), P = load, I = inertia(), E = e_prime(), nu = nu_prime(), G = shear_modulus();
    const double d = -P * c * c / (2 * I * G) - P * length * length / (2 * E * I);
    return {-P * x * x * y / (2 * E * I) - nu * P * y * y * y / (6 * E * I) + P * y * y * y / (6 * I * G) +
                P * length * length * y / (2 * E * I),
            nu * P * x * y * y / (2 * E * I) + P * x * x * x / (6 * E * I) + d * x + tip()};
  }
  Eigen::Vector3d stress(const Vector2d& p) const {
    return {-load * p.x() * p.y() / inertia(), 0.0, -load * (c * c - p.y() * p.y()) / (2 * inertia())};
  }
};

struct CantileverErrors {
  double tip = 0, u_max = 0, energy = 0;   // relative to the tip deflection, ||u||_E
  int nodes = 0;
};

// k: cells across the depth (2 k) and along the length (20 k): square cells of c / k.
CantileverErrors solve_cantilever(const Cantilever& b, int k) {
  const P2Mesh mesh = rectangle_mesh(0, -b.c, b.length, 2 * b.c, 20 * k, 2 * k);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_edge_traction(mesh, b.m, 4, [&b](const Vector2d& x, const Vector2d& n) -> Vector2d {
    const Eigen::Vector3d s = b.stress(x);
    return {s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y()};
  }, f);
  Constraints clamp;
  fix_tagged(mesh, 2, 0, [&b](const Vector2d& x) { return b.displacement(x).x(); }, clamp);
  fix_tagged(mesh, 2, 1, [&b](const Vector2d& x) { return b.displacement(x).y(); }, clamp);
  const Eigen::VectorXd u = solve_elastic(assemble_stiffness(mesh, b.m), f, clamp);
  CantileverErrors e;
  e.nodes = mesh.node_count();
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Vector2d err = u.segment<2>(2 * n) - b.displacement(mesh.nodes[n]);
    e.u_max = std::max(e.u_max, err.norm() / b.tip());
    if (mesh.nodes[n].norm() < 1e-12) e.tip = std::abs(u(2 * n + 1) - b.tip()) / b.tip();
  }
  const auto exact = [&b](const Vector2d& x) { return b.stress(x); };
  e.energy = energy_error(mesh, b.m, u, exact) / energy_norm(mesh, b.m, exact);
  return e;
}

}  // namespace

TEST(FeElasticity, CantileverMatchesTimoshenkoGoodier) {
  // L = 1 m, depth 0.1 m, P = 100 kN/m, steel: tip deflection 0.2177 mm, of which the
  // shear term is 0.2 %. Structured meshes of 20k x 2k cells (k = 1, 2, 4, 8; 205 to
  // 10593 nodes). Expected orders: energy 2, nodal displacement 3 or more (the exact
  // field is cubic, the clamp interpolates it with quadratics).
  const Cantilever b;
  std::vector<double> h, tip, umax, energy;
  for (int k : {1, 2, 4, 8}) {
    const CantileverErrors e = solve_cantilever(b, k);
    h.push_back(b.c / k);
    tip.push_back(e.tip);
    umax.push_back(e.u_max);
    energy.push_back(e.energy);
    RecordProperty("cantilever_k" + std::to_string(k), std::to_string(e.nodes) + " nodes, tip " + sci(e.tip) +
                                                           ", u " + sci(e.u_max) + ", energy " +
                                                           sci(e.energy));
  }
  const double pt = observed_order(h, tip), pu = observed_order(h, umax), pe = observed_order(h, energy);
  RecordProperty("cantilever_orders", "tip " + sci(pt) + ", u " + sci(pu) + ", energy " + sci(pe));
  EXPECT_GT(pe, 1.8);
  EXPECT_GT(pu, 2.7);
  EXPECT_GT(pt, 2.7);
  // k = 8: twice the measured errors (tip 3.4e-8, energy 2.4e-4).
  EXPECT_LT(tip.back(), 7e-8);
  EXPECT_LT(energy.back(), 4.8e-4);
}

namespace {

// Flamant's line load P [N/m] on the half-plane y <= 0, pointing into it (-y) at the
// origin (Timoshenko & Goodier §36; Johnson, Contact Mechanics, §2.2): the radial
// stress field s_r = -2 P cos(theta) / (pi r), s_theta = s_r_theta = 0, theta measured from
// the load's direction, cos(theta) = -y / r. Modelled: the quarter disc x >= 0, y <= 0,
// r <= R (symmetry u_x = 0 on x = 0, tag 1), the exact traction s_r e_r on its arc
// (tag 2, so no truncation error), the free surface y = 0 (tag 3), P/2 at the origin's
// node, u_y = 0 at (0, -R). Gmsh grades the mesh towards the load (Distance +
// Threshold: size R/(16k) at the load up to size R/k at 0.5 R).
struct Flamant {
  double radius = 1.0, load = 1e6;
  Material m{210e9, 0.3};
  double radial(const Vector2d& x) const { return -2 * load * (-x.y() / x.norm()) / (pi * x.norm()); }
  Eigen::Vector3d stress(const Vector2d& x) const {
    const double sr = radial(x), r2 = x.squaredNorm();
    return {sr * x.x() * x.x() / r2, sr * x.y() * x.y() / r2, sr * x.x() * x.y() / r2};
  }
  MeshSpec spec(int k) const {
    const Vector2d o(0, 0), bottom(0, -radius), right(radius, 0);
    MeshSpec s;
    s.loops = {{{CurveKind::polyline, {o, bottom}, 1},
                {CurveKind::circle_arc, {bottom, o, right}, 2},
                {CurveKind::polyline, {right, o}, 3}}};
    s.size = radius / k;
    Refinement near_load;
    near_load.points = {o};
    near_load.size_min = radius / (16 * k);
    near_load.dist_min = 0;
    near_load.dist_max = 0.5 * radius;
    s.refinements = {near_load};
    return s;
  }
};

int nearest_node(const P2Mesh& mesh, const Vector2d& x) {
  int best = 0;
  for (int n = 1; n < mesh.node_count(); ++n)
    if ((mesh.nodes[n] - x).norm() < (mesh.nodes[best] - x).norm()) best = n;
  return best;
}

// The largest stress error at the Gauss points with 0.25 R <= r, relative to 2P/(pi r).
double flamant_error(const Flamant& fl, int k, int& nodes) {
  const P2Mesh mesh = mesh_with_gmsh(fl.spec(k));
  nodes = mesh.node_count();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_nodal_force(nearest_node(mesh, {0, 0}), {0, -fl.load / 2}, f);
  add_edge_traction(mesh, fl.m, 2, [&fl](const Vector2d& x, const Vector2d& n) -> Vector2d {
    const Eigen::Vector3d s = fl.stress(x);
    return {s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y()};
  }, f);
  Constraints c;
  fix_tagged(mesh, 1, 0, 0.0, c);
  c.fix(2 * nearest_node(mesh, {0, -fl.radius}) + 1, 0.0);
  const Eigen::VectorXd u = solve_elastic(assemble_stiffness(mesh, fl.m), f, c);
  double worst = 0;
  for (const auto& q : gauss_point_stresses(mesh, fl.m, u)) {
    const double r = q.x.norm();
    if (r < 0.25 * fl.radius) continue;
    worst = std::max(worst, (q.stress.head<3>() - fl.stress(q.x)).cwiseAbs().maxCoeff() / (2 * fl.load / (pi * r)));
  }
  return worst;
}

}  // namespace

namespace {

std::vector<double> flamant_study(const std::vector<int>& ks, std::vector<double>& h) {
  const Flamant fl;
  std::vector<double> err;
  for (int k : ks) {
    int nodes = 0;
    err.push_back(flamant_error(fl, k, nodes));
    h.push_back(fl.radius / k);
    ::testing::Test::RecordProperty("flamant_k" + std::to_string(k), std::to_string(nodes) + " nodes, stress " + sci(err.back()));
  }
  ::testing::Test::RecordProperty("flamant_order", sci(observed_order(h, err)));
  return err;
}

}  // namespace

TEST(FeElasticity, FlamantStressesAwayFromTheLoad) {
  // R = 1 m, P = 1 MN/m; meshes k = 8, 16, 32 (532 to 7122 nodes). The load is a point
  // force on a P2 node: the solution near it is singular (infinite energy), so only the
  // stresses away from it are compared (r >= R/4, where 2P/(pi r) <= 2.5 MPa). Expected
  // order 2 (P2 stress), reached from k = 32 on: the error ratios per halving are 2.9,
  // 3.2, 3.4, 3.9 for k = 4 ... 64 (FeConvergenceStudy.DISABLED_FlamantFine); 1.72 over
  // these three meshes.
  std::vector<double> h;
  const std::vector<double> err = flamant_study({8, 16, 32}, h);
  EXPECT_GT(observed_order(h, err), 1.6);
  EXPECT_LT(err.back(), 2 * 1.45e-3);   // k = 32: twice the measured 1.45e-3 (0.145 %)
}

TEST(FeConvergenceStudy, DISABLED_FlamantFine) {
  std::vector<double> h;
  const std::vector<double> err = flamant_study({16, 32, 64}, h);
  EXPECT_GT(observed_order(h, err), 1.8);
}

namespace {

// The Lame quarter ring at h = (b - a) / 8 with its load and symmetry conditions.
struct LameSystem {
  Lame c;
  P2Mesh mesh = mesh_with_gmsh(c.spec((c.b - c.a) / 8));
  Eigen::SparseMatrix<double> k = assemble_stiffness(mesh, c.m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  Constraints fix;
  LameSystem() {
    add_pressure(mesh, c.m, 4, c.p, f);
    fix_tagged(mesh, 1, 1, 0.0, fix);
    fix_tagged(mesh, 3, 0, 0.0, fix);
  }
};

}  // namespace

TEST(FeSolver, BackendsAgreeAndManyLoadsEqualSingleSolves) {
  const LameSystem s;
  const ElasticSolver cholmod(s.k, s.fix.dofs(), CholeskyBackend::cholmod_supernodal);
  const Eigen::VectorXd u = cholmod.solve(s.f);
  for (auto backend : {CholeskyBackend::eigen_ldlt, CholeskyBackend::eigen_llt}) {
    const ElasticSolver other(s.k, s.fix.dofs(), backend);
    EXPECT_LT((other.solve(s.f) - u).norm(), 1e-10 * u.norm());
    EXPECT_GT(other.stats().factor_nonzeros, 0);
  }
  // Three loads at once (the pressure, a point force, their sum) against one by one.
  Eigen::MatrixXd loads(s.mesh.dof_count(), 3);
  Eigen::VectorXd point = Eigen::VectorXd::Zero(s.mesh.dof_count());
  add_nodal_force(nearest_node(s.mesh, {s.c.b, 0}), {1e6, 0}, point);
  loads << s.f, point, s.f + point;
  const Eigen::MatrixXd many = cholmod.solve(loads);
  EXPECT_LT((many.col(0) - u).norm(), 1e-12 * u.norm());
  EXPECT_LT((many.col(1) - cholmod.solve(point)).norm(), 1e-12 * many.col(1).norm());
  EXPECT_LT((many.col(2) - many.col(0) - many.col(1)).norm(), 1e-12 * many.col(2).norm());
  // Equilibrium: the x reactions on the y axis balance the pressure's x resultant p a.
  const Eigen::VectorXd r = cholmod.reactions(u, s.f);
  double rx = 0;
  for (int n : tagged_nodes(s.mesh, 3)) rx += r(2 * n);
  EXPECT_NEAR(-rx, s.c.p * s.c.a, 1e-9 * s.c.p * s.c.a);
  // Strain energy = half the work of the pressure, 1/2 f.u.
  EXPECT_NEAR(strain_energy(s.k, u), 0.5 * s.f.dot(u), 1e-10 * strain_energy(s.k, u));
  EXPECT_GT(cholmod.stats().factor_bytes, 0);
}

TEST(FeSolver, RefusesRigidMotionsAndOversizedFactors) {
  const LameSystem s;
  EXPECT_THROW(ElasticSolver(s.k, {}), std::invalid_argument);   // no constraint: singular
  EXPECT_THROW(ElasticSolver(s.k, {}, CholeskyBackend::eigen_ldlt), std::invalid_argument);
  SolverLimits tiny;
  tiny.max_factor_bytes = 1e4;   // the factor needs ~1 MB
  for (auto backend : {CholeskyBackend::cholmod_supernodal, CholeskyBackend::eigen_ldlt}) {
    try {
      ElasticSolver(s.k, s.fix.dofs(), backend, tiny);
      ADD_FAILURE() << "an oversized factor was not refused";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
    }
  }
  Constraints twice;
  twice.fix(3, 0.0);
  EXPECT_THROW(twice.fix(3, 1.0), std::invalid_argument);
  EXPECT_THROW(ElasticSolver(s.k, {-1}), std::invalid_argument);
}

TEST(FeMesher, GmshIsSilentAndTheSizeEstimateHolds) {
  const Lame c;
  // Nothing on stdout from Gmsh.
  ::testing::internal::CaptureStdout();
  const P2Mesh mesh = mesh_with_gmsh(c.spec((c.b - c.a) / 16));
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  // The mesh: every boundary edge tagged 1..4, curved P2 edges on the arcs (edge nodes on
  // the circle, not on the chord), the area of the quarter ring.
  for (int tag = 1; tag <= 4; ++tag) EXPECT_FALSE(tagged_nodes(mesh, tag).empty());
  for (int n : tagged_nodes(mesh, 4)) EXPECT_NEAR(mesh.nodes[n].norm(), c.a, 1e-12);
  EXPECT_NEAR(mesh_area(mesh), pi / 4 * (c.b * c.b - c.a * c.a), 1e-8 * c.b * c.b);
  // The node estimate before meshing (2785 for this spec) against Gmsh's count (2992).
  const double estimate = estimate_node_count(c.spec((c.b - c.a) / 16));
  EXPECT_GT(estimate, 0.8 * mesh.node_count());
  EXPECT_LT(estimate, 1.25 * mesh.node_count());
  // With a refinement (Flamant k = 16, 1895 nodes) the estimate is an upper bound.
  const Flamant fl;
  const double graded = estimate_node_count(fl.spec(16));
  EXPECT_GT(graded, 1895);
  EXPECT_LT(graded, 4 * 1895);
}

TEST(FeMesher, RefusesOversizedAndIllFormedSpecs) {
  const Lame c;
  MeshSpec huge = c.spec(1e-6);   // ~2.7e7 nodes
  try {
    mesh_with_gmsh(huge);
    ADD_FAILURE() << "a mesh of 1e7 nodes was not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
  MeshSpec open = c.spec(0.01);
  open.loops[0].pop_back();   // the loop no longer closes
  EXPECT_THROW(mesh_with_gmsh(open), std::invalid_argument);
  MeshSpec wide = c.spec(0.01);
  wide.loops[0][1].points[2] = Vector2d(-c.b, 0);   // an arc of pi
  EXPECT_THROW(mesh_with_gmsh(wide), std::invalid_argument);
}
