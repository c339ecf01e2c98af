#!/usr/bin/env python3
"""Draw DIR/frc.png for a gearhb_frc run: frc.py DIR

The output coordinate's x_max (upper) and x_min (lower) against omega, solid where
stable and dashed where unstable, contact state marked, bifurcations (if the run
wrote bifurcations.csv) marked with a legend; the title is the model's name and
harmonics (from params.json, the resolved model). Period-2 branches (rows with
period 2 in frc.csv, one per branch id) in their own colour (x_max and x_min over two
forcing periods); the contact rug and the bifurcation markers are those of the period-1
branch (branch 0) and of each period-2 branch on its own curve. A branch the run continued from a
time-integrated orbit of the diagram that lies on none of the others (key numbers orbit_branch_*)
in its own colour (style.plot_orbit_branches), thicker, its contact rug row and its section at
phase 0 under the Poincare points in that colour too. Torus branches (torus.csv,
gearhb_frc's torus key: quasi-periodic motion past a Neimark-Sacker point by two-frequency
harmonic balance) in black dash-dot (x_max and x_min over the torus), the points whose
stability the flow tested (torus.csv `stable`) filled where stable, open where unstable, grey
where unresolved, with a panel of their second frequency as the rotation omega2 / omega, the
Floquet value angle / 2 pi of each NS point marked. Where the run wrote bifurcation_diagram.csv (by
default every run with a range with no stable period-1 orbit, over a band around each), a panel of
its Poincare points under the response (the whole range) and bifurcation_diagram.png (the bands'
window; poincare.py), with the rows of sweep from_hb (the integration started on a stable HB orbit
that no sweep reached at its speed) as hollow diamonds in every panel, named in the legend and the
panel titles only where the run has such rows."""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

from style import (BIFURCATION_COLOURS, BIFURCATION_MARKERS, ORBIT_BRANCH_COLOUR, PERIOD2_COLOURS,  # noqa: E402
                   branch_ids, contact_rug, legend_styles, mark_unresolved_stable, orbit_branches, plot_branch,
                   plot_doubled_branches, plot_orbit_branches, read_csv, rows_of, rug_room, save,
                   shade_no_stable_period1, unresolved_period1_ranges, unstable_period1_ranges)
from poincare import (bands_text, draw_hb_section, draw_poincare, hb_starts_text, value_limits, window,  # noqa: E402
                      with_hb_starts, within)




def per_contact_state(d):
    """The contact rug from the state of each contact (columns contact_1, contact_2, ...):
    intermittent where some contact opens and closes within the period, full where none
    does and some contact stays closed. (The summary column `contact` calls a drive flank
    closed all period beside a back flank open all period "intermittent".)"""
    cols = sorted(k for k in d if k.startswith("contact_"))
    if not cols:
        return d
    states = []
    for i in range(len(d["omega"])):
        s = [d[c][i] for c in cols]
        states.append("intermittent" if "intermittent" in s else "full" if "full" in s else "open")
    return dict(d, contact=states)

def direction_text(q):
    """The output direction q for an axis label: its entries to 3 digits, or only its size when long."""
    if len(q) <= 4:
        return "[%s]" % ", ".join("%.3g" % v for v in q)
    return "output.direction (%d DOFs)" % len(q)


def save_whole(fig, path):
    """Save with the legends placed outside the axes inside the image (tight_layout does not see them)."""
    fig.tight_layout()
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)


def poincare_panel(ax, p, h, direction, sweeps=with_hb_starts(), title=None, orbit=()):
    """The diagram's Poincare points over the HB branch at phase 0, on ax (sweeps: which rows, by
    their sweep; orbit: the ids of the orbit branches); its legend handles."""
    handles = draw_hb_section(ax, h, "omega", "x", orbit=orbit) + draw_poincare(ax, p, "omega", "x", sweeps=sweeps)
    ax.set_ylabel("q'x at phase 0 of each\nforcing period [m]")
    if title:
        ax.set_title(title, fontsize=9)
    return handles


def diagram_figure(d_dir, model, p, h, orbit=()):
    """bifurcation_diagram.png: the up sweep above, the down sweep below."""
    fig, axes = plt.subplots(2, 1, figsize=(6.8, 6.8), sharex=True)
    lo, hi = window(p, "omega")
    ylim = value_limits(p, h, "omega", "x", lo, hi)
    h = within(h, "omega", lo, hi)
    labels = {}
    for ax, sweep in zip(axes, ("up", "down")):
        for hd in poincare_panel(ax, p, h, model["output"]["direction"], with_hb_starts((sweep,)),
                                 "sweep %s (each speed but its first from the previous speed's final state)%s"
                                 % (sweep, hb_starts_text(p)), orbit):
            labels.setdefault(hd.get_label(), hd)
    axes[-1].set_xlim(lo, hi)
    for ax in axes:
        ax.set_ylim(*ylim)
    axes[-1].set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    fig.suptitle("%s\nbifurcation diagram by time integration %s (Poincare section at phase 0)"
                 % (model.get("name", "model"), bands_text(p, "omega", "rad/s")), fontsize=9)
    axes[-1].legend(handles=list(labels.values()), fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2),
                    ncol=2, frameon=False)
    save_whole(fig, d_dir / "bifurcation_diagram.png")


def torus_panel(ax, t, b):
    """Rotation omega2 / omega of each torus branch; the NS points' Floquet angle / 2 pi."""
    for bid in sorted({int(x) for x in t["branch"]}):
        r = rows_of(t, bid)
        ax.plot(r["omega"], r["rotation"], "k-.", marker=".", ms=3, lw=1, label="torus branch %d (HB)" % bid)
    if b is not None:
        import math
        ns = [i for i, k in enumerate(b["type"]) if k == "neimark_sacker"]
        ax.plot([b["omega"][i] for i in ns],
                [abs(math.atan2(b["multiplier_im"][i], b["multiplier_re"][i])) / (2 * math.pi) for i in ns],
                ls="none", marker=BIFURCATION_MARKERS["neimark_sacker"], color=BIFURCATION_COLOURS["neimark_sacker"],
                mfc="none", ms=8, label="NS point: Floquet angle / 2 pi")
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    ax.set_ylabel(r"rotation $\omega_2 / \omega$")
    ax.set_title("second frequency on the torus", fontsize=9)
    ax.legend(fontsize=7, frameon=False, loc="upper center", bbox_to_anchor=(0.5, -0.16))


def no_stable_period1(d_dir, axes):
    """Shade the frequency ranges with no stable period-1 orbit (key numbers unstable_period1_*;
    where the run continued branches from the diagram's orbits, unstable_period1_*_all_branches: on
    none of its period-1 branches) on every panel, their stretches whose stability is unresolved
    hatched apart (unresolved_period1_*); the legend entries (none without such ranges)."""
    kn_file = d_dir / "key_numbers.json"
    kn = json.load(open(kn_file)) if kn_file.exists() else {}
    suffix = "_all_branches" if "unstable_period1_ranges_all_branches" in kn else ""
    return shade_no_stable_period1(axes, unstable_period1_ranges(kn, suffix),
                                   unresolved=unresolved_period1_ranges(kn, suffix))


def read_run(d_dir):
    """What the run wrote: the model, the response (every branch), the diagram, the torus, the
    bifurcations (None where not written)."""
    def table(name):
        f = d_dir / name
        return read_csv(f) if f.exists() and f.read_text().count("\n") > 1 else None
    r = {"model": json.load(open(d_dir / "params.json")), "full": table("frc.csv"), "torus": table("torus.csv"),
         "bif": table("bifurcations.csv"), "diagram": None, "diagram_hb": None}
    if table("bifurcation_diagram_hb.csv") is not None:
        r["diagram"], r["diagram_hb"] = table("bifurcation_diagram.csv"), table("bifurcation_diagram_hb.csv")
    kn_file = d_dir / "key_numbers.json"
    r["orbit"] = orbit_branches(json.load(open(kn_file)) if kn_file.exists() else {})
    r["orbit_ids"] = [bid for bid, _, _ in r["orbit"]]
    r["d"], r["ids"] = rows_of(r["full"], 0), [b for b in branch_ids(r["full"]) if b not in r["orbit_ids"]]
    return r


def layout(r):
    """The response (top left); the period-2 branches close up (right, if any); the torus'
    rotation (right, if any); the Poincare points of the diagram under the response (if any)."""
    rows = 2 if r["diagram"] is not None else 1
    cols = 1 + (1 if r["ids"] else 0) + (1 if r["torus"] is not None else 0)
    fig, grid = plt.subplots(rows, cols, squeeze=False, figsize=(6.8 + 3.6 * (cols - 1), 4.6 + 2.8 * (rows - 1)),
                             gridspec_kw={"width_ratios": [2, 1, 1][:cols], "height_ratios": [3, 2][:rows]})
    axes = {"main": grid[0][0], "closeup": grid[0][1] if r["ids"] else None,
            "torus": grid[0][cols - 1] if r["torus"] is not None else None,
            "poincare": grid[1][0] if rows == 2 else None}
    if axes["poincare"] is not None:
        axes["poincare"].sharex(axes["main"])
        for k in range(1, cols):
            grid[1][k].axis("off")
    return fig, axes


def period2_closeup(ins, full, d, ids):
    """x_min over the period-2 branches' range (where the two periods differ most), period 1 as points."""
    w2 = [w for bid in ids for w in rows_of(full, bid)["omega"]]
    lo2, hi2 = min(w2), max(w2)
    pad = 0.15 * (hi2 - lo2)
    ys = []
    for n, bid in enumerate(ids):
        d2 = rows_of(full, bid)
        plot_branch(ins, d2, "x_min", PERIOD2_COLOURS[n % len(PERIOD2_COLOURS)])
        mark_unresolved_stable(ins, d2, "x_min")
        ys += d2["x_min"]
    span = max(ys) - min(ys)
    near = [i for i, w in enumerate(d["omega"]) if lo2 - pad <= w <= hi2 + pad
            and min(ys) - span <= d["x_min"][i] <= max(ys) + span]
    ins.plot([d["omega"][i] for i in near], [d["x_min"][i] for i in near], ".", color="C0", ms=3)
    ins.set_xlim(lo2 - pad, hi2 + pad)
    ins.set_ylim(min(ys) - 0.3 * span, max(ys) + 0.3 * span)
    ins.set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    ins.set_title("x_min beside the period-2 branches\n(dots: period 1's points)", fontsize=9)


def torus_curves(ax, t, lo="x_min", hi="x_max", label="torus (two-frequency HB): max, min over the torus"):
    """Each torus branch dash-dot, one legend entry for all."""
    first = min(int(x) for x in t["branch"])
    for bid in sorted({int(x) for x in t["branch"]}):
        r = rows_of(t, bid)
        ax.plot(r["omega"], r[hi], "k-.", lw=1, label=label if bid == first else None)
        ax.plot(r["omega"], r[lo], "k-.", lw=1)


def torus_stability_marks(ax, t, lo="x_min", hi="x_max", labelled=True):
    """The torus points whose stability the flow tested (torus.csv `stable`, `lyapunov1`): filled
    where stable, open where unstable (as the period-1 curve's solid and dashed), grey where
    unresolved; one legend entry per kind drawn."""
    if "stable" not in t:
        return
    kinds = [("stable", "o", "k", "k", "torus stable (flow: Lyapunov exponents)"),
             ("unstable", "o", "k", "none", "torus unstable (flow: Lyapunov exponents)"),
             ("unresolved", "d", "0.55", "0.55", "torus stability unresolved (flow)")]
    for kind, marker, colour, face, label in kinds:
        idx = [i for i, s in enumerate(t["stable"]) if t["lyapunov1"][i] == t["lyapunov1"][i] and
               (s == 1.0 if kind == "stable" else s == 0.0 if kind == "unstable" else s != s)]
        for n, y in enumerate((hi, lo)):
            ax.plot([t["omega"][i] for i in idx], [t[y][i] for i in idx], ls="none", marker=marker, ms=4.5,
                    color=colour, mfc=face, zorder=4, label=label if labelled and n == 0 and idx else None)


def contact_rugs(ax, full, ids, orbit_ids=()):
    """One rug row per branch (period 1 at the bottom, then each period-2 branch in its colour,
    then each orbit branch in its own): on coexisting branches the reader sees which one loses
    contact."""
    contact_rug(ax, per_contact_state(rows_of(full, 0)), row=0, colour="C0" if ids or orbit_ids else None)
    for n, bid in enumerate(ids):
        contact_rug(ax, per_contact_state(rows_of(full, bid)), row=n + 1,
                    colour=PERIOD2_COLOURS[n % len(PERIOD2_COLOURS)])
    for n, bid in enumerate(orbit_ids):
        contact_rug(ax, per_contact_state(rows_of(full, bid)), row=len(ids) + n + 1, colour=ORBIT_BRANCH_COLOUR)
    rug_room(ax, rows=1 + len(ids) + len(orbit_ids))


def bifurcation_markers(ax, full, b):
    """Each located bifurcation on the branch it lies on, at that branch's x_max."""
    for kind, m in BIFURCATION_MARKERS.items():
        w, ys = [], []
        for i in range(len(b["omega"])):
            on = rows_of(full, int(b["branch"][i]) if "branch" in b else 0)
            if b["type"][i] != kind or not on["omega"]:
                continue
            j = min(range(len(on["omega"])), key=lambda k: abs(on["omega"][k] - b["omega"][i]))
            w.append(b["omega"][i])
            ys.append(on["x_max"][j])
        if w:
            ax.plot(w, ys, ls="none", marker=m, color=BIFURCATION_COLOURS[kind], mfc="none", ms=8,
                    label=kind.replace("_", " "))


def labels(ax, model, d):
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    ax.set_ylabel("output q'x, q = %s [m]" % direction_text(model["output"]["direction"]))
    lo, hi = sorted((model["omega"]["from"], model["omega"]["to"]))
    beyond = ""   # a branch that folds back out of the range at its start is followed there
    if min(d["omega"]) < lo * (1 - 1e-9) or max(d["omega"]) > hi * (1 + 1e-9):
        beyond = "; the branch folds back out of the range: drawn over %.3g to %.3g" % (min(d["omega"]), max(d["omega"]))
    ax.set_title("%s\nH = %d, swept %g to %g rad/s%s" % (model.get("name", "model"), model["harmonics"],
                                                         model["omega"]["from"], model["omega"]["to"], beyond),
                 fontsize=9)


def poincare_below(axp, r, handles):
    """The diagram's Poincare points under the response, the torus' section on them; the legend."""
    more = poincare_panel(axp, r["diagram"], r["diagram_hb"], r["model"]["output"]["direction"], orbit=r["orbit_ids"])
    if r["torus"] is not None:   # the torus' section theta1 = 0: where its Poincare points lie
        torus_curves(axp, r["torus"], "section_min", "section_max", "torus (HB): least, largest q'x on the section")
        more += [x for x in axp.get_lines() if x.get_label().startswith("torus")]
        torus_stability_marks(axp, r["torus"], "section_min", "section_max", labelled=False)
    axp.set_xlabel(r"forcing frequency $\omega$ [rad/s]")
    axp.set_title("bifurcation diagram by time integration %s%s" % (bands_text(r["diagram"], "omega", "rad/s"),
                                                                     hb_starts_text(r["diagram"])), fontsize=8)
    axp.legend(handles=handles + more, fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.27), ncol=2,
               frameon=False)


def main():
    d_dir = pathlib.Path(sys.argv[1])
    r = read_run(d_dir)
    fig, axes = layout(r)
    ax = axes["main"]
    plot_branch(ax, r["d"], "x_max", "C0", r"$x_{max}$ (upper), $x_{min}$ (lower)")
    plot_branch(ax, r["d"], "x_min", "C0")
    for y in ("x_max", "x_min"):   # "stable" on a failed shooting correction: unresolved, not stable
        mark_unresolved_stable(ax, r["d"], y)
    plot_doubled_branches(ax, r["full"], skip=r["orbit_ids"], mark_unresolved=True)
    plot_orbit_branches(ax, r["full"], r["orbit"])
    if r["ids"]:
        period2_closeup(axes["closeup"], r["full"], r["d"], r["ids"])
    if r["torus"] is not None:
        torus_curves(ax, r["torus"])
        torus_stability_marks(ax, r["torus"])
        torus_panel(axes["torus"], r["torus"], r["bif"])
    if r["bif"] is not None:
        bifurcation_markers(ax, r["full"], r["bif"])
    contact_rugs(ax, r["full"], r["ids"], r["orbit_ids"])
    shaded = no_stable_period1(d_dir, [a for a in (ax, axes["poincare"]) if a is not None])
    labels(ax, r["model"], r["d"])
    handles = ax.get_legend_handles_labels()[0] + shaded + legend_styles(ax)
    if axes["poincare"] is not None:
        ax.set_xlabel("")
        poincare_below(axes["poincare"], r, handles)
        diagram_figure(d_dir, r["model"], r["diagram"], r["diagram_hb"], r["orbit_ids"])
    else:
        fig.legend(handles=handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3,
                   frameon=False)
    save_whole(fig, d_dir / "frc.png")

if __name__ == "__main__":
    main()
