#include "gearhb/fe/gmsh_mesher.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>

namespace gearhb::fe {

namespace {

constexpr double pi = 3.14159265358979323846;

std::string where(int loop, int segment) {
  return "loop " + std::to_string(loop) + ", segment " + std::to_string(segment);
}

const Eigen::Vector2d& start_of(const BoundarySegment& s) { return s.points.front(); }
const Eigen::Vector2d& end_of(const BoundarySegment& s) { return s.points.back(); }

double arc_angle(const BoundarySegment& s) {
  const Eigen::Vector2d a = s.points[0] - s.points[1], b = s.points[2] - s.points[1];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));   // signed, in (-pi, pi]
}

// A polyline through the segment (arcs by 32 chords): for the estimate of the size field.
std::vector<Eigen::Vector2d> sample(const BoundarySegment& s) {
  if (s.kind != CurveKind::circle_arc) return s.points;
  const Eigen::Vector2d c = s.points[1], a = s.points[0] - c;
  const double phi = arc_angle(s), r = a.norm(), a0 = std::atan2(a.y(), a.x());
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 32; ++i) p.push_back(c + r * Eigen::Vector2d(std::cos(a0 + phi * i / 32), std::sin(a0 + phi * i / 32)));
  return p;
}

double extent(const MeshSpec& spec) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (const auto& loop : spec.loops)
    for (const auto& s : loop)
      for (const auto& p : s.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
  return (hi - lo).norm();
}

void check_segment(const BoundarySegment& s, int l, int i, double tol) {
  const bool arc = s.kind == CurveKind::circle_arc;
  if ((arc && s.points.size() != 3) || s.points.size() < 2)
    throw std::invalid_argument("mesh spec: " + where(l, i) + " needs " + (arc ? "3 points (start, centre, end)" : "2 or more points"));
  if (s.tag <= 0) throw std::invalid_argument("mesh spec: " + where(l, i) + " has a tag <= 0");
  for (const auto& p : s.points)
    if (!p.allFinite()) throw std::invalid_argument("mesh spec: " + where(l, i) + " has a point that is not finite");
  if (arc) {
    const double r0 = (s.points[0] - s.points[1]).norm(), r1 = (s.points[2] - s.points[1]).norm();
    if (std::abs(r0 - r1) > tol || !(std::abs(arc_angle(s)) < pi - 1e-9) || r0 <= tol)
      throw std::invalid_argument("mesh spec: " + where(l, i) + ": a circle arc needs start and end equally far from the centre and less than pi");
  }
}

void check_spec(const MeshSpec& spec) {
  if (spec.loops.empty()) throw std::invalid_argument("mesh spec: no boundary loop");
  if (!(spec.size > 0)) throw std::invalid_argument("mesh spec: size must be > 0");
  const double tol = 1e-9 * extent(spec);
  for (int l = 0; l < int(spec.loops.size()); ++l) {
    const auto& loop = spec.loops[l];
    if (loop.empty()) throw std::invalid_argument("mesh spec: loop " + std::to_string(l) + " is empty");
    for (int i = 0; i < int(loop.size()); ++i) {
      check_segment(loop[i], l, i, tol);
      const auto& next = loop[(i + 1) % loop.size()];
      if ((end_of(loop[i]) - start_of(next)).norm() > tol)
        throw std::invalid_argument("mesh spec: " + where(l, i) + " does not end where the next segment begins");
    }
  }
  for (const auto& r : spec.refinements) {
    if (!(r.size_min > 0) || !(r.dist_min >= 0) || !(r.dist_max > r.dist_min))
      throw std::invalid_argument("mesh spec: a refinement needs size_min > 0 and 0 <= dist_min < dist_max");
    for (const auto& [l, i] : r.segments)
      if (l < 0 || l >= int(spec.loops.size()) || i < 0 || i >= int(spec.loops[l].size()))
        throw std::invalid_argument("mesh spec: a refinement names " + where(l, i) + ", which does not exist");
  }
}

double loop_area(const BoundaryLoop& loop) {
  double twice = 0;
  for (const auto& s : loop) {
    const auto p = sample(s);
    for (std::size_t i = 0; i + 1 < p.size(); ++i) twice += p[i].x() * p[i + 1].y() - p[i + 1].x() * p[i].y();
  }
  return std::abs(twice) / 2;
}

// int 1/h^2 over the band dist_min < d < dist_max: with h linear from size_min to size,
// per unit length (band) and per radian (disc, weight r).
struct GradedIntegrals {
  double band = 0, disc = 0;
};
GradedIntegrals graded(const Refinement& r, double size) {
  GradedIntegrals g;
  const int n = 200;
  const double dr = (r.dist_max - r.dist_min) / n;
  for (int i = 0; i < n; ++i) {
    const double d = r.dist_min + (i + 0.5) * dr;
    const double h = r.size_min + (size - r.size_min) * (d - r.dist_min) / (r.dist_max - r.dist_min);
    g.band += dr / (h * h);
    g.disc += d * dr / (h * h);
  }
  return g;
}

}  // namespace

double estimate_node_count(const MeshSpec& spec) {
  check_spec(spec);
  double area = loop_area(spec.loops[0]);
  for (std::size_t l = 1; l < spec.loops.size(); ++l) area -= loop_area(spec.loops[l]);
  // I = int 1/h^2 dA, bounded above: the whole area at the global size plus, for every
  // refinement, discs round its points and bands (with end discs) along its segments at
  // the graded size (overlaps counted twice: the estimate errs on the large side).
  double integral = area / (spec.size * spec.size);
  for (const auto& r : spec.refinements) {
    const GradedIntegrals g = graded(r, std::max(spec.size, r.size_min));
    const double core = 1 / (r.size_min * r.size_min);
    const double disc = pi * r.dist_min * r.dist_min * core + 2 * pi * g.disc;
    integral += disc * double(r.points.size());
    for (const auto& [l, i] : r.segments) {
      const auto p = sample(spec.loops[l][i]);
      double length = 0;
      for (std::size_t k = 0; k + 1 < p.size(); ++k) length += (p[k + 1] - p[k]).norm();
      integral += length * (2 * r.dist_min * core + 2 * g.band) + disc;
    }
  }
  return 2 * 4 / std::sqrt(3.0) * integral;
}

namespace {

// gearhb_gmsh (gmsh_module.cpp), loaded on the first mesh: from the build tree, else from where
// `cmake --install` puts it. A module that cannot be loaded is a runtime_error naming both paths.
using GenerateFn = int (*)(const MeshSpec&, P2Mesh&, std::string&);

GenerateFn load_gmsh_module() {
  std::string why;
  for (const char* path : {GEARHB_GMSH_MODULE, GEARHB_GMSH_MODULE_INSTALLED}) {
    if (void* handle = dlopen(path, RTLD_NOW | RTLD_LOCAL)) {
      if (void* fn = dlsym(handle, "gearhb_gmsh_generate")) return reinterpret_cast<GenerateFn>(fn);
    }
    const char* e = dlerror();
    why += std::string(why.empty() ? "" : "; ") + (e ? e : path);
  }
  throw std::runtime_error("Gmsh cannot be loaded (the module gearhb_gmsh): " + why);
}

}  // namespace

P2Mesh mesh_with_gmsh(const MeshSpec& spec) {
  const double estimate = estimate_node_count(spec);
  if (estimate > spec.max_nodes)
    throw std::invalid_argument("mesh too large: about " + std::to_string(std::llround(estimate)) +
                                " nodes estimated from the size field, above the limit of " +
                                std::to_string(std::llround(spec.max_nodes)) + " (MeshSpec::max_nodes)");
  static const GenerateFn generate = load_gmsh_module();   // once; thread-safe (a static's initialisation)
  P2Mesh mesh;
  std::string error;
  switch (generate(spec, mesh, error)) {
    case 0: break;
    case 2: throw std::bad_alloc();
    default: throw std::runtime_error(error);
  }
  if (mesh.triangles.empty()) throw std::runtime_error("Gmsh made no triangles");
  orient(mesh);
  check_mesh(mesh);
  return mesh;
}

}  // namespace gearhb::fe
