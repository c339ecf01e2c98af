#!/usr/bin/env python3
"""The output folder is always exactly one run's complete output (README "Output files").

    publish_atomic.py PROGRAM WORK_DIR

A run writes into a staging folder and publishes it as DIR in one rename (study.cpp,
publish). Checked here with PROGRAM (a chapter program with --case quick and own):
  * a run into a DIR that held another run's output leaves only its own files;
  * a run killed (SIGKILL, through the test hook GEARHB_PUBLISH_KILL_AT) just before or
    just after the swap leaves DIR as the old or the new complete output, never a mix,
    and the next run cleans up and succeeds;
  * a DIR whose timings.csv was made a folder (a rename into it would fail) is
    replaced whole: exit 0 and a regular timings.csv;
  * a DIR of the user's own files (no key_numbers.json) is refused with exit 2 and left
    untouched.
"""
import os
import pathlib
import shutil
import signal
import subprocess
import sys

PROG, WORK = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
failures = []


def run(out, case, kill_at=None):
    env = dict(os.environ)
    env.pop("GEARHB_PUBLISH_KILL_AT", None)
    if kill_at:
        env["GEARHB_PUBLISH_KILL_AT"] = kill_at
    return subprocess.run([PROG, "--case", case, "--quiet", "--out", str(out)], capture_output=True, text=True,
                          env=env, timeout=300)


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def expect(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
# The two runs' file lists, each from an empty folder.
quick_ref, own_ref = WORK / "quick_ref", WORK / "own_ref"
expect(run(quick_ref, "quick").returncode == 0, "quick run into a new folder")
expect(run(own_ref, "own").returncode == 0, "own run into a new folder")
QUICK, OWN = listing(quick_ref), listing(own_ref)
expect(QUICK != OWN, "the two runs write different file sets (%d and %d files)" % (len(QUICK), len(OWN)))

# No stale files: own after quick in the same folder holds own's files only.
d = WORK / "stale"
run(d, "quick")
p = run(d, "own")
expect(p.returncode == 0 and listing(d) == OWN, "own after quick leaves exactly own's %d files (has %d)"
       % (len(OWN), len(listing(d))))

# Kills at each step of the publish.
for at, expected, name in [("staged", QUICK, "the old output"), ("swapped", OWN, "the new output")]:
    d = WORK / ("kill_" + at)
    run(d, "quick")
    p = run(d, "own", kill_at=at)
    expect(p.returncode == -signal.SIGKILL, "killed at '%s' (status %d)" % (at, p.returncode))
    expect(listing(d) == expected, "after a kill at '%s' DIR is %s, complete" % (at, name))
    p = run(d, "own")
    staging = d.parent / ("." + d.name + ".staging")
    expect(p.returncode == 0 and listing(d) == OWN and not staging.exists(),
           "the next run after a kill at '%s' publishes and cleans up" % at)

# A rename into DIR would fail (timings.csv is a folder): the folder is replaced whole.
d = WORK / "blocked"
run(d, "quick")
(d / "timings.csv").unlink()
(d / "timings.csv").mkdir()
(d / "timings.csv" / "x").write_text("x")
p = run(d, "own")
expect(p.returncode == 0 and (d / "timings.csv").is_file() and listing(d) == OWN,
       "a folder in the place of timings.csv: exit %d, DIR is the new output" % p.returncode)

# A folder of the user's own files is not swept away.
d = WORK / "users"
d.mkdir()
(d / "thesis.tex").write_text("mine")
p = run(d, "own")
expect(p.returncode == 2 and (d / "thesis.tex").read_text() == "mine" and listing(d) == ["thesis.tex"],
       "a folder without key_numbers.json: exit %d, left as it was" % p.returncode)

print("publish: %d failed" % len(failures))
sys.exit(1 if failures else 0)
