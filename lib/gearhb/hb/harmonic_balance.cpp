#include "gearhb/hb/harmonic_balance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include <unsupported/Eigen/IterativeSolvers>

namespace gearhb {

HarmonicBalance::HarmonicBalance(LinearSystem sys, std::vector<UnilateralContact> contacts,
                                 Excitation f, int H, int N, ContactQuadrature quadrature)
    : sys_(std::move(sys)), contacts_(std::move(contacts)), f_(std::move(f)),
      n_(sys_.dofs()), H_(H), aft_(H, N), quad_(quadrature) {
  sys_.check();
  if (H < 1) throw std::invalid_argument("HarmonicBalance: H must be >= 1");
  auto vec = [&](Eigen::VectorXd& v, const char* name) {
    if (v.size() == 0) v = Eigen::VectorXd::Zero(n_);
    if (v.size() != n_) throw std::invalid_argument(std::string("HarmonicBalance: ") + name + " has wrong size");
  };
  vec(f_.f0, "f0");
  vec(f_.fc, "fc");
  vec(f_.fs, "fs");
  if (f_.harmonic < 1 || f_.harmonic > H)
    throw std::invalid_argument("HarmonicBalance: the forcing harmonic must lie in 1..H");
  if (contacts_.size() > std::size_t(kMaxContacts))
    throw std::invalid_argument("HarmonicBalance: " + std::to_string(contacts_.size()) + " contacts; at most " +
                                std::to_string(kMaxContacts));
  for (auto& c : contacts_) {
    if (c.normal.size() != n_) throw std::invalid_argument("HarmonicBalance: contact normal has wrong size");
    if (!(c.kc >= 0.0)) throw std::invalid_argument("HarmonicBalance: contact stiffness must be >= 0");
    if (c.gap_harmonics.size() == 0) c.gap_harmonics = Eigen::VectorXd::Zero(2 * H_ + 1);
    if (c.gap_harmonics.size() < 2 * H_ + 1) {
      // A shorter gap series is padded with zeros (its higher harmonics vanish).
      Eigen::VectorXd g = Eigen::VectorXd::Zero(2 * H_ + 1);
      g.head(c.gap_harmonics.size()) = c.gap_harmonics;
      c.gap_harmonics = g;
    }
    if (c.gap_harmonics.size() > 2 * H_ + 1)
      c.gap_harmonics.conservativeResize(2 * H_ + 1);   // truncated to the H retained
    // Mean stiffness over the period (trapezoid rule on 1024 phases, spectrally
    // accurate for a smooth periodic profile); the profile must stay positive.
    double mean = c.kc;
    if (c.stiffness_profile) {
      const int S = 1024;
      double sum = 0.0;
      for (int j = 0; j < S; ++j) {
        const double s = c.stiffness_profile(2.0 * M_PI * j / S);
        if (!(s > 0.0) || !std::isfinite(s))
          throw std::invalid_argument("HarmonicBalance: contact stiffness profile must be finite and > 0");
        sum += s;
      }
      mean = c.kc * sum / S;
    }
    kc_mean_.push_back(mean);
  }
  const int N_ = aft_.samples(), m = 2 * H_ + 1;
  uc_.resize(m); us_.resize(N_); fs_.resize(N_); ss_.resize(N_); fcoef_.resize(m);
  G_.resize(m, m);
  mc_.resize(2 * m); ms_.resize(2 * m);
}

void HarmonicBalance::linear_terms(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                                   Eigen::VectorXd* dRdomega) const {
  // X and R as n x (2H+1) matrices, one column per coefficient
  const int n = n_, m = 2 * H_ + 1;
  R.resize(size());
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), n, m);
  Eigen::Map<Eigen::MatrixXd> Rm(R.data(), n, m);
  const Eigen::MatrixXd KX = sys_.K * Xm, MX = sys_.M * Xm, CX = sys_.C * Xm;
  Rm.col(0) = KX.col(0) - f_.f0;
  for (int k = 1; k <= H_; ++k) {
    const double kw = k * omega;
    const int c = 2 * k - 1, s = 2 * k;
    Rm.col(c) = KX.col(c) - kw * kw * MX.col(c) + kw * CX.col(s);
    Rm.col(s) = KX.col(s) - kw * kw * MX.col(s) - kw * CX.col(c);
  }
  Rm.col(2 * f_.harmonic - 1) -= f_.fc;
  Rm.col(2 * f_.harmonic) -= f_.fs;
  if (dRdomega) {
    dRdomega->setZero(size());
    Eigen::Map<Eigen::MatrixXd> Dm(dRdomega->data(), n, m);
    for (int k = 1; k <= H_; ++k) {
      const int c = 2 * k - 1, s = 2 * k;
      Dm.col(c) = -2.0 * k * k * omega * MX.col(c) + k * CX.col(s);
      Dm.col(s) = -2.0 * k * k * omega * MX.col(s) - k * CX.col(c);
    }
  }
}

Eigen::MatrixXd HarmonicBalance::harmonic_block(int k, double omega) const {
  if (k == 0) return sys_.K;
  const int n = n_;
  const double kw = k * omega;
  Eigen::MatrixXd B(2 * n, 2 * n);
  const Eigen::MatrixXd D = sys_.K - kw * kw * sys_.M;
  B << D, kw * sys_.C, -kw * sys_.C, D;
  return B;
}

void HarmonicBalance::contact_terms(const Eigen::VectorXd& X, Eigen::VectorXd& R, bool jacobian,
                                    std::vector<Eigen::MatrixXd>* G, double gap_scale, Eigen::VectorXd* dRdscale) const {
  const int n = n_, m = 2 * H_ + 1, N = aft_.samples();
  jacobian = jacobian || dRdscale;
  for (const auto& ct : contacts_) {
    // the contact's product matrix: made in place where G takes it (a copy of m x m per contact
    // and linearization was 3 % of ex. 03's period-2 branch), else in the scratch G_
    Eigen::MatrixXd& Gk = G ? G->emplace_back(m, m) : G_;
    // u(theta) = g(theta) + n' x(theta): coefficients, then samples.
    for (int a = 0; a < m; ++a) uc_[a] = ct.normal.dot(X.segment(a * n, n)) + gap_scale * ct.gap_harmonics[a];
    uc_[0] += ct.gap;
    aft_.to_time(uc_.data(), us_.data());
    if (quad_ == ContactQuadrature::exact) {
      // the moments of the indicator of the contact intervals, weighted by the
      // stiffness profile if any (pieces of at most one sample spacing)
      if (ct.stiffness_profile)
        weighted_indicator_moments(gearhb::contact_intervals(uc_, us_), ct.stiffness_profile, 2 * H_, 2.0 * M_PI / N,
                                   mc_.data(), ms_.data());
      else
        indicator_moments(gearhb::contact_intervals(uc_, us_), 2 * H_, mc_.data(), ms_.data());
      aft_.product_matrix_from_moments(mc_.data(), ms_.data(), Gk);
      Gk *= ct.kc;
      fcoef_.noalias() = Gk * uc_;
    } else {
      for (int j = 0; j < N; ++j) {
        const double k = stiffness_at(ct, 2.0 * M_PI * j / N);
        fs_[j] = contact_force(k, us_[j]);
        ss_[j] = contact_stiffness(k, us_[j]);
      }
      aft_.to_frequency(fs_.data(), fcoef_.data());
      if (jacobian) aft_.product_matrix(ss_.data(), Gk);
    }
    for (int a = 0; a < m; ++a) R.segment(a * n, n) += fcoef_[a] * ct.normal;
    if (dRdscale) {   // dF/dscale = G g_h (exact: the boundary terms vanish, u = 0 there)
      const Eigen::VectorXd dF = Gk * ct.gap_harmonics;
      for (int a = 0; a < m; ++a) dRdscale->segment(a * n, n) += dF[a] * ct.normal;
    }
  }
}

bool HarmonicBalance::gaps_vary() const {
  for (const auto& ct : contacts_)
    if (ct.gap_harmonics.size() > 0 && ct.gap_harmonics.cwiseAbs().maxCoeff() > 0.0) return true;
  return false;
}

void HarmonicBalance::evaluate_gap_scaled(const Eigen::VectorXd& X, double omega, double lambda, Eigen::VectorXd& R,
                                          Eigen::MatrixXd* J, Eigen::VectorXd* dRdlambda) const {
  linear_terms(X, omega, R, nullptr);
  std::vector<Eigen::MatrixXd> G;
  if (dRdlambda) dRdlambda->setZero(size());
  contact_terms(X, R, J != nullptr, J ? &G : nullptr, lambda, dRdlambda);
  if (J) *J = assemble_jacobian(omega, G);
}

Eigen::MatrixXd HarmonicBalance::assemble_jacobian(double omega, const std::vector<Eigen::MatrixXd>& G) const {
  std::vector<int> every(std::size_t(2 * H_ + 1));
  for (std::size_t a = 0; a < every.size(); ++a) every[a] = int(a);
  return assemble_block(omega, G, every);
}

Eigen::MatrixXd HarmonicBalance::assemble_block(double omega, const std::vector<Eigen::MatrixXd>& G,
                                                const std::vector<int>& basis) const {
  const int n = n_;
  std::vector<Eigen::MatrixXd> blocks(std::size_t(H_) + 1);   // the harmonic blocks used, built once
  const Eigen::Index nb = Eigen::Index(basis.size());
  Eigen::MatrixXd Jb = Eigen::MatrixXd::Zero(nb * n, nb * n);
  auto local = [n](int c) { return c == 0 || c % 2 == 1 ? 0 : n; };   // cos (or static) rows first, then sin
  // the linear block of each harmonic, then each contact's G (x) n n'
  for (Eigen::Index i = 0; i < nb; ++i)
    for (Eigen::Index j = 0; j < nb; ++j) {
      const int a = basis[std::size_t(i)], b = basis[std::size_t(j)], k = (a + 1) / 2;
      if ((b + 1) / 2 != k) continue;
      if (blocks[std::size_t(k)].size() == 0) blocks[std::size_t(k)] = harmonic_block(k, omega);
      Jb.block(i * n, j * n, n, n) = blocks[std::size_t(k)].block(local(a), local(b), n, n);
    }
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const Eigen::MatrixXd nn = contacts_[c].normal * contacts_[c].normal.transpose();
    for (Eigen::Index i = 0; i < nb; ++i)
      for (Eigen::Index j = 0; j < nb; ++j) {
        const double g = G[c](basis[std::size_t(i)], basis[std::size_t(j)]);
        if (g != 0.0) Jb.block(i * n, j * n, n, n) += g * nn;
      }
  }
  return Jb;
}

Eigen::MatrixXd HarmonicBalance::jacobian_block(const Eigen::VectorXd& X, double omega, const std::vector<int>& basis) const {
  Eigen::VectorXd R = Eigen::VectorXd::Zero(size());
  std::vector<Eigen::MatrixXd> G;
  contact_terms(X, R, true, &G);
  return assemble_block(omega, G, basis);
}

void HarmonicBalance::evaluate(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                               Eigen::MatrixXd* J, Eigen::VectorXd* dRdomega) const {
  linear_terms(X, omega, R, dRdomega);
  std::vector<Eigen::MatrixXd> G;
  contact_terms(X, R, J != nullptr, J ? &G : nullptr);
  if (J) *J = assemble_jacobian(omega, G);
}

namespace {

// The LU of a condensed bordered matrix (rows equilibrated by row_scale) for one border row, and
// the contacts it condensed on (a linearization with another active set cannot use it).
struct ReducedFactor {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd row_scale, row;
  std::vector<int> active;
};

// A ReducedFactor as Eigen's iterative solvers take a preconditioner: solve(b) = A_f^-1 b.
struct FactorPreconditioner {
  const ReducedFactor* f = nullptr;
  template <typename M> FactorPreconditioner& analyzePattern(const M&) { return *this; }
  template <typename M> FactorPreconditioner& factorize(const M&) { return *this; }
  template <typename M> FactorPreconditioner& compute(const M&) { return *this; }
  template <typename V> Eigen::VectorXd solve(const V& b) const { return f->lu.solve(b.cwiseQuotient(f->row_scale)); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }
};

// GMRES on a condensed system preconditioned by an earlier factorization: at most this many
// iterations (each a product with the matrix and a solve with the factors, about 2 (mP + 1)^2
// flops against the LU's 2/3 (mP + 1)^3), to this relative residual (of the preconditioned system).
constexpr Eigen::Index kGmresIterations = 12;
constexpr double kGmresTolerance = 1e-14;

// The bordered system of continuation with the HB Jacobian J = L + U Gc U'
// (harmonic_balance.hpp): L block diagonal over the harmonics (the linear
// dynamic stiffness), U = [I (x) n_1, ..., I (x) n_P] the contact normals on
// every coefficient, Gc = diag(G_1, ..., G_P) the contacts' product matrices.
// Condensation on the contact coordinates v = U' dx: with Z = L^-1 (.),
//   [ I + S Gc        U' Z_b    ] [ v ]   [ U' Z_f    ]      S = U' L^-1 U,
//   [ -c' W Gc     d - c' Z_b   ] [dw ] = [ g - c' Z_f ],    W = L^-1 U,
// then dx = Z_f - Z_b dw - W Gc v. The reduced matrix has mP + 1 rows (m = 2H+1
// coefficients, P contacts) instead of n m + 1, and det(bordered) = det(L)
// det(reduced): it is singular exactly where the full system is (folds are
// handled by the border as before). Used when L is well conditioned; the result
// is checked by its residual on the full system. Contacts open over the whole period
// (G_i = 0) drop out: P counts the others only. Given the factorization of a linearization
// before (reuse: the iterate before in a corrector, the trial before on a chord), a solve runs
// GMRES preconditioned by it first and factors only where that fails (ex. 03's period-2
// switch and branch at H = 40: 87 % of the solves by GMRES, 7 iterations on average; the
// branch's instructions -27 %, callgrind).
class CondensedLinearization : public Linearization {
 public:
  // blocks: L's diagonal blocks (harmonic 0: n x n, k >= 1: 2n x 2n, [cos; sin]);
  // normals: n x P; G: the P product matrices (m x m).
  CondensedLinearization(std::vector<Eigen::MatrixXd> blocks, std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu,
                         Eigen::MatrixXd normals, std::shared_ptr<const std::vector<Eigen::MatrixXd>> G,
                         Eigen::VectorXd dRdomega, const Scaling& s)
      : L_(std::move(blocks)), lu_(std::move(lu)), normals_(std::move(normals)), Gp_(std::move(G)), G_(*Gp_),
        b_(std::move(dRdomega)), s_(s), m_(2 * int(L_.size()) - 1) {
    const int n = int(normals_.rows()), P = int(normals_.cols()), m = m_;
    for (std::size_t k = 0; k < L_.size(); ++k) offset_.push_back(k == 0 ? 0 : n * (2 * int(k) - 1));
    // Only the contacts whose product matrix is not zero (in contact somewhere in the
    // period) enter: an open contact's G_i = 0 removes its v_i from every equation but its
    // own, and dx does not depend on it (Gc v), so its rows and columns are dropped.
    for (int i = 0; i < P; ++i)
      if (G_[std::size_t(i)].cwiseAbs().maxCoeff() > 0.0) active_.push_back(i);
    // the contact coordinates q = (active contact j, basis a) and W's columns w_q = L_k^-1 (n_i at basis a)
    for (std::size_t j = 0; j < active_.size(); ++j)
      for (int a = 0; a < m; ++a) {
        const int k = (a + 1) / 2, local = (a == 0 || a % 2 == 1) ? 0 : n;
        Eigen::VectorXd e = Eigen::VectorXd::Zero(L_[k].rows());
        e.segment(local, n) = normals_.col(active_[j]);
        coords_.push_back({active_[j], int(j), a, k, local});
        w_.push_back(lu_[k].solve(e));
      }
    Zb_ = solve_L(b_);
    UZb_ = project(Zb_);
    // I + S Gc, S(q1, q2) = n_i1' (w_q2 at basis a1): nonzero for q1, q2 of one harmonic
    const int q = int(coords_.size());
    std::vector<std::vector<int>> in_block(L_.size());
    for (int q2 = 0; q2 < q; ++q2) in_block[std::size_t(coords_[q2].block)].push_back(q2);
    SG_ = RowMatrix::Identity(q, q);
    for (int q1 = 0; q1 < q; ++q1)
      for (const int q2 : in_block[std::size_t(coords_[q1].block)]) {
        const Coord &c1 = coords_[q1], &c2 = coords_[q2];
        const double S = normals_.col(c1.contact).dot(w_[q2].segment(c1.local, n));
        add_row(SG_.row(q1).segment(c2.slot * m, m), S, G_[std::size_t(c2.contact)], c2.basis);
      }
  }

  bool solve_bordered(const Eigen::VectorXd& row, const Eigen::VectorXd& rhs, Eigen::VectorXd& dy) const override {
    const Eigen::Index N = b_.size(), q = Eigen::Index(coords_.size());
    const Eigen::VectorXd f = rhs.head(N) * s_.residual;
    const Eigen::VectorXd c = row.head(N).cwiseQuotient(s_.x);
    const double d = row[N] / s_.omega, g = rhs[N];
    const Eigen::VectorXd Zf = solve_L(f);
    Eigen::VectorXd r(q + 1);
    r.head(q) = project(Zf);
    r[q] = g - c.dot(Zf);
    Eigen::VectorXd vw;
    if (!factored_for(row) && iterate(c, d, r, vw) && expand(f, c, d, g, Zf, vw, dy)) return true;
    if (!factored_for(row)) factor(row, c, d);
    vw = own_->lu.solve(r.cwiseQuotient(own_->row_scale));
    return expand(f, c, d, g, Zf, vw, dy);
  }

  // The factorization of the reduced system kept for the linearizations after this one: its
  // own if it made one, else the one it was given (reuse).
  std::shared_ptr<const ReducedFactor> factorization() const { return own_ ? own_ : given_; }
  void reuse(const CondensedLinearization& before) {
    auto f = before.factorization();
    if (f && f->active == active_ && f->lu.rows() == Eigen::Index(coords_.size()) + 1) given_ = std::move(f);
  }

 private:
  struct Coord { int contact, slot, basis, block, local; };   // slot: the contact's place in active_
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<Eigen::MatrixXd> L_;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu_;
  std::vector<int> offset_;     // first unknown of each block
  Eigen::MatrixXd normals_;
  std::shared_ptr<const std::vector<Eigen::MatrixXd>> Gp_;   // shared with the dense fallback
  const std::vector<Eigen::MatrixXd>& G_;
  Eigen::VectorXd b_, Zb_, UZb_;
  Scaling s_;
  int m_;                       // 2H+1 coefficients per coordinate
  std::vector<int> active_;     // the contacts with G_i != 0
  std::vector<Coord> coords_;
  std::vector<Eigen::VectorXd> w_;
  RowMatrix SG_;
  // The condensed bordered matrix for one bordered row (c, d: the row unscaled), each row
  // equilibrated for the pivoting (row_scale), and its LU, kept for the next solve with the
  // same row (own_); or one of a linearization before, given to precondition (given_).
  mutable std::shared_ptr<const ReducedFactor> own_;
  std::shared_ptr<const ReducedFactor> given_;
  // dst += coef G.row(a), read from G's column a (one contiguous run of memory; a row of the
  // column-major G strides across it): a product matrix (Aft::product_matrix_from_moments) is
  // symmetric but in its first row and column, G(a, 0) = 2 G(0, a) (the mean's coefficient is half
  // a cosine's), so row a >= 1 is column a with its first entry G(a, 0), and row 0 is column 0
  // halved but G(0, 0); halving is exact in binary, so these are the same numbers as G.row(a),
  // bit for bit (tests: ProductMatrixRowsFromColumns). Before, the rows came from a row-major copy
  // of every G per linearization: 2 % of ex. 03's period-2 branch.
  template <typename Row>
  static void add_row(Row&& dst, double coef, const Eigen::MatrixXd& g, int a) {
    const Eigen::Index m = g.rows();
    if (a == 0) {
      dst[0] += coef * g(0, 0);
      dst.tail(m - 1) += coef * (0.5 * g.col(0).tail(m - 1)).transpose();
    } else {
      dst[0] += coef * g(a, 0);
      dst.tail(m - 1) += coef * g.col(a).tail(m - 1).transpose();
    }
  }
  bool factored_for(const Eigen::VectorXd& row) const {
    return own_ && row.size() == own_->row.size() && row == own_->row;
  }
  RowMatrix bordered(const Eigen::VectorXd& c, double d) const {
    const Eigen::Index q = Eigen::Index(coords_.size());
    const int m = m_;
    RowMatrix A(q + 1, q + 1);
    A.topLeftCorner(q, q) = SG_;
    A.topRightCorner(q, 1) = UZb_;
    A.row(q).setZero();
    for (Eigen::Index j = 0; j < q; ++j) {   // -c' W Gc
      const Coord& cj = coords_[j];
      const double wc = w_[j].dot(c.segment(offset_[cj.block], w_[j].size()));
      add_row(A.row(q).segment(cj.slot * m, m), -wc, G_[std::size_t(cj.contact)], cj.basis);
    }
    A(q, q) = d - c.dot(Zb_);
    return A;
  }
  void factor(const Eigen::VectorXd& row, const Eigen::VectorXd& c, double d) const {
    RowMatrix A = bordered(c, d);
    auto f = std::make_shared<ReducedFactor>();
    f->row_scale = Eigen::VectorXd::Ones(A.rows());
    for (Eigen::Index i = 0; i < A.rows(); ++i) {   // row equilibration for the pivoting
      const double omega = A.row(i).cwiseAbs().maxCoeff();
      if (omega > 0.0) A.row(i) /= omega, f->row_scale[i] = omega;
    }
    f->lu.compute(Eigen::MatrixXd(A));
    f->row = row;
    f->active = active_;
    own_ = std::move(f);
  }
  // The reduced system solved by GMRES (Eigen's unsupported IterativeSolvers: Householder
  // GMRES, Walker 1988) preconditioned by the factorization of a linearization before (or of
  // this one for another row): the same matrix up to the step between them, so a few
  // iterations replace an LU. False where there is none or GMRES does not reach
  // kGmresTolerance in kGmresIterations (then the caller factors).
  bool iterate(const Eigen::VectorXd& c, double d, const Eigen::VectorXd& r, Eigen::VectorXd& vw) const {
    const std::shared_ptr<const ReducedFactor> pre = own_ ? own_ : given_;
    if (!pre) return false;
    const RowMatrix A = bordered(c, d);
    Eigen::GMRES<RowMatrix, FactorPreconditioner> gmres;
    gmres.preconditioner().f = pre.get();
    gmres.setMaxIterations(kGmresIterations);
    gmres.set_restart(int(kGmresIterations));
    gmres.setTolerance(kGmresTolerance);
    gmres.compute(A);
    vw = gmres.solve(r);
    return gmres.info() == Eigen::Success && vw.allFinite();
  }
  // dx from the reduced solution vw = (v, dw), checked by its backward error on the full
  // bordered system, as a dense LU would have it; dy scaled.
  bool expand(const Eigen::VectorXd& f, const Eigen::VectorXd& c, double d, double g, const Eigen::VectorXd& Zf,
              const Eigen::VectorXd& vw, Eigen::VectorXd& dy) const {
    const Eigen::Index N = b_.size(), q = Eigen::Index(coords_.size());
    if (!vw.allFinite()) return false;
    const double dw = vw[q];
    Eigen::VectorXd dx = Zf - Zb_ * dw;
    const Eigen::VectorXd Gv = times_G(vw.head(q));
    for (Eigen::Index j = 0; j < q; ++j) dx.segment(offset_[coords_[j].block], w_[j].size()) -= Gv[j] * w_[j];
    const Eigen::VectorXd Ldx = times_L(dx), Gu = times_G(project(dx));
    Eigen::VectorXd res = Ldx + b_ * dw - f;
    for (Eigen::Index j = 0; j < q; ++j) {
      const Coord& cj = coords_[j];
      res.segment(offset_[cj.block] + cj.local, normals_.rows()) += Gu[j] * normals_.col(cj.contact);
    }
    const double scale = f.cwiseAbs().maxCoeff() + Ldx.cwiseAbs().maxCoeff() + std::fabs(dw) * b_.cwiseAbs().maxCoeff();
    const double last = std::fabs(c.dot(dx) + d * dw - g);
    if (!(res.cwiseAbs().maxCoeff() <= 1e-10 * scale) ||
        !(last <= 1e-10 * (std::fabs(g) + c.cwiseAbs().dot(dx.cwiseAbs()) + std::fabs(d * dw))))
      return false;
    dy.resize(N + 1);
    dy.head(N) = dx.cwiseQuotient(s_.x);
    dy[N] = dw / s_.omega;
    return true;
  }
  Eigen::VectorXd solve_L(const Eigen::VectorXd& v) const {
    Eigen::VectorXd out(v.size());
    for (std::size_t k = 0; k < L_.size(); ++k) out.segment(offset_[k], L_[k].rows()) = lu_[k].solve(v.segment(offset_[k], L_[k].rows()));
    return out;
  }
  Eigen::VectorXd times_L(const Eigen::VectorXd& v) const {
    Eigen::VectorXd out(v.size());
    for (std::size_t k = 0; k < L_.size(); ++k) out.segment(offset_[k], L_[k].rows()) = L_[k] * v.segment(offset_[k], L_[k].rows());
    return out;
  }
  Eigen::VectorXd project(const Eigen::VectorXd& x) const {   // U' x
    Eigen::VectorXd u(coords_.size());
    for (std::size_t j = 0; j < coords_.size(); ++j)
      u[j] = normals_.col(coords_[j].contact).dot(x.segment(offset_[coords_[j].block] + coords_[j].local, normals_.rows()));
    return u;
  }
  Eigen::VectorXd times_G(const Eigen::VectorXd& v) const {   // Gc v over the active contacts
    const Eigen::Index m = m_;
    Eigen::VectorXd out(v.size());
    for (std::size_t j = 0; j < active_.size(); ++j)
      out.segment(Eigen::Index(j) * m, m) = G_[std::size_t(active_[j])] * v.segment(Eigen::Index(j) * m, m);
    return out;
  }
};

// A solver that tries the condensed system first and falls back to the dense one
// (assembled on demand) where the condensed residual check fails.
class HbLinearization : public Linearization {
 public:
  HbLinearization(std::unique_ptr<CondensedLinearization> condensed, std::function<Eigen::MatrixXd()> dense_J,
                  Eigen::VectorXd dRdomega, const Scaling& s)
      : condensed_(std::move(condensed)), dense_J_(std::move(dense_J)), dRdomega_(std::move(dRdomega)), s_(s) {}
  bool solve_bordered(const Eigen::VectorXd& row, const Eigen::VectorXd& rhs, Eigen::VectorXd& dy) const override {
    structured_ = condensed_ && condensed_->solve_bordered(row, rhs, dy);
    if (structured_) return true;
    if (!dense_) dense_ = std::make_unique<DenseLinearization>(dense_J_(), dRdomega_, s_);
    return dense_->solve_bordered(row, rhs, dy);
  }
  bool last_solve_structured() const override { return structured_; }
  void reuse(const Linearization& before) override {
    const auto* b = dynamic_cast<const HbLinearization*>(&before);
    if (b && b->condensed_ && condensed_) condensed_->reuse(*b->condensed_);
  }

 private:
  std::unique_ptr<CondensedLinearization> condensed_;
  std::function<Eigen::MatrixXd()> dense_J_;
  Eigen::VectorXd dRdomega_;
  Scaling s_;
  mutable std::unique_ptr<DenseLinearization> dense_;
  mutable bool structured_ = false;
};

}  // namespace

std::unique_ptr<Linearization> HarmonicBalance::linearize(const Eigen::VectorXd& X, double omega, const Scaling& s,
                                                          Eigen::VectorXd& R, Eigen::VectorXd& dRdomega) const {
  linear_terms(X, omega, R, &dRdomega);
  std::vector<Eigen::MatrixXd> G;
  contact_terms(X, R, true, &G);
  const int n = n_, m = 2 * H_ + 1, P = int(contacts_.size());
  // G as it is now, shared with the condensed system (which takes a copy only where it moves the
  // mean stiffness below)
  const auto Gs = std::make_shared<const std::vector<Eigen::MatrixXd>>(std::move(G));
  auto dense = [this, omega, Gs]() { return assemble_jacobian(omega, *Gs); };
  if (P * m >= size()) return std::make_unique<DenseLinearization>(dense(), dRdomega, s);   // nothing to condense
  std::shared_ptr<const std::vector<Eigen::MatrixXd>> Gc = Gs;
  auto singular = [](const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
    const Eigen::VectorXd d = lu.matrixLU().diagonal().cwiseAbs();
    return !(d.minCoeff() > 1e-13 * d.maxCoeff());
  };
  std::vector<Eigen::MatrixXd> blocks;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> factors;
  for (int k = 0; k <= H_; ++k) {
    blocks.push_back(harmonic_block(k, omega));
    factors.emplace_back(blocks.back());
    if (k == 0 && singular(factors.back())) {
      // K singular: a free rigid-body mode that the contacts hold (the transmission error of
      // a gear pair on bearings has no stiffness but the mesh). J = L + U Gc U' equals
      // (L + U D U') + U (Gc - D) U' for any D; D = each contact's mean stiffness on the static
      // coefficient moves sum_i kc_i n_i n_i' from G_i(0, 0) into the static block, exactly.
      auto moved = std::make_shared<std::vector<Eigen::MatrixXd>>(*Gs);
      for (int i = 0; i < P; ++i) {
        blocks[0] += kc_mean_[std::size_t(i)] * contacts_[std::size_t(i)].normal * contacts_[std::size_t(i)].normal.transpose();
        (*moved)[std::size_t(i)](0, 0) -= kc_mean_[std::size_t(i)];
      }
      Gc = moved;
      factors.back().compute(blocks[0]);
    }
    // L still singular (a free mode no contact holds, an undamped resonance of the open
    // system at k omega): the dense system only. Near-singular blocks are caught by the
    // condensed solve's residual check.
    if (singular(factors.back())) return std::make_unique<DenseLinearization>(dense(), dRdomega, s);
  }
  Eigen::MatrixXd normals(n, P);
  for (int i = 0; i < P; ++i) normals.col(i) = contacts_[i].normal;
  return std::make_unique<HbLinearization>(
      std::make_unique<CondensedLinearization>(std::move(blocks), std::move(factors), std::move(normals), Gc, dRdomega, s),
      dense,
      dRdomega, s);
}

Eigen::VectorXd HarmonicBalance::project(const Eigen::VectorXd& X, const Eigen::VectorXd& q) const {
  Eigen::VectorXd c(2 * H_ + 1);
  for (int a = 0; a < 2 * H_ + 1; ++a) c[a] = q.dot(X.segment(a * n_, n_));
  return c;
}

Eigen::VectorXd HarmonicBalance::penetration(const Eigen::VectorXd& X, std::size_t i) const {
  const auto& ct = contacts_.at(i);
  Eigen::VectorXd u = project(X, ct.normal) + ct.gap_harmonics;
  u[0] += ct.gap;
  return u;
}

std::vector<std::pair<double, double>> HarmonicBalance::contact_intervals(const Eigen::VectorXd& X,
                                                                          std::size_t i) const {
  const Eigen::VectorXd u = penetration(X, i);
  return gearhb::contact_intervals(u, aft_.to_time(u));
}

Eigen::VectorXd HarmonicBalance::linear_solution(double omega, bool closed) const {
  return contact_set_solution(omega, closed ? ~0ull : 0ull);
}

Eigen::VectorXd HarmonicBalance::contact_set_solution(double omega, unsigned long long closed) const {
  Eigen::MatrixXd K = sys_.K;
  Eigen::VectorXd f0 = f_.f0;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    if (i >= 64 || !(closed >> i & 1ull)) continue;
    const auto& ct = contacts_[i];
    // a stiffness profile enters with its mean (then this is a first guess only)
    K += kc_mean_[i] * ct.normal * ct.normal.transpose();
    f0 -= kc_mean_[i] * ct.gap * ct.normal;   // constant part of kc (g + n'x) moved to the right
  }
  Eigen::VectorXd X = Eigen::VectorXd::Zero(size());
  // K singular (a free rigid-body mode, e.g. gears with rigid shafts and the mesh
  // open) under a static load that K cannot hold: no static equilibrium, the
  // static part is NaN (linear_first_guess then skips this solution).
  Eigen::VectorXd X0 = K.partialPivLu().solve(f0);
  if (!X0.allFinite() || (K * X0 - f0).norm() > 1e-8 * f0.norm()) X0.setConstant(NAN);
  X.segment(0, n_) = X0;
  LinearSystem s{sys_.M, sys_.C, K};
  const std::complex<double> i(0.0, 1.0);
  // fc cos + fs sin = Re((fc - i fs) e^{i theta})
  const Eigen::VectorXcd F = f_.fc.cast<std::complex<double>>() - i * f_.fs.cast<std::complex<double>>();
  const int p = f_.harmonic;
  const Eigen::VectorXcd Z = frequency_response(s, F, p * omega);
  X.segment(index(2 * p - 1, 0), n_) = Z.real();
  X.segment(index(2 * p, 0), n_) = -Z.imag();
  return X;
}

Eigen::VectorXd HarmonicBalance::open_contact_solution(double omega) const { return linear_solution(omega, false); }
Eigen::VectorXd HarmonicBalance::closed_contact_solution(double omega) const { return linear_solution(omega, true); }

Scaling HarmonicBalance::scaling(double wmin, double wmax) const {
  // The oscillating part of a gap (a transmission error) forces the system as a
  // displacement does; a constant gap, like a static offset, only counts when
  // nothing oscillates.
  double xref = 0.0, xstatic = 0.0;
  for (const auto& ct : contacts_) {
    const double wn = ct.normal.lpNorm<Eigen::Infinity>();
    if (wn > 0) {
      xref = std::max(xref, ct.gap_harmonics.cwiseAbs().sum() / wn);
      xstatic = std::max(xstatic, std::fabs(ct.gap) / wn);
    }
  }
  // Linear response amplitudes (open and closed) over a fine scan of the range.
  // Only the oscillating part sets the scale: the solvers see differences of X
  // (arc length, Newton steps), and along a frequency sweep the static offset
  // changes by no more than the oscillation does. A large static offset (a gear
  // pair under torque: 1e-2 rad of twist beside 1e-5 of vibration) must not
  // swamp the resonance peaks in the arc length.
  const int scan = 400;
  for (int i = 0; i <= scan; ++i) {
    const double omega = wmin + (wmax - wmin) * i / scan;
    for (bool closed : {false, true}) {
      if (closed && contacts_.empty()) continue;
      const Eigen::VectorXd X = linear_solution(omega, closed);
      for (int d = 0; d < n_; ++d) {
        const double a = std::hypot(X[index(2 * f_.harmonic - 1, d)], X[index(2 * f_.harmonic, d)]);
        if (std::isfinite(a)) xref = std::max(xref, a);
        if (std::isfinite(X[d])) xstatic = std::max(xstatic, std::fabs(X[d]));   // NaN: no static equilibrium
      }
    }
  }
  if (!(xref > 0.0)) xref = xstatic;  // no oscillating input: the static size
  if (!(xref > 0.0)) xref = 1.0;      // nothing forces the system: any unit will do
  double kref = sys_.K.diagonal().cwiseAbs().maxCoeff();
  for (std::size_t i = 0; i < contacts_.size(); ++i) kref += kc_mean_[i] * contacts_[i].normal.squaredNorm();
  Scaling s;
  s.x = Eigen::VectorXd::Constant(size(), xref);
  s.omega = std::max(std::fabs(wmax), std::fabs(wmin));
  s.residual = kref * xref;
  return s;
}

}  // namespace gearhb
