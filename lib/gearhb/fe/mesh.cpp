#include "gearhb/fe/mesh.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "gearhb/fe/p2_element.hpp"

namespace gearhb::fe {

namespace {

P2Coordinates coordinates(const P2Mesh& mesh, const std::array<int, 6>& t) {
  P2Coordinates x;
  for (int i = 0; i < 6; ++i) x.col(i) = mesh.nodes[t[i]];
  return x;
}

double det_j_at(const P2Coordinates& x, double xi, double eta) {
  return p2_jacobian(x, p2_reference_gradients(xi, eta)).determinant();
}

// The smallest det J over the corners and the centroid.
double min_det_j(const P2Coordinates& x) {
  return std::min({det_j_at(x, 0, 0), det_j_at(x, 1, 0), det_j_at(x, 0, 1), det_j_at(x, 1.0 / 3, 1.0 / 3)});
}

using EdgeKey = std::pair<int, int>;
EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Each corner pair of a triangle edge -> (triangle, local edge 0..2: 0-1, 1-2, 2-0).
std::map<EdgeKey, std::pair<int, int>> triangle_edges(const P2Mesh& mesh) {
  std::map<EdgeKey, std::pair<int, int>> edges;
  for (int e = 0; e < int(mesh.triangles.size()); ++e) {
    const auto& t = mesh.triangles[e];
    for (int k = 0; k < 3; ++k) edges[key(t[k], t[(k + 1) % 3])] = {e, k};
  }
  return edges;
}

void check_node(const P2Mesh& mesh, int n, const std::string& where) {
  if (n < 0 || n >= mesh.node_count())
    throw std::invalid_argument("mesh: " + where + " names node " + std::to_string(n) + " of " +
                                std::to_string(mesh.node_count()));
}

}  // namespace

void check_mesh(const P2Mesh& mesh) {
  if (mesh.edges.size() != mesh.edge_tags.size())
    throw std::invalid_argument("mesh: " + std::to_string(mesh.edges.size()) + " boundary edges but " +
                                std::to_string(mesh.edge_tags.size()) + " tags");
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    for (int n : mesh.triangles[e]) check_node(mesh, n, "triangle " + std::to_string(e));
    const double d = min_det_j(coordinates(mesh, mesh.triangles[e]));
    if (!(d > 0))
      throw std::invalid_argument("mesh: triangle " + std::to_string(e) +
                                  " has a Jacobian that is not positive (inverted, degenerate or too curved)");
  }
  const auto edges = triangle_edges(mesh);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    for (int n : mesh.edges[e]) check_node(mesh, n, "boundary edge " + std::to_string(e));
    if (!edges.count(key(mesh.edges[e][0], mesh.edges[e][1])))
      throw std::invalid_argument("mesh: boundary edge " + std::to_string(e) + " is not an edge of a triangle");
  }
}

void orient(P2Mesh& mesh) {
  for (auto& t : mesh.triangles) {
    if (det_j_at(coordinates(mesh, t), 1.0 / 3, 1.0 / 3) < 0) {
      // Swap corners 1 and 2; edge nodes follow: 0-1 <-> 0-2 (3 <-> 5), 1-2 stays (4).
      std::swap(t[1], t[2]);
      std::swap(t[3], t[5]);
    }
  }
  const auto edges = triangle_edges(mesh);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    auto& b = mesh.edges[e];
    const auto it = edges.find(key(b[0], b[1]));
    if (it == edges.end())
      throw std::invalid_argument("mesh: boundary edge " + std::to_string(e) + " is not an edge of a triangle");
    const auto& t = mesh.triangles[it->second.first];
    const int k = it->second.second;
    // A counter-clockwise triangle has itself on the left of t[k] -> t[k+1].
    if (b[0] != t[k]) std::swap(b[0], b[1]);
  }
}

std::vector<int> tagged_nodes(const P2Mesh& mesh, int tag) {
  std::vector<int> nodes;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e)
    if (mesh.edge_tags[e] == tag) nodes.insert(nodes.end(), mesh.edges[e].begin(), mesh.edges[e].end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

double mesh_area(const P2Mesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const P2Coordinates x = coordinates(mesh, t);
    for (const auto& q : triangle_rule(2)) area += q.weight * det_j_at(x, q.xi, q.eta);
  }
  return area;
}

P2Mesh rectangle_mesh(double x0, double y0, double lx, double ly, int nx, int ny) {
  if (nx < 1 || ny < 1 || !(lx > 0) || !(ly > 0))
    throw std::invalid_argument("rectangle_mesh: needs lx, ly > 0 and nx, ny >= 1");
  P2Mesh m;
  // A grid of (2nx+1) x (2ny+1) nodes: every second one a corner.
  const int gx = 2 * nx + 1, gy = 2 * ny + 1;
  for (int j = 0; j < gy; ++j)
    for (int i = 0; i < gx; ++i) m.nodes.emplace_back(x0 + lx * i / (gx - 1), y0 + ly * j / (gy - 1));
  auto at = [gx](int i, int j) { return j * gx + i; };
  for (int cj = 0; cj < ny; ++cj) {
    for (int ci = 0; ci < nx; ++ci) {
      const int i = 2 * ci, j = 2 * cj;
      // Lower right triangle (i,j)-(i+2,j)-(i+2,j+2), upper left (i,j)-(i+2,j+2)-(i,j+2).
      m.triangles.push_back({at(i, j), at(i + 2, j), at(i + 2, j + 2), at(i + 1, j), at(i + 2, j + 1), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 2, j + 2), at(i, j + 2), at(i + 1, j + 1), at(i + 1, j + 2), at(i, j + 1)});
    }
  }
  auto edge = [&](int a, int b, int mid, int tag) {
    m.edges.push_back({a, b, mid});
    m.edge_tags.push_back(tag);
  };
  for (int ci = 0; ci < nx; ++ci) {
    const int i = 2 * ci;
    edge(at(i, 0), at(i + 2, 0), at(i + 1, 0), 1);
    edge(at(i + 2, gy - 1), at(i, gy - 1), at(i + 1, gy - 1), 3);
  }
  for (int cj = 0; cj < ny; ++cj) {
    const int j = 2 * cj;
    edge(at(gx - 1, j), at(gx - 1, j + 2), at(gx - 1, j + 1), 2);
    edge(at(0, j + 2), at(0, j), at(0, j + 1), 4);
  }
  return m;
}

}  // namespace gearhb::fe
