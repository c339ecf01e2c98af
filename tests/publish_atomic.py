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
  * a DIR of the user's own files is refused with exit 2 and left untouched, also when it
    holds a folder or a file named key_numbers.json: only the marker .gearhb_run, a
    regular file with the marker line, makes DIR an earlier run's output (issue 32, 9);
  * runs into one DIR at the same time (issue 32, 1): each exits 0 and DIR is then
    exactly one of them, complete; nothing is left beside DIR;
  * a staging folder whose run was killed is removed by the next run, a live run's is not.
"""
import fcntl
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

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


def beside(folder):
    """Staging folders (and a lock file) beside `folder`."""
    return sorted(p.name for p in folder.parent.iterdir() if p.name.startswith("." + folder.name + "."))


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
    expect(len(beside(d)) == 1, "the killed run left its staging folder (%s)" % beside(d))
    p = run(d, "own")
    expect(p.returncode == 0 and listing(d) == OWN and not beside(d),
           "the next run after a kill at '%s' publishes and cleans up (left %s)" % (at, beside(d)))

# A rename into DIR would fail (timings.csv is a folder): the folder is replaced whole.
d = WORK / "blocked"
run(d, "quick")
(d / "timings.csv").unlink()
(d / "timings.csv").mkdir()
(d / "timings.csv" / "x").write_text("x")
p = run(d, "own")
expect(p.returncode == 0 and (d / "timings.csv").is_file() and listing(d) == OWN,
       "a folder in the place of timings.csv: exit %d, DIR is the new output" % p.returncode)

# A folder of the user's own files is not swept away, whatever it holds besides the marker.
def users_folder(name, make):
    d = WORK / name
    d.mkdir()
    (d / "thesis.tex").write_text("mine")
    make(d)
    before = listing(d)
    p = run(d, "own")
    expect(p.returncode == 2 and (d / "thesis.tex").read_text() == "mine" and listing(d) == before
           and not beside(d) and ".gearhb_run" in p.stderr,
           "a user's folder (%s): exit %d, left as it was: %s" % (name, p.returncode, p.stderr.strip()))


users_folder("users", lambda d: None)
users_folder("users_key_numbers_folder", lambda d: (d / "key_numbers.json").mkdir())
users_folder("users_key_numbers_file", lambda d: (d / "key_numbers.json").write_text("{}"))
users_folder("users_marker_folder", lambda d: (d / ".gearhb_run").mkdir())
users_folder("users_marker_other_text", lambda d: (d / ".gearhb_run").write_text("my notes\n"))
users_folder("users_marker_link", lambda d: (d / ".gearhb_run").symlink_to(quick_ref / ".gearhb_run"))

# Runs into one DIR at the same time: both succeed, DIR is one of them whole. The two
# start 0 to 0.3 s apart so that the second starts during the first's steps and at its
# publish; the quick case is written by one, own by the other.
for k in range(6):
    d = WORK / "together"
    first = subprocess.Popen([PROG, "--case", "quick", "--quiet", "--out", str(d)], stderr=subprocess.PIPE, text=True)
    time.sleep(0.05 * k)
    second = run(d, "own")
    first.wait(timeout=300)
    whole = listing(d) in (QUICK, OWN)
    expect(first.returncode == 0 and second.returncode == 0 and whole and not beside(d),
           "two runs at once (%.2f s apart): exit %d and %d, DIR is %s, beside: %s"
           % (0.05 * k, first.returncode, second.returncode,
              "quick's" if listing(d) == QUICK else "own's" if listing(d) == OWN else "a mix", beside(d)))

# Two runs of the same case, started together, publish at about the same moment.
for k in range(3):
    d = WORK / "together_same"
    runs = [subprocess.Popen([PROG, "--case", "quick", "--quiet", "--out", str(d)], stderr=subprocess.PIPE, text=True)
            for _ in range(2)]
    status = [r.wait(timeout=300) for r in runs]
    expect(status == [0, 0] and listing(d) == QUICK and not beside(d),
           "two quick runs at once: exit %s, DIR %s, beside: %s"
           % (status, "complete" if listing(d) == QUICK else "a mix", beside(d)))

# A live run's staging folder is left alone: a process that holds its marker's lock.
d = WORK / "live"
run(d, "quick")
live = d.parent / ("." + d.name + ".staging.1-live")
live.mkdir()
(live / ".gearhb_run").write_text("x")
with open(live / ".gearhb_run", "r+") as f:
    fcntl.flock(f, fcntl.LOCK_EX)
    p = run(d, "own")
    expect(p.returncode == 0 and live.exists(), "a locked staging folder survives another run into DIR")
p = run(d, "own")
expect(p.returncode == 0 and not beside(d), "once unlocked, it is removed by the next run (left %s)" % beside(d))

print("publish: %d failed" % len(failures))
sys.exit(1 if failures else 0)
