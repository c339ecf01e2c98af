#!/usr/bin/env python3
"""Every program command a README shows runs (issue 37 §3): readme_commands.py BUILD_DIR OUT_DIR README.md...

A command is a line of an indented (4-space) block that starts with `build/bin/`, with its
`\\` continuation lines; what follows a run of two or more spaces is a remark (`# ...` or
words), not an argument. Commands with placeholders (an argument in capitals such as
GEAR.json, MODEL.json, DIR, or a `[...]` / `chNN_name` synopsis) are usage lines and are
skipped. Each command runs from the repository root with its `--out` replaced by a folder
under OUT_DIR (added when it has none) and `--quiet`; it must exit 0. Prints each command
with its exit status and time; fails listing the commands that did not exit 0. A command
shown again (the same text, in the same or another README) runs once, and one that a chapter's or
program's console block runs (<!-- console: ... -->, the same program and arguments but --out and
--quiet) is left to that block's test (readme.<name>.console runs it and fails on a non-zero exit).
So is one that a CTest fixture runs (`--ran 'COMMAND' DIR` after the READMEs: the same program and
arguments but --out and --quiet, into DIR); its key_numbers.json must be there (the fixture exited 0).
A --ran command no README shows is not used.
"""
import pathlib
import re
import shlex
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
PLACEHOLDER = re.compile(r"^[A-Z][A-Z0-9_]*(\.json)?$|\[|NN")


def commands(readme):
    lines = readme.read_text().splitlines()
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("    build/bin/"):
            text = line[4:]
            while text.rstrip().endswith("\\") and i + 1 < len(lines):
                i += 1
                text = text.rstrip()[:-1] + " " + lines[i].strip()
            text = re.split(r"\s{2,}", text.strip())[0]   # a remark after two spaces
            out.append(text)
        i += 1
    return out


CONSOLE = re.compile(r"^<!-- console: (.+?) -->", re.M)
CHECKED = re.compile(r"(chapters/[^/]+/README|programs/[^/]+/(README|NOTES))\.md$")


def run_key(program, args):
    """A run as (program, its arguments but --out DIR and --quiet)."""
    key, i = [], 0
    while i < len(args):
        if args[i] == "--out":
            i += 2
            continue
        if args[i] != "--quiet":
            key.append(args[i])
        i += 1
    return program, tuple(key)


def console_runs(readmes):
    """The runs of the console blocks of the READMEs that have a console test (CMakeLists.txt)."""
    runs = set()
    for readme in readmes:
        if CHECKED.search(pathlib.Path(readme).resolve().as_posix()):
            for m in CONSOLE.finditer(pathlib.Path(readme).read_text()):
                words = shlex.split(m.group(1))
                runs.add(run_key(words[0], words[1:]))
    return runs


def runnable(words):
    return not any(PLACEHOLDER.search(w) for w in words[1:]) and not PLACEHOLDER.search(words[0].split("/")[-1])


def main():
    build, out_root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    failed, n, seen = [], 0, set()
    readmes, by_fixture, rest = [], {}, sys.argv[3:]
    while rest:
        if rest[0] == "--ran" and len(rest) >= 3:
            words = shlex.split(rest[1])
            by_fixture[run_key(words[0], words[1:])] = pathlib.Path(rest[2])
            rest = rest[3:]
        else:
            readmes.append(rest.pop(0))
    by_console = console_runs(readmes)
    for readme in readmes:
        for text in commands(pathlib.Path(readme)):
            words = shlex.split(text)
            if not runnable(words):
                print("skip (usage line): %s" % text)
                continue
            if text in seen:
                print("skip (run above): %s" % text)
                continue
            seen.add(text)
            if run_key(words[0].split("/")[-1], words[1:]) in by_console:
                print("skip (run by its console block's test): %s" % text)
                continue
            key = run_key(words[0].split("/")[-1], words[1:])
            if key in by_fixture:
                ran = by_fixture.pop(key)
                ok = (ran / "key_numbers.json").is_file()
                print("%s (run by a fixture into %s): %s" % ("skip" if ok else "FAIL", ran, text))
                if not ok:
                    failed.append("%s (%s): the fixture's run is missing (%s)" % (text, readme, ran / "key_numbers.json"))
                continue
            n += 1
            exe = build / "bin" / words[0].split("/")[-1]
            args = words[1:]
            out = out_root / ("run_%d" % n)
            if "--out" in args:
                args[args.index("--out") + 1] = str(out)
            else:
                args += ["--out", str(out)]
            t0 = time.monotonic()
            p = subprocess.run([str(exe)] + args + ["--quiet"], cwd=ROOT, capture_output=True, text=True,
                               errors="replace", timeout=600)
            print("exit %d in %.1f s: %s" % (p.returncode, time.monotonic() - t0, text))
            if p.returncode != 0:
                failed.append("%s (%s): exit %d: %s" % (text, readme, p.returncode, p.stderr.strip()[-300:]))
    for f in failed:
        print("FAIL: " + f)
    print("%d commands run, %d failed" % (n, len(failed)))
    return 1 if failed or n == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
