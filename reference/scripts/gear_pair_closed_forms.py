#!/usr/bin/python3
"""Independent reference values of reference/gear_examples/*.json (gearhb_gear examples).

Run:  /usr/bin/python3 reference/scripts/gear_pair_closed_forms.py
Prints, per example file, "example key value" for every number this script produces.
Nothing here calls gearhb; it reads the example JSON files only for their inputs.

Geometry (ISO 21771; Niemann & Winter, Maschinenelemente II, ch. 21), x the shift:
  r = m z / 2, rb = r cos(alpha), ra = r + m (ha* + x), rf = r - m (hf* - x);
  centre distance: given a -> cos(alpha_w) = (rb1 + rb2) / a, else
  inv(alpha_w) = inv(alpha) + 2 tan(alpha) (x1 + x2)/(z1 + z2) (bisection, 200 halvings),
  a = (rb1 + rb2) / cos(alpha_w);
  path of contact g_alpha = sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a sin(alpha_w),
  pb = pi m cos(alpha), eps_alpha = g_alpha / pb;
  tip thickness s(ra) = ra s0 / r + 2 ra (inv(alpha) - inv(acos(rb / ra))), s0 = m (pi/2 + 2 x tan alpha);
  undercut limit z_min = 2 (hf* - rho_f* (1 - sin alpha) - x) / sin^2(alpha).
ISO 6336-1:2006 clause 9 (Method B), spur (beta = 0, z_n = z), written out here again:
  q' = 0.04723 + 0.15551/z1 + 0.25791/z2 - 0.00635 x1 - 0.11654 x1/z1 - 0.00193 x2
       - 0.24188 x2/z2 + 0.00529 x1^2 + 0.00182 x2^2   (C9 multiplies x2^2),
  c'_th = 1/q', C_M = 0.8, C_R = 1, C_B = [1 + 0.5 (1.2 - hf*)] [1 - 0.02 (20 - alpha)],
  line-load factor (F_t / b / 100)^0.25 below 100 N/mm (F_t = T1 / r1 at the largest torque),
  c' = c'_th C_M C_R C_B, c_gamma_alpha = c' (0.75 eps_alpha + 0.25) [N/(mm um)].
ISO 6336-1:2006 clause 6.3 (method B) dynamic factor, for a file with a speed range, per torque
(K_A = 1, F_t = T1 / r1, line load w = F_t / b, c' and c_gamma_alpha at that line load):
  ISO 1328-1:1995 grade Q: m, d the geometric means of the range bounds that hold the gear,
  f_pt = [0.3 (m + 0.4 sqrt d) + 4] 2^((Q-5)/2), f_falpha = [2.5 sqrt m + 0.17 sqrt d + 0.5] 2^((Q-5)/2),
  rounded (> 10 um: 1 um, 5..10: 0.5 um, < 5: 0.1 um); f_pb = f_pt cos(alpha), the larger gear's;
  case-hardened running-in y = min(0.075 f, 3 um); C_a = the larger tip relief, or without one
  C_ay = (1500/97 - 18.45)^2 / 18 + 1.5 um;
  m_red = I1 I2 / (I1 rb2^2 + I2 rb1^2) / b [kg/mm], n_E1 = 30000 / (pi z1) sqrt(c_gamma_alpha / m_red),
  N = n1 / n_E1, N_S = 0.5 + 0.35 sqrt(w / 100) (w < 100 N/mm) or 0.85,
  B_p = c' f_pb,eff / w, B_f = c' f_f,eff / w, B_k = |1 - c' C_a / w|, eps_gamma = eps_alpha (spur):
  K_v = N (C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1 (N <= N_S), C_v1 B_p + C_v2 B_f + C_v4 B_k + 1
  (N <= 1.15), C_v5 B_p + C_v6 B_f + C_v7 (N >= 1.5), linear between; the peak over the 801
  evenly spaced speeds of iso_kv.csv.
"""
import json
import math
import pathlib

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "programs" / "gearhb_gear" / "examples"


def inv(a):
    return math.tan(a) - a


def inv_inverse(v):
    lo, hi = 0.0, 1.5
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if inv(mid) < v:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def closed_forms(f):
    mn, aln = f["module"], math.radians(f["pressure_angle_deg"])
    beta = math.radians(f.get("helix_angle_deg", 0.0))
    # ISO 21771 transverse quantities (helical; the spur values at beta = 0)
    m = mn / math.cos(beta)
    al = math.atan(math.tan(aln) / math.cos(beta)) if beta else aln
    rack = f.get("basic_rack", {})
    ha, hf, rho = rack.get("addendum", 1.0), rack.get("dedendum", 1.25), rack.get("root_radius", 0.38)
    g = f["gears"]
    z = [g[0]["z"], g[1]["z"]]
    x = [g[0].get("x", 0.0), g[1].get("x", 0.0)]
    r = [m * zi / 2 for zi in z]
    rb = [ri * math.cos(al) for ri in r]
    ra = [r[i] + mn * (ha + x[i]) for i in range(2)]
    rf = [r[i] - mn * (hf - x[i]) for i in range(2)]
    a = f.get("centre_distance", 0.0)
    if a > 0:
        aw = math.acos((rb[0] + rb[1]) / a)
    else:
        aw = inv_inverse(inv(al) + 2 * math.tan(aln) * (x[0] + x[1]) / (z[0] + z[1])) if x[0] + x[1] != 0 else al
        a = (rb[0] + rb[1]) / math.cos(aw)
    ga = math.sqrt(ra[0] ** 2 - rb[0] ** 2) + math.sqrt(ra[1] ** 2 - rb[1] ** 2) - a * math.sin(aw)
    pb = math.pi * m * math.cos(al)
    eps = ga / pb
    b = min(g[0]["b"], g[1]["b"])
    eps_beta = b * math.sin(beta) / (math.pi * mn)
    out = {"centre_distance_m": a, "operating_pressure_angle_deg": math.degrees(aw), "contact_ratio": eps,
           "path_of_contact_m": ga, "base_pitch_m": pb, "overlap_ratio": eps_beta, "total_contact_ratio": eps + eps_beta,
           "transverse_module_m": m, "transverse_pressure_angle_deg": math.degrees(al),
           "base_helix_angle_deg": math.degrees(math.asin(math.sin(beta) * math.cos(aln)))}
    zmin = []
    for i in range(2):
        n = str(i + 1)
        out["base_radius_%s_m" % n] = rb[i]
        out["tip_radius_%s_m" % n] = ra[i]
        out["root_radius_%s_m" % n] = rf[i]
        out["operating_pitch_radius_%s_m" % n] = rb[i] / math.cos(aw)
        s0 = m * (math.pi / 2 + 2 * x[i] * math.tan(aln))   # ISO 21771: s_t = m_t (pi/2 + 2 x tan alpha_n)
        out["tip_thickness_%s_m" % n] = ra[i] * s0 / r[i] + 2 * ra[i] * (inv(al) - inv(math.acos(rb[i] / ra[i])))
        # in the transverse section (coefficients in m_t: times cos(beta))
        zmin.append(2 * math.cos(beta) * (hf - rho * (1 - math.sin(al)) - x[i]) / math.sin(al) ** 2)
        out["undercut_z_min_%s" % n] = zmin[i]
    out["undercut"] = 1.0 if any(z[i] < zmin[i] for i in range(2)) else 0.0
    # ISO 6336-1 method B: virtual numbers of teeth zn = z / (cos^2 beta_b cos beta), c' with cos(beta)
    cb = math.cos(math.asin(math.sin(beta) * math.cos(aln)))
    zn = [zi / (cb * cb * math.cos(beta)) for zi in z]
    q = (0.04723 + 0.15551 / zn[0] + 0.25791 / zn[1] - 0.00635 * x[0] - 0.11654 * x[0] / zn[0] - 0.00193 * x[1]
         - 0.24188 * x[1] / zn[1] + 0.00529 * x[0] ** 2 + 0.00182 * x[1] ** 2)
    b_mm = b * 1e3
    line_load = max(f["torques"]) / r[0] / b_mm
    load = (line_load / 100) ** 0.25 if line_load < 100 else 1.0
    C_B = (1 + 0.5 * (1.2 - hf)) * (1 - 0.02 * (20 - f["pressure_angle_deg"]))
    out["iso6336_c_prime_th"] = 1 / q
    out["iso6336_c_prime"] = (1 / q) * 0.8 * 1.0 * C_B * math.cos(beta) * load
    out["iso6336_c_gamma_alpha"] = out["iso6336_c_prime"] * (0.75 * eps + 0.25)
    out["iso6336_c_gamma_beta"] = 0.85 * out["iso6336_c_gamma_alpha"]
    if "speed" in f:
        out.update(iso_kv(f, z, x, r, rb, eps, hf, C_B, b_mm))
    return out


def iso1328(Q, m_mm, d_mm):
    def mean(v, bounds):
        for lo, hi in zip(bounds, bounds[1:]):
            if v <= hi:
                return math.sqrt(lo * hi)
        raise ValueError("outside ISO 1328-1")

    def rnd(v):
        step = 1.0 if v > 10 else 0.5 if v >= 5 else 0.1
        return math.floor(v / step + 0.5) * step

    m = mean(m_mm, [0.5, 2, 3.5, 6, 10, 16, 25, 40, 70])
    d = mean(d_mm, [5, 20, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6000, 8000, 10000])
    q = 2.0 ** ((Q - 5) / 2)
    return rnd((0.3 * (m + 0.4 * math.sqrt(d)) + 4) * q), rnd((2.5 * math.sqrt(m) + 0.17 * math.sqrt(d) + 0.5) * q)


def iso_kv(f, z, x, r, rb, eps, hf, C_B, b_mm):
    g = f["gears"]
    Q = f.get("dynamics", {}).get("iso_quality_grade", 5)
    tol = [iso1328(Q, f["module"] * 1e3, 2 * r[i] * 1e3) for i in range(2)]
    f_pb = max(t[0] for t in tol) * math.cos(math.radians(f["pressure_angle_deg"]))
    f_fa = max(t[1] for t in tol)
    pb_eff, fa_eff = f_pb - min(0.075 * f_pb, 3.0), f_fa - min(0.075 * f_fa, 3.0)
    relief = max(gi.get("tip_relief", {}).get("amount", 0.0) for gi in g) * 1e6
    C_a = relief if relief > 0 else (1500 / 97 - 18.45) ** 2 / 18 + 1.5
    I1, I2 = g[0]["inertia"], g[1]["inertia"]
    m_red = I1 * I2 / (I1 * rb[1] ** 2 + I2 * rb[0] ** 2) / b_mm
    q = (0.04723 + 0.15551 / z[0] + 0.25791 / z[1] - 0.00635 * x[0] - 0.11654 * x[0] / z[0] - 0.00193 * x[1]
         - 0.24188 * x[1] / z[1] + 0.00529 * x[0] ** 2 + 0.00182 * x[1] ** 2)
    eg = eps
    if eg <= 2:
        C1, C2, C3, C4, C5, C6 = 0.32, 0.34, 0.23, 0.90, 0.47, 0.47
    else:
        C1, C2, C3 = 0.32, 0.57 / (eg - 0.3), 0.096 / (eg - 1.56)
        C4, C5, C6 = (0.57 - 0.05 * eg) / (eg - 1.44), 0.47, 0.12 / (eg - 1.74)
    C7 = 0.75 if eg <= 1.5 else (0.125 * math.sin(math.pi * (eg - 2)) + 0.875 if eg <= 2.5 else 1.0)
    sp = f["speed"]
    to_rpm = 60.0 / z[0] if sp.get("unit", "mesh_hz") == "mesh_hz" else 1.0
    n_from, n_to = sp["from"] * to_rpm, sp["to"] * to_rpm
    out = {"iso_f_pb_um": f_pb, "iso_f_f_alpha_um": f_fa, "iso_tip_relief_um": C_a}
    for i, T in enumerate(f["torques"]):
        w = T / r[0] / b_mm
        cp = (1 / q) * 0.8 * C_B * ((w / 100) ** 0.25 if w < 100 else 1.0)
        cga = cp * (0.75 * eps + 0.25)
        nE = 30000 / (math.pi * z[0]) * math.sqrt(cga / m_red)
        NS = 0.5 + 0.35 * math.sqrt(w / 100) if w < 100 else 0.85
        Bp, Bf, Bk = cp * pb_eff / w, cp * fa_eff / w, abs(1 - cp * C_a / w)
        res, sup = C1 * Bp + C2 * Bf + C4 * Bk + 1, C5 * Bp + C6 * Bf + C7

        def kv(n1):
            N = n1 / nE
            if N <= NS:
                return N * (C1 * Bp + C2 * Bf + C3 * Bk) + 1
            if N <= 1.15:
                return res
            if N < 1.5:
                return sup + (res - sup) * (1.5 - N) / 0.35
            return sup

        out["iso_kv_resonance_speed_rpm_%d" % (i + 1)] = nE
        out["iso_kv_peak_%d" % (i + 1)] = max(kv(n_from + (n_to - n_from) * j / 800) for j in range(801))
    return out


def main():
    for path in sorted(EXAMPLES.glob("*.json")):
        for k, v in closed_forms(json.load(open(path))).items():
            print("%s %s %.16g" % (path.stem, k, v))


if __name__ == "__main__":
    main()
