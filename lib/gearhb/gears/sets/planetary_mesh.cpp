#include "gearhb/gears/sets/planetary_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/core/linear_dynamics.hpp"

namespace gearhb {

namespace {

double cycles_mod_1(double v) { return v - std::floor(v); }

}  // namespace

double RectangularMesh::stiffness(double theta) const {
  const double phase = cycles_mod_1(theta / (2.0 * M_PI));
  return phase < contact_ratio - 1.0 ? ratio * single() : single();
}

Eigen::VectorXd RectangularMesh::harmonics(int H) const {
  // k = k_single + (k_double - k_single) 1[0, 2 pi d), d = eps - 1:
  // a_l = dk sin(2 pi l d) / (pi l), b_l = dk (1 - cos(2 pi l d)) / (pi l).
  Eigen::VectorXd c = Eigen::VectorXd::Zero(2 * H + 1);
  const double d = contact_ratio - 1.0, dk = (ratio - 1.0) * single() / mean;
  c(0) = 1.0;
  for (int l = 1; l <= H; ++l) {
    c(2 * l - 1) = dk * std::sin(2.0 * M_PI * l * d) / (M_PI * l);
    c(2 * l) = dk * (1.0 - std::cos(2.0 * M_PI * l * d)) / (M_PI * l);
  }
  return c;
}

double SampledMesh::mean() const {
  double sum = 0.0;
  for (double k : samples) sum += k;
  return samples.empty() ? 0.0 : sum / double(samples.size());
}

Eigen::VectorXd SampledMesh::harmonics(int H) const {
  if (int(samples.size()) < 4 || H > (int(samples.size()) - 2) / 2)
    throw std::invalid_argument("SampledMesh: J samples resolve at most (J - 2) / 2 harmonics");
  return periodic_fourier(samples, H) / mean();
}

Eigen::VectorXd PlanetaryMeshes::harmonics(bool ring_mesh, int H) const {
  const SampledMesh& computed = ring_mesh ? ring_computed : sun_computed;
  if (!computed.samples.empty()) return computed.harmonics(H);
  return (ring_mesh ? ring : sun).harmonics(H);
}

MeshPhases mesh_phases(const PlanetaryTeeth& t, const std::vector<double>& planet_angles, double ring_sun_phase) {
  MeshPhases p;
  for (double psi : planet_angles) {
    p.sun.push_back(cycles_mod_1(t.sun * psi / (2.0 * M_PI)));
    p.ring.push_back(cycles_mod_1(ring_sun_phase - t.ring * psi / (2.0 * M_PI)));
  }
  return p;
}

namespace {

// The stiffness profile of a mesh kind, cut to H harmonics: s(theta - shift) with shift = 2 pi phase.
std::function<double(double)> shifted(const Eigen::VectorXd& c, double phase) {
  const double shift = 2.0 * M_PI * phase;
  return [c, shift](double theta) { return trig_series(c, theta - shift); };
}

void check_meshes(const PlanetaryMeshes& m, int N) {
  if (int(m.phases.sun.size()) != N || int(m.phases.ring.size()) != N)
    throw std::invalid_argument("planetary_mesh_contacts: one mesh phase per planet and mesh");
  if (!m.backlash.empty() && int(m.backlash.size()) != 2 * N)
    throw std::invalid_argument("planetary_mesh_contacts: one backlash per mesh (2N)");
  if (!m.pin_errors.empty() && int(m.pin_errors.size()) != N)
    throw std::invalid_argument("planetary_mesh_contacts: one pin error per planet");
  for (double b : m.backlash)
    if (!(b >= 0.0)) throw std::invalid_argument("planetary_mesh_contacts: a backlash must be >= 0");
  for (const RectangularMesh* r : {&m.sun, &m.ring})
    if (!(r->mean > 0.0 && r->contact_ratio >= 1.0 && r->contact_ratio <= 2.0 && r->ratio >= 1.0))
      throw std::invalid_argument("planetary_mesh_contacts: a mesh needs k_mean > 0, 1 <= eps <= 2, ratio >= 1");
}

}  // namespace

std::vector<int> back_flank_contacts(const PlanetaryMeshes& m, int planets) {
  std::vector<int> back(std::size_t(2 * planets), -1);
  int next = 2 * planets;
  for (std::size_t i = 0; i < m.backlash.size() && i < back.size(); ++i)
    if (std::isfinite(m.backlash[i])) back[i] = next++;
  return back;
}

std::vector<UnilateralContact> planetary_mesh_contacts(const PlanetarySet& s, const PlanetaryMeshes& m, int H) {
  const int N = s.planets();
  check_meshes(m, N);
  std::vector<UnilateralContact> drive, back;
  for (int i = 0; i < 2 * N; ++i) {
    const bool ring = i >= N;
    const int n = i % N;
    const RectangularMesh& mesh = ring ? m.ring : m.sun;
    const Eigen::VectorXd c = m.harmonics(ring, H);
    for (int j = 0; j < 64 * (H + 1); ++j)   // the truncated wave (Gibbs) must stay a stiffness
      if (trig_series(c, 2.0 * M_PI * j / (64.0 * (H + 1))) <= 0.0)
        throw std::invalid_argument("planetary_mesh_contacts: the stiffness series is not positive");
    const double gamma = (ring ? m.phases.ring : m.phases.sun)[std::size_t(n)];
    const double alpha = ring ? s.ring_pressure_angle : s.sun_pressure_angle;
    UnilateralContact ct;
    ct.normal = ring ? ring_mesh_direction(s, n) : sun_mesh_direction(s, n);
    ct.kc = mesh.mean;
    ct.gap = m.pin_errors.empty() ? 0.0 : -m.pin_errors[std::size_t(n)] * std::cos(alpha);
    ct.stiffness_profile = shifted(c, gamma);
    if (!m.backlash.empty() && std::isfinite(m.backlash[std::size_t(i)])) {
      UnilateralContact b;
      b.normal = -ct.normal;
      b.kc = mesh.mean;
      b.gap = -m.backlash[std::size_t(i)] - ct.gap;
      const double psi = ring ? m.ring_back_mirror : m.sun_back_mirror;
      b.stiffness_profile = std::isfinite(psi) ? shifted(reflected_series(c, psi), gamma) : shifted(c, gamma + m.back_phase);
      back.push_back(std::move(b));
    }
    drive.push_back(std::move(ct));
  }
  drive.insert(drive.end(), back.begin(), back.end());
  if (int(drive.size()) > kMaxContacts)
    throw std::invalid_argument("planetary_mesh_contacts: " + std::to_string(drive.size()) + " contacts, at most " +
                                std::to_string(kMaxContacts));
  return drive;
}

PlanetaryMeshOrbit planetary_mesh_orbit(const HarmonicBalance& hb, const std::vector<int>& back, const Eigen::VectorXd& X,
                                        int mesh, double F0) {
  const int H = hb.harmonics(), J = 32 * (2 * H + 1);
  const int b = back[std::size_t(mesh)];
  const UnilateralContact& cd = hb.contacts()[std::size_t(mesh)];
  const Eigen::VectorXd ud = hb.penetration(X, std::size_t(mesh));
  const Eigen::VectorXd ub = b >= 0 ? hb.penetration(X, std::size_t(b)) : Eigen::VectorXd();
  Eigen::VectorXd sd(J), sb(b >= 0 ? J : 0);
  PlanetaryMeshOrbit o;
  double net = 0.0;
  for (int j = 0; j < J; ++j) {
    const double th = 2.0 * M_PI * j / J;
    sd(j) = trig_series(ud, th);
    const double fd = contact_force(stiffness_at(cd, th), sd(j));
    double fb = 0.0;
    if (b >= 0) {
      sb(j) = trig_series(ub, th);
      fb = contact_force(stiffness_at(hb.contacts()[std::size_t(b)], th), sb(j));
    }
    o.force_max = std::max(o.force_max, fd);
    net = std::max(net, std::fabs(fd - fb));
  }
  o.dynamic_factor = net / F0;
  o.drive = contact_state(ud, sd);
  o.back = b >= 0 ? contact_state(ub, sb) : ContactState::open;
  return o;
}

double planetary_sampled_dynamic_factor(const HarmonicBalance& hb, const std::vector<int>& back, const Eigen::MatrixXd& xs,
                                        int per_period, const std::vector<double>& F0) {
  auto force = [&](std::size_t k, const Eigen::VectorXd& x, double th) {
    const UnilateralContact& ct = hb.contacts()[k];
    double u = ct.gap + ct.normal.dot(x);
    if (ct.gap_harmonics.size() > 0) u += trig_series(ct.gap_harmonics, th);
    return contact_force(stiffness_at(ct, th), u);
  };
  double kv = 0.0;
  for (Eigen::Index j = 0; j < xs.rows(); ++j) {
    const double th = 2.0 * M_PI * double(j % per_period) / double(per_period);
    const Eigen::VectorXd x = xs.row(j).transpose();
    for (std::size_t i = 0; i < F0.size(); ++i) {
      const double N = force(i, x, th) - (back[i] >= 0 ? force(std::size_t(back[i]), x, th) : 0.0);
      kv = std::max(kv, std::fabs(N) / F0[i]);
    }
  }
  return kv;
}

std::vector<double> planetary_static_mesh_forces(const HarmonicBalance& hb, int planets) {
  const unsigned long long drive = (1ull << (2 * planets)) - 1ull;
  const Eigen::VectorXd x0 = hb.contact_set_solution(1.0, drive).head(hb.dofs());
  std::vector<double> F0(std::size_t(2 * planets), 0.0);
  for (int i = 0; i < 2 * planets; ++i) {
    const UnilateralContact& ct = hb.contacts()[std::size_t(i)];
    const double f = hb.mean_stiffness(std::size_t(i)) * (ct.normal.dot(x0) + ct.gap) / planets;
    for (int k = 0; k < planets; ++k) F0[std::size_t(i < planets ? k : planets + k)] += f;
  }
  return F0;
}

std::vector<double> planet_load_sharing(const std::vector<PlanetaryMeshOrbit>& meshes, int planets) {
  double sum = 0.0;
  for (int n = 0; n < planets; ++n) sum += meshes[std::size_t(n)].force_max;
  std::vector<double> L;
  for (int n = 0; n < planets; ++n) L.push_back(sum > 0.0 ? planets * meshes[std::size_t(n)].force_max / sum : NAN);
  return L;
}

Eigen::MatrixXd planetary_modal_damping(const PlanetarySet& s, double zeta) {
  const PlanetaryMatrices m = planetary_matrices(s);
  const Modes modes = modal_analysis(m.M, m.K_bearing + m.K_mesh);
  const Eigen::MatrixXd MPhi = m.M * modes.Phi;
  return MPhi * (2.0 * zeta * modes.omega).asDiagonal() * MPhi.transpose();
}

HarmonicBalance planetary_harmonic_balance(PlanetarySet s, const PlanetaryMeshes& m, double zeta,
                                           const Eigen::VectorXd& f0, int H) {
  s.sun_mesh = m.sun.mean;
  s.ring_mesh = m.ring.mean;
  const PlanetaryMatrices mat = planetary_matrices(s);
  LinearSystem sys{mat.M, planetary_modal_damping(s, zeta), mat.K_bearing};
  Excitation f{f0, Eigen::VectorXd::Zero(s.dofs()), Eigen::VectorXd::Zero(s.dofs()), 1};
  return HarmonicBalance(std::move(sys), planetary_mesh_contacts(s, m, H), std::move(f), H);
}

}  // namespace gearhb
