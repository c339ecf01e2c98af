"""A chapter's own case switches at the period doublings of its curve (issue 34 §1): every PD
of the period-1 curve in bifurcations.csv that starts a branch (starts_branch) has that
branch's period-2 rows in each response table named, and key_numbers.json counts the ranges
with no stable period-1 orbit; the PDs the README quotes (PD=w1,w2,...: omegas to 1e-3 rad/s)
are the period-1 curve's. Usage: own_case_branches.py DIR PD=w1,w2 TABLE... (tables in DIR)."""
import csv
import json
import sys
from pathlib import Path


def main(folder, quoted, tables):
    d = Path(folder)
    bif = list(csv.DictReader(open(d / "bifurcations.csv")))
    pds = [float(r["omega"]) for r in bif if r["type"] == "period_doubling" and r["period"] == "1"]
    missing = [w for w in quoted if not any(abs(w - p) < 1e-3 for p in pds)]
    started = {r["starts_branch"] for r in bif
               if r["type"] == "period_doubling" and r["period"] == "1" and r["starts_branch"]}
    errors = [] if started else ["no period doubling of the period-1 curve starts a branch"]
    errors += [f"the quoted PD at {w} is not among the period-1 curve's {pds}" for w in missing]
    for t in tables:
        rows = list(csv.DictReader(open(d / t)))
        for b in sorted(started):
            n = sum(r["branch"] == b and r["period"] == "2" for r in rows)
            if n < 3:
                errors.append(f"{t}: branch {b} has {n} period-2 rows")
    ranges = json.load(open(d / "key_numbers.json")).get("unstable_period1_ranges_own", {}).get("value", 0)
    if ranges < 1:
        errors.append("key number unstable_period1_ranges_own missing or 0")
    print(f"branches started {sorted(started)}, ranges with no stable period-1 orbit {ranges}")
    for e in errors:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], [float(w) for w in sys.argv[2].removeprefix("PD=").split(",")], sys.argv[3:]))
