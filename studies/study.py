#!/usr/bin/env python3
"""Design studies of gear pairs (issue 24): many gearhb_gear runs described by one study file.

    study.py check  STUDY.json                          validate; print the number of designs
    study.py run    DESIGN_DIR GEARHB BASE LIMIT DESIGN run one design (DESIGN: its JSON, LIMIT: seconds);
                                                        always writes DESIGN_DIR/status.json, exit 0
    study.py gather STUDY.json OUT                      OUT/table.csv: one row per design (axes, status, key numbers)
    study.py maps   STUDY.json OUT                      OUT/maps.png and OUT/best.txt from the table

The workflow engine is Snakemake (studies/Snakefile): it runs `run` for every design, on the
cores of one machine or as Slurm jobs, resumes an interrupted study and reruns nothing that is
done. This file holds no scheduler: only the study's meaning.

A study file (JSON):
    {"name": "tip relief",                       (optional: printable text, at most 200 characters)
     "base": "programs/gearhb_gear/examples/thesis_pair_relief.json",   (relative to the study file)
     "axes": [ {"path": "gears.0.tip_relief.amount", "grid": {"from": 0, "to": 30e-6, "points": 41}},
               {"path": "gears.0.tip_relief.start.length", "values": [6.684e-3, 8.856e-3]},
               {"path": "torques.0", "random": {"from": 100, "to": 300, "samples": 5, "seed": 1}} ],
     "same": [["gears.1.tip_relief.amount", "gears.0.tip_relief.amount"]],  (set equal to an axis)
     "set":  {"plot": 0},                                                   (fixed overrides)
     "maps": ["ste_ptp_um_1", "dynamic_factor_peak_1"],    (key numbers mapped by study_maps.py)
     "time_limit_s": 600}          (optional: seconds one design may run, > 0, at most 86400; default 600)
Designs are the product of the axes (at most 1e6; an axis at most 1e5 values). A path is the
gear file's keys and list indices joined by dots (letters, digits, _). `base` must resolve
(symlinks followed) to a regular .json file holding a JSON object. The study file and the base
are read like the programs read their files: at most 16 MiB of UTF-8, nested at most 32 levels,
no key twice in one object.

A design's folder is named by the first 12 hex digits of the SHA-256 of the base path and its
resolved overrides (sorted JSON), so the same design always lands in the same folder and a rerun
finds it done; the time limit is not part of it (changing it redoes nothing).

Contract. A bad study: one line `study: '<key>' <why>` on stderr (the key escaped to printable
text), exit 2, nothing written. `run` records ANY failure of a design (the program refused it,
crashed, was killed by a signal, exceeded the time limit, could not start, or the design's JSON
is unreadable) as status "failed" with a one-line reason (the program's last stderr line, bytes
that are not UTF-8 escaped as \\xff) and exits 0, so the study goes on; on the time limit it
kills the program's whole process group. Only an interrupted study (SIGINT, SIGTERM, SIGHUP:
the program is killed with it) leaves no status, so that a resumed study redoes the design.
`gather` makes a design whose status.json or key_numbers.json is missing or unreadable a
failed row with the reason. Any other error: one line, exit 1, no traceback.
"""
import collections
import csv
import ctypes
import hashlib
import itertools
import json
import math
import os
import pathlib
import random
import re
import signal
import stat
import subprocess
import sys
import tempfile
import time

MAX_FILE_BYTES = 16 << 20          # the programs' limit for an input file
MAX_DEPTH = 32                     # the programs' limit for nesting
MAX_DESIGNS = 1000000
MAX_AXIS_VALUES = 100000
MAX_NAME_CHARS = 200
MAX_BASE_CHARS = 4096
MAX_REASON_CHARS = 500
DEFAULT_TIME_LIMIT_S = 600
MAX_TIME_LIMIT_S = 86400
KILL_GRACE_S = 2                   # from SIGTERM to SIGKILL on the time limit
STUDY_KEYS = ("name", "base", "axes", "same", "set", "maps", "time_limit_s")
PATH = re.compile(r"[A-Za-z0-9_]+(\.[A-Za-z0-9_]+)*")
NAME = re.compile(r"[A-Za-z0-9_]+")

Study = collections.namedtuple("Study", "name base axes same fixed maps time_limit_s")
Study.__doc__ = """A validated study: base (resolved path), axes [(path, values)], same [(path, axis
path)], fixed {path: number}, maps [key number], time_limit_s."""


class StudyError(Exception):
    """A bad study (or an unreadable file of one): str() is the one line `study: '<key>' <why>`."""

    def __init__(self, key, why):
        super().__init__(key, why)
        self.key, self.why = key, why

    def __str__(self):
        return "study: '%s' %s" % (self.key, self.why)


class Interrupted(BaseException):
    """The study was stopped (SIGTERM, SIGHUP): the design ends without a status."""


def escaped(text, limit=MAX_REASON_CHARS):
    """text as one printable line of valid UTF-8: every character that is not printable (line
    breaks, control characters, a lone surrogate such as \\udc80) as its Python escape, and at
    most `limit` characters of the text ('...' marks a cut)."""
    cut = text[:limit]
    out = "".join(c if c.isprintable() else ascii(c)[1:-1] for c in cut)
    return out + ("..." if len(text) > limit else "")


def fail(key, why):
    raise StudyError(escaped(key, MAX_NAME_CHARS), escaped(why))


# ---- reading a JSON file as the programs do ----------------------------------------------------

def read_bytes(path, key):
    """The bytes of a regular file of at most MAX_FILE_BYTES. The file is checked after it is
    opened (fstat), so what is checked is what is read; O_NONBLOCK: opening a FIFO does not hang."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as e:
        fail(key, "cannot be opened (%s: %s)" % (path, e.strerror))
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            fail(key, "is not a regular file (%s)" % path)
        chunks, size = [], 0
        while size <= MAX_FILE_BYTES:
            chunk = os.read(fd, MAX_FILE_BYTES + 1 - size)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as e:
        fail(key, "cannot be read (%s: %s)" % (path, e.strerror))
    finally:
        os.close(fd)
    if size > MAX_FILE_BYTES:
        fail(key, "is larger than 16 MiB (%s)" % path)
    return b"".join(chunks)


def depth(value):
    """Levels of nesting of a parsed JSON value (a number or a text: 0), without recursion."""
    deepest, todo = 0, [(value, 1)]
    while todo:
        v, level = todo.pop()
        if isinstance(v, (dict, list)):
            deepest = max(deepest, level)
            todo.extend((child, level + 1) for child in (v.values() if isinstance(v, dict) else v))
    return deepest


def read_json(path, key):
    """The JSON value of a file: at most 16 MiB of UTF-8, nested at most 32 levels, no key twice in
    one object. Every error is a StudyError naming `key` (the key that names the file)."""
    data = read_bytes(path, key)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        fail(key, "is not UTF-8 text (byte %d of %s)" % (e.start, path))

    def unique(pairs):
        obj = {}
        for k, v in pairs:
            if k in obj:
                fail(key, "has the key '%s' twice in one object" % escaped(k, MAX_NAME_CHARS))
            obj[k] = v
        return obj

    try:
        value = json.loads(text, object_pairs_hook=unique)
    except RecursionError:
        fail(key, "is nested deeper than %d levels" % MAX_DEPTH)
    except ValueError as e:
        fail(key, "is not valid JSON (%s)" % e)
    if depth(value) > MAX_DEPTH:
        fail(key, "is nested deeper than %d levels" % MAX_DEPTH)
    return value


# ---- validating a study ------------------------------------------------------------------------

def number(v, key):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or v != v or abs(v) > 1e150:
        fail(key, "must be a finite number")
    return float(v)


def whole(v, key, lo, hi):
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        fail(key, "must be a whole number in %d..%d" % (lo, hi))
    return v


def dotted_path(v, key):
    if not isinstance(v, str) or len(v) > MAX_NAME_CHARS or not PATH.fullmatch(v):
        fail(key, "must be a dotted path of the gear file's keys and indices (letters, digits, _; "
                  "e.g. gears.0.tip_relief.amount)")
    return v


def only_keys(obj, where, allowed):
    for k in obj:
        if k not in allowed:
            fail(where + k, "is not a key here (%s)" % ", ".join(allowed))


def axis(a, k):
    """(path, values) of the study's axis k."""
    key = "axes.%d" % k
    if not isinstance(a, dict):
        fail(key, "must be an object {path, and one of values, grid, random}")
    only_keys(a, key + ".", ("path", "values", "grid", "random"))
    path = dotted_path(a.get("path"), key + ".path")
    kinds = [x for x in ("values", "grid", "random") if x in a]
    if len(kinds) != 1:
        fail(key, "needs exactly one of values, grid, random")
    kind, spec = kinds[0], a[kinds[0]]
    key += "." + kind
    if kind == "values":
        if not isinstance(spec, list) or not 1 <= len(spec) <= MAX_AXIS_VALUES:
            fail(key, "must be a list of 1..%d numbers" % MAX_AXIS_VALUES)
        return path, [number(v, "%s.%d" % (key, i)) for i, v in enumerate(spec)]
    if not isinstance(spec, dict):
        fail(key, "must be an object")
    count_key = "points" if kind == "grid" else "samples"
    only_keys(spec, key + ".", ("from", "to", count_key) + (("seed",) if kind == "random" else ()))
    lo, hi = number(spec.get("from"), key + ".from"), number(spec.get("to"), key + ".to")
    n = whole(spec.get(count_key), key + "." + count_key, 1, MAX_AXIS_VALUES)
    if kind == "grid":
        return path, ([lo + (hi - lo) * i / (n - 1) for i in range(n)] if n > 1 else [lo])
    rng = random.Random(whole(spec.get("seed", 0), key + ".seed", -2 ** 31, 2 ** 31 - 1))
    return path, [lo + (hi - lo) * rng.random() for _ in range(n)]


def name_text(v):
    if v is not None and (not isinstance(v, str) or len(v) > MAX_NAME_CHARS or not v.isprintable()):
        fail("name", "must be printable text of at most %d characters" % MAX_NAME_CHARS)
    return v


def base_file(v, folder):
    """The gear file: resolved (symlinks followed) to a regular .json file holding a JSON object."""
    if not isinstance(v, str) or not v or len(v) > MAX_BASE_CHARS or not v.isprintable():
        fail("base", "must be the gear file's path (printable text)")
    path = (folder / v).resolve()
    if path.suffix != ".json":
        fail("base", "must name a .json gear file (%s)" % path)
    if not isinstance(read_json(path, "base"), dict):
        fail("base", "must hold a JSON object, a gear file (%s)" % path)
    return path


def time_limit(v):
    if v is None:
        return float(DEFAULT_TIME_LIMIT_S)
    t = number(v, "time_limit_s")
    if not 0 < t <= MAX_TIME_LIMIT_S:
        fail("time_limit_s", "must be seconds, > 0 and at most %d" % MAX_TIME_LIMIT_S)
    return t


def same_pairs(same, axis_paths):
    if not isinstance(same, list):
        fail("same", "must be a list of [path, axis path] pairs")
    pairs = []
    for k, pair in enumerate(same):
        key = "same.%d" % k
        if not isinstance(pair, list) or len(pair) != 2:
            fail(key, "must be a [path, axis path] pair")
        dst, src = dotted_path(pair[0], key + ".0"), dotted_path(pair[1], key + ".1")
        if src not in axis_paths:
            fail(key + ".1", "copies '%s', which is not an axis" % src)
        if dst in axis_paths or dst in [p for p, _ in pairs]:
            fail(key + ".0", "sets '%s', which an axis or another pair sets already" % dst)
        pairs.append((dst, src))
    return pairs


def fixed_numbers(fixed, taken):
    if not isinstance(fixed, dict):
        fail("set", "must be an object of path: number")
    for p, v in fixed.items():
        dotted_path(p, "set." + p)
        if p in taken:
            fail("set." + p, "is set by an axis or by same already")
        number(v, "set." + p)
    return {p: float(v) for p, v in fixed.items()}


def map_names(maps):
    if not isinstance(maps, list) or len(maps) > 100:
        fail("maps", "must be a list of at most 100 key-number names")
    for k, m in enumerate(maps):
        if not isinstance(m, str) or len(m) > MAX_NAME_CHARS or not NAME.fullmatch(m):
            fail("maps.%d" % k, "must be a key number's name (letters, digits, _)")
    return maps


def count(axes):
    """The number of designs, the product of the axis lengths (no design is made)."""
    return math.prod(len(v) for _, v in axes)


def load(study_path):
    """The study, validated (a Study); a bad one raises StudyError naming the key."""
    study_path = pathlib.Path(study_path)
    s = read_json(study_path, str(study_path))
    if not isinstance(s, dict):
        fail(str(study_path), "must hold a JSON object")
    only_keys(s, "", STUDY_KEYS)
    name = name_text(s.get("name"))
    base = base_file(s.get("base"), study_path.parent)
    limit = time_limit(s.get("time_limit_s"))
    axes = s.get("axes")
    if not isinstance(axes, list) or not axes:
        fail("axes", "must be a non-empty list")
    axes = [axis(a, k) for k, a in enumerate(axes)]
    paths = [p for p, _ in axes]
    for k, p in enumerate(paths):
        if p in paths[:k]:
            fail("axes.%d.path" % k, "names '%s', which axes.%d names already" % (p, paths.index(p)))
    same = same_pairs(s.get("same", []), paths)
    fixed = fixed_numbers(s.get("set", {}), set(paths) | {dst for dst, _ in same})
    maps = map_names(s.get("maps", []))
    if count(axes) > MAX_DESIGNS:
        fail("axes", "give %d designs; at most %d" % (count(axes), MAX_DESIGNS))
    return Study(name, base, axes, same, fixed, maps, limit)


def iter_designs(study):
    """(hash, {path: value} of the axes, [(path, value)] overrides) of every design, in the
    product's order, one at a time."""
    for combo in itertools.product(*[v for _, v in study.axes]):
        point = dict(zip([p for p, _ in study.axes], combo))
        overrides = dict(study.fixed)
        overrides.update(point)
        overrides.update({dst: point[src] for dst, src in study.same})
        text = json.dumps(sorted(overrides.items()), separators=(",", ":"))
        digest = hashlib.sha256((str(study.base) + text).encode()).hexdigest()[:12]
        yield digest, point, sorted(overrides.items())


def designs(study_path):
    """[(hash, point, overrides)] of every design of a study file."""
    return list(iter_designs(load(study_path)))


def design_json(point, overrides):
    """A design as `run` takes it (one line)."""
    return json.dumps({"axes": point, "overrides": overrides}, separators=(",", ":"))


# ---- running one design ------------------------------------------------------------------------

class DesignError(Exception):
    """A design that cannot run (its JSON or its time limit unreadable): a failed row."""


def parse_design(text):
    """(the design, its [(path, value)] overrides) from its JSON (design_json), or DesignError."""
    try:
        spec = json.loads(text)
        pairs = spec["overrides"]
        if not isinstance(spec.get("axes"), dict) or not all(
                isinstance(p, str) and PATH.fullmatch(p) and not isinstance(v, bool) and isinstance(v, (int, float))
                and math.isfinite(v) for p, v in pairs):
            raise ValueError("not a design")
        return spec, [(p, v) for p, v in pairs]
    except (ValueError, TypeError, KeyError, AttributeError) as e:
        raise DesignError("the design's overrides are unreadable (%s)" % e)


def parse_limit(text):
    try:
        t = float(text)
    except ValueError:
        t = math.nan
    if not 0 < t <= MAX_TIME_LIMIT_S:
        raise DesignError("time limit '%s' is not seconds in (0, %d]" % (text, MAX_TIME_LIMIT_S))
    return t


def die_with_parent():
    """A preexec_fn: the program gets SIGKILL when this process dies, even by SIGKILL (Linux
    PR_SET_PDEATHSIG). A killed study must leave no design running that a resumed study would
    start again into the same folder. None where prctl does not exist."""
    prctl = getattr(ctypes.CDLL(None, use_errno=True), "prctl", None)
    parent = os.getpid()
    if prctl is None:
        return None

    def preexec():
        prctl(1, int(signal.SIGKILL))   # 1: PR_SET_PDEATHSIG
        if os.getppid() != parent:      # this process died before prctl
            os._exit(1)
    return preexec


def signal_group(pgid, sig):
    try:
        os.killpg(pgid, sig)
    except ProcessLookupError:
        pass


def has_exited(pid):
    """Whether the child has exited, without reaping it (WNOWAIT): while it is unreaped its pid,
    the id of its process group, cannot be given to another process."""
    return os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None


def stop_group(proc):
    """SIGTERM to the program's whole process group, up to KILL_GRACE_S for the program to end,
    then SIGKILL to whatever of the group is left; then reap the program."""
    signal_group(proc.pid, signal.SIGTERM)
    deadline = time.monotonic() + KILL_GRACE_S
    while time.monotonic() < deadline and not has_exited(proc.pid):
        time.sleep(0.02)
    signal_group(proc.pid, signal.SIGKILL)
    proc.wait()


def run_program(args, stderr_file, limit):
    """(exit status, hit the time limit). The program runs in a session (and process group) of its
    own, so that on the time limit its whole group - any children it started too - is killed."""
    proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=stderr_file,
                            start_new_session=True, preexec_fn=die_with_parent())
    try:
        return proc.wait(timeout=limit), False
    except subprocess.TimeoutExpired:
        stop_group(proc)
        return proc.returncode, True
    except BaseException:   # interrupted: the program goes down with the study
        stop_group(proc)
        raise


def last_line(f):
    """The last non-blank line of the program's stderr (its last 64 KiB), one printable line of
    valid UTF-8: bytes that are not UTF-8 as \\xff."""
    f.seek(0, os.SEEK_END)
    f.seek(max(0, f.tell() - 65536))
    lines = [line.strip() for line in f.read().split(b"\n") if line.strip()]
    return escaped(lines[-1].decode("utf-8", "backslashreplace")) if lines else ""


def failed(reason, code=None):
    return {"status": "failed", "exit": code, "reason": escaped(reason)}


def signal_name(code):
    try:
        return "%s (%d)" % (signal.Signals(-code).name, -code)
    except ValueError:
        return str(-code)


def run_design(d, gearhb, base, limit_text, design_text):
    """The status of one design (ok, or failed with its reason)."""
    limit = parse_limit(limit_text)
    spec, overrides = parse_design(design_text)
    write_atomic(d / "overrides.json", json.dumps(spec, indent=1))
    args = [gearhb, str(base), "--quiet", "--out", str(d / "run")]
    for path, value in overrides:
        args += ["--set", "%s=%r" % (path, value)]
    try:
        with tempfile.TemporaryFile(dir=d) as err:
            code, timed_out = run_program(args, err, limit)
            reason = last_line(err)
    except OSError as e:
        raise DesignError("%s cannot run (%s)" % (gearhb, e.strerror or e))
    if timed_out:
        return failed("time limit (%g s)" % limit, code)
    if code < 0:
        return failed("killed by signal %s" % signal_name(code), code)
    if code != 0:
        return failed(reason or "exit %d" % code, code)
    if not (d / "run" / "key_numbers.json").is_file():
        return failed("exit 0 without run/key_numbers.json", code)
    return {"status": "ok", "exit": 0, "reason": ""}


def write_atomic(path, text):
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def on_signal(signum, frame):
    raise Interrupted(signum)


def run(design_dir, gearhb, base, limit_text, design_text):
    """One design into DESIGN_DIR (made here, when the design runs): status.json says ok or failed
    with a one-line reason, whatever went wrong. Only an interrupt leaves no status."""
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, on_signal)
    d = pathlib.Path(design_dir)
    d.mkdir(parents=True, exist_ok=True)
    try:
        status = run_design(d, gearhb, base, limit_text, design_text)
    except DesignError as e:
        status = failed(str(e))
    except Exception as e:   # any failure of the design is its row, never the end of the study
        status = failed("study.py run: %s: %s" % (type(e).__name__, e))
    write_atomic(d / "status.json", json.dumps(status))


# ---- the table ---------------------------------------------------------------------------------

def key_numbers(path):
    """{name: value} of a run's key_numbers.json ({name: {"value": number, ...}})."""
    kn = read_json(path, "run/key_numbers.json")
    if not isinstance(kn, dict):
        fail("run/key_numbers.json", "is not an object of key numbers")
    out = {}
    for k, v in kn.items():
        value = v.get("value") if isinstance(v, dict) else None
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            fail("run/key_numbers.json", "has no number for '%s'" % k)
        out[escaped(k, MAX_NAME_CHARS)] = value
    return out


def outcome(d):
    """(status, reason, {key number: value}) of one design's folder. A missing or unreadable
    status.json or key_numbers.json makes the design a failed row with the reason."""
    try:
        st = read_json(d / "status.json", "status.json")
        if not (isinstance(st, dict) and st.get("status") in ("ok", "failed") and isinstance(st.get("reason"), str)):
            fail("status.json", "is not a design's status")
        if st["status"] == "failed":
            return "failed", escaped(st["reason"]), {}
        return "ok", "", key_numbers(d / "run" / "key_numbers.json")
    except StudyError as e:
        return "failed", "%s %s" % (e.key, e.why), {}


def table_rows(study, out):
    rows, keys = [], []
    for h, point, _ in iter_designs(study):
        status, reason, numbers = outcome(out / "designs" / h)
        row = {"design": h}
        row.update(point)
        row.update({"status": status, "reason": reason})
        numbers = {k: v for k, v in numbers.items() if k not in row}   # a key number never hides a column
        row.update(numbers)
        keys += [k for k in numbers if k not in keys]
        rows.append(row)
    return rows, keys


def gather(study_path, out):
    study = load(study_path)
    out = pathlib.Path(out)
    rows, keys = table_rows(study, out)
    columns = ["design"] + [p for p, _ in study.axes] + ["status", "reason"] + keys
    tmp = out / "table.csv.tmp"
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=columns, restval="")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.17g" % v if isinstance(v, float) else v) for k, v in r.items()})
    tmp.replace(out / "table.csv")


# ---- the command line --------------------------------------------------------------------------

def command(argv):
    if len(argv) == 3 and argv[1] == "check":
        print("%d designs" % count(load(argv[2]).axes))
    elif len(argv) == 7 and argv[1] == "run":
        run(*argv[2:])
    elif len(argv) == 4 and argv[1] == "gather":
        gather(argv[2], argv[3])
    elif len(argv) == 4 and argv[1] == "maps":
        import study_maps
        study_maps.draw(argv[2], argv[3])
    else:
        sys.stderr.write(__doc__)
        return 2
    return 0


def main(argv):
    try:
        return command(argv)
    except StudyError as e:
        print(e, file=sys.stderr)
        return 2
    except (KeyboardInterrupt, Interrupted) as e:
        signum = e.args[0] if isinstance(e, Interrupted) else signal.SIGINT
        print("study: interrupted by %s" % signal.Signals(signum).name, file=sys.stderr)
        return 128 + signum
    except Exception as e:   # a bug or the system: still one line, no traceback
        print("study: %s: %s" % (type(e).__name__, escaped(str(e))), file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
