#include "gearhb/gears/ste_continuous.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/gears/gear_geometry.hpp"
#include "gearhb/gears/hertz.hpp"
#include "gearhb/gears/tooth_fe.hpp"

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

// Nodal (w, theta) of the element e for a cantilever loaded by the nodal loads
// `load` (4 values on the element's DOFs).
Eigen::Vector4d loaded_element(const ToothBeam& t, int e, const Eigen::Vector4d& load) {
  BeamModel m;
  const int b = m.add_beam(t.x, t.EI);
  m.clamp(m.node(b, 0));
  m.add_force(m.node(b, e), load[0]);
  m.add_moment(m.node(b, e), load[1]);
  m.add_force(m.node(b, e + 1), load[2]);
  m.add_moment(m.node(b, e + 1), load[3]);
  const BeamModel::Solution s = m.solve();
  const int n1 = m.node(b, e), n2 = m.node(b, e + 1);
  return {s.Q[BeamModel::w_dof(n1)], s.Q[BeamModel::theta_dof(n1)], s.Q[BeamModel::w_dof(n2)],
          s.Q[BeamModel::theta_dof(n2)]};
}

double hertz_two_pairs(const SteModel& m, double FA, double FB) {
  const double b = m.gear.face_width, nh = double(int(m.hertz));
  switch (m.two_pair_hertz) {
    case TwoPairHertz::equal_split: return nh * palmgren_line_contact_approach(0.5 * (FA + FB), b);
    case TwoPairHertz::fe_split_mean:
      return nh * 0.5 * (palmgren_line_contact_approach(FA, b) + palmgren_line_contact_approach(FB, b));
    case TwoPairHertz::consistent: break;
  }
  throw std::invalid_argument("ste_continuous: the consistent two-pair Hertz split is not offered");
}

}  // namespace

Eigen::Matrix2d tooth_flexibility(const ToothBeam& tooth, double a) {
  if (tooth.x.size() < 2) throw std::invalid_argument("tooth_flexibility: the beam needs an element");
  if (!(a > 0.0) || a > tooth.x.back() * (1 + 1e-12))
    throw std::invalid_argument("tooth_flexibility: load height " + std::to_string(a) +
                                " m is not on the tooth (0, " + std::to_string(tooth.x.back()) + "]");
  const auto [e, xi] = locate(tooth, a);
  const double L = tooth.x[e + 1] - tooth.x[e];
  const Eigen::Vector4d N = shape(xi, L), dN = shape_dx(xi, L);
  const Eigen::Vector4d qF = loaded_element(tooth, e, N), qM = loaded_element(tooth, e, dN);
  Eigen::Matrix2d G;
  G << N.dot(qF), N.dot(qM), dN.dot(qF), dN.dot(qM);
  return G;
}

double fused_pair_stiffness(const ToothBeam& tooth, double a1, double a2) {
  const Eigen::Matrix2d D = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  const Eigen::Matrix2d G = tooth_flexibility(tooth, a1) + D * tooth_flexibility(tooth, a2) * D;
  return G.inverse()(0, 0);
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

std::vector<StePoint> ste_continuous(const SteModel& m, double torque, int samples) {
  if (samples < 4 || samples > 1 << 16)
    throw std::invalid_argument("ste_continuous: samples per mesh cycle must be in [4, 65536]");
  const ToothBeam tooth = tooth_beam(m);
  const PathOfContact path = path_of_contact(m.gear, m.gear);
  const double rf = m.gear.root_radius(), pb = path.base_pitch, F = m.force(torque);
  const double nh = double(int(m.hertz)), b = m.gear.face_width;
  std::vector<StePoint> out;
  for (int j = 0; j < samples; ++j) {
    StePoint p;
    p.phase = double(j) / samples;
    const double s = p.phase * pb;
    const ContactRadii rA = contact_radii(m.gear, m.gear, s);
    p.a1A = rA.r1 - rf;
    p.a2A = rA.r2 - rf;
    if (s + pb <= path.AE) {
      const ContactRadii rB = contact_radii(m.gear, m.gear, s + pb);
      p.pairs = 2;
      p.a1B = rB.r1 - rf;
      p.a2B = rB.r2 - rf;
      const double kA = fused_pair_stiffness(tooth, p.a1A, p.a2A), kB = fused_pair_stiffness(tooth, p.a1B, p.a2B);
      p.elastic = F / (kA + kB);
      p.force_A = kA * p.elastic;
      p.force_B = kB * p.elastic;
      p.hertz = hertz_two_pairs(m, p.force_A, p.force_B);
    } else {
      p.elastic = single_pair_elastic(m, tooth, s, F);
      p.force_A = F;
      p.hertz = nh * palmgren_line_contact_approach(F, b);
    }
    p.ste = p.elastic + p.hertz;
    out.push_back(p);
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

Eigen::VectorXd periodic_fourier(const std::vector<double>& samples, int H) {
  const int N = int(samples.size());
  if (N < 4 || H < 0) throw std::invalid_argument("periodic_fourier: need >= 4 samples and H >= 0");
  const int Hc = std::min(H, (N - 2) / 2);
  Aft aft(Hc, N);
  const Eigen::VectorXd c = aft.to_frequency(Eigen::Map<const Eigen::VectorXd>(samples.data(), N));
  Eigen::VectorXd out = Eigen::VectorXd::Zero(2 * H + 1);
  out.head(c.size()) = c;
  return out;
}

double mean_stiffness(const std::vector<double>& ste, double F) {
  double sum = 0.0;
  for (double e : ste) sum += F / e;
  return sum / double(ste.size());
}

}  // namespace gearhb
