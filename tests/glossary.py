#!/usr/bin/env python3
"""The glossary (README "Glossary") against the code: a gear run's files use each name for
the quantity the glossary defines, recomputed here from the run's own tables.

  k(theta) = F / STE               ste_<i>.csv k_N_per_m; its mean mesh_stiffness_mean_N_per_m_<i>
  k_e(theta) = F / (STE - g)       its mean mesh_stiffness_kc_N_per_m_<i>, the kc of the dynamics
                                   (g: the no-load transmission error, the smallest separation)
  f_mesh_hz = omega / (2 pi)       frc_<i>.csv
  speed_rpm = 60 f_mesh_hz / z1    frc_<i>.csv

usage: glossary.py RUN_DIR GEAR_FILE.json   (RUN_DIR: a gearhb_gear run with a speed range)
Exit 1 naming the first name whose quantity differs (1e-9 relative), 0 otherwise.
"""
import csv
import json
import math
import pathlib
import sys

REL = 1e-9


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def close(a, b):
    return abs(a - b) <= REL * max(abs(a), abs(b), 1e-300)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run, gear_file = pathlib.Path(sys.argv[1]), json.load(open(sys.argv[2]))
    key = {k: v["value"] for k, v in json.load(open(run / "key_numbers.json")).items()}
    z1 = gear_file["gears"][0]["z"]
    bad, checked = [], 0
    for i in range(1, len(gear_file["torques"]) + 1):
        F = key["tooth_force_N_%d" % i]
        ste = rows(run / ("ste_%d.csv" % i))
        k = [F / (float(r["ste_um"]) * 1e-6) for r in ste]
        seps = [[float(r[c]) for c in r if c.startswith("separation_um_") and r[c] != ""] for r in ste]
        ke = [F / ((float(r["ste_um"]) - min(s)) * 1e-6) for r, s in zip(ste, seps)]
        pairs = [("k_N_per_m", float(r["k_N_per_m"]), kk) for r, kk in zip(ste, k)]
        pairs.append(("mesh_stiffness_mean_N_per_m_%d" % i, key["mesh_stiffness_mean_N_per_m_%d" % i], sum(k) / len(k)))
        if "mesh_stiffness_kc_N_per_m_%d" % i in key:
            pairs.append(("mesh_stiffness_kc_N_per_m_%d" % i, key["mesh_stiffness_kc_N_per_m_%d" % i],
                          sum(ke) / len(ke)))
        frc = run / ("frc_%d.csv" % i)
        if frc.exists():
            for r in rows(frc):
                w = float(r["omega"])
                pairs += [("f_mesh_hz", float(r["f_mesh_hz"]), w / (2 * math.pi)),
                          ("speed_rpm", float(r["speed_rpm"]), 60 * w / (2 * math.pi) / z1)]
        for name, ours, glossary in pairs:
            checked += 1
            if not close(ours, glossary):
                bad.append("%s (torque %d): the run has %.12g, the glossary's definition gives %.12g"
                           % (name, i, ours, glossary))
    for b in bad[:10]:
        print(b)
    print("glossary.py: %d values checked, %d differ" % (checked, len(bad)))
    return 1 if bad or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
