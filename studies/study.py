#!/usr/bin/env python3
"""Design studies of gear pairs (issue 24): many gearhb_gear runs described by one study file.

    study.py check   STUDY.json                    validate; print the number of designs (exit 2 on a bad file)
    study.py designs STUDY.json OUT                resolve the designs into OUT/designs/<hash>/overrides.json
    study.py run     DESIGN_DIR GEARHB BASE        run one design; always writes DESIGN_DIR/status.json
    study.py gather  STUDY.json OUT                OUT/table.csv: one row per design (axes, status, key numbers)
    study.py maps    STUDY.json OUT                OUT/maps.png and OUT/best.txt from the table

The workflow engine is Snakemake (studies/Snakefile): it runs `run` for every design, on the
cores of one machine or as Slurm jobs, resumes an interrupted study and reruns nothing that is
done. This file holds no scheduler: only the study's meaning.

A study file (JSON):
    {"base": "chapters/gearhb_gear/examples/thesis_pair_relief.json",   (relative to the study file)
     "axes": [ {"path": "gears.0.tip_relief.amount", "grid": {"from": 0, "to": 30e-6, "points": 41}},
               {"path": "gears.0.tip_relief.start.length", "values": [6.684e-3, 8.856e-3]},
               {"path": "torques.0", "random": {"from": 100, "to": 300, "samples": 5, "seed": 1}} ],
     "same": [["gears.1.tip_relief.amount", "gears.0.tip_relief.amount"]],  (set equal to an axis)
     "set":  {"plot": 0},                                                   (fixed overrides)
     "maps": ["ste_ptp_um_1", "dynamic_factor_peak_1"]}     (key numbers mapped by study_maps.py)
Designs are the product of the axes. A design's folder is named by the first 12 hex digits of
the SHA-256 of its resolved overrides (sorted JSON), so the same design always lands in the same
folder and a rerun finds it done. Every error names the key; a bad study exits 2 before anything
runs.
"""
import csv
import hashlib
import itertools
import json
import pathlib
import random
import subprocess
import sys


class StudyError(Exception):
    pass


def fail(key, why):
    raise StudyError("study: '%s' %s" % (key, why))


def number(v, key):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or v != v or abs(v) > 1e150:
        fail(key, "must be a finite number")
    return float(v)


def axis_values(axis, k):
    key = "axes.%d" % k
    if not isinstance(axis, dict) or not isinstance(axis.get("path"), str) or not axis["path"]:
        fail(key + ".path", "must be a dotted path of the gear file (e.g. gears.0.tip_relief.amount)")
    kinds = [x for x in ("values", "grid", "random") if x in axis]
    if len(kinds) != 1 or set(axis) - {"path", kinds[0]}:
        fail(key, "needs its path and exactly one of values, grid, random")
    kind, spec = kinds[0], axis[kinds[0]]
    if kind == "values":
        if not isinstance(spec, list) or not spec:
            fail(key + ".values", "must be a non-empty list")
        return [number(v, "%s.values.%d" % (key, i)) for i, v in enumerate(spec)]
    if not isinstance(spec, dict):
        fail(key + "." + kind, "must be an object")
    lo, hi = number(spec.get("from"), key + "." + kind + ".from"), number(spec.get("to"), key + "." + kind + ".to")
    count_key = "points" if kind == "grid" else "samples"
    n = spec.get(count_key)
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= 100000:
        fail("%s.%s.%s" % (key, kind, count_key), "must be a whole number in 1..100000")
    if kind == "grid":
        return [lo + (hi - lo) * i / (n - 1) for i in range(n)] if n > 1 else [lo]
    seed = spec.get("seed", 0)
    if isinstance(seed, bool) or not isinstance(seed, int):
        fail(key + ".random.seed", "must be a whole number")
    rng = random.Random(seed)
    return [lo + (hi - lo) * rng.random() for _ in range(n)]


def load(study_path):
    """The study, validated: (base path, [(path, values)], [(path, source path)], {fixed})."""
    study_path = pathlib.Path(study_path)
    try:
        s = json.loads(study_path.read_text())
    except (OSError, ValueError) as e:
        raise StudyError("study: %s: %s" % (study_path, e))
    if not isinstance(s, dict):
        fail("", "must be a JSON object")
    unknown = set(s) - {"name", "base", "axes", "same", "set", "maps"}
    if unknown:
        fail(sorted(unknown)[0], "is not a study key (name, base, axes, same, set, maps)")
    if not isinstance(s.get("base"), str):
        fail("base", "must be the gear file's path")
    base = (study_path.parent / s["base"]).resolve()
    if not base.is_file():
        fail("base", "names no file (%s)" % base)
    axes = s.get("axes")
    if not isinstance(axes, list) or not axes:
        fail("axes", "must be a non-empty list")
    axes = [(a["path"], axis_values(a, k)) for k, a in enumerate(axes)]
    paths = [p for p, _ in axes]
    if len(set(paths)) != len(paths):
        fail("axes", "names a path twice")
    same = s.get("same", [])
    if not isinstance(same, list) or any(not (isinstance(x, list) and len(x) == 2 and all(isinstance(p, str) for p in x))
                                         for x in same):
        fail("same", "must be a list of [path, axis path] pairs")
    for k, (_, src) in enumerate(same):
        if src not in paths:
            fail("same.%d" % k, "copies '%s', which is not an axis" % src)
    fixed = s.get("set", {})
    if not isinstance(fixed, dict):
        fail("set", "must be an object of path: number")
    maps = s.get("maps", [])
    if not isinstance(maps, list) or not all(isinstance(m, str) for m in maps):
        fail("maps", "must be a list of key-number names")
    fixed = {p: number(v, "set." + p) for p, v in fixed.items()}
    total = 1
    for _, v in axes:
        total *= len(v)
    if total > 1000000:
        fail("axes", "give %d designs; at most 1000000" % total)
    return base, axes, [tuple(x) for x in same], fixed


def designs(study_path):
    """[(hash, {path: value} of the axes, [(path, value)] overrides)] in a deterministic order."""
    base, axes, same, fixed = load(study_path)
    out = []
    for combo in itertools.product(*[v for _, v in axes]):
        point = dict(zip([p for p, _ in axes], combo))
        overrides = dict(fixed)
        overrides.update(point)
        overrides.update({dst: point[src] for dst, src in same})
        text = json.dumps(sorted(overrides.items()), separators=(",", ":"))
        out.append((hashlib.sha256((str(base) + text).encode()).hexdigest()[:12], point, sorted(overrides.items())))
    return out


def write_designs(study_path, out):
    out = pathlib.Path(out)
    for h, point, overrides in designs(study_path):
        d = out / "designs" / h
        d.mkdir(parents=True, exist_ok=True)
        f = d / "overrides.json"
        text = json.dumps({"axes": point, "overrides": overrides}, indent=1)
        if not f.exists() or f.read_text() != text:   # unchanged file, unchanged mtime: Snakemake reruns nothing
            f.write_text(text)


def run(design_dir, gearhb, base):
    """One design; status.json says ok or failed with the program's one-line reason. Exit 0 always,
    so a failed design does not stop the study."""
    d = pathlib.Path(design_dir)
    spec = json.loads((d / "overrides.json").read_text())
    args = [gearhb, str(base), "--quiet", "--out", str(d / "run")]
    for path, value in spec["overrides"]:
        args += ["--set", "%s=%r" % (path, value)]
    p = subprocess.run(args, capture_output=True, text=True)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    status = {"status": "ok" if p.returncode == 0 else "failed", "exit": p.returncode,
              "reason": "" if p.returncode == 0 else (lines[-1] if lines else "exit %d" % p.returncode)}
    tmp = d / "status.json.tmp"
    tmp.write_text(json.dumps(status))
    tmp.replace(d / "status.json")


def table_rows(study_path, out):
    out = pathlib.Path(out)
    rows, keys = [], []
    for h, point, _ in designs(study_path):
        d = out / "designs" / h
        st = json.loads((d / "status.json").read_text())
        row = {"design": h}
        row.update(point)
        row.update({"status": st["status"], "reason": st["reason"]})
        kn = d / "run" / "key_numbers.json"
        if st["status"] == "ok" and kn.exists():
            for k, v in json.loads(kn.read_text()).items():
                row[k] = v["value"]
                if k not in keys:
                    keys.append(k)
        rows.append(row)
    return rows, keys


def gather(study_path, out):
    out = pathlib.Path(out)
    rows, keys = table_rows(study_path, out)
    _, axes, _, _ = load(study_path)
    columns = ["design"] + [p for p, _ in axes] + ["status", "reason"] + keys
    tmp = out / "table.csv.tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, restval="")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.17g" % v if isinstance(v, float) else v) for k, v in r.items()})
    tmp.replace(out / "table.csv")


def main(argv):
    try:
        if len(argv) == 3 and argv[1] == "check":
            print("%d designs" % len(designs(argv[2])))
        elif len(argv) == 4 and argv[1] == "designs":
            write_designs(argv[2], argv[3])
        elif len(argv) == 5 and argv[1] == "run":
            run(argv[2], argv[3], argv[4])
        elif len(argv) == 4 and argv[1] == "gather":
            gather(argv[2], argv[3])
        elif len(argv) == 4 and argv[1] == "maps":
            import study_maps
            study_maps.draw(argv[2], argv[3])
        else:
            sys.stderr.write(__doc__)
            return 2
    except StudyError as e:
        print(e, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
