#include "gearhb/gears/sets/planetary.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gearhb/core/linear_dynamics.hpp"

namespace gearhb {

namespace {

void positive(double v, const std::string& what) {
  if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument("planetary set: " + what + " must be > 0");
}
void non_negative(double v, const std::string& what) {
  if (!(v >= 0.0) || !std::isfinite(v)) throw std::invalid_argument("planetary set: " + what + " must be >= 0");
}

void check_member(const CentralMember& m, const std::string& name) {
  positive(m.mass, name + " mass");
  positive(m.inertia_r2, name + " inertia_r2");
  non_negative(m.bearing, name + " bearing");
  non_negative(m.torsional, name + " torsional");
}

// The kinetic energies of a mass-normalised shape: central translations, central
// rotations, and sum_n |q_n - q_1|^2_M over the planets.
struct ShapeEnergies {
  double central_translation = 0.0, central_rotation = 0.0, planets_unlike = 0.0;
};

ShapeEnergies shape_energies(const PlanetarySet& s, const Eigen::MatrixXd& M, const Eigen::VectorXd& phi) {
  ShapeEnergies e;
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 2; ++k) e.central_translation += M(3 * j + k, 3 * j + k) * phi(3 * j + k) * phi(3 * j + k);
    e.central_rotation += M(3 * j + 2, 3 * j + 2) * phi(3 * j + 2) * phi(3 * j + 2);
  }
  for (int n = 1; n < s.planets(); ++n)
    for (int k = 0; k < 3; ++k) {
      const double d = phi(planet_coordinate(n, k)) - phi(planet_coordinate(0, k));
      e.planets_unlike += M(planet_coordinate(n, k), planet_coordinate(n, k)) * d * d;
    }
  return e;
}

}  // namespace

void PlanetarySet::check() const {
  check_member(carrier, "carrier");
  check_member(ring, "ring");
  check_member(sun, "sun");
  positive(planet_mass, "planet mass");
  positive(planet_inertia_r2, "planet inertia_r2");
  non_negative(planet_bearing, "planet bearing");
  positive(sun_mesh, "sun-planet mesh stiffness");
  positive(ring_mesh, "ring-planet mesh stiffness");
  if (!(sun_pressure_angle > 0.0 && sun_pressure_angle < M_PI / 2) ||
      !(ring_pressure_angle > 0.0 && ring_pressure_angle < M_PI / 2))
    throw std::invalid_argument("planetary set: pressure angles must be in (0, 90) deg");
  if (planet_angles.empty()) throw std::invalid_argument("planetary set: at least one planet");
  for (double a : planet_angles)
    if (!std::isfinite(a)) throw std::invalid_argument("planetary set: planet angles must be finite");
  if (!std::isfinite(carrier_speed)) throw std::invalid_argument("planetary set: carrier speed must be finite");
}

std::vector<double> equally_spaced(int planets) {
  std::vector<double> psi(std::size_t(std::max(planets, 0)));
  for (int n = 0; n < planets; ++n) psi[std::size_t(n)] = 2.0 * M_PI * n / planets;
  return psi;
}

PlanetarySet lin_parker_1999_set(int planets) {
  PlanetarySet s;
  s.carrier = {5.43, 6.29, 1e8, 0.0};
  s.ring = {2.35, 3.0, 1e8, 1e9};
  s.sun = {0.4, 0.39, 1e8, 0.0};
  s.planet_mass = 0.66;
  s.planet_inertia_r2 = 0.61;
  s.planet_bearing = 1e8;
  s.sun_mesh = s.ring_mesh = 5e8;
  s.sun_pressure_angle = s.ring_pressure_angle = 24.6 * M_PI / 180.0;
  s.planet_angles = equally_spaced(planets);
  return s;
}

Eigen::VectorXd sun_mesh_direction(const PlanetarySet& s, int n) {
  const double psi = s.planet_angles.at(std::size_t(n)) - s.sun_pressure_angle, a = s.sun_pressure_angle;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(s.dofs());
  d(coordinate(Body::sun, 0)) = -std::sin(psi);
  d(coordinate(Body::sun, 1)) = std::cos(psi);
  d(coordinate(Body::sun, 2)) = 1.0;
  d(planet_coordinate(n, 0)) = -std::sin(a);
  d(planet_coordinate(n, 1)) = -std::cos(a);
  d(planet_coordinate(n, 2)) = 1.0;
  return d;
}

Eigen::VectorXd ring_mesh_direction(const PlanetarySet& s, int n) {
  const double psi = s.planet_angles.at(std::size_t(n)) + s.ring_pressure_angle, a = s.ring_pressure_angle;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(s.dofs());
  d(coordinate(Body::ring, 0)) = -std::sin(psi);
  d(coordinate(Body::ring, 1)) = std::cos(psi);
  d(coordinate(Body::ring, 2)) = 1.0;
  d(planet_coordinate(n, 0)) = std::sin(a);
  d(planet_coordinate(n, 1)) = -std::cos(a);
  d(planet_coordinate(n, 2)) = -1.0;
  return d;
}

PlanetaryMatrices planetary_matrices(const PlanetarySet& s) {
  s.check();
  const int n = s.dofs();
  PlanetaryMatrices m;
  m.M = Eigen::MatrixXd::Zero(n, n);
  m.K_bearing = Eigen::MatrixXd::Zero(n, n);
  m.K_mesh = Eigen::MatrixXd::Zero(n, n);
  m.G = Eigen::MatrixXd::Zero(n, n);
  m.K_omega = Eigen::MatrixXd::Zero(n, n);
  auto body = [&](int i0, double mass, double inertia_r2) {
    m.M(i0, i0) = m.M(i0 + 1, i0 + 1) = mass;
    m.M(i0 + 2, i0 + 2) = inertia_r2;
    m.G(i0, i0 + 1) = -2.0 * mass;
    m.G(i0 + 1, i0) = 2.0 * mass;
    m.K_omega(i0, i0) = m.K_omega(i0 + 1, i0 + 1) = mass;
  };
  const CentralMember* central[3] = {&s.carrier, &s.ring, &s.sun};
  for (int j = 0; j < 3; ++j) {
    body(3 * j, central[j]->mass, central[j]->inertia_r2);
    m.K_bearing(3 * j, 3 * j) = m.K_bearing(3 * j + 1, 3 * j + 1) = central[j]->bearing;
    m.K_bearing(3 * j + 2, 3 * j + 2) = central[j]->torsional;
  }
  for (int p = 0; p < s.planets(); ++p) {
    body(planet_coordinate(p, 0), s.planet_mass, s.planet_inertia_r2);
    const double psi = s.planet_angles[std::size_t(p)];
    Eigen::VectorXd radial = Eigen::VectorXd::Zero(n), tangential = Eigen::VectorXd::Zero(n);
    radial(coordinate(Body::carrier, 0)) = std::cos(psi);
    radial(coordinate(Body::carrier, 1)) = std::sin(psi);
    radial(planet_coordinate(p, 0)) = -1.0;
    tangential(coordinate(Body::carrier, 0)) = -std::sin(psi);
    tangential(coordinate(Body::carrier, 1)) = std::cos(psi);
    tangential(coordinate(Body::carrier, 2)) = 1.0;
    tangential(planet_coordinate(p, 1)) = -1.0;
    m.K_bearing += s.planet_bearing * (radial * radial.transpose() + tangential * tangential.transpose());
    const Eigen::VectorXd ds = sun_mesh_direction(s, p), dr = ring_mesh_direction(s, p);
    m.K_mesh += s.sun_mesh * ds * ds.transpose() + s.ring_mesh * dr * dr.transpose();
  }
  return m;
}

std::string to_string(ModeType t) {
  switch (t) {
    case ModeType::rotational: return "rotational";
    case ModeType::translational: return "translational";
    case ModeType::planet: return "planet";
    case ModeType::mixed: break;
  }
  return "mixed";
}

ModeType classify_mode(const PlanetarySet& s, const Eigen::MatrixXd& M, const Eigen::VectorXd& phi, double tol) {
  const ShapeEnergies e = shape_energies(s, M, phi);
  if (e.central_translation + e.central_rotation < tol) return ModeType::planet;
  if (e.central_translation < tol && e.planets_unlike < tol) return ModeType::rotational;
  if (e.central_rotation < tol) return ModeType::translational;
  return ModeType::mixed;
}

std::vector<PlanetaryMode> planetary_modes(const PlanetarySet& s) {
  const PlanetaryMatrices m = planetary_matrices(s);
  const Modes modes = modal_analysis(m.M, m.K_bearing + m.K_mesh);
  const int n = s.dofs();
  std::vector<PlanetaryMode> out(static_cast<std::size_t>(n));
  const double same = 1e-7 * modes.omega.maxCoeff();
  int group = -1;
  for (int i = 0; i < n; ++i) {
    PlanetaryMode& p = out[std::size_t(i)];
    p.omega = modes.omega(i);
    p.shape = modes.Phi.col(i);
    p.type = classify_mode(s, m.M, p.shape);
    if (i == 0 || p.omega - out[std::size_t(i - 1)].omega > same) ++group;
    p.group = group;
  }
  for (int i = 0; i < n;) {   // multiplicity and one type per group
    int j = i;
    bool one_type = true;
    while (j < n && out[std::size_t(j)].group == out[std::size_t(i)].group) {
      one_type = one_type && out[std::size_t(j)].type == out[std::size_t(i)].type;
      ++j;
    }
    for (int k = i; k < j; ++k) {
      out[std::size_t(k)].multiplicity = j - i;
      if (!one_type) out[std::size_t(k)].type = ModeType::mixed;
    }
    i = j;
  }
  return out;
}

Eigen::VectorXd natural_frequencies_at_speed(const PlanetarySet& s, double carrier_speed) {
  const PlanetaryMatrices m = planetary_matrices(s);
  const int n = s.dofs();
  // In the state (z, z' / w), z = M^(1/2) q and w the largest natural frequency's scale, the
  // first-order matrix has blocks of one size (~w): its eigenvalues lose eps w, not eps w^2.
  const Eigen::VectorXd h = m.M.diagonal().cwiseSqrt().cwiseInverse();   // M is diagonal
  const Eigen::MatrixXd K = h.asDiagonal() * m.stiffness(carrier_speed) * h.asDiagonal();
  const Eigen::MatrixXd G = h.asDiagonal() * m.G * h.asDiagonal();
  const double w = std::sqrt(std::max(K.cwiseAbs().rowwise().sum().maxCoeff(), 1e-300));
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n) = w * Eigen::MatrixXd::Identity(n, n);
  A.bottomLeftCorner(n, n) = -K / w;
  A.bottomRightCorner(n, n) = -carrier_speed * G;
  const Eigen::VectorXcd lambda = general_eigenvalues(A, "natural_frequencies_at_speed");
  std::vector<double> f(std::size_t(2 * n));
  for (int i = 0; i < 2 * n; ++i) f[std::size_t(i)] = std::abs(lambda(i).imag());
  std::sort(f.begin(), f.end());
  Eigen::VectorXd omega(n);   // each frequency appears as +i omega and -i omega
  for (int i = 0; i < n; ++i) omega(i) = f[std::size_t(2 * i)];
  return omega;
}

int planet_not_assembling(const PlanetaryTeeth& t, const std::vector<double>& planet_angles, double tol) {
  for (std::size_t n = 0; n < planet_angles.size(); ++n) {
    const double teeth = (t.sun + t.ring) * planet_angles[n] / (2.0 * M_PI);
    if (std::fabs(teeth - std::round(teeth)) > tol) return int(n);
  }
  return -1;
}

double planet_tip_clearance(const PlanetaryTeeth& t, const std::vector<double>& planet_angles) {
  if (planet_angles.size() < 2) return INFINITY;
  std::vector<double> psi = planet_angles;
  for (double& a : psi) a -= 2.0 * M_PI * std::floor(a / (2.0 * M_PI));
  std::sort(psi.begin(), psi.end());
  const double tip_diameter = (t.planet + 2.0 * t.addendum) * t.module;
  double clearance = INFINITY;
  for (std::size_t n = 0; n < psi.size(); ++n) {
    const double gap = n + 1 < psi.size() ? psi[n + 1] - psi[n] : psi[0] + 2.0 * M_PI - psi[n];
    clearance = std::min(clearance, 2.0 * t.centre_distance() * std::sin(0.5 * gap) - tip_diameter);
  }
  return clearance;
}

}  // namespace gearhb
