#include "gearhb/hb/bifurcation_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "gearhb/core/gsl_errors.hpp"

namespace gearhb {

const char* to_string(Motion m) {
  switch (m) {
    case Motion::periodic: return "periodic";
    case Motion::quasi_periodic: return "quasi_periodic";
    case Motion::chaotic: return "chaotic";
    case Motion::unsettled: return "unsettled";
    case Motion::failed: break;
  }
  return "failed";
}

std::string check_bifurcation_options(const BifurcationDiagramOptions& o, std::string* why) {
  auto bad = [&](const char* key, const std::string& text) {
    if (why) *why = text;
    return std::string(key);
  };
  if (o.speeds < 2 || o.speeds > 100000) return bad("speeds", "must be a whole number in [2, 100000]");
  if (o.transient_periods < 0 || o.transient_periods > 1000000)
    return bad("transient_periods", "must be a whole number in [0, 1000000]");
  if (o.max_period < 1 || o.max_period > 64) return bad("max_period", "must be a whole number in [1, 64]");
  if (o.periods < 2 * o.max_period || o.periods > 100000)
    return bad("periods", "must be a whole number in [2 max_period, 100000] (a period must repeat at least twice)");
  if (!(o.period_tol >= 1e-14 && o.period_tol <= 0.1)) return bad("period_tol", "must be in [1e-14, 0.1]");
  if (o.lyapunov_periods < 10 || o.lyapunov_periods > 1000000)
    return bad("lyapunov_periods", "must be a whole number in [10, 1000000]");
  if (o.lyapunov_min_periods != 0 && (o.lyapunov_min_periods < 30 || o.lyapunov_min_periods > 1000000))
    return bad("lyapunov_min_periods", "must be 0 (off) or a whole number in [30, 1000000]");
  if (!(o.lyapunov_threshold > 0.0 && o.lyapunov_threshold <= 1.0))
    return bad("lyapunov_threshold", "must be in (0, 1]");
  return "";
}

namespace {
// The Poincare state S = (x, v / omega) (both halves displacements).
Eigen::VectorXd section_state(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double omega) {
  Eigen::VectorXd s(2 * x.size());
  s << x, v / omega;
  return s;
}
}  // namespace

int poincare_period(const Eigen::MatrixXd& xs, const Eigen::MatrixXd& vs, double omega, int max_period, double tol) {
  const Eigen::Index rows = xs.rows();
  for (int n = 1; n <= max_period && n < rows; ++n) {
    bool repeats = true;
    for (Eigen::Index j = 0; j + n < rows && repeats; ++j) {
      const double dx = (xs.row(j + n) - xs.row(j)).cwiseAbs().maxCoeff();
      const double dv = (vs.row(j + n) - vs.row(j)).cwiseAbs().maxCoeff() / omega;
      repeats = std::max(dx, dv) <= tol;
    }
    if (repeats) return n;
  }
  return 0;
}

double largest_lyapunov_exponent(const TimeIntegrator& ti, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                 double omega, int periods, const TimeIntegrationOptions& opt, Eigen::VectorXd* x_end,
                                 Eigen::VectorXd* v_end) {
  return lyapunov_exponents(ti, x0, v0, omega, periods, 1, opt, x_end, v_end)[0];
}

std::vector<double> lyapunov_exponents(
    const TimeIntegrator& ti, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double omega, int periods,
    int count, const TimeIntegrationOptions& opt, Eigen::VectorXd* x_end, Eigen::VectorXd* v_end,
    const std::function<void(const Eigen::VectorXd&, const Eigen::VectorXd&)>& section, Eigen::MatrixXd* logs,
    const std::function<bool(const Eigen::VectorXd&)>& stop, int* periods_done) {
  const Eigen::Index n = x0.size();
  if (count < 1 || count > 2 * n) throw std::invalid_argument("Lyapunov exponents: count must be 1..2 dofs");
  if (periods < 1) throw std::invalid_argument("Lyapunov exponents: periods must be >= 1");
  Eigen::VectorXd x = x0, v = v0, xT, vT;
  // The tangent vectors in (x, v / omega): the first with every component alike, the others
  // along the unit vectors, made orthonormal.
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(2 * n, count);
  W.col(0) = Eigen::VectorXd::Ones(2 * n).normalized();
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(count);
  Eigen::VectorXd ln_r(count);
  if (logs) logs->setZero(periods, count);
  int done = 0;
  for (int k = 0; k <= periods; ++k) {
    for (int j = 0; j < count; ++j) {   // modified Gram-Schmidt: W = Q R, Q into W
      for (int i = 0; i < j; ++i) W.col(j) -= W.col(i).dot(W.col(j)) * W.col(i);
      const double r = W.col(j).norm();
      if (!(r > 0.0) || !std::isfinite(r))
        throw std::runtime_error("Lyapunov exponents: a tangent vector vanished or diverged");
      ln_r[j] = std::log(r);
      if (k > 0) sum[j] += ln_r[j];
      if (k > 0 && logs) (*logs)(k - 1, j) = ln_r[j];
      W.col(j) /= r;
    }
    done = k;
    if (k == periods || (k > 0 && stop && stop(ln_r))) break;
    ti.tangent_map(x, v, omega, opt, W, xT, vT);   // W in (x, v / omega) through one period
    x = xT, v = vT;
    if (section) section(x, v);
  }
  if (x_end) *x_end = x;
  if (v_end) *v_end = v;
  if (logs) logs->conservativeResize(done, count);
  if (periods_done) *periods_done = done;
  std::vector<double> out(count);
  for (int j = 0; j < count; ++j) out[j] = sum[j] / done;
  return out;
}

namespace {
// The states after 1..periods forcing periods from (x, v) (rows of xs, vs) and the product of
// the period maps' monodromy matrices.
void chain(const TimeIntegrator& ti, double omega, int periods, const TimeIntegrationOptions& opt, Eigen::VectorXd x,
           Eigen::VectorXd v, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs, Eigen::MatrixXd& M) {
  xs.resize(periods, x.size());
  vs.resize(periods, x.size());
  M = Eigen::MatrixXd::Identity(2 * x.size(), 2 * x.size());
  for (int k = 0; k < periods; ++k) {
    Eigen::VectorXd xT, vT;
    Eigen::MatrixXd Phi;
    ti.period_map(x, v, omega, opt, xT, vT, Phi);
    M = Phi * M;
    x = xT, v = vT;
    xs.row(k) = x.transpose();
    vs.row(k) = v.transpose();
  }
}

// The n states of the cycle through (x, v) whose states after 1..n periods are the rows of xs, vs
// (shoot_cycle's), reduced to its least period m (the first m dividing n after which it repeats
// within tol in (x, v / omega)), into cx, cv (rows; (x, v) first); returns m.
int cycle_states(const Eigen::VectorXd& x, const Eigen::VectorXd& v, const Eigen::MatrixXd& xs, const Eigen::MatrixXd& vs,
                 int n, double omega, double tol, Eigen::MatrixXd& cx, Eigen::MatrixXd& cv) {
  for (int m = 1; m < n; ++m)
    if (n % m == 0 && std::max((xs.row(m - 1).transpose() - x).cwiseAbs().maxCoeff(),
                               (vs.row(m - 1).transpose() - v).cwiseAbs().maxCoeff() / omega) <= tol) {
      n = m;
      break;
    }
  cx.resize(n, x.size());
  cv.resize(n, x.size());
  cx.row(0) = x.transpose();
  cv.row(0) = v.transpose();
  for (int k = 1; k < n; ++k) cx.row(k) = xs.row(k - 1), cv.row(k) = vs.row(k - 1);
  return n;
}
}  // namespace

bool shoot_cycle(const TimeIntegrator& ti, double omega, int n, double tol, const TimeIntegrationOptions& opt,
                 Eigen::VectorXd& x, Eigen::VectorXd& v, Eigen::MatrixXd& xs, Eigen::MatrixXd& vs, double& modulus) {
  const Eigen::Index d = x.size();
  Eigen::VectorXd S(2 * d), F(2 * d);
  S << x, v;
  Eigen::MatrixXd M;
  bool converged = false;
  for (int it = 0; it < 12 && !converged; ++it) {
    chain(ti, omega, n, opt, S.head(d), S.tail(d), xs, vs, M);
    F << xs.row(n - 1).transpose() - S.head(d), vs.row(n - 1).transpose() - S.tail(d);
    converged = std::max(F.head(d).cwiseAbs().maxCoeff(), F.tail(d).cwiseAbs().maxCoeff() / omega) <= 1e-2 * tol;
    if (!converged) S -= (M - Eigen::MatrixXd::Identity(2 * d, 2 * d)).partialPivLu().solve(F);
    if (!S.allFinite()) return false;
  }
  if (!converged) return false;
  chain(ti, omega, n, opt, S.head(d), S.tail(d), xs, vs, M);   // the orbit and its monodromy at the fixed point
  modulus = M.eigenvalues().cwiseAbs().maxCoeff();
  x = S.head(d), v = S.tail(d);
  return true;
}

int attracting_cycle(const TimeIntegrator& ti, const DiagramPoint& p, const Eigen::VectorXd& x_end,
                     const Eigen::VectorXd& v_end, int max_period, double tol, const TimeIntegrationOptions& opt,
                     Eigen::MatrixXd& cx, Eigen::MatrixXd& cv) {
  const Eigen::Index rows = p.x.rows(), d = x_end.size();
  if (rows < 2) return 0;
  const double w = p.omega;
  auto state = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
    Eigen::VectorXd s(2 * d);
    s << x, v / w;
    return s;
  };
  auto recorded = [&](Eigen::Index j) { return state(p.x.row(j).transpose(), p.v.row(j).transpose()); };
  // The candidate period: the smallest repetition error at the end of the recording.
  int n = 1;
  double best = INFINITY;
  for (int m = 1; m <= max_period && m < rows; ++m) {
    const double r = (recorded(rows - 1) - recorded(rows - 1 - m)).cwiseAbs().maxCoeff();
    if (r < best) best = r, n = m;
  }
  // Newton shooting on the n-period map from the last state.
  Eigen::VectorXd x = x_end, v = v_end;
  Eigen::MatrixXd xs, vs;
  double modulus = INFINITY;
  if (!shoot_cycle(ti, w, n, tol, opt, x, v, xs, vs, modulus) || modulus >= 1.0) return 0;   // none, or not attracting
  const Eigen::VectorXd Sstar = state(x, v);
  if (!((state(x_end, v_end) - Sstar).cwiseAbs().maxCoeff() < (recorded(0) - Sstar).cwiseAbs().maxCoeff()))
    return 0;   // the integration is not approaching it
  return cycle_states(x, v, xs, vs, n, w, tol, cx, cv);
}

bool polish_periodic_point(const TimeIntegrator& ti, DiagramPoint& p, double tol, const TimeIntegrationOptions& opt) {
  if (p.motion != Motion::periodic || p.n < 1 || p.x.rows() < 1) return false;
  Eigen::VectorXd x = p.x.bottomRows(1).transpose(), v = p.v.bottomRows(1).transpose();
  Eigen::MatrixXd xs, vs, cx, cv;
  double modulus = INFINITY;
  if (!shoot_cycle(ti, p.omega, p.n, tol, opt, x, v, xs, vs, modulus) || modulus >= 1.0) return false;
  if (cycle_states(x, v, xs, vs, p.n, p.omega, tol, cx, cv) != p.n) return false;   // a cycle of lower period
  p.x = cx, p.v = cv;
  return true;
}

namespace {
// The sequential stop of the Lyapunov estimate (the options' lyapunov_min_periods says why):
// fed ln |Phi_k w_k| period by period; true once, at the end of a block of kLyapunovBlock
// periods after at least lyapunov_min_periods, the mean of the block means after the first
// (lambda') exceeds lyapunov_threshold by more than 3 standard errors of that mean (the
// batch-means scatter: sd of the block means / sqrt(their number)).
constexpr int kLyapunovBlock = 10;
class LyapunovStop {
 public:
  explicit LyapunovStop(const BifurcationDiagramOptions& o) : min_(o.lyapunov_min_periods), threshold_(o.lyapunov_threshold) {}
  bool operator()(const Eigen::VectorXd& ln_r) {
    block_ += ln_r[0];
    if (++k_ % kLyapunovBlock != 0) return false;
    if (k_ > kLyapunovBlock) means_.push_back(block_ / kLyapunovBlock);   // the first block: the tangent vector aligning
    block_ = 0.0;
    if (min_ == 0 || k_ < min_ || means_.size() < 2) return false;
    const Eigen::Map<const Eigen::VectorXd> b(means_.data(), Eigen::Index(means_.size()));
    const double mean = b.mean();
    const double sd = std::sqrt((b.array() - mean).square().sum() / double(b.size() - 1));
    return mean - threshold_ > 3.0 * sd / std::sqrt(double(b.size()));
  }

 private:
  int min_, k_ = 0;
  double threshold_, block_ = 0.0;
  std::vector<double> means_;
};

// One speed of a sweep: integrate from (x, v), record, classify (see the header); (x, v) become
// the state the next speed starts from.
void diagram_speed(const TimeIntegrator& ti, const BifurcationDiagramOptions& opt, double tol, DiagramPoint& p,
                   Eigen::VectorXd& x, Eigen::VectorXd& v) {
  // The transient ends once the Poincare point repeats after n <= max_period periods within
  // period_tol / 100: a period-1 orbit approached with a multiplier mu near -1 repeats after 2
  // periods |mu^2 - 1| / |mu - 1| times more closely than after 1, so a transient ended at
  // period_tol would be read as period 2; at period_tol / 100 it is not unless |mu| > 0.99.
  std::deque<Eigen::VectorXd> last;
  auto settled = [&](const Eigen::VectorXd& xk, const Eigen::VectorXd& vk) {
    const Eigen::VectorXd S = section_state(xk, vk, p.omega);
    bool repeats = false;
    for (std::size_t j = 0; j < last.size() && !repeats; ++j)
      repeats = (S - last[last.size() - 1 - j]).cwiseAbs().maxCoeff() <= 0.01 * tol;
    last.push_back(S);
    if (int(last.size()) > opt.max_period) last.pop_front();
    return repeats;
  };
  try {
    ti.poincare(x, v, p.omega, opt.transient_periods, opt.periods, opt.integration, p.x, p.v, settled, &p.transient);
    x = p.x.bottomRows(1).transpose();
    v = p.v.bottomRows(1).transpose();
    p.n = poincare_period(p.x, p.v, p.omega, opt.max_period, tol);
    if (p.n > 0) {
      p.motion = Motion::periodic;
      return;
    }
    Eigen::VectorXd xe, ve;
    LyapunovStop stop(opt);
    p.lyapunov = lyapunov_exponents(ti, x, v, p.omega, opt.lyapunov_periods, 1, opt.integration, &xe, &ve, {}, nullptr,
                                    std::ref(stop), &p.lyapunov_periods)[0];
    if (p.lyapunov_periods < opt.lyapunov_periods) {   // stopped early: the rest of the dwell without the tangent
      Eigen::MatrixXd xs, vs;
      ti.poincare(xe, ve, p.omega, 0, opt.lyapunov_periods - p.lyapunov_periods, opt.integration, xs, vs);
      x = xs.bottomRows(1).transpose(), v = vs.bottomRows(1).transpose();
      // A chaotic transient that settled within the dwell: its last Poincare points repeat.
      const Eigen::Index tail = std::min<Eigen::Index>(xs.rows(), 2 * opt.max_period + 1);
      const int n = poincare_period(xs.bottomRows(tail), vs.bottomRows(tail), p.omega, opt.max_period, tol);
      if (tail > 2 * n && n > 0) {
        p.motion = Motion::periodic, p.n = n;
        p.x = xs.bottomRows(tail), p.v = vs.bottomRows(tail);
        return;
      }
      p.motion = Motion::chaotic;   // lambda' clearly above the threshold (LyapunovStop)
      return;
    }
    x = xe, v = ve;
    p.motion = p.lyapunov > opt.lyapunov_threshold    ? Motion::chaotic
               : p.lyapunov >= -opt.lyapunov_threshold ? Motion::quasi_periodic
                                                       : Motion::unsettled;
    if (p.motion == Motion::chaotic) return;
    Eigen::MatrixXd cx, cv;
    const int n = attracting_cycle(ti, p, x, v, opt.max_period, tol, opt.integration, cx, cv);
    if (n > 0) {
      p.motion = Motion::periodic, p.n = n, p.by_shooting = true;
      p.x = cx, p.v = cv;
      x = cx.row(0).transpose(), v = cv.row(0).transpose();
    }
  } catch (const std::runtime_error& e) {   // this speed fails; the next starts from the last good state
    p.motion = Motion::failed;
    p.failure = e.what();
    p.x.resize(0, x.size());
    p.v.resize(0, x.size());
  }
}
}  // namespace

std::vector<double> sweep_speeds(double omega_min, double omega_max, int speeds, const std::vector<double>& added) {
  std::vector<double> w;
  for (int k = 0; k < speeds; ++k) w.push_back(omega_min + (omega_max - omega_min) * double(k) / double(speeds - 1));
  for (double a : added)
    if (std::isfinite(a) && a > omega_min && a < omega_max) w.push_back(a);
  std::sort(w.begin(), w.end());
  w.erase(std::unique(w.begin(), w.end()), w.end());
  return w;
}

std::vector<double> speeds_missed(double omega_min, double omega_max, int speeds,
                                  const std::vector<std::pair<double, double>>& ranges) {
  const std::vector<double> grid = sweep_speeds(omega_min, omega_max, speeds, {});
  std::vector<double> out;
  for (const auto& [from, to] : ranges) {
    const double a = std::max(from, omega_min), b = std::min(to, omega_max);
    if (!(a <= b)) continue;
    if (std::none_of(grid.begin(), grid.end(), [&](double w) { return a <= w && w <= b; })) out.push_back(0.5 * (a + b));
  }
  return out;
}

DiagramPoint diagram_point(const HarmonicBalance& hb, double omega, const Eigen::VectorXd& x0,
                           const Eigen::VectorXd& v0, const BifurcationDiagramOptions& opt) {
  std::string why;
  const std::string key = check_bifurcation_options(opt, &why);
  if (!key.empty()) throw std::invalid_argument("diagram point: " + key + " " + why);
  if (!(omega > 0.0)) throw std::invalid_argument("diagram point: needs omega > 0");
  if (x0.size() != hb.dofs() || v0.size() != hb.dofs())
    throw std::invalid_argument("diagram point: x0, v0 must hold one value per dof");
  const TimeIntegrator ti(hb);
  DiagramPoint p;
  p.omega = omega;
  p.from_orbit = true;
  Eigen::VectorXd x = x0, v = v0;
  diagram_speed(ti, opt, opt.period_tol * opt.integration.x_scale, p, x, v);
  return p;
}

BifurcationDiagram bifurcation_diagram(const HarmonicBalance& hb, double omega_min, double omega_max,
                                       const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                                       const BifurcationDiagramOptions& opt,
                                       const std::function<void(const DiagramPoint&, int)>& progress) {
  std::string why;
  const std::string key = check_bifurcation_options(opt, &why);
  if (!key.empty()) throw std::invalid_argument("bifurcation diagram: " + key + " " + why);
  if (!(omega_min > 0.0 && omega_max > omega_min)) throw std::invalid_argument("bifurcation diagram: needs 0 < omega_min < omega_max");
  const bool down_given = opt.down_x0.size() > 0 || opt.down_v0.size() > 0;
  if (down_given && (opt.down_x0.size() != x0.size() || opt.down_v0.size() != x0.size()))
    throw std::invalid_argument("bifurcation diagram: down_x0, down_v0 must be empty or hold one value per dof");
  const TimeIntegrator ti(hb);
  const double tol = opt.period_tol * opt.integration.x_scale;
  const std::vector<double> omegas = sweep_speeds(omega_min, omega_max, opt.speeds, opt.added_speeds);
  const std::vector<double> grid = sweep_speeds(omega_min, omega_max, opt.speeds, {});
  const int N = int(omegas.size());
  BifurcationDiagram d;
  d.points.resize(2 * std::size_t(N));
  std::mutex reporting;
  // Sweep s (0 up, 1 down) from (x, v): the points s N .. s N + N - 1 (omega rising, then falling).
  auto sweep = [&](int s, Eigen::VectorXd x, Eigen::VectorXd v) {
    for (int j = 0; j < N; ++j) {
      DiagramPoint& p = d.points[std::size_t(s * N + j)];
      p.omega = omegas[std::size_t(s == 0 ? j : N - 1 - j)];
      p.added = !std::binary_search(grid.begin(), grid.end(), p.omega);
      p.up = s == 0;
      diagram_speed(ti, opt, tol, p, x, v);
      if (progress) {
        const std::lock_guard<std::mutex> lock(reporting);
        progress(p, s * N + j);
      }
    }
    return std::make_pair(x, v);
  };
  if (!down_given) {
    const auto end = sweep(0, x0, v0);
    sweep(1, end.first, end.second);
    return d;
  }
  // Two threads: every GSL call site switches the error handler off and restores the one it
  // found; with the handler off here first, every thread finds and restores "off".
  const GslErrorsReturned gsl_errors;
  std::exception_ptr failed_down;
  std::thread down([&] {
    try {
      sweep(1, opt.down_x0, opt.down_v0);
    } catch (...) {
      failed_down = std::current_exception();
    }
  });
  try {
    sweep(0, x0, v0);
  } catch (...) {
    down.join();
    throw;
  }
  down.join();
  if (failed_down) std::rethrow_exception(failed_down);
  return d;
}

}  // namespace gearhb
