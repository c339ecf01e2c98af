#include "gearhb/gears/tooth/tooth_fe.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gearhb {

Eigen::Matrix4d beam_element_stiffness(double EI, double L) {
  if (!(EI > 0.0) || !(L > 0.0))
    throw std::invalid_argument("beam_element_stiffness: EI and L must be > 0");
  Eigen::Matrix4d k;
  const double L2 = L * L;
  k << 12, 6 * L, -12, 6 * L,
       6 * L, 4 * L2, -6 * L, 2 * L2,
       -12, -6 * L, 12, -6 * L,
       6 * L, 2 * L2, -6 * L, 4 * L2;
  return (EI / (L2 * L)) * k;
}

int BeamModel::add_beam(const std::vector<double>& x, const std::vector<double>& EI) {
  if (x.size() < 2 || EI.size() != x.size() - 1)
    throw std::invalid_argument("add_beam: need n >= 2 node positions and n-1 element EI values");
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1])) throw std::invalid_argument("add_beam: node positions must increase");
  for (double v : EI)
    if (!(v > 0.0)) throw std::invalid_argument("add_beam: EI must be > 0");
  beams_.push_back({x, EI, n_nodes_});
  n_nodes_ += int(x.size());
  state_.resize(2 * n_nodes_);
  force_.resize(2 * n_nodes_, 0.0);
  return int(beams_.size()) - 1;
}

int BeamModel::node(int beam, int local) const {
  const Beam& b = beams_.at(beam);
  if (local < 0 || local >= int(b.x.size())) throw std::out_of_range("BeamModel::node");
  return b.first_node + local;
}

Eigen::MatrixXd BeamModel::stiffness() const {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs(), dofs());
  for (const Beam& b : beams_)
    for (std::size_t e = 0; e + 1 < b.x.size(); ++e) {
      const int d0 = 2 * (b.first_node + int(e));
      K.block<4, 4>(d0, d0) += beam_element_stiffness(b.EI[e], b.x[e + 1] - b.x[e]);
    }
  return K;
}

void BeamModel::prescribe(int dof, double value) {
  DofState& s = state_.at(dof);
  if (s.kind != Kind::free) throw std::logic_error("BeamModel: DOF " + std::to_string(dof) + " constrained twice");
  s.kind = Kind::prescribed;
  s.value = value;
}

void BeamModel::make_slave(int dof, int master_dof, double factor) {
  DofState& s = state_.at(dof);
  if (s.kind != Kind::free) throw std::logic_error("BeamModel: DOF " + std::to_string(dof) + " constrained twice");
  if (state_.at(master_dof).kind == Kind::slave)
    throw std::logic_error("BeamModel: a master DOF cannot itself be a slave");
  s.kind = Kind::slave;
  s.master = master_dof;
  s.factor = factor;
}

void BeamModel::clamp(int n) {
  prescribe(w_dof(n), 0.0);
  prescribe(theta_dof(n), 0.0);
}

void BeamModel::guide(int n, double w0) {
  prescribe(w_dof(n), w0);
  prescribe(theta_dof(n), 0.0);
}

void BeamModel::fuse(int master, int slave, double w_sign, bool fuse_rotation) {
  make_slave(w_dof(slave), w_dof(master), w_sign);
  if (fuse_rotation) make_slave(theta_dof(slave), theta_dof(master), 1.0);
}

void BeamModel::add_force(int n, double Fy) { force_.at(w_dof(n)) += Fy; }
void BeamModel::add_moment(int n, double Mx) { force_.at(theta_dof(n)) += Mx; }

// A positive definite reduced matrix means every beam is held. Each pivot is
// compared with its own diagonal entry (translations and rotations differ in
// scale by L^2, so a global threshold would be meaningless). The first pivot that
// fails names the DOF, node and beam that can move freely.
void BeamModel::check_held(const Eigen::LDLT<Eigen::MatrixXd>& ldlt, const Eigen::MatrixXd& Kr,
                           const std::vector<int>& column) const {
  const int n = int(Kr.rows());
  const Eigen::VectorXd D = ldlt.vectorD();
  const Eigen::VectorXd diag = (ldlt.transpositionsP() * Kr.diagonal()).eval();
  Eigen::VectorXi original = Eigen::VectorXi::LinSpaced(n, 0, n - 1);
  original = (ldlt.transpositionsP() * original).eval();
  int bad = -1;
  for (int i = 0; bad < 0 && i < n; ++i)
    if (!(D[i] > 1e-10 * std::fabs(diag[i]))) bad = i;
  if (bad < 0 && ldlt.info() != Eigen::Success) bad = 0;
  if (bad < 0) return;
  const int dof = int(std::find(column.begin(), column.end(), original[bad]) - column.begin());
  const int nd = dof / 2;
  int beam = 0;
  while (beam + 1 < beams() && beams_[beam + 1].first_node <= nd) ++beam;
  throw std::runtime_error(
      "BeamModel::solve: the stiffness matrix is singular at the " + std::string(dof % 2 ? "rotation" : "deflection") +
      " of node " + std::to_string(nd + 1) + " (beam " + std::to_string(beam + 1) + ", local node " +
      std::to_string(nd - beams_[beam].first_node) + " from its root; 1-based global numbers): that beam can move "
      "without straining, so clamp or guide its root or fuse it to a held beam (or its EI is about 1e10 times "
      "smaller than its neighbours')");
}

BeamModel::Solution BeamModel::solve() const {
  const int N = dofs();
  // Column of each independent (free) DOF in u.
  std::vector<int> column(N, -1);
  int n_free = 0;
  for (int i = 0; i < N; ++i)
    if (state_[i].kind == Kind::free) column[i] = n_free++;
  // Q = T u + Q0. Each row of T has at most one nonzero (a free DOF is its own
  // column, a slave DOF its master's column times +-1), stored as (col, factor).
  std::vector<int> col(N, -1);
  std::vector<double> factor(N, 0.0);
  Eigen::VectorXd Q0 = Eigen::VectorXd::Zero(N);
  for (int i = 0; i < N; ++i) {
    const DofState& s = state_[i];
    if (s.kind == Kind::free) {
      col[i] = column[i];
      factor[i] = 1.0;
    } else if (s.kind == Kind::prescribed) {
      Q0[i] = s.value;
    } else {
      const DofState& m = state_[s.master];
      if (m.kind == Kind::prescribed) {
        Q0[i] = s.factor * m.value;
      } else {
        col[i] = column[s.master];
        factor[i] = s.factor;
      }
    }
  }
  const Eigen::MatrixXd K = stiffness();
  const Eigen::VectorXd F = Eigen::Map<const Eigen::VectorXd>(force_.data(), N);
  Solution sol;
  sol.Q = Q0;
  if (n_free > 0) {
    // Kr = T' K T and fr = T' (F - K Q0), accumulated entry by entry (T is a
    // signed selection matrix: the thesis' Boolean matrix).
    Eigen::MatrixXd Kr = Eigen::MatrixXd::Zero(n_free, n_free);
    Eigen::VectorXd fr = Eigen::VectorXd::Zero(n_free);
    const Eigen::VectorXd rhs = F - K * Q0;
    for (int i = 0; i < N; ++i) {
      if (col[i] < 0) continue;
      fr[col[i]] += factor[i] * rhs[i];
      for (int j = 0; j < N; ++j)
        if (col[j] >= 0 && K(i, j) != 0.0) Kr(col[i], col[j]) += factor[i] * factor[j] * K(i, j);
    }
    Eigen::LDLT<Eigen::MatrixXd> ldlt(Kr);
    check_held(ldlt, Kr, column);
    const Eigen::VectorXd u = ldlt.solve(fr);
    for (int i = 0; i < N; ++i)
      if (col[i] >= 0) sol.Q[i] += factor[i] * u[col[i]];
  }
  sol.reactions = K * sol.Q - F;
  return sol;
}

Eigen::Vector4d BeamModel::element_end_forces(const Solution& s, int beam, int element) const {
  const Beam& b = beams_.at(beam);
  if (element < 0 || element + 1 >= int(b.x.size())) throw std::out_of_range("element_end_forces");
  const int d0 = 2 * (b.first_node + element);
  return beam_element_stiffness(b.EI[element], b.x[element + 1] - b.x[element]) *
         s.Q.segment<4>(d0);
}

double cantilever_point_load_deflection(double F, double a, double x, double EI) {
  if (x <= a) return F * x * x * (3 * a - x) / (6 * EI);
  return F * a * a * (3 * x - a) / (6 * EI);
}

double stepped_cantilever_compliance(const std::vector<double>& x, const std::vector<double>& EI,
                                     double a) {
  double c = 0.0;
  for (std::size_t e = 0; e + 1 < x.size() && x[e] < a; ++e) {
    const double u0 = a - x[e], u1 = a - std::min(x[e + 1], a);
    c += (u0 * u0 * u0 - u1 * u1 * u1) / (3.0 * EI[e]);
  }
  return c;
}

double stepped_clamped_guided_stiffness(const std::vector<double>& x, const std::vector<double>& EI) {
  // I_k = int x^k / EI dx, exact on each constant segment.
  double I0 = 0, I1 = 0, I2 = 0;
  for (std::size_t e = 0; e + 1 < x.size(); ++e) {
    const double a = x[e], b = x[e + 1];
    I0 += (b - a) / EI[e];
    I1 += (b * b - a * a) / (2.0 * EI[e]);
    I2 += (b * b * b - a * a * a) / (3.0 * EI[e]);
  }
  return 1.0 / (I2 - I1 * I1 / I0);
}

}  // namespace gearhb
