#include "gearhb/fe/p2_element.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gearhb::fe {

namespace {

std::vector<TrianglePoint> dunavant_degree2() {
  const double w = 1.0 / 6.0;
  return {{1.0 / 6, 1.0 / 6, w}, {2.0 / 3, 1.0 / 6, w}, {1.0 / 6, 2.0 / 3, w}};
}

// Points of the orbit (a, a), (1-2a, a), (a, 1-2a), each with weight w.
void add_orbit(std::vector<TrianglePoint>& rule, double a, double w) {
  rule.push_back({a, a, w});
  rule.push_back({1 - 2 * a, a, w});
  rule.push_back({a, 1 - 2 * a, w});
}

std::vector<TrianglePoint> dunavant_degree4() {
  std::vector<TrianglePoint> rule;
  add_orbit(rule, 0.445948490915965, 0.223381589678011 / 2);
  add_orbit(rule, 0.091576213509771, 0.109951743655322 / 2);
  return rule;
}

}  // namespace

const std::vector<TrianglePoint>& triangle_rule(int degree) {
  static const std::vector<TrianglePoint> rule2 = dunavant_degree2();
  static const std::vector<TrianglePoint> rule4 = dunavant_degree4();
  if (degree == 2) return rule2;
  if (degree == 4) return rule4;
  throw std::invalid_argument("triangle quadrature of degree " + std::to_string(degree) +
                              ": only degree 2 (3 points) and 4 (6 points) are provided");
}

P2Values p2_shape(double xi, double eta) {
  const double l0 = 1 - xi - eta, l1 = xi, l2 = eta;
  P2Values n;
  n << l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0;
  return n;
}

P2Gradients p2_reference_gradients(double xi, double eta) {
  const double l0 = 1 - xi - eta, l1 = xi, l2 = eta;
  P2Gradients d;
  d.col(0) << -(4 * l0 - 1), -(4 * l0 - 1);
  d.col(1) << 4 * l1 - 1, 0;
  d.col(2) << 0, 4 * l2 - 1;
  d.col(3) << 4 * (l0 - l1), -4 * l1;
  d.col(4) << 4 * l2, 4 * l1;
  d.col(5) << -4 * l2, 4 * (l0 - l2);
  return d;
}

P2Gradients p2_physical_gradients(const P2Coordinates& X, double xi, double eta, double& det_j) {
  const P2Gradients dn = p2_reference_gradients(xi, eta);
  const Eigen::Matrix2d j = p2_jacobian(X, dn);
  det_j = j.determinant();
  // dN/dx = J^{-T} dN/dxi with J^{-T} = adj(J)^T / det J.
  Eigen::Matrix2d inv_t;
  inv_t << j(1, 1), -j(1, 0), -j(0, 1), j(0, 0);
  return (inv_t / det_j) * dn;
}

Eigen::Vector3d edge_shape(double s) {
  return {0.5 * s * (s - 1), 0.5 * s * (s + 1), 1 - s * s};
}

Eigen::Vector3d edge_shape_derivative(double s) {
  return {s - 0.5, s + 0.5, -2 * s};
}

const std::array<LinePoint, 3>& gauss_legendre_3() {
  static const double p = std::sqrt(0.6);
  static const std::array<LinePoint, 3> rule{{{-p, 5.0 / 9}, {0.0, 8.0 / 9}, {p, 5.0 / 9}}};
  return rule;
}

}  // namespace gearhb::fe
