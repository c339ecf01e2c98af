#!/usr/bin/python3
"""The thesis gear file through gearhb_gear reproduces chapter 8 (issue 21 §2).

Usage: gear_dynamics_vs_ch08.py GEARHB_GEAR CH08 EXAMPLE WORKDIR
Runs chapter 8's regression subset (H = 5 at 100 / 200 / 300 N m, drive flank only) and
gearhb_gear on programs/gearhb_gear/examples/thesis_pair.json (the same pair, chapter 8's
speed range, damping and H, with its 15 um backlash and the back flank modelled), then
checks per torque, with the issue's tolerances:
  peak DTE RMS           within 0.5 %   (dte_rms_peak_um_<i> vs peak_rms_um_T<T>_H5)
  every fold             within 2 Hz    (bifurcations_<i>.csv vs bifurcations_T<T>_H5.csv)
  first drive-flank loss within 2 Hz    (drive_loss_first_f_mesh_hz_<i> vs loss_onset_hz_T<T>_H5)
and that the back flank is never reached (no back_impact_first_f_mesh_hz_<i>), so the two
programs solve the same problem. Prints one line per check; exit 1 on any failure.
"""
import csv
import json
import math
import pathlib
import shutil
import subprocess
import sys


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("FAIL: %s exited %d: %s" % (cmd[0], r.returncode, r.stderr.strip()[-400:]))


def folds(path):
    with open(path) as f:
        return sorted(float(r["omega"]) / (2 * math.pi) for r in csv.DictReader(f) if r["type"] == "fold")


def main():
    gear, ch08, example, work = sys.argv[1], sys.argv[2], sys.argv[3], pathlib.Path(sys.argv[4])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    run([ch08, "--case", "quick", "--quiet", "--out", str(work / "ch08")])
    run([gear, example, "--set", "plot=0", "--quiet", "--out", str(work / "gear")])
    a = {k: v["value"] for k, v in json.load(open(work / "ch08" / "key_numbers.json")).items()}
    b = {k: v["value"] for k, v in json.load(open(work / "gear" / "key_numbers.json")).items()}
    failed = 0

    def check(name, ours, theirs, ok):
        nonlocal failed
        print("%-4s %-40s gearhb_gear %-14.8g ch08 %-14.8g" % ("ok" if ok else "FAIL", name, ours, theirs))
        failed += 0 if ok else 1

    for i, T in enumerate((100, 200, 300), start=1):
        tag = "T%d_H5" % T
        ours, theirs = b["dte_rms_peak_um_%d" % i], a["peak_rms_um_" + tag]
        check("peak DTE RMS %d N m [um]" % T, ours, theirs, abs(ours - theirs) <= 5e-3 * theirs)
        fo, ft = folds(work / "gear" / ("bifurcations_%d.csv" % i)), folds(work / "ch08" / ("bifurcations_%s.csv" % tag))
        check("fold count %d N m" % T, len(fo), len(ft), len(fo) == len(ft) and len(fo) > 0)
        for k, (x, y) in enumerate(zip(fo, ft)):
            check("fold %d at %d N m [Hz]" % (k + 1, T), x, y, abs(x - y) <= 2.0)
        ours, theirs = b.get("drive_loss_first_f_mesh_hz_%d" % i, math.nan), a["loss_onset_hz_" + tag]
        check("first drive-flank loss %d N m [Hz]" % T, ours, theirs, abs(ours - theirs) <= 2.0)
        check("back flank never reached %d N m" % T, 0, 0, "back_impact_first_f_mesh_hz_%d" % i not in b)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
