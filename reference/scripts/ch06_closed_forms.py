#!/usr/bin/env python3
"""Independent reference values of chapter 6 (6-DOF gear pair), from closed forms.

Run:  /usr/bin/python3 reference/scripts/ch06_closed_forms.py
Prints the values recorded in reference/ch06_gear_pair.json. Nothing here calls gearhb.

Model (thesis §6.1-6.2, chapter README): q = [x1, y1, th1, x2, y2, th2],
M = diag(m1, m1, I1, m2, m2, I2), K = diag(kx1, ky1, kth1, kx2, ky2, kth2) (supports),
mesh deflection Delta = T2 q, T2 = [cos a, -sin a, rb1, -cos a, sin a, -rb2],
closed-mesh stiffness K + kc T2' T2, damping C = beta K (supports only).

1. Open natural frequencies: K and M diagonal, so sqrt(k/m), sqrt(kth/I) exactly.
2. Closed natural frequencies: kc T2'T2 is a rank-one update, so besides the
   uncoupled frequencies whose T2 entry vanishes in the modal sense (the x-y
   combination normal to the line of action of each gear), the others are the roots
   of the secular equation 1 + kc sum_i T2_i^2 / (k_i - w^2 m_i) = 0 (scipy brentq,
   one root between consecutive poles and one above the last).
3. First contact change of Figs. 41 and 43 (Fa = 1e4 on F = Fa [1,0,1,1,0,1]):
   before the first change the response is linear, Delta(t) = D0 + Re(D1 e^{iwt}),
   with D0 = T2 Ks^-1 F0 and D1 = T2 (Ks - w^2 M + i w C)^-1 F (Ks = K + Kc for a
   start in full contact, K for an open start). Full contact ends (Fig. 41,
   Fi = 1e7) where D0 - |D1| = 0; the open mesh first touches (Fig. 43, Fi = -1e6)
   where D0 + |D1| = 0: brentq on a bracket found by a scan from 2 krad/s.
"""
import numpy as np
from scipy.optimize import brentq

a = np.radians(24.6)
m1, I1, rb1 = 0.4, 0.39, 0.0774
m2, I2, rb2 = 0.66, 0.61, 0.1003
kx, kth = 1e8, 1e9
beta = 1e-6
M = np.diag([m1, m1, I1, m2, m2, I2])
K = np.diag([kx, kx, kth, kx, kx, kth])
T2 = np.array([np.cos(a), -np.sin(a), rb1, -np.cos(a), np.sin(a), -rb2])


def open_frequencies():
    return np.sort(np.sqrt(np.diag(K) / np.diag(M)))


def closed_frequencies(kc):
    """Eigenfrequencies of (K + kc T2'T2, M) from the secular equation."""
    k, m = np.diag(K), np.diag(M)
    # Gear i's x and y share k and m: combine them into one coordinate along the
    # line of action (T2 weight cos^2 + sin^2 = 1) and one normal to it (weight 0,
    # frequency unchanged).
    groups = [(kx, m1, 1.0), (kth, I1, rb1 ** 2), (kx, m2, 1.0), (kth, I2, rb2 ** 2)]
    poles = sorted(np.sqrt(kk / mm) for kk, mm, _ in groups)

    def secular(w):
        return 1.0 + kc * sum(t2 / (kk - w * w * mm) for kk, mm, t2 in groups)

    roots = []
    edges = [0.0] + poles + [10 * poles[-1]]
    for lo, hi in zip(edges[:-1], edges[1:]):
        a_, b_ = lo * (1 + 1e-14), hi * (1 - 1e-14)   # a root may sit 1e-9 from a pole (kc = 5e2)
        if secular(a_) * secular(b_) < 0:
            roots.append(brentq(secular, a_, b_, xtol=1e-12, rtol=1e-15))
    unchanged = [np.sqrt(kx / m1), np.sqrt(kx / m2)]   # the normal x-y combinations
    return np.sort(np.array(roots + unchanged))


def first_change(Fi, Fa, kc, closed):
    F0 = np.array([0, 0, Fi, 0, 0, -Fi * rb2 / rb1])
    F = Fa * np.array([1, 0, 1, 1, 0, 1.0])
    Ks = K + kc * np.outer(T2, T2) if closed else K
    C = beta * K
    D0 = T2 @ np.linalg.solve(Ks, F0)
    sign = -1.0 if closed else 1.0   # crest (open start) or trough (closed start) of Delta

    def g(w):
        D1 = T2 @ np.linalg.solve(Ks - w * w * M + 1j * w * C, F)
        return D0 + sign * abs(D1)

    ws = np.linspace(2000.0, 62000.0, 60001)
    vals = [g(w) for w in ws]
    for i in range(1, len(ws)):
        if np.sign(vals[i]) != np.sign(vals[0]):
            return brentq(g, ws[i - 1], ws[i], xtol=1e-12, rtol=1e-15)
    return float("nan")


if __name__ == "__main__":
    for i, w in enumerate(open_frequencies(), 1):
        print("omega_open_%d %.12g" % (i, w))
    for tag, kc in (("", 5e8), ("_kc_alt", 5e2)):
        for i, w in enumerate(closed_frequencies(kc), 1):
            print("omega_closed_%d%s %.12g" % (i, tag, w))
    print("first_change_omega_fig41 %.12g" % first_change(1e7, 1e4, 5e8, closed=True))
    print("first_change_omega_fig43 %.12g" % first_change(-1e6, 1e4, 5e8, closed=False))
