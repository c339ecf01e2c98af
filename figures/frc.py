#!/usr/bin/env python3
"""Draw DIR/frc.png for a gearhb_frc run: frc.py DIR

The output coordinate's x_max (upper) and x_min (lower) against omega, solid where
stable and dashed where unstable, contact state marked, bifurcations (if the run
wrote bifurcations.csv) marked with a legend; the title is the model's name and
harmonics (from params.json, the resolved model)."""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

from style import legend_styles, mark_contact, plot_branch, read_csv, save  # noqa: E402

MARKERS = {"fold": ("o", "C3"), "period_doubling": ("D", "C4"), "neimark_sacker": ("^", "C2")}


def main():
    d_dir = pathlib.Path(sys.argv[1])
    model = json.load(open(d_dir / "params.json"))
    d = read_csv(d_dir / "frc.csv")
    fig, ax = plt.subplots(figsize=(6.8, 4.6))
    plot_branch(ax, d, "x_max", "C0", r"$x_{max}$ (upper), $x_{min}$ (lower)")
    plot_branch(ax, d, "x_min", "C0")
    mark_contact(ax, d, "x_max", "C0")
    bif = d_dir / "bifurcations.csv"
    if bif.exists() and bif.read_text().count("\n") > 1:
        b = read_csv(bif)
        for kind, (m, c) in MARKERS.items():
            w = [b["omega"][i] for i in range(len(b["omega"])) if b["type"][i] == kind]
            if w:
                ys = []
                for wi in w:
                    j = min(range(len(d["omega"])), key=lambda k: abs(d["omega"][k] - wi))
                    ys.append(d["x_max"][j])
                ax.plot(w, ys, ls="none", marker=m, color=c, mfc="none", ms=8, label=kind.replace("_", " "))
    direction = model["output"]["direction"]
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    ax.set_ylabel("output q'x, q = %s [m]" % direction)
    ax.set_title("%s\nH = %d, %g to %g rad/s" % (model.get("name", "model"), model["harmonics"],
                                                  model["omega"]["from"], model["omega"]["to"]), fontsize=9)
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + legend_styles(ax), fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14),
              ncol=3, frameon=False)
    save(fig, d_dir / "frc.png")


if __name__ == "__main__":
    main()
