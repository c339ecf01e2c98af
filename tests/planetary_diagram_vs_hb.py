#!/usr/bin/env python3
"""gearhb_planetary's two views must agree (issue 34 section 3): its bifurcation diagram by time
integration (bifurcation_diagram.csv: the sun's rotation u_s at phase 0 of each mesh period)
against the harmonic-balance orbits at the same phase (bifurcation_diagram_hb.csv).

  planetary_diagram_vs_hb.py DIR MIN_COMPARED

At every speed of the diagram where HB has a stable orbit of period p (the rows point = speed
of the HB table: period 1, or a period-2 (4) branch; each segment stable at both ends that
brackets the speed, solved by Newton there), one of the two sweeps must be period p with its p
Poincare values on HB's p values (both sorted) within E + 1e-6 |u_s| (1e-6: the classifier's
period_tol), E HB's truncation error of u_s at phase 0.

E, from HB's own spectrum (sun_harmonics.csv: the amplitude |c_l| of u_s's mesh harmonic l at
every point of the period-1 curve): the amplitude of the highest retained harmonic that is not
zero (above 1e-9 of the largest; mesh phasing leaves only the rotational family l z_s / N whole
in u_s, l = 5 for the five-planet set), the larger of the two curve points that bracket the
speed: the size of the first harmonic HB leaves out if the spectrum does not grow past it. A
stated estimate, not a bound: the planetary set has no exact-orbit columns (its meshes'
stiffness varies, response.csv's hb_orbit_error is empty) to take gearhb_frc's shooting error
from. The time integration is independent of HB (GSL rk8pd, contact switches
located, rel_tol 1e-10). At least MIN_COMPARED speeds must be compared (the check cannot pass
empty; a run with no diagram fails). Exit 1 naming the speeds that fail."""
import csv
import sys

from diagram_vs_hb import verdict


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def truncation_errors(d_dir):
    """{f_mesh_hz: E} at every point of the period-1 curve (sun_harmonics.csv)."""
    by_point = {}
    for r in rows(d_dir + "/sun_harmonics.csv"):
        by_point.setdefault(float(r["f_mesh_hz"]), {})[int(r["harmonic"])] = float(r["u_um"])
    errors = {}
    for hz, c in by_point.items():
        largest = max(c.values())
        errors[hz] = c[max(l for l, a in c.items() if a > 1e-9 * largest)]
    return errors


def error_at(errors, hz):
    """The larger E of the two curve points that bracket hz (the nearest one at an end)."""
    below = [h for h in errors if h <= hz]
    above = [h for h in errors if h >= hz]
    near = ([max(below)] if below else []) + ([min(above)] if above else [])
    return max(errors[h] for h in near)


def main():
    d_dir, min_compared = sys.argv[1], int(sys.argv[2])
    diagram = rows(d_dir + "/bifurcation_diagram.csv")
    hb = [r for r in rows(d_dir + "/bifurcation_diagram_hb.csv") if r["point"] == "speed"]
    errors = truncation_errors(d_dir)
    orbits = {}   # (hz, period, branch) -> its p values
    for r in hb:
        orbits.setdefault((float(r["f_mesh_hz"]), int(r["period"]), r["branch"]), []).append(float(r["u_s_um"]))
    points = {}   # (hz, sweep) -> rows
    for r in diagram:
        points.setdefault((float(r["f_mesh_hz"]), r["sweep"]), []).append(r)
    failures, compared = [], 0
    for (hz, p, branch), values in sorted(orbits.items()):
        E = error_at(errors, hz)
        hb_values = sorted(values)
        best = None
        for sweep in ("up", "down"):
            rs = points.get((hz, sweep), [])
            if not rs or rs[0]["motion"] != "periodic" or int(rs[0]["n"]) != p:
                continue
            ti = sorted(float(r["u_s_um"]) for r in rs)
            off = max(abs(a - b) for a, b in zip(ti, hb_values))
            best = off if best is None else min(best, off)
        what = "f_mesh_hz = %g, period %d (branch %s)" % (hz, p, branch)
        if best is None:
            failures.append("%s: HB has a stable orbit (%s), no sweep is period %d there (%s)" % (
                what, ", ".join("%.6f" % v for v in hb_values), p,
                "; ".join("%s %s n = %s" % (s, points[(hz, s)][0]["motion"], points[(hz, s)][0]["n"])
                          for s in ("up", "down") if (hz, s) in points)))
            continue
        allowed = E + 1e-6 * max(abs(v) for v in hb_values)
        print("%s: |u_s(TI) - u_s(HB)| = %.3g um, HB's truncation error E = %.3g um (allowed %.3g)" % (
            what, best, E, allowed))
        compared += 1
        if best > allowed:
            failures.append("%s: the Poincare points lie %.3g um off HB's orbit, more than E + 1e-6 |u_s| = %.3g um" % (
                what, best, allowed))
    print("speeds compared: %d" % compared)
    return verdict(failures, compared, min_compared)


if __name__ == "__main__":
    sys.exit(main())
