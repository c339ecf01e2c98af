#include "gearhb/fe/elasticity.hpp"

#include <stdexcept>
#include <string>

#include "gearhb/fe/p2_element.hpp"

namespace gearhb::fe {

namespace {

using StrainMatrix = Eigen::Matrix<double, 3, 12>;

P2Coordinates coordinates(const P2Mesh& mesh, int element) {
  P2Coordinates x;
  for (int i = 0; i < 6; ++i) x.col(i) = mesh.nodes[mesh.triangles[element][i]];
  return x;
}

StrainMatrix strain_matrix(const P2Gradients& g) {
  StrainMatrix b = StrainMatrix::Zero();
  for (int i = 0; i < 6; ++i) {
    b(0, 2 * i) = g(0, i);
    b(1, 2 * i + 1) = g(1, i);
    b(2, 2 * i) = g(1, i);
    b(2, 2 * i + 1) = g(0, i);
  }
  return b;
}

Eigen::Matrix<double, 12, 1> element_displacements(const P2Mesh& mesh, int element, const Eigen::VectorXd& u) {
  Eigen::Matrix<double, 12, 1> ue;
  for (int i = 0; i < 6; ++i) {
    const int n = mesh.triangles[element][i];
    ue(2 * i) = u(2 * n);
    ue(2 * i + 1) = u(2 * n + 1);
  }
  return ue;
}

// (s_xx, s_yy, s_xy) -> (s_xx, s_yy, s_xy, s_zz).
Eigen::Vector4d with_out_of_plane(const Eigen::Vector3d& s, const Material& m) {
  const double szz = m.plane == PlaneModel::strain ? m.poisson_ratio * (s(0) + s(1)) : 0.0;
  return {s(0), s(1), s(2), szz};
}

void check_displacements(const P2Mesh& mesh, const Eigen::VectorXd& u) {
  if (u.size() != mesh.dof_count())
    throw std::invalid_argument("displacements: " + std::to_string(u.size()) + " values for " +
                                std::to_string(mesh.dof_count()) + " DOFs");
}

}  // namespace

Eigen::Matrix3d elasticity_matrix(const Material& m) {
  const double e = m.youngs_modulus, nu = m.poisson_ratio;
  if (!(e > 0) || !(nu > -1 && nu < 0.5) || !(m.thickness > 0))
    throw std::invalid_argument("material: needs E > 0, -1 < nu < 0.5 and thickness > 0");
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (m.plane == PlaneModel::strain) {
    const double c = e / ((1 + nu) * (1 - 2 * nu));
    d << 1 - nu, nu, 0, nu, 1 - nu, 0, 0, 0, (1 - 2 * nu) / 2;
    return c * d;
  }
  const double c = e / (1 - nu * nu);
  d << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return c * d;
}

ElementMatrix element_stiffness(const P2Mesh& mesh, int element, const Material& material, int quadrature_degree) {
  const Eigen::Matrix3d d = elasticity_matrix(material);
  const P2Coordinates x = coordinates(mesh, element);
  ElementMatrix k = ElementMatrix::Zero();
  for (const auto& q : triangle_rule(quadrature_degree)) {
    double det_j = 0;
    const StrainMatrix b = strain_matrix(p2_physical_gradients(x, q.xi, q.eta, det_j));
    if (!(det_j > 0))
      throw std::invalid_argument("element_stiffness: triangle " + std::to_string(element) +
                                  " has det J <= 0 at a quadrature point");
    k.noalias() += (q.weight * det_j * material.thickness) * b.transpose() * d * b;
  }
  return k;
}

Eigen::SparseMatrix<double> assemble_stiffness(const P2Mesh& mesh, const Material& material, int quadrature_degree) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(mesh.triangles.size() * 144);
  for (int e = 0; e < int(mesh.triangles.size()); ++e) {
    const ElementMatrix k = element_stiffness(mesh, e, material, quadrature_degree);
    const auto& t = mesh.triangles[e];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) triplets.emplace_back(2 * t[i / 2] + i % 2, 2 * t[j / 2] + j % 2, k(i, j));
  }
  Eigen::SparseMatrix<double> kg(mesh.dof_count(), mesh.dof_count());
  kg.setFromTriplets(triplets.begin(), triplets.end());
  return kg;
}

void add_edge_traction(const P2Mesh& mesh, const Material& material, int tag, const Traction& traction,
                       Eigen::VectorXd& f) {
  if (f.size() != mesh.dof_count()) throw std::invalid_argument("add_edge_traction: f has the wrong size");
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    if (mesh.edge_tags[e] != tag) continue;
    const auto& edge = mesh.edges[e];
    Eigen::Matrix<double, 2, 3> x;
    for (int i = 0; i < 3; ++i) x.col(i) = mesh.nodes[edge[i]];
    for (const auto& q : gauss_legendre_3()) {
      const Eigen::Vector3d n = edge_shape(q.s);
      const Eigen::Vector2d tangent = x * edge_shape_derivative(q.s);   // dx/ds
      const double ds = tangent.norm();
      const Eigen::Vector2d normal(tangent(1) / ds, -tangent(0) / ds);   // domain on the left
      const Eigen::Vector2d tr = traction(x * n, normal);
      for (int i = 0; i < 3; ++i) f.segment<2>(2 * edge[i]) += (q.weight * ds * material.thickness * n(i)) * tr;
    }
  }
}

void add_pressure(const P2Mesh& mesh, const Material& material, int tag, double pressure, Eigen::VectorXd& f) {
  add_edge_traction(mesh, material, tag,
                    [pressure](const Eigen::Vector2d&, const Eigen::Vector2d& n) -> Eigen::Vector2d { return -pressure * n; },
                    f);
}

void add_nodal_force(int node, const Eigen::Vector2d& force, Eigen::VectorXd& f) {
  if (node < 0 || 2 * node + 1 >= f.size()) throw std::invalid_argument("add_nodal_force: no such node");
  f.segment<2>(2 * node) += force;
}

Eigen::Vector4d element_stress(const P2Mesh& mesh, const Material& material, const Eigen::VectorXd& u, int element,
                               double xi, double eta) {
  double det_j = 0;
  const StrainMatrix b = strain_matrix(p2_physical_gradients(coordinates(mesh, element), xi, eta, det_j));
  const Eigen::Vector3d s = elasticity_matrix(material) * (b * element_displacements(mesh, element, u));
  return with_out_of_plane(s, material);
}

std::vector<StressPoint> gauss_point_stresses(const P2Mesh& mesh, const Material& material, const Eigen::VectorXd& u,
                                              int quadrature_degree) {
  check_displacements(mesh, u);
  std::vector<StressPoint> points;
  const auto& rule = triangle_rule(quadrature_degree);
  points.reserve(mesh.triangles.size() * rule.size());
  for (int e = 0; e < int(mesh.triangles.size()); ++e) {
    const P2Coordinates x = coordinates(mesh, e);
    for (const auto& q : rule)
      points.push_back({x * p2_shape(q.xi, q.eta), element_stress(mesh, material, u, e, q.xi, q.eta)});
  }
  return points;
}

Eigen::MatrixX4d nodal_stresses(const P2Mesh& mesh, const Material& material, const Eigen::VectorXd& u) {
  check_displacements(mesh, u);
  static const double corner[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  Eigen::MatrixX4d sum = Eigen::MatrixX4d::Zero(mesh.node_count(), 4);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(mesh.node_count());
  for (int e = 0; e < int(mesh.triangles.size()); ++e) {
    for (int i = 0; i < 6; ++i) {
      const int n = mesh.triangles[e][i];
      sum.row(n) += element_stress(mesh, material, u, e, corner[i][0], corner[i][1]).transpose();
      count(n) += 1;
    }
  }
  for (int n = 0; n < mesh.node_count(); ++n)
    if (count(n) > 0) sum.row(n) /= count(n);
  return sum;
}

double strain_energy(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& u) {
  return 0.5 * u.dot(stiffness * u);
}

}  // namespace gearhb::fe
