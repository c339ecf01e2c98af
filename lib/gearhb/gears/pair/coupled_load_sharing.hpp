#pragma once
// Load sharing of tooth pairs that deflect each other (issue 33 §2): the contact
// problem of the influence-coefficient method (Conry & Seireg, J. Eng. Ind. 93:1115,
// 1971), solved exactly. The coupled generalisation of load_sharing.hpp, whose pairs
// are independent springs.
//
// n candidate contacts (the tooth pairs geometrically in mesh at one phase) with
//   C   (n x n, symmetric positive definite) the compliance: C_ij [m/N] is the
//       approach of contact j along the line of action under a unit force at contact i
//       (both gears' bodies, C = C_gear1 + C_gear2, plus any local contact compliance);
//   g_i >= 0 [m] the initial separation (tip reliefs of both teeth at contact i);
//   X   [m] the rigid-body approach of the two gears along the line of action;
//   F   [N] the tooth force.
// Compatibility and contact (a linear complementarity problem):
//     w = C f + g - X 1 >= 0,   f >= 0,   f_i w_i = 0,   1^T f = F.
// These are the Karush-Kuhn-Tucker conditions of the strictly convex quadratic program
//     minimise 1/2 f^T C f + g^T f   subject to f >= 0, 1^T f = F,
// X being the multiplier of the equality: the complementary energy of the contacts. A
// strictly convex program on a non-empty convex set has exactly one minimiser, so the
// problem has exactly one solution f (and X, when some f_i > 0, which 1^T f = F > 0
// ensures).
//
// Algorithm (exact active set by enumeration): for every non-empty set S of contacts
// (the loaded ones), solve the equality-constrained system
//     [C_SS  -1] [f_S]   [-g_S]
//     [1^T    0] [ X ] = [  F ],   f_i = 0 off S,
// and accept S when f_S >= 0 and w_i >= 0 off S (the KKT conditions). It terminates
// because there are 2^n - 1 sets (n <= 3 for a spur pair: at most 7 small solves) and
// one of them satisfies the KKT conditions (the unique solution's loaded set); no
// penalty, no iteration tolerance: the open/closed state is exact up to round-off
// (a tie, f_i = w_i = 0, is accepted either way and gives the same f). n is limited to
// 12 (4095 sets).
//
// With C diagonal, C = diag(1/k_i), this is load_sharing.hpp's elastic problem
// F_i = k_i max(X - g_i, 0) (HertzCount::none): the unit tests check it against
// share_load.
#include <vector>

#include <Eigen/Dense>

namespace gearhb {

struct CoupledShare {
  Eigen::VectorXd force;   // f_i [N] (0 = open)
  double approach = 0;     // X [m]
  int loaded = 0;          // contacts with f_i > 0
};

// Throws std::invalid_argument for sizes that differ, n = 0 or n > 12, F <= 0, or a C
// for which no set satisfies the KKT conditions (C not positive definite).
CoupledShare share_load_coupled(const Eigen::MatrixXd& compliance, const Eigen::VectorXd& separation,
                                double force);

// The same problem with C block diagonal: blocks of contacts that deflect each other within a
// block only (a helical face's slices, pair_helical.hpp: the FE section couples the tooth pairs
// of one slice, the slices are independent), each block up to 12 contacts, any number of
// blocks. At a given approach X each block's contacts solve the complementarity problem
//     w_b = C_b f_b + g_b - X 1 >= 0,   f_b >= 0,   f_b . w_b = 0
// (unique for C_b positive definite; found by enumerating its loaded sets as above), and the
// total force sum_b 1^T f_b(X) is continuous, piecewise linear and non-decreasing in X. X is
// found on it exactly: from each iterate's loaded sets the root of their linear piece,
//     X = (F + sum_b 1^T C_SS^-1 g_S) / (sum_b 1^T C_SS^-1 1),
// accepted when the loaded sets there are those it came from (then it is the exact root);
// otherwise the next iterate if it lies inside the bracket of the total, else the bracket's
// midpoint (at most 200 iterates: std::runtime_error). Forces in block order, concatenated.
// std::invalid_argument as share_load_coupled (per block), and for no block.
CoupledShare share_load_blocks(const std::vector<Eigen::MatrixXd>& compliance,
                               const std::vector<Eigen::VectorXd>& separation, double force);

}  // namespace gearhb
