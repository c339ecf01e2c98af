#!/usr/bin/env python3
"""Run every chapter program and draw every thesis figure (`make figures`).

For each chapter program build/bin/chNN_name:
  1. run it:  build/bin/chNN_name --out build/data/chNN_name
  2. draw:    figures/chNN_name.py  (its draw(data_dir, fig_dir) function)
Figures land in build/figures/figNN_*.png, named after the thesis figure number.
"""
import argparse
import importlib.util
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--build", default="build")
    ap.add_argument("--only", help="run just this chapter (e.g. ch03_mass_wall)")
    args = ap.parse_args()
    build = pathlib.Path(args.build).resolve()
    fig_dir = build / "figures"
    fig_dir.mkdir(parents=True, exist_ok=True)
    chapters = sorted(p for p in (build / "bin").glob("ch[0-9][0-9]_*") if p.is_file())
    if args.only:
        chapters = [p for p in chapters if p.name == args.only]
    if not chapters:
        sys.exit("no chapter programs in %s/bin: run `make build` first" % build)
    for exe in chapters:
        data_dir = build / "data" / exe.name
        t0 = time.time()
        print("[figures] %s --out %s" % (exe, data_dir), flush=True)
        subprocess.run([str(exe), "--out", str(data_dir)], check=True)
        script = HERE / (exe.name + ".py")
        if not script.exists():
            print("[figures]   (no figure script %s)" % script.name)
            continue
        spec = importlib.util.spec_from_file_location(exe.name, script)
        mod = importlib.util.module_from_spec(spec)
        sys.path.insert(0, str(HERE))
        spec.loader.exec_module(mod)
        made = mod.draw(data_dir, fig_dir)
        for f in made:
            print("[figures]   wrote %s" % f)
        print("[figures]   %s done in %.1f s" % (exe.name, time.time() - t0), flush=True)
    import report
    print("[figures] report: %s" % report.write(build))


if __name__ == "__main__":
    main()
