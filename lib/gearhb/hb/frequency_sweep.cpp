#include "gearhb/hb/frequency_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "gearhb/hb/first_point.hpp"
#include "gearhb/hb/response.hpp"
#include "gearhb/hb/time_integration.hpp"

namespace gearhb {

const char* to_string(BifurcationType t) {
  switch (t) {
    case BifurcationType::fold: return "fold";
    case BifurcationType::branch_point: return "branch_point";
    case BifurcationType::period_doubling: return "period_doubling";
    case BifurcationType::neimark_sacker: return "neimark_sacker";
  }
  return "?";
}

FrequencyCurve require_complete(FrequencyCurve c, const std::string& label) {
  if (!c.complete && !c.natural)
    throw std::runtime_error(c.failure.empty() ? "case " + label + ": incomplete branch" : c.failure);
  return c;
}

namespace {

// A multiplier is real when Eigen's real Schur form returns it with no imaginary
// part (complex pairs of a real matrix come with |Im| well above round-off unless
// they are about to split on the real axis).
bool is_real(std::complex<double> m) { return std::fabs(m.imag()) <= 1e-12 * std::max(1.0, std::abs(m)); }

// Reports point i of the curve to opt.step_progress as being in `step`; at omega (a trial
// point on the chord before it), if given.
void report(const SweepOptions& opt, const char* step, const FrequencyCurve& c, std::size_t i, double omega = NAN) {
  const BranchPoint& p = c.branch.points[i];
  if (opt.step_progress) opt.step_progress(step, {int(i), std::isnan(omega) ? p.omega : omega, p.ds});
}

PointFloquet point_floquet(const FloquetResult& r) {
  PointFloquet p;
  p.modulus = r.modulus;
  p.angle = r.angle;
  p.orbit_error = r.orbit_error;
  p.corrected = r.corrected;
  p.shooting = r.shooting;
  p.x0 = r.x0;
  p.v0 = r.v0;
  p.lower_period = r.lower_period;
  for (Eigen::Index i = 0; i < r.multipliers.size(); ++i) {
    const auto m = r.multipliers[i];
    if (!(std::abs(m) > 1.0)) continue;
    if (!is_real(m)) ++p.outside_complex;
    else if (m.real() > 0) ++p.outside_real_positive;
    else ++p.outside_real_negative;
  }
  return p;
}

int outside(const PointFloquet& p) { return p.outside_real_positive + p.outside_real_negative + p.outside_complex; }

// The Floquet results of the points of one chord already computed, keyed by the exact point
// (X, omega), so that none is computed twice: locate_state_change probes the chord's ends
// first (their results are the branch's, from floquet_of_branch) and returns one of its trial
// points (whose result its probe had), and each shooting of a stiff contact costs seconds.
class FloquetMemo {
 public:
  FloquetMemo(const HarmonicBalance& hb, double xs, const FloquetOptions& fo) : hb_(hb), xs_(xs), fo_(fo) {}
  void add(const BranchPoint& p, const FloquetResult& r) { seen_.push_back({p.X, p.omega, r}); }
  // The result at (X, omega); `computing` is called before a result that is not known yet.
  const FloquetResult& at(const Eigen::VectorXd& X, double omega, const std::function<void()>& computing = nullptr) {
    for (const auto& e : seen_)
      if (e.omega == omega && e.X.size() == X.size() && e.X == X) return e.r;
    if (computing) computing();
    seen_.push_back({X, omega, floquet_of_hb_orbit(hb_, X, omega, xs_, fo_)});
    return seen_.back().r;
  }

 private:
  struct Entry {
    Eigen::VectorXd X;
    double omega;
    FloquetResult r;
  };
  const HarmonicBalance& hb_;
  double xs_;
  const FloquetOptions& fo_;
  std::deque<Entry> seen_;   // references into it stay valid as it grows
};

// The kind of crossing: through +1 (fold or branch point), through -1 (period
// doubling) or a complex pair (Neimark-Sacker). A pair near the real axis counts as
// real (|arg| or |pi - arg| below 1e-3).
BifurcationType crossing_type(std::complex<double> m) {
  const double a = std::fabs(std::arg(m));
  if (a < 1e-3) return BifurcationType::fold;
  if (M_PI - a < 1e-3) return BifurcationType::period_doubling;
  return BifurcationType::neimark_sacker;
}

// The multiplier that crossed the unit circle between two points a, b: the one
// nearest the circle among the kinds whose count outside changed from a to b (any
// kind if none did).
std::complex<double> crossing_multiplier(const FloquetResult& r, const PointFloquet& a, const PointFloquet& b) {
  auto changed = [&](BifurcationType t) {
    switch (t) {
      case BifurcationType::period_doubling: return a.outside_real_negative != b.outside_real_negative;
      case BifurcationType::neimark_sacker: return a.outside_complex != b.outside_complex;
      default: return a.outside_real_positive != b.outside_real_positive;
    }
  };
  std::complex<double> best(NAN, NAN), any(NAN, NAN);
  double d = INFINITY, d_any = INFINITY;
  for (Eigen::Index i = 0; i < r.multipliers.size(); ++i) {
    const auto m = r.multipliers[i];
    const double dist = std::fabs(std::abs(m) - 1.0);
    if (dist < d_any) d_any = dist, any = m;
    if (changed(crossing_type(m)) && dist < d) d = dist, best = m;
  }
  return std::isfinite(d) ? best : any;
}

// One crossing, one entry. The multipliers are those of the orbit corrected by shooting
// (floquet.hpp), and next to a fold of the HB branch the shooting Newton from the HB
// points of both sides may converge to the same exact orbit (the HB points lie closer to
// each other than their truncation error, hb_orbit_error): the corrected family then does
// not turn where the HB branch does, a crossing of that family near the fold is met once
// on each side of it (the Kahraman-Singh oscillator at F_a = 0.1, H = 10: the fold at
// Omega = 0.31452 and the period doubling at 0.31465 twice each), and the fold itself may
// show no +1 crossing at all (H = 20: the doubling twice, the fold missed). So:
//  - an entry of the same type as an earlier one, at the same omega (1e-6 relative), with
//    a fold of the branch between them (within 2 points) is the same crossing: dropped;
//  - a fold of the branch (its tangent's omega component changes sign, located by the
//    continuation) with no fold entry within 2 points or 1e-3 relative omega is listed
//    as a fold at the located turning point, with the real multiplier nearest +1 of the
//    corrected orbit there; smooth = 0 unless that multiplier is within 1e-2 of +1.
std::vector<Bifurcation> one_entry_per_crossing(const HarmonicBalance& hb, const FrequencyCurve& c, double xs,
                                                const FloquetOptions& fo) {
  std::vector<Bifurcation> out;
  const auto& folds = c.branch.folds;
  for (const auto& bf : c.bifurcations) {
    bool same = false;
    for (const auto& k : out) {
      if (k.type != bf.type || !k.located || !bf.located || std::fabs(k.omega - bf.omega) > 1e-6 * std::fabs(bf.omega)) continue;
      for (const auto& f : folds) same = same || (f.after_point >= k.after_point - 2 && f.after_point <= bf.after_point + 2);
    }
    if (!same) out.push_back(bf);
  }
  for (const auto& f : folds) {
    bool listed = false;
    for (const auto& k : out)
      listed = listed || (k.type == BifurcationType::fold &&
                          (std::abs(k.after_point - f.after_point) <= 2 || std::fabs(k.omega - f.omega) <= 1e-3 * std::fabs(f.omega)));
    if (listed) continue;
    Bifurcation bf;
    bf.type = BifurcationType::fold;
    bf.omega = f.omega;
    bf.X = f.X;
    bf.after_point = f.after_point;
    bf.multiplier = std::complex<double>(NAN, 0.0);
    try {
      const FloquetResult r = floquet_of_hb_orbit(hb, f.X, f.omega, xs, fo);
      double d = INFINITY;
      for (Eigen::Index i = 0; i < r.multipliers.size(); ++i)
        if (is_real(r.multipliers[i]) && std::abs(r.multipliers[i] - 1.0) < d)
          d = std::abs(r.multipliers[i] - 1.0), bf.multiplier = r.multipliers[i];
      if (!std::isfinite(d)) bf.multiplier = r.critical;
    } catch (const std::exception&) {
      bf.located = false;
    }
    bf.smooth = bf.located && std::abs(bf.multiplier - 1.0) <= 1e-2;
    if (!std::isfinite(bf.multiplier.real())) bf.multiplier = 0.0;
    out.insert(std::upper_bound(out.begin(), out.end(), bf,
                                [](const Bifurcation& a, const Bifurcation& b) { return a.after_point < b.after_point; }),
               bf);
  }
  return out;
}

std::string failure_report(const HarmonicBalance& hb, const Branch& b) {
  std::ostringstream os;
  os << b.summary();
  if (!b.failures.empty()) {
    double kc = 0.0;
    for (const auto& ct : hb.contacts()) kc = std::max(kc, ct.kc);
    const auto& f = b.failures.back();
    os << " [stopped at omega = " << f.omega << ", residual " << f.residual << ", step " << f.ds
       << "; hint: the corrector fails where the solution is poorly resolved - H = " << hb.harmonics()
       << " may be too small for this contact stiffness (kc = " << kc
       << "), or lower ds_min / raise corrector_max_iterations]";
  }
  return os.str();
}

}  // namespace

namespace {

// A band of instability narrower than a step between two stable points (a Mathieu
// tongue of a time-varying stiffness, crossed in one continuation step): the count of
// multipliers outside the circle is 0 at both ends, so the crossing loop above sees
// nothing. The multipliers' trend says where to look: an interval is searched when the
// critical multiplier is near the real axis at an end (|arg mu| within 0.15 pi of 0 or
// pi: a tongue opens where a pair meets on the real axis), within 0.25 of the circle
// there (|mu| > 0.75), and no fold of the branch within 2 points (whose +1 multiplier
// is not a band). The largest |mu| on the chord is then found by
// golden-section search (12 corrected points); if it lies outside the circle, both
// crossings are located on either side of it as the loop above does. A band whose peak
// stays below |mu| 0.75 at both neighbours, or that a smooth |mu| does not announce,
// is not found; the cost is 12-40 corrected Floquet points per searched interval.
void add_narrow_bands(const HarmonicBalance& hb, FrequencyCurve& c, double xs, const SweepOptions& opt,
                      double corrector_tolerance, const std::vector<FloquetResult>& fr) {
  const FloquetOptions& fo = opt.floquet;
  const auto& P = c.branch.points;
  const auto& F = c.floquet;
  auto near_real = [](const PointFloquet& f) {
    const double a = std::fabs(f.angle);
    return f.modulus > 0.75 && (a < 0.15 * M_PI || a > 0.85 * M_PI);
  };
  std::size_t i = 0;   // the interval searched: (i - 1, i)
  std::unique_ptr<FloquetMemo> memo;   // the interval's points
  auto floquet_at = [&](const Eigen::VectorXd& X, double omega) -> const FloquetResult& {
    return memo->at(X, omega, [&] { report(opt, "narrow bands", c, i, omega); });
  };
  auto probe = [&](const Eigen::VectorXd& X, double omega) {
    const FloquetResult& r = floquet_at(X, omega);
    return StateProbe{outside(point_floquet(r)), std::log(r.modulus)};
  };
  for (i = 1; i < P.size(); ++i) {
    if (outside(F[i - 1]) != 0 || outside(F[i]) != 0) continue;
    if (!near_real(F[i - 1]) && !near_real(F[i])) continue;
    bool near_fold = false;   // a +1 multiplier of a fold of the branch is not a band
    for (const auto& f : c.branch.folds) near_fold = near_fold || std::abs(f.after_point - int(i - 1)) <= 2;
    if (near_fold) continue;
    memo = std::make_unique<FloquetMemo>(hb, xs, fo);
    memo->add(P[i - 1], fr[i - 1]);
    memo->add(P[i], fr[i]);
    try {
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      double lo = 0.0, hi = 1.0;
      BranchPoint p1 = point_on_chord(hb, P[i - 1], P[i], c.scaling, hi - g, corrector_tolerance);
      BranchPoint p2 = point_on_chord(hb, P[i - 1], P[i], c.scaling, lo + g, corrector_tolerance);
      double m1 = floquet_at(p1.X, p1.omega).modulus;
      double m2 = floquet_at(p2.X, p2.omega).modulus;
      for (int k = 0; k < 10 && m1 < 1.0 && m2 < 1.0; ++k) {
        if (m1 > m2) {
          hi = lo + g * (hi - lo);
          p2 = p1, m2 = m1;
          p1 = point_on_chord(hb, P[i - 1], P[i], c.scaling, hi - g * (hi - lo), corrector_tolerance);
          m1 = floquet_at(p1.X, p1.omega).modulus;
        } else {
          lo = hi - g * (hi - lo);
          p1 = p2, m1 = m2;
          p2 = point_on_chord(hb, P[i - 1], P[i], c.scaling, lo + g * (hi - lo), corrector_tolerance);
          m2 = floquet_at(p2.X, p2.omega).modulus;
        }
      }
      if (std::max(m1, m2) < 1.0) continue;
      const BranchPoint& peak = m1 >= m2 ? p1 : p2;
      for (const auto& [a, b] : {std::pair{&P[i - 1], &peak}, std::pair{&peak, &P[i]}}) {
        const BranchPoint at = locate_state_change(hb, *a, *b, c.scaling, probe, 1e-9, corrector_tolerance);
        Bifurcation bf;
        bf.after_point = int(i) - 1;
        bf.omega = at.omega;
        bf.X = at.X;
        bf.multiplier = floquet_at(at.X, at.omega).critical;
        bf.type = crossing_type(bf.multiplier);
        if (bf.type == BifurcationType::fold) bf.type = BifurcationType::branch_point;   // +1 with no fold of the branch
        bf.smooth = std::fabs(std::abs(bf.multiplier) - 1.0) <= 1e-2;
        c.bifurcations.push_back(bf);
      }
    } catch (const std::exception&) {
      // a corrector failure on the chord: the interval is not searched further
    }
  }
}

}  // namespace

std::function<std::uint64_t(const Eigen::VectorXd&)> contact_regime(const HarmonicBalance& hb) {
  static_assert(2 * kMaxContacts <= 64, "two bits per contact in one 64-bit word");
  const auto aft = std::make_shared<Aft>(hb.harmonics(), std::max(256, 2 * hb.harmonics() + 2));
  return [aft, &hb](const Eigen::VectorXd& X) {
    std::uint64_t code = 0;
    for (std::size_t i = 0; i < hb.contacts().size(); ++i) {
      const Eigen::VectorXd uc = hb.penetration(X, i);
      code |= std::uint64_t(contact_state(uc, aft->to_time(uc))) << (2 * i);
    }
    return code;
  };
}

namespace {

// Step 1: the scaling of the sweep, refused where the model is beyond double precision.
Scaling checked_scaling(const HarmonicBalance& hb, const SweepOptions& opt, const std::string& label) {
  const Scaling s = hb.scaling(opt.omega_min, opt.omega_max);
  std::ostringstream os;
  if (!std::isfinite(s.residual))
    os << "case " << label << ": the model's stiffness scale is " << s.residual
       << " (a stiffness or contact stiffness that is not finite)";
  else if (!(s.x[0] >= 1e-150 && s.x[0] <= 1e150))
    os << "case " << label << ": the model's characteristic displacement over the range is " << s.x[0]
       << " (loads or stiffnesses beyond double precision: the response must lie within 1e-150 ... 1e150)";
  if (!os.str().empty()) throw std::invalid_argument(os.str());
  return s;
}

// Step 2: the continuation's options for the sweep: its direction, and steps across a
// change of the contact state kept short (continuation.hpp; contact_regime).
ContinuationOptions sweep_continuation(const HarmonicBalance& hb, const SweepOptions& opt) {
  ContinuationOptions co = opt.continuation;
  const bool up = opt.direction == SweepDirection::up;
  co.omega_start = up ? opt.omega_min : opt.omega_max;
  co.omega_end = up ? opt.omega_max : opt.omega_min;
  if (!co.regime && !hb.contacts().empty()) co.regime = contact_regime(hb);
  return co;
}

// Step 3: the branch. The first point: Newton from the linear guess inside the
// continuation (as always); if that fails, find_first_point's contact sets and
// forcing-amplitude continuation (first_point.hpp), and the continuation again from what
// it found. A first point on a fold pair whose branch leaves the range at its start (the
// stable low-amplitude orbit of a clearance oscillator below a superharmonic fold): the
// branch is followed outside the range by up to a quarter of the range, where it may turn
// at the pair's other fold and come back through the start. False: it cannot start
// (c.failure says why).
bool trace_branch(const HarmonicBalance& hb, const SweepOptions& opt, const ContinuationOptions& co,
                  const std::string& label, FrequencyCurve& c) {
  auto run = [&](const Eigen::VectorXd& X0) {
    return opt.natural ? natural_continuation(hb, X0, c.scaling, co) : arc_length_continuation(hb, X0, c.scaling, co);
  };
  bool started = false;
  FirstPointOptions fo;
  try {
    fo.linear_guess = linear_first_guess(hb, co.omega_start);
    c.branch = run(fo.linear_guess);
    started = !c.branch.points.empty();
  } catch (const std::invalid_argument&) {
    // neither linear guess is finite (K singular under a static load): find_first_point
  }
  if (!started) {
    fo.newton.tolerance = co.tolerance;
    fo.continuation = co;
    fo.continuation.progress = nullptr;
    const FirstPoint fp = find_first_point(hb, co.omega_start, c.scaling, fo);
    if (!fp.found) {
      std::ostringstream os;
      os << "case " << label << ": the sweep cannot start: no periodic solution found at omega = " << co.omega_start
         << " (" << fp.failure << ")";
      c.branch = Branch{};
      c.failure = os.str();
      return false;
    }
    c.first_point = fp.method;
    c.branch = run(fp.X);
  }
  if (!opt.natural && !c.branch.complete && !c.branch.failures.empty() && co.start_excursion == 0.0 &&
      c.branch.failures.back().what == "branch turned back out of the range at its start") {
    ContinuationOptions wide = co;
    wide.start_excursion = 0.25 * (opt.omega_max - opt.omega_min);
    Branch again = arc_length_continuation(hb, c.branch.points.front().X, c.scaling, wide);
    if (again.complete) c.branch = std::move(again);
  }
  c.complete = c.branch.complete;
  if (!c.complete) c.failure = "case " + label + ": " + failure_report(hb, c.branch);
  return true;
}

// Step 4: Floquet multipliers of every point's corrected orbit.
std::vector<FloquetResult> floquet_of_branch(const HarmonicBalance& hb, const SweepOptions& opt, FrequencyCurve& c) {
  std::vector<FloquetResult> fr;
  fr.reserve(c.branch.points.size());
  for (std::size_t i = 0; i < c.branch.points.size(); ++i) {
    const BranchPoint& p = c.branch.points[i];
    report(opt, "stability", c, i);
    fr.push_back(floquet_of_hb_orbit(hb, p.X, p.omega, c.scaling.x[0], opt.floquet));
    c.floquet.push_back(point_floquet(fr.back()));
    c.stable.push_back(fr.back().stable);
  }
  return fr;
}

// Step 5: bifurcations between consecutive points where the number of multipliers
// outside the unit circle changes (a real pair that merges into a complex pair outside
// the circle changes the counts per kind but not this number: no bifurcation). The
// change is located on the chord, and the multiplier nearest the circle there says which
// kind of crossing it is.
void locate_crossings(const HarmonicBalance& hb, const SweepOptions& opt, double corrector_tolerance,
                      const std::vector<FloquetResult>& fr, FrequencyCurve& c) {
  const auto& P = c.branch.points;
  const double xs = c.scaling.x[0];
  for (std::size_t i = 1; i < P.size(); ++i) {
    if (outside(c.floquet[i - 1]) == outside(c.floquet[i])) continue;
    report(opt, "bifurcations", c, i);
    // The probe: the count outside, and log |mu| of the crossing multiplier (zero on the circle).
    const PointFloquet &fa = c.floquet[i - 1], &fb = c.floquet[i];
    FloquetMemo memo(hb, xs, opt.floquet);
    memo.add(P[i - 1], fr[i - 1]);
    memo.add(P[i], fr[i]);
    auto state = [&memo, &opt, &fa, &fb, &c, i](const Eigen::VectorXd& X, double omega) {
      const FloquetResult& r = memo.at(X, omega, [&] { report(opt, "bifurcations", c, i, omega); });
      return StateProbe{outside(point_floquet(r)), std::log(std::abs(crossing_multiplier(r, fa, fb)))};
    };
    Bifurcation bf;
    bf.after_point = int(i) - 1;
    try {
      const BranchPoint at = locate_state_change(hb, P[i - 1], P[i], c.scaling, state, 1e-9, corrector_tolerance);
      bf.omega = at.omega;
      bf.X = at.X;
      bf.multiplier = crossing_multiplier(memo.at(at.X, at.omega), fa, fb);
    } catch (const std::exception&) {
      // corrector failure on the chord (rare): the second point's multiplier
      bf.located = false;
      bf.omega = P[i].omega;
      bf.multiplier = crossing_multiplier(fr[i], fa, fb);
    }
    bf.type = crossing_type(bf.multiplier);
    bf.smooth = bf.located && std::fabs(std::abs(bf.multiplier) - 1.0) <= 1e-2;
    if (bf.type == BifurcationType::fold) {
      // a fold of the branch (the corrected orbit's +1 crossing), or a branch point if
      // the HB branch has no fold near it: the two differ by the HB truncation error
      // (NLvib ex. 03 at H = 5: 5 points, 6e-4 relative in omega), so "near" is within
      // 2 points or 1e-3 relative
      bool fold = false;
      for (const auto& f : c.branch.folds)
        fold = fold || std::abs(f.after_point - bf.after_point) <= 2 ||
               std::fabs(f.omega - bf.omega) <= 1e-3 * std::fabs(f.omega);
      if (!fold) bf.type = BifurcationType::branch_point;
    }
    c.bifurcations.push_back(bf);
  }
}

// The real multiplier below zero nearest -1 (in |log |mu||), NaN if none.
std::complex<double> negative_real_nearest_minus_one(const FloquetResult& r) {
  std::complex<double> best(NAN, NAN);
  double d = INFINITY;
  for (Eigen::Index i = 0; i < r.multipliers.size(); ++i) {
    const auto m = r.multipliers[i];
    if (is_real(m) && m.real() < 0.0 && std::fabs(std::log(std::abs(m))) < d) d = std::fabs(std::log(std::abs(m))), best = m;
  }
  return best;
}

// Step 5b: the period doublings the count of step 5 misses. det(I + M) has the sign
// (-1)^(real multipliers below -1) (a complex pair contributes |1 + mu|^2 > 0, a real multiplier
// above -1 a positive factor), so it changes sign between two points exactly where an odd number
// of real multipliers crossed -1, whatever else crossed in the same step. Step 5 sees a change
// of the number outside the circle and locates one crossing: a period doubling in the same step
// as a crossing the other way (count unchanged: a fold, the Kahraman-Singh oscillator near
// Omega = 0.3148) or as a Neimark-Sacker pair (count 2 -> 1: ch. 6 Fig. 40 near 9.16 krad/s,
// where a period-2 branch merged "where no PD was located") is not listed. Here every step whose
// parity of real multipliers below -1 changes and that lists no period doubling gets one: the
// change of that parity located on the chord as step 5 locates the count (indicator log |mu| of
// the real multiplier below zero nearest -1), `smooth` as there (a multiplier that jumps across
// -1, at a grazing orbit, gives smooth = 0). Costs nothing where no such step exists.
void add_period_doublings_by_parity(const HarmonicBalance& hb, const SweepOptions& opt, double corrector_tolerance,
                                    const std::vector<FloquetResult>& fr, FrequencyCurve& c) {
  const auto& P = c.branch.points;
  const std::size_t listed = c.bifurcations.size();
  for (std::size_t i = 1; i < P.size(); ++i) {
    if (c.floquet[i - 1].outside_real_negative % 2 == c.floquet[i].outside_real_negative % 2) continue;
    bool has_pd = false;
    for (std::size_t k = 0; k < listed; ++k)
      has_pd = has_pd || (c.bifurcations[k].after_point == int(i) - 1 &&
                          c.bifurcations[k].type == BifurcationType::period_doubling);
    if (has_pd) continue;
    report(opt, "bifurcations", c, i);
    FloquetMemo memo(hb, c.scaling.x[0], opt.floquet);
    memo.add(P[i - 1], fr[i - 1]);
    memo.add(P[i], fr[i]);
    // the multiplier below -1 of the last trial on the odd side: the one that crossed, where it
    // jumps across -1 (the located point, on the even side, may have no real multiplier below 0)
    std::complex<double> odd_side(NAN, NAN);
    auto probe = [&memo, &opt, &c, i, &odd_side](const Eigen::VectorXd& X, double omega) {
      const FloquetResult& r = memo.at(X, omega, [&] { report(opt, "bifurcations", c, i, omega); });
      const int parity = point_floquet(r).outside_real_negative % 2;
      const std::complex<double> m = negative_real_nearest_minus_one(r);
      if (parity == 1) odd_side = m;
      return StateProbe{parity, std::log(std::abs(m))};
    };
    // of the located point's and the odd side's real multiplier below 0, the one nearest -1
    auto crossing = [&odd_side](const FloquetResult& r) {
      const std::complex<double> m = negative_real_nearest_minus_one(r);
      if (!std::isfinite(m.real())) return std::isfinite(odd_side.real()) ? odd_side : std::complex<double>(0.0);
      if (!std::isfinite(odd_side.real())) return m;
      return std::fabs(std::log(std::abs(m))) <= std::fabs(std::log(std::abs(odd_side))) ? m : odd_side;
    };
    Bifurcation bf;
    bf.type = BifurcationType::period_doubling;
    bf.after_point = int(i) - 1;
    try {
      const BranchPoint at = locate_state_change(hb, P[i - 1], P[i], c.scaling, probe, 1e-9, corrector_tolerance);
      bf.omega = at.omega;
      bf.X = at.X;
      bf.multiplier = crossing(memo.at(at.X, at.omega));
    } catch (const std::exception&) {
      bf.located = false;
      bf.omega = P[i].omega;
      bf.multiplier = crossing(fr[i]);
    }
    bf.smooth = bf.located && std::fabs(std::abs(bf.multiplier) - 1.0) <= 1e-2;
    c.bifurcations.push_back(bf);
  }
  if (c.bifurcations.size() > listed)
    std::stable_sort(c.bifurcations.begin(), c.bifurcations.end(),
                     [](const Bifurcation& a, const Bifurcation& b) { return a.after_point < b.after_point; });
}

}  // namespace

FrequencyCurve sweep_frequency(const HarmonicBalance& hb, const SweepOptions& opt,
                               const std::string& label) {
  FrequencyCurve c;
  c.natural = opt.natural;
  c.stability = opt.stability;
  c.scaling = checked_scaling(hb, opt, label);
  const ContinuationOptions co = sweep_continuation(hb, opt);
  if (!trace_branch(hb, opt, co, label, c)) return c;
  analyse_stability(hb, opt, c);
  return c;
}

void analyse_stability(const HarmonicBalance& hb, const SweepOptions& opt, FrequencyCurve& c) {
  const std::size_t points = c.branch.points.size();
  if (opt.stability == StabilityMethod::hill || opt.hill_cross_check) c.hill_stable = branch_stability(hb, c.branch);
  if (opt.stability == StabilityMethod::hill) c.stable = c.hill_stable;
  if (opt.stability == StabilityMethod::none) c.stable.assign(points, true);
  if (opt.stability != StabilityMethod::floquet) return;
  const std::vector<FloquetResult> fr = floquet_of_branch(hb, opt, c);
  if (!opt.locate_bifurcations || opt.natural) return;
  const double tolerance = opt.continuation.tolerance;
  locate_crossings(hb, opt, tolerance, fr, c);
  add_period_doublings_by_parity(hb, opt, tolerance, fr, c);
  const bool parametric = std::any_of(hb.contacts().begin(), hb.contacts().end(),
                                      [](const UnilateralContact& ct) { return bool(ct.stiffness_profile); });
  if (opt.narrow_bands == BandSearch::always || (opt.narrow_bands == BandSearch::parametric && parametric)) {
    add_narrow_bands(hb, c, c.scaling.x[0], opt, tolerance, fr);
    std::stable_sort(c.bifurcations.begin(), c.bifurcations.end(),
                     [](const Bifurcation& a, const Bifurcation& b) { return a.after_point < b.after_point; });
  }
  c.bifurcations = one_entry_per_crossing(hb, c, c.scaling.x[0], opt.floquet);
}

namespace {
std::function<bool(const Eigen::VectorXd&)> state_predicate(const HarmonicBalance& hb,
                                                            ContactState not_this, int contact) {
  if (contact >= int(hb.contacts().size()))
    throw std::invalid_argument("contact predicate: contact " + std::to_string(contact) + " of " +
                                std::to_string(hb.contacts().size()));
  // The state does not depend on the plotted coordinate; 256 samples per period.
  const auto ev = std::make_shared<const ResponseEvaluator>(hb, Eigen::VectorXd::Zero(hb.dofs()), 256);
  return [ev, not_this, contact](const Eigen::VectorXd& X) {
    const ResponseSummary s = ev->summarize(X);
    return (contact < 0 ? s.contact : s.contact_states[std::size_t(contact)]) != not_this;
  };
}
}  // namespace

std::function<bool(const Eigen::VectorXd&)> touches_somewhere(const HarmonicBalance& hb, int contact) {
  return state_predicate(hb, ContactState::open, contact);
}
std::function<bool(const Eigen::VectorXd&)> opens_somewhere(const HarmonicBalance& hb, int contact) {
  return state_predicate(hb, ContactState::full, contact);
}

double first_transition(const HarmonicBalance& hb, const FrequencyCurve& c,
                        const std::function<bool(const Eigen::VectorXd&)>& state,
                        const TransitionOptions& opt) {
  const auto& P = c.branch.points;
  for (std::size_t i = 1; i < P.size(); ++i)
    if (!state(P[i - 1].X) && state(P[i].X))
      return locate_transition(hb, P[i - 1], P[i], c.scaling, state, opt);
  return NAN;
}

TimeIntegrationCheck compare_with_time_integration(const HarmonicBalance& hb, const FrequencyCurve& c,
                                                   const Eigen::VectorXd& q,
                                                   const TimeIntegrationCheckOptions& opt) {
  ResponseEvaluator ev(hb, q);
  const auto& P = c.branch.points;
  // Eligible points: stable, in the requested state, away from every fold.
  std::vector<std::size_t> eligible;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const ResponseSummary r = ev.summarize(P[i].X);
    if (!c.stable[i] || r.contact != opt.state) continue;
    if (c.floquet.size() == P.size() && c.floquet[i].modulus > opt.max_multiplier) continue;
    if (r.grazing_distance < opt.min_grazing_distance) continue;
    if (r.x_max < opt.min_crest_fraction * 0.5 * (r.x_max - r.x_min)) continue;
    bool near = false;
    for (const auto& f : c.branch.folds) near = near || std::fabs(f.omega - P[i].omega) < opt.fold_margin * f.omega;
    if (near || (opt.accept && !opt.accept(i))) continue;
    eligible.push_back(i);
  }
  TimeIntegrationCheck out;
  if (eligible.empty()) return out;
  // Up to opt.points of them, evenly spread along the branch.
  std::vector<std::size_t> chosen;
  const std::size_t m = std::min<std::size_t>(opt.points, eligible.size());
  for (std::size_t j = 0; j < m; ++j)
    chosen.push_back(eligible[m == 1 ? 0 : j * (eligible.size() - 1) / (m - 1)]);

  TimeIntegrator ti(hb);
  TimeIntegrationOptions to;
  to.x_scale = c.scaling.x[0];
  for (std::size_t i : chosen) {
    const auto r = ev.summarize(P[i].X);
    Eigen::VectorXd x0, v0;
    hb_initial_state(hb, P[i].X, P[i].omega, x0, v0);
    const SteadyState ss = ti.steady_state(x0, v0, P[i].omega, to);
    if (!ss.converged) {
      std::ostringstream os;
      os << "time integration did not reach a periodic state at omega = " << P[i].omega * opt.omega_factor
         << " rad/s after " << ss.periods << " periods (mismatch " << ss.mismatch << ")";
      throw std::runtime_error(os.str());
    }
    const double xm = (ss.x * q).maxCoeff();
    const double rel = std::fabs(r.x_max - xm) / std::fabs(xm);
    out.worst_rel_diff = std::max(out.worst_rel_diff, rel);
    out.rows.push_back({P[i].omega * opt.omega_factor, r.x_max, xm, rel, int(ss.periods), r.contact});
    ++out.points;
  }
  return out;
}

}  // namespace gearhb
