#!/usr/bin/env python3
"""The design-study workflow (studies/, issue 24) through Snakemake on 2 cores.

    study_workflow.py BUILD_DIR WORK_DIR

studies/small.json: 3 relief amounts (one of them negative, which gearhb_gear refuses) x 3
torques = 9 designs. Checks:
  1. the study runs to its table; the 3 refused designs are in it with status 'failed' and the
     program's one-line reason naming the key, the 6 others 'ok';
  2. every number of the table equals a single run of gearhb_gear with the same overrides
     (identical: the same deterministic program, so a mismatch means the workflow changed a design);
  3. a rerun has nothing to do (snakemake --dry-run lists no job);
  4. a study killed while running resumes and ends with the same table (bit for bit).
A bad study file exits 2 naming the key, before anything runs.
"""
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
STUDY = ROOT / "studies" / "small.json"
SNAKEFILE = ROOT / "studies" / "Snakefile"


def snakemake(out, gearhb, *extra, **kw):
    cmd = ["snakemake", "-s", str(SNAKEFILE), "--cores", "2", "--config", "study=%s" % STUDY, "out=%s" % out,
           "gearhb=%s" % gearhb] + list(extra)
    return subprocess.run(cmd, capture_output=True, text=True, cwd=out.parent, **kw)


def main(build, work):
    build, work = pathlib.Path(build).resolve(), pathlib.Path(work).resolve()
    gearhb = build / "bin" / "gearhb_gear"
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    errors = []
    # 0. a bad study: exit 2, one line naming the key
    bad = work / "bad.json"
    bad.write_text(json.dumps({"base": str(ROOT / "studies" / "tip_relief_base.json"),
                               "axes": [{"path": "torques.0", "grid": {"from": 1, "to": 2}}]}))
    p = subprocess.run([sys.executable, str(ROOT / "studies" / "study.py"), "check", str(bad)], capture_output=True, text=True)
    if p.returncode != 2 or "axes.0.grid.points" not in p.stderr:
        errors.append("bad study: exit %d, %r" % (p.returncode, p.stderr))
    # 1. the study
    out = work / "run1"
    p = snakemake(out, gearhb)
    if p.returncode != 0:
        sys.exit("snakemake failed: %s" % p.stderr[-2000:])
    table = (out / "table.csv").read_text().splitlines()
    header, rows = table[0].split(","), [r.split(",") for r in table[1:]]
    col = {c: i for i, c in enumerate(header)}
    failed = [r for r in rows if r[col["status"]] == "failed"]
    if len(rows) != 9 or len(failed) != 3:
        errors.append("expected 9 designs, 3 failed; got %d, %d" % (len(rows), len(failed)))
    for r in failed:
        if "tip_relief.amount" not in r[col["reason"]] or float(r[col["gears.0.tip_relief.amount"]]) >= 0:
            errors.append("failed design without its reason: %s" % r[:4])
    # 2. against single runs
    sys.path.insert(0, str(ROOT / "studies"))
    import study
    designs = {h: o for h, _, o in study.designs(STUDY)}
    for r in rows:
        if r[col["status"]] != "ok":
            continue
        single = work / ("single_" + r[0])
        args = [str(gearhb), str(ROOT / "studies" / "tip_relief_base.json"), "--quiet", "--out", str(single)]
        for path, value in designs[r[0]]:
            args += ["--set", "%s=%r" % (path, value)]
        subprocess.run(args, check=True, capture_output=True)
        kn = json.loads((single / "key_numbers.json").read_text())
        for k, v in kn.items():
            if "%.17g" % v["value"] != r[col[k]]:
                errors.append("design %s: %s = %s in the table, %.17g in a single run" % (r[0], k, r[col[k]], v["value"]))
    # 3. a rerun does nothing
    p = snakemake(out, gearhb, "--dry-run", "--quiet")
    if p.returncode != 0 or "Job stats" in p.stdout or "rule design" in p.stdout:
        errors.append("a rerun would run jobs: %s" % p.stdout[-500:])
    # 4. killed, then resumed
    out2 = work / "run2"
    cmd = ["snakemake", "-s", str(SNAKEFILE), "--cores", "1", "--config", "study=%s" % STUDY, "out=%s" % out2,
           "gearhb=%s" % gearhb]
    proc = subprocess.Popen(cmd, cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 60
    while time.time() < deadline and len(list(out2.glob("designs/*/status.json"))) < 3:
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    done_before = len(list(out2.glob("designs/*/status.json")))
    if (out2 / "table.csv").exists() or done_before >= 9:
        errors.append("the study was not interrupted (%d designs done)" % done_before)
    # a killed Snakemake leaves its lock: --unlock, then resume (--rerun-incomplete redoes a design cut mid-run)
    subprocess.run(cmd + ["--unlock"], cwd=work, capture_output=True, text=True)
    p = subprocess.run(cmd + ["--rerun-incomplete"], cwd=work, capture_output=True, text=True)
    if p.returncode != 0:
        errors.append("resume failed: %s" % p.stderr[-1000:])
    elif (out2 / "table.csv").read_text() != (out / "table.csv").read_text():
        errors.append("the resumed study's table differs from the uninterrupted one")
    for e in errors:
        print(e)
    print("study workflow: 9 designs, the killed run had finished %d, %d problems" % (done_before, len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
