#!/usr/bin/env python3
"""The branches through the diagram's orbits off every branch (app/orbit_branches.hpp
orbit_branches_of_diagram: gearhb_frc's step 4b, gearhb_gear's per torque), checked from a run's
key numbers and tables:

  frc_orbit_branch_checks.py DIR              a gearhb_frc run (frc.csv, omega, x)
  frc_orbit_branch_checks.py DIR torque=I     torque I of a gearhb_gear run (frc_I.csv, speed_rpm,
                                              dte_um, key numbers ending in _I)

- the diagram has orbits of period 1 or 2 off every branch the sweep found
  (diagram_off_branch_period1 + _period2 >= 2), a branch was continued from them and none is left
  (off_curve_orbits_left = 0);
- every such orbit of the period p of a continued branch lies on a continued branch of period p
  within HB's own error (the sum of their orbit_branch_diagram_speeds is
  diagram_off_branch_period<p>);
- each branch's HB start differs from the integrated orbit by no more than its bound; its
  Floquet stability (shooting on the exact flow) is that of the GSL monodromy of the integrated
  orbits and, where it has an unstable stretch (three unstable points in a row in the table), at
  >= 1 of its unstable points (stability_agrees = 1, unstable_checked >= 1);
- the frequency-response and bifurcation tables hold its rows under its id and period;
- the tables, read here (not the program's verdict): at every diagram speed where a sweep is
  periodic with the period p of a continued branch, one stable period-p HB orbit solved at that
  speed (rows point = speed of bifurcation_diagram_hb.csv, any branch of period p; each of the
  orbit's p values) lies within its own error bound (hb_orbit_error) plus 1e-6 |x| of each of its
  Poincare points: with the continued branch, HB holds every orbit of that period the time
  integration found (diagram_vs_hb.py lists those it does not). Not compared: speeds inside a
  chord of a branch of period p whose ends differ in stability (the program solves no orbit
  there, bifurcation_input.hpp add_hb_section_rows; near the bifurcation the integration also
  converges slowly); at least 80 % of the points are compared;
- where a period-1 branch was continued: the ranges with no stable period-1 orbit on any branch
  (unstable_period1_*_all_branches) lie inside the curve's, and at every diagram speed in the
  curve's ranges but outside those, a sweep is period 1 (the time integration confirms the stable
  orbit the continued branch adds).
Exit 1 naming the first check that fails."""
import csv
import json
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class Run:
    """Where a run keeps what is checked: gearhb_frc's files and columns, or torque I of gearhb_gear's."""

    def __init__(self, d_dir, torque=None):
        self.d_dir, self.torque = d_dir, torque
        self.suffix = "" if torque is None else "_%d" % torque
        self.speed = "omega" if torque is None else "speed_rpm"   # one column in every table
        self.value = "x" if torque is None else "dte_um"
        self.unit = "omega" if torque is None else "rpm"           # of the unstable-range key numbers
        tables = ("frc.csv", "bifurcations.csv") if torque is None else ("frc_%d.csv" % torque, "bifurcations_%d.csv" % torque)
        self.frc, self.bif = rows(d_dir + "/" + tables[0]), rows(d_dir + "/" + tables[1])
        mine = lambda r: torque is None or int(r["torque_index"]) == torque
        self.diagram = [r for r in rows(d_dir + "/bifurcation_diagram.csv") if mine(r)]
        self.section = [r for r in rows(d_dir + "/bifurcation_diagram_hb.csv") if mine(r)]


def ranges(k, run, tag):
    n = int(k.get("unstable_period1_ranges%s%s" % (tag, run.suffix), 0))
    return [(k["unstable_period1_from_%s%s%s_%d" % (run.unit, tag, run.suffix, j)],
             k["unstable_period1_to_%s%s%s_%d" % (run.unit, tag, run.suffix, j)]) for j in range(1, n + 1)]


def stability_change_chords(run, period):
    """[(lo, hi)]: the chords of every branch of that period whose ends differ in stability."""
    by_branch = {}
    for r in run.frc:
        if int(r["period"]) == period:
            by_branch.setdefault(r["branch"], []).append((float(r[run.speed]), r["stable"]))
    return [(min(a[0], b[0]), max(a[0], b[0])) for pts in by_branch.values() for a, b in zip(pts, pts[1:])
            if a[1] != b[1]]


def points_on_hb(run, period):
    """(diagram points of that period compared, those on no stable HB orbit of that period at their
    speed, points not compared: at a speed inside a stability-change chord)."""
    chords = stability_change_chords(run, period)
    hb = {}
    for r in run.section:
        if r["point"] == "speed" and int(r["period"]) == period and r["stable"] == "1" and r["hb_orbit_error"]:
            hb.setdefault(float(r[run.speed]), []).append((float(r[run.value]), float(r["hb_orbit_error"])))
    points, off, skipped = 0, [], 0
    for r in run.diagram:
        if r["motion"] != "periodic" or int(r["n"]) != period:
            continue
        w, x = float(r[run.speed]), float(r[run.value])
        if any(a <= w <= b for a, b in chords):
            skipped += 1
            continue
        points += 1
        if not any(abs(x - z) <= e + 1e-6 * abs(x) for z, e in hb.get(w, [])):
            off.append("%s sweep %s %s = %s" % (r[run.speed], r["sweep"], run.value, r[run.value]))
    return points, off, skipped


def confirmed(run, k):
    """The diagram speeds in the curve's unstable ranges but in no all-branches one that no sweep
    has period 1 at (should be none), and how many such speeds there are."""
    inside = lambda w, rs: any(a <= w <= b for a, b in rs)
    curve, every = ranges(k, run, ""), ranges(k, run, "_all_branches")
    by_speed = {}
    for r in run.diagram:
        w = float(r[run.speed])
        if inside(w, curve) and not inside(w, every):
            by_speed.setdefault(w, set()).add(r["n"] if r["motion"] == "periodic" else r["motion"])
    return [w for w, kinds in sorted(by_speed.items()) if "1" not in kinds], len(by_speed)


def interior_unstable(table):
    """True if the branch's rows hold three unstable points in a row (an unstable stretch)."""
    s = [r["stable"] for r in table]
    return any(s[i - 1] == s[i] == s[i + 1] == "0" for i in range(1, len(s) - 1))


def main():
    d_dir = sys.argv[1]
    torque = next((int(a.split("=", 1)[1]) for a in sys.argv[2:] if a.startswith("torque=")), None)
    run = Run(d_dir, torque)
    sfx = run.suffix
    k = {n: v["value"] for n, v in json.load(open(d_dir + "/key_numbers.json")).items()}
    n = int(k["orbit_branches" + sfx])
    tags = ["%s_%d" % (sfx, j) for j in range(1, n + 1)]
    of = lambda t, tag: [r for r in t if int(r["branch"]) == int(k["orbit_branch_id" + tag])]
    periods = sorted({int(k["orbit_branch_period" + t]) for t in tags})
    off = {p: k["diagram_off_branch_period%d%s" % (p, sfx)] for p in (1, 2)}
    checks = [
        ("diagram_off_branch_period1 + _period2 >= 2", off[1] + off[2] >= 2),
        ("orbit_branches >= 1", n >= 1),
        ("off_curve_orbits_left = 0", k["off_curve_orbits_left" + sfx] == 0),
    ]
    checks += [("every off-branch period-%d orbit on a continued branch" % p,
                sum(k["orbit_branch_diagram_speeds" + t] for t in tags if k["orbit_branch_period" + t] == p) == off[p])
               for p in periods]
    for t in tags:
        checks += [
            ("branch%s: start within its bound" % t,
             k["orbit_branch_hb_vs_time_integration" + t] <= k["orbit_branch_hb_error_bound" + t]),
            ("branch%s: stability agrees with the GSL monodromy" % t, k["orbit_branch_stability_agrees" + t] == 1),
            ("branch%s: unstable points checked" % t,
             k["orbit_branch_unstable_checked" + t] >= 1 or not interior_unstable(of(run.frc, t))),
            ("branch%s: table rows, its period" % t, len(of(run.frc, t)) > 2 and
             all(int(r["period"]) == k["orbit_branch_period" + t] for r in of(run.frc, t))),
            ("branch%s: bifurcation rows" % t, len(of(run.bif, t)) == k["orbit_branch_bifurcations" + t]),
        ]
    for p in periods:
        points, missed, skipped = points_on_hb(run, p)
        checks.append(("period-%d diagram points (%d, %d not compared) on a stable HB orbit%s" % (
            p, points, skipped, (": off " + "; ".join(missed)) if missed else ""),
            points >= 4 * skipped and points > 0 and not missed))
    if 1 in periods:
        not_p1, changed = confirmed(run, k)
        every, curve = ranges(k, run, "_all_branches"), ranges(k, run, "")
        checks += [
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
