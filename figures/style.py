"""Shared plotting helpers: read the chapter CSVs and draw frequency responses.

Convention for every frequency-response figure: stable branches solid,
unstable branches (Floquet multipliers of the orbit) dashed; markers show where the contact is intermittent
or full; reference levels (gap, natural frequencies) dotted and labelled.
"""
import csv

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


def plot_branch(ax, d, y="x_max", color="C0", label=None, x="omega", scale=1.0):
    """One continuation branch: solid where stable, dashed where unstable.
    Consecutive runs share their end point so the curve stays connected."""
    xs, ys = d[x], [v * scale for v in d[y]]
    first = True
    for flag, i0, i1 in runs([int(s) for s in d["stable"]]):
        j1 = min(i1 + 1, len(xs) - 1)
        ax.plot(xs[i0:j1 + 1], ys[i0:j1 + 1], color=color, ls="-" if flag else "--",
                lw=1.4, label=label if first else None)
        first = False


def mark_contact(ax, d, y="x_max", color="C0", x="omega", scale=1.0):
    """Small markers on points in intermittent (dot) and full (square) contact."""
    for state, m in (("intermittent", "."), ("full", "s")):
        pts = [(d[x][i], d[y][i] * scale) for i in range(len(d[x])) if d["contact"][i] == state]
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
