#!/usr/bin/env python3
"""Hostile inputs that once crashed or misled a program, each ending as the contract says.

    reliability.py BIN_DIR SOURCE_DIR WORK_DIR

The contract (README "Running a chapter"): bad input is one line on stderr and exit
status 2, a solver failure one line and exit 1, nothing written in either case (no
output folder, no staging folder); no input crashes. Each case below is a reproducer
from a re-audit of the programs: a non-finite value inside the numerics (a denormal
mass), an output path with shell metacharacters, deeply nested or duplicate-key JSON,
a device as an input file, a value with a newline, and messages that must name the key.
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys

BIN, SRC, WORK = (pathlib.Path(p).resolve() for p in sys.argv[1:4])
EXAMPLES = SRC / "chapters" / "gearhb_frc" / "examples"
failures = []


def run(args, out, cwd=None, timeout=120):
    staging = out.parent / ("." + out.name + ".staging")
    shutil.rmtree(out, ignore_errors=True)
    shutil.rmtree(staging, ignore_errors=True)
    cmd = [str(BIN / args[0])] + [str(a) for a in args[1:]] + ["--quiet", "--out", str(out)]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=cwd)
    return p, staging


def case(name, args, status, says=(), says_not=(), cwd=None):
    """Run `args`; expect exit `status` with one stderr line containing each of `says`."""
    out = WORK / name
    p, staging = run(args, out, cwd)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    what = "%s (%s)" % (name, " ".join(map(str, args)))
    if p.returncode != status:
        failures.append("%s: exit %d, expected %d: %s" % (what, p.returncode, status, p.stderr.strip()[-300:]))
        return p
    if status != 0:
        if len(lines) != 1:
            failures.append("%s: %d lines on stderr, expected 1: %r" % (what, len(lines), p.stderr))
        if out.exists() or staging.exists():
            failures.append("%s: exit %d but something was written" % (what, status))
        for s in says:
            if s not in p.stderr:
                failures.append("%s: message does not say %r: %s" % (what, s, p.stderr.strip()))
        for s in says_not:
            if s in p.stderr:
                failures.append("%s: message says %r: %s" % (what, s, p.stderr.strip()))
    print("ok %-34s exit %d %s" % (name, p.returncode, (lines[0] if lines else "")[:150]))
    return p


def model(name, change):
    """A copy of two_masses.json with `change` applied to its JSON text or object."""
    m = json.loads((EXAMPLES / "two_masses.json").read_text())
    text = change(m) if callable(change) else change
    path = WORK / (name + ".json")
    path.write_text(text if isinstance(text, str) else json.dumps(m))
    return path


shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
two = EXAMPLES / "two_masses.json"

# 1. A non-finite value inside the numerics (a denormal mass): exit 1 or 2, never a crash.
for prog, sets in [("ch03_mass_wall", ["H=5", "m=4.9e-324"]),
                   ("ch05_comparin_singh", ["H=5", "m1=4.9e-324"]),
                   ("ch08_gear_response", ["H=3", "I2=1e-320"]),
                   ("ch09_backlash", ["H=3", "I1=2.2250738585072014e-308"])]:
    args = [prog, "--case", "own"] + sum((["--set", s] for s in sets), [])
    p = case("denormal_" + prog, args, 2, says=[sets[1].split("=")[0]])
case("frc_stiffness_-1e30", ["gearhb_frc", two, "--set", "stiffness.0.0=-1e30"], 1)

# 2. No shell: an output path with quotes, ';', $() and blanks is a path, nothing more.
shell_dir = WORK / "shell"
shell_dir.mkdir()
for weird in ["o'; touch INJECTED; echo '", 'o"; touch INJECTED; echo "', "o $(touch INJECTED) `touch INJECTED`"]:
    out = shell_dir / weird
    p, staging = run(["gearhb_frc", EXAMPLES / "mass_wall.json"], out, cwd=shell_dir)
    if p.returncode != 0 or not (out / "frc.csv").exists():
        failures.append("shell path %r: exit %d: %s" % (weird, p.returncode, p.stderr.strip()))
    if list(shell_dir.rglob("INJECTED")) or pathlib.Path("INJECTED").exists():
        failures.append("shell path %r: a command in the path ran (INJECTED exists)" % weird)
    if shutil.which("/usr/bin/python3") and not (out / "frc.png").exists():
        failures.append("shell path %r: frc.png not drawn" % weird)
    print("ok shell path %r: exit %d, no INJECTED" % (weird, p.returncode))

# 3. Deep nesting: refused with one line, not a stack overflow.
deep = WORK / "deep.json"
deep.write_text('{"name": "deep", "mass": ' + "[" * 1000000 + "]" * 1000000 + "}")
case("nested_1e6", ["gearhb_frc", deep], 2, says=["nested deeper"])

# 5. A solver that fails is exit 1 with its reason, no placeholder in any file; a range
# beyond the model's numbers is refused by name.
case("frc_omega_to_1e308", ["gearhb_frc", EXAMPLES / "mass_wall.json", "--set", "omega.to=1e308"], 2,
     says=["omega.to"])
case("frc_omega_to_1e100", ["gearhb_frc", EXAMPLES / "mass_wall.json", "--set", "omega.to=1e100"], 1,
     says=["did not reach omega.to"])
# A sweep that cannot start (K = 0, the static load pressing a flank of stiffness 0: no
# equilibrium, no periodic solution) says so: exit 1, nothing written.
case("frc_cannot_start", ["gearhb_frc", EXAMPLES / "clearance_oscillator.json", "--set", "contacts.0.kc=0"], 1,
     says=["cannot start", "no static equilibrium"])

# 6. Bad model input names the key or the path, exit 2.
for label, value in [("number", 5), ("null", None), ("object", {}), ("array", [])]:
    case("name_" + label, ["gearhb_frc", model("name_" + label, lambda m, v=value: m.update(name=v))], 2,
         says=["'name'"])
case("model_is_folder", ["gearhb_frc", WORK], 2, says=["folder"])
case("mass_1e-320", ["gearhb_frc", two, "--set", "mass.0.0=1e-320"], 2, says=["mass.0.0"])

# 7. Unbounded input: a device as a gap file, a newline in a value, a key twice.
def gap_file(path):
    def change(m):
        m["contacts"][0]["gap_file"] = str(path)
    return change
case("gap_file_dev_zero", ["gearhb_frc", model("dev_zero", gap_file("/dev/zero"))], 2,
     says=["gap_file", "not a regular file"])
case("newline_in_value", ["ch03_mass_wall", "--case", "own", "--set", "gap=1\n2"], 2, says=["\\n"])
case("duplicate_key", ["gearhb_frc", model("duplicate", '{"name": "a", "name": "b"}')], 2, says=["twice"])

# 8.-10. Messages that give the real reason and name the parameter.
case("backlash_0", ["ch09_backlash", "--case", "own", "--set", "backlash_um=0"], 1,
     says=["mesh stiffness F / STE does not exist"], says_not=["outside 1e-150"])
case("ch09_I1_denormal", ["ch09_backlash", "--set", "I1=4.9e-324"], 2, says=["I1"])
case("direction_1.8e308", ["gearhb_frc", two, "--set", "contacts.0.direction.0=1.7e308"], 2,
     says=["contacts.0.direction.0"])
case("stiffness_1.8e308", ["gearhb_frc", two, "--set", "stiffness.0.0=1.7e308"], 2, says=["stiffness.0.0"])
case("H_too_large", ["ch03_mass_wall", "--case", "own", "--set", "H=2147483648"], 2, says=["too large"])
case("ste_file_names_key", ["ch08_gear_response", "--case", "own", "--set", "ste_file=/dev/zero"], 2,
     says=["ste_file"])
case("too_many_dofs", ["gearhb_frc", model("dofs", lambda m: m.update(
    mass=[[1.0 if r == c else 0.0 for c in range(1366)] for r in range(1366)]))], 2, says=["too many"])

# A CRLF gap file is read like an LF one.
crlf = WORK / "gap_crlf.csv"
crlf.write_bytes(b"phase,gap\r\n" + b"".join(b"%.6f,%.3e\r\n" % (i / 64, 1e-3) for i in range(64)))
case("gap_file_crlf", ["gearhb_frc", model("crlf", gap_file(crlf)), "--set", "plot=0"], 0)

for f in failures:
    print("FAIL " + f)
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
