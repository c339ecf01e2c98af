#!/usr/bin/env python3
"""The sun-planet mesh stiffness of a planetary set computed from its teeth equals gearhb_gear's
for the same pair (issue 36; lib/gearhb/tools/planetary_stiffness.hpp).

    planetary_pair_stiffness.py BIN_DIR SET.json PAIR.json WORK_DIR

Runs gearhb_planetary on SET.json (mesh.stiffness tooth_model; its response cut to a few points:
only the stiffness is compared) and gearhb_gear on PAIR.json, a gear-pair file of the same
sun-planet pair written by hand with T1 = the input torque / N (sun input, tooth force over the
base radius: the mesh's nominal force). Checks, phase by phase, that mesh_stiffness.csv's
k_sun_planet_N_per_m equals ste_1.csv's k_N_per_m (relative 1e-9: the two CSV writers round
alike), and that the key number torque_Nm_sun_planet is PAIR.json's torque.
"""
import csv
import json
import os
import shutil
import subprocess
import sys


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()}")


def column(path, name):
    with open(path, newline="") as f:
        return [(float(row["phase"]), float(row[name])) for row in csv.DictReader(f)]


def main():
    bin_dir, set_file, pair_file, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    planetary, gear = os.path.join(work, "planetary"), os.path.join(work, "gear")
    run([os.path.join(bin_dir, "gearhb_planetary"), set_file, "--set", "plot=0", "--set", "response.f_mesh_hz.to=1320",
         "--set", "response.stability=0", "--quiet", "--out", planetary])
    run([os.path.join(bin_dir, "gearhb_gear"), pair_file, "--set", "plot=0", "--quiet", "--out", gear])
    ours = column(os.path.join(planetary, "mesh_stiffness.csv"), "k_sun_planet_N_per_m")
    theirs = column(os.path.join(gear, "ste_1.csv"), "k_N_per_m")
    if len(ours) != len(theirs):
        sys.exit(f"{len(ours)} phases against gearhb_gear's {len(theirs)}")
    worst = 0.0
    for (p1, k1), (p2, k2) in zip(ours, theirs):
        if abs(p1 - p2) > 1e-12:
            sys.exit(f"phase {p1} against gearhb_gear's {p2}")
        worst = max(worst, abs(k1 / k2 - 1.0))
    with open(os.path.join(planetary, "key_numbers.json")) as f:
        keys = json.load(f)
    T1 = keys["torque_Nm_sun_planet"]["value"]
    with open(pair_file) as f:
        T_hand = json.load(f)["torques"][0]
    print(f"{len(ours)} phases: largest relative difference of k {worst:.3g}; T1 {T1} N m against {T_hand} by hand")
    if worst > 1e-9 or abs(T1 / T_hand - 1.0) > 1e-12:
        sys.exit("the planetary set's sun-planet stiffness is not gearhb_gear's")


if __name__ == "__main__":
    main()
