#!/usr/bin/env python3
"""Numbers a README quotes from an independent reference script, checked against a fresh run.

    script_numbers_in_readme.py SCRIPT README NUMBER [NUMBER ...]

Runs SCRIPT (reference/scripts/..., numpy/scipy only) and fails unless every NUMBER (as the
README prints it; a leading '-' may be the typographic minus there) appears both in the
script's output and in the README. So a README cannot keep a number its script no longer
gives. CTest: reference.ch06_bilinear_modes_in_readme.
"""
import subprocess
import sys


def main(script, readme, numbers):
    out = subprocess.run([sys.executable, script], capture_output=True, text=True, check=True).stdout
    text = open(readme, encoding="utf-8").read()
    missing = []
    for n in numbers:
        if n not in out:
            missing.append("%s: not in the output of %s" % (n, script))
        if n not in text and n.replace("-", "\u2212") not in text:
            missing.append("%s: not in %s" % (n, readme))
    for m in missing:
        print(m)
    print("%d numbers, %d missing" % (len(numbers), len(missing)))
    return 1 if missing else 0


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
