#pragma once
// Linear elasticity in the plane on P2 triangles (lib/gearhb/fe/mesh.hpp): stiffness,
// loads, stresses and strain energy.
//
// Equations (Zienkiewicz, Taylor & Zhu, The Finite Element Method, 7th ed., vol. 1,
// ch. 2 and 6; Timoshenko & Goodier, Theory of Elasticity, 3rd ed., §§7-8):
//   strain  eps = B u_e,  eps = (eps_xx, eps_yy, gamma_xy),
//           B = [dN/dx 0; 0 dN/dy; dN/dy dN/dx] per node (6 nodes, 12 DOFs u_x, u_y);
//   stress  sigma = D eps, sigma = (s_xx, s_yy, s_xy), with
//     plane strain (eps_zz = 0; the default: a gear face wide against its tooth)
//       D = E / ((1+nu)(1-2nu)) [1-nu nu 0; nu 1-nu 0; 0 0 (1-2nu)/2],  s_zz = nu (s_xx + s_yy),
//     plane stress (s_zz = 0; a thin plate)
//       D = E / (1-nu^2) [1 nu 0; nu 1 0; 0 0 (1-nu)/2];
//   element stiffness  K_e = t * int_e B^T D B dA  by the triangle rule of p2_element.hpp
//     (degree 2, 3 points by default: exact for straight-sided elements), thickness t
//     = 1 m unless set: forces and energies are then per metre of face width;
//   edge load  f_i = t * int_edge N_i tr ds,  tr the traction (force per area) [Pa];
//   strain energy  U = 1/2 u^T K u  [J, per the thickness].
// Global DOFs: node n has u_x at 2n, u_y at 2n+1. Assembly: triplets summed into an
// Eigen::SparseMatrix (compressed column, symmetric, both triangles stored).
#include <functional>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "gearhb/fe/mesh.hpp"

namespace gearhb::fe {

enum class PlaneModel { strain, stress };

struct Material {
  double youngs_modulus = 210e9;   // E [Pa] (steel)
  double poisson_ratio = 0.3;      // nu [-], in (-1, 0.5)
  PlaneModel plane = PlaneModel::strain;
  double thickness = 1.0;          // t [m]: 1 m gives forces and stiffness per metre of width
};

// D (3x3) above. Throws std::invalid_argument for E <= 0, nu outside (-1, 0.5), t <= 0.
Eigen::Matrix3d elasticity_matrix(const Material& material);

using ElementMatrix = Eigen::Matrix<double, 12, 12>;

// K_e of triangle `element`, DOFs ordered (u_x, u_y) of nodes 0..5.
// quadrature_degree: 2 (default; exact on straight sides) or 4 (curved elements).
ElementMatrix element_stiffness(const P2Mesh& mesh, int element, const Material& material,
                                int quadrature_degree = 2);

// K (dof_count x dof_count).
Eigen::SparseMatrix<double> assemble_stiffness(const P2Mesh& mesh, const Material& material,
                                               int quadrature_degree = 2);

// Traction [Pa] at a boundary point x with outward unit normal n.
using Traction = std::function<Eigen::Vector2d(const Eigen::Vector2d& x, const Eigen::Vector2d& n)>;

// f += loads of the traction over every boundary edge with this tag (3-point Gauss,
// curved edges by their isoparametric map).
void add_edge_traction(const P2Mesh& mesh, const Material& material, int tag, const Traction& traction,
                       Eigen::VectorXd& f);
// A pressure p [Pa] pushing on the boundary: traction -p n.
void add_pressure(const P2Mesh& mesh, const Material& material, int tag, double pressure, Eigen::VectorXd& f);
// A force [N] at one node.
void add_nodal_force(int node, const Eigen::Vector2d& force, Eigen::VectorXd& f);

// Stress (s_xx, s_yy, s_xy, s_zz) [Pa] of the displacement u at points.
struct StressPoint {
  Eigen::Vector2d x;
  Eigen::Vector4d stress;
};

// At the points of the triangle rule of this degree in every element (element by element).
std::vector<StressPoint> gauss_point_stresses(const P2Mesh& mesh, const Material& material,
                                              const Eigen::VectorXd& u, int quadrature_degree = 2);

// At the nodes (row n = node n, columns s_xx, s_yy, s_xy, s_zz): each element's stress
// evaluated at its own nodes, averaged over the elements sharing the node. On a straight
// P2 element the stress is linear, so this equals extrapolating its 3-point Gauss values.
Eigen::MatrixX4d nodal_stresses(const P2Mesh& mesh, const Material& material, const Eigen::VectorXd& u);

// The stress of the displacement u inside element `element` at (xi, eta).
Eigen::Vector4d element_stress(const P2Mesh& mesh, const Material& material, const Eigen::VectorXd& u,
                               int element, double xi, double eta);

// U = 1/2 u^T K u.
double strain_energy(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& u);

}  // namespace gearhb::fe
