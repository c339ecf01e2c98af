"""Shared plotting helpers: read the chapter CSVs and draw frequency responses.

Convention for every frequency-response figure: stable branches solid,
unstable branches (Floquet multipliers of the orbit) dashed; markers show where the contact is intermittent
or full; reference levels (gap, natural frequencies) dotted and labelled.

Values drawn (VALUES): "exact" (the default) draws a measure's exact twin (x_max_exact, ...: the
HB point corrected on the exact piecewise-linear flow, lib/README "The exact orbit") wherever the
table has it; points without one (`exact` != ok) are gaps in the curve with a grey x at the HB
value, and a table with no exact value at all (a time-varying stiffness) is drawn from HB.
"hb" draws the harmonic-balance values. Set by make_all.py --values or GEARHB_FIGURE_VALUES.
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams.update({"figure.dpi": 110, "savefig.dpi": 130, "axes.grid": True,
                     "grid.alpha": 0.3, "legend.fontsize": 8, "axes.titlesize": 10})


def read_csv(path):
    """CSV -> dict of columns (floats where possible; an empty field, "none", reads as NaN)."""
    with open(path) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        names = reader.fieldnames or []
    cols = {k: [] for k in names}   # a header-only table (e.g. no bifurcations) has empty columns
    for k in (names if rows else []):
        vals = [r[k] for r in rows]
        try:
            cols[k] = [float(v) if v != "" else float("nan") for v in vals]
        except ValueError:
            cols[k] = vals
    return cols


VALUES = os.environ.get("GEARHB_FIGURE_VALUES", "exact")


def uses_exact(d, y, values=None):
    """Whether column y is drawn from its exact twin: `values` (default VALUES) is "exact" and
    the table has exact values."""
    return ((values or VALUES) == "exact" and (y + "_exact") in d
            and any(s == "ok" for s in d.get("exact", [])))


def column(d, y, values=None):
    """The values of column y to draw: its exact twin where uses_exact (NaN where a point has
    none), else the column itself."""
    if not uses_exact(d, y, values):
        return d[y]
    return [v if s == "ok" else float("nan") for v, s in zip(d[y + "_exact"], d["exact"])]


def read_params(data_dir):
    """The run's parameters (params.json) as {name: value}."""
    import json
    with open(data_dir / "params.json") as f:
        return {k: v["value"] for k, v in json.load(f).items()}


def case_rows(data_dir):
    """The run's case table (cases.csv) as {label: {column: value}}."""
    d = read_csv(data_dir / "cases.csv")
    return {lb: {k: d[k][i] for k in d} for i, lb in enumerate(d["label"])}


def runs(flags):
    """Split indices 0..n-1 into maximal runs of equal flag: [(flag, i0, i1)] (inclusive)."""
    out, start = [], 0
    for i in range(1, len(flags) + 1):
        if i == len(flags) or flags[i] != flags[start]:
            out.append((flags[start], start, i - 1))
            start = i
    return out


def plot_branch(ax, d, y="x_max", color="C0", label=None, x="omega", scale=1.0, values=None):
    """One continuation branch: solid where stable, dashed where unstable.
    Consecutive runs share their end point so the curve stays connected.
    values: "exact" or "hb" for this curve (default VALUES; a figure about HB's own
    truncation order passes "hb")."""
    exact = uses_exact(d, y, values)
    xs, ys = d[x], [v * scale for v in column(d, y, values)]
    first = True
    for flag, i0, i1 in runs([int(s) for s in d["stable"]]):
        j1 = min(i1 + 1, len(xs) - 1)
        ax.plot(xs[i0:j1 + 1], ys[i0:j1 + 1], color=color, ls="-" if flag else "--",
                lw=1.4, label=label if first else None)
        first = False
    note_values(ax, exact)
    if exact:   # points with no exact value: their HB value, marked (one legend entry per axes)
        bad = [i for i in range(len(xs)) if d["exact"][i] != "ok"]
        if bad:
            first_x = not getattr(ax, "_gearhb_x_marked", False)
            ax._gearhb_x_marked = True
            ax.plot([xs[i] for i in bad], [d[y][i] * scale for i in bad], ls="none", marker="x", ms=4,
                    color="0.4", label="no exact value (correction failed): HB shown" if first_x else None)


def note_values(ax, exact):
    """A small note in the axes' corner: which values its curves show."""
    kinds = getattr(ax, "_gearhb_values", set()) | {"exact" if exact else "hb"}
    ax._gearhb_values = kinds
    text = {frozenset({"exact"}): "curves: exact orbit (HB corrected on the exact flow)",
            frozenset({"hb"}): "curves: harmonic balance",
            frozenset({"exact", "hb"}): "curves: exact orbit where available, else harmonic balance"}[frozenset(kinds)]
    if getattr(ax, "_gearhb_note", None) is None:
        ax._gearhb_note = ax.text(0.005, 0.005, text, transform=ax.transAxes, ha="left", va="bottom", fontsize=6,
                                  color="0.35")
    else:
        ax._gearhb_note.set_text(text)


def mark_contact(ax, d, y="x_max", color="C0", x="omega", scale=1.0, values=None):
    """Small markers on points in intermittent (dot) and full (square) contact."""
    for state, m in (("intermittent", "."), ("full", "s")):
        ys = column(d, y, values)
        pts = [(d[x][i], ys[i] * scale) for i in range(len(d[x])) if d["contact"][i] == state]
        if pts:
            ax.plot(*zip(*pts), ls="none", marker=m, ms=5 if m == "." else 3, color=color, alpha=0.6)


def legend_styles(ax):
    """Proxy legend entries explaining line styles and markers."""
    from matplotlib.lines import Line2D
    return [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
            Line2D([], [], color="k", ls="--", label="unstable (Floquet)"),
            Line2D([], [], color="k", ls="none", marker=".", label="intermittent contact"),
            Line2D([], [], color="k", ls="none", marker="s", ms=3, label="full contact")]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return str(path)
