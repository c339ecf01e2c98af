#!/usr/bin/env python3
"""The two views of one model must agree (issue 34 section 3): a program run's bifurcation
diagram by time integration (bifurcation_diagram.csv) against its harmonic-balance branch at
the same phase (bifurcation_diagram_hb.csv).

  diagram_vs_hb.py DIR X VALUE ERROR_SCALE MIN_COMPARED [GROUP]

X: the frequency column (omega, f_mesh_hz), VALUE: the Poincare value column (x, dte_um),
GROUP: a column splitting the tables into curves (torque_index; the frequency response of
curve g is then frc_<g>.csv, else frc.csv), or label=L for a chapter case's own files
(bifurcation_diagram_L.csv, bifurcation_diagram_hb_L.csv, frc_L.csv). The HB orbits at the diagram's own speeds are the
rows `point = speed` of the HB table (every segment of the branch stable at both ends that
brackets the speed, solved by Newton there). The tolerance: HB's own error bound,
hb_orbit_error of the frequency-response table (max |x_HB - x_exact| over the period, the
exact orbit by shooting), its largest value E over the curve's stable points times
ERROR_SCALE (to VALUE's unit), plus 1e-6 |value| (the classifier's period_tol). At every such
speed one of the two sweeps must be period 1 within E of one of the stable HB orbits there
(coexisting orbits: one of them), or, where the program integrated from a stable HB orbit that
no sweep reached (rows with sweep `from_hb`: coexisting attractors), that integration; such
speeds are listed. Period-1 points on no stable HB orbit (an orbit the one
continuation branch does not hold) are listed, not failed. At least MIN_COMPARED speeds must
be compared (the check cannot pass empty). Exit 1 naming the first speeds that fail."""
import csv
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    d_dir, X, V, scale, min_compared = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
    group = sys.argv[6] if len(sys.argv) > 6 else None
    stem = ""
    if group and group.startswith("label="):
        stem, group = "_" + group[len("label="):], None
    diagram, hb = rows(d_dir + "/bifurcation_diagram%s.csv" % stem), rows(d_dir + "/bifurcation_diagram_hb%s.csv" % stem)
    curves = sorted({r[group] for r in hb}) if group else [None]
    failures, elsewhere, coexisting, compared, worst = [], [], [], 0, 0.0
    for g in curves:
        h = [r for r in hb if group is None or r[group] == g]
        branch = [r for r in h if r["point"] == "branch"]
        frc = rows(d_dir + ("/frc%s.csv" % stem if g is None else "/frc_%s.csv" % g))
        frc = [r for r in frc if r.get("branch", "0") == "0"]   # the period-1 branch (period-2 rows follow it)
        assert len(frc) == len(branch), "frc and the HB section table differ in length"
        E = max(float(r["hb_orbit_error"]) * scale for r, b in zip(frc, branch) if b["stable"] == "1"
                and r["hb_orbit_error"])
        print("curve %s: E = %.3g %s" % (g, E, V))
        at_speed = {}
        for r in h:
            if r["point"] == "speed":
                at_speed.setdefault(float(r[X]), []).append(float(r[V]))
        points = {}
        for r in diagram:
            if group is None or r[group] == g:
                points.setdefault(float(r[X]), {}).setdefault(r["sweep"], []).append(r)
        for w, sweeps in points.items():
            where = "%s%s = %g" % ("" if g is None else "curve %s, " % g, X, w)
            period1 = [float(rs[0][V]) for rs in sweeps.values() if rs[0]["motion"] == "periodic" and rs[0]["n"] == "1"]
            swept = [float(rs[0][V]) for k, rs in sweeps.items() if k != "from_hb" and rs[0]["motion"] == "periodic"
                     and rs[0]["n"] == "1"]
            orbits = at_speed.get(w, [])
            allowed = lambda y: E + 1e-6 * abs(y)  # noqa: E731
            for y in period1:
                if not any(abs(y - q) <= allowed(y) for q in orbits):
                    elsewhere.append("%s (%s = %.6g)" % (where, V, y))
            if not orbits:
                continue
            offs = [abs(y - q) for y in period1 for q in orbits if abs(y - q) <= allowed(y)]
            if offs:
                compared += 1
                worst = max(worst, min(offs))
                if not any(abs(y - q) <= allowed(y) for y in swept for q in orbits):
                    coexisting.append("%s%s = %g" % ("" if g is None else "curve %s, " % g, X, w))
            else:
                failures.append("%s: HB has a stable orbit (%s), no sweep is period 1 on it within %.3g (%s)" % (
                    where, ", ".join("%.6g" % q for q in orbits), E,
                    "; ".join("%s %s n = %s %s" % (k, rs[0]["motion"], rs[0]["n"], rs[0][V]) for k, rs in sweeps.items())))
    print("speeds compared: %d (largest difference %.3g %s)" % (compared, worst, V))
    if coexisting:
        print("on the stable HB orbit only from it (sweep from_hb; the sweeps on another attractor): " +
              "; ".join(coexisting))
    if elsewhere:
        print("period 1 on no stable HB orbit of the branch: " + "; ".join(elsewhere))
    return verdict(failures, compared, min_compared)


def verdict(failures, compared, min_compared):
    """The exit status: 1 (the first 10 failures printed) if any speed failed or fewer than
    min_compared were compared, else 0."""
    for f in failures[:10]:
        print(f)
    if compared < min_compared:
        print("only %d compared, expected at least %d" % (compared, min_compared))
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
