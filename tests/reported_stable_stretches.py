#!/usr/bin/env python3
"""A stability label must not rest on a failed correction (issue 34): runs gearhb_gear and checks
its console lines of the period-2 (4) branches against its own table frc_1.csv.

  reported_stable_stretches.py GEARHB_GEAR MODEL OUT [--set key=value]...
  reported_stable_stretches.py --ran OUT      (a run CTest made: its stdout in OUT.stdout)

For every line "period-p branch k, ...: stable at a-b, ... rpm; largest stable K_v K, ...;
stability unresolved (shooting correction failed) at c, d-e rpm":
  - each stretch a-b holds a stable row of branch k (speed within a-b, rounded to 1 rpm) whose
    shooting correction converged (exact != not_converged);
  - every run of consecutive stable rows of branch k all with exact = not_converged (an
    unresolved stretch) is in the unresolved list, and in no stable stretch but where a
    resolved stable row lies within 1 rpm of it;
  - K is the largest dynamic_factor over the stable rows outside those runs (to the printed 2 decimals).
The table's `exact` column comes from each point's shooting, independent of how the program
groups the labels into stretches. Exit 1 naming what fails."""
import csv
import re
import subprocess
import sys
from pathlib import Path

LINE = re.compile(r"period-(\d+) branch (\d+), [^:]*:(?: stable at ([^;]*?) rpm; largest stable K_v ([\d.]+),[^;]*)?"
                  r"(?: unstable everywhere)?(?:; stability unresolved \(shooting correction failed\) at (.*) rpm)?$")


def stretches(text):
    out = []
    for part in (text or "").split(","):
        a, _, b = part.strip().partition("-")
        if a:
            out.append((float(a), float(b or a)))
    return out


def unresolved_runs(rows):
    """Runs [i, j] of consecutive stable rows all with exact = not_converged."""
    runs, i = [], 0
    while i < len(rows):
        j = i
        while rows[i]["stable"] == "1" and j + 1 < len(rows) and rows[j + 1]["stable"] == "1":
            j += 1
        if rows[i]["stable"] == "1" and all(rows[k]["exact"] == "not_converged" for k in range(i, j + 1)):
            runs.append((i, j))
        i = j + 1
    return runs


def check_branch(rows, stable_at, kv, unresolved, name):
    errors = []
    speed = lambda r: float(r["speed_rpm"])
    inside = lambda r, a, b: a - 0.5 <= speed(r) <= b + 0.5
    runs = unresolved_runs(rows)
    bad = {k for i, j in runs for k in range(i, j + 1)}
    resolved = [r for k, r in enumerate(rows) if r["stable"] == "1" and k not in bad]
    for a, b in stable_at:
        if not any(inside(r, a, b) and r["exact"] != "not_converged" for r in resolved):
            errors.append("%s: stable at %g-%g rpm, but no stable row there has a converged correction" % (name, a, b))
    for i, j in runs:
        lo, hi = min(speed(rows[i]), speed(rows[j])), max(speed(rows[i]), speed(rows[j]))
        if not any(a - 0.5 <= lo and hi <= b + 0.5 for a, b in unresolved):
            errors.append("%s: rows at %.2f-%.2f rpm are stable with no converged correction, not listed unresolved"
                          % (name, lo, hi))
        near = any(abs(speed(r) - lo) < 1 or abs(speed(r) - hi) < 1 for r in resolved)
        if not near and any(a - 0.5 <= lo and hi <= b + 0.5 for a, b in stable_at):
            errors.append("%s: the unresolved rows at %.2f-%.2f rpm are reported stable" % (name, lo, hi))
    if kv is not None and resolved and "%.2f" % max(float(r["dynamic_factor"]) for r in resolved) != kv:
        errors.append("%s: largest stable K_v %s, the table's resolved stable rows give %.4f"
                      % (name, kv, max(float(r["dynamic_factor"]) for r in resolved)))
    return errors, len(runs)


def main(program, model, out, sets):
    if program == "--ran":   # the run's stdout and folder (a CTest fixture ran the command)
        out = model
        text = Path(out + ".stdout").read_text()
    else:
        text = subprocess.run([program, model, "--out", out, "--set", "plot=0"] + sets, check=True,
                              capture_output=True, text=True).stdout
    rows = list(csv.DictReader(open(Path(out) / "frc_1.csv")))
    first = re.search(r"T1 = (\S+) N m", text).group(1)   # frc_1.csv: the file's first torque
    errors, lines, runs = [], 0, 0
    for line in text.splitlines():
        if ": T1 = %s N m: period-" % first not in line or "PD at" in line:
            continue
        m = LINE.search(line)
        if not m:
            errors.append("unparsed: " + line)
            continue
        period, branch = m.group(1), m.group(2)
        mine = [r for r in rows if r["period"] == period and r["branch"] == branch]
        e, n = check_branch(mine, stretches(m.group(3)), m.group(4), stretches(m.group(5)),
                            "period-%s branch %s" % (period, branch))
        errors += e
        lines += 1
        runs += n
    print("%d branch lines of the first torque checked, %d unresolved stretches in its table" % (lines, runs))
    if lines == 0:
        errors.append("no branch line found")
    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else None, sys.argv[4:]))
