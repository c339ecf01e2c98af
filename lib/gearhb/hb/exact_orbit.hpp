#pragma once
// The response measures of the exact periodic orbit (issue 25).
//
// floquet_of_hb_orbit (floquet.hpp) corrects every harmonic-balance point by
// Newton's method on the exact period map of the piecewise-linear flow; the corrected
// state (x0, v0) at phase 0 lies on the true periodic solution to the shooting
// tolerance (1e-10), whatever H was. ExactOrbit follows that orbit once more over one
// period, piece by piece (FlowSegment: between the shooting nodes and the exact contact
// switches, z(t0 + s) = exp(A_S s) z0), and measures a coordinate y = q' x on it:
//   x_mean, x_rms_ac, x_h1  integrals over the period by Gauss-Legendre quadrature
//                           (8 points) on every piece, cut into sub-pieces with
//                           h x rate <= 1 (the pieces are analytic: the rule is exact
//                           to rounding, ~1e-16 relative), the bound relaxed as a damped
//                           mode decays within the piece (exact_orbit.cpp sub_piece);
//   x_max, x_min            the largest and smallest of y at every sub-piece end
//                           (including the contact switches) and at every zero of y'
//                           bracketed on the quadrature nodes, refined by safeguarded
//                           Newton with y'' from the generator;
// and the mean contact force (1/T) int kc max(u_i, 0) dt the same way over the pieces
// where contact i is closed. The names are those of ResponseSummary (response.hpp):
// the tables write them with the suffix `_exact` (lib/README "Output files").
//
// `consistent` checks the pieces: at every quadrature node each contact's penetration
// has the sign of the piece's contact state (to 1e-8 of the penetration's range), so a
// contact touch that the shooting nodes stepped over is reported, not hidden. An orbit
// that is not finite (or no period: omega not positive and finite) throws std::runtime_error.
// Only for a constant contact stiffness (a time-varying one has no piecewise-linear
// flow: the constructor throws std::invalid_argument, as PiecewiseLinearFlow does).
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gearhb/hb/floquet.hpp"
#include "gearhb/hb/frequency_sweep.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

// The measures of one coordinate on the exact orbit (ResponseSummary's names).
struct ExactMeasures {
  double x_max = NAN, x_min = NAN, x_rms_ac = NAN, x_h1 = NAN, x_mean = NAN;
};

class ExactOrbit {
 public:
  // The orbit through (x0, v0) at phase 0 (FloquetResult::x0, v0 of a corrected point);
  // X, the HB point it was corrected from, places the shooting nodes (shooting_nodes).
  ExactOrbit(const HarmonicBalance& hb, const Eigen::VectorXd& X, double omega, const Eigen::VectorXd& x0,
             const Eigen::VectorXd& v0, int steps = 0);
  ExactMeasures measures(const Eigen::VectorXd& q) const;
  double mean_contact_force(std::size_t i) const;
  // x at time t in [0, T] (T = 2 pi / omega).
  Eigen::VectorXd x_at(double t) const;
  // max(|x(T) - x0|, |v(T) - v0| / omega) / max |x| over the orbit: how periodic it is.
  double period_mismatch() const { return mismatch_; }
  // No contact penetration of the wrong sign at any quadrature node (see above).
  bool consistent() const { return consistent_; }
  double omega() const { return omega_; }
  // Sub-pieces followed, and the contact states among them whose propagator uses Pade
  // exponentials (floquet.hpp: not diagonalisable to cond 1e4; each node then costs more).
  std::size_t pieces() const { return pieces_.size(); }
  int pade_states() const { return flow_.pade_states(); }

 private:
  struct Piece {          // a sub-piece of a FlowSegment
    double t0 = 0.0, h = 0.0;
    unsigned state = 0;
    Eigen::VectorXd z0;   // state at t0
  };
  PiecewiseLinearFlow flow_;
  double omega_, T_;
  int n_;
  std::vector<Piece> pieces_;
  Eigen::MatrixXd z_;           // augmented state at every quadrature node (columns)
  Eigen::VectorXd t_, w_;       // node times and weights
  std::vector<unsigned> state_; // contact state of every node
  double mismatch_ = 0.0;
  bool consistent_ = true;
  double extremum(const Piece& p, const Eigen::VectorXd& q, double lo, double hi) const;
  void split_into_pieces(const std::vector<FlowSegment>& segments);   // the constructor's steps
  void place_nodes();
  void check(const HarmonicBalance& hb, const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, const Eigen::VectorXd& xT,
             const Eigen::VectorXd& vT);
};

// Whether a point of a frequency curve has exact measures (the tables' `exact` column):
//  ok             the corrected orbit, consistent (every contact switch on the pieces);
//  not_converged  the shooting Newton did not reach FloquetOptions::tolerance (near a
//                 grazing orbit or a bifurcation, or H far from the truth);
//  inconsistent   following the corrected orbit failed or stepped over a contact switch;
//  lower_period   a period-p point whose corrected orbit repeats after one forcing period
//                 (FloquetResult::lower_period): no exact orbit of period p there;
//  unavailable    no piecewise-linear flow (a time-varying contact stiffness: its
//                 multipliers come from the variational equation, not corrected) or the
//                 curve was computed without Floquet stability (Hill, none).
enum class ExactStatus { ok, not_converged, inconsistent, unavailable, lower_period };
const char* to_string(ExactStatus s);

struct ExactPoint {
  ExactStatus status = ExactStatus::unavailable;
  std::vector<ExactMeasures> measures;   // one per requested coordinate (NaN unless ok)
};

// The exact measures of point i of curve c for the coordinates qs' x.
ExactPoint exact_point(const HarmonicBalance& hb, const FrequencyCurve& c, std::size_t i,
                       const std::vector<Eigen::VectorXd>& qs);

}  // namespace gearhb
