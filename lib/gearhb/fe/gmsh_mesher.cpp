#include "gearhb/fe/gmsh_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

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

std::mutex gmsh_mutex;

// Gmsh initialised for one call, finalised on every way out.
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 0);
    gmsh::logger::start();
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // Throws std::runtime_error with Gmsh's error lines if it logged any.
  static void throw_on_errors(const std::string& step) {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    std::string errors;
    for (const auto& line : log)
      if (line.rfind("Error", 0) == 0) errors += (errors.empty() ? "" : "; ") + line;
    if (!errors.empty()) throw std::runtime_error("Gmsh failed at " + step + ": " + errors);
  }
};

int add_point(const Eigen::Vector2d& p) { return gmsh::model::geo::addPoint(p.x(), p.y(), 0.0); }

// The Gmsh curves of one segment from point tag `from` to `to`.
std::vector<int> add_segment(const BoundarySegment& s, int from, int to) {
  std::vector<int> inner{from};
  for (std::size_t i = 1; i + 1 < s.points.size(); ++i) inner.push_back(add_point(s.points[i]));
  inner.push_back(to);
  switch (s.kind) {
    case CurveKind::circle_arc: return {gmsh::model::geo::addCircleArc(from, inner[1], to)};
    case CurveKind::spline: return {gmsh::model::geo::addSpline(inner)};
    case CurveKind::polyline: break;
  }
  std::vector<int> lines;
  for (std::size_t i = 0; i + 1 < inner.size(); ++i) lines.push_back(gmsh::model::geo::addLine(inner[i], inner[i + 1]));
  return lines;
}

struct Geometry {
  std::vector<std::vector<std::vector<int>>> curves;   // [loop][segment] -> Gmsh curves
  std::map<int, std::vector<int>> curves_of_tag;
};

Geometry build_geometry(const MeshSpec& spec) {
  Geometry g;
  std::vector<int> loop_tags;
  for (const auto& loop : spec.loops) {
    std::vector<int> starts;
    for (const auto& s : loop) starts.push_back(add_point(start_of(s)));
    std::vector<std::vector<int>> segs;
    std::vector<int> all;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      segs.push_back(add_segment(loop[i], starts[i], starts[(i + 1) % loop.size()]));
      all.insert(all.end(), segs.back().begin(), segs.back().end());
      auto& tagged = g.curves_of_tag[loop[i].tag];
      tagged.insert(tagged.end(), segs.back().begin(), segs.back().end());
    }
    g.curves.push_back(segs);
    loop_tags.push_back(gmsh::model::geo::addCurveLoop(all));
  }
  gmsh::model::geo::addPlaneSurface(loop_tags);
  return g;
}

void add_size_fields(const MeshSpec& spec, const Geometry& g) {
  std::vector<double> thresholds;
  for (const auto& r : spec.refinements) {
    std::vector<double> points, curves;
    for (const auto& p : r.points) points.push_back(add_point(p));
    for (const auto& [l, i] : r.segments)
      for (int c : g.curves[l][i]) curves.push_back(c);
    gmsh::model::geo::synchronize();
    const int distance = gmsh::model::mesh::field::add("Distance");
    if (!points.empty()) gmsh::model::mesh::field::setNumbers(distance, "PointsList", points);
    if (!curves.empty()) gmsh::model::mesh::field::setNumbers(distance, "CurvesList", curves);
    // Points sampled per curve for the distance (Gmsh 4.8's name; "Sampling" from 4.9 on).
    gmsh::model::mesh::field::setNumber(distance, "NNodesByEdge", 200);
    const int threshold = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMin", r.size_min);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMax", spec.size);
    gmsh::model::mesh::field::setNumber(threshold, "DistMin", r.dist_min);
    gmsh::model::mesh::field::setNumber(threshold, "DistMax", r.dist_max);
    thresholds.push_back(threshold);
  }
  if (thresholds.empty()) return;
  const int minimum = gmsh::model::mesh::field::add("Min");
  gmsh::model::mesh::field::setNumbers(minimum, "FieldsList", thresholds);
  gmsh::model::mesh::field::setAsBackgroundMesh(minimum);
}

void set_mesh_options(const MeshSpec& spec) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", spec.size);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.Algorithm", 6);   // Frontal-Delaunay, Gmsh's default for 2-D
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::option::setNumber("Mesh.SecondOrderLinear", 0);   // edge nodes on the curves
}

// The P2 mesh Gmsh made: triangles (type 9), tagged boundary edges (type 8); nodes
// renumbered 0.. in the order the triangles first use them (unused points dropped).
P2Mesh extract_mesh(const Geometry& g) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> position;
  for (std::size_t i = 0; i < tags.size(); ++i) position[tags[i]] = i;
  P2Mesh m;
  std::unordered_map<std::size_t, int> number;
  auto node = [&](std::size_t tag) {
    const auto it = number.find(tag);
    if (it != number.end()) return it->second;
    const std::size_t p = position.at(tag);
    m.nodes.emplace_back(xyz[3 * p], xyz[3 * p + 1]);
    return number[tag] = int(m.nodes.size()) - 1;
  };
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, -1);
  for (std::size_t k = 0; k < types.size(); ++k) {
    if (types[k] != 9) throw std::runtime_error("Gmsh made elements of type " + std::to_string(types[k]) + ", not P2 triangles");
    const auto& n = node_tags[k];
    for (std::size_t e = 0; e + 6 <= n.size(); e += 6)
      m.triangles.push_back({node(n[e]), node(n[e + 1]), node(n[e + 2]), node(n[e + 3]), node(n[e + 4]), node(n[e + 5])});
  }
  for (const auto& [tag, curves] : g.curves_of_tag) {
    for (int c : curves) {
      gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, c);
      for (std::size_t k = 0; k < types.size(); ++k) {
        if (types[k] != 8) continue;
        const auto& n = node_tags[k];
        for (std::size_t e = 0; e + 3 <= n.size(); e += 3) {
          m.edges.push_back({node(n[e]), node(n[e + 1]), node(n[e + 2])});
          m.edge_tags.push_back(tag);
        }
      }
    }
  }
  return m;
}

}  // namespace

P2Mesh mesh_with_gmsh(const MeshSpec& spec) {
  const double estimate = estimate_node_count(spec);
  if (estimate > spec.max_nodes)
    throw std::invalid_argument("mesh too large: about " + std::to_string(std::llround(estimate)) +
                                " nodes estimated from the size field, above the limit of " +
                                std::to_string(std::llround(spec.max_nodes)) + " (MeshSpec::max_nodes)");
  P2Mesh mesh;
  {
    const std::lock_guard<std::mutex> lock(gmsh_mutex);
    const GmshSession session;
    try {
      gmsh::model::add("gearhb_fe");
      const Geometry g = build_geometry(spec);
      gmsh::model::geo::synchronize();
      for (const auto& [tag, curves] : g.curves_of_tag) gmsh::model::addPhysicalGroup(1, curves, tag);
      add_size_fields(spec, g);
      set_mesh_options(spec);
      GmshSession::throw_on_errors("building the geometry");
      gmsh::model::mesh::generate(2);
      GmshSession::throw_on_errors("meshing");
      mesh = extract_mesh(g);
    } catch (const std::string& message) {   // Gmsh 4.8 throws its error message as a string
      throw std::runtime_error("Gmsh failed: " + message);
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error("Gmsh made no triangles");
  orient(mesh);
  check_mesh(mesh);
  return mesh;
}

}  // namespace gearhb::fe
