#pragma once
// The first point of a frequency sweep: a periodic solution of the harmonic
// balance at one omega, found with no solution nearby to start from.
//
// Why this needs more than Newton from a linear guess. The classic guesses are the
// open-contact and the all-closed linear solutions. A system with no spring to
// ground (K = 0, a gear pair with backlash, the Kahraman & Singh clearance
// oscillator x'' + 2 zeta x' + f(x) = F_m + F_a cos(Omega t) with a dead zone f)
// has neither: with the contacts open it has no static equilibrium (K singular
// under F_m), and with clearances on both sides the contacts cannot all be closed
// at once, so the all-closed solution lies inside the dead zone where the
// Jacobian's static block is K = 0: Newton stops at once on a singular Jacobian.
// The state the system really rests in is one contact set: the loaded flank
// closed, the others open (x = 1 + F_m / kc for the oscillator).
//
// The design, in the order tried (each step only if the previous one failed, so a
// model that started before starts exactly as before):
//  1. Newton from linear_first_guess (the better of the open and all-closed linear
//     solutions; below).
//  2. Newton from the linear solution of every other contact set S (the contacts of
//     S permanently closed, the others removed; HarmonicBalance::contact_set_solution),
//     in increasing order of its harmonic-balance residual. A set that the response
//     never leaves (the loaded flank closed all period, a small forcing) makes its
//     linear solution exact: Newton converges in one step. All 2^P sets for
//     P <= max_set_contacts contacts, else the single-contact sets and the set of the
//     loaded flanks (of two contacts with opposite normals, the one with the larger
//     gap; every contact without an opposite one: a planetary set's drive flanks).
//  3. Continuation in the forcing amplitude: the periodic forcing fc, fs is scaled
//     by lambda in [0, 1]. At lambda = 0 the forcing is static (f0; and the periodic
//     part of a gap if the model has one) and its solution is found by steps 1-2
//     (for the oscillator: the loaded static equilibrium, exact); then pseudo-arc-
//     length continuation in lambda (continuation.hpp, the same corrector, step
//     control and short steps at contact-state changes as the frequency sweep) up to
//     lambda = 1, which is the solution sought. Arc length, not natural steps,
//     because the amplitude response at a fixed omega may itself fold (the
//     hysteresis of an impacting oscillator near its resonance). Where the multi-
//     impact response of a large forcing is far from any linear solution (the
//     oscillator at Omega = 0.3, F_a >= 0.1), this is what starts the sweep.
//  4. Where a contact's stiffness varies over the period (stiffness_profile: a gear mesh, a
//     planetary set driven by its meshes alone, which step 3 cannot scale): continuation
//     in the depth lambda of the variation, profile 1 + lambda (s - 1), from the model with
//     constant stiffnesses (started by steps 1-2: its orbit is static where nothing else
//     forces it) to lambda = 1. Exact at every lambda: the contact force is linear in s, so
//     the residual is (1 - lambda) R_constant + lambda R. (The loaded planetary example of
//     gearhb_planetary from 1500 Hz, inside its range of contact loss, starts here.)
//     Switched with step 3 (amplitude_continuation).
// Limits: the homotopy scales the external forcing only (a model forced only by the
// periodic part of its gaps, a transmission error, gains nothing from it); a
// static problem with no equilibrium (K = 0 and no static load pressing a contact)
// has none to start from. Either way the result says so (`failure`), and a sweep
// that cannot start is reported incomplete, never as an empty success.
#include <string>

#include <Eigen/Dense>

#include "gearhb/hb/continuation.hpp"
#include "gearhb/hb/harmonic_balance.hpp"

namespace gearhb {

struct FirstPointOptions {
  NewtonOptions newton{1e-10, 50};   // each Newton solve of steps 1-2
  int max_set_contacts = 6;          // step 2 tries all 2^P sets up to this many contacts
  bool amplitude_continuation = true;   // steps 3 and 4
  // Step 3's continuation (omega_start / omega_end are set to 0 and 1; its scaled
  // arc length measures lambda in units of 1). `regime` and the step sizes are used.
  ContinuationOptions continuation;
  // Step 1's guess if the caller has it already (the sweep tried it first); empty:
  // linear_first_guess computes it.
  Eigen::VectorXd linear_guess;
};

enum class FirstPointMethod { none, linear_guess, contact_set, amplitude_continuation, stiffness_continuation };
const char* to_string(FirstPointMethod m);

struct FirstPoint {
  bool found = false;
  Eigen::VectorXd X;                 // the converged solution at omega (if found)
  FirstPointMethod method = FirstPointMethod::none;
  unsigned long long contact_set = 0;   // step 2, or the set step 3's static start came from
  int newton_solves = 0;             // Newton solves tried (steps 1, 2 and 3's static start)
  int homotopy_points = 0;           // points of step 3's branch
  std::string failure;               // why not (empty if found)
};

// Linear first guess at omega: the open- or closed-contact solution, whichever
// has the smaller residual; a non-finite one (the open solution of a system with
// K singular, a free rigid-body mode, under a static load) is skipped. Throws
// std::invalid_argument if neither is finite.
Eigen::VectorXd linear_first_guess(const HarmonicBalance& hb, double omega);

// The first point at omega (see above); x scaling s as for the sweep (s.omega is not used).
FirstPoint find_first_point(const HarmonicBalance& hb, double omega, const Scaling& s,
                            const FirstPointOptions& opt = {});

}  // namespace gearhb
