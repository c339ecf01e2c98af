"""Figures 25-30 of thesis ch. 5 (Comparin & Singh impact pair) from build/data/ch05_comparin_singh.

Each figure: the relative displacement delta = x1 - x2 (x_max upper curve, x_min lower curve)
of the harmonic-balance solution for the two gaps of that thesis figure, the contact level
delta = -g (the bodies touch when delta > -g), the open and closed natural frequencies, and
in the title the prediction of the analytic regime classifier for each gap.
Which cases form a figure, their loads and the plotted ranges come from the run
(cases.csv, params.json).
"""
import math

import matplotlib.pyplot as plt

from style import (CONTACT_LEVEL, NATURAL_CLOSED, NATURAL_OPEN, case_rows, contact_rug, legend_styles, plot_branch,
                   read_csv, read_params, rug_room, save)


def figures(rows):
    """The thesis figures of the run in table order: [(number, [labels of its gaps])]."""
    out = {}
    for label, r in rows.items():
        out.setdefault(int(r["figure"]), []).append(label)
    return list(out.items())


def short_name(rows, labels, base):
    """File name part: what the figure varies against the first figure's loading
    (force amplitude Fa_1, mean force F0), then its gaps (m = minus, p = plus)."""
    r = rows[labels[0]]
    topic = ("force_" if r["Fa_1"] != base["Fa_1"] else "") + ("mean_" if r["F0"] != base["F0"] else "")
    gaps = "_".join(("m%g" % -rows[lb]["gap"]) if rows[lb]["gap"] < 0 else ("p%g" % rows[lb]["gap"]) for lb in labels)
    return topic + "gap_" + gaps


def zoom_window(r):
    """The predicted intermittent band widened by 3.5 band widths on each side (to show the
    folds of the overhang beside it), rounded outward to the band's decade."""
    lo, hi = r["intermittent_from"], r["intermittent_to"]
    lo, hi = lo - 3.5 * (hi - lo), hi + 3.5 * (hi - lo)
    step = 10 ** math.floor(math.log10(hi - lo))
    return round(math.floor(lo / step) * step, 12), round(math.ceil(hi / step) * step, 12)


def draw_case(ax, d, color, text, row=0):
    plot_branch(ax, d, "x_max", color, text)
    plot_branch(ax, d, "x_min", color)
    contact_rug(ax, d, row=row, colour=color)


def frc_figure(data_dir, fig_dir, num, short, labels, cases, omega_open, omega_closed, p):
    rows = [cases[lb] for lb in labels]
    has_zoom = any(r["intermittent_from"] == r["intermittent_from"] for r in rows)
    if has_zoom:
        fig, (ax, axz) = plt.subplots(1, 2, figsize=(10.5, 5.0), gridspec_kw={"width_ratios": [2, 1]})
    else:
        fig, ax = plt.subplots(figsize=(7.2, 5.0))
    title = ["Fig. %d: $F_0$ = %g N, $F_{a,1}$ = %g N (HB, H = %d)" % (num, rows[0]["F0"], rows[0]["Fa_1"], p["H"])]
    zoom = None
    for n, (lb, r) in enumerate(zip(labels, rows)):
        d = read_csv(data_dir / ("frc_%s.csv" % lb))
        c = "C%d" % n
        g = r["gap"]
        draw_case(ax, d, c, r"g = %g m: $\delta_{max}$ (upper), $\delta_{min}$ (lower)" % g, row=n)
        ax.axhline(-g, **dict(CONTACT_LEVEL, color=c))
        x_text = p["omega_min"] + (p["omega_max"] - p["omega_min"]) / 75
        ax.annotate(r"contact level $\delta = -g$ = %g m (in contact above)" % -g, (x_text, -g), color=c,
                    fontsize=7, xytext=(0, 3), textcoords="offset points")
        title.append("g = %g m, predicted: %s" % (g, r["prediction"].replace("W", r"$\Omega$")))
        if r["intermittent_from"] == r["intermittent_from"]:  # not NaN: zoom on the contact change
            zoom = (d, c, g, r)
    d0, d1 = (read_csv(data_dir / ("frc_%s.csv" % lb)) for lb in labels)
    if len(d0["x_max"]) == len(d1["x_max"]) and max(abs(a - b) for a, b in zip(d0["x_max"], d1["x_max"])) < 1e-9:
        # halfway between the top of the curves and the lowest contact level: clear of both
        y = 0.5 * (max(d0["x_max"]) + min(-r["gap"] for r in rows))
        ax.annotate("the two curves coincide: without contact (type 1) the response\n"
                    "does not depend on g (both gaps are never reached)" if rows[0]["gap"] < 0 else
                    "the two curves differ only by a shift", (0.03, y), xycoords=("axes fraction", "data"),
                    va="center", fontsize=8)
    for w, name, look in ((omega_open, "open", NATURAL_OPEN), (omega_closed, "closed", NATURAL_CLOSED)):
        ax.axvline(w, **look)
        ax.annotate(r"$\omega_{%s}$ = %.3f" % (name, w), (w, 0.12), xycoords=("data", "axes fraction"),
                    fontsize=7, rotation=90, xytext=(2, 0), textcoords="offset points", color="0.35")
    ax.set_xlim(p["omega_min"], p["omega_max"])
    rug_room(ax, len(labels))
    ax.set_xlabel(r"forcing frequency $\Omega$ [rad/s]")
    ax.set_ylabel(r"relative displacement $\delta = x_1 - x_2$ [m]")
    ax.set_title("\n".join(title), fontsize=8.5)
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + legend_styles(), loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, fontsize=7,
              frameon=False)   # below the axes: never over a curve
    if zoom is not None:
        d, c, g, r = zoom
        draw_case(axz, d, c, None)
        axz.axhline(-g, **dict(CONTACT_LEVEL, color=c, label=r"contact level $\delta = -g$"))
        axz.axvspan(r["intermittent_from"], r["intermittent_to"], color="0.85", zorder=0,
                    label="predicted intermittent\n(no linear solution valid)")
        axz.axvline(omega_closed, **NATURAL_CLOSED)
        axz.set_xlim(*zoom_window(r))
        rug_room(axz)
        axz.set_xlabel(r"$\Omega$ [rad/s] (zoom)")
        axz.set_ylabel(r"$\delta$ [m]")
        axz.set_title("zoom, g = %g m: outside the grey band the\nlinear full-contact solution coexists" % g,
                      fontsize=8.5)
        axz.legend(loc="center right", fontsize=7, framealpha=0.95)
    return save(fig, fig_dir / ("fig%02d_comparin_singh_%s.png" % (num, short)))


def validation_map(data_dir, fig_dir, k):
    """k: the spring between the masses [N/m], for the static penetration s = g + F0/k."""
    v = read_csv(data_dir / "classifier_validation.csv")
    fig, axes = plt.subplots(2, 2, figsize=(9.5, 7.0), sharex=True)
    style = {"type1_open": ("C0", "o", "type 1 predicted (never in contact)"),
             "type2_full": ("C2", "s", "type 2 predicted (always in contact)"),
             "intermittent": ("C3", "D", "intermittent predicted")}
    combos = sorted(set(zip(v["F0"], v["Fa_1"])))   # the grid's (F0, Fa_1) pairs
    for ax, (F0, Fa_1) in zip(axes.flat, combos):
        idx = [i for i in range(len(v["F0"])) if v["F0"][i] == F0 and v["Fa_1"][i] == Fa_1]
        levels = sorted(set(round(v["gap"][i] + F0 / k, 9) for i in idx))
        row = {lv: j for j, lv in enumerate(levels)}   # one row per static penetration s (evenly spaced rows)
        for key, (c, m, lab) in style.items():
            pts = [(v["omega"][i], row[round(v["gap"][i] + F0 / k, 9)]) for i in idx if v["prediction"][i] == key]
            if pts:
                ax.plot(*zip(*pts), ls="none", marker=m, color=c, ms=4, label=lab)
        co = [(v["omega"][i], row[round(v["gap"][i] + F0 / k, 9)]) for i in idx if v["verdict"][i] == "agree_coexisting"]
        if co:
            ax.plot(*zip(*co), ls="none", marker="o", mfc="none", mec="k", ms=9,
                    label="agrees, + coexisting intermittent HB solutions")
        bad = [(v["omega"][i], row[round(v["gap"][i] + F0 / k, 9)]) for i in idx if v["verdict"][i] in ("disagree", "no_solution")]
        if bad:
            ax.plot(*zip(*bad), ls="none", marker="x", color="m", ms=10, mew=2, label="disagrees")
        ax.axhline(sum(1 for lv in levels if lv < 0) - 0.5, color="0.5", lw=0.8)
        ax.set_yticks(range(len(levels)))
        ax.set_yticklabels(["%g" % lv for lv in levels], fontsize=7)
        ax.set_title(r"$F_0$ = %g N, $F_{a,1}$ = %g N" % (F0, Fa_1))
        ax.set_ylabel(r"$s = g + F_0/k$ [m]")
    for ax in axes[1]:
        ax.set_xlabel(r"$\Omega$ [rad/s]")
    n = len(v["F0"])
    agree = sum(1 for x in v["verdict"] if x == "agree")
    co = sum(1 for x in v["verdict"] if x == "agree_coexisting")
    dis = n - agree - co
    fig.suptitle("Supplement: classifier vs every harmonic-balance solution at each grid point\n"
                 "rows: static penetration with the contact open, s = g + F0/k (s < 0: type 1 candidate, s > 0: type 2)\n"
                 "%d points: %d agree, %d agree with a coexisting intermittent solution, %d disagree"
                 % (n, agree, co, dis), fontsize=10)
    h, lab = axes[0, 0].get_legend_handles_labels()
    for ax in axes.flat[1:]:
        for hh, ll in zip(*ax.get_legend_handles_labels()):
            if ll not in lab:
                h.append(hh)
                lab.append(ll)
    fig.legend(h, lab, loc="lower center", ncol=2, fontsize=8)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(fig_dir / "figS2_ch05_classifier_validation.png")
    plt.close(fig)
    return str(fig_dir / "figS2_ch05_classifier_validation.png")


def draw(data_dir, fig_dir):
    cases = case_rows(data_dir)
    p = read_params(data_dir)
    import json
    key = json.load(open(data_dir / "key_numbers.json"))
    wo, wc = key["omega_open"]["value"], key["omega_closed"]["value"]
    figs = figures(cases)
    base = cases[figs[0][1][0]]
    out = [frc_figure(data_dir, fig_dir, num, short_name(cases, labels, base), labels, cases, wo, wc, p)
           for num, labels in figs]
    out.append(validation_map(data_dir, fig_dir, p["k"]))
    return out
