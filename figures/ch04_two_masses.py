"""Figures 20-23 of thesis ch. 4 (two masses that can touch) from build/data/ch04_two_masses.

Left panel: the relative displacement d = x1 - x2 (the quantity the contact sees),
its maximum and minimum over a period, with the contact level d = -g. Right panel:
the first-harmonic amplitude of each mass, which shows that the masses themselves
resonate at sqrt(k/m) in phase (a motion the contact never feels).
"""
import math

import matplotlib.pyplot as plt

from style import (CONTACT_LEVEL, NATURAL_CLOSED, NATURAL_OPEN, case_rows, contact_rug, legend_styles, plot_branch,
                   read_csv, read_params, rug_room, save)


def natural_frequencies(data_dir):
    m = read_csv(data_dir / "modes.csv")
    return {st: sorted({round(w, 9) for s, w in zip(m["state"], m["omega"]) if s == st})
            for st in ("open", "closed")}


def frequency_window(p, wn):
    """The run's frequency range (params.json) zoomed on the natural frequencies, where
    everything happens: from 0.72 x the lowest to 1.13 x the highest, widened to a round
    step (a tenth of the window's decade), inside the range."""
    ws = wn["open"] + wn["closed"]
    lo, hi = 0.72 * min(ws), 1.13 * max(ws)
    step = 10 ** math.floor(math.log10(hi - lo)) / 10
    lo, hi = round(math.floor(lo / step) * step, 12), round(math.ceil(hi / step) * step, 12)
    return max(p["omega_min"], lo), min(p["omega_max"], hi)


def frequency_axis(ax, wn, p):
    """Natural-frequency reference lines (style.NATURAL_OPEN / NATURAL_CLOSED) and the zoomed w axis."""
    for w in wn["open"]:
        ax.axvline(w, **NATURAL_OPEN)
    for w in wn["closed"]:
        ax.axvline(w, **NATURAL_CLOSED)
    ax.set_xlim(*frequency_window(p, wn))
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s] (zoom; data %g-%g)" % (p["omega_min"], p["omega_max"]))


def draw_one(data_dir, fig_dir, fig, stem, gap, wn, p):
    d = read_csv(data_dir / ("frc_%s.csv" % stem))
    fig_, (a1, a2) = plt.subplots(1, 2, figsize=(10.5, 4.0))
    plot_branch(a1, d, "x_max", "C0", r"$d_{max}$ (upper), $d_{min}$ (lower)")
    plot_branch(a1, d, "x_min", "C0")
    contact_rug(a1, d)
    lo, hi = min(d["x_min"]), max(d["x_max"])
    span = hi - lo
    level = -gap
    visible = lo - span <= level <= hi + span   # is the contact level worth drawing?
    if visible:
        a1.axhline(level, **dict(CONTACT_LEVEL, label="contact level d = -g = %g m" % level))
    title = "Fig. %s: relative motion, g = %g m" % (fig, gap)
    if not visible:
        title += "\n(contact level d = -g = %g m is far %s: the masses never %s)" % (
            level, "above" if level > hi else "below", "touch" if level > hi else "separate")
    frequency_axis(a1, wn, p)
    a1.set_ylabel(r"relative displacement $d = x_1 - x_2$ [m]")
    a1.set_title(title)
    from matplotlib.lines import Line2D
    h, _ = a1.get_legend_handles_labels()
    h += [Line2D([], [], **NATURAL_OPEN, label=r"open $\omega_n$ = %s rad/s" %
                 ", ".join("%.4g" % w for w in wn["open"])),
          Line2D([], [], **NATURAL_CLOSED, label=r"closed $\omega_n$ = %s rad/s" %
                 ", ".join("%.4g" % w for w in wn["closed"]))]
    a1.legend(handles=h + legend_styles(a1), fontsize=7, loc="upper left", framealpha=0.9)
    top, bottom = (max(hi, level), min(lo, level)) if visible else (hi, lo)
    a1.set_ylim(bottom - 0.1 * (top - bottom), top + 0.9 * (top - bottom))
    rug_room(a1)

    for name, c in (("x1", "C0"), ("x2", "C1")):
        e = read_csv(data_dir / ("frc_%s_%s.csv" % (stem, name)))
        plot_branch(a2, e, "x_h1", c, "mass %s" % name[1])
    frequency_axis(a2, wn, p)
    a2.set_ylabel("first-harmonic amplitude of each mass [m]")
    a2.set_title("each mass on the same branch (the in-phase mode at sqrt(k/m)\ndoes not strain the contact)",
                 fontsize=9)
    a2.legend(fontsize=8, loc="upper right")
    return save(fig_, fig_dir / ("fig%s_two_masses_g%s.png" % (fig, ("%g" % gap))))


def draw(data_dir, fig_dir):
    wn = natural_frequencies(data_dir)
    p = read_params(data_dir)
    return [draw_one(data_dir, fig_dir, "%d" % r["figure"], label, r["gap"], wn, p)
            for label, r in case_rows(data_dir).items()]
