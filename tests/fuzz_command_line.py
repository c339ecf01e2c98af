#!/usr/bin/env python3
"""Hostile command lines against one program (README "Running a chapter").

    fuzz_command_line.py PROGRAM WORK_DIR [--runs N] [--seed S] [--timeout T] [--file FILE.json]

Reads the program's parameters from --help (or, with --file, the numbers of the input
file by their dotted paths, for a program that reads a file: gearhb_frc, gearhb_gear),
then runs it N times with one to three random `--set key=value` overrides (extreme,
malformed, non-finite, huge or scaled values) on `--case own` (or on the file, with
plot=0), each into a fresh output folder, and asserts the classes:
  exit 0  the folder holds key_numbers.json, no data file holds inf or nan, no staging left;
  exit 1  one line on stderr, the output folder was not created, no staging left;
  exit 2  one line on stderr, nothing written;
  killed by the timeout (a valid but slow input): no output folder, or the whole one (killed
          after its publish, in the exit: key_numbers.json present), no partial one.
Anything else (a signal such as SIGSEGV/SIGABRT, another status) fails the test.
"""
import argparse
import pathlib
import random
import re
import shutil
import subprocess
import sys

NASTY = ["0", "-1", "1e308", "-1e308", "1e-320", "nan", "inf", "-inf", "1e9", "-1e9", "0x10",
         "1e400", "abc", "", " 1", "2147483648", "3.5", "1e-300", "-0", "+5", "1.", ".5", "5e",
         "4.9e-324", "2.2250738585072014e-308", "1.7e308", "1\n2", "/dev/zero", "."]
# Output folder names: every third run's holds shell metacharacters (nothing may run them).
OUT_NAMES = ["run%03d", "run%03d o'; touch INJECTED; echo '", "run%03d $(touch INJECTED)"]


def parameters(prog):
    out = subprocess.run([prog, "--help"], capture_output=True, text=True, timeout=30).stdout
    params, in_table = [], False
    for line in out.splitlines():
        if line.startswith("Parameters"):
            in_table = True
            continue
        m = re.match(r"^  (\S+)\s+(\S+)\s+\S+\s", line)
        if in_table and m and m.group(1) != "name":
            params.append((m.group(1), m.group(2)))
    return params


def file_numbers(path):
    """The numbers of a JSON file as (dotted path, value) pairs."""
    import json

    def walk(node, prefix):
        if isinstance(node, dict):
            items = node.items()
        elif isinstance(node, list):
            items = enumerate(node)
        else:
            return [(prefix, str(node))] if isinstance(node, (int, float)) and not isinstance(node, bool) else []
        out = []
        for k, v in items:
            out += walk(v, "%s.%s" % (prefix, k) if prefix else str(k))
        return out
    return walk(json.load(open(path)), "")


def value_for(rng, default):
    r = rng.random()
    if r < 0.6:
        return rng.choice(NASTY)
    try:
        d = float(default)
    except ValueError:
        return rng.choice(NASTY)
    return repr(d * rng.choice([0.5, 2, 10, 1e3, -1, 1e-3]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("work")
    ap.add_argument("--runs", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=3.0)
    ap.add_argument("--file", help="the program reads this file; fuzz its numbers")
    a = ap.parse_args()
    # the runs start in the work folder: relative paths would break
    if "/" in a.program:
        a.program = str(pathlib.Path(a.program).resolve())
    if a.file:
        a.file = str(pathlib.Path(a.file).resolve())
    rng = random.Random(a.seed)
    params = file_numbers(a.file) if a.file else parameters(a.program)
    if not params:
        sys.exit("no parameters found in %s --help" % a.program)
    work = pathlib.Path(a.work).resolve()
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    counts, failures = {}, []
    for i in range(a.runs):
        name = OUT_NAMES[i % len(OUT_NAMES)] % i
        out = work / name
        def staging(name=name):   # this run's staging folders (app/output_folder.hpp), a lock file
            return [f for f in work.iterdir() if f.name.startswith("." + name + ".")]
        sets = []
        for key, default in rng.sample(params, min(len(params), rng.randint(1, 3))):
            sets += ["--set", "%s=%s" % (key, value_for(rng, default))]
        head = [a.program, a.file, "--set", "plot=0"] if a.file else [a.program, "--case", "own"]
        cmd = head + ["--quiet", "--out", str(out)] + sets
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=a.timeout, cwd=work)
        except subprocess.TimeoutExpired:
            counts["timeout"] = counts.get("timeout", 0) + 1
            # The folder is published in one rename at the end (app/output_folder.hpp): a run
            # killed after it (e.g. in the sanitizers' leak check at exit) leaves the whole
            # folder, one killed before leaves none; a folder without key_numbers.json is partial.
            if out.exists() and not (out / "key_numbers.json").exists():
                failures.append("%s: killed, and a partial %s exists" % (" ".join(sets), out))
            for f in staging():
                shutil.rmtree(f, ignore_errors=True)
            continue
        s = p.returncode
        counts[s] = counts.get(s, 0) + 1
        what = " ".join(sets)
        err_lines = [l for l in p.stderr.splitlines() if l.strip()]
        if s == 0:
            if not (out / "key_numbers.json").exists():
                failures.append("%s: exit 0 without key_numbers.json" % what)
            for f in out.glob("*"):
                if f.suffix in (".csv", ".json") and re.search(r"\b(-?inf|nan|NaN|null)\b", f.read_text()):
                    failures.append("%s: %s holds inf/nan/null" % (what, f.name))
        elif s in (1, 2):
            if len(err_lines) != 1:
                failures.append("%s: exit %d with %d lines on stderr: %r" % (what, s, len(err_lines), p.stderr))
            if out.exists():
                failures.append("%s: exit %d but %s was written" % (what, s, out))
        else:
            failures.append("%s: exit status %d (signal or crash): %s" % (what, s, p.stderr.strip()[-300:]))
        if staging():
            failures.append("%s: staging folder left behind: %s" % (what, [f.name for f in staging()]))
        if list(work.rglob("INJECTED")) or pathlib.Path("INJECTED").exists():
            failures.append("%s into %r: a command in the output path ran" % (what, name))
    print("%s: %d runs: %s" % (pathlib.Path(a.program).name, a.runs,
                               ", ".join("%s: %d" % (k, v) for k, v in sorted(counts.items(), key=str))))
    for f in failures:
        print("FAIL " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
