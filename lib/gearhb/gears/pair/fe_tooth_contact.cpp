#include "gearhb/gears/pair/fe_tooth_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "gearhb/fe/elasticity.hpp"
#include "gearhb/fe/gmsh_mesher.hpp"
#include "gearhb/fe/p2_element.hpp"
#include "gearhb/gears/pair/coupled_load_sharing.hpp"
#include "gearhb/gears/geometry/tooth_form.hpp"

namespace gearhb {

using Eigen::Vector2d;

namespace {

constexpr double pi = M_PI;
constexpr int bore_tag = 1, left_cut_tag = 2, right_cut_tag = 3;

// Boundary classes of a tooth, left (before the tip) to right.
enum Cls { root_left = 0, fillet_left = 1, flank_left = 2, tip = 3, flank_right = 4, fillet_right = 5, root_right = 6 };
int tooth_tag(int tooth, int cls) { return 100 + 10 * tooth + cls; }

Cls classify(ToothSegment s, bool right) {
  switch (s) {
    case ToothSegment::root: return right ? root_right : root_left;
    case ToothSegment::fillet: return right ? fillet_right : fillet_left;
    case ToothSegment::tip: return tip;
    default: return right ? flank_right : flank_left;   // involute, relief, rounding
  }
}

// The polyline cut into runs of one (tooth, class): one boundary segment each (a Gmsh
// spline through its points, or a line for two points), ending where the next begins.
struct Run {
  int tooth, cls;
  std::vector<Vector2d> points;
};

std::vector<Run> boundary_runs(const FormPolyline& line) {
  std::vector<Run> runs;
  std::map<int, bool> past_tip;   // per tooth: a tip point has been passed
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    const int t = line.tooth[i];
    const bool is_tip = line.segment[i] == ToothSegment::tip;
    const bool right = past_tip[t] && !is_tip;
    if (is_tip) past_tip[t] = true;
    const int cls = classify(line.segment[i], right);
    if (runs.empty() || runs.back().tooth != t || runs.back().cls != cls) runs.push_back({t, cls, {}});
    runs.back().points.push_back(line.points[i]);
  }
  // A point where two segments meet carries the label of the one nearer the tip
  // (tooth_form.hpp): on the right side that is the earlier run, so the junction also
  // starts the next run (each run spans its segment of the form exactly).
  for (std::size_t i = 0; i + 1 < runs.size(); ++i)
    if (runs[i].tooth == runs[i + 1].tooth && runs[i].cls >= tip)
      runs[i + 1].points.insert(runs[i + 1].points.begin(), runs[i].points.back());
  return runs;
}

fe::BoundarySegment segment_of(const std::vector<Vector2d>& points, int tag) {
  fe::BoundarySegment s;
  s.kind = points.size() >= 3 ? fe::CurveKind::spline : fe::CurveKind::polyline;
  s.points = points;
  s.tag = tag;
  return s;
}

// Circle arcs from angle a0 to a1 (polar angle from +y, clockwise) at radius r, each
// under 90 degrees (Gmsh's arcs must be below pi).
std::vector<fe::BoundarySegment> arcs(double r, double a0, double a1, int tag) {
  const int pieces = std::max(1, int(std::ceil(std::abs(a1 - a0) / (0.5 * pi))));
  std::vector<fe::BoundarySegment> out;
  for (int k = 0; k < pieces; ++k) {
    const double b0 = a0 + (a1 - a0) * k / pieces, b1 = a0 + (a1 - a0) * (k + 1) / pieces;
    fe::BoundarySegment s;
    s.kind = fe::CurveKind::circle_arc;
    s.points = {r * Vector2d(std::sin(b0), std::cos(b0)), Vector2d(0, 0), r * Vector2d(std::sin(b1), std::cos(b1))};
    s.tag = tag;
    out.push_back(s);
  }
  return out;
}

// A point on a P2 boundary edge: parameter s in [-1, 1] of the point nearest to x.
struct EdgePoint {
  int edge = -1;
  double s = 0, distance = 1e300;
};

Vector2d edge_position(const fe::P2Mesh& m, int e, double s) {
  const Eigen::Vector3d N = fe::edge_shape(s);
  const auto& n = m.edges[e];
  return N(0) * m.nodes[n[0]] + N(1) * m.nodes[n[1]] + N(2) * m.nodes[n[2]];
}
Vector2d edge_tangent(const fe::P2Mesh& m, int e, double s) {
  const Eigen::Vector3d N = fe::edge_shape_derivative(s);
  const auto& n = m.edges[e];
  return N(0) * m.nodes[n[0]] + N(1) * m.nodes[n[1]] + N(2) * m.nodes[n[2]];
}

EdgePoint nearest_on_edges(const fe::P2Mesh& m, const std::vector<int>& edges, const Vector2d& x) {
  EdgePoint best;
  for (int e : edges) {
    // Coarse samples, then Newton on d/ds |x(s) - x|^2 / 2 = t . (x(s) - x).
    double s = -1, d = 1e300;
    for (int k = 0; k <= 10; ++k) {
      const double sk = -1 + 0.2 * k, dk = (edge_position(m, e, sk) - x).norm();
      if (dk < d) d = dk, s = sk;
    }
    for (int it = 0; it < 20; ++it) {
      const Vector2d r = edge_position(m, e, s) - x, t = edge_tangent(m, e, s);
      const Eigen::Vector3d N2(1.0, 1.0, -2.0);   // second derivatives of the edge shapes
      const auto& n = m.edges[e];
      const Vector2d tt = N2(0) * m.nodes[n[0]] + N2(1) * m.nodes[n[1]] + N2(2) * m.nodes[n[2]];
      const double step = t.dot(r) / (t.squaredNorm() + r.dot(tt));
      s = std::clamp(s - step, -1.0, 1.0);
      if (std::abs(step) < 1e-14) break;
    }
    d = (edge_position(m, e, s) - x).norm();
    if (d < best.distance) best = {e, s, d};
  }
  return best;
}

}  // namespace

struct FeGearModel::Impl {
  GearGeometry gear;
  double E = 0, nu = 0;
  FeGearOptions options;
  fe::Material material;
  fe::P2Mesh mesh;
  std::unique_ptr<fe::ElasticSolver> solver;
  int first_loaded = 0;      // sector tooth carrying pair 0
  int teeth_modelled = 0;
  double bore = 0, w = 0, theta_b = 0, rb = 0, form_roll = 0, tip_roll = 0;
  std::map<int, std::vector<int>> edges_of_tag;
  // The fillet stations of the loaded teeth (section 4) and where each sits in its triangle.
  std::vector<FilletStation> stations;
  struct StationPlace {
    int triangle = 0;
    double xi = 0, eta = 0;
    Vector2d tangent;
  };
  std::vector<StationPlace> places;
  // sigma_tt at every station per unit load at (tooth, roll): filled by every solve.
  mutable std::map<std::pair<int, double>, Eigen::VectorXd> station_stress;

  Vector2d point(const FlankPoint& p) const {
    const double psi = theta_b - p.roll / rb + 2 * pi * (first_loaded + p.tooth) / gear.teeth;
    return rb * Vector2d(std::sin(psi), std::cos(psi)) + p.roll * normal(p);
  }
  Vector2d normal(const FlankPoint& p) const {
    const double psi = theta_b - p.roll / rb + 2 * pi * (first_loaded + p.tooth) / gear.teeth;
    return {std::cos(psi), -std::sin(psi)};
  }
  int flank_tag(int loaded_tooth) const { return tooth_tag(first_loaded + loaded_tooth, flank_right); }

  EdgePoint locate(const FlankPoint& p) const {
    if (p.tooth < 0 || p.tooth >= options.loaded_teeth)
      throw std::invalid_argument("FeGearModel: loaded tooth " + std::to_string(p.tooth) + " outside 0..K-1");
    if (p.roll < form_roll - 1e-12 || p.roll > tip_roll + 1e-12)
      throw std::invalid_argument("FeGearModel: roll length outside the involute flank");
    const EdgePoint e = nearest_on_edges(mesh, edges_of_tag.at(flank_tag(p.tooth)), point(p));
    if (e.distance > 1e-3 * gear.module)
      throw std::invalid_argument("FeGearModel: flank point (tooth " + std::to_string(p.tooth) + ", roll " +
                                  std::to_string(p.roll) + " m) " + std::to_string(e.distance) +
                                  " m from the meshed flank");
    return e;
  }

  // The unit Hertzian pressure of half-width w at p (consistent nodal loads, 8 x 3 Gauss
  // points per edge), scaled to a unit force along -n exactly.
  Eigen::VectorXd unit_load(const FlankPoint& p) const {
    const Vector2d x0 = point(p), n0 = normal(p), t0(-n0.y(), n0.x());
    Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
    const double p0 = 2.0 / (pi * w * material.thickness);
    for (int e : edges_of_tag.at(flank_tag(p.tooth))) {
      const auto& nodes = mesh.edges[e];
      const double near = std::min({(mesh.nodes[nodes[0]] - x0).norm(), (mesh.nodes[nodes[1]] - x0).norm(),
                                    (mesh.nodes[nodes[2]] - x0).norm()});
      const double length = (mesh.nodes[nodes[1]] - mesh.nodes[nodes[0]]).norm();
      if (near > w + length) continue;
      constexpr int sub = 8;
      for (int k = 0; k < sub; ++k)
        for (const auto& g : fe::gauss_legendre_3()) {
          const double s = -1 + (2.0 * k + 1 + g.s) / sub, weight = g.weight / sub;
          const Vector2d x = edge_position(mesh, e, s), dx = edge_tangent(mesh, e, s);
          const double t = (x - x0).dot(t0);
          if (std::abs(t) >= w) continue;
          const double pressure = p0 * std::sqrt(1 - t * t / (w * w));
          const Vector2d n = Vector2d(dx.y(), -dx.x()).normalized();   // outward (domain on the left)
          const Vector2d traction = -pressure * n * dx.norm() * weight * material.thickness;
          const Eigen::Vector3d N = fe::edge_shape(s);
          for (int a = 0; a < 3; ++a) f.segment<2>(2 * nodes[a]) += N(a) * traction;
        }
    }
    Vector2d resultant(0, 0);
    for (int i = 0; i < mesh.node_count(); ++i) resultant += f.segment<2>(2 * i);
    return f / resultant.dot(-n0);
  }

  // Displacement of the point along its inward normal.
  double inward_displacement(const Eigen::Ref<const Eigen::VectorXd>& u, const FlankPoint& p,
                             const EdgePoint& e) const {
    const Eigen::Vector3d N = fe::edge_shape(e.s);
    const auto& nodes = mesh.edges[e.edge];
    Vector2d v(0, 0);
    for (int a = 0; a < 3; ++a) v += N(a) * u.segment<2>(2 * nodes[a]);
    return -normal(p).dot(v);
  }

  void build_stations();
  Eigen::VectorXd stress_at_stations(const Eigen::VectorXd& u) const;
  void set_up(const GearGeometry& g, const FeGearOptions& o);
  fe::MeshSpec mesh_spec();
  void build_mesh();
};

void FeGearModel::Impl::set_up(const GearGeometry& g, const FeGearOptions& o) {
  gear = g;
  options = o;
  w = o.load_width * g.module;
  rb = g.base_radius();
  const double alpha = g.pressure_angle_rad();
  theta_b = (pi / 2 + 2 * g.profile_shift * std::tan(alpha)) / g.teeth + involute(alpha);
}

void FeGearModel::Impl::build_mesh() {
  mesh = fe::mesh_with_gmsh(mesh_spec());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) edges_of_tag[mesh.edge_tags[e]].push_back(int(e));
  build_stations();
}

// Every node of the fillet edges of the loaded teeth (both sides), in order along each
// fillet from the root to the flank, placed in the triangle that holds its edge.
void FeGearModel::Impl::build_stations() {
  std::map<std::pair<int, int>, int> triangle_of_side;   // sorted corner pair -> triangle
  for (int t = 0; t < int(mesh.triangles.size()); ++t)
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.triangles[t][c], b = mesh.triangles[t][(c + 1) % 3];
      triangle_of_side[{std::min(a, b), std::max(a, b)}] = t;
    }
  static const double local[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int k = 0; k < options.loaded_teeth; ++k) {
    const int t = first_loaded + k;
    const double centre = 2 * pi * t / gear.teeth;
    const Vector2d axis(std::sin(centre), std::cos(centre));   // the tooth's centre line, outward
    for (int cls : {fillet_right, fillet_left}) {
      const auto it = edges_of_tag.find(tooth_tag(t, cls));
      if (it == edges_of_tag.end()) continue;
      for (int e : it->second) {
        const auto& en = mesh.edges[e];
        const int tri = triangle_of_side.at({std::min(en[0], en[1]), std::max(en[0], en[1])});
        for (int a : {0, 2, 1}) {   // end a, middle, end b: s = -1, 0, 1
          int i = 0;
          while (mesh.triangles[tri][i] != en[a]) ++i;
          const double s_edge = a == 0 ? -1.0 : a == 2 ? 0.0 : 1.0;
          const Vector2d x = mesh.nodes[en[a]], tangent = edge_tangent(mesh, e, s_edge).normalized();
          FilletStation st;
          st.tooth = k;
          st.loaded_side = cls == fillet_right;
          st.x = x;
          st.radius = x.norm();
          st.tangent_deg = std::acos(std::min(1.0, std::abs(tangent.dot(axis)))) * 180 / pi;
          stations.push_back(st);
          places.push_back({tri, local[i][0], local[i][1], tangent});
        }
      }
    }
  }
}

Eigen::VectorXd FeGearModel::Impl::stress_at_stations(const Eigen::VectorXd& u) const {
  Eigen::VectorXd out(long(stations.size()));
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const StationPlace& p = places[i];
    const Eigen::Vector4d sg = fe::element_stress(mesh, material, u, p.triangle, p.xi, p.eta);
    Eigen::Matrix2d S;
    S << sg(0), sg(2), sg(2), sg(1);
    out(long(i)) = p.tangent.dot(S * p.tangent);
  }
  return out;
}

// The geometry and the graded sizes of the gear's mesh (section 1), with the runs' tags.
fe::MeshSpec FeGearModel::Impl::mesh_spec() {
  const double m = gear.module, rf = gear.root_radius();
  ToothFormOptions fo;
  fo.root_radius_coefficient = options.root_radius_coefficient;
  fo.spacing = m / 60;
  const ToothForm form = tooth_form(gear, fo);
  form_roll = form.form_roll;
  tip_roll = std::sqrt(form.tip_radius * form.tip_radius - rb * rb);
  const bool whole = options.sector_teeth == 0;
  teeth_modelled = whole ? gear.teeth : options.sector_teeth;
  const int K = options.loaded_teeth;
  if (K < 1 || K > teeth_modelled) throw std::invalid_argument("FeGearModel: the sector must hold the loaded teeth");
  first_loaded = whole ? 1 : (teeth_modelled - K) / 2;
  bore = options.rim_radius > 0 ? options.rim_radius : std::max(rf - 3 * m, 0.5 * rf);
  if (!(bore < rf - m)) throw std::invalid_argument("FeGearModel: bore radius must be below rf - m");

  const FormPolyline line = whole ? gear_outline(form) : form_sector(form, 0, teeth_modelled);
  const std::vector<Run> runs = boundary_runs(line);
  fe::BoundaryLoop outer;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::vector<Vector2d> pts = runs[i].points;
    const Vector2d next = i + 1 < runs.size() ? runs[i + 1].points.front() : runs[0].points.front();
    if ((i + 1 < runs.size() || whole) && (next - pts.back()).norm() > 0) pts.push_back(next);
    outer.push_back(segment_of(pts, tooth_tag(runs[i].tooth, runs[i].cls)));
  }
  fe::MeshSpec spec;
  const FeMeshDensity& d = options.density;
  spec.size = d.body_size * d.scale * m;
  spec.max_nodes = options.max_nodes;
  if (whole) {
    spec.loops.push_back(outer);
    fe::BoundaryLoop hole = arcs(bore, 0, 2 * pi, bore_tag);
    spec.loops.push_back(hole);
  } else {
    const Vector2d end = line.points.back(), start = line.points.front();
    const double a_end = std::atan2(end.x(), end.y()), a_start = std::atan2(start.x(), start.y());
    outer.push_back(segment_of({end, bore * end.normalized()}, right_cut_tag));
    for (auto& s : arcs(bore, a_end, a_start, bore_tag)) outer.push_back(s);
    outer.push_back(segment_of({bore * start.normalized(), start}, left_cut_tag));
    spec.loops.push_back(outer);
  }
  // Refinements: the loaded flanks; the loaded teeth and their neighbours; the other teeth.
  fe::Refinement contact, near, far;
  contact.size_min = d.contact_size * d.scale * m;
  contact.dist_min = w;
  contact.dist_max = w + 2 * m;
  near.size_min = d.tooth_size * d.scale * m;
  near.dist_min = 0;
  near.dist_max = 2 * m;
  // On a tooth's boundary h stays below a quarter module whatever the scale: a P2 edge much
  // longer than the fillet's curvature radius (about rho_f* m) is too curved to map.
  far.size_min = std::min(d.far_tooth_size * d.scale, 0.25) * m;
  far.dist_min = far.size_min;   // points size_min apart: every boundary point within size_min of one
  far.dist_max = 2 * m;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const int t = runs[i].tooth, k = t - first_loaded;
    const std::pair<int, int> seg{0, int(i)};
    if (k >= 0 && k < K && runs[i].cls == flank_right) contact.segments.push_back(seg);
    if (k >= -1 && k <= K) {
      near.segments.push_back(seg);
      continue;
    }
    // The other teeth by points about far.size_min apart along their boundary: Gmsh's
    // distance to hundreds of curves (200 samples each) is slow to evaluate, to a point
    // cloud fast (a whole gear of 62 teeth: 4 s less meshing).
    const std::vector<Vector2d>& pts = runs[i].points;
    double since = 1e300;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (j > 0) since += (pts[j] - pts[j - 1]).norm();
      if (since >= far.size_min) far.points.push_back(pts[j]), since = 0;
    }
  }
  spec.refinements = {contact, near};
  if (!far.points.empty()) spec.refinements.push_back(far);
  return spec;
}

double fe_gear_node_estimate(const GearGeometry& gear, const FeGearOptions& options) {
  FeGearModel::Impl s;
  s.set_up(gear, options);
  return fe::estimate_node_count(s.mesh_spec());
}

FeGearModel::FeGearModel(const GearGeometry& gear, double youngs_modulus, double poisson_ratio,
                         const FeGearOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.set_up(gear, options);
  s.E = youngs_modulus;
  s.nu = poisson_ratio;
  s.material.youngs_modulus = youngs_modulus;
  s.material.poisson_ratio = poisson_ratio;
  s.material.thickness = gear.face_width;
  s.build_mesh();
  fe::Constraints fix;
  fe::fix_tagged(s.mesh, bore_tag, 0, 0.0, fix);
  fe::fix_tagged(s.mesh, bore_tag, 1, 0.0, fix);
  if (options.sector_teeth > 0 && options.cut_faces == CutFaces::fixed)
    for (int tag : {left_cut_tag, right_cut_tag})
      for (int c : {0, 1}) fe::fix_tagged(s.mesh, tag, c, 0.0, fix);
  s.solver = std::make_unique<fe::ElasticSolver>(fe::assemble_stiffness(s.mesh, s.material, 4), fix.dofs());
}

FeGearModel::~FeGearModel() = default;
FeGearModel::FeGearModel(FeGearModel&&) noexcept = default;
FeGearModel& FeGearModel::operator=(FeGearModel&&) noexcept = default;

std::vector<Eigen::MatrixXd> FeGearModel::compliance(const std::vector<std::vector<FlankPoint>>& sets) const {
  const Impl& s = *impl_;
  // Distinct points, each loaded once.
  std::map<std::pair<int, double>, int> index;
  std::vector<FlankPoint> points;
  std::vector<EdgePoint> located;
  for (const auto& set : sets)
    for (const FlankPoint& p : set)
      if (index.emplace(std::make_pair(p.tooth, p.roll), int(points.size())).second) {
        points.push_back(p);
        located.push_back(s.locate(p));
      }
  // Readings wanted: (load point, read point) pairs of every set.
  std::map<std::pair<int, int>, double> reading;
  for (const auto& set : sets)
    for (const FlankPoint& a : set)
      for (const FlankPoint& b : set)
        reading[{index.at({a.tooth, a.roll}), index.at({b.tooth, b.roll})}] = 0.0;
  constexpr int block = 64;
  for (int first = 0; first < int(points.size()); first += block) {
    const int cols = std::min(block, int(points.size()) - first);
    Eigen::MatrixXd f(s.mesh.dof_count(), cols);
    for (int j = 0; j < cols; ++j) f.col(j) = s.unit_load(points[first + j]);
    const Eigen::MatrixXd u = s.solver->solve(f);
    for (int j = 0; j < cols; ++j) {
      const FlankPoint& p = points[first + j];
      s.station_stress.emplace(std::make_pair(p.tooth, p.roll), s.stress_at_stations(u.col(j)));
    }
    for (auto& [key, value] : reading)
      if (key.first >= first && key.first < first + cols)
        value = s.inward_displacement(u.col(key.first - first), points[key.second], located[key.second]);
  }
  std::vector<Eigen::MatrixXd> out;
  for (const auto& set : sets) {
    const int n = int(set.size());
    Eigen::MatrixXd C(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        C(i, j) = reading.at({index.at({set[i].tooth, set[i].roll}), index.at({set[j].tooth, set[j].roll})});
    out.push_back(C);
  }
  return out;
}

Eigen::MatrixXd FeGearModel::raw_compliance(const std::vector<FlankPoint>& points) const {
  return compliance(std::vector<std::vector<FlankPoint>>{points}).front();
}

Eigen::MatrixXd FeGearModel::compliance(const std::vector<FlankPoint>& points) const {
  const Eigen::MatrixXd C = raw_compliance(points);
  return 0.5 * (C + C.transpose());
}

Eigen::MatrixXd FeGearModel::fillet_stress(const std::vector<FlankPoint>& loads) const {
  const Impl& s = *impl_;
  std::vector<FlankPoint> missing;
  for (const FlankPoint& p : loads)
    if (!s.station_stress.count({p.tooth, p.roll})) missing.push_back(p);
  if (!missing.empty()) raw_compliance(missing);   // solves them, filling the stations' stresses
  Eigen::MatrixXd out(long(s.stations.size()), long(loads.size()));
  for (std::size_t j = 0; j < loads.size(); ++j) out.col(long(j)) = s.station_stress.at({loads[j].tooth, loads[j].roll});
  return out;
}

const std::vector<FilletStation>& FeGearModel::fillet_stations() const { return impl_->stations; }

double FeGearModel::width_correction(double half_width) const {
  const Impl& s = *impl_;
  return 2 * (1 - s.nu * s.nu) / (pi * s.E * s.gear.face_width) * std::log(s.w / half_width);
}

double FeGearModel::body_torsion_compliance() const {
  const Impl& s = *impl_;
  if (s.options.sector_teeth != 0) throw std::logic_error("body_torsion_compliance: whole-gear models only");
  // A unit load along the line of action at the pitch point of every tooth's right flank.
  const double xi_c = s.rb * std::tan(s.gear.pressure_angle_rad());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(s.mesh.dof_count());
  double torque = 0;
  for (int t = 0; t < s.gear.teeth; ++t) {
    // Tooth t of the model is loaded tooth t - first_loaded.
    const FlankPoint p{t - s.first_loaded, xi_c};
    const Vector2d x0 = s.point(p), n0 = s.normal(p);
    const std::vector<int>& edges = s.edges_of_tag.at(tooth_tag(t, flank_right));
    const EdgePoint e = nearest_on_edges(s.mesh, edges, x0);
    const Eigen::Vector3d N = fe::edge_shape(e.s);
    for (int a = 0; a < 3; ++a) f.segment<2>(2 * s.mesh.edges[e.edge][a]) += -N(a) * n0;
    torque += x0.x() * (-n0.y()) - x0.y() * (-n0.x());
  }
  const Eigen::VectorXd u = s.solver->solve(f);
  double rotation = 0;
  int count = 0;
  for (int t = 0; t < s.gear.teeth; ++t)
    for (int cls : {root_left, root_right}) {
      const auto it = s.edges_of_tag.find(tooth_tag(t, cls));
      if (it == s.edges_of_tag.end()) continue;
      for (int e : it->second)
        for (int a = 0; a < 3; ++a) {
          const int n = s.mesh.edges[e][a];
          const Vector2d x = s.mesh.nodes[n];
          rotation += (x.x() * u(2 * n + 1) - x.y() * u(2 * n)) / x.squaredNorm();
          ++count;
        }
    }
  return std::abs(rotation / count / torque);
}

Eigen::Vector2d FeGearModel::flank_point(const FlankPoint& p) const { return impl_->point(p); }
Eigen::Vector2d FeGearModel::flank_normal(const FlankPoint& p) const { return impl_->normal(p); }
double FeGearModel::load_half_width() const { return impl_->w; }
double FeGearModel::bore_radius() const { return impl_->bore; }
double FeGearModel::form_roll() const { return impl_->form_roll; }
double FeGearModel::tip_roll() const { return impl_->tip_roll; }
const fe::P2Mesh& FeGearModel::mesh() const { return impl_->mesh; }
const fe::FactorStats& FeGearModel::factor_stats() const { return impl_->solver->stats(); }
const GearGeometry& FeGearModel::gear() const { return impl_->gear; }
const FeGearOptions& FeGearModel::options() const { return impl_->options; }

// ---------------------------------------------------------------------------
namespace {

bool same_density(const FeMeshDensity& a, const FeMeshDensity& b) {
  return a.contact_size == b.contact_size && a.tooth_size == b.tooth_size && a.far_tooth_size == b.far_tooth_size &&
         a.body_size == b.body_size && a.scale == b.scale;
}
bool same_gear(const GearGeometry& a, const GearGeometry& b) {
  return a.module == b.module && a.teeth == b.teeth && a.pressure_angle_deg == b.pressure_angle_deg &&
         a.addendum == b.addendum && a.dedendum == b.dedendum && a.face_width == b.face_width &&
         a.profile_shift == b.profile_shift;
}
bool same_options(const FeGearOptions& a, const FeGearOptions& b) {
  return a.sector_teeth == b.sector_teeth && a.loaded_teeth == b.loaded_teeth && a.rim_radius == b.rim_radius &&
         a.cut_faces == b.cut_faces && a.root_radius_coefficient == b.root_radius_coefficient &&
         a.load_width == b.load_width && same_density(a.density, b.density) && a.max_nodes == b.max_nodes;
}

}  // namespace

namespace {

// The contact points of the pairs at mesh phase phi on gear 1 or 2: pair k at
// s = (phi + k) pb from A while s <= AE (as mesh_phases), roll lengths T1A + s on gear 1
// and T1T2 - T1A - s on gear 2.
std::vector<FlankPoint> pair_points(const PathOfContact& path, double phi, int gear) {
  std::vector<FlankPoint> out;
  for (int k = 0;; ++k) {
    const double s = (phi + k) * path.base_pitch;
    if (s > path.AE * (1 + 1e-12)) break;
    const double xi1 = path.T1A + std::min(s, path.AE);
    out.push_back({k, gear == 1 ? xi1 : path.T1T2 - xi1});
  }
  return out;
}

// Knots in the mesh phase for interpolating the compliances: j / N, j = 0..N, and the
// phase at which each pair k reaches E (phi = eps - k, when below 1). Entry (k, l) of the
// compliance is a smooth function of the phase on [0, min(phi_max k, phi_max l)],
// interpolated piecewise cubically through its knots.
struct PhaseGrid {
  std::vector<double> knots;
  PhaseGrid(const PathOfContact& path, int n) {
    for (int j = 0; j <= n; ++j) knots.push_back(double(j) / n);
    const double eps = path.AE / path.base_pitch;
    for (int k = 0; eps - k > 0; ++k)
      if (eps - k < 1) knots.push_back(eps - k);
    std::sort(knots.begin(), knots.end());
    knots.erase(std::unique(knots.begin(), knots.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                knots.end());
  }
  Eigen::MatrixXd interpolate(const std::vector<Eigen::MatrixXd>& at_knots, double phi, int n) const {
    Eigen::MatrixXd C(n, n);
    for (int k = 0; k < n; ++k)
      for (int l = k; l < n; ++l) {
        std::vector<double> x, y;
        for (std::size_t j = 0; j < knots.size(); ++j)
          if (at_knots[j].rows() > std::max(k, l)) x.push_back(knots[j]), y.push_back(at_knots[j](k, l));
        C(k, l) = C(l, k) = spline_value(x, y, std::clamp(phi, x.front(), x.back()));
      }
    return C;
  }
  // Piecewise cubic Lagrange interpolation: the four knots nearest to `at` (one-sided at
  // the ends), error O(h^4) up to the ends (a natural spline's free ends give O(h^2)).
  static double spline_value(const std::vector<double>& x, const std::vector<double>& y, double at) {
    const int n = int(x.size());
    if (n == 1) return y[0];
    const int order = std::min(n, 4);
    const int i = int(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;   // at in [x_i, x_i+1)
    const int first = std::clamp(i - (order / 2 - 1), 0, n - order);
    double v = 0;
    for (int a = first; a < first + order; ++a) {
      double basis = 1;
      for (int b = first; b < first + order; ++b)
        if (b != a) basis *= (at - x[b]) / (x[a] - x[b]);
      v += basis * y[a];
    }
    return v;
  }
};

}  // namespace

void FePairModel::compliances(const std::vector<std::vector<FlankPoint>>& sets1,
                              const std::vector<std::vector<FlankPoint>>& sets2, bool shared,
                              std::vector<Eigen::MatrixXd>& c1, std::vector<Eigen::MatrixXd>& c2) const {
  if (shared) {
    std::vector<std::vector<FlankPoint>> all = sets1;
    all.insert(all.end(), sets2.begin(), sets2.end());
    const std::vector<Eigen::MatrixXd> c = gear1_->compliance(all);
    c1.assign(c.begin(), c.begin() + long(sets1.size()));
    c2.assign(c.begin() + long(sets1.size()), c.end());
  } else {
    c1 = gear1_->compliance(sets1);
    c2 = gear2_->compliance(sets2);
  }
}

FePairModel::FePairModel(const PairSteModel& pair, int samples, const FePairOptions& options)
    : pair_(pair), options_(options), path_(pair.path()) {
  const int K = int(std::ceil(path_.contact_ratio - 1e-12));
  options_.gear1.loaded_teeth = std::max(options_.gear1.loaded_teeth, K);
  options_.gear2.loaded_teeth = std::max(options_.gear2.loaded_teeth, K);
  gear1_ = std::make_unique<FeGearModel>(pair.gear1, pair.youngs_modulus1, options.poisson_ratio1, options_.gear1);
  const bool shared = same_gear(pair.gear1, pair.gear2) && pair.youngs_modulus1 == pair.youngs_modulus2 &&
                      options.poisson_ratio1 == options.poisson_ratio2 && same_options(options_.gear1, options_.gear2);
  if (!shared)
    gear2_ = std::make_unique<FeGearModel>(pair.gear2, pair.youngs_modulus2, options.poisson_ratio2, options_.gear2);
  estar_inverse_ = (1 - options.poisson_ratio1 * options.poisson_ratio1) / pair.youngs_modulus1 +
                   (1 - options.poisson_ratio2 * options.poisson_ratio2) / pair.youngs_modulus2;
  length_ = std::min(pair.gear1.face_width, pair.gear2.face_width);

  if (samples == 0) return;   // the models only (phases_at)
  const std::vector<MeshPhase> kinematics = mesh_phases(pair, samples, [](double, double, bool) { return 1.0; });
  std::vector<std::vector<FlankPoint>> sets1, sets2;
  for (const MeshPhase& q : kinematics) {
    sets1.push_back(pair_points(path_, q.phase, 1));
    sets2.push_back(pair_points(path_, q.phase, 2));
    if (sets1.back().size() != q.pairs.size()) throw std::logic_error("FePairModel: pairs differ from mesh_phases");
  }
  std::vector<Eigen::MatrixXd> c1, c2;
  if (options.knots_per_base_pitch > 0) {
    const PhaseGrid grid(path_, options.knots_per_base_pitch);
    std::vector<std::vector<FlankPoint>> knots1, knots2;
    for (double phi : grid.knots) {
      knots1.push_back(pair_points(path_, phi, 1));
      knots2.push_back(pair_points(path_, phi, 2));
    }
    std::vector<Eigen::MatrixXd> k1, k2;
    compliances(knots1, knots2, shared, k1, k2);
    for (const MeshPhase& q : kinematics) {
      c1.push_back(grid.interpolate(k1, q.phase, int(q.pairs.size())));
      c2.push_back(grid.interpolate(k2, q.phase, int(q.pairs.size())));
    }
  } else {
    compliances(sets1, sets2, shared, c1, c2);
  }
  for (std::size_t q = 0; q < kinematics.size(); ++q)
    phases_.push_back(make_phase(kinematics[q].phase, kinematics[q].pairs, c1[q], c2[q], sets1[q], sets2[q]));
}

FePhase FePairModel::make_phase(double phase, const std::vector<PairContact>& pairs, const Eigen::MatrixXd& c1,
                                const Eigen::MatrixXd& c2, const std::vector<FlankPoint>& points1,
                                const std::vector<FlankPoint>& points2) const {
  FePhase p;
  p.phase = phase;
  p.pairs = pairs;
  const Eigen::MatrixXd C = c1 + c2;
  p.compliance = 0.5 * (C + C.transpose());
  const int n = int(p.pairs.size());
  p.local.resize(n);
  p.local_log.resize(n);
  p.contact_radius.resize(n);
  for (int k = 0; k < n; ++k) {
    const double xi1 = points1[k].roll, xi2 = points2[k].roll;
    p.contact_radius(k) = xi1 * xi2 / (xi1 + xi2);
    // width_correction(a) = kappa ln(w / a) = kappa ln w - kappa ln a: kappa = correction at a = w / e.
    const double k1 = gear1().width_correction(gear1().load_half_width() / std::exp(1.0));
    const double k2 = gear2().width_correction(gear2().load_half_width() / std::exp(1.0));
    p.local(k) = k1 + k2;
    p.local_log(k) = k1 * std::log(gear1().load_half_width()) + k2 * std::log(gear2().load_half_width());
  }
  return p;
}

std::vector<FePhase> FePairModel::phases_at(const std::vector<std::vector<PairContact>>& sets) const {
  std::vector<std::vector<FlankPoint>> sets1, sets2;
  for (const auto& set : sets) {
    sets1.emplace_back();
    sets2.emplace_back();
    for (std::size_t k = 0; k < set.size(); ++k) {   // as pair_points: roll T1A + s on gear 1
      const double xi1 = path_.T1A + std::min(set[k].s, path_.AE);
      sets1.back().push_back({int(k), xi1});
      sets2.back().push_back({int(k), path_.T1T2 - xi1});
    }
  }
  std::vector<Eigen::MatrixXd> c1, c2;
  compliances(sets1, sets2, !gear2_, c1, c2);
  std::vector<FePhase> out;
  for (std::size_t q = 0; q < sets.size(); ++q) out.push_back(make_phase(0.0, sets[q], c1[q], c2[q], sets1[q], sets2[q]));
  return out;
}

double FePairModel::force(double torque) const { return torque / pair_.gear1.base_radius(); }

double FePairModel::contact_compliance(int k, const FePhase& p, double F) const {
  const double a = std::sqrt(4 * F * p.contact_radius(k) * estar_inverse_ / (pi * length_));
  return p.local_log(k) - p.local(k) * std::log(a);
}

FeStePoint FePairModel::solve_phase(const FePhase& p, double F) const {
  const int n = int(p.pairs.size());
  Eigen::VectorXd g(n);
  for (int k = 0; k < n; ++k) g(k) = p.pairs[k].separation;
  Eigen::VectorXd f = Eigen::VectorXd::Constant(n, F / n);
  CoupledShare share;
  for (int pass = 0;; ++pass) {
    Eigen::MatrixXd C = p.compliance;
    for (int k = 0; k < n; ++k) C(k, k) += contact_compliance(k, p, std::max(f(k), 1e-6 * F));
    share = share_load_coupled(C, g, F);
    const double change = (share.force - f).cwiseAbs().maxCoeff();
    f = share.force;
    if (change <= 1e-12 * F) break;
    if (pass == 100) throw std::runtime_error("FePairModel: the contact compliance did not converge");
  }
  FeStePoint out;
  out.phase = p.phase;
  out.force = f;
  out.loaded = share.loaded;
  out.ste = share.approach;
  out.stiffness = F / share.approach;
  return out;
}

std::vector<FeStePoint> FePairModel::ste(double torque) const {
  std::vector<FeStePoint> out;
  for (const FePhase& p : phases_) out.push_back(solve_phase(p, force(torque)));
  return out;
}

std::vector<PairStePoint> FePairModel::pair_ste(double torque, bool reliefs) const {
  std::vector<PairStePoint> out;
  for (const FePhase& phase : phases_) {
    FePhase p = phase;
    if (!reliefs)
      for (PairContact& c : p.pairs) c.separation = 0.0;   // the separations are the reliefs only
    const FeStePoint q = solve_phase(p, force(torque));
    PairStePoint o;
    o.mesh.phase = p.phase;
    o.mesh.pairs = p.pairs;
    for (std::size_t k = 0; k < p.pairs.size(); ++k) o.mesh.pairs[k].force = q.force(Eigen::Index(k));
    o.loaded = q.loaded;
    o.approach = o.ste = q.ste;
    o.hertz = 0;
    out.push_back(o);
  }
  return out;
}

void FePairModel::set_reliefs(const TipRelief& relief1, const TipRelief& relief2) {
  pair_.relief1 = relief1;
  pair_.relief2 = relief2;
  const double rb1 = pair_.gear1.base_radius();
  for (FePhase& p : phases_)
    for (PairContact& c : p.pairs) {   // as mesh_phases computes it
      const double T1P = std::sqrt(std::max(0.0, c.r1 * c.r1 - rb1 * rb1));
      c.separation = tip_relief_at(relief1, T1P) + tip_relief_at(relief2, path_.T1T2 - T1P);
    }
}

double FePairModel::single_pair_stiffness(double s, double F) const {
  const ContactRadii r = contact_radii(pair_.gear1, pair_.gear2, path_, s);
  PairContact c;
  c.s = s;
  c.r1 = r.r1;
  c.r2 = r.r2;
  const double xi1 = std::sqrt(r.r1 * r.r1 - std::pow(pair_.gear1.base_radius(), 2));
  const double xi2 = std::sqrt(r.r2 * r.r2 - std::pow(pair_.gear2.base_radius(), 2));
  // Pair 0 on the loaded tooth whose range holds s (labels are free, section 2).
  const int k = std::min(int(s / path_.base_pitch), gear1().options().loaded_teeth - 1);
  FePhase p;
  p.phase = 0;
  p.pairs = {c};
  const double C = gear1().compliance({FlankPoint{k, xi1}})(0, 0) + gear2().compliance({FlankPoint{k, xi2}})(0, 0);
  p.compliance = Eigen::MatrixXd::Constant(1, 1, C);
  const double k1 = gear1().width_correction(gear1().load_half_width() / std::exp(1.0));
  const double k2 = gear2().width_correction(gear2().load_half_width() / std::exp(1.0));
  p.local = Eigen::VectorXd::Constant(1, k1 + k2);
  p.local_log = Eigen::VectorXd::Constant(1, k1 * std::log(gear1().load_half_width()) +
                                                 k2 * std::log(gear2().load_half_width()));
  p.contact_radius = Eigen::VectorXd::Constant(1, xi1 * xi2 / (xi1 + xi2));
  return solve_phase(p, F).stiffness;
}

std::vector<FeRootStressPoint> FePairModel::root_stress(double torque, int gear) const {
  if (gear != 1 && gear != 2) throw std::invalid_argument("FePairModel::root_stress: gear 1 or 2");
  const FeGearModel& g = gear == 1 ? gear1() : gear2();
  const std::vector<FilletStation>& st = g.fillet_stations();
  std::vector<FeRootStressPoint> out;
  for (const FePhase& p : phases_) {
    const FeStePoint q = solve_phase(p, force(torque));
    const std::vector<FlankPoint> points = pair_points(path_, p.phase, gear);
    const Eigen::VectorXd sigma = g.fillet_stress(points) * q.force;
    for (std::size_t k = 0; k < points.size(); ++k) {
      FeRootStressPoint r;
      r.s = (p.phase + double(k)) * path_.base_pitch;
      r.stress = -1e300;
      for (std::size_t i = 0; i < st.size(); ++i) {
        if (st[i].tooth != int(k)) continue;
        r.fillet.emplace_back(int(i), sigma(long(i)));
        if (st[i].loaded_side && sigma(long(i)) > r.stress) r.stress = sigma(long(i)), r.station = int(i);
      }
      out.push_back(r);
    }
  }
  std::sort(out.begin(), out.end(), [](const FeRootStressPoint& a, const FeRootStressPoint& b) { return a.s < b.s; });
  return out;
}

std::vector<FeContactPressure> FePairModel::contact_pressure(double torque) const {
  std::vector<FeContactPressure> out;
  for (const FePhase& p : phases_) {
    const FeStePoint q = solve_phase(p, force(torque));
    for (long k = 0; k < q.force.size(); ++k) {
      if (!(q.force(k) > 0.0)) continue;
      FeContactPressure c;
      c.s = p.pairs[std::size_t(k)].s;
      c.force = q.force(k);
      c.half_width = std::sqrt(4 * c.force * p.contact_radius(k) * estar_inverse_ / (pi * length_));
      c.peak_pressure = 2 * c.force / (pi * c.half_width * length_);
      out.push_back(c);
    }
  }
  std::sort(out.begin(), out.end(), [](const FeContactPressure& a, const FeContactPressure& b) { return a.s < b.s; });
  return out;
}

double fe_mean_stiffness(const std::vector<FeStePoint>& points, double force) {
  double sum = 0;
  for (const auto& p : points) sum += force / p.ste;
  return sum / double(points.size());
}

}  // namespace gearhb
