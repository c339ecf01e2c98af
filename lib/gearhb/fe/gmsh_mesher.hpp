#pragma once
// Meshing a plane region with Gmsh (C++ API, Debian libgmsh-dev 4.8; Geuzaine & Remacle,
// IJNME 79:1309, 2009) into P2 triangles (lib/gearhb/fe/mesh.hpp).
//
// The region: closed boundary loops, the first the outer boundary, the others holes.
// A loop is a chain of segments, each ending where the next begins (the last where the
// first begins); every segment carries a physical tag that its boundary edges keep:
//   polyline    straight lines through the points (one Gmsh line per pair);
//   spline      Gmsh's interpolating spline through the points (a tooth flank given by
//               points);
//   circle_arc  points = {start, centre, end}, an arc of less than pi.
// Second-order elements: Gmsh places the edge nodes of boundary edges on the curves
// (Mesh.ElementOrder = 2, Mesh.SecondOrderLinear = 0), so curved boundaries are curved
// P2 edges.
//
// Element size: `size` everywhere (Mesh.MeshSizeMax), smaller near given points and
// segments by Gmsh's Distance + Threshold fields (the minimum of all refinements):
//   h(d) = size_min for d <= dist_min, linear up to `size` at d = dist_max, `size` beyond,
// d the distance to the refinement's points/segments. Sizes from the geometry's points
// and curvature are switched off, so h is only what is asked for.
//
// Memory guard: before Gmsh runs, the number of P2 nodes is estimated from the size
// field, N ~ 2 * (triangles) = 2 * int 4 / (sqrt(3) h^2) dA (equilateral triangles of
// side h; a P2 mesh has about twice as many nodes as triangles), the integral by
// sampling h on a grid over the outer loop; above MeshSpec::max_nodes the mesh is refused
// (std::invalid_argument) before it is built. The default 2 million nodes is the size
// whose Cholesky factor fits the solver's default limit (linear_solver.hpp).
//
// Gmsh is a process-wide singleton and not thread-safe: every call here holds one mutex,
// initialises Gmsh (no configuration files, General.Terminal = 0 and General.Verbosity
// = 0: nothing printed) and finalises it before returning, also on an exception. A
// program must not use the Gmsh API itself while a mesh is being built.
#include <vector>

#include <Eigen/Dense>

#include "gearhb/fe/mesh.hpp"

namespace gearhb::fe {

enum class CurveKind { polyline, spline, circle_arc };

struct BoundarySegment {
  CurveKind kind = CurveKind::polyline;
  std::vector<Eigen::Vector2d> points;
  int tag = 1;   // physical tag (> 0) of its boundary edges
};

using BoundaryLoop = std::vector<BoundarySegment>;

struct Refinement {
  std::vector<Eigen::Vector2d> points;   // refine near these points ...
  std::vector<std::pair<int, int>> segments;   // ... and near these (loop, segment) indices
  double size_min = 0;    // element size near them [m]
  double dist_min = 0;    // size_min up to this distance [m]
  double dist_max = 0;    // the global size from this distance on [m]
};

struct MeshSpec {
  std::vector<BoundaryLoop> loops;   // outer boundary first, then holes
  double size = 0;                   // global element size [m]
  std::vector<Refinement> refinements;
  double max_nodes = 2e6;            // memory guard (above)
};

// The estimated number of P2 nodes (memory guard above). Throws std::invalid_argument
// for an ill-formed spec (no loop, a loop that is not closed, a size <= 0, a circle arc
// without three points, ...).
double estimate_node_count(const MeshSpec& spec);

// The P2 mesh, oriented (mesh.hpp) and checked. Throws std::invalid_argument for an
// ill-formed spec or an estimate above max_nodes, std::runtime_error when Gmsh fails
// (its error messages in the text).
P2Mesh mesh_with_gmsh(const MeshSpec& spec);

}  // namespace gearhb::fe
