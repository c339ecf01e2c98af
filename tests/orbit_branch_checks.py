"""Checks of a run's branches continued from time-integrated orbits (chapter step 3c of ch. 6,
hb/orbit_branch.hpp), from its key numbers and tables, for the case LABEL:

  orbit_branch_checks.py OUT LABEL

- the diagram has periodic orbits off every branch of the continued curve (off_curve_orbits >= 2:
  at least two speeds to compare), and one branch was continued from them;
- every such orbit lies on that branch within HB's own error at its speed
  (orbit_branch_diagram_speeds = off_curve_orbits, off_curve_orbits_left = 0): the branch's points
  agree with the time integration, an independent method, there;
- its HB start differs from the integrated orbit by no more than its bound;
- its Floquet stability (shooting on the exact flow) is that of the GSL monodromy of the
  integrated orbit at those speeds and at >= 1 of its unstable points (stability_agrees = 1);
- frc_LABEL.csv and bifurcations_LABEL.csv hold rows of its branch id, period 1.
Exit 1 naming the first check that fails."""
import csv
import json
import sys


def main():
    out, label = sys.argv[1], sys.argv[2]
    k = {n: v["value"] for n, v in json.load(open(out + "/key_numbers.json")).items()}
    tag = "_%s_1" % label
    bid = int(k["orbit_branch_id" + tag])
    frc = [r for r in csv.DictReader(open("%s/frc_%s.csv" % (out, label))) if int(r["branch"]) == bid]
    bif = [r for r in csv.DictReader(open("%s/bifurcations_%s.csv" % (out, label))) if int(r["branch"]) == bid]
    checks = [
        ("off_curve_orbits >= 2", k["off_curve_orbits_" + label] >= 2),
        ("orbit_branches = 1", k["orbit_branches_" + label] == 1),
        ("off_curve_orbits_left = 0", k["off_curve_orbits_left_" + label] == 0),
        ("every off-curve orbit on the branch",
         k["orbit_branch_diagram_speeds" + tag] == k["off_curve_orbits_" + label]),
        ("start within its bound", k["orbit_branch_hb_vs_time_integration" + tag] <= k["orbit_branch_hb_error_bound" + tag]),
        ("stability agrees with the GSL monodromy", k["orbit_branch_stability_agrees" + tag] == 1),
        ("unstable points checked", k["orbit_branch_unstable_checked" + tag] >= 1),
        ("frc rows of the branch, period 1", len(frc) > 2 and all(r["period"] == "1" for r in frc)),
        ("bifurcation rows of the branch", len(bif) == k["orbit_branch_bifurcations" + tag]),
    ]
    for what, ok in checks:
        print("%-45s %s" % (what, "ok" if ok else "FAILED"))
        if not ok:
            sys.exit(1)


if __name__ == "__main__":
    main()
