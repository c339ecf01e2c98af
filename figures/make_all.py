#!/usr/bin/env python3
"""Run every chapter program and draw every thesis figure (`make figures`).

For each chapter program build/bin/chNN_name:
  1. run it:  build/bin/chNN_name --out build/data/chNN_name   (two programs at a time)
  2. draw:    figures/chNN_name.py  (its draw(data_dir, fig_dir) function)
Figures land in build/figures/figNN_*.png, named after the thesis figure number.
Then, if build/bin/gearhb_gear exists, every gear-pair example of
programs/gearhb_gear/examples/ is run into build/data/gearhb_gear/<example>/ (the program
draws its own figures there) and its figures are copied to
build/figures/gear_<example>_<figure>.png, and figures/gear_methods.py draws the FE / beam /
potential-energy comparison from those folders (build/figures/gear_methods*.png),
figures/tooth_model_chart.py the tooth models' error against cost
(build/figures/gear_tooth_models.png, build/data/gearhb_gear/tooth_models/tooth_models.csv) and
figures/gear_models.py the one-DOF against six-DOF comparison (build/figures/gear_models.png),
figures/helical_ste.py the STE peak-to-peak of a helical pair against its helix angle
(build/figures/gear_helical_ste.png, build/data/gearhb_gear/helical_ste/helical_ste.csv);
then every example of programs/gearhb_frc/examples/ into build/data/gearhb_frc/<example>/
(figures copied to build/figures/frc_<example>_*.png), and every example of
programs/gearhb_planetary/examples/ into
build/data/gearhb_planetary/<example>/ (figures copied to build/figures/planetary_<example>_*.png);
build/figures/index.html (figures/report.py)
links them all. build/figures/timings.csv records each step's wall time of this run (the only
timings the READMEs point to; `make bench` measures the library's).
"""
import argparse
import concurrent.futures
import importlib.util
import pathlib
import shutil
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def run_examples(program, prefix, build, fig_dir, timings):
    """Run every example of programs/<program>/examples/ into build/data/<program>/<example>/ (the
    program draws its own figures there) and copy them to build/figures/<prefix>_<example>_*.png."""
    for example in sorted((HERE.parent / "programs" / program.name / "examples").glob("*.json")):
        out = build / "data" / program.name / example.stem
        print("[figures] %s %s --out %s" % (program, example.name, out), flush=True)
        t0 = time.time()
        subprocess.run([str(program), str(example), "--quiet", "--out", str(out)], check=True)
        timings.append(("%s %s" % (program.name, example.stem), time.time() - t0))
        for png in sorted(out.glob("*.png")):
            shutil.copy(png, fig_dir / ("%s_%s_%s" % (prefix, example.stem, png.name)))


def arguments():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--build", default="build")
    ap.add_argument("--only", help="run just this chapter (e.g. ch03_mass_wall)")
    ap.add_argument("--jobs", type=int, default=2, help="chapter programs run at once")
    ap.add_argument("--values", choices=("exact", "hb"), default="exact",
                    help="frequency responses drawn from the exact orbit where the table has it (default) "
                         "or from harmonic balance")
    return ap.parse_args()


def run_chapters(chapters, build, fig_dir, jobs, timings):
    """The chapter programs, two at a time (the machine has two cores; each program is
    single-threaded); each chapter's figures are drawn as soon as its data is there."""
    def run(exe):
        t0 = time.time()
        data_dir = build / "data" / exe.name
        print("[figures] %s --out %s" % (exe, data_dir), flush=True)
        subprocess.run([str(exe), "--quiet", "--out", str(data_dir)], check=True)
        return exe, data_dir, time.time() - t0

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for fut in concurrent.futures.as_completed([pool.submit(run, exe) for exe in chapters]):
            exe, data_dir, secs = fut.result()
            script = HERE / (exe.name + ".py")
            if not script.exists():
                print("[figures]   (no figure script %s)" % script.name)
                continue
            spec = importlib.util.spec_from_file_location(exe.name, script)
            mod = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(mod)
            made = mod.draw(data_dir, fig_dir)
            timings.append((exe.name, secs))
            print("[figures]   %s: data in %.1f s, %d figures" % (exe.name, secs, len(made)), flush=True)


def run_gear_pairs(gear, build, fig_dir, timings):
    """Every gear-pair example, then the comparisons drawn from their folders or run on their own."""
    run_examples(gear, "gear", build, fig_dir, timings)
    import gear_methods        # FE / beam / potential energy side by side
    import gear_models         # one DOF against six
    import helical_ste         # a helical pair's STE peak-to-peak against its helix angle
    import tooth_model_chart   # which tooth model a scene needs: error against cost (FE at five sizes)
    data = build / "data" / "gearhb_gear"
    made = gear_methods.draw(data, fig_dir)
    t0 = time.time()
    made += tooth_model_chart.draw(gear, data / "tooth_models", fig_dir)
    timings.append(("tooth_model_chart", time.time() - t0))
    made += helical_ste.draw(gear, data / "helical_ste", fig_dir)
    made += gear_models.draw(data, fig_dir)
    for png in made:
        print("[figures]   %s" % png, flush=True)


def main():
    args = arguments()
    import style
    style.VALUES = args.values
    build = pathlib.Path(args.build).resolve()
    fig_dir = build / "figures"
    fig_dir.mkdir(parents=True, exist_ok=True)
    chapters = sorted(p for p in (build / "bin").glob("ch[0-9][0-9]_*") if p.is_file())
    if args.only:
        chapters = [p for p in chapters if p.name == args.only]
    if not chapters:
        sys.exit("no chapter programs in %s/bin: run `make build` first" % build)
    timings = [("make_figures_start", 0.0)]
    start = time.time()
    run_chapters(chapters, build, fig_dir, args.jobs, timings)
    tools = {name: build / "bin" / name for name in ("gearhb_gear", "gearhb_frc", "gearhb_planetary")}
    if not args.only:
        if tools["gearhb_gear"].is_file():
            run_gear_pairs(tools["gearhb_gear"], build, fig_dir, timings)
        for name, prefix in (("gearhb_frc", "frc"), ("gearhb_planetary", "planetary")):
            if tools[name].is_file():
                run_examples(tools[name], prefix, build, fig_dir, timings)
    timings[0] = ("make_figures_total", time.time() - start)
    with open(fig_dir / "timings.csv", "w") as f:
        f.write("step,wall_s\n" + "".join("%s,%.1f\n" % t for t in timings))
    import report
    print("[figures] report: %s" % report.write(build))

if __name__ == "__main__":
    main()
