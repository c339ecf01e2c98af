#include "gearhb/gears/dte_model.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "gearhb/core/fourier.hpp"
#include "gearhb/hb/contact.hpp"

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

double dte_parametric_stiffness(const DteGear& g, int H, double theta) {
  const Eigen::VectorXd e = ste_harmonics(g, H);
  double v = e[0];
  for (int k = 1; k <= H; ++k) v += e[2 * k - 1] * std::cos(k * theta) + e[2 * k] * std::sin(k * theta);
  return g.F0 / v;
}

HarmonicBalance dte_harmonic_balance(const DteGear& g, int H, int N, ContactQuadrature q, DteModel model) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Constant(1, 1, g.me), C = Eigen::MatrixXd::Constant(1, 1, g.c);
  const Eigen::MatrixXd K = Eigen::MatrixXd::Zero(1, 1);   // rigid shafts: no spring to ground
  const Eigen::VectorXd one = Eigen::VectorXd::Constant(1, 1.0);
  Excitation f{Eigen::VectorXd::Constant(1, g.F0), Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1)};
  Eigen::VectorXd e = ste_harmonics(g, H);
  if (model == DteModel::parametric) {
    // k(theta) = F0 / e_H(theta) = kc s(theta); e_H must stay positive
    const Aft aft(H, 64 * (2 * H + 1));
    const Eigen::VectorXd es = aft.to_time(e);
    if (!(es.minCoeff() > 0.0))
      throw std::invalid_argument("parametric mesh model: the STE cut to H = " + std::to_string(H) +
                                  " harmonics is not positive over the whole mesh cycle (min " +
                                  std::to_string(es.minCoeff()) + " m)");
    const double F0 = g.F0, kc = g.kc;
    UnilateralContact mesh{one, kc, 0.0, {}, [e, F0, kc, H](double th) {
                             double v = e[0];
                             for (int k = 1; k <= H; ++k) v += e[2 * k - 1] * std::cos(k * th) + e[2 * k] * std::sin(k * th);
                             return F0 / (kc * v);
                           }};
    return HarmonicBalance(LinearSystem{M, C, K}, {mesh}, f, H, N, q);
  }
  const double e0 = e[0];
  e[0] = 0.0;
  UnilateralContact mesh{one, g.kc, e0, e};
  return HarmonicBalance(LinearSystem{M, C, K}, {mesh}, f, H, N, q);
}

Eigen::VectorXd dte_closed_contact(const DteGear& g, int H, double omega) {
  const Eigen::VectorXd e = ste_harmonics(g, H);
  Eigen::VectorXd X(2 * H + 1);
  X[0] = g.F0 / g.kc - e[0];
  for (int n = 1; n <= H; ++n) {
    const double w = n * omega;
    // E_n = a - i b for e = Re(E e^{i n theta}); the same for X.
    const std::complex<double> E(e[2 * n - 1], -e[2 * n]);
    const std::complex<double> Xn = -g.kc * E / std::complex<double>(g.kc - w * w * g.me, w * g.c);
    X[2 * n - 1] = Xn.real();
    X[2 * n] = -Xn.imag();
  }
  return X;
}

Eigen::VectorXd dte_penetration(const DteGear& g, const Eigen::VectorXd& X) {
  const int H = int(X.size() - 1) / 2;
  return X + ste_harmonics(g, H);
}

double dte_mean_contact_force(const DteGear& g, const Eigen::VectorXd& X, DteModel model) {
  const Eigen::VectorXd u = model == DteModel::parametric ? X : dte_penetration(g, X);
  const int H = int(u.size() - 1) / 2;
  const Aft aft(H, std::max(Aft::default_samples(H), 64));
  const Eigen::VectorXd us = aft.to_time(u);
  const auto intervals = contact_intervals(u, us);
  if (model == DteModel::parametric) {
    // (1/2pi) int_I k d: the moment of order 0 of the indicator weighted by k d
    auto kd = [&](double th) {
      double d = u[0];
      for (int k = 1; k <= H; ++k) d += u[2 * k - 1] * std::cos(k * th) + u[2 * k] * std::sin(k * th);
      return dte_parametric_stiffness(g, H, th) * d;
    };
    double Sc = 0.0, Ss = 0.0;
    weighted_indicator_moments(intervals, kd, 0, 2.0 * M_PI / aft.samples(), &Sc, &Ss);
    return Sc;
  }
  double sum = 0.0;
  for (const auto& [a, b] : intervals) {
    sum += u[0] * (b - a);
    for (int k = 1; k <= H; ++k)
      sum += (u[2 * k - 1] * (std::sin(k * b) - std::sin(k * a)) - u[2 * k] * (std::cos(k * b) - std::cos(k * a))) / k;
  }
  return g.kc * sum / (2.0 * M_PI);
}

double rms_ac(const Eigen::VectorXd& c) {
  return std::sqrt(0.5 * c.tail(c.size() - 1).squaredNorm());
}

}  // namespace gearhb
