#!/usr/bin/python3
"""Independent evaluation of gearhb_gear's loaded STE with model.method = potential_energy.

Run:  /usr/bin/python3 reference/scripts/gear_pair_pe_ste.py        (about 10 s)
Prints "example key value" for the STE key numbers of every example file in
programs/gearhb_gear/examples/ whose model.method is potential_energy. Nothing here calls
gearhb or shares code with it:

  * the tooth compliance (bending, shear 1.2/(G A), axial compression, Sainsot et al. 2004
    fillet foundation clamped at the bore = the file's rim_radius, theta_f of the
    rack-generated root, plane strain E/(1 - nu^2) in bending and compression) is the one of
    tests/pe_independent_check.py: integrals in the centre-line coordinate x by composite
    Simpson (the library: Gauss-Legendre in the pressure angle), the half thickness y(x) by
    bisection on the involute radius (here vectorised with numpy), the straight flank at the
    base-circle half thickness between root and base circle when rf < rb (split there);
  * Hertz linear, Yang & Sun: 1/k_h = (2 / (pi b)) [(1 - nu1^2)/E1 + (1 - nu2^2)/E2], b = min(b1, b2);
  * a pair: 1/k = sum over both teeth of (bending + shear + axial + fillet) + 1/k_h;
  * the mesh cycle as gear_pair_beam_ste.py: pairs at s_k = (phi + k) pb from A while
    s_k <= AE, contact radii r_i = sqrt(rb_i^2 + T_iP^2), separation the sum of both tip
    reliefs (gear_pair_beam_ste.relief); the load shared exactly by linear springs with gaps (the active set of the
    smallest gaps, X = (F + sum k g) / sum k), STE = X (no Palmgren term: the PE Hertz is
    linear and inside k); tooth force T1 / r1 or T1 / rb1.
Keys: ste_max_um_i, ste_ptp_um_i, mesh_stiffness_mean_N_per_m_i, loaded_contact_ratio_i,
single_pair_deflection_um_i (one pair alone at the pitch point C, no relief).
A helical file (helix_angle_deg beta > 0; issue 35) is sliced, written here from ISO 21771 and the
thin-slice model's statement (programs/gearhb_gear/NOTES.md "Helical pairs"), not from the library:
  * the transverse section: m_t = m_n / cos(beta), alpha_t = atan(tan(alpha_n) / cos(beta)), the rack's
    addendum, dedendum and root radius and the shift the normal ones as lengths (coefficients on m_t
    times cos(beta)): a spur PeTooth of that section;
  * eps_beta = b sin(beta) / (pi m_n); N slices (model.slices, default 20), slice j read at phase
    phi + (j + 1/2) eps_beta / N; its contact line with each tooth pair spans ds = eps_beta pb / N along
    the path, centred at (psi + q) pb; the part of it on [0, AE] (fraction w) is the contact, read at
    that part's centre, of stiffness w k / N (k the full-width section's PE pair stiffness, linear
    Hertz inside it); the load shared exactly over all slices x pairs by the same linear active set;
  * single pair: the tooth pair whose mid-face contact is at C, each slice's part of it on the path,
    stagger centred on the face.
"""
import json
import math
import pathlib

import numpy as np

from gear_pair_beam_ste import relief   # the tip relief at a roll length (same folder, no gearhb)

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "programs" / "gearhb_gear" / "examples"
SAINSOT = [[-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045],
           [60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086],
           [-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236],
           [-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904]]


def inv(a):
    return np.tan(a) - a


def simpson(f, a, b, n):
    """Composite Simpson of the vectorised f on [a, b] with n (even) intervals."""
    x = np.linspace(a, b, n + 1)
    w = np.ones(n + 1)
    w[1:-1:2], w[2:-1:2] = 4.0, 2.0
    return (b - a) / n / 3.0 * np.dot(w, f(x))


class PeTooth:
    def __init__(self, f, g):
        self.m, self.a0 = f["module"], math.radians(f["pressure_angle_deg"])
        rack = f.get("basic_rack", {})
        self.ha, self.hf, self.rho = rack.get("addendum", 1.0), rack.get("dedendum", 1.25), rack.get("root_radius", 0.38)
        self.z, self.x, self.b = g["z"], g.get("x", 0.0), g["b"]
        self.E, self.nu, self.rint = g["E"], g.get("nu", 0.3), g["rim_radius"]
        self.r0 = self.m * self.z / 2
        self.rb = self.r0 * math.cos(self.a0)
        self.ra = self.r0 + self.m * (self.ha + self.x)
        self.rf = self.r0 - self.m * (self.hf - self.x)
        self.tb = (math.pi / 2 + 2 * self.x * math.tan(self.a0)) / self.z + float(inv(self.a0))

    def theta(self, r):
        return self.tb - inv(np.arccos(np.minimum(1.0, self.rb / r)))

    def half_thickness(self, X):
        """y on the involute where r cos(theta(r)) = X (bisection, 80 halvings)."""
        lo = np.full_like(X, max(self.rb, self.rf))
        hi = np.full_like(X, self.ra)
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            below = mid * np.cos(self.theta(mid)) < X
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        r = 0.5 * (lo + hi)
        return r * np.sin(self.theta(r))

    def compliance(self, r_c, n=20000):
        Ep, G, b = self.E / (1 - self.nu**2), self.E / (2 * (1 + self.nu)), self.b
        tc = float(self.theta(r_c))
        xc, yc = r_c * math.cos(tc), r_c * math.sin(tc)
        am = math.acos(self.rb / r_c) - tc
        c, s = math.cos(am), math.sin(am)

        def integrand(y, X):
            A, I, M = 2 * y * b, 2.0 / 3.0 * y**3 * b, c * (xc - X) - s * yc
            return M * M / (Ep * I) + 1.2 * c * c / (G * A) + s * s / (Ep * A)

        total = 0.0
        if self.rf < self.rb:   # straight flank at the base-circle half thickness, then the involute
            hb = self.rb * math.sin(self.tb)
            x0, xb = math.sqrt(self.rf**2 - hb**2), self.rb * math.cos(self.tb)
            total += simpson(lambda X: integrand(np.full_like(X, hb), X), x0, xb, n)
        else:
            xb = self.rf * math.cos(float(self.theta(self.rf)))
        total += simpson(lambda X: integrand(self.half_thickness(X), X), xb, xc, n)
        tf = (math.pi / 2 + 2 * (self.hf - self.rho) * math.tan(self.a0) + 2 * self.rho / math.cos(self.a0)) / self.z
        hF = self.rf / self.rint
        L, Mm, P, Q = [t[0] / tf**2 + t[1] * hF**2 + t[2] * hF / tf + t[3] / tf + t[4] * hF + t[5] for t in SAINSOT]
        Sf, u = 2 * self.rf * tf, xc - yc * math.tan(am) - self.rf
        fillet = c * c / (self.E * b) * (L * (u / Sf) ** 2 + Mm * u / Sf + P * (1 + Q * math.tan(am) ** 2))
        return total + fillet


def share(pairs, F):
    """Linear springs (k, gap): the exact active set; returns (approach X, loaded pairs)."""
    order = sorted(range(len(pairs)), key=lambda i: pairs[i][1])
    for m in range(1, len(pairs) + 1):
        idx = order[:m]
        X = (F + sum(pairs[i][0] * pairs[i][1] for i in idx)) / sum(pairs[i][0] for i in idx)
        if m == len(pairs) or X <= pairs[order[m]][1]:
            return X, m


def transverse(f):
    """The transverse section of a helical file as a spur file (ISO 21771; the file itself at beta = 0)."""
    beta = math.radians(f.get("helix_angle_deg", 0.0))
    if beta == 0:
        return f
    c = math.cos(beta)
    rack = f.get("basic_rack", {})
    t = dict(f)
    t["module"] = f["module"] / c
    t["pressure_angle_deg"] = math.degrees(math.atan(math.tan(math.radians(f["pressure_angle_deg"])) / c))
    t["basic_rack"] = {"addendum": rack.get("addendum", 1.0) * c, "dedendum": rack.get("dedendum", 1.25) * c,
                       "root_radius": rack.get("root_radius", 0.38) * c}
    t["gears"] = [dict(g, x=g.get("x", 0.0) * c) for g in f["gears"]]
    return t


def on_path(c, ds, AE):
    """The part of a contact line centred at c, spread over ds, on [0, AE]: (centre, fraction)."""
    lo, hi = max(0.0, c - ds / 2), min(AE, c + ds / 2)
    return ((lo + hi) / 2, min(1.0, (hi - lo) / ds)) if hi - lo > 1e-9 * ds else (None, 0.0)


def evaluate(f, n_phases=None):
    normal_module, beta = f["module"], math.radians(f.get("helix_angle_deg", 0.0))
    f = transverse(f)
    g = f["gears"]
    t1, t2 = PeTooth(f, g[0]), PeTooth(f, g[1])
    model = f.get("model", {})
    a0 = t1.a0
    if f.get("centre_distance", 0.0) > 0:
        aw = math.acos((t1.rb + t2.rb) / f["centre_distance"])
    else:
        xs, target = t1.x + t2.x, float(inv(a0)) + 2 * math.tan(a0) * (t1.x + t2.x) / (t1.z + t2.z)
        lo, hi = 0.0, 1.5
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if float(inv(mid)) < target else (lo, mid)
        aw = a0 if xs == 0 else 0.5 * (lo + hi)
    T1T2 = (t1.rb + t2.rb) * math.tan(aw)
    T1A = T1T2 - math.sqrt(t2.ra**2 - t2.rb**2)
    AE, pb = math.sqrt(t1.ra**2 - t1.rb**2) - T1A, math.pi * t1.m * math.cos(a0)
    b = min(t1.b, t2.b)
    hertz = 2 / (math.pi * b) * ((1 - t1.nu**2) / t1.E + (1 - t2.nu**2) / t2.E)

    def k_pair(T1P):
        return 1.0 / (t1.compliance(math.hypot(t1.rb, T1P)) + t2.compliance(math.hypot(t2.rb, T1T2 - T1P)) + hertz)

    rel1, rel2 = g[0].get("tip_relief"), g[1].get("tip_relief")
    phases = []
    n = n_phases or model.get("phases", 64)
    N = model.get("slices", 20) if beta > 0 else 1
    eps_beta = b * math.sin(beta) / (math.pi * normal_module)
    ds = eps_beta * pb / N
    for j in range(n):
        pts = []
        if N == 1 and ds == 0:
            s = j / n * pb
            while s <= AE:
                T1P = T1A + s
                pts.append((k_pair(T1P), relief(rel1, t1, T1P) + relief(rel2, t2, T1T2 - T1P)))
                s += pb
        else:
            for sl in range(N):
                psi = (j / n + (sl + 0.5) / N * eps_beta) % 1.0
                for q in range(-2, int(AE / pb) + 3):
                    c, w = on_path((psi + q) * pb, ds, AE)
                    if w > 0:
                        T1P = T1A + c
                        pts.append((w * k_pair(T1P) / N, relief(rel1, t1, T1P) + relief(rel2, t2, T1T2 - T1P), w))
        phases.append(pts)
    T1C = t1.rb * math.tan(aw)
    if ds == 0:
        k_C = k_pair(T1C)
    else:   # the pair whose mid-face contact is at C: its slices' parts on the path, in parallel
        k_C = 0.0
        for sl in range(N):
            c, w = on_path(T1C - T1A + ((sl + 0.5) / N - 0.5) * eps_beta * pb, ds, AE)
            if w > 0:
                k_C += w * k_pair(T1A + c) / N
    out = {}
    for i, T in enumerate(f["torques"]):
        F = T / (t1.r0 if model.get("tooth_force", "pitch_radius") == "pitch_radius" else t1.rb)
        ste, loaded = zip(*(share(p, F) for p in phases))
        if ds > 0:   # the loaded contact ratio: contacts counted by their fraction, per slice
            loaded = [sum(q[2] for q in sorted(p, key=lambda q: q[1])[:m]) / N for p, m in zip(phases, loaded)]
        key = str(i + 1)
        out["ste_max_um_" + key] = max(ste) * 1e6
        out["ste_ptp_um_" + key] = (max(ste) - min(ste)) * 1e6
        out["mesh_stiffness_mean_N_per_m_" + key] = sum(F / e for e in ste) / len(ste)
        out["loaded_contact_ratio_" + key] = sum(loaded) / len(loaded)
        out["single_pair_deflection_um_" + key] = F / k_C * 1e6
    return out


def main():
    for path in sorted(EXAMPLES.glob("*.json")):
        f = json.load(open(path))
        if f.get("model", {}).get("method", "beam") != "potential_energy":
            continue
        for k, v in evaluate(f).items():
            print("%s %s %.16g" % (path.stem, k, v))
        # the loaded contact ratio converged in the phases (count over 2048), with tip relief
        if any(gear.get("tip_relief") for gear in f["gears"]):
            for k, v in evaluate(f, n_phases=2048).items():
                if k.startswith("loaded_contact_ratio_"):
                    print("%s %s %.16g" % (path.stem + "_fine", k, v))


if __name__ == "__main__":
    main()
