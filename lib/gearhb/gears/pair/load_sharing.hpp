#pragma once
// Load sharing between the tooth pairs in contact at one mesh phase (issue 20):
// a small contact problem, solved exactly.
//
// Pair i (i = 1..n, n = 1..3 for spur gears) has an elastic stiffness k_i [N/m]
// and an initial separation g_i >= 0 [m] (the tip reliefs of both teeth at its
// contact point: a relieved pair starts apart and carries load only once the
// approach X of the gear bodies closes g_i). Its force and the compatibility of
// the approaches are
//
//     F_i = 0                                   if X <= g_i   (open),
//     X  = g_i + F_i / k_i + n_H delta(F_i)     if F_i > 0    (loaded),
//     sum_i F_i = F                              (the tooth force),
//
// delta the Palmgren approach of one contact (hertz.hpp), n_H = 0, 1 or 2 times.
// Every branch is monotone in X, so the solution is unique:
//
//  * Hertz outside the compatibility (the thesis' readings, ch. 7: `equal_split`,
//    `fe_split_mean`): the elastic problem F_i = k_i max(X - g_i, 0) is solved by
//    its active set exactly: the pairs close in the order of g_i; with the m
//    smallest gaps closed X_m = (F + sum k_i g_i) / sum k_i, and m is the first
//    for which the next gap stays open (X_m <= g_(m+1)). Hertz is then added to the
//    transmission error as ch. 7 does: n_H delta(F / m) (equal split over the loaded
//    pairs) or the mean of n_H delta(F_i) over them. With every g_i = 0 this is
//    ch. 7's X = F / (k_A + k_B), F_i = k_i X, bit for bit.
//  * `consistent`: Hertz inside the compatibility. For given X each loaded pair's
//    force solves the monotone scalar equation F_i / k_i + n_H delta(F_i) = X - g_i,
//    and sum F_i(X) = F is monotone in X; both are solved by GSL's Brent to 1e-14
//    relative (the active set follows: pairs with g_i >= X carry nothing).
// No penalty and no regularisation: the open/closed state of each pair is exact.
#include <vector>

#include "gearhb/gears/pair/ste.hpp"

namespace gearhb {

struct ContactPair {
  double stiffness = 0.0;    // k_i [N/m] > 0
  double separation = 0.0;   // g_i [m] >= 0
  // The part of the contact line (length contact_length) this contact stands for, in (0, 1]:
  // its Hertz approach is the whole line's at the same line load, delta(F_i / line_fraction)
  // (a helical face's slice that is partly on the path, pair_helical.hpp). Used by the
  // consistent split; 1 for a spur pair.
  double line_fraction = 1.0;
};

struct LoadShare {
  std::vector<double> force;   // F_i [N], one per pair (0 = open)
  int loaded = 0;              // pairs with F_i > 0
  double approach = 0.0;       // X [m]: elastic + relief (+ Hertz when consistent)
  double hertz = 0.0;          // Hertz part of the transmission error [m]
  double ste = 0.0;            // transmission error [m]: X + hertz (thesis readings) or X (consistent)
};

// F > 0 the tooth force [N]; hertz_count n_H; contact_length the Hertz line length [m].
LoadShare share_load(const std::vector<ContactPair>& pairs, double F, HertzCount hertz_count,
                     TwoPairHertz split, double contact_length);

}  // namespace gearhb
