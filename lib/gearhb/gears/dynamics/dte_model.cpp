#include "gearhb/gears/dynamics/dte_model.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/hb/contact.hpp"
#include "gearhb/hb/response.hpp"

namespace gearhb {

double equivalent_mass(double I1, double I2, double r1, double r2) {
  return I1 * I2 / (I1 * r2 * r2 + I2 * r1 * r1);
}

double mesh_damping(double zeta, double kc, double me) { return 2.0 * zeta * std::sqrt(kc * me); }

Eigen::VectorXd ste_harmonics(const DteGear& g, int H) {
  if (g.ste.size() < 1) throw std::invalid_argument("DteGear: empty STE");
  Eigen::VectorXd e = Eigen::VectorXd::Zero(2 * H + 1);
  const int n = std::min<int>(int(g.ste.size()), 2 * H + 1);
  e.head(n) = g.ste.head(n);
  return e;
}

const char* to_string(DteModel m) { return m == DteModel::parametric ? "parametric" : "constant"; }

namespace {
// A series cut (or zero-padded) to H harmonics; an empty one is 0.
Eigen::VectorXd cut(const Eigen::VectorXd& c, int H) {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(2 * H + 1);
  const int n = std::min<int>(int(c.size()), 2 * H + 1);
  e.head(n) = c.head(n);
  return e;
}
// The elastic part e_H - g_H of the STE (g the no-load transmission error).
Eigen::VectorXd elastic_ste(const DteGear& g, int H) { return ste_harmonics(g, H) - cut(g.nlte, H); }
}  // namespace

double dte_parametric_stiffness(const DteGear& g, int H, double theta) {
  return g.F0 / trig_series(elastic_ste(g, H), theta);
}

HarmonicBalance dte_harmonic_balance(const DteGear& g, int H, int N, ContactQuadrature q, DteModel model) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Constant(1, 1, g.me), C = Eigen::MatrixXd::Constant(1, 1, g.c);
  const Eigen::MatrixXd K = Eigen::MatrixXd::Zero(1, 1);   // rigid shafts: no spring to ground
  const Eigen::VectorXd one = Eigen::VectorXd::Constant(1, 1.0);
  Excitation f{Eigen::VectorXd::Constant(1, g.F0), Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1)};
  return HarmonicBalance(LinearSystem{M, C, K}, dte_mesh_contacts(g, H, model, one), f, H, N, q);
}

std::vector<UnilateralContact> dte_mesh_contacts(const DteGear& g, int H, DteModel model, const Eigen::VectorXd& n) {
  // A contact whose penetration is  sign u + p(theta),  p given by its coefficients.
  auto contact = [&](double sign, Eigen::VectorXd p) {
    const double p0 = p[0];
    p[0] = 0.0;
    return UnilateralContact{sign * n, g.kc, p0, p};
  };
  const Eigen::VectorXd gH = cut(g.nlte, H);
  const Eigen::VectorXd gb = reflected_series(gH, g.back_phase);   // g_b(theta) = g(psi - theta)
  const Eigen::VectorXd bn = Eigen::VectorXd::Unit(2 * H + 1, 0) * (has_back_flank(g) ? g.backlash : 0.0);
  std::vector<UnilateralContact> mesh;
  if (model == DteModel::parametric) {
    // k_el(theta) = F0 / (e_H - g_H)(theta) = kc s(theta); e_H - g_H must stay positive
    const Eigen::VectorXd el = elastic_ste(g, H);
    const Aft aft(H, 64 * (2 * H + 1));
    const Eigen::VectorXd es = aft.to_time(el);
    if (!(es.minCoeff() > 0.0))
      throw std::invalid_argument("parametric mesh model: the elastic STE (STE minus the no-load transmission error) cut to H = " +
                                  std::to_string(H) + " harmonics is not positive over the whole mesh cycle (min " +
                                  std::to_string(es.minCoeff()) + " m)");
    const double F0 = g.F0, kc = g.kc;
    auto profile = [el, F0, kc](double th) { return F0 / (kc * trig_series(el, th)); };
    mesh.push_back(contact(1.0, -gH));                         // d - g
    mesh.back().stiffness_profile = profile;
    if (has_back_flank(g)) {
      const double psi = g.back_phase;
      mesh.push_back(contact(-1.0, -bn - gb));                 // -d - b_n - g_b
      mesh.back().stiffness_profile = [profile, psi](double th) { return profile(psi - th); };
    }
    return mesh;
  }
  const Eigen::VectorXd e = ste_harmonics(g, H);
  mesh.push_back(contact(1.0, e));                             // x + e
  if (has_back_flank(g)) mesh.push_back(contact(-1.0, -e - bn - gb));   // -(x + e) - b_n - g_b
  return mesh;
}

Eigen::VectorXd dte_closed_contact(const DteGear& g, int H, double omega) {
  const Eigen::VectorXd e = ste_harmonics(g, H);
  Eigen::VectorXd X(2 * H + 1);
  X[0] = g.F0 / g.kc - e[0];
  for (int n = 1; n <= H; ++n) {
    const double omega_n = n * omega;
    // E_n = a - i b for e = Re(E e^{i n theta}); the same for X.
    const std::complex<double> E(e[2 * n - 1], -e[2 * n]);
    const std::complex<double> Xn = -g.kc * E / std::complex<double>(g.kc - omega_n * omega_n * g.me, omega_n * g.c);
    X[2 * n - 1] = Xn.real();
    X[2 * n] = -Xn.imag();
  }
  return X;
}

Eigen::VectorXd dte_penetration(const DteGear& g, const Eigen::VectorXd& X) {
  const int H = int(X.size() - 1) / 2;
  return X + ste_harmonics(g, H);
}

double dte_mean_contact_force(const HarmonicBalance& hb, const Eigen::VectorXd& X) {
  double F = mean_contact_force(hb, X, 0);
  if (hb.contacts().size() > 1) F -= mean_contact_force(hb, X, 1);
  return F;
}

double rms_ac(const Eigen::VectorXd& c) {
  return std::sqrt(0.5 * c.tail(c.size() - 1).squaredNorm());
}

}  // namespace gearhb
