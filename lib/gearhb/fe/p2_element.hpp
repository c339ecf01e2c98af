#pragma once
// The 6-node quadratic triangle (P2) and its 3-node edge: shape functions, their
// derivatives, the isoparametric map, and the quadrature rules used on them.
//
// Shape functions: lib/gearhb/fe/mesh.hpp (numbering of Gmsh type 9). With
// L0 = 1 - xi - eta, L1 = xi, L2 = eta,
//   dN0 = (4L0-1)(-1,-1)   dN1 = (4L1-1)(1,0)   dN2 = (4L2-1)(0,1)
//   dN3 = 4(L0 - L1, -L1)  dN4 = 4(L2, L1)      dN5 = 4(-L2, L0 - L2)     [d/dxi, d/deta]
// The Jacobian J = sum_i x_i dN_i^T maps reference to physical derivatives,
// dN/dx = J^{-T} dN/dxi, and dA = det J dxi deta.
//
// Triangle rules (points in (xi, eta), weights summing to the reference area 1/2):
//   degree 2, 3 points: (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), weights 1/6 each
//     (Strang & Fix 1973, table 4.1; Dunavant 1985, IJNME 21:1129, degree 2). Exact for
//     the stiffness of a straight-sided P2 triangle: B is linear there, B^T D B quadratic.
//   degree 4, 6 points: Dunavant 1985, degree 4 (a = 0.445948490915965, weight
//     0.223381589678011/2; b = 0.091576213509771, weight 0.109951743655322/2, each at
//     (a, a), (1-2a, a), (a, 1-2a)). For curved elements, whose integrand is rational.
// Edge rule: 3-point Gauss-Legendre on s in [-1, 1] (points 0, +-sqrt(3/5), weights 8/9,
//   5/9), exact to degree 5: a quadratic traction times a quadratic shape function on a
//   straight edge (degree 4) is integrated exactly.
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace gearhb::fe {

struct TrianglePoint {
  double xi, eta, weight;   // weight: share of the reference area 1/2
};

// The rule of this polynomial degree: 2 (3 points) or 4 (6 points); otherwise
// std::invalid_argument.
const std::vector<TrianglePoint>& triangle_rule(int degree);

using P2Values = Eigen::Matrix<double, 6, 1>;
using P2Gradients = Eigen::Matrix<double, 2, 6>;   // column i: (dN_i/dxi, dN_i/deta)

P2Values p2_shape(double xi, double eta);
P2Gradients p2_reference_gradients(double xi, double eta);

// Node coordinates of one triangle as the columns of a 2x6 matrix.
using P2Coordinates = Eigen::Matrix<double, 2, 6>;

// J = X dN^T (2x2), columns: dx/dxi, dx/deta.
inline Eigen::Matrix2d p2_jacobian(const P2Coordinates& X, const P2Gradients& dN) {
  return X * dN.transpose();
}

// Physical gradients dN/dx (2x6) and det J at (xi, eta). det J <= 0 is returned as is
// (the caller decides; check_mesh refuses such elements).
P2Gradients p2_physical_gradients(const P2Coordinates& X, double xi, double eta, double& det_j);

// The 3-node edge [a, b, middle] at s in [-1, 1]: shape values (a, b, middle).
Eigen::Vector3d edge_shape(double s);
Eigen::Vector3d edge_shape_derivative(double s);

struct LinePoint {
  double s, weight;   // on [-1, 1], weights summing to 2
};
const std::array<LinePoint, 3>& gauss_legendre_3();

}  // namespace gearhb::fe
