#include "gearhb/hb/period_doubling.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "gearhb/hb/chord_trials.hpp"
#include "gearhb/hb/floquet.hpp"

namespace gearhb {

std::shared_ptr<HarmonicBalance> subharmonic_model(const HarmonicBalance& hb, int p, int H2) {
  if (p < 1) throw std::invalid_argument("subharmonic_model: the period must be >= 1");
  const int H = hb.harmonics();
  if (H2 == 0) H2 = p * H;
  if (H2 < p) throw std::invalid_argument("subharmonic_model: H2 must be at least the period");
  std::vector<UnilateralContact> contacts = hb.contacts();
  for (auto& ct : contacts) {
    const Eigen::VectorXd g = ct.gap_harmonics;   // 2H + 1 (HarmonicBalance pads it)
    Eigen::VectorXd gp = Eigen::VectorXd::Zero(2 * H2 + 1);
    gp[0] = g[0];
    for (int k = 1; 2 * k < g.size() && p * k <= H2; ++k) {
      gp[2 * p * k - 1] = g[2 * k - 1];
      gp[2 * p * k] = g[2 * k];
    }
    ct.gap_harmonics = gp;
    if (ct.stiffness_profile) ct.stiffness_profile = [s = ct.stiffness_profile, p](double theta) { return s(p * theta); };
  }
  Excitation f = hb.excitation();
  f.harmonic *= p;
  // the same time samples per forcing period as hb where H2 = p H, the default otherwise
  const int N = H2 == p * H ? p * hb.samples() : 0;
  return std::make_shared<HarmonicBalance>(hb.system(), contacts, f, H2, N, hb.quadrature());
}

Eigen::VectorXd to_subharmonic_basis(const HarmonicBalance& hb, const HarmonicBalance& hbp, int p,
                                     const Eigen::VectorXd& X) {
  const int n = hb.dofs();
  Eigen::VectorXd Xp = Eigen::VectorXd::Zero(hbp.size());
  Xp.head(n) = X.head(n);
  for (int k = 1; k <= hb.harmonics() && p * k <= hbp.harmonics(); ++k) {
    Xp.segment(hbp.index(2 * p * k - 1, 0), n) = X.segment(hb.index(2 * k - 1, 0), n);
    Xp.segment(hbp.index(2 * p * k, 0), n) = X.segment(hb.index(2 * k, 0), n);
  }
  return Xp;
}

Eigen::VectorXd subharmonic_part(const HarmonicBalance& hbp, int p, const Eigen::VectorXd& X) {
  Eigen::VectorXd out = X;
  const int n = hbp.dofs();
  for (int a = 0; a < 2 * hbp.harmonics() + 1; ++a)
    if (((a + 1) / 2) % p == 0) out.segment(a * n, n).setZero();
  return out;
}

namespace {

struct Failed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace

namespace {

// The odd-harmonic rows and columns of hbp's Jacobian at X (the block that decides a
// period-2 branch point on a period-1 orbit: even and odd harmonics decouple there).
Eigen::MatrixXd odd_block(const HarmonicBalance& hbp, const Eigen::VectorXd& X, double Omega, std::vector<int>& odd) {
  std::vector<int> basis;
  for (int a = 0; a < 2 * hbp.harmonics() + 1; ++a)
    if (((a + 1) / 2) % 2 == 1) basis.push_back(a);
  odd.clear();
  const int n = hbp.dofs();
  for (const int a : basis)
    for (int d = 0; d < n; ++d) odd.push_back(a * n + d);
  return hbp.jacobian_block(X, Omega, basis);
}

// A bracket [lo, hi] of a sign change of f on the chord fraction, for regula falsi (Illinois):
// a trial (t, f(t)) replaces the end of its sign, and the value at the end kept twice in a row
// is halved (so the bracket shrinks from both sides).
struct Illinois {
  double lo, hi, f_lo, f_hi;
  int side = 0;
  void update(double t, double ft) {
    if ((ft > 0.0) == (f_lo > 0.0)) {
      lo = t, f_lo = ft;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = t, f_hi = ft;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
};

// The sign of det A and log |det A| (from the LU's pivots: det itself over- or underflows).
struct SignedLogDet {
  int sign = 1;
  double log_abs = 0.0;
};
SignedLogDet signed_log_det(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  SignedLogDet d{int(lu.permutationP().determinant()), 0.0};
  for (Eigen::Index i = 0; i < lu.rows(); ++i) {
    const double u = lu.matrixLU()(i, i);
    if (u < 0.0) d.sign = -d.sign;
    d.log_abs += std::log(std::fabs(u));
  }
  return d;
}

// The critical Floquet eigenvector of the corrected PD orbit (multiplier near -1), made real,
// displacements and velocities scaled alike (velocities / omega, as the shooting scales them).
Eigen::VectorXd critical_eigenvector(const HarmonicBalance& hb, const FloquetResult& fr, double w, bool smooth) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(fr.monodromy);
  Eigen::Index j = 0;
  es.eigenvalues().unaryExpr([](std::complex<double> m) { return std::abs(m + 1.0); }).real().minCoeff(&j);
  if (!smooth) {
    // a multiplier that jumped across -1: the real one farthest beyond -1, else the real
    // negative one nearest -1
    const Eigen::VectorXcd& mus = es.eigenvalues();
    auto rank = [](std::complex<double> m) {   // smaller is preferred; real negative ones only
      if (!(m.real() < 0.0 && std::fabs(m.imag()) <= 1e-9 * std::abs(m))) return HUGE_VAL;
      return m.real() < -1.0 ? m.real() : std::fabs(m.real() + 1.0);
    };
    for (Eigen::Index k = 0; k < mus.size(); ++k)
      if (rank(mus[k]) < rank(mus[j])) j = k;
  }
  const std::complex<double> mu = es.eigenvalues()[j];
  if (!smooth && !(mu.real() < 0.0 && std::fabs(mu.imag()) <= 1e-9 * std::abs(mu))) {
    std::ostringstream os;
    os << "no real negative Floquet multiplier at the PD point (nearest -1: " << mu.real() << (mu.imag() < 0 ? "" : "+")
       << mu.imag() << "i)";
    throw Failed(os.str());
  }
  if (smooth && std::abs(mu + 1.0) > 0.05) {
    std::ostringstream os;
    os << "no Floquet multiplier near -1 at the PD point (nearest " << mu.real() << (mu.imag() < 0 ? "" : "+")
       << mu.imag() << "i)";
    throw Failed(os.str());
  }
  // the eigenvector of a real multiplier, made real (Eigen returns it up to a complex factor)
  Eigen::VectorXcd ec = es.eigenvectors().col(j);
  Eigen::Index big = 0;
  ec.cwiseAbs().maxCoeff(&big);
  ec *= std::conj(ec[big]) / std::abs(ec[big]);
  const int n = hb.dofs();
  Eigen::VectorXd e = ec.real();
  e.tail(n) /= w;
  e /= e.cwiseAbs().maxCoeff();
  e.tail(n) *= w;
  return e;
}

// The eigen-solution from e over one forcing period at the N nodes T i / N (columns): by central
// differences of the exact flow from the corrected state +- delta e, or, on the variational
// path (fr not corrected: a time-varying contact stiffness, or FloquetOptions::correct_orbit
// false), by the variational equation about the HB orbit whose monodromy gave e.
Eigen::MatrixXd eigen_solution(const HarmonicBalance& hb, const Eigen::VectorXd& X, const FloquetResult& fr,
                               const Eigen::VectorXd& e, double w, double xs, int N, const FloquetOptions& fo) {
  const int n = hb.dofs();
  const double T = 2.0 * M_PI / w, delta = 1e-6 * xs;
  std::vector<double> nodes(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) nodes[std::size_t(i)] = T * i / N;
  if (!fr.corrected) return variational_solution(hb, X, w, e, nodes, fo.variational_tolerance);
  PiecewiseLinearFlow flow(hb);
  Eigen::VectorXd xT, vT;
  Eigen::MatrixXd Phi, xp, xm;
  flow.period_map(fr.x0 + delta * e.head(n), fr.v0 + delta * e.tail(n), w, nodes, xT, vT, Phi, &xp);
  flow.period_map(fr.x0 - delta * e.head(n), fr.v0 - delta * e.tail(n), w, nodes, xT, vT, Phi, &xm);
  return (xp - xm) / (2.0 * delta);
}

// The odd harmonics k of Omega = omega / 2 of the eigen-solution D at Omega t_i = pi i / N (the
// antiperiodic extension makes the integral over two periods twice that over one), on hbp's
// basis, unit norm.
Eigen::VectorXd odd_harmonics_of(const HarmonicBalance& hb, const HarmonicBalance& hbp, const Eigen::MatrixXd& D) {
  const int n = hb.dofs(), N = int(D.cols());
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(hbp.size());
  for (int k = 1; k <= hbp.harmonics(); k += 2) {
    Eigen::VectorXd ck = Eigen::VectorXd::Zero(n), sk = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < N; ++i) {
      const double th = M_PI * k * i / N;
      ck += D.col(i) * std::cos(th);
      sk += D.col(i) * std::sin(th);
    }
    phi.segment(hbp.index(2 * k - 1, 0), n) = 2.0 * ck / N;
    phi.segment(hbp.index(2 * k, 0), n) = 2.0 * sk / N;
  }
  if (!(phi.norm() > 0.0)) throw Failed("the critical eigen-solution has no odd harmonics");
  return phi.normalized();
}

// The branch point of the period-2 model itself: where the odd block of its Jacobian on
// the period-1 branch is singular (det changes sign), searched on the chords within two
// points of the PD, the nearest taken (the chords in order of their distance from the PD's,
// the lower first, each point's det computed once, where needed: ex. 03, 2 points each where
// 6 were), located on the chord by regula falsi (Illinois) on det relative to its larger end
// to a chord fraction of 1e-12, or to a trial where that is below 1e-10: det is resolved to
// about 1e-11 of its ends (the trial points are corrected to the corrector's tolerance), and
// the trials after such a one only narrowed a bracket that this noise decides (ex. 03: 8 and 11
// trials where 11 and 15 were, the branch points moved by 2e-13 of the chord, omega by 3e-15
// relative; bisection took 40). The HB model at
// finite H2 has it beside the PD of the exact orbit (ex. 03: 2e-6 at H2 = 80) or not at
// all (ex. 03 at H2 = 42: the odd block's smallest singular value dips to 1e-5 of its
// largest and turns back): then there is no period-2 HB branch to switch to. `lu`: the LU of
// the odd block at the point returned.
BranchPoint period2_branch_point(const HarmonicBalance& hb, const HarmonicBalance& hbp, const FrequencyCurve& c,
                                 const Bifurcation& bf, const SweepOptions& opt, std::vector<int>& odd,
                                 Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  const auto& P = c.branch.points;
  auto det_at = [&](const BranchPoint& q) {
    lu.compute(odd_block(hbp, to_subharmonic_basis(hb, hbp, 2, q.X), q.omega / 2.0, odd));
    return signed_log_det(lu);
  };
  const int lo_i = std::max(0, bf.after_point - 2), hi_i = std::min(int(P.size()) - 2, bf.after_point + 2);
  std::vector<std::optional<SignedLogDet>> at(std::size_t(std::max(0, hi_i - lo_i + 2)));   // points lo_i .. hi_i + 1
  auto det_of = [&](int i) -> const SignedLogDet& {
    auto& d = at[std::size_t(i - lo_i)];
    if (!d) d = det_at(P[std::size_t(i)]);
    return *d;
  };
  int best = -1;
  for (int dist = 0; dist <= 2 && best < 0; ++dist)
    for (const int i : {bf.after_point - dist, bf.after_point + dist})
      if (best < 0 && i >= lo_i && i <= hi_i && det_of(i).sign != det_of(i + 1).sign) best = i;
  if (best < 0) {
    std::ostringstream os;
    os << "the period-2 model (H2 = " << hbp.harmonics()
       << ") has no branch point within two points of the PD (its odd block stays regular at this truncation): raise the harmonics H of the model";
    throw Failed(os.str());
  }
  const BranchPoint &pa = P[std::size_t(best)], &pb = P[std::size_t(best) + 1];
  const SignedLogDet &da = det_of(best), &db = det_of(best + 1);
  const double log_ref = std::max(da.log_abs, db.log_abs);
  auto relative = [log_ref](const SignedLogDet& d) { return d.sign * std::exp(d.log_abs - log_ref); };
  Illinois br{0.0, 1.0, relative(da), relative(db)};
  BranchPoint q = pa;
  bool lu_at_q = false;
  ChordTrials trials(hb, pa, pb, c.scaling, opt.continuation.tolerance);
  for (int it = 0; it < 60 && br.hi - br.lo > 1e-12; ++it) {
    // the secant point, kept inside the bracket's inner 98 % (so the bracket shrinks)
    const double w = br.hi - br.lo;
    const double tm = std::clamp(br.lo + w * br.f_lo / (br.f_lo - br.f_hi), br.lo + 0.01 * w, br.hi - 0.01 * w);
    q = trials.at(tm);
    const double f = relative(det_at(q));
    br.update(tm, f);
    lu_at_q = true;
    if (std::fabs(f) < 1e-10) break;   // zero to det's resolution
  }
  if (!lu_at_q) det_at(q);
  return q;
}

}  // namespace

SwitchPoint critical_direction(const HarmonicBalance& hb, const FrequencyCurve& c, const Bifurcation& bf,
                               const SweepOptions& opt, const PeriodDoublingOptions& pdo, const HarmonicBalance& hbp) {
  if (!bf.located || bf.X.size() != hb.size()) throw Failed("the PD was not located (a corrector failed on its chord)");
  // the located point itself (a point re-derived from omega on the chord misses it where the
  // branch turns within the chord: beside a fold)
  SwitchPoint sp;
  sp.at.X = bf.X;
  sp.at.omega = bf.omega;
  const double xs = c.scaling.x[0], w = sp.at.omega;
  // the corrected orbit on the exact flow where there is one and the sweep corrects its orbits;
  // else the variational equation about the HB orbit (its monodromy and eigen-solution)
  bool profile = false;
  for (const auto& ct : hb.contacts()) profile = profile || bool(ct.stiffness_profile);
  FloquetOptions fo = opt.floquet;
  fo.correct_orbit = fo.correct_orbit && !profile;
  FloquetResult fr = floquet_of_hb_orbit(hb, sp.at.X, w, xs, fo);
  // The Floquet direction only starts the inverse iteration of step 4, which converges to the
  // odd block's null vector from any start not normal to it. Where it cannot come from the
  // corrected orbit it comes from the variational equation about the HB orbit (the shooting
  // correction of the PD orbit did not converge), or from the real multiplier that jumped
  // beyond -1 (a non-smooth PD, as at a grazing orbit: no eigenvector at -1 itself); either
  // is said in `direction`, and the inverse iteration then runs to convergence.
  if (fo.correct_orbit && !fr.corrected) {
    fo.correct_orbit = false;
    fr = floquet_of_hb_orbit(hb, sp.at.X, w, xs, fo);
    sp.direction = "on the variational equation about the HB orbit (the PD orbit's shooting correction did not converge)";
  }
  if (!bf.smooth) {
    std::ostringstream os;
    os << (sp.direction.empty() ? "" : " ") << "at a non-smooth PD (a multiplier jumps across -1 to "
       << bf.multiplier.real();
    if (bf.multiplier.imag() != 0.0) os << (bf.multiplier.imag() < 0 ? "" : "+") << bf.multiplier.imag() << "i";
    os << " within the located bracket, as at a grazing orbit), along the eigenvector of a real negative multiplier";
    sp.direction += os.str();
  }
  Eigen::VectorXd e;
  try {
    e = critical_eigenvector(hb, fr, w, bf.smooth);
  } catch (const Failed& f) {
    throw Failed(sp.direction.empty() ? f.what() : sp.direction + ": " + f.what());
  }
  sp.phi_floquet = odd_harmonics_of(hb, hbp, eigen_solution(hb, sp.at.X, fr, e, w, xs, pdo.samples, fo));
  std::vector<int> odd;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;   // of the odd block at the branch point
  sp.branch_point = period2_branch_point(hb, hbp, c, bf, opt, odd, lu);
  // its null vector by inverse iteration from the Floquet direction
  Eigen::VectorXd v(odd.size()), po(odd.size());
  for (std::size_t i = 0; i < odd.size(); ++i) po[Eigen::Index(i)] = sp.phi_floquet[odd[i]];
  v = po;
  for (int it = 0; it < 3; ++it) v = lu.solve(v).normalized();
  for (int it = 0; it < 20 && !sp.direction.empty(); ++it) {
    Eigen::VectorXd u = lu.solve(v).normalized();
    if (u.dot(v) < 0.0) u = -u;
    const double change = (u - v).norm();
    v = u;
    if (change < 1e-12) break;
  }
  if (v.dot(po) < 0.0) v = -v;
  sp.agreement = v.dot(po) / po.norm();
  sp.phi = Eigen::VectorXd::Zero(hbp.size());
  for (std::size_t i = 0; i < odd.size(); ++i) sp.phi[odd[i]] = v[Eigen::Index(i)];
  return sp;
}

namespace {

// Step 5: the point where the branch crossed the period-1 branch, between its last two
// points (odd part along phi, the odd part of a, positive at a and negative at b): regula
// falsi (Illinois) on the chord fraction, each trial corrected onto the branch.
BranchPoint merge_point(const HarmonicBalance& hbp, const BranchPoint& a, const BranchPoint& b, const Scaling& s,
                        const Eigen::VectorXd& phi, double tolerance) {
  auto f = [&](const Eigen::VectorXd& X) { return subharmonic_part(hbp, 2, X).dot(phi) / s.x[0]; };
  Illinois br{0.0, 1.0, f(a.X), f(b.X)};
  BranchPoint best = std::fabs(br.f_lo) < std::fabs(br.f_hi) ? a : b;
  ChordTrials trials(hbp, a, b, s, tolerance);
  for (int it = 0; it < 40 && std::fabs(f(best.X)) > 1e-9; ++it) {
    const double t = (br.lo * br.f_hi - br.hi * br.f_lo) / (br.f_hi - br.f_lo);
    best = trials.at(t);
    br.update(t, f(best.X));
  }
  return best;
}

// A corrector that converged far off its predictor (the arc-length corrector's hyperplane is
// unbounded: on ch. 6 Fig. 44, forced a hundredfold, one step of 0.005 landed 54000 rad/s away,
// at a negative frequency, from the PD point itself): the branch ends before the first chord
// longer than five times the step that made it (scaled as the continuation measures it), as a
// failure saying where
// (`factor`: forcing frequency per base frequency).
// The first chord, from the branch point, is corrected in the hyperplane normal to the null
// vector, which holds the whole omega axis: the branch's own curvature may move it several steps
// in omega, so it counts as a jump only where it leaves the range [omega_min, omega_max] (base
// frequencies) from a branch point inside it.
void end_before_jump(Branch& b, const Scaling& s, double factor, double omega_min, double omega_max) {
  for (std::size_t k = 1; k < b.points.size(); ++k) {
    const BranchPoint &a = b.points[k - 1], &z = b.points[k];
    const double dw = (z.omega - a.omega) / s.omega;
    const double chord = std::sqrt(((z.X - a.X).array() / s.x.array()).square().sum() + dw * dw);
    auto inside = [omega_min, omega_max](const BranchPoint& q) { return q.omega >= omega_min && q.omega <= omega_max; };
    const bool jumped = k == 1 ? inside(a) && !inside(z) : chord > 5.0 * z.ds && z.ds > 0.0;
    if (!jumped) continue;
    std::ostringstream os;
    os << "the corrector jumped from omega = " << factor * a.omega << " to " << factor * z.omega << " (a chord "
       << chord / z.ds << " times its step): the branch ends before it";
    b.points.resize(k);
    b.folds.erase(std::remove_if(b.folds.begin(), b.folds.end(), [k](const Fold& f) { return f.after_point + 1 >= int(k); }),
                  b.folds.end());
    b.complete = false;
    b.failures.push_back(Failure{a.omega, 0.0, z.ds, os.str()});
    return;
  }
}

}  // namespace

namespace {

// How a period-2 branch met the period-1 branch: its odd part reversed against the point before
// (a smooth branch turns its odd part gradually; it flips only through zero: it crossed onto the
// mirror half), or vanished (the corrector turned onto the period-1 branch, itself a solution
// of the period-2 model: odd parts of 1e-18 against 1e-2 on the branch, the bilinear
// oscillator of ch. 3 at omega = 2.64; before, that went on along the period-1 branch until the
// rounding-level odd part happened to flip, 0.1 rad/s later).
enum class Merge { none, crossed, joined };

// The continuation of the period-2 branch away from its branch point, with what decides its end.
struct Period2Continuation {
  const HarmonicBalance& hbp;
  Scaling s;
  ContinuationOptions co;
  ContinuationEnd end;
  Eigen::VectorXd prev_odd;
  double largest = 0.0;   // the largest odd part of the points so far

  Merge merge_at(const Eigen::VectorXd& X) const {
    const Eigen::VectorXd odd = subharmonic_part(hbp, 2, X);
    if (largest > 0.0 && odd.norm() <= 1e-8 * largest) return Merge::joined;
    return odd.dot(prev_odd) < 0.0 ? Merge::crossed : Merge::none;
  }

  Period2Continuation(const HarmonicBalance& hbp_, const FrequencyCurve& c, const SweepOptions& opt,
                      const PeriodDoublingOptions& pdo)
      : hbp(hbp_), s(c.scaling), co(opt.continuation) {
    s.x = Eigen::VectorXd::Constant(hbp.size(), c.scaling.x[0]);
    s.omega = c.scaling.omega / 2.0;
    co.fast_iterations = pdo.fast_iterations;
    co.curvature_predictor = pdo.curvature_predictor;
    co.regime = hbp.contacts().empty() ? nullptr : contact_regime(hbp);
    end.omega_min = opt.omega_min / 2.0;
    end.omega_max = opt.omega_max / 2.0;
    end.stop = [this](const Eigen::VectorXd& X, double) {
      if (merge_at(X) != Merge::none) return EndAt::past_branch_point;
      prev_odd = subharmonic_part(hbp, 2, X);
      largest = std::max(largest, prev_odd.norm());
      return EndAt::no;
    };
  }
  Period2Continuation(const Period2Continuation&) = delete;   // end.stop holds `this`

  // The first step: pdo.step, shortened tenfold while the corrector fails (the branch point is
  // singular: its basin shrinks with the step's error against the branch).
  Branch from_branch_point(const Eigen::VectorXd& X0, double Omega0, const Eigen::VectorXd& phi, double xs,
                           double step0) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(hbp.size() + 1);
    d.head(hbp.size()) = phi / xs;
    Branch b;
    for (double step = step0;; step *= 0.1) {
      prev_odd = phi;
      largest = 0.0;
      b = arc_length_continuation_from(hbp, X0, Omega0, d, step, s, co, end);
      if (b.points.size() > 1 || step < 1e-6 * step0) break;
    }
    return b;
  }

  // A step that overshot the merge (near a branch point the branch is a parabola omega - omega_b
  // ~ odd^2, nearly normal to the period-1 branch: a step along its tangent crosses to the mirror
  // half) with the last point still far from it (odd part above 5 % of the branch's largest): the
  // last chord is walked again from its start with steps ten times shorter, up to five times.
  void refine_overshoot(Branch& b, double xs) {
    auto odd_norm = [this](const BranchPoint& q) { return subharmonic_part(hbp, 2, q.X).norm(); };
    for (int refine = 0; refine < 5 && b.complete && b.points.size() >= 2 && end.stop(b.points.back().X, 0.0) != EndAt::no; ++refine) {
      double largest = 0.0;
      for (const auto& q : b.points) largest = std::max(largest, odd_norm(q));
      const BranchPoint a = b.points[b.points.size() - 2], z = b.points.back();
      if (odd_norm(a) <= 0.05 * largest) break;
      Eigen::VectorXd chord(hbp.size() + 1);
      chord.head(hbp.size()) = (z.X - a.X) / xs;
      chord[hbp.size()] = (z.omega - a.omega) / s.omega;
      ContinuationOptions fine = co;
      fine.ds_max = 0.1 * std::max(chord.norm(), co.ds_min);
      fine.ds_initial = fine.ds_max;
      prev_odd = subharmonic_part(hbp, 2, a.X);
      Branch more = arc_length_continuation_from(hbp, a.X, a.omega, chord, fine.ds_max, s, fine, end);
      if (more.points.empty()) break;
      b.points.pop_back();
      for (auto& f : more.folds) f.after_point += int(b.points.size());
      b.folds.insert(b.folds.end(), more.folds.begin(), more.folds.end());
      b.points.insert(b.points.end(), more.points.begin(), more.points.end());
      b.complete = more.complete;
      b.failures = more.failures;
    }
  }
};

// The merge point of a branch on hb's basis: a period-2 point whose odd harmonics vanish is the
// period-1 orbit X1 (harmonic 2k of Omega -> k of omega), at c's omega 2 Omega.
Eigen::VectorXd period1_part(const HarmonicBalance& hb, const HarmonicBalance& hbp, const Eigen::VectorXd& Xp) {
  const int n = hb.dofs();
  Eigen::VectorXd X = Eigen::VectorXd::Zero(hb.size());
  X.head(n) = Xp.head(n);
  for (int k = 1; k <= hb.harmonics() && 2 * k <= hbp.harmonics(); ++k) {
    X.segment(hb.index(2 * k - 1, 0), n) = Xp.segment(hbp.index(4 * k - 1, 0), n);
    X.segment(hb.index(2 * k, 0), n) = Xp.segment(hbp.index(4 * k, 0), n);
  }
  return X;
}

// Where on c a branch met it: the chord (points j, j + 1) of c nearest the period-1 orbit (X1, w)
// in the scaled unknowns. Not the nearest omega: a branch with folds passes one omega several
// times (ch. 6 Fig. 40: three times at 8654 rad/s, on chords with and without a PD).
int nearest_chord(const FrequencyCurve& c, const Eigen::VectorXd& X1, double w) {
  const auto& P = c.branch.points;
  const Scaling& s = c.scaling;
  auto scaled = [&s](const Eigen::VectorXd& X, double omega) {
    Eigen::VectorXd z(X.size() + 1);
    z.head(X.size()) = X.array() / s.x.array();
    z[X.size()] = omega / s.omega;
    return z;
  };
  const Eigen::VectorXd z = scaled(X1, w);
  int best = -1;
  double dmin = INFINITY;
  for (std::size_t j = 0; j + 1 < P.size(); ++j) {
    const Eigen::VectorXd a = scaled(P[j].X, P[j].omega), d = scaled(P[j + 1].X, P[j + 1].omega) - a;
    const double t = d.squaredNorm() > 0.0 ? std::clamp((z - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const double dist = (z - a - t * d).norm();
    if (dist < dmin) dmin = dist, best = int(j);
  }
  return best;
}

// The PD of c other than the i-th located on chord j of c or on a chord next to it (the period-2
// model's branch point, where the HB branch meets c, lies beside the PD of the exact orbit by the
// truncation error: ch. 6 Fig. 40 at H = 10, 19 rad/s from the PD at 8674.3 rad/s, 2.2e-3
// relative; the bilinear oscillator at H = 3, 1.4e-3), the one nearest w; -1 where none.
int pd_on_chord(const FrequencyCurve& c, std::size_t i, int j, double w) {
  int to = -1;
  double dmin = INFINITY;
  for (std::size_t k = 0; k < c.bifurcations.size(); ++k) {
    const Bifurcation& bf = c.bifurcations[k];
    if (bf.type != BifurcationType::period_doubling || k == i || std::abs(bf.after_point - j) > 1) continue;
    if (std::fabs(bf.omega - w) < dmin) dmin = std::fabs(bf.omega - w), to = int(k);
  }
  return to;
}

// The merge at the period-2 model's branch point beside the PD r.to of c (where the switch there
// would start a branch), appended as the branch's last point; where there is none (no branch
// point of the period-2 model there), nothing changes.
void end_at_branch_point(PeriodDoubledBranch& r, Branch& b, const HarmonicBalance& hb, const HarmonicBalance& hbp,
                         const FrequencyCurve& c, const SweepOptions& opt, double P) {
  try {
    std::vector<int> odd;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    const BranchPoint q = period2_branch_point(hb, hbp, c, c.bifurcations[std::size_t(r.to)], opt, odd, lu);
    b.points.push_back(BranchPoint{to_subharmonic_basis(hb, hbp, 2, q.X), q.omega / 2.0, 0, 0.0, 0.0, 0.0});
    r.omega_end = P * q.omega;
  } catch (const std::exception&) {
  }
}

// The merge of a branch that crossed the period-1 branch: the crossing refined on its last chord
// (merge_point) says on which chord of c it met c; the branch ends at the period-2 model's branch
// point beside the PD there, or at the refined crossing where no PD lies there. Not the refined
// crossing itself: the crossing is the branch point, where the chord's trial points may converge
// onto the period-1 branch (a solution of the period-2 model too) anywhere near it, and |odd| = 0
// holds all along that branch (ex. 03 at H = 40 with the step growing: 2.7e-6 past the branch
// point). Returns the chord of c where it met c.
int end_at_crossing(PeriodDoubledBranch& r, Branch& b, const Period2Continuation& p2, const HarmonicBalance& hb,
                    const FrequencyCurve& c, std::size_t i, const SweepOptions& opt, double P) {
  try {
    b.points.back() = merge_point(p2.hbp, b.points[b.points.size() - 2], b.points.back(), p2.s, p2.prev_odd,
                                  p2.co.tolerance);
  } catch (const std::exception&) {
    b.points.pop_back();   // a corrector failed on the last chord: the branch ends before it
  }
  const BranchPoint e = b.points.back();
  r.omega_end = 2.0 * P * e.omega;
  const int j = nearest_chord(c, period1_part(hb, p2.hbp, e.X), 2.0 * e.omega);
  r.to = pd_on_chord(c, i, j, 2.0 * e.omega);
  if (r.to >= 0 && b.points.size() >= 2) {
    b.points.pop_back();
    const std::size_t before = b.points.size();
    end_at_branch_point(r, b, hb, p2.hbp, c, opt, P);
    if (b.points.size() == before) b.points.push_back(e);
  }
  return j;
}

// The merge of a branch that joined the period-1 branch: its last point lies on that branch past
// the merge and is dropped; the merge is the period-2 model's branch point beside the PD of c
// on the chord where it joined (where the switch would start a branch), or, where no PD was
// located there, the branch ends at the point before. Returns the chord of c where it joined.
int end_at_join(PeriodDoubledBranch& r, Branch& b, const HarmonicBalance& hb, const HarmonicBalance& hbp,
                const FrequencyCurve& c, std::size_t i, const SweepOptions& opt, double P) {
  const BranchPoint on = b.points.back();   // on the period-1 branch
  b.points.pop_back();
  const int j = nearest_chord(c, period1_part(hb, hbp, on.X), 2.0 * on.omega);
  r.to = pd_on_chord(c, i, j, 2.0 * on.omega);
  r.omega_end = 2.0 * P * b.points.back().omega;
  if (r.to >= 0) end_at_branch_point(r, b, hb, hbp, c, opt, P);
  return j;
}

// What the period-1 sweep says about chord j of c (points j, j + 1) where a branch met c, for the
// end's line: whether their orbits' shooting correction converged, and, where both did and the
// parity of their real multipliers below -1 is the same (no PD in between, frequency_sweep.cpp
// step 5b), that no multiplier crossed -1 there: the period-2 HB branch then ends at a branch
// point of its own truncation, not at a PD of the exact orbit.
bool has_chord_floquet(const FrequencyCurve& c, int j) {
  return j >= 0 && std::size_t(j) + 1 < c.branch.points.size() && c.floquet.size() == c.branch.points.size();
}
bool chord_unresolved(const FrequencyCurve& c, int j) {
  return has_chord_floquet(c, j) && (!c.floquet[std::size_t(j)].corrected || !c.floquet[std::size_t(j) + 1].corrected);
}
std::string chord_evidence(const FrequencyCurve& c, int j, double P) {
  const auto& Q = c.branch.points;
  std::ostringstream os;
  if (!has_chord_floquet(c, j)) return "";
  const PointFloquet &a = c.floquet[std::size_t(j)], &b = c.floquet[std::size_t(j) + 1];
  os << "between its points at omega = " << P * Q[std::size_t(j)].omega << " and " << P * Q[std::size_t(j) + 1].omega;
  if (chord_unresolved(c, j))
    os << ", where the shooting correction of the period-" << int(P) << " orbit did not converge: multipliers unresolved";
  else if (a.outside_real_negative % 2 == b.outside_real_negative % 2)
    os << ", whose corrected orbits show no multiplier crossing -1";
  return os.str();
}

// How the branch ends: failed (where and why), merged with the period-1 branch (at which of its
// located PDs, if any), or left the range; said in os.
void classify_end(PeriodDoubledBranch& r, Branch& b, const Period2Continuation& p2, const HarmonicBalance& hb,
                  const FrequencyCurve& c, std::size_t i, const SweepOptions& opt, double P, std::ostringstream& os) {
  const BranchPoint& last = b.points.back();
  const Merge m = b.points.size() >= 3 ? p2.merge_at(last.X) : Merge::none;
  if (!b.complete) {
    const Failure& f = b.failures.empty() ? Failure{last.omega, 0.0, 0.0, "stopped"} : b.failures.back();
    os << "failed at omega = " << 2.0 * P * f.omega << ": " << f.what;
    r.end = PeriodDoubledBranch::End::failed;
    r.omega_end = 2.0 * P * f.omega;
  } else if (m != Merge::none) {
    const int j = m == Merge::crossed ? end_at_crossing(r, b, p2, hb, c, i, opt, P) : end_at_join(r, b, hb, p2.hbp, c, i, opt, P);
    r.end = PeriodDoubledBranch::End::merged;
    const int period = int(P);
    os << "merges with the period-" << period << " branch at omega = " << r.omega_end;
    if (r.to >= 0) {
      const Bifurcation& bf = c.bifurcations[std::size_t(r.to)];
      os << " (the PD located at " << P * bf.omega << (bf.smooth ? "" : ", non-smooth: a multiplier jumps across -1");
      if (chord_unresolved(c, bf.after_point)) os << "; " << chord_evidence(c, bf.after_point, P);
      os << ")";
    } else {
      os << " where no PD of the period-" << period << " branch was located";
      const std::string e = chord_evidence(c, j, P);
      if (!e.empty()) os << " (" << e << ")";
    }
  } else {
    r.end = PeriodDoubledBranch::End::left_range;
    r.omega_end = 2.0 * P * last.omega;
    os << "leaves the range at omega = " << r.omega_end;
  }
}

// Floquet stability and bifurcations of the switched branch, its progress in the forcing frequency.
void branch_stability(PeriodDoubledBranch& r, const SweepOptions& opt) {
  SweepOptions o2 = opt;
  o2.omega_min /= 2.0;
  o2.omega_max /= 2.0;
  if (opt.step_progress)
    o2.step_progress = [&opt, &r](const std::string& step, const ContinuationProgress& q) {
      ContinuationProgress f = q;
      f.omega *= r.period;
      opt.step_progress("period-" + std::to_string(r.period) + " " + step, f);
    };
  analyse_stability(*r.model, o2, r.curve);
}

// One switch: at the i-th bifurcation of c (a PD), the period-2 branch from its critical
// direction, continued to its end.
// The branch of `earlier` that starts or ends at the period-2 branch point X0 (base frequency
// Omega), if any: a branch point beside two PDs (a non-smooth PD next to a smooth one, within two
// points: ch. 6 Fig. 40's at 8460.8 rad/s found the one where the branch from 8298.2 merged, and
// retraced that branch).
const PeriodDoubledBranch* branch_through(const std::vector<PeriodDoubledBranch>& earlier, const Eigen::VectorXd& X0,
                                          double Omega) {
  auto same = [&](const BranchPoint& q) {
    return q.X.size() == X0.size() && std::fabs(q.omega - Omega) <= 1e-9 * Omega &&
           (q.X - X0).norm() <= 1e-6 * std::max(X0.norm(), q.X.norm());
  };
  for (const auto& o : earlier)
    if (!o.curve.branch.points.empty() && (same(o.curve.branch.points.front()) || same(o.curve.branch.points.back())))
      return &o;
  return nullptr;
}

void switch_branch(PeriodDoubledBranch& r, const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i,
                   const SweepOptions& opt, const PeriodDoublingOptions& pdo,
                   const std::vector<PeriodDoubledBranch>& earlier, std::ostringstream& os) {
  const double P = pdo.period;   // hb's omegas are the forcing frequency / P
  r.model = subharmonic_model(hb, 2);
  const HarmonicBalance& hbp = *r.model;
  const SwitchPoint sp = critical_direction(hb, c, c.bifurcations[i], opt, pdo, hbp);
  const BranchPoint& at = sp.branch_point;
  r.omega_branch_point = P * at.omega;
  r.direction_agreement = sp.agreement;
  if (!sp.direction.empty()) os << "switched " << sp.direction << "; ";
  Period2Continuation p2(hbp, c, opt, pdo);
  const Eigen::VectorXd X0 = to_subharmonic_basis(hb, hbp, 2, at.X);
  if (const PeriodDoubledBranch* o = branch_through(earlier, X0, at.omega / 2.0)) {
    std::ostringstream why;
    why << "its period-2 branch point (omega = " << r.omega_branch_point
        << ") is an end of the branch from the PD at omega = " << o->omega_start << ": not continued again";
    throw Failed(why.str());
  }
  Branch b = p2.from_branch_point(X0, at.omega / 2.0, sp.phi, c.scaling.x[0], pdo.step);
  p2.refine_overshoot(b, c.scaling.x[0]);
  // the branch starts at the PD point: the period-1 orbit, a solution of the period-2 model
  b.points.insert(b.points.begin(), BranchPoint{X0, at.omega / 2.0, 0, 0.0, 0.0, 0.0});
  for (auto& f : b.folds) ++f.after_point;
  end_before_jump(b, p2.s, 2.0 * P, p2.end.omega_min, p2.end.omega_max);
  classify_end(r, b, p2, hb, c, i, opt, P, os);
  FrequencyCurve& c2 = r.curve;
  c2.scaling = p2.s;
  c2.stability = opt.stability;
  c2.branch = std::move(b);
  c2.complete = r.end != PeriodDoubledBranch::End::failed;
  if (!c2.complete) c2.failure = os.str();
  branch_stability(r, opt);
}

}  // namespace

std::vector<PeriodDoubledBranch> period_doubled_branches(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                         const SweepOptions& opt, const PeriodDoublingOptions& pdo) {
  std::vector<PeriodDoubledBranch> out;
  if (c.natural || c.branch.points.size() < 2) return out;
  for (std::size_t i = 0; i < c.bifurcations.size(); ++i) {
    const Bifurcation& bf = c.bifurcations[i];
    if (bf.type != BifurcationType::period_doubling) continue;
    bool reached = false;
    for (const auto& o : out) reached = reached || o.to == int(i);
    if (reached) continue;
    PeriodDoubledBranch r;
    r.period = 2 * pdo.period;
    r.from = i;
    r.omega_start = pdo.period * bf.omega;
    std::ostringstream os;
    os << "period-" << r.period << " branch from the PD at omega = " << r.omega_start << ": ";
    if (!(bf.omega >= opt.omega_min && bf.omega <= opt.omega_max)) {
      // on a stretch the curve took beyond its range (a fold pair beside the start: start_excursion)
      os << "not switched: the PD lies outside the range [" << pdo.period * opt.omega_min << ", "
         << pdo.period * opt.omega_max << "]";
      r.end = PeriodDoubledBranch::End::left_range;
      r.omega_end = r.omega_start;
      r.why = os.str();
      out.push_back(std::move(r));
      continue;
    }
    try {
      switch_branch(r, hb, c, i, opt, pdo, out, os);
    } catch (const std::exception& e) {
      os << "failed: " << e.what();
      r.end = PeriodDoubledBranch::End::failed;
    }
    r.why = os.str();
    out.push_back(std::move(r));
  }
  return out;
}

bool has_points(const PeriodDoubledBranch& b) {
  return !b.curve.branch.points.empty() && b.curve.stable.size() == b.curve.branch.points.size();
}

std::vector<int> branch_starts(const FrequencyCurve& c, const std::vector<PeriodDoubledBranch>& pd, int parent) {
  std::vector<int> starts(c.bifurcations.size(), -1);
  for (std::size_t k = 0; k < pd.size(); ++k)
    if (pd[k].parent == parent && has_points(pd[k]) && pd[k].from < starts.size()) starts[pd[k].from] = int(k) + 1;
  return starts;
}

std::vector<PeriodDoubledBranch> period_doubling_cascade(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                         const SweepOptions& opt, int depth, PeriodDoublingOptions pdo) {
  std::vector<PeriodDoubledBranch> out;
  if (depth < 1) return out;
  pdo.period = 1;
  out = period_doubled_branches(hb, c, opt, pdo);
  SweepOptions o = opt;   // in the base frequency of the parents' models
  std::size_t begin = 0;
  for (int d = 2; d <= depth; ++d) {
    const std::size_t end = out.size();
    o.omega_min /= 2.0;
    o.omega_max /= 2.0;
    for (std::size_t k = begin; k < end; ++k) {
      if (!has_points(out[k])) continue;
      pdo.period = out[k].period;
      std::vector<PeriodDoubledBranch> more = period_doubled_branches(*out[k].model, out[k].curve, o, pdo);
      for (auto& b : more) {
        b.parent = int(k);
        out.push_back(std::move(b));
      }
    }
    begin = end;
  }
  return out;
}

namespace {

// stable_intervals with the labels `stable` (one per point of c).
Intervals intervals_of(const FrequencyCurve& c, const std::vector<bool>& stable, int period) {
  const auto& P = c.branch.points;
  Intervals out;
  if (stable.size() != P.size()) return out;
  for (std::size_t k = 0; k + 1 < P.size(); ++k) {
    const double a = period * P[k].omega, b = period * P[k + 1].omega;
    if (stable[k] && stable[k + 1]) {
      out.emplace_back(std::min(a, b), std::max(a, b));
    } else if (stable[k] != stable[k + 1]) {
      double at = 0.5 * (a + b);
      for (const auto& bf : c.bifurcations)
        if (bf.after_point == int(k)) {
          at = period * bf.omega;
          break;
        }
      const double from = stable[k] ? a : b;
      out.emplace_back(std::min(from, at), std::max(from, at));
    }
  }
  if (P.size() == 1 && stable[0]) out.emplace_back(period * P[0].omega, period * P[0].omega);
  return merged(std::move(out));
}

// The runs [first, last] of consecutive stable points with no corrected point, each point's
// shooting tried and failed (a point whose multipliers are the variational equation's by choice,
// FloquetOptions::correct_orbit = false, tried none: its label is that method's, not unresolved).
std::vector<std::pair<std::size_t, std::size_t>> unresolved_runs(const FrequencyCurve& c) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  const std::size_t n = c.branch.points.size();
  if (c.stable.size() != n || c.floquet.size() != n) return runs;
  auto failed = [&](std::size_t k) { return c.floquet[k].shooting && !c.floquet[k].corrected; };
  for (std::size_t i = 0; i < n;) {
    if (!c.stable[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    bool all_failed = failed(i);
    for (; j + 1 < n && c.stable[j + 1]; ++j) all_failed = all_failed && failed(j + 1);
    if (all_failed) runs.emplace_back(i, j);
    i = j + 1;
  }
  return runs;
}

}  // namespace

Intervals stable_intervals(const FrequencyCurve& c, int period) { return intervals_of(c, c.stable, period); }

std::vector<bool> resolved_stable(const FrequencyCurve& c) {
  std::vector<bool> st = c.stable;
  for (const auto& [i, j] : unresolved_runs(c))
    for (std::size_t k = i; k <= j; ++k) st[k] = false;
  return st;
}

Intervals resolved_stable_intervals(const FrequencyCurve& c, int period) {
  return intervals_of(c, resolved_stable(c), period);
}

Intervals unresolved_stable_stretches(const FrequencyCurve& c, int period) {
  Intervals out;
  for (const auto& [i, j] : unresolved_runs(c)) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = i; k <= j; ++k)
      lo = std::min(lo, period * c.branch.points[k].omega), hi = std::max(hi, period * c.branch.points[k].omega);
    out.emplace_back(lo, hi);
  }
  std::sort(out.begin(), out.end());
  return out;
}

Period1Ranges period1_ranges(double lo, double hi, const std::vector<const FrequencyCurve*>& curves) {
  Intervals resolved, labelled;
  for (const FrequencyCurve* c : curves) {
    const Intervals r = resolved_stable_intervals(*c), l = stable_intervals(*c);
    resolved.insert(resolved.end(), r.begin(), r.end());
    labelled.insert(labelled.end(), l.begin(), l.end());
  }
  Period1Ranges out;
  out.no_stable = uncovered(lo, hi, resolved);
  const Intervals unstable = uncovered(lo, hi, labelled);
  for (const auto& [a, b] : out.no_stable) {   // its parts that the labels call stable
    const Intervals parts = uncovered(a, b, unstable);
    out.unresolved.insert(out.unresolved.end(), parts.begin(), parts.end());
  }
  return out;
}

Intervals merged(Intervals iv) {
  std::sort(iv.begin(), iv.end());
  Intervals out;
  for (const auto& i : iv)
    if (!out.empty() && i.first <= out.back().second) out.back().second = std::max(out.back().second, i.second);
    else out.push_back(i);
  return out;
}

Intervals uncovered(double lo, double hi, Intervals covered) {
  std::sort(covered.begin(), covered.end());
  const double tiny = 1e-9 * (hi - lo);
  Intervals gaps;
  double at = lo;
  for (const auto& [a, b] : covered) {
    if (a - at > tiny && a > lo) gaps.emplace_back(at, std::min(a, hi));
    at = std::max(at, b);
    if (at >= hi) break;
  }
  if (hi - at > tiny) gaps.emplace_back(at, hi);
  return gaps;
}

}  // namespace gearhb
