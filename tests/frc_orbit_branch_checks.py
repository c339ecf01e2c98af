#!/usr/bin/env python3
"""gearhb_frc's branches through the diagram's orbits off every branch (step 4b,
app/orbit_branches.hpp), checked from a run's key numbers and tables:

  frc_orbit_branch_checks.py DIR

- the diagram has period-1 orbits off every branch the sweep found (diagram_off_branch_period1
  >= 2), a branch was continued from them and none is left (off_curve_orbits_left = 0);
- every such period-1 orbit lies on a continued period-1 branch within HB's own error (the sum
  of their orbit_branch_diagram_speeds is diagram_off_branch_period1);
- each branch's HB start differs from the integrated orbit by no more than its bound; its
  Floquet stability (shooting on the exact flow) is that of the GSL monodromy of the integrated
  orbits and at >= 1 of its unstable points (stability_agrees = 1, unstable_checked >= 1);
- frc.csv and bifurcations.csv hold its rows under its id and period;
- the tables, read here (not the program's verdict): at every diagram speed where a sweep is
  periodic with period 1, one stable period-1 HB orbit solved at that speed (rows point = speed
  of bifurcation_diagram_hb.csv, any branch) lies within its own error bound (hb_orbit_error)
  plus 1e-6 |x| of its Poincare point: with the continued branch, HB holds every period-1 orbit
  the time integration found (diagram_vs_hb.py lists those it does not). Not compared: speeds
  inside a chord of a period-1 branch of frc.csv whose ends differ in stability (the program
  solves no orbit there, bifurcation_input.hpp add_hb_section_rows; near the bifurcation the
  integration also converges slowly); at least 80 % of the points are compared;
- the ranges with no stable period-1 orbit on any branch (unstable_period1_*_all_branches) lie
  inside the curve's, and at every diagram speed in the curve's ranges but outside those, a sweep
  is period 1 (the time integration confirms the stable orbit the continued branch adds).
Exit 1 naming the first check that fails."""
import csv
import json
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def ranges(k, suffix):
    n = int(k.get("unstable_period1_ranges" + suffix, 0))
    return [(k["unstable_period1_from_omega%s_%d" % (suffix, j)], k["unstable_period1_to_omega%s_%d" % (suffix, j)])
            for j in range(1, n + 1)]


def stability_change_chords(d_dir):
    """[(lo, hi)]: the chords of every period-1 branch of frc.csv whose ends differ in stability."""
    by_branch = {}
    for r in rows(d_dir + "/frc.csv"):
        if r["period"] == "1":
            by_branch.setdefault(r["branch"], []).append((float(r["omega"]), r["stable"]))
    return [(min(a[0], b[0]), max(a[0], b[0])) for pts in by_branch.values() for a, b in zip(pts, pts[1:])
            if a[1] != b[1]]


def period1_points_on_hb(d_dir):
    """(period-1 diagram points compared, those on no stable period-1 HB orbit at their speed,
    points not compared: at a speed inside a stability-change chord)."""
    chords = stability_change_chords(d_dir)
    hb = {}
    for r in rows(d_dir + "/bifurcation_diagram_hb.csv"):
        if r["point"] == "speed" and r["period"] == "1" and r["stable"] == "1" and r["hb_orbit_error"]:
            hb.setdefault(float(r["omega"]), []).append((float(r["x"]), float(r["hb_orbit_error"])))
    points, off, skipped = 0, [], 0
    for r in rows(d_dir + "/bifurcation_diagram.csv"):
        if r["motion"] != "periodic" or r["n"] != "1":
            continue
        w, x = float(r["omega"]), float(r["x"])
        if any(a <= w <= b for a, b in chords):
            skipped += 1
            continue
        points += 1
        if not any(abs(x - z) <= e + 1e-6 * abs(x) for z, e in hb.get(w, [])):
            off.append("%s sweep %s x = %s" % (r["omega"], r["sweep"], r["x"]))
    return points, off, skipped


def confirmed(d_dir, k):
    """The diagram speeds in the curve's unstable ranges but in no all-branches one that no sweep
    has period 1 at (should be none), and how many such speeds there are."""
    inside = lambda w, rs: any(a <= w <= b for a, b in rs)
    curve, every = ranges(k, ""), ranges(k, "_all_branches")
    by_speed = {}
    for r in rows(d_dir + "/bifurcation_diagram.csv"):
        w = float(r["omega"])
        if inside(w, curve) and not inside(w, every):
            by_speed.setdefault(w, set()).add(r["n"] if r["motion"] == "periodic" else r["motion"])
    return [w for w, kinds in sorted(by_speed.items()) if "1" not in kinds], len(by_speed)


def main():
    d_dir = sys.argv[1]
    k = {n: v["value"] for n, v in json.load(open(d_dir + "/key_numbers.json")).items()}
    n = int(k["orbit_branches"])
    tags = ["_%d" % j for j in range(1, n + 1)]
    frc, bif = rows(d_dir + "/frc.csv"), rows(d_dir + "/bifurcations.csv")
    of = lambda t, tag: [r for r in t if int(r["branch"]) == int(k["orbit_branch_id" + tag])]
    points, off, skipped = period1_points_on_hb(d_dir)
    not_p1, changed = confirmed(d_dir, k)
    every, curve = ranges(k, "_all_branches"), ranges(k, "")
    checks = [
        ("diagram_off_branch_period1 >= 2", k["diagram_off_branch_period1"] >= 2),
        ("orbit_branches >= 1", n >= 1),
        ("off_curve_orbits_left = 0", k["off_curve_orbits_left"] == 0),
        ("every off-branch period-1 orbit on a continued branch",
         sum(k["orbit_branch_diagram_speeds" + t] for t in tags if k["orbit_branch_period" + t] == 1)
         == k["diagram_off_branch_period1"]),
    ]
    for t in tags:
        checks += [
            ("branch%s: start within its bound" % t,
             k["orbit_branch_hb_vs_time_integration" + t] <= k["orbit_branch_hb_error_bound" + t]),
            ("branch%s: stability agrees with the GSL monodromy" % t, k["orbit_branch_stability_agrees" + t] == 1),
            ("branch%s: unstable points checked" % t, k["orbit_branch_unstable_checked" + t] >= 1),
            ("branch%s: frc.csv rows, its period" % t, len(of(frc, t)) > 2 and
             all(int(r["period"]) == k["orbit_branch_period" + t] for r in of(frc, t))),
            ("branch%s: bifurcations.csv rows" % t, len(of(bif, t)) == k["orbit_branch_bifurcations" + t]),
        ]
    checks += [
        ("period-1 diagram points (%d, %d not compared) on a stable HB orbit%s" % (
            points, skipped, (": off " + "; ".join(off)) if off else ""), points >= 4 * skipped and points > 0 and not off),
        ("all-branches ranges inside the curve's", all(any(c <= a and b <= d for c, d in curve) for a, b in every)),
        ("period 1 by time integration where only the new branch is stable (%d speeds%s)"
         % (changed, (", not at " + ", ".join("%g" % w for w in not_p1)) if not_p1 else ""), changed > 0 and not not_p1),
    ]
    for what, ok in checks:
        print("%-60s %s" % (what, "ok" if ok else "FAILED"))
        if not ok:
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
