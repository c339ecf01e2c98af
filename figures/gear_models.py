#!/usr/bin/env python3
"""One DOF or six? The thesis gear at 300 N m and the light-load relieved gear at 20 N m, each
with chapter 8's torsional model (rigid bearings) and with the gear centres on bearings
(k_b = 1e8 N/m, 2.8 kg per gear): gear_models.py DATA FIGURES

DATA is build/data/gearhb_gear (make_all.py runs every example there); draws
FIGURES/gear_models.png and prints the README table (peak DTE RMS, peak K_v, first back
impact, sweep time per curve from timings.csv).
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

from style import COMPARISON_COLOURS, plot_branch, read_csv, save  # noqa: E402

SCENES = [("thesis gear, 300 N m", "thesis_pair", 3), ("relieved gear, light load 20 N m", "thesis_pair_light_load", 1)]
# Models, not torques: comparison colours (style.py), never a torque colour.
MODELS = [("one DOF (rigid bearings)", "", COMPARISON_COLOURS[0]),
          ("six DOFs (bearings 1e8 N/m)", "_six_dof", COMPARISON_COLOURS[1])]


def load(data, example, i):
    d = data / example
    kn = {k: v["value"] for k, v in __import__("json").load(open(d / "key_numbers.json")).items()}
    t = read_csv(d / "timings.csv")
    sweeps = [t["seconds"][k] for k, s in enumerate(t["step"]) if s.startswith("sweep ")]   # one per torque, in order
    modes = read_csv(d / "modes.csv")
    f = [modes["f_hz"][k] for k in range(len(modes["f_hz"])) if int(modes["torque_index"][k]) == i]
    return read_csv(d / ("frc_%d.csv" % i)), kn, sweeps[i - 1], f


def draw(data, fig_dir):
    fig, axes = plt.subplots(2, 2, figsize=(11.5, 7.4))
    rows = []
    for r, (scene, example, i) in enumerate(SCENES):
        for name, suffix, colour in MODELS:
            frc, kn, sweep_s, modes = load(data, example + suffix, i)
            for c, (y, scale) in enumerate((("x_rms_ac", 1e6), ("dynamic_factor", 1.0))):
                plot_branch(axes[r][c], frc, y=y, x="speed_rpm", color=colour, scale=scale)
            rows.append((scene, name, kn["dte_rms_peak_um_%d" % i], kn["dynamic_factor_peak_%d" % i],
                         kn.get("back_impact_first_f_mesh_hz_%d" % i), sweep_s, len(frc["omega"]), modes))
        axes[r][0].set_ylabel("%s\nDTE RMS [um]" % scene)
        axes[r][1].set_ylabel("K_v = max |mesh force| / F0")
    for ax in axes[1]:
        ax.set_xlabel("speed of gear 1 [rpm]")
    for ax in axes.flat:
        ax.set_ylim(bottom=0)
    handles = [Line2D([], [], color=c, label=n) for n, _, c in MODELS]
    handles += [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
                Line2D([], [], color="k", ls="--", label="unstable (Floquet)")]
    axes[1][1].legend(handles=handles, fontsize=7, loc="upper left")
    fig.suptitle("Is the torsional model enough? One DOF against six (x, y, theta per gear on bearings)", fontsize=10)
    out = save(fig, fig_dir / "gear_models.png")
    print("| scene | model | peak DTE RMS [um] | peak K_v | first back impact [mesh Hz] | sweep [s] | points |")
    print("|---|---|---|---|---|---|---|")
    for scene, name, rms, kv, back, sec, pts, _ in rows:
        print("| %s | %s | %.3f | %.3f | %s | %.2f | %d |" % (scene, name, rms, kv, "%.0f" % back if back else "none",
                                                             sec, pts))
    return [out]


if __name__ == "__main__":
    draw(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]))
