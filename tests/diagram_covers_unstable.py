#!/usr/bin/env python3
"""A run with a stretch where no period-1 orbit is stable has its bifurcation diagram there, by
default (issue 34 section 3): every range of the key numbers (unstable_period1_from_<unit><s>_<k>,
unstable_period1_to_<unit><s>_<k>) lies inside one band of bifurcation_diagram.csv (the span of X
over the rows of that band and curve), with speeds below and above it (the margin that shows the
period-1 motion on both sides, unless the range ends at the run's range: the first and last
period-1 point of frc.csv / frc_<g>.csv), and the diagram is not period 1 somewhere in each range
that holds a speed of its band's grid (a range narrower than the grid's step may hold none; at
least one range must).

  diagram_covers_unstable.py DIR X UNIT [GROUP]

X: the diagram's frequency column in the key numbers' unit (omega, speed_rpm); UNIT: the key
numbers' infix (omega, rpm); GROUP: a column splitting the diagram into curves (torque_index: the
key numbers then end in _<g>_<k>). Exit 1 naming the first range that fails."""
import csv
import json
import sys


def main():
    d_dir, X, unit = sys.argv[1], sys.argv[2], sys.argv[3]
    group = sys.argv[4] if len(sys.argv) > 4 else None
    key = {k: v["value"] for k, v in json.load(open(d_dir + "/key_numbers.json")).items()}
    with open(d_dir + "/bifurcation_diagram.csv") as f:
        rows = list(csv.DictReader(f))
    curves = sorted({r[group] for r in rows}) if group else [None]
    failures, checked, resolved = [], 0, 0
    for g in curves:
        suffix = "" if g is None else "_" + g
        mine = [r for r in rows if g is None or r[group] == g]
        spans = {}
        for r in mine:
            lo, hi = spans.get(r["band"], (float(r[X]), float(r[X])))
            spans[r["band"]] = (min(lo, float(r[X])), max(hi, float(r[X])))
        with open(d_dir + ("/frc.csv" if g is None else "/frc_%s.csv" % g)) as f:
            p1 = [float(r[X]) for r in csv.DictReader(f) if r.get("branch", "0") == "0"]
        full = sorted((p1[0], p1[-1]))
        k = 1
        while "unstable_period1_from_%s%s_%d" % (unit, suffix, k) in key:
            a, b = key["unstable_period1_from_%s%s_%d" % (unit, suffix, k)], key["unstable_period1_to_%s%s_%d" % (unit, suffix, k)]
            where = "curve %s range %d (%.6g to %.6g)" % (g, k, a, b)
            inside = [n for n, (lo, hi) in spans.items() if lo <= a * (1 + 1e-9) and b * (1 - 1e-9) <= hi]
            checked += 1
            if not inside:
                failures.append("%s: in no band (%s)" % (where, spans))
            else:
                xs = [float(r[X]) for r in mine if r["band"] == inside[0]]
                below, above = [x for x in xs if x < a], [x for x in xs if x > b]
                if not below and a > full[0] * (1 + 1e-9):
                    failures.append("%s: no speed below it" % where)
                if not above and b < full[1] * (1 - 1e-9):
                    failures.append("%s: no speed above it" % where)
                inner = [r for r in mine if a <= float(r[X]) <= b]
                if inner:   # a range narrower than the grid's step may hold no speed of its band
                    resolved += 1
                    if all(r["motion"] == "periodic" and r["n"] == "1" for r in inner):
                        failures.append("%s: the diagram is period 1 at every speed in it" % where)
            print("%s: band %s" % (where, inside[0] if inside else "none"))
            k += 1
    if checked == 0 or resolved == 0:
        print("no range with no stable period-1 orbit in the key numbers" if checked == 0 else
              "no range holds a speed of the diagram")
        return 1
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
