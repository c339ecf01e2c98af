#!/usr/bin/env python3
"""A long run is never silent (issue 32 item 10): progress_lines.py SECONDS MAX_GAP -- PROGRAM ARGS...

Runs PROGRAM ARGS for SECONDS (then kills it, its process group with it), reading its stdout
and stderr as they come, and fails if any stretch of MAX_GAP seconds passes without a line
(from the start to the first line, between two lines, or from the last line to the end of
the window), or if the program exits before the window ends with a status other than 0. The
cases are in-range inputs measured at a minute or more (tests/CMakeLists.txt), so the window
sees their long steps: the continuation, the Floquet stability of each point, the
bifurcation trials, the tables and the time-integration check all report through
Run::progress (at most a line a second).
"""
import os
import selectors
import signal
import subprocess
import sys
import time


def main():
    seconds, max_gap = float(sys.argv[1]), float(sys.argv[2])
    command = sys.argv[sys.argv.index("--") + 1:]
    start = time.monotonic()
    p = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    sel = selectors.DefaultSelector()
    for stream in (p.stdout, p.stderr):
        os.set_blocking(stream.fileno(), False)
        sel.register(stream, selectors.EVENT_READ)
    last, gaps, lines, tail = start, [], 0, {p.stdout: b"", p.stderr: b""}
    while time.monotonic() - start < seconds and sel.get_map():
        for key, _ in sel.select(timeout=0.2):
            data = key.fileobj.read()
            if not data:
                sel.unregister(key.fileobj)
                continue
            now = time.monotonic()
            n = data.count(b"\n")
            if n:
                gaps.append(now - last)
                last, lines = now, lines + n
            tail[key.fileobj] = (tail[key.fileobj] + data)[-400:]
    ended = p.poll() is not None or not sel.get_map()
    if not ended:
        os.killpg(p.pid, signal.SIGKILL)
    code = p.wait()
    end = time.monotonic()
    gaps.append(min(end, start + seconds) - last)
    worst = max(gaps)
    print("%d lines in %.1f s, longest silence %.1f s (limit %.0f s), %s" % (
        lines, end - start, worst, max_gap, "exit %d" % code if ended else "killed at the end of the window"))
    if ended and code != 0:
        print("FAIL: exit %d; stderr tail: %r" % (code, tail[p.stderr]))
        return 1
    if worst > max_gap:
        print("FAIL: silent for %.1f s" % worst)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
