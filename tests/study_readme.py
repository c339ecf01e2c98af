#!/usr/bin/env python3
"""The numbers studies/README.md quotes from the example study, against a fresh run of it.

    study_readme.py BUILD_DIR WORK_DIR

Runs studies/tip_relief.json through Snakemake on 2 cores (about a minute) and checks every row
of the README's result table (unmodified and best STE peak-to-peak and peak K_v, the best
amounts, the single-pair deflection) and the design count. CTest: studies.tip_relief_readme.
"""
import csv
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
ROW = re.compile(r"^\| (short|long) \| (\d+) N m \| ([\d.]+) -> ([\d.]+) um \(([\d.]+) um\) \| ([\d.]+) -> ([\d.]+) "
                 r"\(([\d.]+) um\) \| ([\d.]+) um \|$", re.M)
LENGTH = {"short": "0.0066839999999999998", "long": "0.0088563943022806485"}


def main(build, work):
    work = pathlib.Path(work).resolve()
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    out = work / "tip_relief"
    subprocess.run(["snakemake", "-s", str(ROOT / "studies" / "Snakefile"), "--cores", "2", "--quiet", "--config",
                    "study=%s" % (ROOT / "studies" / "tip_relief.json"), "out=%s" % out,
                    "gearhb=%s" % (pathlib.Path(build).resolve() / "bin" / "gearhb_gear")],
                   cwd=work, check=True, capture_output=True)
    rows = list(csv.DictReader(open(out / "table.csv")))
    text = (ROOT / "studies" / "README.md").read_text()
    errors = []
    if "**%d designs**, 0 failed" % len(rows) not in text or any(r["status"] != "ok" for r in rows):
        errors.append("design count or failures differ from the README (%d designs)" % len(rows))
    quoted = ROW.findall(text)
    if len(quoted) != 6:
        errors.append("expected 6 result rows in the README, found %d" % len(quoted))
    for length, torque, u_ptp, b_ptp, a_ptp, u_kv, b_kv, a_kv, delta in quoted:
        sub = [r for r in rows if r["gears.0.tip_relief.start.length"] == LENGTH[length] and r["torques.0"] == torque]
        unmod = [r for r in sub if float(r["gears.0.tip_relief.amount"]) == 0][0]
        best_ptp = min(sub, key=lambda r: float(r["ste_ptp_um_1"]))
        best_kv = min(sub, key=lambda r: float(r["dynamic_factor_peak_1"]))
        got = [("%.3f", float(unmod["ste_ptp_um_1"]), u_ptp), ("%.3f", float(best_ptp["ste_ptp_um_1"]), b_ptp),
               ("%g", 1e6 * float(best_ptp["gears.0.tip_relief.amount"]), a_ptp),
               ("%.3f", float(unmod["dynamic_factor_peak_1"]), u_kv), ("%.3f", float(best_kv["dynamic_factor_peak_1"]), b_kv),
               ("%g", 1e6 * float(best_kv["gears.0.tip_relief.amount"]), a_kv),
               ("%.2f", float(unmod["single_pair_deflection_um_1"]), delta)]
        for fmt, value, readme in got:
            if float(fmt % value) != float(readme):
                errors.append("%s %s N m: README %s, study %s" % (length, torque, readme, fmt % value))
    for e in errors:
        print(e)
    print("studies README: %d rows checked, %d problems" % (len(quoted), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
