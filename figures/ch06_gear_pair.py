"""Figures 40-45 of thesis ch. 6 (6-DOF gear pair) from build/data/ch06_gear_pair.

Every curve of the run's case table (cases.csv) becomes one figure; titles come from
the table (figure, Fi, Fa, kc). Plotted coordinate: the mesh deflection Delta = T2 q.
Upper panel: Delta_max and Delta_min over a period with the contact level Delta = 0
(teeth touch where Delta > 0) and the bifurcations found on the curve; where three or
more folds crowd together, a middle panel zooms on them. Lower panel: the oscillating
amplitude (Delta_max - Delta_min)/2 beside the linear open / closed-mesh amplitudes.
Dotted verticals: linear natural frequencies; the rug at the bottom: the contact state
(figures/style.py). Grey bands: the ranges with no stable period-1 orbit (key numbers
unstable_period1_*_<label>); the period-2 (and period-4) branches switched at the curve's period
doublings in their own colours (rows of branch id > 0 in frc_<label>.csv); a branch continued from a
time-integrated orbit off the curve (key numbers orbit_branch_*_<label>, chapter step 3c) in its own
style (brown, thicker), and then the grey bands are the ranges with no stable period-1 orbit on any
period-1 branch (unstable_period1_*_all_branches_<label>). The deepest Delta_min off every natural frequency is pointed at as the
mesh's bilinear mode (chapter README, reference/scripts/ch06_bilinear_modes.py).
"""
import json
import math

from style import (read_params, BIFURCATION_COLOURS, BIFURCATION_MARKERS, CONTACT_LEVEL, LINEAR_CLOSED, LINEAR_OPEN, NATURAL_CLOSED,
                   ORBIT_BRANCH_COLOUR, UNRESOLVED_MARKER,
                   NATURAL_OPEN, bifurcation_handles, case_rows, column, contact_rug, legend_styles, orbit_branches,
                   plot_branch, plot_doubled_branches, plot_orbit_branches, read_csv, rows_of, rug_room, save,
                   shade_no_stable_period1, unresolved_period1_ranges, unstable_period1_ranges)

import matplotlib.pyplot as plt

FOLD_CLUSTER_GAP = 2000.0   # rad/s: folds closer than this form one cluster (one zoom panel)


def modes(data_dir, mesh):
    d = read_csv(data_dir / "modes.csv")
    idx = [i for i in range(len(d["mesh"])) if d["mesh"][i] == mesh]
    return sorted(set(round(d["omega_open"][i], 3) for i in idx)), sorted(set(round(d["omega_closed"][i], 3) for i in idx))


def mark_bifurcations(ax, data_dir, label, full):
    """Period doublings, Neimark-Sacker points and branch points on the Delta_max curve of the
    branch each lies on (period 1, or a period-2 branch)."""
    b = read_csv(data_dir / ("bifurcations_%s.csv" % label))
    used = []
    for k, (t, w, located, smooth) in enumerate(zip(b["type"], b["omega"], b["located"], b["smooth"])):
        if t == "fold" or not (located and smooth):
            continue   # folds show as turning points; jumps and unlocated changes are only in the csv
        # the Delta_max value at the nearest point of the branch
        d = rows_of(full, int(b["branch"][k]) if "branch" in b else 0)
        i = min(range(len(d["omega"])), key=lambda j: abs(d["omega"][j] - w))
        y = column(d, "x_max")[i]
        y = d["x_max"][i] if math.isnan(y) else y   # no exact value there: the HB one
        ax.plot(w / 1e3, y * 1e3, ls="none", marker=BIFURCATION_MARKERS[t], color=BIFURCATION_COLOURS[t],
                ms=6, mfc="none", mew=1.2)
        used.append(t)
    return sorted(set(used))


def fold_window(data_dir, label, span):
    """The first cluster of folds (neighbours closer than FOLD_CLUSTER_GAP), widened by a quarter
    of its width each side, in krad/s; None unless the cluster is a crowd (3 folds or more): a
    lone fold reads well at full scale."""
    b = read_csv(data_dir / ("bifurcations_%s.csv" % label))
    on = b.get("branch", [0] * len(b["type"]))
    folds = sorted(w for t, w, k in zip(b["type"], b["omega"], on) if t == "fold" and int(k) == 0)
    if not folds:
        return None
    cluster = [folds[0]]
    for w in folds[1:]:
        if w - cluster[-1] > FOLD_CLUSTER_GAP:
            break
        cluster.append(w)
    if len(cluster) < 3:
        return None
    lo, hi = cluster[0], cluster[-1]
    pad = max(0.25 * (hi - lo), 0.01 * span)
    return (lo - pad) / 1e3, (hi + pad) / 1e3


def delta_panel(ax, data_dir, label, full, w_open, w_closed, orbits=()):
    """Delta_max, Delta_min, the period-doubled branches, the branches from time-integrated orbits
    (`orbits`, orbit_branches), the contact level, the contact rug (period 1) and the bifurcations."""
    d = rows_of(full, 0)
    plot_branch(ax, d, "x_max", "C0", r"$\Delta_{max}$", x="w_k", scale=1e3)
    plot_branch(ax, d, "x_min", "C1", r"$\Delta_{min}$", x="w_k", scale=1e3)
    plot_doubled_branches(ax, full, x="w_k", scale=1e3, entry_per_branch=False, skip=[o[0] for o in orbits])
    plot_orbit_branches(ax, full, orbits, x="w_k", scale=1e3, omega_scale=1e-3, unit="krad/s")
    kinds = mark_bifurcations(ax, data_dir, label, full)
    ax.axhline(0.0, **CONTACT_LEVEL)
    natural_lines(ax, w_open, w_closed)
    ax.set_ylabel(r"mesh deflection $\Delta$ [mm]")
    contact_rug(ax, d, x="w_k")
    return kinds


def natural_lines(ax, w_open, w_closed):
    for w in w_open:
        ax.axvline(w / 1e3, **NATURAL_OPEN)
    for w in w_closed:
        ax.axvline(w / 1e3, **NATURAL_CLOSED)


def mark_bilinear_dip(ax, d, w_open, w_closed):
    """The deepest Delta_min, where it lies on no natural-frequency line (3 %) in intermittent
    contact: the bilinear mode of the mesh (chapter README, reference/scripts/ch06_bilinear_modes.py)."""
    i = min(range(len(d["x_min"])), key=lambda k: d["x_min"][k])
    w = d["omega"][i]
    if d["contact"][i] != "intermittent" or any(abs(w - wn) < 0.03 * wn for wn in w_open + w_closed):
        return
    ax.annotate("deepest $\\Delta_{min}$ at %.2f krad/s: the bilinear mode of the mesh\n(closed-mesh motion while the "
                "teeth touch, free gears while apart;\nits free period 22.18 krad/s: README)" % (w / 1e3),
                (w / 1e3, d["x_min"][i] * 1e3), xytext=(14, 6), textcoords="offset points", ha="left", va="bottom",
                fontsize=7, arrowprops=dict(arrowstyle="->", lw=0.8))


def separation_note(d, params):
    """A title line, from this run's numbers, where the mesh opens wider than a base radius: the
    thesis' loads drive this model (no back flank, so no backlash limits the opening) to
    separations no real pair could reach."""
    gap, rb = -min(d["x_min"]), min(params["rb1"], params["rb2"])
    if gap <= rb:
        return ""
    return ("\nlargest separation $-\\Delta_{min}$ = %.3g m = %.1f x the smaller base radius (%.3g m):\nthe thesis' "
            "loads on a model without a back flank" % (gap, gap / rb, rb))


def zoom_panel(az, a1, data_dir, label, full, d, zoom, w_open, w_closed, orbits=()):
    """Delta on the folds' window, framed (dotted) on the whole curve above (its height: the
    period-1 curve's and the orbit branches')."""
    delta_panel(az, data_dir, label, full, w_open, w_closed, orbits)
    ys = [0.0]
    for b in [d] + [rows_of(full, o[0]) for o in orbits]:
        ys += [b[y][k] * 1e3 for k, w in enumerate(b["w_k"]) if zoom[0] <= w <= zoom[1] for y in ("x_max", "x_min")]
    pad = 0.08 * (max(ys) - min(ys))
    az.set_xlim(*zoom)
    az.set_ylim(min(ys) - pad, max(ys) + pad)
    rug_room(az)
    az.set_title("zoom on the folds: %.2f-%.2f krad/s" % zoom, fontsize=9)
    a1.axvspan(*zoom, fill=False, ec="0.3", ls=":", lw=0.9)   # framed: grey fill marks no stable period 1


def amplitude_panel(a2, full, d, lin, s, w_open, w_closed, orbits=()):
    """The oscillating amplitude against the linear open and closed meshes (linear_*.csv is for
    Fa = 1e4: scaled by s)."""
    plot_branch(a2, d, "amp", "0.15", r"$(\Delta_{max} - \Delta_{min})/2$", x="w_k", scale=1e3)
    plot_doubled_branches(a2, full, ys=("amp",), x="w_k", scale=1e3, entry_per_branch=False, skip=[o[0] for o in orbits])
    plot_orbit_branches(a2, full, orbits, ys=("amp",), x="w_k", scale=1e3, omega_scale=1e-3, unit="krad/s")
    a2.semilogy([w / 1e3 for w in lin["omega"]], [v * s * 1e3 for v in lin["delta_open"]], **LINEAR_OPEN,
                label="linear, mesh open")
    a2.semilogy([w / 1e3 for w in lin["omega"]], [v * s * 1e3 for v in lin["delta_closed"]], **LINEAR_CLOSED,
                label="linear, mesh closed")
    natural_lines(a2, w_open, w_closed)
    contact_rug(a2, d, x="w_k")
    a2.set_xlim(min(d["w_k"]), max(d["w_k"]))
    rug_room(a2)
    a2.set_ylabel(r"oscillating amplitude of $\Delta$ [mm]")
    a2.set_xlabel(r"forcing frequency $\omega$ [krad/s]   (dotted: natural frequencies, light grey open, dark closed "
                  "mesh)", fontsize=8)


def case_figure(data_dir, fig_dir, row, name):
    label, mesh = row["label"], row["mesh"]
    full = read_csv(data_dir / ("frc_%s.csv" % label))
    lin = read_csv(data_dir / ("linear_%s.csv" % mesh))
    w_open, w_closed = modes(data_dir, mesh)
    full["w_k"] = [w / 1e3 for w in full["omega"]]
    full["amp"] = [(a - b) / 2 for a, b in zip(full["x_max"], full["x_min"])]
    if "x_max_exact" in full:
        full["amp_exact"] = [(a - b) / 2 for a, b in zip(full["x_max_exact"], full["x_min_exact"])]
    d = rows_of(full, 0)
    with open(data_dir / "key_numbers.json") as f:
        kn = json.load(f)
    orbits = orbit_branches(kn, "_" + label)
    p_span = max(d["omega"]) - min(d["omega"])
    zoom = fold_window(data_dir, label, p_span)
    rows = 3 if zoom else 2
    fig_, axes = plt.subplots(rows, 1, figsize=(7.6, 11.6 if zoom else 8.8),
                              gridspec_kw={"height_ratios": [1.2, 1.0, 0.9][:rows]})
    a1, a2 = axes[0], axes[-1]
    kinds = delta_panel(a1, data_dir, label, full, w_open, w_closed, orbits)
    a1.set_xlim(min(d["w_k"]), max(d["w_k"]))
    rug_room(a1)
    a1.annotate(r"contact level $\Delta$ = 0 (teeth touch above)", (0.99, 0.0), xycoords=("axes fraction", "data"),
                fontsize=7, xytext=(0, 3), textcoords="offset points", ha="right")
    if mesh == "kc":
        mark_bilinear_dip(a1, d, w_open, w_closed)
    what = "Fig. %d" % int(row["figure"]) if mesh == "kc" else \
        "Supplement S%d (Fig. %d's loads with the printed kc)" % (int(row["figure"]), int(row["figure"]))
    a1.set_title("%s:\n$F_i$ = %g N m, F = %g [1,0,1,1,0,1] N, N m, $k_c$ = %g N/m%s"
                 % (what, row["Fi"], row["Fa"], row["kc"], separation_note(d, read_params(data_dir))), fontsize=9)
    if zoom:
        zoom_panel(axes[1], a1, data_dir, label, full, d, zoom, w_open, w_closed, orbits)
    amplitude_panel(a2, full, d, lin, row["Fa"] / 1e4, w_open, w_closed, orbits)
    h1, _ = a1.get_legend_handles_labels()
    h2, _ = a2.get_legend_handles_labels()
    seen = set()
    handles = [h for h in h1 + h2 if not (h.get_label() in seen or seen.add(h.get_label()))]   # one entry per label
    handles += shade_no_stable_period1(axes, *no_stable_period1(kn, label), scale=1e-3, unit="krad/s")
    fig_.legend(handles=handles + legend_styles() + bifurcation_handles(kinds), fontsize=7, ncol=2,
                loc="lower center", framealpha=0.9)
    fig_.tight_layout(rect=(0, 0.12 if zoom else 0.17, 1, 1))
    fig_.savefig(fig_dir / name)
    plt.close(fig_)
    return str(fig_dir / name)


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
    for label, row in case_rows(data_dir).items():
        if (data_dir / ("bifurcation_diagram_%s.csv" % label)).exists():
            out.append(diagram_figure(data_dir, fig_dir, label, row))
    return out


# The diagram figure's columns: a case whose bands spread far is drawn in columns split at these
# speeds [krad/s] (Fig. 40: the grazing region 7.5-12 krad/s in 25-50 rad/s steps; 12.4-15.5
# krad/s, Delta to -4 mm; the narrow band 17.6-18.4 krad/s; the bands of 26-62 krad/s, Delta
# within 0.3 mm); a case not listed: one column.
DIAGRAM_COLUMNS = {"fig40": (12.2, 16.5, 22.0), "fig44": (12.2, 16.5, 22.0)}


def diagram_figure(data_dir, fig_dir, label, row):
    """Supplement: the case's bifurcation diagram by time integration over its bands (bifurcation_diagram_<label>.csv)
    under its harmonic-balance curves, a column per group of bands (DIAGRAM_COLUMNS): above, Delta_max and
    Delta_min of every branch; below, Delta at phase 0 of each forcing period (the Poincare section) over the
    HB branches at that phase. Hatched: the gaps between a column's bands (no diagram computed there)."""
    full = read_csv(data_dir / ("frc_%s.csv" % label))
    p, h = (read_csv(data_dir / ("bifurcation_diagram_%s.csv" % label)),
            read_csv(data_dir / ("bifurcation_diagram_hb_%s.csv" % label)))
    for d in (full, h, p):
        d["w_k"] = [w / 1e3 for w in d["omega"]]
    with open(data_dir / "key_numbers.json") as f:
        kn = json.load(f)
    bands = diagram_bands(p["w_k"])
    cuts = DIAGRAM_COLUMNS.get(label, ())
    columns = [c for c in ([b for b in bands if a <= b[0] < z] for a, z in zip((-math.inf,) + cuts, cuts + (math.inf,)))
               if c]
    fig, axes = plt.subplots(2, len(columns), figsize=(7.6 if len(columns) == 1 else 4.8 * len(columns), 8.6), sharex="col",
                             squeeze=False, gridspec_kw={"height_ratios": [1.0, 1.2]})
    handles = []
    for k, col in enumerate(columns):
        handles += diagram_column(axes[0][k], axes[1][k], data_dir, label, (full, p, h, kn), col)
    axes[0][0].set_ylabel(r"mesh deflection $\Delta$ [mm]")
    axes[1][0].set_ylabel(r"$\Delta$ at phase 0 of each forcing period [mm]")
    scaled = kn.get("diagram_scaled_by_" + label, {}).get("value")
    speeds = len(set(p["omega"]))
    how = ("time integration (GSL rk8pd, speed stepped up then down, %d speeds each way%s)"
           % (speeds, "" if len(bands) == 1 else " over %d bands" % len(bands))
           if scaled is None else "time integration: the smaller-load case's points x %g (homogeneous in the loads)"
           % scaled)
    title = ("Fig. %d's case ($F_i$ = %g N m, F = %g): bifurcation diagram by %s under the harmonic-balance branches"
             % (int(row["figure"]), row["Fi"], row["Fa"], how))
    if len(columns) == 1:
        axes[0][0].set_title(title.replace(" (", "\n(", 1) if scaled is None else title.replace(": the", ":\nthe"),
                             fontsize=9)
    else:
        fig.suptitle(title, fontsize=10)
    handles += shade_no_stable_period1((), *no_stable_period1(kn, label), scale=1e-3, unit="krad/s")   # its entries
    h1, l1 = axes[0][0].get_legend_handles_labels()
    styles = [hd for hd in legend_styles() if "rug" not in hd.get_label()]   # no contact rug here
    if len(columns) > 1:   # a branch's colour is its column's: one entry per period and style
        handles = [generic_branch_entry(hd) for hd in handles]
    seen, unique = set(), []
    for hd in h1 + handles + styles:
        if hd.get_label() not in seen:
            seen.add(hd.get_label())
            unique.append(hd)
    fig.tight_layout()
    fig.legend(handles=unique, fontsize=7, ncol=2 if len(columns) == 1 else 4, loc="upper center",
               bbox_to_anchor=(0.5, 0.0), framealpha=0.9)
    path = fig_dir / ("figS47_ch06_diagram_%s.png" % label)
    fig.savefig(path, bbox_inches="tight")   # the legend below the axes, inside the image
    plt.close(fig)
    return str(path)


def generic_branch_entry(handle):
    """A legend entry "HB period p (branch b), its p points (...)" as poincare.draw_hb_section's
    entry for many branches (grey, "a colour each"); any other entry as it is."""
    import re
    from matplotlib.lines import Line2D
    m = re.match(r"HB period (\d+) \(branch \d+\), its \d+ points \((\w+)\)", handle.get_label())
    if not m:
        return handle
    return Line2D([], [], color="0.35", ls=handle.get_linestyle(), label="HB period-%s branches (a colour each), "
                  "their %s points (%s)" % (m.group(1), m.group(1), m.group(2)))


def diagram_bands(speeds):
    """[(lo, hi)] of the diagram's bands from its speeds: a new band where the gap to the next
    speed exceeds 1.5 times the larger of the steps beside it, before (in the band) and after (each
    band's grid is uniform but for a speed added in a range with no stable period-1 orbit that the
    grid misses, which halves a step: hb/bifurcation_diagram.hpp speeds_missed)."""
    w = sorted(set(speeds))
    bands, start = [], 0
    for i in range(1, len(w)):
        step = max(w[i - 1] - w[i - 2], w[i + 1] - w[i] if i + 1 < len(w) else 0.0) if i - 1 > start else None
        if step is not None and w[i] - w[i - 1] > 1.5 * step:
            bands.append((w[start], w[i - 1]))
            start = i
    bands.append((w[start], w[-1]))
    return bands


def diagram_column(a1, a2, data_dir, label, data, bands):
    """One column of the diagram figure: the bands `bands` [(lo, hi)] krad/s of the case's diagram,
    the HB branches over the whole column (y limits from what lies in the bands), the gaps between
    the bands hatched. Returns the legend handles of the lower panel."""
    from poincare import draw_hb_section, draw_poincare
    full, p, h, kn = data
    lo, hi = bands[0][0], bands[-1][1]
    inside = lambda d, one_row_points=False: rows_near(d, lo, hi, one_row_points)
    band = inside(full, True)
    plot_branch(a1, rows_of(band, 0), "x_max", "0.15", r"HB period 1: $\Delta_{max}$, $\Delta_{min}$", x="w_k",
                scale=1e3)
    plot_branch(a1, rows_of(band, 0), "x_min", "0.15", None, x="w_k", scale=1e3)
    orbits = orbit_branches(kn, "_" + label)
    plot_doubled_branches(a1, band, x="w_k", scale=1e3, entry_per_branch=False, skip=[o[0] for o in orbits])
    plot_orbit_branches(a1, band, orbits, x="w_k", scale=1e3, omega_scale=1e-3, unit="krad/s")
    a1.axhline(0.0, **CONTACT_LEVEL)
    handles = draw_hb_section(a2, inside(h), "w_k", "delta", scale=1e3)
    for k, (bid, w, period) in enumerate(orbits, 1):   # the orbit branches' sections (period 1: chapter step 3c)
        path = data_dir / ("orbit_branch_section_%s_%d.csv" % (label, k))
        if path.exists():
            hk = read_csv(path)
            hk["w_k"] = [v / 1e3 for v in hk["omega"]]
            handles += draw_hb_section(a2, inside(hk), "w_k", "delta", scale=1e3, colour=ORBIT_BRANCH_COLOUR,
                                       label="HB branch %d at the same phase" % bid)
    handles += draw_poincare(a2, p, "w_k", "delta", scale=1e3, sweeps=("up", "down", "from_hb"),
                             keep=lambda i: lo <= p["w_k"][i] <= hi)
    handles += mark_unresolved(a2, h, rows_of(full, 0), lo, hi, int(read_params(data_dir)["H"]))
    a2.set_xlabel(r"forcing frequency $\omega$ [krad/s]")
    pad = 0.01 * (hi - lo)
    a2.set_xlim(lo - pad, hi + pad)
    in_bands = lambda w: any(a <= w <= b for a, b in bands)
    fit_to_bands(a1, [v * 1e3 for y in ("x_max", "x_min") for w, v in zip(band["w_k"], band[y]) if in_bands(w)])
    fit_to_bands(a2, [v * 1e3 for w, v in zip(p["w_k"] + h["w_k"], p["delta"] + h["delta"]) if in_bands(w)])
    for (a, b), (c, _) in zip(bands, bands[1:]):
        for ax in (a1, a2):
            ax.axvspan(b, c, facecolor="none", edgecolor="0.8", hatch="///", lw=0, zorder=0)
    if len(bands) > 1:
        from matplotlib.patches import Patch
        handles.append(Patch(facecolor="none", edgecolor="0.6", hatch="///", label="between the bands: no diagram"))
    ranges, unresolved = no_stable_period1(kn, label)
    near = lambda rs: [r for r in rs if r[1] / 1e3 >= lo and r[0] / 1e3 <= hi]
    shade_no_stable_period1((a1, a2), near(ranges), unresolved=near(unresolved),
                            scale=1e-3)
    return handles


def no_stable_period1(kn, label):
    """The case's ranges with no stable period-1 orbit [(from, to)] rad/s and, of them, the stretches
    whose stability is unresolved (unresolved_period1_*): on any period-1 branch
    where it has orbit branches (chapter step 3c), else on its continued curve."""
    every = "_all_branches_" + label
    suffix = every if "unstable_period1_ranges" + every in kn else "_" + label
    return unstable_period1_ranges(kn, suffix), unresolved_period1_ranges(kn, suffix)


def rows_near(d, lo, hi, one_row_points):
    """The rows of table d with w_k in [lo, hi] krad/s, and the rows next to them on the same
    branch (columns branch, point where the table has them), so that a branch's line reaches the
    panel's edge where the continuation stepped across it; with one_row_points False (the HB
    section, a period-p orbit in p consecutive rows) the neighbours of period-1 rows only."""
    n = len(d["w_k"])
    same = lambda i, j: all(d[c][i] == d[c][j] for c in ("branch", "point") if c in d)
    near = lambda i, j: same(i, j) and (one_row_points or str(d.get("period", ["1"] * n)[i]) in ("1", "1.0"))
    keep = [lo <= w <= hi for w in d["w_k"]]
    keep = [keep[i] or any(0 <= j < n and keep[j] and near(i, j) for j in (i - 1, i + 1)) for i in range(n)]
    return {c: [v[i] for i in range(n) if keep[i]] for c, v in d.items()}


def fit_to_bands(ax, values):
    """y limits from the values that lie in the bands, 5 % margin (the HB curves between the bands
    may leave the panel)."""
    if values:
        a, b = min(values), max(values)
        m = 0.05 * (b - a) if b > a else 0.05 * abs(a) + 1e-12
        ax.set_ylim(a - m, b + m)


def mark_unresolved(ax, h, curve, lo, hi, H):
    """The HB section's points (h's branch rows, in the order of the period-1 rows `curve` of the
    frequency response) whose shooting correction failed (exact = not_converged): their stability
    label is not resolved at H harmonics. Marked over [lo, hi] krad/s; the legend handle (or none)."""
    from matplotlib.lines import Line2D
    branch = [i for i, pt in enumerate(h["point"]) if pt == "branch"]
    bad = [i for i, e in zip(branch, curve["exact"]) if e == "not_converged" and lo <= h["w_k"][i] <= hi]
    if not bad:
        return []
    ax.plot([h["w_k"][i] for i in bad], [h["delta"][i] * 1e3 for i in bad], zorder=7, **UNRESOLVED_MARKER)
    return [Line2D([], [], label="HB point whose shooting correction fails:\nstability not resolved at H = %d" % H,
                   **UNRESOLVED_MARKER)]


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
