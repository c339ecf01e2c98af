#!/usr/bin/env python3
"""Hostile study files and hostile designs (issue 32, items 2-4): studies/study.py never dies.

    study_hostile.py WORK_DIR

Fake programs (a shell script standing in for gearhb_gear, written into WORK_DIR) make every
failure of a design fast and deterministic. Checks:
  a. every bad study file (a non-object axis, 100,000-deep and 33-deep nesting, a duplicate key,
     a name that is not short printable text, a base that is /etc/passwd, /proc/self/environ, a
     folder, a FIFO, a device, a symlink to /proc or not a JSON object, a lone surrogate in a
     path of axes / same / set, a file over 16 MiB or not UTF-8, a bad time limit, ...) makes
     `check` and `gather` exit 2 with one line of valid UTF-8 `study: '<key>' <why>` naming the
     key, and write nothing; a valid study (the control) exits 0. Then every value of a valid
     study replaced by values of every JSON type: exit 0 or 2, never an unexpected exception;
  b. `study.py run` always exits 0 and writes status.json: a program printing 0xff bytes and
     exiting 1 -> failed, the bytes escaped (\\xff); one hanging while ignoring SIGTERM, with a
     child, under a 2 s limit -> failed "time limit (2 s)" within the limit and the grace, its
     whole process group gone; one killed by SIGSEGV; exit 0 without key numbers; a program that
     does not exist; an unreadable design or time limit. An interrupted `run` (SIGTERM) leaves no
     status and no process; a `run` killed by SIGKILL takes its program with it;
  c. a study of 8 designs through Snakemake (2 ok, 2 hanging, 2 printing non-UTF-8, 2 crashing)
     ends with table.csv holding every design's row and reason; its dry run beforehand writes no
     design folder and asks Slurm for runtime = 3 min (2 s rounded up + 2); a rerun has nothing
     to do; `gather` over a missing, a non-UTF-8 status.json and a corrupt key_numbers.json makes
     those designs failed rows with the reason.
CTest: studies.hostile (about 30 s).
"""
import contextlib
import io
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
TOOL = ROOT / "studies" / "study.py"
sys.path.insert(0, str(ROOT / "studies"))
import study  # noqa: E402

FAKE = r"""#!/bin/sh
# A stand-in for gearhb_gear: BASE --quiet --out DIR [--set PATH=VALUE]...; the value of mode says what it does
# (0: a run with the files the study reads: key numbers, STE and DTE for study_maps).
out= mode= torque=0
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift ;;
    --set) case $2 in mode=*) mode=${2#mode=} ;; torques.0=*) torque=${2#torques.0=} ;; esac; shift ;;
  esac
  shift
done
ulimit -c 0
case $mode in
  0.0) mkdir -p "$out" && printf '{"x": {"value": %s, "unit": "1"}}\n' "$torque" > "$out/key_numbers.json" &&
       printf 'phase,ste_um\n0,1\n1,2\n' > "$out/ste_1.csv" &&
       printf 'omega,f_mesh_hz,x_rms_ac\n1,1,1e-6\n2,2,2e-6\n' > "$out/frc_1.csv" ;;
  1.0) trap '' TERM; echo $$ > "$out.pids"; sleep 1000 & echo $! >> "$out.pids"; wait ;;
  2.0) printf 'fake: a first line\nfake: bad byte \377\376 in a name\n' >&2; exit 1 ;;
  3.0) kill -SEGV $$ ;;
  4.0) exit 0 ;;
  5.0) echo $$ > "$out.pids"; exec sleep 1000 ;;
esac
"""

errors = []


def expect(ok, what):
    if not ok:
        errors.append(what)
    return ok


def tool(*args, cwd=None, **kw):
    return subprocess.run([sys.executable, str(TOOL)] + [str(a) for a in args], cwd=cwd, capture_output=True, **kw)


def one_line_naming(stderr, key):
    """stderr is one line of valid UTF-8 `study: '<key>' ...`."""
    try:
        text = stderr.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return text.count("\n") == 1 and text.endswith("\n") and text.startswith("study: '%s' " % key)


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


# ---- a. bad study files ------------------------------------------------------------------------

def bad_studies(base, d):
    """[(label, text of the study file, the key its error must name)]."""
    def s(**kw):
        study_obj = {"base": base, "axes": [{"path": "mode", "values": [0, 1]}]}
        study_obj.update(kw)
        return json.dumps(study_obj)
    ok_head = '{"base": %s, "axes": [{"path": "mode", "values": [0]}], ' % json.dumps(base)
    return [
        ("axes: [1]", s(axes=[1]), "axes.0"),
        ("100,000-deep nesting", ok_head + '"name": ' + "[" * 100000 + "]" * 100000 + "}", "s.json"),
        ("33-deep nesting", ok_head + '"name": ' + "[" * 32 + "]" * 32 + "}", "s.json"),
        ("32-deep nesting (depth fine, name bad)", ok_head + '"name": ' + "[" * 31 + "]" * 31 + "}", "name"),
        ("duplicate key", ok_head + '"name": "a", "name": "b"}', "s.json"),
        ("name a number", s(name=5), "name"),
        ("name with a line break", s(name="a\nb"), "name"),
        ("name of 201 characters", s(name="n" * 201), "name"),
        ("base ../../../etc/passwd", s(base="../../../../../../../../etc/passwd"), "base"),
        ("base /proc/self/environ", s(base="/proc/self/environ"), "base"),
        ("base /dev/null", s(base="/dev/null"), "base"),
        ("base a folder", s(base=str(d / "folder.json")), "base"),
        ("base a FIFO", s(base=str(d / "fifo.json")), "base"),
        ("base a symlink to /proc", s(base=str(d / "environ.json")), "base"),
        ("base not an object", s(base=str(d / "list.json")), "base"),
        ("base not UTF-8", s(base=str(d / "ff.json")), "base"),
        ("base a number", s(base=5), "base"),
        ("base missing", s(base=str(d / "none.json")), "base"),
        ("set key a lone surrogate", s(set={"\udc80": 1}), "set.\\udc80"),
        ("axis path a lone surrogate", s(axes=[{"path": "\udc80", "values": [1]}]), "axes.0.path"),
        ("axis path with =", s(axes=[{"path": "mode=1", "values": [1]}]), "axes.0.path"),
        ("same path a lone surrogate", s(same=[["\udc80", "mode"]]), "same.0.0"),
        ("same copies no axis", s(same=[["torques.0", "speed"]]), "same.0.1"),
        ("set an axis too", s(set={"mode": 1}), "set.mode"),
        ("set a text value", s(set={"plot": "x"}), "set.plot"),
        ("over 16 MiB", ok_head + " " * (16 << 20) + "}", "s.json"),
        ("not UTF-8", (ok_head + '"name": "\xff"}').encode("latin-1"), "s.json"),
        ("not JSON", "{", "s.json"),
        ("not an object", "[]", "s.json"),
        ("unknown key", s(axis=[]), "axis"),
        ("time_limit_s 0", s(time_limit_s=0), "time_limit_s"),
        ("time_limit_s -1", s(time_limit_s=-1), "time_limit_s"),
        ("time_limit_s text", s(time_limit_s="600"), "time_limit_s"),
        ("time_limit_s true", s(time_limit_s=True), "time_limit_s"),
        ("time_limit_s a week", s(time_limit_s=604800), "time_limit_s"),
        ("values empty", s(axes=[{"path": "mode", "values": []}]), "axes.0.values"),
        ("values NaN", ok_head.replace("[0]", "[NaN]") + '"set": {}}', "axes.0.values.0"),
        ("grid unknown key", s(axes=[{"path": "mode", "grid": {"from": 0, "to": 1, "points": 2, "step": 1}}]),
         "axes.0.grid.step"),
        ("random seed 1.5", s(axes=[{"path": "mode", "random": {"from": 0, "to": 1, "samples": 2, "seed": 1.5}}]),
         "axes.0.random.seed"),
        ("two kinds", s(axes=[{"path": "mode", "values": [1], "grid": {}}]), "axes.0"),
        ("1e10 designs", s(axes=[{"path": "a", "grid": {"from": 0, "to": 1, "points": 100000}},
                                 {"path": "b", "grid": {"from": 0, "to": 1, "points": 100000}}]), "axes"),
        ("maps [1]", s(maps=[1]), "maps.0"),
        ("same path twice", s(axes=[{"path": "mode", "values": [1]}, {"path": "mode", "values": [2]}]), "axes.1.path"),
    ]


def check_bad_studies(work):
    d = work / "a"
    d.mkdir()
    base = d / "base.json"
    base.write_text('{"mode": 0, "plot": 0, "torques": [100]}')
    (d / "folder.json").mkdir()
    os.mkfifo(d / "fifo.json")
    (d / "environ.json").symlink_to("/proc/self/environ")
    (d / "list.json").write_text("[1]")
    (d / "ff.json").write_bytes(b'{"mode": "\xff"}')
    good = json.dumps({"name": "n" * 200, "base": str(base), "time_limit_s": 0.5,
                       "axes": [{"path": "mode", "grid": {"from": 0, "to": 1, "points": 3}}]})
    cases = [("control: a valid study", good, None)] + bad_studies(str(base), d)
    for k, (label, text, key) in enumerate(cases):
        case = d / ("case%d" % k)
        case.mkdir()
        f = case / "s.json"
        f.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8", "surrogatepass"))
        t0 = time.monotonic()
        p = tool("check", "s.json", cwd=case, timeout=60)
        q = tool("gather", "s.json", "out", cwd=case, timeout=60)
        seconds = time.monotonic() - t0
        if key is None:
            expect(p.returncode == 0 and p.stdout == b"3 designs\n" and not p.stderr,
                   "%s: exit %d, %r %r" % (label, p.returncode, p.stdout, p.stderr))
            continue
        for cmd, r in (("check", p), ("gather", q)):
            expect(r.returncode == 2 and one_line_naming(r.stderr, key) and not r.stdout,
                   "%s: %s exit %d, stderr %r (expected one line naming '%s')" % (label, cmd, r.returncode,
                                                                                  r.stderr[:300], key))
        expect(listing(case) == ["s.json"], "%s: wrote %s" % (label, listing(case)))
        expect(seconds < 20, "%s: took %.1f s" % (label, seconds))
    print("a. %d bad study files: exit 2 naming the key, nothing written (and 1 valid control)" % (len(cases) - 1))
    return base


def locations(value, where=()):
    """Every place of a JSON value (as a tuple of keys and indices), the value itself first."""
    yield where
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else []
    for k, v in items:
        yield from locations(v, where + (k,))


def replaced(value, where, new):
    if not where:
        return new
    copy = json.loads(json.dumps(value))
    node = copy
    for k in where[:-1]:
        node = node[k]
    node[where[-1]] = new
    return copy


def check_every_type(work, base):
    """Every value of a valid study replaced by values of every JSON type: exit 0 or 2, one line."""
    valid = {"name": "types", "base": str(base), "time_limit_s": 5,
             "axes": [{"path": "mode", "grid": {"from": 0, "to": 1, "points": 2}},
                      {"path": "torques.0", "random": {"from": 1, "to": 2, "samples": 2, "seed": 1}},
                      {"path": "plot", "values": [0, 1]}],
             "same": [["speed", "mode"]], "set": {"x": 1}, "maps": ["x"]}
    hostile = [None, True, 0, -1, 2.5, 1e300, "", "x", "\udc80", [], [1], [[]], {}, {"a": 1}, {"\udc80": None}]
    f = work / "types.json"
    runs = 0
    for where in list(locations(valid)):
        for new in hostile:
            f.write_text(json.dumps(replaced(valid, where, new)), encoding="utf-8", errors="surrogatepass")
            err = io.StringIO()
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
                code = study.main(["study.py", "check", str(f)])
            runs += 1
            line = err.getvalue()
            expect(code == 0 and not line or code == 2 and line.count("\n") == 1 and line.startswith("study: '"),
                   "%s = %r: exit %d, %r" % (".".join(map(str, where)), new, code, line))
            line.encode("utf-8")   # valid UTF-8: raises on a lone surrogate
    print("a. %d studies with a value of another type: exit 0 or 2 with one line" % runs)


# ---- b. study.py run ---------------------------------------------------------------------------

def live_in_group(pgid):
    """The processes of a process group that are alive (zombies excepted)."""
    live = []
    for stat_file in pathlib.Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat_file.read_text()
        except OSError:
            continue
        state, _, pgrp = text[text.rindex(")") + 2:].split()[:3]
        if int(pgrp) == pgid and state != "Z":
            live.append(int(stat_file.parent.name))
    return live


def gone(pids_file):
    """Whether the process group whose leader's pid the fake program wrote is gone (waits up to 2 s)."""
    if not pids_file.exists():
        return expect(False, "%s was not written" % pids_file)
    pgid = int(pids_file.read_text().split()[0])
    deadline = time.monotonic() + 2
    while live_in_group(pgid) and time.monotonic() < deadline:
        time.sleep(0.05)
    return expect(not live_in_group(pgid), "processes left of group %d: %s" % (pgid, live_in_group(pgid)))


def run_design(fake, base, folder, mode, limit="30", design=None):
    design = design or study.design_json({"mode": mode}, [("mode", mode)])
    t0 = time.monotonic()
    p = tool("run", folder, fake, base, limit, design, timeout=60)
    expect(p.returncode == 0 and not p.stderr, "run %s: exit %d, %r" % (folder.name, p.returncode, p.stderr))
    try:
        status = json.loads((folder / "status.json").read_bytes().decode("utf-8"))
    except (OSError, ValueError) as e:
        expect(False, "run %s: no readable status.json (%s)" % (folder.name, e))
        status = {}
    return status, time.monotonic() - t0


def check_run(work, fake, base):
    d = work / "b"
    d.mkdir()
    cases = [("ok", 0.0, {}, "", "ok"),
             ("non_utf8", 2.0, {}, "fake: bad byte \\xff\\xfe in a name", "failed"),
             ("segv", 3.0, {}, "killed by signal SIGSEGV (11)", "failed"),
             ("no_key_numbers", 4.0, {}, "exit 0 without run/key_numbers.json", "failed"),
             ("no_program", 0.0, {"fake": d / "none"}, "cannot run (No such file or directory)", "failed"),
             ("bad_design", 0.0, {"design": "{not json"}, "the design's overrides are unreadable", "failed"),
             ("bad_override", 0.0, {"design": '{"axes": {}, "overrides": [["a=b", 1]]}'},
              "the design's overrides are unreadable", "failed"),
             ("bad_limit", 0.0, {"limit": "abc"}, "time limit 'abc' is not seconds", "failed")]
    for name, mode, kw, reason, want in cases:
        status, _ = run_design(kw.get("fake", fake), base, d / name, mode, kw.get("limit", "30"), kw.get("design"))
        expect(status.get("status") == want and reason in status.get("reason", "-"),
               "run %s: %r, expected %s with %r" % (name, status, want, reason))
    status, seconds = run_design(fake, base, d / "hang", 1.0, limit="2")
    expect(status.get("status") == "failed" and status.get("reason") == "time limit (2 s)" and
           2 <= seconds < 2 + study.KILL_GRACE_S + 3, "run hang: %r after %.1f s" % (status, seconds))
    gone(d / "hang" / "run.pids")
    # interrupted by SIGTERM (Snakemake stopping): no status, no process
    for sig in (signal.SIGTERM, signal.SIGKILL):
        folder = d / ("interrupted_%s" % sig.name)
        proc = subprocess.Popen([sys.executable, str(TOOL), "run", str(folder), str(fake), str(base), "100",
                                 study.design_json({"mode": 5.0}, [("mode", 5.0)])], stderr=subprocess.PIPE)
        deadline = time.monotonic() + 10
        while not (folder / "run.pids").exists() and time.monotonic() < deadline:
            time.sleep(0.02)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=30)
        expect(not (folder / "status.json").exists(), "%s: a status was written" % sig.name)
        expect(sig == signal.SIGKILL or proc.returncode == 128 + sig and err == b"study: interrupted by SIGTERM\n",
               "%s: exit %d, %r" % (sig.name, proc.returncode, err))
        gone(folder / "run.pids")
    print("b. study.py run: %d designs failed with their reason, a 2 s hang ended in %.1f s, interrupts leave "
          "no status and no process" % (len(cases), seconds))


# ---- c. a study through Snakemake --------------------------------------------------------------

def snakemake(study_file, out, fake, *extra):
    return subprocess.run(["snakemake", "-s", str(ROOT / "studies" / "Snakefile"), "--cores", "2", "--config",
                           "study=%s" % study_file, "out=%s" % out, "gearhb=%s" % fake] + list(extra),
                          cwd=out.parent, capture_output=True, text=True, timeout=240)


def table(out):
    import csv
    with open(out / "table.csv", encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def check_snakemake(work, fake, base):
    d = work / "c"
    d.mkdir()
    study_file = d / "hostile.json"
    study_file.write_text(json.dumps({"name": "hostile", "base": str(base), "time_limit_s": 2,
                                      "axes": [{"path": "mode", "values": [0, 1, 2, 3]},
                                               {"path": "torques.0", "values": [100, 200]}],
                                      "set": {"plot": 0}, "maps": ["x"]}))
    out = d / "out"
    p = snakemake(study_file, out, fake, "--dry-run")
    expect(p.returncode == 0 and not out.exists(), "dry run: exit %d, wrote %s" % (p.returncode, out.exists()))
    expect("runtime=3" in p.stdout, "dry run: no runtime=3 in %r" % p.stdout[-1500:])
    p = snakemake(study_file, out, fake)
    if not expect(p.returncode == 0, "snakemake: exit %d: %s" % (p.returncode, p.stderr[-2000:])):
        return
    rows = table(out)
    want = {"0": ("ok", ""), "1": ("failed", "time limit (2 s)"),
            "2": ("failed", "fake: bad byte \\xff\\xfe in a name"), "3": ("failed", "killed by signal SIGSEGV (11)")}
    expect(len(rows) == 8, "table: %d rows, expected 8" % len(rows))
    for r in rows:
        mode = r["mode"].split(".")[0]
        expect((r["status"], r["reason"]) == want[mode], "table: mode %s: %s %r" % (mode, r["status"], r["reason"]))
        expect(mode != "0" or r["x"] == r["torques.0"], "table: mode 0 without its key number: %r" % r)
    expect((out / "maps.png").exists(), "no maps.png")
    for pids in out.glob("designs/*/run.pids"):
        gone(pids)
    p = snakemake(study_file, out, fake, "--dry-run", "--quiet")
    expect(p.returncode == 0 and "rule design" not in p.stdout and "Job stats" not in p.stdout,
           "a rerun would run jobs: %s" % p.stdout[-500:])
    # gather over broken design folders
    by_mode = {}
    for r in rows:
        by_mode.setdefault(r["mode"].split(".")[0], []).append(r["design"])
    broken = {by_mode["0"][0]: ("run/key_numbers.json", b"{"), by_mode["1"][0]: ("status.json", None),
              by_mode["2"][0]: ("status.json", b'{"status": "ok", "reason": "\xff"}')}
    for h, (name, data) in broken.items():
        f = out / "designs" / h / name
        f.unlink()
        if data is not None:
            f.write_bytes(data)
    p = tool("gather", study_file, out, timeout=60)
    rows = {r["design"]: r for r in table(out)}
    expect(p.returncode == 0 and len(rows) == 8, "gather over broken folders: exit %d, %d rows, %r" % (
        p.returncode, len(rows), p.stderr))
    for h, reason in ((by_mode["0"][0], "run/key_numbers.json is not valid JSON"),
                      (by_mode["1"][0], "status.json cannot be opened"),
                      (by_mode["2"][0], "status.json is not UTF-8 text")):
        r = rows.get(h, {})
        expect(r.get("status") == "failed" and r.get("reason", "").startswith(reason),
               "gather: design %s: %r, expected failed with %r" % (h, r, reason))
    print("c. Snakemake: 8 designs (2 ok, 2 hanging, 2 non-UTF-8, 2 crashing), every one a row; the dry run wrote "
          "nothing; gather survives 3 broken design folders")


def main(work):
    work = pathlib.Path(work).resolve()
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    fake = work / "fake_gearhb"
    fake.write_text(FAKE)
    fake.chmod(0o755)
    t0 = time.monotonic()
    base = check_bad_studies(work)
    check_every_type(work, base)
    check_run(work, fake, base)
    if shutil.which("snakemake"):
        check_snakemake(work, fake, base)
    else:
        expect(False, "snakemake not found")
    for e in errors:
        print("PROBLEM:", e)
    print("study hostile: %d problems in %.0f s" % (len(errors), time.monotonic() - t0))
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
