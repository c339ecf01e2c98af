#!/usr/bin/env python3
"""The two views of one model must agree (issue 34 section 3): a program run's bifurcation
diagram by time integration (bifurcation_diagram.csv) against its harmonic-balance branch at
the same phase (bifurcation_diagram_hb.csv).

  diagram_vs_hb.py DIR X VALUE ERROR_SCALE MIN_COMPARED [GROUP]

X: the frequency column (omega, f_mesh_hz), VALUE: the Poincare value column (x, dte_um),
GROUP: a column splitting the tables into curves (torque_index; the frequency response of
curve g is then frc_<g>.csv, else frc.csv), or label=L for a chapter case's own files
(bifurcation_diagram_L.csv, bifurcation_diagram_hb_L.csv, frc_L.csv). The HB orbits at the diagram's own speeds are the
rows `point = speed` of the HB table (every segment of a branch stable at both ends that
brackets the speed, solved by Newton there): the period-1 branch and, where the table has the
period and branch columns, every period-2 (4) branch, a period-p orbit with its p values at
phase 0 of its p forcing periods. The tolerance: HB's own error bound plus 1e-6 |value| (the
classifier's period_tol): the orbit's own, column hb_orbit_error of the HB table where the
program wrote it (the orbit corrected by shooting over p forcing periods at the speed itself:
sum |q_i| max |x_HB - x_exact|, in VALUE's unit; the program keeps only orbits whose correction
is stable and of period p), else E, the largest hb_orbit_error of the frequency-response table
over the branch's stable points times ERROR_SCALE (to VALUE's unit). At every such
speed one of the two sweeps must be period p with its p values (sorted) within the bound of those of
one of the stable HB orbits there, or period n, a divisor of p, with its n values each within the
bound of p/n of the orbit's (a period-p orbit whose values repeat every n periods to within the bound
is the period-n motion the classifier, blind below its period_tol, reports: ch. 6 Fig. 40 at
8150 rad/s, 5 rad/s past the period doubling at 8145.26 where its period-2 branch merges, the
branch's two values agree to 1e-11 and both sweeps call it period 1) (coexisting orbits: one of them), or, where the program
integrated from a stable HB orbit that no sweep was on (rows with sweep `from_hb`: coexisting
attractors), that integration; such speeds are listed. Periodic points on no
stable HB orbit (an orbit the continued branches do not hold) are listed, not failed. At least MIN_COMPARED speeds must
be compared (the check cannot pass empty). Exit 1 naming the first speeds that fail."""
import csv
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def orbits_at_speeds(h, X, V):
    """{speed: [(period, branch, sorted values, own bound or None)]}: the HB orbits solved at the
    diagram's speeds (rows point = speed; a period-p orbit is p consecutive rows), with the
    orbit's own error bound where the table has it (column hb_orbit_error: shooting at the speed,
    in VALUE's unit). Tables without the period and branch columns hold the period-1 branch only."""
    at_speed, i = {}, 0
    speed = [r for r in h if r["point"] == "speed"]
    while i < len(speed):
        r = speed[i]
        p, b = int(r.get("period", "1")), r.get("branch", "0")
        values = sorted(float(q[V]) for q in speed[i:i + p])
        own = float(r["hb_orbit_error"]) if r.get("hb_orbit_error") else None
        at_speed.setdefault(float(r[X]), []).append((p, b, values, own))
        i += p
    return at_speed


def error_bounds(frc, scale):
    """{branch: E}: the largest hb_orbit_error over the branch's stable points, times scale."""
    E = {}
    for r in frc:
        if r["stable"] == "1" and r["hb_orbit_error"]:
            b = r.get("branch", "0")
            E[b] = max(E.get(b, 0.0), float(r["hb_orbit_error"]) * scale)
    return E


def split_starts(sweeps):
    """{sweep: rows} of one speed with the rows of sweep from_hb split into one entry per start
    (from_hb, from_hb 2, ...): the program integrates from every stable HB orbit at the speed
    that no sweep reached (a period-1 orbit and a period-2 one may both be there), writing the
    points one after the other, n rows for a periodic one of period n, else rows of one motion."""
    out = {k: rs for k, rs in sweeps.items() if k != "from_hb"}
    rs, i, k = sweeps.get("from_hb", []), 0, 1
    while i < len(rs):
        if rs[i]["motion"] == "periodic":
            j = i + int(rs[i]["n"])
        else:
            j = i + 1
            while j < len(rs) and (rs[j]["motion"], rs[j]["lyapunov"]) == (rs[i]["motion"], rs[i]["lyapunov"]):
                j += 1
        out["from_hb" if k == 1 else "from_hb %d" % k] = rs[i:j]
        i, k = j, k + 1
    return out


def main():
    d_dir, X, V, scale, min_compared = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
    group = sys.argv[6] if len(sys.argv) > 6 else None
    stem = ""
    if group and group.startswith("label="):
        stem, group = "_" + group[len("label="):], None
    diagram, hb = rows(d_dir + "/bifurcation_diagram%s.csv" % stem), rows(d_dir + "/bifurcation_diagram_hb%s.csv" % stem)
    curves = sorted({r[group] for r in hb}) if group else [None]
    failures, elsewhere, coexisting, compared, worst, by_period = [], [], [], 0, 0.0, {}
    for g in curves:
        h = [r for r in hb if group is None or r[group] == g]
        E = error_bounds(rows(d_dir + ("/frc%s.csv" % stem if g is None else "/frc_%s.csv" % g)), scale)
        print("curve %s: E = %s %s" % (g, ", ".join("%.3g (branch %s)" % (e, b) for b, e in sorted(E.items())), V))
        at_speed = orbits_at_speeds(h, X, V)
        points = {}
        for r in diagram:
            if group is None or r[group] == g:
                points.setdefault(float(r[X]), {}).setdefault(r["sweep"], []).append(r)
        for w in points:
            points[w] = split_starts(points[w])
        for w, sweeps in points.items():
            where = "%s%s = %g" % ("" if g is None else "curve %s, " % g, X, w)
            periodic = [(int(rs[0]["n"]), sorted(float(r[V]) for r in rs), k) for k, rs in sweeps.items()
                        if rs[0]["motion"] == "periodic"]
            # each orbit's bound: its own (shooting at the speed) where written, else its branch's E
            orbits = [(p, b, q, own if own is not None else E[b]) for p, b, q, own in at_speed.get(w, [])
                      if own is not None or b in E]

            def off(n, ys, orbit):   # largest difference, None where not within the bound
                p, b, q, bound = orbit
                if p % n or len(ys) != n or len(q) != p:
                    return None
                ys = sorted(y for y in ys for _ in range(p // n))   # n values, each p/n times
                d = [abs(y - z) for y, z in zip(ys, q)]
                return max(d) if all(e <= bound + 1e-6 * abs(y) for e, y in zip(d, ys)) else None
            for n, ys, _ in periodic:
                if not any(off(n, ys, o) is not None for o in orbits):
                    elsewhere.append("%s (period %d, %s = %s)" % (where, n, V, ", ".join("%.6g" % y for y in ys)))
            if not orbits:
                continue
            offs = [(off(n, ys, o), o[0], k) for n, ys, k in periodic for o in orbits]
            offs = [(e, p, k) for e, p, k in offs if e is not None]
            if offs:
                compared += 1
                e, p, _ = min(offs)
                worst = max(worst, e)
                by_period[p] = by_period.get(p, 0) + 1
                if all(k.startswith("from_hb") for _, _, k in offs):
                    coexisting.append(where)
            else:
                failures.append("%s: HB has a stable orbit (%s), no sweep is periodic on it within its bound (%s)" % (
                    where, "; ".join("period %d branch %s: %s within %.3g" % (p, b, ", ".join("%.6g" % z for z in q), bound)
                                     for p, b, q, bound in orbits),
                    "; ".join("%s %s n = %s %s" % (k, rs[0]["motion"], rs[0]["n"], rs[0][V]) for k, rs in sweeps.items())))
    print("speeds compared: %d (largest difference %.3g %s; %s)" % (
        compared, worst, V, ", ".join("period %d: %d" % kv for kv in sorted(by_period.items()))))
    if coexisting:
        print("on the stable HB orbit only from it (sweep from_hb; the sweeps on another attractor): " +
              "; ".join(coexisting))
    if elsewhere:
        print("periodic on no stable HB orbit: " + "; ".join(elsewhere))
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
