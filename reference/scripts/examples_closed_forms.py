#!/usr/bin/env python3
"""Independent values for the gearhb_frc examples (reference/examples/*.json).

Run: /usr/bin/python3 reference/scripts/examples_closed_forms.py
Uses only closed forms and numpy/scipy (not gearhb):
  - natural frequencies: sqrt of the generalised eigenvalues of (K, M), contacts open
    and closed (K + kc d d'), by scipy.linalg.eigh;
  - contact onset of a 1-DOF oscillator with a clearance g: the lower frequency where the
    linear amplitude F / sqrt((k - m w^2)^2 + (c w)^2) reaches -g (root of a quadratic in w^2);
  - the 6-DOF gear pair's closed-mesh frequencies (the same eigenproblem).
"""
import json
import math
import pathlib

import numpy as np
from scipy.linalg import eigh

EX = pathlib.Path(__file__).resolve().parents[2] / "programs" / "gearhb_frc" / "examples"


def modes(model):
    M = np.array(model["mass"], float)
    K = np.array(model["stiffness"], float)
    Kc = K.copy()
    for c in model.get("contacts", []):
        d = np.array(c["direction"], float)
        Kc += c["kc"] * np.outer(d, d)
    return np.sqrt(eigh(K, M, eigvals_only=True)), np.sqrt(eigh(Kc, M, eigvals_only=True))


def onset_1dof(m, c, k, F, gap):
    # (k - m w^2)^2 + (c w)^2 = (F/a)^2 with a = -gap:  m^2 s^2 + (c^2 - 2 k m) s + k^2 - (F/a)^2 = 0, s = w^2
    a = -gap
    A, B, C = m * m, c * c - 2 * k * m, k * k - (F / a) ** 2
    s = (-B - math.sqrt(B * B - 4 * A * C)) / (2 * A)
    return math.sqrt(s)


def main():
    for f in sorted(EX.glob("*.json")):
        model = json.load(open(f))
        wo, wc = modes(model)
        print("%s:" % f.stem)
        for i, (a, b) in enumerate(zip(wo, wc)):
            print("  omega_open_%d = %.15g  omega_closed_%d = %.15g" % (i + 1, a, i + 1, b))
        if len(model["mass"]) == 1 and model.get("contacts"):
            m, k = model["mass"][0][0], model["stiffness"][0][0]
            c = model["damping"][0][0]
            F = model["forcing"]["cos"][0]
            gap = max(ct["gap"] for ct in model["contacts"])
            print("  contact_onset_omega = %.15g" % onset_1dof(m, c, k, F, gap))


if __name__ == "__main__":
    main()
