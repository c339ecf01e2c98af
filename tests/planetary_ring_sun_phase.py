#!/usr/bin/env python3
"""gearhb_planetary's ring-sun phase gamma_rs from the teeth (key number ring_sun_phase_from_teeth,
and ring_sun_phase where the file does not give it) against the construction in the plane of
reference/scripts/planetary_ring_sun_phase.py (issue 36); and the ring-planet mesh's back-flank
mirror phase (key number back_mirror_phase_ring_planet) against its construction there.

    planetary_ring_sun_phase.py BIN_DIR SET.json WORK_DIR

Three tooth sets: SET.json's, 27 / 33 / 93 teeth, and SET.json's at 20 degrees; each run's
response cut to a few points (only the phase is compared). Agreement to 1e-9 of a cycle.
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "reference", "scripts"))
from planetary_ring_sun_phase import ring_back_mirror, ring_sun_phase  # noqa: E402


def main():
    bin_dir, set_file, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(set_file) as f:
        s = json.load(f)
    t = s["teeth"]
    cases = [({}, (t["sun"], t["planet"], t["ring"], s["pressure_angle_deg"])),
             ({"teeth.sun": 27, "teeth.ring": 93}, (27, t["planet"], 93, s["pressure_angle_deg"])),
             ({"pressure_angle_deg": 20}, (t["sun"], t["planet"], t["ring"], 20.0))]
    bad = 0
    for i, (sets, (zs, zp, zr, alpha)) in enumerate(cases):
        out = os.path.join(work, str(i))
        cmd = [os.path.join(bin_dir, "gearhb_planetary"), set_file, "--set", "plot=0", "--set",
               "response.f_mesh_hz.to=1320", "--set", "response.stability=0", "--quiet", "--out", out]
        for k, v in sets.items():
            cmd += ["--set", f"{k}={v}"]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()}")
        with open(os.path.join(out, "key_numbers.json")) as f:
            keys = json.load(f)
        ours, used = keys["ring_sun_phase_from_teeth"]["value"], keys["ring_sun_phase"]["value"]
        ref = ring_sun_phase(zs, zp, zr, s["module"], alpha)
        d = min(abs(ours - ref), 1 - abs(ours - ref))
        print(f"z {zs}/{zp}/{zr}, {alpha} deg: gamma_rs {ours:.12f}, construction {ref:.12f}, used {used:.12f}")
        back, back_ref = keys["back_mirror_phase_ring_planet"]["value"], ring_back_mirror(zs, zp, zr, s["module"], alpha)
        d_back = min(abs(back - back_ref), 1 - abs(back - back_ref))
        print(f"    ring-planet back-flank mirror phase {back:.12f}, construction {back_ref:.12f}")
        if d > 1e-9 or used != ours or d_back > 1e-9:
            bad += 1
    if bad:
        sys.exit(f"{bad} case(s) differ")


if __name__ == "__main__":
    main()
