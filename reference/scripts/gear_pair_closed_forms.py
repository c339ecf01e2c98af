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
"""
import json
import math
import pathlib

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "chapters" / "gearhb_gear" / "examples"


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
    m, al = f["module"], math.radians(f["pressure_angle_deg"])
    rack = f.get("basic_rack", {})
    ha, hf, rho = rack.get("addendum", 1.0), rack.get("dedendum", 1.25), rack.get("root_radius", 0.38)
    g = f["gears"]
    z = [g[0]["z"], g[1]["z"]]
    x = [g[0].get("x", 0.0), g[1].get("x", 0.0)]
    r = [m * zi / 2 for zi in z]
    rb = [ri * math.cos(al) for ri in r]
    ra = [r[i] + m * (ha + x[i]) for i in range(2)]
    rf = [r[i] - m * (hf - x[i]) for i in range(2)]
    a = f.get("centre_distance", 0.0)
    if a > 0:
        aw = math.acos((rb[0] + rb[1]) / a)
    else:
        aw = inv_inverse(inv(al) + 2 * math.tan(al) * (x[0] + x[1]) / (z[0] + z[1])) if x[0] + x[1] != 0 else al
        a = (rb[0] + rb[1]) / math.cos(aw)
    ga = math.sqrt(ra[0] ** 2 - rb[0] ** 2) + math.sqrt(ra[1] ** 2 - rb[1] ** 2) - a * math.sin(aw)
    pb = math.pi * m * math.cos(al)
    eps = ga / pb
    out = {"centre_distance_m": a, "operating_pressure_angle_deg": math.degrees(aw), "contact_ratio": eps,
           "path_of_contact_m": ga, "base_pitch_m": pb}
    zmin = []
    for i in range(2):
        n = str(i + 1)
        out["base_radius_%s_m" % n] = rb[i]
        out["tip_radius_%s_m" % n] = ra[i]
        out["root_radius_%s_m" % n] = rf[i]
        out["operating_pitch_radius_%s_m" % n] = rb[i] / math.cos(aw)
        s0 = m * (math.pi / 2 + 2 * x[i] * math.tan(al))
        out["tip_thickness_%s_m" % n] = ra[i] * s0 / r[i] + 2 * ra[i] * (inv(al) - inv(math.acos(rb[i] / ra[i])))
        zmin.append(2 * (hf - rho * (1 - math.sin(al)) - x[i]) / math.sin(al) ** 2)
        out["undercut_z_min_%s" % n] = zmin[i]
    out["undercut"] = 1.0 if any(z[i] < zmin[i] for i in range(2)) else 0.0
    # ISO 6336-1 method B (spur)
    q = (0.04723 + 0.15551 / z[0] + 0.25791 / z[1] - 0.00635 * x[0] - 0.11654 * x[0] / z[0] - 0.00193 * x[1]
         - 0.24188 * x[1] / z[1] + 0.00529 * x[0] ** 2 + 0.00182 * x[1] ** 2)
    b_mm = min(g[0]["b"], g[1]["b"]) * 1e3
    line_load = max(f["torques"]) / r[0] / b_mm
    load = (line_load / 100) ** 0.25 if line_load < 100 else 1.0
    C_B = (1 + 0.5 * (1.2 - hf)) * (1 - 0.02 * (20 - f["pressure_angle_deg"]))
    out["iso6336_c_prime_th"] = 1 / q
    out["iso6336_c_prime"] = (1 / q) * 0.8 * 1.0 * C_B * load
    out["iso6336_c_gamma_alpha"] = out["iso6336_c_prime"] * (0.75 * eps + 0.25)
    return out


def main():
    for path in sorted(EXAMPLES.glob("*.json")):
        for k, v in closed_forms(json.load(open(path))).items():
            print("%s %s %.16g" % (path.stem, k, v))


if __name__ == "__main__":
    main()
