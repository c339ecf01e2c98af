#include "gearhb/gears/pair/ste_continuous.hpp"

#include <algorithm>
#include <memory>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/gears/geometry/gear_geometry.hpp"
#include "gearhb/gears/tooth/hertz.hpp"
#include "gearhb/gears/pair/load_sharing.hpp"
#include "gearhb/gears/tooth/tooth_fe.hpp"

namespace gearhb {

namespace {

// Hermite shape functions of an element of length L at xi, and their x-derivatives.
Eigen::Vector4d shape(double xi, double L) {
  const double x2 = xi * xi, x3 = x2 * xi;
  return {1 - 3 * x2 + 2 * x3, L * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, L * (x3 - x2)};
}
Eigen::Vector4d shape_dx(double xi, double L) {
  const double x2 = xi * xi;
  return Eigen::Vector4d(-6 * xi + 6 * x2, L * (1 - 4 * xi + 3 * x2), 6 * xi - 6 * x2, L * (3 * x2 - 2 * xi)) / L;
}

// Element holding height a (the last one whose left node is <= a) and its local xi.
std::pair<int, double> locate(const ToothBeam& t, double a) {
  const int ne = int(t.x.size()) - 1;
  int e = int(std::upper_bound(t.x.begin(), t.x.end(), a) - t.x.begin()) - 1;
  e = std::clamp(e, 0, ne - 1);
  return {e, (a - t.x[e]) / (t.x[e + 1] - t.x[e])};
}

}  // namespace

ToothCompliance::ToothCompliance(const ToothBeam& tooth) : tooth_(tooth) {
  if (tooth.x.size() < 2) throw std::invalid_argument("tooth_flexibility: the beam needs an element");
  BeamModel m;
  m.add_beam(tooth.x, tooth.EI);
  const Eigen::MatrixXd K = m.stiffness();
  const int n = int(K.rows()) - 2;   // root node clamped: its w and theta removed
  ldlt_.compute(K.bottomRightCorner(n, n));
  if (ldlt_.info() != Eigen::Success) throw std::runtime_error("tooth_flexibility: the cantilever is singular");
}

Eigen::Matrix2d ToothCompliance::at(double a) const {
  const ToothBeam& tooth = tooth_;
  if (!(a > 0.0) || a > tooth.x.back() * (1 + 1e-12))
    throw std::invalid_argument("tooth_flexibility: load height " + std::to_string(a) +
                                " m is not on the tooth (0, " + std::to_string(tooth.x.back()) + "]");
  const auto [e, xi] = locate(tooth, a);
  const double L = tooth.x[e + 1] - tooth.x[e];
  const Eigen::Vector4d N = shape(xi, L), dN = shape_dx(xi, L);
  // Consistent nodal loads of a unit force (N) and a unit moment (N') on element e,
  // DOFs 2e..2e+3 of the beam, 2 less in the clamped system.
  const int n = int(ldlt_.rows());
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(n, 2);
  for (int k = 0; k < 4; ++k) {
    const int d = 2 * e + k - 2;
    if (d < 0) continue;
    f(d, 0) = N[k];
    f(d, 1) = dN[k];
  }
  const Eigen::MatrixXd q = ldlt_.solve(f);
  Eigen::Matrix<double, 4, 2> qe = Eigen::Matrix<double, 4, 2>::Zero();
  for (int k = 0; k < 4; ++k) {
    const int d = 2 * e + k - 2;
    if (d >= 0) qe.row(k) = q.row(d);
  }
  Eigen::Matrix2d G;
  G << N.dot(qe.col(0)), N.dot(qe.col(1)), dN.dot(qe.col(0)), dN.dot(qe.col(1));
  return G;
}

Eigen::Matrix2d tooth_flexibility(const ToothBeam& tooth, double a) { return ToothCompliance(tooth).at(a); }

double fused_pair_stiffness(const ToothBeam& tooth, double a1, double a2) {
  return fused_pair_stiffness(tooth, a1, tooth, a2);
}

double fused_pair_stiffness(const ToothBeam& driving, double a1, const ToothBeam& driven, double a2) {
  return fused_pair_stiffness(tooth_flexibility(driving, a1), tooth_flexibility(driven, a2));
}

double fused_pair_stiffness(const Eigen::Matrix2d& G1, const Eigen::Matrix2d& G2) {
  const Eigen::Matrix2d D = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  return (G1 + D * G2 * D).inverse()(0, 0);
}

double cantilever_pair_stiffness(const ToothBeam& driving, double a1, const ToothBeam& driven, double a2) {
  return cantilever_pair_stiffness(tooth_flexibility(driving, a1), tooth_flexibility(driven, a2));
}

double cantilever_pair_stiffness(const Eigen::Matrix2d& G1, const Eigen::Matrix2d& G2) {
  return 1.0 / (G1(0, 0) + G2(0, 0));
}

double single_pair_elastic(const SteModel& m, const ToothBeam& tooth, double s, double F) {
  const ContactRadii r = contact_radii(m.gear, m.gear, s);
  const double rf = m.gear.root_radius();
  return F * (tooth_flexibility(tooth, r.r1 - rf)(0, 0) + tooth_flexibility(tooth, r.r2 - rf)(0, 0));
}

double single_pair_ste(const SteModel& m, const ToothBeam& tooth, double s, double F) {
  return single_pair_elastic(m, tooth, s, F) +
         double(int(m.hertz)) * palmgren_line_contact_approach(F, m.gear.face_width);
}

namespace {

// ch. 7's model as the identical-gear pair.
PairSteModel pair_of(const SteModel& m) {
  PairSteModel p;
  p.gear1 = p.gear2 = m.gear;
  p.youngs_modulus1 = p.youngs_modulus2 = m.youngs_modulus;
  p.tooth_elements = m.elements();
  p.thickness_at = m.thickness_at;
  p.hertz = m.hertz;
  p.pair_hertz = m.two_pair_hertz;
  p.pair_stiffness = PairStiffness::fused;
  p.tooth_force = m.tooth_force;
  return p;
}

}  // namespace

std::vector<StePoint> ste_continuous(const SteModel& m, double torque, int samples) {
  if (samples < 4 || samples > 1 << 16)
    throw std::invalid_argument("ste_continuous: samples per mesh cycle must be in [4, 65536]");
  const ToothBeam tooth = tooth_beam(m);
  const PairSteModel p = pair_of(m);
  const double rf = m.gear.root_radius();
  std::vector<StePoint> out;
  for (const PairStePoint& q : pair_ste(p, mesh_phases(p, tooth, tooth, samples), torque)) {
    StePoint o;
    o.phase = q.mesh.phase;
    o.pairs = int(q.mesh.pairs.size());
    const PairContact& A = q.mesh.pairs[0];
    o.a1A = A.r1 - rf;
    o.a2A = A.r2 - rf;
    o.force_A = A.force;
    if (o.pairs > 1) {
      const PairContact& B = q.mesh.pairs[1];
      o.a1B = B.r1 - rf;
      o.a2B = B.r2 - rf;
      o.force_B = B.force;
    }
    o.elastic = q.approach;
    o.hertz = q.hertz;
    o.ste = q.ste;
    out.push_back(o);
  }
  return out;
}

std::vector<double> ste_values(const std::vector<MeshPosition>& cycle) {
  std::vector<double> v;
  for (const auto& p : cycle) v.push_back(p.ste);
  return v;
}
std::vector<double> ste_values(const std::vector<StePoint>& cycle) {
  std::vector<double> v;
  for (const auto& p : cycle) v.push_back(p.ste);
  return v;
}

double mean_stiffness(const std::vector<double>& ste, double F) {
  double sum = 0.0;
  for (double e : ste) sum += F / e;
  return sum / double(ste.size());
}

}  // namespace gearhb

namespace gearhb {

PathOfContact PairSteModel::path() const { return path_of_contact(gear1, gear2, centre_distance); }

int PairSteModel::elements() const {
  if (tooth_elements > 0) return tooth_elements;
  // floor(8 eps_alpha): ch. 7's rule for its 8 positions per base pitch (14 for the thesis gear).
  return int(std::floor(8 * path().contact_ratio + 1e-9));
}

double PairSteModel::force(double torque) const {
  return tooth_force == ToothForce::over_pitch_radius ? torque / gear1.pitch_radius() : torque / gear1.base_radius();
}

double PairSteModel::contact_length() const { return std::min(gear1.face_width, gear2.face_width); }

namespace {

// A contact point from the radii on both gears; separation from both reliefs.
PairContact contact_point(const PairSteModel& m, const PathOfContact& path, double r1, double r2) {
  const double rb1 = m.gear1.base_radius();
  PairContact c;
  c.r1 = r1;
  c.r2 = r2;
  const double T1P = std::sqrt(std::max(0.0, r1 * r1 - rb1 * rb1));
  c.s = T1P - path.T1A;
  c.separation = tip_relief_at(m.relief1, T1P) + tip_relief_at(m.relief2, path.T1T2 - T1P);
  return c;
}

// The beams' pair stiffness of the model's reading (each cantilever factorised once).
PairStiffnessFn beam_pair_stiffness(const PairSteModel& m, const ToothBeam& t1, const ToothBeam& t2) {
  const auto c1 = std::make_shared<const ToothCompliance>(t1), c2 = std::make_shared<const ToothCompliance>(t2);
  const double rf1 = m.gear1.root_radius(), rf2 = m.gear2.root_radius();
  const PairStiffness reading = m.pair_stiffness;
  return [c1, c2, rf1, rf2, reading](double r1, double r2, bool sharing) {
    const Eigen::Matrix2d G1 = c1->at(r1 - rf1), G2 = c2->at(r2 - rf2);
    if (sharing && reading == PairStiffness::fused) return fused_pair_stiffness(G1, G2);
    return cantilever_pair_stiffness(G1, G2);
  };
}

}  // namespace

std::vector<MeshPhase> mesh_phases(const PairSteModel& m, int samples, const PairStiffnessFn& stiffness) {
  const int ne = m.elements();
  return mesh_phases(m, tooth_beam(m.gear1, m.youngs_modulus1, ne, m.thickness_at),
                     tooth_beam(m.gear2, m.youngs_modulus2, ne, m.thickness_at), samples, stiffness);
}

std::vector<MeshPhase> mesh_phases(const PairSteModel& m, const ToothBeam& t1, const ToothBeam& t2, int samples,
                                   const PairStiffnessFn& stiffness) {
  const PathOfContact path = m.path();
  const double rf1 = m.gear1.root_radius(), rf2 = m.gear2.root_radius();
  auto contact = [&](double r1, double r2) { return contact_point(m, path, r1, r2); };
  std::vector<MeshPhase> out;
  const int P = m.positions_per_base_pitch;
  if (P > 0) {
    const PairStiffnessFn k = stiffness ? stiffness : beam_pair_stiffness(m, t1, t2);
    // ch. 7's node reading (ste.hpp mesh_positions).
    if (m.gear1.teeth != m.gear2.teeth || m.gear1.profile_shift != m.gear2.profile_shift || m.relief1.amount > 0 ||
        m.relief2.amount > 0 || t1.x != t2.x || t1.EI != t2.EI)
      throw std::invalid_argument("mesh_phases: the node reading needs identical gears without relief");
    if (P < 2 || P > max_positions_per_base_pitch)
      throw std::invalid_argument("mesh_phases: positions per base pitch outside [2, 128]");
    const int ne = int(t1.x.size()) - 1;
    if (ne < P || ne >= 2 * P)
      throw std::invalid_argument("mesh_phases: the node reading needs P <= n_e < 2 P");
    for (int j = 0; j < P; ++j) {
      MeshPhase ph;
      ph.phase = double(j) / P;
      for (int k1 = j + 1; k1 <= ne; k1 += P) ph.pairs.push_back(contact(rf1 + t1.x[k1], rf2 + t2.x[ne + 1 - k1]));
      const bool sharing = ph.pairs.size() > 1;
      for (PairContact& c : ph.pairs) c.stiffness = k(c.r1, c.r2, sharing);
      out.push_back(ph);
    }
    return out;
  }
  if (samples < 4 || samples > 1 << 16)
    throw std::invalid_argument("mesh_phases: samples per mesh cycle must be in [4, 65536]");
  std::vector<double> phases(std::size_t(samples), 0.0);
  for (int j = 0; j < samples; ++j) phases[std::size_t(j)] = double(j) / samples;
  return mesh_phases_at(m, t1, t2, phases, stiffness);
}

PairContact pair_contact_at(const PairSteModel& m, const PathOfContact& path, double s) {
  const ContactRadii r = contact_radii(m.gear1, m.gear2, path, s);
  PairContact c = contact_point(m, path, r.r1, r.r2);
  c.s = s;
  return c;
}

PairStiffnessFn beam_pair_stiffness(const PairSteModel& m) {
  const int ne = m.elements();
  return beam_pair_stiffness(m, tooth_beam(m.gear1, m.youngs_modulus1, ne, m.thickness_at),
                             tooth_beam(m.gear2, m.youngs_modulus2, ne, m.thickness_at));
}

std::vector<MeshPhase> mesh_phases_at(const PairSteModel& m, const std::vector<double>& phases,
                                      const PairStiffnessFn& stiffness) {
  const int ne = m.elements();
  return mesh_phases_at(m, tooth_beam(m.gear1, m.youngs_modulus1, ne, m.thickness_at),
                        tooth_beam(m.gear2, m.youngs_modulus2, ne, m.thickness_at), phases, stiffness);
}

std::vector<MeshPhase> mesh_phases_at(const PairSteModel& m, const ToothBeam& t1, const ToothBeam& t2,
                                      const std::vector<double>& phases, const PairStiffnessFn& stiffness) {
  const PathOfContact path = m.path();
  const double pb = path.base_pitch;
  const PairStiffnessFn k = stiffness ? stiffness : beam_pair_stiffness(m, t1, t2);
  std::vector<MeshPhase> out;
  out.reserve(phases.size());
  for (double phase : phases) {
    if (!(phase >= 0.0 && phase < 1.0)) throw std::invalid_argument("mesh_phases_at: a phase outside [0, 1)");
    MeshPhase ph;
    ph.phase = phase;
    for (double s = ph.phase * pb; s <= path.AE; s += pb) {
      const ContactRadii r = contact_radii(m.gear1, m.gear2, path, s);
      PairContact c = contact_point(m, path, r.r1, r.r2);
      c.s = s;
      ph.pairs.push_back(c);
    }
    const bool sharing = ph.pairs.size() > 1;
    for (PairContact& c : ph.pairs) c.stiffness = k(c.r1, c.r2, sharing);
    out.push_back(ph);
  }
  return out;
}

std::vector<PairStePoint> pair_ste(const PairSteModel& m, const std::vector<MeshPhase>& phases, double torque) {
  const double F = m.force(torque), L = m.contact_length();
  std::vector<PairStePoint> out;
  out.reserve(phases.size());
  std::vector<ContactPair> pairs;
  for (const MeshPhase& ph : phases) {
    pairs.clear();
    for (const PairContact& c : ph.pairs) pairs.push_back({c.stiffness, c.separation});
    PairStePoint p;
    p.mesh = ph;
    take_share(p, share_load(pairs, F, m.hertz, m.pair_hertz, L));
    out.push_back(std::move(p));
  }
  return out;
}

void take_share(PairStePoint& p, const LoadShare& share, double scale) {
  for (std::size_t i = 0; i < share.force.size(); ++i) p.mesh.pairs[i].force = share.force[i] / scale;
  p.loaded = share.loaded;
  p.approach = share.approach;
  p.hertz = share.hertz;
  p.ste = share.ste;
}

double single_pair_ste(const PairSteModel& m, double s, double torque, const PairStiffnessFn& stiffness) {
  PairSteModel alone = m;
  alone.relief1.amount = alone.relief2.amount = 0.0;
  alone.positions_per_base_pitch = 0;
  if (stiffness) {
    const ContactRadii r = contact_radii(alone.gear1, alone.gear2, alone.path(), s);
    return share_load({{stiffness(r.r1, r.r2, false), 0.0}}, alone.force(torque), alone.hertz, alone.pair_hertz,
                      alone.contact_length()).ste;
  }
  const int ne = alone.elements();
  const ToothBeam t1 = tooth_beam(alone.gear1, alone.youngs_modulus1, ne, alone.thickness_at);
  const ToothBeam t2 = tooth_beam(alone.gear2, alone.youngs_modulus2, ne, alone.thickness_at);
  const PathOfContact path = alone.path();
  const ContactRadii r = contact_radii(alone.gear1, alone.gear2, path, s);
  const double k = cantilever_pair_stiffness(t1, r.r1 - alone.gear1.root_radius(), t2, r.r2 - alone.gear2.root_radius());
  return share_load({{k, 0.0}}, alone.force(torque), alone.hertz, alone.pair_hertz, alone.contact_length()).ste;
}

double loaded_contact_ratio(const std::vector<PairStePoint>& cycle, const PathOfContact& path) {
  std::vector<std::pair<double, double>> sf;   // (s, force) of every pair at every phase
  for (const auto& p : cycle)
    for (const auto& c : p.mesh.pairs) sf.emplace_back(c.s, c.force);
  if (sf.empty()) return 0.0;
  std::sort(sf.begin(), sf.end());
  const auto loaded = [&](std::size_t i) { return sf[i].second > 0.0; };
  // The end of the loaded stretch that starts or stops between samples i and j = i +- 1
  // (i loaded, j not): the zero of the line through the loaded samples i and i - (j - i).
  const auto edge = [&](std::size_t i, std::size_t j) {
    const std::size_t k = j > i ? i - 1 : i + 1;   // the loaded side's next sample
    const bool line = k < sf.size() && loaded(k) && sf[k].second != sf[i].second;
    double t = 0.5;                                // no second loaded sample: the midpoint
    if (line) t = sf[i].second / (sf[k].second - sf[i].second) * (sf[i].first - sf[k].first) / (sf[j].first - sf[i].first);
    return std::clamp(t, 0.0, 1.0) * std::fabs(sf[j].first - sf[i].first);
  };
  double length = 0.0;
  if (loaded(0)) length += sf[0].first;                                  // from A
  if (loaded(sf.size() - 1)) length += path.AE - sf.back().first;       // to E
  for (std::size_t i = 0; i + 1 < sf.size(); ++i) {
    const bool a = loaded(i), b = loaded(i + 1);
    if (a && b) length += sf[i + 1].first - sf[i].first;
    else if (a) length += edge(i, i + 1);
    else if (b) length += edge(i + 1, i);
  }
  return length / path.base_pitch;
}

}  // namespace gearhb
