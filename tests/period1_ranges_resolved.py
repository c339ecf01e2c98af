#!/usr/bin/env python3
"""A range with no stable period-1 orbit excludes only resolved-stable points (issue 34): checks a
run's key numbers against its own frequency-response table.

  period1_ranges_resolved.py DIR TABLE X UNIT SUFFIX [--expect-unresolved] [--period P]... [--diagram CSV]

TABLE: the run's table in DIR (frc.csv, frc_1.csv, frc_fig40.csv); X its frequency column (omega,
speed_rpm); UNIT the key numbers' infix (omega, rpm); SUFFIX their suffix (_1, _fig40; - for none). An
unresolved run is a run of consecutive stable rows of one branch all with exact = not_converged (the
label rests on no converged shooting correction); a resolved stable row, any other stable row. On
the period-1 curve (branch 0), between its first and last row:
  - no resolved stable row lies inside an unstable_period1_from_<UNIT><SUFFIX>_k ..._to_... range
    (a stable orbit exists there);
  - every row of an unresolved run lies in an unresolved_period1_from_<UNIT><SUFFIX>_k ... range
    (the part of a range whose labels say stable but rest on no correction), unless a run of
    resolved stable rows (another sheet of the curve) spans its frequency: it is not counted
    stable, so it lies in a range where no other orbit is;
  - every unresolved_period1 range lies in an unstable_period1 range and holds a row of an
    unresolved run.
--period P (P > 1): every unresolved run of a period-P branch lies in a range
unresolved_periodP_from_omega<SUFFIX>_k ..._to_... (omega: the branches' keys are in rad/s), and
every such range holds one. --diagram CSV (a bifurcation diagram of the run, column X): every
unstable_period1 range, its unresolved stretches included, holds a speed of the diagram (the
library adds one where the grid misses the range) and lies within one band of the diagram's
speeds (a band ends where the gap to the next speed exceeds 1.5 times the larger of the steps beside it, as
figures/ch06_gear_pair.py diagram_bands reads them). --expect-unresolved: the table must have an unresolved run on the
period-1 curve (and on the period-P branches), so that the check is not empty. The `stable` and
`exact` columns come from each point's Floquet multipliers and shooting, independent of how the
program groups the labels into ranges. Exit 1 naming what fails."""
import csv
import json
import sys
from pathlib import Path

from reported_stable_stretches import unresolved_runs   # runs of stable rows all not_converged


def ranges(key, what, unit, suffix):
    n = int(key.get(what + "_ranges" + suffix, -1))
    if n < 0:
        return None
    return [(key["%s_from_%s%s_%d" % (what, unit, suffix, k)], key["%s_to_%s%s_%d" % (what, unit, suffix, k)])
            for k in range(1, n + 1)]


def inside(x, rs, strict=False):
    tol = 1e-9 * max(abs(x), 1.0)
    if strict:
        return any(a + tol < x < b - tol for a, b in rs)
    return any(a - tol <= x <= b + tol for a, b in rs)


def stable_spans(rows, X, skip):
    """[(lo, hi)] of each run of consecutive stable rows not in `skip` (the frequencies where a
    resolved stable orbit of the curve exists, between its points)."""
    spans, i = [], 0
    while i < len(rows):
        if rows[i]["stable"] != "1" or i in skip:
            i += 1
            continue
        j = i
        while j + 1 < len(rows) and rows[j + 1]["stable"] == "1" and j + 1 not in skip:
            j += 1
        xs = [float(rows[k][X]) for k in range(i, j + 1)]
        spans.append((min(xs), max(xs)))
        i = j + 1
    return spans


def check_period1(rows, X, no_stable, unresolved):
    errors = []
    lo, hi = sorted((float(rows[0][X]), float(rows[-1][X])))
    runs = unresolved_runs(rows)
    bad = {k for i, j in runs for k in range(i, j + 1)}
    resolved = stable_spans(rows, X, bad)
    for k, r in enumerate(rows):
        x = float(r[X])
        if not lo < x < hi:
            continue
        if k in bad and not inside(x, unresolved) and not inside(x, resolved):
            errors.append("period 1: row at %s = %.6g of an unresolved run in no unresolved_period1 range" % (X, x))
        if r["stable"] == "1" and k not in bad and inside(x, no_stable, strict=True):
            errors.append("period 1: resolved stable row at %s = %.6g inside an unstable_period1 range" % (X, x))
    for a, b in unresolved:
        if not any(inside(a, [r]) and inside(b, [r]) for r in no_stable):
            errors.append("period 1: unresolved_period1 range %.6g-%.6g in no unstable_period1 range" % (a, b))
        if not any(inside(float(rows[k][X]), [(a, b)]) for k in bad):
            errors.append("period 1: unresolved_period1 range %.6g-%.6g holds no unresolved row" % (a, b))
    return errors, len(runs)


def check_period(all_rows, period, listed):
    errors, count = [], 0
    spans = []
    for branch in sorted({r["branch"] for r in all_rows if r["period"] == str(period)}):
        rows = [r for r in all_rows if r["period"] == str(period) and r["branch"] == branch]
        for i, j in unresolved_runs(rows):
            xs = [float(rows[k]["omega"]) for k in range(i, j + 1)]
            spans.append((min(xs), max(xs)))
            if not any(inside(min(xs), [(a, b)]) and inside(max(xs), [(a, b)]) for a, b in listed):
                errors.append("period %d branch %s: unresolved rows at %.6g-%.6g rad/s in no unresolved_period%d range"
                              % (period, branch, min(xs), max(xs), period))
            count += 1
    for a, b in listed:
        if not any(inside(s, [(a, b)]) for s, _ in spans):
            errors.append("unresolved_period%d range %.6g-%.6g holds no unresolved run" % (period, a, b))
    return errors, count


def diagram_bands(xs):
    """[(lo, hi)] of the diagram's bands from its speeds (each band's grid uniform but for the
    speeds added in ranges the grid misses: the larger step beside a gap is the band's)."""
    w = sorted(set(xs))
    bands, start = [], 0
    for i in range(1, len(w)):
        step = max(w[i - 1] - w[i - 2], w[i + 1] - w[i] if i + 1 < len(w) else 0.0)
        if i - 1 > start and w[i] - w[i - 1] > 1.5 * step:
            bands.append((w[start], w[i - 1]))
            start = i
    bands.append((w[start], w[-1]))
    return bands


def check_diagram(path, X, no_stable):
    speeds = [float(r[X]) for r in csv.DictReader(open(path))]
    bands = diagram_bands(speeds)
    return (["range %.6g-%.6g in no band of the diagram %s" % (a, b, bands) for a, b in no_stable
             if not any(inside(a, [band]) and inside(b, [band]) for band in bands)] +
            ["range %.6g-%.6g holds no speed of the diagram" % (a, b) for a, b in no_stable
             if not any(inside(w, [(a, b)]) for w in speeds)])


def main(argv):
    d_dir, table, X, unit, suffix = argv[:5]
    suffix = "" if suffix == "-" else suffix
    expect = "--expect-unresolved" in argv
    periods = [int(argv[k + 1]) for k, a in enumerate(argv) if a == "--period"]
    key = {k: v["value"] for k, v in json.load(open(Path(d_dir) / "key_numbers.json")).items()}
    rows = list(csv.DictReader(open(Path(d_dir) / table)))
    errors = []
    no_stable = ranges(key, "unstable_period1", unit, suffix)
    unresolved = ranges(key, "unresolved_period1", unit, suffix)
    if no_stable is None or unresolved is None:
        print("key numbers unstable_period1_ranges%s / unresolved_period1_ranges%s missing" % (suffix, suffix))
        return 1
    e, n = check_period1([r for r in rows if r.get("branch", "0") == "0"], X, no_stable, unresolved)
    errors += e
    print("period 1: %d ranges with no stable orbit, %d unresolved stretches (%d unresolved runs in the table)"
          % (len(no_stable), len(unresolved), n))
    if expect and n == 0:
        errors.append("period 1: no unresolved run in the table (the check would be empty)")
    for p in periods:
        listed = ranges(key, "unresolved_period%d" % p, "omega", suffix)
        if listed is None:
            errors.append("key number unresolved_period%d_ranges%s missing" % (p, suffix))
            continue
        e, n = check_period(rows, p, listed)
        errors += e
        print("period %d: %d unresolved ranges listed, %d unresolved runs in the table" % (p, len(listed), n))
        if expect and n == 0:
            errors.append("period %d: no unresolved run in the table (the check would be empty)" % p)
    if "--diagram" in argv:
        path = Path(d_dir) / argv[argv.index("--diagram") + 1]
        e = check_diagram(path, X, no_stable)
        errors += e
        print("diagram %s: %d ranges, %d failures (a range in no band, or holding no speed)" % (path.name, len(no_stable), len(e)))
    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
