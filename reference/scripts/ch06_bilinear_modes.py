#!/usr/bin/env python3
"""The bilinear (piecewise-linear) modes of chapter 6's gear mesh: which resonance is the
Delta_min dip of Figs. 40/44 at 22.2 krad/s (and the fold of Figs. 43/45 at 21.7 krad/s)?

Run:  /usr/bin/python3 reference/scripts/ch06_bilinear_modes.py
Nothing here calls gearhb (numpy/scipy only; the model as in ch06_closed_forms.py).

Model: M q'' + K q + T2' kc max(T2 q, 0) = 0 (undamped, unforced, gap 0), q = [x1, y1, th1,
x2, y2, th2], Delta = T2 q. With gap 0 the contact force is positively homogeneous, so the
free periodic orbits that open and close the mesh (the "bilinear modes") have a frequency
that does not depend on their amplitude, and the ratio Delta_min / Delta_max is fixed too.
Near a forced resonance of such a mode the response takes its shape; a static load small
against the vibration (Fig. 40: static Delta 1.9e-3 mm against Delta_max 1.17 mm) hardly
moves it. The forced curves therefore peak at the bilinear frequency, which is neither an
open- nor a closed-mesh natural frequency: no natural-frequency line passes through it.

Method: a synchronous free orbit passes through two rest points (all velocities zero) half a
period apart. Unknowns: the rest position q0 (normalised) and the half period; equations:
q'(T/2) = 0 (scipy least_squares). The flow is exact: in each region (mesh closed, Delta > 0:
stiffness K + kc T2'T2; open: K) the motion is the sum of that region's undamped modes,
cos/sin in closed form; the switch is the first sign change of Delta(t) (a sum of sinusoids)
on a grid of 1/32 of the region's shortest period, refined by brentq to rounding. Started from
each closed-mesh mode with the harmonic mean 2 w_open w_closed / (w_open + w_closed) as the
first guess; each orbit found is listed once with its frequency and Delta_min / Delta_max.
(An earlier version integrated with DOP853, rtol 1e-11, and printed the same table in ~70 s.)
"""
import math

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq, least_squares

a = math.radians(24.6)
m1, I1, rb1 = 0.4, 0.39, 0.0774
m2, I2, rb2 = 0.66, 0.61, 0.1003
kx = ky = 1e8
kth = 1e9
kc = 5e8
M = np.diag([m1, m1, I1, m2, m2, I2])
K = np.diag([kx, ky, kth, kx, ky, kth])
T2 = np.array([math.cos(a), -math.sin(a), rb1, -math.cos(a), math.sin(a), -rb2])


class Region:
    """The undamped modes of M q'' + Kr q = 0: q(t) = Phi (a cos wt + b sin wt), Phi' M Phi = I."""

    def __init__(self, Kr):
        w2, self.Phi = eigh(Kr, M)
        self.w = np.sqrt(w2)
        self.d = T2 @ self.Phi                    # Delta of each mode
        self.h = 2.0 * math.pi / self.w.max() / 32.0   # the grid the switch is searched on

    def coefficients(self, q, v):
        return self.Phi.T @ M @ q, (self.Phi.T @ M @ v) / self.w

    def state(self, ab, t):
        a, b = ab
        c, s = np.cos(self.w * t), np.sin(self.w * t)
        return self.Phi @ (a * c + b * s), self.Phi @ (self.w * (b * c - a * s))

    def delta(self, ab, t):
        """Delta at the times t (an array) after the start of the segment."""
        a, b = ab
        wt = np.outer(t, self.w)
        return (np.cos(wt) * (self.d * a) + np.sin(wt) * (self.d * b)).sum(axis=1)


CLOSED, OPEN = Region(K + kc * np.outer(T2, T2)), Region(K)


def first_switch(r, ab, t_max):
    """The first time in (0, t_max] where Delta changes sign, or None."""
    # right after a switch Delta starts at 0: its sign is the one it takes just after
    ref = np.sign(r.delta(ab, np.array([r.h * 1e-3]))[0])
    t0, chunk = 0.0, 256
    while t0 < t_max:
        t = np.minimum(t0 + r.h * np.arange(1, chunk + 1), t_max)
        d = r.delta(ab, t)
        idx = np.nonzero(np.sign(d) != ref)[0]
        if idx.size:
            k = idx[0]
            lo = t0 if k == 0 else t[k - 1]
            return brentq(lambda s: r.delta(ab, np.array([s]))[0], max(lo, r.h * 1e-3), t[k], xtol=1e-300,
                          rtol=4 * np.finfo(float).eps, maxiter=200)
        t0 = t[-1]
    return None


def segments(q0, t_end):
    """The exact flow from rest at q0 over [0, t_end]: the list of (start time, region, coefficients)."""
    q, v, t, out = q0.copy(), np.zeros(6), 0.0, []
    r = CLOSED if T2 @ q0 > 0 else OPEN
    while True:
        ab = r.coefficients(q, v)
        out.append((t, r, ab))
        s = first_switch(r, ab, t_end - t)
        if s is None:
            return out
        q, v = r.state(ab, s)
        t += s
        r = OPEN if r is CLOSED else CLOSED


def flow(q0, t_end):
    """(q, v) at t_end from rest at q0."""
    t, r, ab = segments(q0, t_end)[-1]
    return r.state(ab, t_end - t)


def delta_samples(q0, t_end, n):
    """Delta at n equally spaced times over [0, t_end]."""
    ts, segs = np.linspace(0.0, t_end, n), segments(q0, t_end)
    starts = np.array([s[0] for s in segs])
    which = np.searchsorted(starts, ts, side="right") - 1
    return np.array([segs[k][1].delta(segs[k][2], np.array([t - segs[k][0]]))[0] for t, k in zip(ts, which)])


def rest_to_rest(x):
    """Velocities at the half period (scaled by it) from the rest point x[:6]."""
    q0 = x[:6] / np.linalg.norm(x[:6])
    return flow(q0, x[6])[1] * x[6]


def bilinear_modes():
    w2_closed, shapes = eigh(K + kc * np.outer(T2, T2), M)
    w_open = np.sqrt(eigh(K, M, eigvals_only=True))
    found = {}
    for j, w2 in enumerate(w2_closed):
        wc = math.sqrt(w2)
        shape = shapes[:, j] / np.linalg.norm(shapes[:, j])
        if abs(T2 @ shape) < 1e-9:
            continue   # the mesh does not move in this mode: no switching
        for wo in sorted(set(np.round(w_open, 6))):
            guess = np.concatenate([shape, [math.pi / (2 * wo * wc / (wo + wc))]])
            r = least_squares(rest_to_rest, guess, xtol=1e-14, ftol=1e-14, gtol=1e-14)
            if r.cost > 1e-16 or r.x[6] <= 0:
                continue
            q0, half = r.x[:6] / np.linalg.norm(r.x[:6]), r.x[6]
            delta = delta_samples(q0, 2 * half, 4001)
            if not delta.min() < 0 < delta.max():
                continue   # no switching: a linear mode
            w = math.pi / half
            key = (round(w, 1), round(delta.min() / delta.max(), 3))
            found.setdefault(key, (j + 1, wc))
    # an orbit met again at k times its frequency (k rest-to-rest legs per half period) is one mode
    modes = sorted(found.items())
    return [m for m in modes if not any(o[0][1] == m[0][1] and o[0][0] < m[0][0] and
                                        abs(m[0][0] / o[0][0] - round(m[0][0] / o[0][0])) < 1e-4 for o in modes)]


if __name__ == "__main__":
    print("bilinear mode [rad/s] | Delta_min/Delta_max | started from closed-mesh mode (rad/s)")
    for (w, ratio), (j, wc) in bilinear_modes():
        print("%10.1f | %7.3f | %d (%.1f)" % (w, ratio, j, wc))
