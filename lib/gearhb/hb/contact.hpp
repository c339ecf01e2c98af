#pragma once
// Unilateral contact law (thesis §2.3, §3; lib/README.md "The method in one page"):
//
//     F_c = max( k_c (g + v), 0 ),     v = n' x  (relative displacement along the normal n)
//
// g > 0 is a preload (bodies pressed together at x = 0), g < 0 a gap. The force
// F_c acts on the structure as  -n F_c  (it pushes the DOFs along -n), so the
// equation of motion reads  M x'' + C x' + K x + n F_c = f(t)
// (n is the member `normal`).
// The gap may also vary periodically with the forcing phase (e.g. a
// transmission error): g(theta) = g + sum_k (gc_k cos k theta + gs_k sin k theta).
// So may the stiffness (a parametric contact, e.g. a gear mesh whose stiffness
// varies with the mesh phase): k_c(theta) = kc s(theta), s > 0 a 2 pi-periodic
// profile; since s > 0 the contact is closed exactly where g + v > 0, as for a
// constant kc, and the law stays piecewise linear in x.
#include <functional>
#include <vector>

#include <Eigen/Dense>

namespace gearhb {

struct UnilateralContact {
  Eigen::VectorXd normal;  // contact normal over the DOFs (v = normal' x)
  double kc = 0.0;         // contact stiffness [N/m]
  double gap = 0.0;        // g: > 0 preload, < 0 clearance [m]
  // Optional periodic part of the gap, real Fourier coefficients [0, a1, b1, ...]
  // in the harmonic-balance basis (empty = constant gap).
  Eigen::VectorXd gap_harmonics;
  // Optional stiffness profile s(theta) > 0 (2 pi-periodic, smooth inside the
  // contact intervals): the stiffness is kc s(theta). Empty = constant kc.
  std::function<double(double)> stiffness_profile = {};
};

// The most contacts a model may have: the exact flow (floquet.hpp) and the sweep's
// contact regime (frequency_sweep.cpp) index contact states by the bits of one word.
// HarmonicBalance refuses more; model files say so naming `contacts`.
constexpr int kMaxContacts = 30;

// The contact stiffness at phase theta: kc, or kc s(theta) with a profile.
inline double stiffness_at(const UnilateralContact& c, double theta) {
  return c.stiffness_profile ? c.kc * c.stiffness_profile(theta) : c.kc;
}

// The contact law and its derivative dF/dv (0 or kc; at u = 0 we take 0).
inline double contact_force(double kc, double u) { return u > 0.0 ? kc * u : 0.0; }
inline double contact_stiffness(double kc, double u) { return u > 0.0 ? kc : 0.0; }

// Contact state over one period, from the penetration samples u = g + v.
enum class ContactState { open, full, intermittent };
const char* to_string(ContactState s);

// Whether the contacts of `set` (bit i: contacts[i], i < 64) can all be closed at once,
// i.e. g_i + n_i'x > 0 for every i of the set at one x, with g_i the largest value of the
// gap over the period (gap plus the sum of its harmonics' amplitudes). Decided pair by
// pair: two contacts with opposite normals (n_j = -c n_i, c > 0) close together only if
// c g_i + g_j > 0 (a clearance on both sides of one coordinate: never). Exact for one
// DOF (Helly's theorem on the line: intervals meet iff every two do); for more DOFs a
// set that fails the pair test is impossible, one that passes is reported possible.
bool contacts_can_close_together(const std::vector<UnilateralContact>& contacts, unsigned long long set);

}  // namespace gearhb

// --- Exact Galerkin projection of the piecewise-linear law -------------------
//
// Sampling max(kc u, 0) at N points (plain AFT) makes the discrete residual
// piecewise linear in the coefficients, with a kink each time a sample enters or
// leaves contact; near a fold these kinks show up as spurious micro-folds whose
// size shrinks only slowly with N (ch. 3 sample study). Because u(theta) is a
// trigonometric polynomial and the law is linear inside contact, the projection
// can be done exactly instead:
//   1. locate every crossing u(theta) = 0: the N samples are only a starting
//      grid; with the bound |u''| <= sum k^2 (|a_k| + |b_k|) each grid interval is
//      proved root-free, or proved to hold exactly one (monotonic) root, or split
//      in two, so a contact interval between two samples (a narrow graze) is found
//      too and the result does not depend on N; each root is refined with GSL's
//      Brent solver on the trigonometric polynomial;
//   2. the force coefficients are  F = kc P uc  and the Jacobian  dF/duc = kc P,
//      P = product matrix (fourier.hpp) of the contact indicator, whose moments
//      <1_I cos m theta>, <1_I sin m theta> over the contact intervals I are
//      closed-form integrals. (The boundary terms of dF/duc vanish since u = 0 there.)
// The result is the Galerkin harmonic balance itself, with no aliasing error.
#include <utility>
#include <vector>

namespace gearhb {

// Contact intervals [a, b] (b > a, angles in radians, may extend past 2 pi) where
// u(theta) > 0, for u with real Fourier coefficients `uc` sampled as `us` on the
// uniform grid of `us.size()` points (any N >= 1: the grid only seeds the search,
// every interval between two samples is found, see above). Full contact gives
// {[0, 2 pi]}; a touch narrower than 1e-12 rad (a tangential graze) counts as none.
std::vector<std::pair<double, double>> contact_intervals(const Eigen::VectorXd& uc,
                                                         const Eigen::VectorXd& us);

// Smallest and largest value over a period of the trigonometric polynomial with
// coefficients `c`, given its uniform samples: the extreme samples, refined between
// their neighbours by GSL's Brent minimiser (so a crest that falls between two
// samples is not missed; exact to ~1e-13 in phase).
std::pair<double, double> trig_extremes(const Eigen::VectorXd& c, const Eigen::VectorXd& samples);

// Contact state over a period of the penetration u (coefficients uc, samples us):
// open if max u <= 0, full if min u > 0, intermittent otherwise (extremes refined).
ContactState contact_state(const Eigen::VectorXd& uc, const Eigen::VectorXd& us);

// Moments Sc[m] = (1/2pi) int_I cos(m theta), Ss[m] = (1/2pi) int_I sin(m theta), m = 0..M.
void indicator_moments(const std::vector<std::pair<double, double>>& intervals, int M,
                       double* Sc, double* Ss);

// The same moments of the indicator weighted by a smooth function weight(theta) (a
// time-varying contact stiffness profile): Sc[m] = (1/2pi) int_I weight cos(m theta),
// Ss[m] = (1/2pi) int_I weight sin(m theta), m = 0..M, by 10-point Gauss-Legendre
// quadrature on pieces of each interval no longer than `max_piece` [rad]. The
// interval ends are the exact contact crossings, so the quadrature never straddles
// the kink of the law; inside, w, cos and sin are smooth and the rule (exact for
// polynomials of degree 19 on each piece) converges to round-off once a piece
// spans well under one period of cos(M theta) and of w's fastest variation.
void weighted_indicator_moments(const std::vector<std::pair<double, double>>& intervals,
                                const std::function<double(double)>& weight, int M, double max_piece,
                                double* Sc, double* Ss);

}  // namespace gearhb
