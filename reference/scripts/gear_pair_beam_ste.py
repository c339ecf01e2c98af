#!/usr/bin/python3
"""Independent evaluation of gearhb_gear's loaded STE (the chapter 7 beam model of a pair).

Run:  /usr/bin/python3 reference/scripts/gear_pair_beam_ste.py
Prints "example key value" for the STE key numbers of every example file in
programs/gearhb_gear/examples/ with model.method beam (the potential-energy files are
gear_pair_pe_ste.py's) (and of thesis_pair on ch. 7's 8 node positions,
as "thesis_pair_p8"). Nothing here calls gearhb: the same model, written again
with numpy (dense FE) and scipy (brentq), to check the C++ implementation:

  * each tooth a cantilever from its root circle rf to its tip ra, n_e equal
    Euler-Bernoulli elements (n_e = floor(8 eps_alpha) unless the file says),
    thickness s(r) at each element's root-side node (involute, with the shift;
    s(rb) below the base circle), EI = E b s^3 / 12;
  * flexibility at height a (root clamped): the load enters element e at
    xi = (a - x_e)/L_e as consistent nodal loads N(xi) F and N'(xi) M (cubic Hermite
    shape functions), the deflection / rotation are read back the same way;
  * pairs at s_k = (phi + k) pb from A while s_k <= AE; contact radii
    r_i = sqrt(rb_i^2 + T_iP^2), load heights r_i - rf_i; separation = the sum of the
    two tip reliefs (Ca ((xi - xi_S)/(xi_a - xi_S))^n beyond the start);
  * pair stiffness: "fused" [(G1 + D G2 D)^-1]_00 where the phase has more than one
    pair, 1/(G1_ww + G2_ww) otherwise; "cantilevers" always the latter;
  * sharing: equal_split / fe_split_mean: elastic active set (the m smallest gaps),
    X = (F + sum k g)/sum k, Hertz n_H delta(F/m) or the mean of n_H delta(F_i);
    consistent: brentq on X of sum F_i(X) = F, F_i from F_i/k_i + n_H delta(F_i) = X - g_i;
  * Palmgren delta = 3.84e-5 F^0.9 / L^0.8 [mm] (F in N, L in mm), n_H = 2 per tooth,
    1 per contact; tooth force T1 / r1 or T1 / rb1.
A helical file (helix_angle_deg beta > 0, or a lead modification) is sliced (issue 35), written
here from ISO 21771 without the library's formulas:
  * the transverse gear: m_t = m_n / cos(beta), alpha_t = atan(tan(alpha_n) / cos(beta)),
    ra = r + m_n (ha* + x), rf = r - m_n (hf* - x), s0 = m_t (pi/2 + 2 x tan(alpha_n));
  * overlap ratio eps_beta = b sin(beta) / (pi m_n); N slices (model.slices, default 20), slice j
    at y_j = (j + 1/2) b / N, read at phase phi + eps_beta y_j / b;
  * a slice's contact line spans ds = eps_beta pb / N along the path, centred at (psi + q) pb;
    its part on the path [0, AE] (fraction w) is the contact, read at that part's centre;
  * each slice contact: w times the full-width beam stiffness / N, its gap the tip reliefs plus
    both gears' lead modification at y_j (crowning C (2y/b - 1)^2, end relief C_I (L_I - d)/L_I);
  * the load shared over all slices x pairs with each contact's Hertz that of the whole line at
    the same line load: the sharing above with stiffness w k, force N F, line b, delta(f / w);
  * single pair: the tooth pair whose mid-face contact is at C, its slices on the path alone.
"""
import json
import math
import pathlib

import numpy as np
from scipy.optimize import brentq

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "programs" / "gearhb_gear" / "examples"


def inv(a):
    return math.tan(a) - a


def inv_inverse(v):
    return brentq(lambda a: inv(a) - v, 1e-9, 1.5, xtol=1e-15, rtol=1e-15)


class Gear:
    def __init__(self, f, g):
        self.mn, self.aln = f["module"], math.radians(f["pressure_angle_deg"])
        beta = math.radians(f.get("helix_angle_deg", 0.0))
        self.m = self.mn / math.cos(beta)
        self.al = math.atan(math.tan(self.aln) / math.cos(beta)) if beta else self.aln
        rack = f.get("basic_rack", {})
        self.ha, self.hf = rack.get("addendum", 1.0) * self.mn, rack.get("dedendum", 1.25) * self.mn
        self.z, self.x, self.b, self.E = g["z"], g.get("x", 0.0), g["b"], g["E"]
        self.r = self.m * self.z / 2
        self.rb = self.r * math.cos(self.al)
        self.ra = self.r + self.ha + self.x * self.mn
        self.rf = self.r - self.hf + self.x * self.mn

    def thickness(self, r):
        r = max(r, self.rb)
        s0 = self.m * (math.pi / 2 + 2 * self.x * math.tan(self.aln))   # ISO 21771: s_t = m_t (pi/2 + 2 x tan alpha_n)
        return r * s0 / self.r + 2 * r * (inv(self.al) - inv(math.acos(min(1.0, self.rb / r))))


def hermite(xi, L):
    N = np.array([1 - 3 * xi**2 + 2 * xi**3, L * (xi - 2 * xi**2 + xi**3), 3 * xi**2 - 2 * xi**3, L * (xi**3 - xi**2)])
    dN = np.array([-6 * xi + 6 * xi**2, L * (1 - 4 * xi + 3 * xi**2), 6 * xi - 6 * xi**2, L * (3 * xi**2 - 2 * xi)]) / L
    return N, dN


class Beam:
    def __init__(self, gear, ne):
        h = gear.ha + gear.hf
        self.x = np.array([i * h / ne for i in range(ne + 1)])
        EI = [gear.E * gear.b * gear.thickness(gear.rf + self.x[e]) ** 3 / 12 for e in range(ne)]
        n = 2 * (ne + 1)
        K = np.zeros((n, n))
        for e in range(ne):
            L = self.x[e + 1] - self.x[e]
            k = EI[e] / L**3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                                         [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
            K[2 * e:2 * e + 4, 2 * e:2 * e + 4] += k
        self.Kr = K[2:, 2:]   # root clamped

    def flexibility(self, a):
        ne = len(self.x) - 1
        e = min(max(int(np.searchsorted(self.x, a, side="right")) - 1, 0), ne - 1)
        L = self.x[e + 1] - self.x[e]
        N, dN = hermite((a - self.x[e]) / L, L)
        G = np.zeros((2, 2))
        for col, load in enumerate((N, dN)):
            f = np.zeros(2 * (ne + 1))
            f[2 * e:2 * e + 4] = load
            q = np.concatenate([[0.0, 0.0], np.linalg.solve(self.Kr, f[2:])])
            qe = q[2 * e:2 * e + 4]
            G[0, col], G[1, col] = N @ qe, dN @ qe
        return G


def relief(rel, gear, roll):
    if not rel or rel.get("amount", 0.0) <= 0:
        return 0.0
    tip = math.sqrt(gear.ra**2 - gear.rb**2)
    st = rel["start"]
    if "length" in st:
        start = tip - st["length"]
    elif "diameter" in st:
        start = math.sqrt((st["diameter"] / 2) ** 2 - gear.rb**2)
    else:
        start = gear.rb * math.radians(st["roll_angle_deg"])
    if roll <= start:
        return 0.0
    u = min(1.0, (roll - start) / (tip - start))
    return rel["amount"] * (u * u if rel.get("shape", "linear") == "parabolic" else u)


def palmgren(F, L):
    return 3.84e-5 * F**0.9 / (L * 1e3) ** 0.8 / 1e3 if F > 0 else 0.0


def share(pairs, F, nh, split, L):
    """pairs: [(k, g)] or [(k, g, w)] (w: the contact's fraction of the line) -> (ste, forces)."""
    frac = [p[2] if len(p) > 2 else 1.0 for p in pairs]
    pairs = [(p[0], p[1]) for p in pairs]
    order = sorted(range(len(pairs)), key=lambda i: pairs[i][1])
    if split != "consistent" or nh == 0:
        for m in range(1, len(pairs) + 1):
            idx = order[:m]
            X = (F + sum(pairs[i][0] * pairs[i][1] for i in idx)) / sum(pairs[i][0] for i in idx)
            if m == len(pairs) or X <= pairs[order[m]][1]:
                break
        forces = [pairs[i][0] * (X - pairs[i][1]) if i in idx else 0.0 for i in range(len(pairs))]
        if split == "fe_split_mean":
            hz = nh * sum(palmgren(forces[i], L) for i in idx) / m
        else:
            hz = nh * palmgren(F / m, L)
        return X + hz, forces

    def force(i, X):
        k, g = pairs[i]
        d = X - g
        if d <= 0:
            return 0.0
        return brentq(lambda f: f / k + nh * palmgren(f / frac[i], L) - d, 0.0, k * d, xtol=1e-300, rtol=1e-15)

    k0, g0 = pairs[order[0]]
    X = brentq(lambda X: sum(force(i, X) for i in range(len(pairs))) - F, g0,
               g0 + 1.01 * (F / k0 + nh * palmgren(F / frac[order[0]], L)), xtol=1e-300, rtol=1e-15)
    return X, [force(i, X) for i in range(len(pairs))]


def lead(g, y, b):
    """Both lead modifications of one gear at y across the face b."""
    ld = g.get("lead", {})
    c = ld.get("crowning", 0.0) * (2 * y / b - 1) ** 2
    er = ld.get("end_relief", {})
    d = min(y, b - y)
    if er.get("amount", 0.0) > 0 and d < er["length"]:
        c += er["amount"] * (er["length"] - d) / er["length"]
    return c


def evaluate(f, positions=0, n_phases=None, slices=None):
    g1, g2 = Gear(f, f["gears"][0]), Gear(f, f["gears"][1])
    model = f.get("model", {})
    a = f.get("centre_distance", 0.0)
    if a > 0:
        aw = math.acos((g1.rb + g2.rb) / a)
    else:
        xs = g1.x + g2.x
        aw = g1.al if xs == 0 else inv_inverse(inv(g1.al) + 2 * math.tan(g1.al) * xs / (g1.z + g2.z))
    T1C, T2C = g1.rb * math.tan(aw), g2.rb * math.tan(aw)
    T1T2 = T1C + T2C
    T1E, T2A = math.sqrt(g1.ra**2 - g1.rb**2), math.sqrt(g2.ra**2 - g2.rb**2)
    T1A = T1T2 - T2A
    AE, pb = T1E - T1A, math.pi * g1.m * math.cos(g1.al)
    ne = model.get("tooth_elements", 0) or int(math.floor(8 * AE / pb + 1e-9))
    b1, b2 = Beam(g1, ne), Beam(g2, ne)
    nh = {"none": 0, "per_contact": 1, "per_tooth": 2}[model.get("hertz", "per_tooth")]
    split = model.get("pair_hertz", "equal_split")
    fused = model.get("pair_stiffness", "fused") == "fused"
    L = min(g1.b, g2.b)
    rel1, rel2 = f["gears"][0].get("tip_relief"), f["gears"][1].get("tip_relief")

    def stiffness(r1, r2, sharing):
        G1, G2 = b1.flexibility(r1 - g1.rf), b2.flexibility(r2 - g2.rf)
        if sharing and fused:
            D = np.diag([1.0, -1.0])
            return np.linalg.inv(G1 + D @ G2 @ D)[0, 0]
        return 1.0 / (G1[0, 0] + G2[0, 0])

    helical = f.get("helix_angle_deg", 0.0) > 0 or any("lead" in g for g in f["gears"])
    N = (slices or model.get("slices", 20)) if helical else 1
    eps_beta = L * math.sin(math.radians(f.get("helix_angle_deg", 0.0))) / (math.pi * g1.mn)

    ds = eps_beta * pb / N

    def point(s, gap, w):
        T1P = T1A + s
        T2P = T1T2 - T1P
        return (math.hypot(g1.rb, T1P), math.hypot(g2.rb, T2P), relief(rel1, g1, T1P) + relief(rel2, g2, T2P) + gap, w)

    def points(phase, slice_gap):
        if ds == 0:
            pts, s = [], phase * pb
            while s <= AE:
                pts.append(point(s, slice_gap, 1.0))
                s += pb
            return pts
        pts = []
        for q in range(-2, int(AE / pb) + 3):
            lo, hi = max(0.0, (phase + q) * pb - ds / 2), min(AE, (phase + q) * pb + ds / 2)
            if hi - lo > 1e-9 * ds:
                pts.append(point((lo + hi) / 2, slice_gap, min(1.0, (hi - lo) / ds)))
        return pts

    phases = []
    if positions:
        for j in range(positions):
            pts = [(g1.rf + b1.x[k], g2.rf + b2.x[ne + 1 - k]) for k in range(j + 1, ne + 1, positions)]
            phases.append([(r1, r2, 0.0) for r1, r2 in pts])
    else:
        n = n_phases or model.get("phases", 64)
        ys = [(j + 0.5) * L / N for j in range(N)]
        gaps = [lead(f["gears"][0], y, L) + lead(f["gears"][1], y, L) for y in ys]
        for j in range(n):
            pts = []
            for y, gap in zip(ys, gaps):
                psi = (j / n + eps_beta * y / L) % 1.0
                p = points(psi, gap)
                pts += [(r1, r2, g, w, len(p) > 1) for r1, r2, g, w in p]
            phases.append(pts)
    ks = [[(q[3] * stiffness(q[0], q[1], q[4]), q[2], q[3]) if len(q) > 3 else (stiffness(q[0], q[1], len(p) > 1), q[2])
           for q in p] for p in phases]
    out = {}
    for i, T in enumerate(f["torques"]):
        F = T / (g1.r if model.get("tooth_force", "pitch_radius") == "pitch_radius" else g1.rb)
        ste, loaded = [], []
        for pairs in ks:
            e, forces = share(pairs, N * F, nh, split, L)
            ste.append(e)
            loaded.append(sum(q[2] if len(q) > 2 else 1.0 for q, fi in zip(pairs, forces) if fi > 0))
        n = str(i + 1)
        out["ste_max_um_" + n] = max(ste) * 1e6
        out["ste_ptp_um_" + n] = (max(ste) - min(ste)) * 1e6
        out["ste_mean_um_" + n] = sum(ste) / len(ste) * 1e6
        out["mesh_stiffness_mean_N_per_m_" + n] = sum(F / e for e in ste) / len(ste)
        out["loaded_contact_ratio_" + n] = sum(loaded) / len(loaded) / N
        # one pair alone at the pitch point C (s = AC)
        alone = []
        for j in range(N):
            c = T1C - T1A + ((j + 0.5) / N - 0.5) * eps_beta * pb
            lo, hi = (max(0.0, c - ds / 2), min(AE, c + ds / 2)) if ds else (c, c)
            w = min(1.0, (hi - lo) / ds) if ds else float(0 <= c <= AE)
            if w > (1e-9 if ds else 0):
                T1P = T1A + (lo + hi) / 2
                alone.append((w * stiffness(math.hypot(g1.rb, T1P), math.hypot(g2.rb, T1T2 - T1P), False), 0.0, w))
        out["single_pair_deflection_um_" + n] = share(alone, N * F, nh, split, L)[0] * 1e6
    return out


def main():
    for path in sorted(EXAMPLES.glob("*.json")):
        f = json.load(open(path))
        if f.get("model", {}).get("method", "beam") != "beam":
            continue   # gear_pair_pe_ste.py
        for k, v in evaluate(f).items():
            print("%s %s %.16g" % (path.stem, k, v))
        # The loaded contact ratio converged in the phases: counted over 2048 phases
        # (error <= 2 / 2048: two lift-off points per cycle), for a file with tip relief.
        if any(g.get("tip_relief") for g in f["gears"]):
            for k, v in evaluate(f, n_phases=2048).items():
                if k.startswith("loaded_contact_ratio_"):
                    print("%s %s %.16g" % (path.stem + "_fine", k, v))
        if path.stem == "thesis_pair":
            for k, v in evaluate(f, positions=8).items():
                print("thesis_pair_p8 %s %.16g" % (k, v))


if __name__ == "__main__":
    main()
