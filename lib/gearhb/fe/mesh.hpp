#pragma once
// A 2-D mesh of 6-node quadratic triangles (P2) with 3-node boundary edges carrying
// physical tags: the mesh that lib/gearhb/fe/elasticity.hpp computes on.
//
// Node numbering of a triangle (Gmsh's element type 9; Zienkiewicz, Taylor & Zhu, The
// Finite Element Method, 7th ed., vol. 1, §6.5): corners 0, 1, 2 counter-clockwise, then
// the edge nodes 3 on edge 0-1, 4 on edge 1-2, 5 on edge 2-0. In area coordinates
// L0 = 1 - xi - eta, L1 = xi, L2 = eta of the reference triangle (0,0), (1,0), (0,1),
//
//     N0 = L0 (2 L0 - 1)   N1 = L1 (2 L1 - 1)   N2 = L2 (2 L2 - 1)
//     N3 = 4 L0 L1         N4 = 4 L1 L2         N5 = 4 L2 L0,
//
// and the element is isoparametric, x = sum_i N_i x_i: an edge node off the straight
// chord makes a curved (quadratic) edge, as Gmsh places it on a curved boundary.
//
// A boundary edge is [end a, end b, middle] (Gmsh's element type 8), oriented so that the
// domain lies on its left: walking from a to b, the outward normal points to the right,
// n = (t_y, -t_x) for the tangent t (orient_boundary_edges does this).
//
// Degrees of freedom elsewhere in fe/: node n carries u_x at 2n and u_y at 2n+1.
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace gearhb::fe {

struct P2Mesh {
  std::vector<Eigen::Vector2d> nodes;          // coordinates [m]
  std::vector<std::array<int, 6>> triangles;   // node numbers, order above
  std::vector<std::array<int, 3>> edges;       // boundary edges [a, b, middle]
  std::vector<int> edge_tags;                  // physical tag of each boundary edge

  int node_count() const { return int(nodes.size()); }
  int dof_count() const { return 2 * node_count(); }
};

// Throws std::invalid_argument naming what is wrong: a node number out of range, edge
// and tag counts that differ, a triangle whose Jacobian is not positive at its corners
// and its centroid (inverted, degenerate or too strongly curved), or a boundary edge that
// is not an edge of a triangle.
void check_mesh(const P2Mesh& mesh);

// Turns every triangle counter-clockwise (positive Jacobian at its centroid) and every
// boundary edge so that its triangle lies on its left. Throws std::invalid_argument for
// a boundary edge that is not an edge of a triangle.
void orient(P2Mesh& mesh);

// The nodes of all boundary edges with this tag (corners and middles), sorted, unique.
std::vector<int> tagged_nodes(const P2Mesh& mesh, int tag);

// Sum of the triangles' areas (exact for curved P2 triangles: 3-point rule on det J,
// a polynomial of degree 2).
double mesh_area(const P2Mesh& mesh);

// A structured P2 mesh of the rectangle [x0, x0+lx] x [y0, y0+ly]: nx x ny cells, each
// cut into two triangles along its diagonal from lower left to upper right. Boundary
// edge tags: 1 bottom (y = y0), 2 right, 3 top, 4 left. For the checks of a beam or a
// patch; meshes of real shapes come from Gmsh (gmsh_mesher.hpp).
P2Mesh rectangle_mesh(double x0, double y0, double lx, double ly, int nx, int ny);

}  // namespace gearhb::fe
