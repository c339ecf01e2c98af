// Gmsh's part of gmsh_mesher (gmsh_mesher.hpp): the geometry, the size fields, the mesh and its
// extraction through Gmsh's C++ API. Built as the module gearhb_gmsh (lib/CMakeLists.txt), the one
// object that links libgmsh: gmsh_mesher.cpp loads it when the first mesh is made (dlopen), so a
// program that never meshes does not load Gmsh's ~100 shared libraries (OpenCASCADE, FLTK, X11:
// about 0.08 s of CPU at every start, nearly all of it the dynamic linker's symbol lookups).
#include <gmsh.h>

#include <exception>
#include <map>
#include <new>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "gearhb/fe/gmsh_mesher.hpp"

namespace gearhb::fe {

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
    for (const auto& s : loop) starts.push_back(add_point(s.points.front()));
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

// The P2 mesh of SPEC as Gmsh made it (gmsh_mesher.cpp checks the spec before and orients and
// checks the mesh after). Gmsh 4.8 throws its error message as a string.
P2Mesh gmsh_generate(const MeshSpec& spec) {
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
    return extract_mesh(g);
  } catch (const std::string& message) {
    throw std::runtime_error("Gmsh failed: " + message);
  }
}

}  // namespace

}  // namespace gearhb::fe

// The module's one entry point (gmsh_mesher.cpp, load_gmsh_module): 0 and the mesh in OUT, 1 and
// the reason in ERROR, 2 out of memory (nothing is thrown across the module's edge).
extern "C" __attribute__((visibility("default"))) int gearhb_gmsh_generate(const gearhb::fe::MeshSpec& spec,
                                                                            gearhb::fe::P2Mesh& out,
                                                                            std::string& error) {
  try {
    out = gearhb::fe::gmsh_generate(spec);
    return 0;
  } catch (const std::bad_alloc&) {
    return 2;
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "Gmsh failed: an exception that is not a std::exception";
  }
  return 1;
}
