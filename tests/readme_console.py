#!/usr/bin/env python3
"""README console blocks that cannot go stale.

    readme_console.py --check BUILD_DIR README.md [README.md ...]   (CTest: readme.<chapter>.console)
    readme_console.py --write BUILD_DIR README.md [README.md ...]   (make docs: regenerate the blocks)

A README quotes a program's console output between two markers:

    <!-- console: ch03_mass_wall --quiet -->
    ```
    ch03_mass_wall: g-1.2_F0.01: 193 points, 0 folds, 0 rejected steps, complete
    ...
    ch03_mass_wall: done in 1.2 s, data in build/data/ch03_mass_wall
    ```
    <!-- end console -->

The marker names the program (in BUILD_DIR/bin) and its arguments; the block is what the
program prints on stdout. --write runs it and replaces the block; --check runs it and fails
on any line that differs. Wall times are excepted (a run's "done in X s" line is compared
without its time and output folder): everything else a README shows must be what the
program prints now.

A number in the prose or a table comes from the same run's key_numbers.json:

    worst difference <!-- key: xmax_rel_diff_hb_vs_time_integration %.1e -->5.4e-05<!-- /key -->
    <!-- key: ti_rms_rel_diff_T100_H5 *100 %.3f -->0.050<!-- /key --> %

(name, an optional factor, a printf format); --write fills it in, --check compares. With
several console blocks, `name@N` takes the number from the N-th block's run (1-based); a
bare name from the last block that has it.

The programs run in the repository's root folder, so a block may name an example file by
its path there (`gearhb_gear programs/gearhb_gear/examples/thesis_pair.json --set plot=0`).

    readme_console.py --check|--write BUILD_DIR README.md ... --ran 'COMMAND' DIR [--ran 'COMMAND' DIR]...

A block whose marker text is COMMAND is not run again: CTest ran exactly that command (with --quiet,
which only silences the progress lines on stderr) into DIR as a fixture (a regression run,
tests/CMakeLists.txt), its stdout in DIR.stdout; the block is checked against (--write: written from)
that run's stdout and key_numbers.json. A missing DIR.stdout or key_numbers.json fails the check.
To write a README from the runs its CTest check reads, run that test's command line
(`ctest -R readme.<name>.console -N -V`) with --write for --check, after the fixtures ran.
"""
import json
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

KEY = re.compile(r"<!-- key: (\S+?)(?:@(\d+))?(?: \*(\S+))? (%\S+) -->(.*?)<!-- /key -->")
ROOT = pathlib.Path(__file__).resolve().parent.parent
MARK = re.compile(r"^<!-- console: (.+?) -->\n(.*?)^<!-- end console -->\n", re.M | re.S)
DONE = re.compile(r"done in [0-9.]+ s, data in .*$")


def normalised(line):
    return DONE.sub("done in (time), data in (folder)", line.rstrip())


def run(build, command, key_numbers, ran=None):
    """The program's stdout lines; its key numbers are appended to the list `key_numbers`.
    With `ran` (the folder a fixture ran exactly this command into), that run's."""
    args = shlex.split(command)
    program = args[0]
    if ran is not None:
        ran = pathlib.Path(ran)
        stdout, keys = pathlib.Path(str(ran) + ".stdout"), ran / "key_numbers.json"
        if not stdout.is_file() or not keys.is_file():
            sys.exit("%s: the fixture's run is missing (%s, %s)" % (command, stdout, keys))
        key_numbers.append({k: v["value"] for k, v in json.loads(keys.read_text()).items()})
        return [DONE.sub(lambda m: m.group(0).split(", data in ")[0] + ", data in build/data/" + program, l)
                for l in stdout.read_text().splitlines()]
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / program
        p = subprocess.run([str(build / "bin" / program)] + args[1:] + ["--out", str(out)],
                           capture_output=True, text=True, timeout=600, cwd=ROOT)
        if p.returncode != 0:
            sys.exit("%s exited %d: %s" % (command, p.returncode, p.stderr.strip()[-500:]))
        key_numbers.append({k: v["value"] for k, v in json.loads((out / "key_numbers.json").read_text()).items()})
    # the folder a reader's own run writes to (the program's default)
    return [DONE.sub(lambda m: m.group(0).split(", data in ")[0] + ", data in build/data/" + program, l)
            for l in p.stdout.splitlines()]


def fill_keys(text, key_numbers, readme, check):
    """Key-number markers filled from key_numbers (one dict per console block, in order);
    returns (text, number of differences)."""
    differ = 0
    merged = {}
    for k in key_numbers:
        merged.update(k)

    def value(m):
        nonlocal differ
        name, block, factor, fmt, old = m.group(1), m.group(2), float(m.group(3) or 1), m.group(4), m.group(5)
        source = merged if block is None else (key_numbers[int(block) - 1] if 0 < int(block) <= len(key_numbers) else {})
        if name not in source:
            sys.exit("%s: key number '%s' is not in the run's key_numbers.json" % (readme, m.group(0)[:60]))
        new = fmt % (source[name] * factor)
        if check and new != old:
            differ += 1
            print("%s: key number %s\n  README:  %s\n  program: %s" % (readme, name, old, new))
        return m.group(0).replace("-->" + old + "<!--", "-->" + new + "<!--")
    return KEY.sub(value, text), differ


def main():
    mode, build, rest = sys.argv[1], pathlib.Path(sys.argv[2]).resolve(), sys.argv[3:]
    if mode not in ("--check", "--write"):
        sys.exit(__doc__)
    readmes, ran = [], {}
    while rest:
        if rest[0] == "--ran" and len(rest) >= 3:
            ran[rest[1]] = rest[2]
            rest = rest[3:]
        elif rest[0] == "--ran":
            sys.exit(__doc__)
        else:
            readmes.append(rest.pop(0))
    failures = 0
    for readme in map(pathlib.Path, readmes):
        text = readme.read_text()
        blocks = list(MARK.finditer(text))
        if not blocks:
            if mode == "--check":
                sys.exit("%s: no console block" % readme)
            print("%s: no console block" % readme)
            continue
        pieces, last, key_numbers = [], 0, []
        for m in blocks:
            lines = run(build, m.group(1), key_numbers, ran.get(m.group(1)))
            quoted = [l for l in m.group(2).splitlines() if not l.startswith("```")]
            if mode == "--check":
                old, new = [normalised(l) for l in quoted], [normalised(l) for l in lines]
                for i in range(max(len(old), len(new))):
                    a = old[i] if i < len(old) else "(no line)"
                    b = new[i] if i < len(new) else "(no line)"
                    if a != b:
                        failures += 1
                        print("%s: '%s' line %d\n  README:  %s\n  program: %s" % (readme, m.group(1), i + 1, a, b))
            pieces += [text[last:m.start()], "<!-- console: %s -->\n```\n%s\n```\n<!-- end console -->\n"
                       % (m.group(1), "\n".join(lines))]
            last = m.end()
        pieces.append(text[last:])
        for command in set(ran) - {m.group(1) for m in blocks}:
            failures += 1
            print("%s: no console block runs '%s' (--ran)" % (readme, command))
        text, differ = fill_keys("".join(pieces), key_numbers, readme, mode == "--check")
        failures += differ
        if mode == "--write":
            readme.write_text(text)
            print("%s: %d console block(s) written" % (readme, len(blocks)))
        else:
            print("%s: %d console block(s) checked" % (readme, len(blocks)))
    print("%d differ" % failures)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
