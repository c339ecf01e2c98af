#include "gearhb/gears/sets/planetary_mesh.hpp"

#include <cmath>
#include <stdexcept>

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

MeshPhases mesh_phases(const PlanetaryTeeth& t, const std::vector<double>& planet_angles, double ring_sun_phase) {
  MeshPhases p;
  for (double psi : planet_angles) {
    p.sun.push_back(cycles_mod_1(t.sun * psi / (2.0 * M_PI)));
    p.ring.push_back(cycles_mod_1(ring_sun_phase - t.ring * psi / (2.0 * M_PI)));
  }
  return p;
}

std::vector<UnilateralContact> planetary_mesh_contacts(const PlanetarySet& s, const PlanetaryMeshes& m, int H) {
  const int N = s.planets();
  if (int(m.phases.sun.size()) != N || int(m.phases.ring.size()) != N)
    throw std::invalid_argument("planetary_mesh_contacts: one mesh phase per planet and mesh");
  for (const RectangularMesh* r : {&m.sun, &m.ring})
    if (!(r->mean > 0.0 && r->contact_ratio >= 1.0 && r->contact_ratio <= 2.0 && r->ratio >= 1.0))
      throw std::invalid_argument("planetary_mesh_contacts: a mesh needs k_mean > 0, 1 <= eps <= 2, ratio >= 1");
  std::vector<UnilateralContact> contacts;
  for (int ring = 0; ring < 2; ++ring) {
    const RectangularMesh& mesh = ring ? m.ring : m.sun;
    const Eigen::VectorXd c = mesh.harmonics(H);
    for (int j = 0; j < 64 * (H + 1); ++j)   // the truncated wave (Gibbs) must stay a stiffness
      if (trig_series(c, 2.0 * M_PI * j / (64.0 * (H + 1))) <= 0.0)
        throw std::invalid_argument("planetary_mesh_contacts: the stiffness series is not positive");
    for (int n = 0; n < N; ++n) {
      UnilateralContact ct;
      ct.normal = ring ? ring_mesh_direction(s, n) : sun_mesh_direction(s, n);
      ct.kc = mesh.mean;
      const double shift = 2.0 * M_PI * (ring ? m.phases.ring : m.phases.sun)[std::size_t(n)];
      ct.stiffness_profile = [c, shift](double theta) { return trig_series(c, theta - shift); };
      contacts.push_back(std::move(ct));
    }
  }
  return contacts;
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
