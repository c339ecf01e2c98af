#!/usr/bin/python3
"""Independent reference values of reference/ch09_backlash.json (thesis ch. 9), without gearhb.

Run:  /usr/bin/python3 reference/scripts/ch09_backlash_closed_form.py
Prints "key value" for the thesis gear (ch07_closed_form_ste.py: m = 3 mm, z = 50,
alpha = 20 deg, ha = 3 mm, E = 207 GPa), b = 15 um, T = 300 N m.

  * normal backlash b cos(mu): at C mu = alpha; at E' mu = alpha + eps + eps' with
    eps = atan((T2C + AC)/rb) - alpha, eps' = atan(CE'/rb), CE' = pb - AC, either exact
    (T2C = rb tan alpha) or as printed (T2C = rb sin alpha and lengths rounded to
    0.1 mm for eps, CE' rounded to 0.1 mm over the unrounded rb for eps');
  * the roll reading along the single-pair zone: mu(P) = alpha + (mu(E') - alpha)
    theta(P)/theta(E'), theta(P) = atan((rb tan alpha + CP)/rb) - alpha;
  * ch. 7's 8-position STE (ch07_closed_form_ste.ste_cycle: quad integrals of the
    stepped beams, no FE), the position of pair A on the path from the height of its
    driving node, s = sqrt((rf + x_k)^2 - rb^2) - T1A, the clip min(STE, b_n) at the
    single-pair positions, and the mean of F / STE.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ch07_closed_form_ste as c7  # noqa: E402

b = 15e-6
alpha, rb, ra, rf, pb, F = c7.alpha, c7.rb, c7.ra, c7.rf, c7.pb, c7.F
T2C = rb * math.tan(alpha)
AC = math.sqrt(ra ** 2 - rb ** 2) - T2C          # = CE (identical gears)
rnd = lambda v: round(v / 1e-4) * 1e-4           # noqa: E731  the thesis prints 0.1 mm


def geometry(values):
    if values == "exact":
        CEp = pb - AC
        eps = math.atan((T2C + AC) / rb) - alpha
    else:
        CEp = rnd(pb - AC)
        eps = math.atan((rnd(rb * math.sin(alpha)) + rnd(AC)) / rnd(rb)) - alpha
    epsp = math.atan(CEp / rb)
    return CEp, eps, epsp, alpha + eps + epsp


def mu_roll(s, mu_end):
    """mu at the point s from A (A' and E' symmetric about C: AC = CE)."""
    CP, CE_end = abs(s - AC), pb - AC
    roll = lambda d: math.atan((T2C + d) / rb) - alpha   # noqa: E731
    return alpha + (mu_end - alpha) * roll(CP) / roll(CE_end)


def main():
    out = {"bn_C_um": b * math.cos(alpha) * 1e6}
    for values in ("thesis", "exact"):
        CEp, eps, epsp, mu = geometry(values)
        out["CE_prime_mm_" + values] = CEp * 1e3
        out["epsilon_deg_" + values] = math.degrees(eps)
        out["epsilon_prime_deg_" + values] = math.degrees(epsp)
        out["mu_E_prime_deg_" + values] = math.degrees(mu)
        out["bn_E_prime_um_" + values] = b * math.cos(mu) * 1e6
    # ch. 7's 8 positions at 300 N m, clipped (thesis values, roll reading)
    P = 8
    ne = int(math.floor(P * 2 * AC / pb))
    x, _ = c7.stepped(ne)
    ste = c7.ste_cycle(P)
    T1A = T2C - AC
    mu_end = geometry("thesis")[3]
    clipped, limited = [], 0
    for j, e in enumerate(ste):
        k1 = j + 1
        if k1 + P <= ne:          # two pairs: unchanged
            clipped.append(e)
            continue
        s = math.sqrt((rf + x[k1]) ** 2 - rb ** 2) - T1A
        bn = b * math.cos(mu_roll(s, mu_end))
        limited += e > bn
        clipped.append(min(e, bn))
    out["kc_p8_free_T300"] = np.mean(F / ste)
    out["kc_p8_clip_T300"] = np.mean(F / np.array(clipped))
    out["limited_positions_p8_T300"] = limited
    for k in sorted(out):
        print("%s %.12g" % (k, out[k]))


if __name__ == "__main__":
    main()
