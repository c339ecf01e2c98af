#!/usr/bin/env python3
"""Lin & Parker 1999's example set, without gearhb: the matrices of their model written out
again from the mesh and bearing deflections (LP 1999 eqs. (1)-(3)) in numpy, the natural
frequencies by scipy.linalg.eigh, for N = 3, 4, 5 equally spaced planets.

A second implementation, for reference/lin_parker_1999.md's table of the frequencies the
paper's Table 1 has but issue 36 does not quote; the published N = 3 rotational
frequencies are the check of both.

usage: /usr/bin/python3 reference/scripts/lin_parker_1999.py
"""
import numpy as np
import scipy.linalg as sl

ALPHA = np.radians(24.6)
# (mass [kg], I/r^2 [kg], radial bearing [N/m], torsional [N/m]): carrier, ring, sun
CENTRAL = [(5.43, 6.29, 1e8, 0.0), (2.35, 3.0, 1e8, 1e9), (0.4, 0.39, 1e8, 0.0)]
PLANET = (0.66, 0.61, 1e8)
K_SP = K_RP = 5e8


def matrices(angles):
    n = 3 * (len(angles) + 3)
    M, K = np.zeros((n, n)), np.zeros((n, n))
    for j, (m, i_r2, kb, ku) in enumerate(CENTRAL):
        M[3 * j, 3 * j] = M[3 * j + 1, 3 * j + 1] = m
        M[3 * j + 2, 3 * j + 2] = i_r2
        K[3 * j, 3 * j] = K[3 * j + 1, 3 * j + 1] = kb
        K[3 * j + 2, 3 * j + 2] = ku
    for p, psi in enumerate(angles):
        i = 9 + 3 * p
        M[i, i] = M[i + 1, i + 1] = PLANET[0]
        M[i + 2, i + 2] = PLANET[1]
        radial, tangential, sun, ring = (np.zeros(n) for _ in range(4))
        radial[[0, 1, i]] = np.cos(psi), np.sin(psi), -1
        tangential[[0, 1, 2, i + 1]] = -np.sin(psi), np.cos(psi), 1, -1
        ps, pr = psi - ALPHA, psi + ALPHA
        sun[[6, 7, 8, i, i + 1, i + 2]] = -np.sin(ps), np.cos(ps), 1, -np.sin(ALPHA), -np.cos(ALPHA), 1
        ring[[3, 4, 5, i, i + 1, i + 2]] = -np.sin(pr), np.cos(pr), 1, np.sin(ALPHA), -np.cos(ALPHA), -1
        K += PLANET[2] * (np.outer(radial, radial) + np.outer(tangential, tangential))
        K += K_SP * np.outer(sun, sun) + K_RP * np.outer(ring, ring)
    return M, K


def main():
    for N in (3, 4, 5):
        M, K = matrices(2 * np.pi * np.arange(N) / N)
        lam = sl.eigh(K, M, eigvals_only=True)
        f = np.sqrt(np.clip(lam, 0, None)) / (2 * np.pi)
        print(f"N = {N}:", " ".join(f"{v:.1f}" for v in f))


if __name__ == "__main__":
    main()
