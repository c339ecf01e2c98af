#!/usr/bin/python3
"""Independent reference values of reference/ch07_ste.json (thesis ch. 7), without FE.

Run:  /usr/bin/python3 reference/scripts/ch07_closed_form_ste.py
Prints every key number this script produces, as "key value", for the thesis gear
(m = 3 mm, z = 50, alpha = 20 deg, ha = 3 mm, hf = 3.75 mm, b = 20 mm, E = 207 GPa),
T = 300 N m, tooth force F = T / r = 4000 N. Nothing here calls gearhb.

  * path of contact: AC = CE = sqrt(ra^2 - rb^2) - rb tan(alpha), eps = AE / pb;
  * thesis section 7.7 angles with the thesis' printed (0.1 mm rounded) intermediates,
    and T2C = rb tan(alpha) corrected;
  * constant 6 mm tooth (section 7.4): one pair = two cantilevers,
    STE = F (a1^3 + a2^3) / (3 EI); two pairs = two clamped-guided beams of
    n_e + 1 elements carrying F/2 each: X = (F/2) L^3 / (12 EI), root moment (F/2) L / 2;
  * involute tooth (section 7.5): stepped beams, element thickness s(r) at the
    root-side node; one pair: F (C(a1) + C(a2)) with the unit-load compliance
    C(a) = int_0^a (a - x)^2 / EI(x) dx; two pairs: X = F / (k_A + k_B),
    k = 1 / (I2 - I1^2 / I0), I_k = int_0^L x^k / EI(x) dx along the fused beam
    (driving root guided, driven root clamped). The integrals are taken with
    scipy.integrate.quad (breakpoints at the steps), not with the library's sums;
    Hertz: Palmgren 3.84e-5 F^0.9 / L^0.8 [mm], twice per contact (once per tooth),
    two pairs at F/2 each. Mean mesh stiffness = mean over the cycle of F / STE.
"""
import math

import numpy as np
from scipy.integrate import quad

m, z, alpha, ha, hf, b, E = 3e-3, 50, math.radians(20.0), 3e-3, 3.75e-3, 0.02, 207e9
T = 300.0
r = m * z / 2
rb, ra, rf = r * math.cos(alpha), r + ha, r - hf
pb = math.pi * m * math.cos(alpha)
F = T / r


def inv(a):
    return math.tan(a) - a


def thickness(rr):
    return rr * (math.pi * m / 2) / r + 2 * rr * (inv(alpha) - inv(math.acos(rb / rr)))


def palmgren(force):   # [m]
    return 3.84e-5 * force ** 0.9 / (b * 1e3) ** 0.8 / 1e3


def geometry(out):
    CE = math.sqrt(ra ** 2 - rb ** 2) - rb * math.tan(alpha)
    out["contact_ratio"] = 2 * CE / pb
    out["AC_mm"] = out["CE_mm"] = CE * 1e3
    rnd = lambda v: round(v / 1e-4) * 1e-4   # noqa: E731  the thesis prints 0.1 mm
    rb_, CE_, T2C = rnd(rb), rnd(CE), rnd(rb * math.sin(alpha))
    T2E = rnd(T2C - CE_)
    beta = alpha - math.atan(T2E / rb_)
    eps = math.atan((T2C + CE_) / rb_) - alpha
    out["beta_deg"], out["epsilon_deg"] = math.degrees(beta), math.degrees(eps)
    out["force_variation_percent"] = 100 * (math.cos(alpha - beta) - math.cos(alpha + eps)) / math.cos(alpha + eps)
    out["corrected_T2C_mm"] = rb * math.tan(alpha) * 1e3


def constant_tooth(out):
    ne, EI = 10, E * b * 0.006 ** 3 / 12
    Le = (ha + hf) / ne
    out["ste_single_pair_const_um"] = F * ((5 * Le) ** 3 + (6 * Le) ** 3) / (3 * EI) * 1e6   # nodes 6-18
    L = (ne + 1) * Le
    out["ste_two_pairs_const_um"] = 0.5 * F * L ** 3 / (12 * EI) * 1e6
    out["reaction_moment_guided_root_N_m"] = -0.5 * F * L / 2
    out["reaction_force_clamped_root_N"] = -0.5 * F
    out["reaction_moment_clamped_root_N_m"] = -0.5 * F * L / 2
    for k in ("ste_single_pair_const_fe_vs_exact_rel", "ste_two_pairs_const_fe_vs_exact_rel",
              "ste_fe_vs_closed_form_max_rel"):
        out[k] = 0.0   # FE and exact formula agree exactly for nodal loads (Hermite elements)


def stepped(ne):
    """Node heights and element EI of the involute tooth (s at the root-side node)."""
    x = np.linspace(0.0, ha + hf, ne + 1)
    EI = np.array([E * b * thickness(rf + x[e]) ** 3 / 12 for e in range(ne)])
    return x, EI


def piecewise(xs, EIs):
    """1/EI(s) along a beam given by segment ends xs and stiffnesses EIs."""
    return lambda s: 1.0 / EIs[min(np.searchsorted(xs, s, side="right") - 1, len(EIs) - 1)]


def cantilever_compliance(x, EI, a):
    f = piecewise(x, EI)
    pts = [p for p in x if 0 < p < a]
    return quad(lambda s: (a - s) ** 2 * f(s), 0, a, points=pts or None, epsabs=0, epsrel=1e-13, limit=200)[0]


def fused_stiffness(x, EI, k1, k2):
    Le = x[1]
    xs = list(x[:k1 + 1]) + [x[k1] + (i + 1) * Le for i in range(k2)]
    EIs = list(EI[:k1]) + [EI[j] for j in range(k2 - 1, -1, -1)]
    f = piecewise(np.array(xs), EIs)
    L = xs[-1]
    I = [quad(lambda s: s ** k * f(s), 0, L, points=xs[1:-1], epsabs=0, epsrel=1e-13, limit=200)[0] for k in range(3)]
    return 1.0 / (I[2] - I[1] ** 2 / I[0])


def ste_cycle(P):
    ne = int(math.floor(P * (2 * (math.sqrt(ra ** 2 - rb ** 2) - rb * math.tan(alpha)) / pb)))
    x, EI = stepped(ne)
    ste = []
    for j in range(P):
        k1 = j + 1
        k2 = ne + 1 - k1
        if k1 + P <= ne:
            kA, kB = fused_stiffness(x, EI, k1, k2), fused_stiffness(x, EI, k1 + P, ne + 1 - k1 - P)
            ste.append(F / (kA + kB) + 2 * palmgren(F / 2))
        else:
            ste.append(F * (cantilever_compliance(x, EI, x[k1]) + cantilever_compliance(x, EI, x[k2])) + 2 * palmgren(F))
    return np.array(ste)


def main():
    out = {}
    geometry(out)
    constant_tooth(out)
    for P, tag in ((8, ""), (6, "_first_model")):
        s = ste_cycle(P)
        out["ste_max%s_T3_um" % tag] = s.max() * 1e6
        out["mean_stiffness%s_T3_MN_per_m" % tag] = np.mean(F / s) / 1e6
    for k in sorted(out):
        print("%s %.12g" % (k, out[k]))


if __name__ == "__main__":
    main()
