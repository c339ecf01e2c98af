"""Figures 40-45 of thesis ch. 6 (6-DOF gear pair) from build/data/ch06_gear_pair.

Plotted coordinate: the mesh deflection Delta = T2 q (the thesis' relative motion
Delta = delta1 - delta2). Upper panel: Delta_max and Delta_min over a period, with the
contact level Delta = 0 (teeth touch where Delta > 0). Lower panel: the oscillating
amplitude (Delta_max - Delta_min)/2 beside the linear open / closed-mesh amplitudes.
Dotted verticals: linear natural frequencies (open grey, closed-mesh red).
"""
from style import plot_branch, read_csv, runs, save

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch


def shade_intermittent(ax, d):
    """Light band over every omega span where the mesh opens and closes within a period."""
    flags = [c == "intermittent" for c in d["contact"]]
    for flag, i0, i1 in runs(flags):
        if flag:
            ax.axvspan(min(d["w_k"][i0:i1 + 1]), max(d["w_k"][i0:i1 + 1]), color="gold", alpha=0.25, lw=0)

CASES = [(40, 1e5, 1e4, "transitions expected"), (41, 1e7, 1e4, "text: stays in full contact"),
         (42, -1e8, 1e4, "text: stays open"), (43, -1e6, 1e4, "transitions expected"),
         (44, 1e7, 1e6, "larger forcing: toward opening"), (45, -1e8, 1e6, "larger forcing: toward contact")]


def kc_tag(kc):
    s = "%g" % kc
    return s.replace("+", "")


def modes(data_dir, kc):
    d = read_csv(data_dir / "modes.csv")
    idx = [i for i in range(len(d["kc"])) if abs(d["kc"][i] - kc) <= 1e-9 * kc]
    return sorted(set(round(d["omega_open"][i], 3) for i in idx)), sorted(set(round(d["omega_closed"][i], 3) for i in idx))


def case_figure(data_dir, fig_dir, fig, Fi, Fa, note, kc, name):
    d = read_csv(data_dir / ("frc_fig%d_kc%s.csv" % (fig, kc_tag(kc))))
    lin = read_csv(data_dir / ("linear_kc%s.csv" % kc_tag(kc)))
    w_open, w_closed = modes(data_dir, kc)
    d["w_k"] = [w / 1e3 for w in d["omega"]]
    d["amp"] = [(a - b) / 2 for a, b in zip(d["x_max"], d["x_min"])]
    # dashed where Hill OR the Floquet multipliers (GSL monodromy) call the orbit unstable
    d["stable"] = [min(a, b) for a, b in zip(d["stable"], d["stable_floquet"])]
    fig_, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 7.0), sharex=True)
    plot_branch(a1, d, "x_max", "C0", r"$\Delta_{max}$", x="w_k", scale=1e3)
    plot_branch(a1, d, "x_min", "C1", r"$\Delta_{min}$", x="w_k", scale=1e3)
    shade_intermittent(a1, d)
    a1.axhline(0.0, color="k", lw=1.0, ls=":")
    a1.annotate(r"contact level $\Delta$ = 0 (teeth touch above)", (0.01, 0.0), xycoords=("axes fraction", "data"),
                fontsize=7, xytext=(0, 3), textcoords="offset points")
    a1.set_ylabel(r"mesh deflection $\Delta$ [mm]")
    a1.set_title("Fig. %d: $F_i$ = %g N m, F = %g [1,0,1,1,0,1], $k_c$ = %g N/m (%s)" % (fig, Fi, Fa, kc, note),
                 fontsize=9)
    h, _ = a1.get_legend_handles_labels()
    extra = [Line2D([], [], color="k", ls="-", label="stable"),
             Line2D([], [], color="k", ls="--", label="unstable (Hill or Floquet)"),
             Patch(color="gold", alpha=0.25, label="intermittent contact")]
    a1.legend(handles=h + extra, fontsize=7, ncol=3, loc="best", framealpha=0.9)
    plot_branch(a2, d, "amp", "C2", r"HB: $(\Delta_{max} - \Delta_{min})/2$", x="w_k", scale=1e3)
    shade_intermittent(a2, d)
    s = Fa / 1e4
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
    a2.legend(fontsize=7, loc="lower right", framealpha=0.9)
    return save(fig_, fig_dir / name)


def draw(data_dir, fig_dir):
    out = []
    cases = read_csv(data_dir / "cases.csv")
    kcs = sorted(set(cases["kc"]), reverse=True)
    kc = cases["kc"][0]   # the default kc comes first
    names = {40: "gearpair_Fi1e5", 41: "gearpair_Fi1e7", 42: "gearpair_Fi-1e8", 43: "gearpair_Fi-1e6",
             44: "gearpair_Fi1e7_F1e6", 45: "gearpair_Fi-1e8_F1e6"}
    for fig, Fi, Fa, note in CASES:
        out.append(case_figure(data_dir, fig_dir, fig, Fi, Fa, note, kc, "fig%02d_%s.png" % (fig, names[fig])))
    # Supplement: the other kc, same cases (the kc study of the README)
    other = [k for k in kcs if k != kc]
    if other:
        k2 = other[0]
        for fig, Fi, Fa, note in CASES:
            out.append(case_figure(data_dir, fig_dir, fig, Fi, Fa, note, k2,
                                   "figS%d_ch06_kc%s.png" % (fig, kc_tag(k2))))
    return out
