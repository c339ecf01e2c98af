#include "gearhb/hb/first_point.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

Eigen::VectorXd linear_first_guess(const HarmonicBalance& hb, double omega) {
  // A candidate that is not finite (the open-contact solution of a system with a
  // free rigid-body mode, K singular, under a static load) or whose residual is
  // not finite is skipped.
  Eigen::VectorXd best;
  double r_best = INFINITY;
  Eigen::VectorXd R;
  for (bool closed : {false, true}) {
    if (closed && hb.contacts().empty()) break;
    Eigen::VectorXd X = closed ? hb.closed_contact_solution(omega) : hb.open_contact_solution(omega);
    if (!X.allFinite()) continue;
    hb.evaluate(X, omega, R, nullptr, nullptr);
    const double r = R.norm();
    if (std::isfinite(r) && (best.size() == 0 || r < r_best)) {
      best = std::move(X);
      r_best = r;
    }
  }
  if (best.size() == 0) {
    std::ostringstream os;
    os << "linear_first_guess: neither the open- nor the closed-contact linear solution is finite at omega = "
       << omega << " (a free rigid-body mode under a static load with no contact to hold it, or loads so large that the response overflows)";
    throw std::invalid_argument(os.str());
  }
  return best;
}

const char* to_string(FirstPointMethod m) {
  switch (m) {
    case FirstPointMethod::none: return "none";
    case FirstPointMethod::linear_guess: return "linear_guess";
    case FirstPointMethod::contact_set: return "contact_set";
    case FirstPointMethod::amplitude_continuation: return "amplitude_continuation";
    case FirstPointMethod::stiffness_continuation: return "stiffness_continuation";
  }
  return "?";
}

namespace {

// R_lambda(X) = R(X, omega) with the periodic forcing fc, fs and the periodic parts of the
// gaps (a transmission error) scaled by lambda, the continuation parameter in place of omega:
// R_lambda = R_1(gaps scaled by lambda) + (1 - lambda) f_per, f_per the forcing's first-harmonic
// coefficients, so dR/dlambda = dR/d(gap scale) - f_per. At lambda = 0 the problem is static.
class AmplitudeHomotopy : public ParametricProblem {
 public:
  AmplitudeHomotopy(const HarmonicBalance& hb, double omega) : hb_(hb), w_(omega), fper_(Eigen::VectorXd::Zero(hb.size())) {
    const int n = hb.dofs();
    const int p = hb.excitation().harmonic;
    fper_.segment(hb.index(2 * p - 1, 0), n) = hb.excitation().fc;
    fper_.segment(hb.index(2 * p, 0), n) = hb.excitation().fs;
  }
  int size() const override { return hb_.size(); }
  void evaluate(const Eigen::VectorXd& X, double lambda, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX,
                Eigen::VectorXd* dRdomega) const override {
    hb_.evaluate_gap_scaled(X, w_, lambda, R, dRdX, dRdomega);
    R += (1.0 - lambda) * fper_;
    if (dRdomega) *dRdomega -= fper_;
  }
  bool forced() const { return fper_.cwiseAbs().maxCoeff() > 0.0 || hb_.gaps_vary(); }

 private:
  const HarmonicBalance& hb_;
  double w_;
  Eigen::VectorXd fper_;
};

// Step 4: continuation in the depth of the contacts' stiffness variation. The contact force
// kc s(theta) max(u, 0) is linear in the profile s, so the balance of the profile
// s_lambda = 1 + lambda (s - 1) is R_lambda = (1 - lambda) R_0 + lambda R_1, R_0 that of the
// model with constant stiffnesses kc (lambda = 0: no parametric excitation) and R_1 the
// model's own: exactly, not a linearisation. Only the contacts with a profile change.
class StiffnessHomotopy : public ParametricProblem {
 public:
  StiffnessHomotopy(const HarmonicBalance& hb, double omega) : hb_(hb), w_(omega) {
    std::vector<UnilateralContact> flat = hb.contacts();
    for (auto& c : flat) c.stiffness_profile = {};
    flat_ = std::make_unique<HarmonicBalance>(hb.system(), flat, hb.excitation(), hb.harmonics(), hb.samples(),
                                              hb.quadrature());
  }
  int size() const override { return hb_.size(); }
  void evaluate(const Eigen::VectorXd& X, double lambda, Eigen::VectorXd& R, Eigen::MatrixXd* dRdX,
                Eigen::VectorXd* dRdlambda) const override {
    Eigen::VectorXd R0, unused;
    Eigen::MatrixXd J0;
    flat_->evaluate(X, w_, R0, dRdX ? &J0 : nullptr, nullptr);
    hb_.evaluate(X, w_, R, dRdX, nullptr);
    if (dRdlambda) *dRdlambda = R - R0;
    R = (1.0 - lambda) * R0 + lambda * R;
    if (dRdX) *dRdX = (1.0 - lambda) * J0 + lambda * *dRdX;
  }
  bool parametric() const {
    for (const auto& c : hb_.contacts())
      if (c.stiffness_profile) return true;
    return false;
  }
  const HarmonicBalance& flat() const { return *flat_; }

 private:
  const HarmonicBalance& hb_;
  double w_;
  std::unique_ptr<HarmonicBalance> flat_;
};

struct Candidate {
  Eigen::VectorXd X;
  unsigned long long set = 0;
  double residual = 0.0;
};

// The set of the loaded flanks (step 2, many contacts): of two contacts with opposite
// normals (n_j = -c n_i, c > 0: the two flanks of one clearance) the one with the larger
// gap, and every contact without an opposite one.
unsigned long long loaded_flanks(const HarmonicBalance& hb) {
  const auto& c = hb.contacts();
  const int P = std::min(int(c.size()), 64);
  unsigned long long S = P >= 64 ? ~0ull : (1ull << P) - 1ull;
  for (int i = 0; i < P; ++i)
    for (int j = i + 1; j < P; ++j) {
      const double ni = c[std::size_t(i)].normal.norm(), nj = c[std::size_t(j)].normal.norm();
      if (!(ni > 0.0 && nj > 0.0)) continue;
      if ((c[std::size_t(i)].normal / ni + c[std::size_t(j)].normal / nj).norm() > 1e-12) continue;
      S &= ~(1ull << (c[std::size_t(i)].gap >= c[std::size_t(j)].gap ? j : i));
    }
  return S;
}

// Linear solutions of every contact set except `skip` (step 2), finite ones only,
// sorted by their residual in `p` at parameter `par`; `static_only` drops their
// harmonics (the lambda = 0 problem has no periodic forcing).
std::vector<Candidate> contact_set_candidates(const HarmonicBalance& hb, const ParametricProblem& p, double omega,
                                              double par, const FirstPointOptions& opt, bool static_only,
                                              const std::vector<unsigned long long>& skip) {
  const int P = int(hb.contacts().size());
  std::vector<unsigned long long> sets;
  if (P <= opt.max_set_contacts && P < 63) {
    for (unsigned long long S = 0; S < (1ull << P); ++S) sets.push_back(S);
  } else {
    for (int i = 0; i < P && i < 64; ++i) sets.push_back(1ull << i);
    sets.push_back(loaded_flanks(hb));
  }
  std::vector<Candidate> out;
  Eigen::VectorXd R;
  for (unsigned long long S : sets) {
    if (std::find(skip.begin(), skip.end(), S) != skip.end()) continue;
    Eigen::VectorXd X = hb.contact_set_solution(omega, S);
    if (static_only) X.tail(X.size() - hb.dofs()).setZero();
    if (!X.allFinite()) continue;
    p.evaluate(X, par, R, nullptr, nullptr);
    const double r = R.norm();
    if (std::isfinite(r)) out.push_back({std::move(X), S, r});
  }
  std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.residual < b.residual; });
  return out;
}

// Newton from each candidate in turn at parameter `par`; the first that converges goes
// to fp.X and fp.contact_set (true), none: false.
bool first_converged(const ParametricProblem& p, const std::vector<Candidate>& cands, double par, const Scaling& s,
                     const FirstPointOptions& opt, FirstPoint& fp) {
  for (const auto& c : cands) {
    Eigen::VectorXd X = c.X;
    ++fp.newton_solves;
    if (newton_solve(p, X, par, s, opt.newton).converged) {
      fp.X = std::move(X);
      fp.contact_set = c.set;
      return true;
    }
  }
  return false;
}

// 1. Newton from the better of the open and all-closed linear solutions; on failure, why.
bool from_linear_guess(const HarmonicBalance& hb, double omega, const Scaling& s, const FirstPointOptions& opt,
                       FirstPoint& fp, std::ostringstream& why) {
  try {
    Eigen::VectorXd X = opt.linear_guess.size() ? opt.linear_guess : linear_first_guess(hb, omega);
    ++fp.newton_solves;
    const NewtonReport r = newton_solve(hb, X, omega, s, opt.newton);
    if (r.converged) {
      fp.X = std::move(X);
      return true;
    }
    why << "Newton from the linear open/closed-contact guess: " << r.message;
  } catch (const std::invalid_argument& e) {
    why << e.what();
  }
  return false;
}

// What a homotopy is called in the failure reports: "the <name> continuation from <start>
// stopped (did not reach the full <full>)".
struct HomotopyWords {
  const char *name, *start, *full;
};

// Steps 3 and 4 from their start X (at lambda = 0): arc-length continuation of the homotopy
// to lambda = 1, confirmed there by a last Newton solve on the model; on failure, why.
bool continue_to_one(const ParametricProblem& homotopy, const HarmonicBalance& hb, double omega, const Scaling& s,
                     const FirstPointOptions& opt, const Eigen::VectorXd& X0, const HomotopyWords& w, FirstPoint& fp,
                     std::ostringstream& why) {
  ContinuationOptions co = opt.continuation;
  co.omega_start = 0.0;
  co.omega_end = 1.0;
  Scaling sl = s;
  sl.omega = 1.0;
  const Branch b = arc_length_continuation(homotopy, X0, sl, co);
  fp.homotopy_points = int(b.points.size());
  if (!b.complete || b.points.empty() || b.points.back().omega != 1.0) {
    why << "; the " << w.name << " continuation from " << w.start << " stopped ("
        << (b.failures.empty() ? std::string("did not reach the full ") + w.full : b.summary()) << ")";
    return false;
  }
  Eigen::VectorXd X = b.points.back().X;
  ++fp.newton_solves;
  const NewtonReport r = newton_solve(hb, X, omega, s, opt.newton);
  if (!r.converged) {
    why << "; the " << w.name << " continuation reached lambda = 1 but Newton there failed: " << r.message;
    return false;
  }
  fp.X = std::move(X);
  return true;
}

// 3. Continuation in the forcing amplitude lambda from the static problem (lambda = 0) to the
// problem itself (lambda = 1), confirmed there by a last Newton solve; on failure, why.
bool from_amplitude_continuation(const HarmonicBalance& hb, double omega, const Scaling& s,
                                 const FirstPointOptions& opt, FirstPoint& fp, std::ostringstream& why) {
  const AmplitudeHomotopy homotopy(hb, omega);
  if (!opt.amplitude_continuation) return false;
  if (!homotopy.forced()) {   // say so: a set driven by its mesh stiffness alone ends here (first_point.hpp "Limits")
    why << "; no forcing-amplitude continuation: the model has no periodic external forcing to scale (its excitation"
           " is its contacts' time-varying stiffness or gap, which the continuation does not scale)";
    return false;
  }
  if (!first_converged(homotopy, contact_set_candidates(hb, homotopy, omega, 0.0, opt, true, {}), 0.0, s, opt, fp)) {
    why << "; the forcing-amplitude continuation has no start: no static equilibrium under the static load alone"
           " (no contact set holds it; with K singular a static load must press a contact)";
    return false;
  }
  return continue_to_one(homotopy, hb, omega, s, opt, fp.X, {"forcing-amplitude", "the static equilibrium", "amplitude"},
                         fp, why);
}

// 4. Continuation in the depth of the stiffness variation (StiffnessHomotopy) from the
// model with constant contact stiffnesses, whose first point steps 1-2 find (its orbit is
// static where nothing else forces it), to the model itself; on failure, why.
bool from_stiffness_continuation(const HarmonicBalance& hb, double omega, const Scaling& s,
                                 const FirstPointOptions& opt, FirstPoint& fp, std::ostringstream& why) {
  const StiffnessHomotopy homotopy(hb, omega);
  if (!opt.amplitude_continuation || !homotopy.parametric()) return false;
  const HarmonicBalance& flat = homotopy.flat();
  Eigen::VectorXd X = linear_first_guess(flat, omega);
  ++fp.newton_solves;
  if (!newton_solve(flat, X, omega, s, opt.newton).converged) {
    const int P = int(flat.contacts().size());
    const unsigned long long all = P >= 64 ? ~0ull : (1ull << P) - 1ull;
    if (!first_converged(flat, contact_set_candidates(flat, flat, omega, omega, opt, false, {0ull, all}), omega, s, opt,
                         fp)) {
      why << "; the stiffness-variation continuation has no start: no solution with constant contact stiffnesses";
      return false;
    }
    X = fp.X;
  }
  return continue_to_one(homotopy, hb, omega, s, opt, X, {"stiffness-variation", "constant stiffnesses", "variation"}, fp,
                         why);
}

}  // namespace

FirstPoint find_first_point(const HarmonicBalance& hb, double omega, const Scaling& s, const FirstPointOptions& opt) {
  FirstPoint fp;
  std::ostringstream why;
  auto found = [&](FirstPointMethod m) {
    fp.found = true;
    fp.method = m;
    return fp;
  };
  if (from_linear_guess(hb, omega, s, opt, fp, why)) return found(FirstPointMethod::linear_guess);
  const int P = int(hb.contacts().size());
  if (P > 0) {
    // 2. Newton from the linear solution of every other contact set.
    const unsigned long long all = P >= 64 ? ~0ull : (1ull << P) - 1ull;
    const auto cands = contact_set_candidates(hb, hb, omega, omega, opt, false, {0ull, all});
    if (first_converged(hb, cands, omega, s, opt, fp)) return found(FirstPointMethod::contact_set);
    why << "; Newton from the linear solution of each of the " << cands.size() << " other contact sets failed";
    if (from_amplitude_continuation(hb, omega, s, opt, fp, why)) return found(FirstPointMethod::amplitude_continuation);
    if (from_stiffness_continuation(hb, omega, s, opt, fp, why)) return found(FirstPointMethod::stiffness_continuation);
  }
  fp.failure = why.str();
  return fp;
}

}  // namespace gearhb
