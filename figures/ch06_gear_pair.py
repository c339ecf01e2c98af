"""Figures 40-45 of thesis ch. 6 (6-DOF gear pair) from build/data/ch06_gear_pair.

Every curve of the run's case table (cases.csv) becomes one figure; titles come from
the table (figure, Fi, Fa, kc). Plotted coordinate: the mesh deflection Delta = T2 q.
Upper panel: Delta_max and Delta_min over a period with the contact level Delta = 0
(teeth touch where Delta > 0) and the bifurcations found on the curve. Lower panel:
the oscillating amplitude (Delta_max - Delta_min)/2 beside the linear open /
closed-mesh amplitudes. Dotted verticals: linear natural frequencies.
"""
import math

from style import case_rows, column, plot_branch, read_csv, runs, save

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

MARKERS = {"fold": ("o", "k"), "branch_point": ("D", "C4"), "period_doubling": ("v", "C3"),
           "neimark_sacker": ("*", "C2")}


def shade_intermittent(ax, d):
    """Light band over every omega span where the mesh opens and closes within a period."""
    flags = [c == "intermittent" for c in d["contact"]]
    for flag, i0, i1 in runs(flags):
        if flag:
            ax.axvspan(min(d["w_k"][i0:i1 + 1]), max(d["w_k"][i0:i1 + 1]), color="gold", alpha=0.25, lw=0)


def modes(data_dir, mesh):
    d = read_csv(data_dir / "modes.csv")
    idx = [i for i in range(len(d["mesh"])) if d["mesh"][i] == mesh]
    return sorted(set(round(d["omega_open"][i], 3) for i in idx)), sorted(set(round(d["omega_closed"][i], 3) for i in idx))


def mark_bifurcations(ax, data_dir, label, d):
    """Period doublings, Neimark-Sacker points and branch points on the Delta_max curve."""
    b = read_csv(data_dir / ("bifurcations_%s.csv" % label))
    used = []
    for t, w, located, smooth in zip(b["type"], b["omega"], b["located"], b["smooth"]):
        if t == "fold" or not (located and smooth):
            continue   # folds show as turning points; jumps and unlocated changes are only in the csv
        # the Delta_max value at the nearest point of the branch
        i = min(range(len(d["omega"])), key=lambda j: abs(d["omega"][j] - w))
        m, c = MARKERS[t]
        y = column(d, "x_max")[i]
        y = d["x_max"][i] if math.isnan(y) else y   # no exact value there: the HB one
        ax.plot(w / 1e3, y * 1e3, ls="none", marker=m, color=c, ms=6, mfc="none", mew=1.2)
        used.append(t)
    return sorted(set(used))


def case_figure(data_dir, fig_dir, row, name):
    label, mesh = row["label"], row["mesh"]
    d = read_csv(data_dir / ("frc_%s.csv" % label))
    lin = read_csv(data_dir / ("linear_%s.csv" % mesh))
    w_open, w_closed = modes(data_dir, mesh)
    d["w_k"] = [w / 1e3 for w in d["omega"]]
    d["amp"] = [(a - b) / 2 for a, b in zip(d["x_max"], d["x_min"])]
    if "x_max_exact" in d:
        d["amp_exact"] = [(a - b) / 2 for a, b in zip(d["x_max_exact"], d["x_min_exact"])]
    fig_, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 7.2), sharex=True)
    plot_branch(a1, d, "x_max", "C0", r"$\Delta_{max}$", x="w_k", scale=1e3)
    plot_branch(a1, d, "x_min", "C1", r"$\Delta_{min}$", x="w_k", scale=1e3)
    shade_intermittent(a1, d)
    kinds = mark_bifurcations(a1, data_dir, label, d)
    a1.axhline(0.0, color="k", lw=1.0, ls=":")
    a1.annotate(r"contact level $\Delta$ = 0 (teeth touch above)", (0.99, 0.0), xycoords=("axes fraction", "data"),
                fontsize=7, xytext=(0, -9), textcoords="offset points", ha="right")
    a1.set_ylabel(r"mesh deflection $\Delta$ [mm]")
    a1.set_title("Fig. %d: $F_i$ = %g N m, F = %g [1,0,1,1,0,1] N, N m, $k_c$ = %g N/m"
                 % (int(row["figure"]), row["Fi"], row["Fa"], row["kc"]), fontsize=9)
    h, _ = a1.get_legend_handles_labels()
    extra = [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
             Line2D([], [], color="k", ls="--", label="unstable (Floquet)"),
             Patch(color="gold", alpha=0.25, label="intermittent contact")]
    extra += [Line2D([], [], ls="none", marker=MARKERS[k][0], color=MARKERS[k][1], mfc="none",
                     label=k.replace("_", " ")) for k in kinds]
    a1.legend(handles=h + extra, fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.02),
              framealpha=0.9)
    plot_branch(a2, d, "amp", "C2", r"$(\Delta_{max} - \Delta_{min})/2$", x="w_k", scale=1e3)
    shade_intermittent(a2, d)
    s = row["Fa"] / 1e4   # linear_*.csv is for Fa = 1e4
    a2.semilogy([w / 1e3 for w in lin["omega"]], [v * s * 1e3 for v in lin["delta_open"]], color="0.5", lw=0.9,
                ls="-.", label="linear, mesh open")
    a2.semilogy([w / 1e3 for w in lin["omega"]], [v * s * 1e3 for v in lin["delta_closed"]], color="C3", lw=0.9,
                ls="-.", label="linear, mesh closed")
    for ax in (a1, a2):
        for w in w_open:
            ax.axvline(w / 1e3, color="0.6", ls=":", lw=0.8)
        for w in w_closed:
            ax.axvline(w / 1e3, color="C3", ls=":", lw=0.8)
    a2.set_ylabel(r"oscillating amplitude of $\Delta$ [mm]")
    a2.set_xlabel(r"forcing frequency $\omega$ [krad/s]   (dotted: natural frequencies, grey open, red closed mesh)",
                  fontsize=8)
    a2.legend(fontsize=7, loc="upper right", framealpha=0.9)
    fig_.subplots_adjust(hspace=0.32)
    return save(fig_, fig_dir / name)


def power_of_ten(v):
    """1e5 -> "1e5", -1e8 -> "-1e8" (file names)."""
    return ("%.0e" % v).replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")


def draw(data_dir, fig_dir):
    out = []
    for label, row in case_rows(data_dir).items():
        tag = power_of_ten(row["Fi"]) + ("" if row["Fa"] == 1e4 else "_F" + power_of_ten(row["Fa"]))
        if row["mesh"] == "kc":
            name = "fig%d_gearpair_Fi%s.png" % (int(row["figure"]), tag)
        else:
            name = "figS%d_ch06_kc_alt.png" % int(row["figure"])
        out.append(case_figure(data_dir, fig_dir, row, name))
    if (data_dir / "period2_fig43.csv").exists():
        out.append(period_doubling_figure(data_dir, fig_dir))
    return out


def period_doubling_figure(data_dir, fig_dir):
    """Supplement: the period-2 orbit GSL finds beyond Fig. 43's first period doubling."""
    import json
    d = read_csv(data_dir / "period2_fig43.csv")
    with open(data_dir / "key_numbers.json") as f:
        key = {k: v["value"] for k, v in json.load(f).items()}
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    ax.plot(d["periods"], [v * 1e3 for v in d["delta_time_integration"]], color="C0", lw=1.4,
            label="GSL rk8pd after %d periods: period 2" % 3000)
    ax.plot(d["periods"], [v * 1e3 for v in d["delta_hb_period_one"]], color="C1", lw=1.0, ls="--",
            label=r"harmonic balance: period-1 orbit (unstable, $\mu$ = %.3f)" % key["period2_multiplier_fig43"])
    for p in range(1, 4):
        ax.axvline(p, color="0.6", ls=":", lw=0.8)
    ax.axhline(0.0, color="k", lw=1.0, ls=":")
    ax.set_xlabel(r"time [forcing periods $2\pi/\omega$]")
    ax.set_ylabel(r"mesh deflection $\Delta$ [mm]")
    ax.set_title(r"Beyond Fig. 43's period doubling: $\omega$ = %.1f rad/s, $F_i$ = -1e6 N m, F = 1e4 (H = 16)"
                 % key["period2_omega_fig43"], fontsize=9)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, framealpha=0.9)
    return save(fig, fig_dir / "figS46_ch06_period_doubling.png")
