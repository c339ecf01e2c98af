#!/usr/bin/env python3
"""JSON examples in the READMEs parse, and the example files run (issue 37 §3):

    readme_json.py BUILD_DIR OUT_DIR README.md...

A JSON block is an indented (4-space) block whose first line starts with `{`; it ends at the
first blank line. Every one must be valid JSON as it stands (what a user copies). A block
right after the line `<!-- example file: PROGRAM -->` is also written to a file and run,
`build/bin/PROGRAM FILE --set plot=0 --quiet --out OUT_DIR/...`: it must exit 0.
"""
import itertools
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MARK = re.compile(r"^<!-- example file: (\w+) -->$")


def blocks(readme):
    """[(first line number, text, program or None)]: runs of non-blank lines whose first is `    {`."""
    lines = readme.read_text().splitlines()
    out = []
    for blank, run in itertools.groupby(enumerate(lines), key=lambda nl: not nl[1].strip()):
        run = list(run)
        m = MARK.match(run[0][1])
        if m:   # the marker line opens the run; the block follows it
            run = run[1:]
        if blank or not run or not run[0][1].startswith("    {"):
            continue
        out.append((run[0][0] + 1, "\n".join(l[4:] for _, l in run), m.group(1) if m else None))
    return out


def main():
    build, out_root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    out_root.mkdir(parents=True, exist_ok=True)
    errors, parsed, ran = [], 0, 0
    for readme in sys.argv[3:]:
        for line, text, program in blocks(pathlib.Path(readme)):
            where = "%s:%d" % (readme, line)
            try:
                json.loads(text)
                parsed += 1
            except json.JSONDecodeError as e:
                errors.append("%s: not JSON (%s)" % (where, e))
                continue
            if program:
                f = out_root / ("example_%d.json" % (ran + 1))
                f.write_text(text + "\n")
                p = subprocess.run([str(build / "bin" / program), str(f), "--set", "plot=0", "--quiet", "--out",
                                    str(out_root / ("run_%d" % (ran + 1)))], cwd=ROOT, capture_output=True,
                                   text=True, errors="replace", timeout=600)
                ran += 1
                print("%s: %s exit %d" % (where, program, p.returncode))
                if p.returncode != 0:
                    errors.append("%s: %s exits %d: %s" % (where, program, p.returncode, p.stderr.strip()[-300:]))
    for e in errors:
        print("FAIL: " + e)
    print("%d JSON blocks parsed, %d example files run, %d problems" % (parsed, ran, len(errors)))
    return 1 if errors or parsed == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
