#pragma once
// Harmonic balance with unilateral contacts (thesis ch. 2; lib/README.md "The method in one page").
//
// Equation of motion, n DOFs, forcing at frequency omega (theta = omega t):
//
//   M x'' + C x' + K x + sum_i n_i max(kc_i (g_i(theta) + n_i' x), 0)
//        = f0 + fc cos(theta) + fs sin(theta)
//
// Unknowns: the real Fourier coefficients of x, static term kept (the thesis
// drops it in ch. 3-4, which is wrong as soon as the contact force has a mean),
// stored harmonic-major:  X = [X_0 (n), X_c1 (n), X_s1 (n), ..., X_cH (n), X_sH (n)].
//
// Residual (Galerkin projection on cos(k theta), sin(k theta), k = 0..H):
//   k = 0:  K X_0                              + Fnl_0  - f0
//   k >= 1: (K - (k omega)^2 M) X_ck + k omega C X_sk  + Fnl_ck - fc [k = 1]
//           (K - (k omega)^2 M) X_sk - k omega C X_ck  + Fnl_sk - fs [k = 1]
// (thesis §2.2: D(n) = -(n omega)^2 M + i n omega C + K; the thesis prints -(n omega^2) M.)
//
// The contact forces Fnl come from AFT (thesis §2.3): for each contact, the
// coefficients of u = g + n'x (n = UnilateralContact::normal) go to N time samples (FFTW), then either
//  - sampled (the classic AFT): the law is applied sample by sample and the
//    samples go back to coefficients; Jacobian dFnl/dX = sum_i (n_i n_i') (x) G(s_i),
//    G the AFT product matrix of the sampled stiffness s_i = kc_i [u_i > 0]
//    (kc_i(theta_j) for a contact with a stiffness profile);
//  - exact (default): the samples only bracket the contact crossings, which are
//    refined on the trigonometric polynomial, and the projection of the
//    piecewise-linear law is integrated in closed form (contact.hpp). Same
//    Jacobian structure with G the product matrix of the contact indicator.
//    With a time-varying stiffness kc s(theta) (contact.hpp), G is the product
//    matrix of s times the indicator, its moments integrated by Gauss-Legendre
//    quadrature between the exact crossings (weighted_indicator_moments).
// Both Jacobians are exact for their residual. Why exact is the default: the
// sampled residual is piecewise linear in X with a kink per sample crossing,
// which near folds creates spurious micro-folds (ch. 3 sample study).
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/contact.hpp"
#include "gearhb/core/fourier.hpp"
#include "gearhb/core/linear_dynamics.hpp"
#include "gearhb/core/newton.hpp"

namespace gearhb {

enum class ContactQuadrature { exact, sampled };

// External forcing f0 + fc cos(p theta) + fs sin(p theta), each an n-vector, on harmonic
// p = `harmonic` of the model's base frequency (theta = omega t). p = 1: the forcing
// frequency is the base frequency (every period-1 model). p = 2: the model of a period-2
// orbit (subharmonic.hpp): its base frequency is half the forcing frequency.
struct Excitation {
  Eigen::VectorXd f0, fc, fs;
  int harmonic = 1;
};

// Threads: a HarmonicBalance keeps work buffers (its own and its Aft's), so one object
// is evaluated by one thread at a time. Build one model per thread: construction is
// thread-safe (FFTW planning is serialised in core/fourier.cpp), and two threads with a
// model each give the same results bit for bit (test_threads.cpp).
class HarmonicBalance : public ParametricProblem {
 public:
  // N = 0: Aft::default_samples(H) = 4 (2H+1) time samples per period.
  HarmonicBalance(LinearSystem sys, std::vector<UnilateralContact> contacts, Excitation f, int H,
                  int N = 0, ContactQuadrature quadrature = ContactQuadrature::exact);
  ContactQuadrature quadrature() const { return quad_; }

  int size() const override { return (2 * H_ + 1) * n_; }
  int dofs() const { return n_; }
  int harmonics() const { return H_; }
  int samples() const { return aft_.samples(); }
  const LinearSystem& system() const { return sys_; }
  const std::vector<UnilateralContact>& contacts() const { return contacts_; }
  const Excitation& excitation() const { return f_; }

  void evaluate(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX,
                Eigen::VectorXd* dRdomega) const override;
  // The residual with the periodic parts of every gap (gap_harmonics) scaled by lambda, its
  // Jacobian in X and dR/dlambda: find_first_point's homotopy for a model forced through its
  // gaps (a gear mesh driven by its transmission error; first_point.hpp).
  void evaluate_gap_scaled(const Eigen::VectorXd& X, double omega, double lambda, Eigen::VectorXd& R,
                           Eigen::MatrixXd* dRdX, Eigen::VectorXd* dRdlambda) const;
  bool gaps_vary() const;   // some contact has a periodic gap
  // The rows and columns of dR/dX at (X, omega) that belong to the coefficients `basis` (0 static,
  // 2k-1 cos k, 2k sin k; every DOF of each, in the order of X), the same numbers as evaluate's
  // dense Jacobian there without assembling it (a period-2 model's odd block: period_doubling.cpp).
  Eigen::MatrixXd jacobian_block(const Eigen::VectorXd& X, double omega, const std::vector<int>& basis) const;
  // For continuation: with fewer contact coordinates than unknowns (P (2H+1) < n (2H+1),
  // i.e. n > P) the bordered systems are solved by condensation on the contact
  // coordinates (harmonic_balance.cpp, CondensedLinearization): an LU of size
  // P (2H+1) + 1 instead of n (2H+1) + 1, checked by its residual, with the dense
  // LU as the fallback; given the linearization before (Linearization::reuse), its solves run
  // GMRES preconditioned by that one's factorization first (an LU only where GMRES fails). A singular K (a free mode the contacts hold) takes the contacts'
  // mean stiffness into its static block (and out of their product matrices) first.
  std::unique_ptr<Linearization> linearize(const Eigen::VectorXd& X, double omega, const Scaling& s,
                                           Eigen::VectorXd& R, Eigen::VectorXd& dRdomega) const override;

  // Index of coefficient `basis` (0 static, 2k-1 cos k, 2k sin k) of DOF `dof` in X.
  int index(int basis, int dof) const { return basis * n_ + dof; }
  // Coefficients (2H+1) of the coordinate q' x (e.g. q = e_1, or e_1 - e_2).
  Eigen::VectorXd project(const Eigen::VectorXd& X, const Eigen::VectorXd& q) const;
  // Coefficients (2H+1) of the penetration u = g(theta) + n'x of contact i (contact where u > 0).
  Eigen::VectorXd penetration(const Eigen::VectorXd& X, std::size_t i) const;
  // The contact intervals of contact i on the orbit X (contact_intervals, its roots seeded on this
  // model's time samples, as the residual's): the model's FFT plans, where building an Aft per
  // call planned two FFTs each time (shooting_nodes: 2 % of ex. 03's period-2 branch).
  std::vector<std::pair<double, double>> contact_intervals(const Eigen::VectorXd& X, std::size_t i) const;

  // Solution with every contact removed (open contact): static + first harmonic,
  // exact for the linear system. A natural first guess for Newton. If K cannot
  // hold the static load (K singular: a free rigid-body mode) the static part is NaN.
  Eigen::VectorXd open_contact_solution(double omega) const;
  // The same with every contact permanently closed (springs kc_i n_i n_i' and
  // their constant preloads kc_i g_i added): exact while the contacts stay shut.
  // A contact with a stiffness profile (contact.hpp) enters with its mean
  // stiffness: then this is only a first guess.
  Eigen::VectorXd closed_contact_solution(double omega) const;
  // The same with the contacts of the set `closed` (bit i: contact i, i < 64) permanently
  // closed and the others removed: exact while that contact set holds over the whole
  // period. The open and closed solutions are the empty and the full set.
  Eigen::VectorXd contact_set_solution(double omega, unsigned long long closed) const;
  // Mean over the period of contact i's stiffness (kc, or kc times the mean profile).
  double mean_stiffness(std::size_t i) const { return kc_mean_[i]; }

  // Characteristic sizes, from the problem's own data over [omega_min, omega_max]:
  // displacement = the largest of the open- and closed-contact linear vibration
  // amplitudes (first harmonic, scanned over the range) and of the gaps'
  // oscillating parts (the static offset and constant gaps only if nothing
  // oscillates);
  // residual = (max diagonal of K + sum kc) x that.
  Scaling scaling(double omega_min, double omega_max) const;

 private:
  LinearSystem sys_;
  std::vector<UnilateralContact> contacts_;
  Excitation f_;
  int n_, H_;
  Aft aft_;
  ContactQuadrature quad_;
  std::vector<double> kc_mean_;   // per contact, mean stiffness over the period
  // Work buffers (evaluate is const but not re-entrant: one object per thread).
  mutable Eigen::VectorXd uc_, us_, fs_, ss_, fcoef_, mc_, ms_;
  mutable Eigen::MatrixXd G_;
  Eigen::VectorXd linear_solution(double omega, bool closed) const;
  // The pieces of evaluate: the linear terms of R (and dR/domega), the contact
  // forces added to R (and each contact's product matrix G, kc included), the
  // dynamic stiffness block of harmonic k, and J from those.
  void linear_terms(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R, Eigen::VectorXd* dRdomega) const;
  // The contacts' force coefficients added to R, their product matrices to G (if given);
  // the gaps' periodic parts scaled by gap_scale, and d(R)/d(gap_scale) added to dRdscale.
  void contact_terms(const Eigen::VectorXd& X, Eigen::VectorXd& R, bool jacobian, std::vector<Eigen::MatrixXd>* G,
                     double gap_scale = 1.0, Eigen::VectorXd* dRdscale = nullptr) const;
  Eigen::MatrixXd harmonic_block(int k, double omega) const;
  Eigen::MatrixXd assemble_jacobian(double omega, const std::vector<Eigen::MatrixXd>& G) const;
  // J's rows and columns of the coefficients `basis` (every DOF of each) from the contacts' G.
  Eigen::MatrixXd assemble_block(double omega, const std::vector<Eigen::MatrixXd>& G, const std::vector<int>& basis) const;
};

}  // namespace gearhb
