"""Shared plotting helpers: read the chapter CSVs and draw frequency responses.

One convention for every figure of every chapter, defined here and nowhere else:
  - stability: stable branches solid, unstable branches (Floquet multipliers of the orbit) dashed;
    where the stability label is not trusted, grey (UNRESOLVED);
  - contact state: a thin rug at the bottom of the axes, one row per curve (contact_rug):
    gold where the contact is intermittent, grey where it is full, empty where open; it never
    covers a curve, so the solid/dashed stability stays readable;
  - torques: one colour per torque (torque_colour): the thesis' 100, 200, 300 N m are blue,
    orange, red in every chapter; a figure with other torques colours them by rank, lightest
    blue, heaviest red;
  - curves that are not torques (models, readings, methods, harmonics H) use COMPARISON_COLOURS,
    never a torque colour;
  - bifurcations: one marker per type (BIFURCATION_MARKERS), hollow;
  - linear references: LINEAR_OPEN / LINEAR_CLOSED (grey dash-dot), natural frequencies
    NATURAL_OPEN / NATURAL_CLOSED (grey dotted verticals), contact levels CONTACT_LEVEL.

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


def plot_branch(ax, d, y="x_max", color="C0", label=None, x="omega", scale=1.0, values=None, unresolved=(), lw=1.4,
                alpha=1.0):
    """One continuation branch: solid where stable, dashed where unstable, grey (UNRESOLVED)
    at the indices `unresolved` (a stability label that is not trusted).
    Consecutive runs share their end point so the curve stays connected.
    values: "exact" or "hb" for this curve (default VALUES; a figure about HB's own
    truncation order passes "hb")."""
    exact = uses_exact(d, y, values)
    xs, ys = d[x], [v * scale for v in column(d, y, values)]
    bad = set(unresolved)
    first = True
    for flag, i0, i1 in runs([2 if i in bad else int(s) for i, s in enumerate(d["stable"])]):
        j1 = min(i1 + 1, len(xs) - 1)
        if flag == 2:
            ax.plot(xs[i0:j1 + 1], ys[i0:j1 + 1], color=UNRESOLVED, ls="-", lw=2.4, alpha=0.9, zorder=3)
            continue
        ax.plot(xs[i0:j1 + 1], ys[i0:j1 + 1], color=color, ls="-" if flag else "--",
                lw=lw, alpha=alpha, label=label if first else None)
        first = False
    note_values(ax, exact)
    if exact:   # points with no exact value: their HB value, marked (one legend entry per axes)
        no_exact = [i for i in range(len(xs)) if d["exact"][i] != "ok"]
        if no_exact:
            first_x = not getattr(ax, "_gearhb_x_marked", False)
            ax._gearhb_x_marked = True
            ax.plot([xs[i] for i in no_exact], [d[y][i] * scale for i in no_exact], ls="none", marker="x", ms=4,
                    color="0.4", label="no exact value (correction failed): HB shown" if first_x else None)


def flickering_stability(d, x="omega", margin=2):
    """Indices where the stability label is not trusted. Between two turning points (folds in x)
    the label of a simple overhang is constant, and it changes at the folds (give or take
    `margin` points). On each such piece of the branch the points whose label differs from the
    piece's majority, away from its ends, are the untrusted ones; the whole span from the first
    to the last of them is returned (the label flips there)."""
    xs, st = d[x], [int(s) for s in d["stable"]]
    turns = [0] + [i for i in range(1, len(xs) - 1) if (xs[i] - xs[i - 1]) * (xs[i + 1] - xs[i]) < 0] + [len(xs) - 1]
    out = []
    for a, b in zip(turns[:-1], turns[1:]):
        piece = st[a:b + 1]
        majority = 1 if 2 * sum(piece) >= len(piece) else 0
        odd = [i for i in range(a + margin + 1, b - margin) if st[i] != majority]
        if odd:
            out += range(odd[0] - 1, odd[-1] + 2)
    return out


def note_values(ax, exact):
    """A small note in the axes' corner: which values its curves show."""
    kinds = getattr(ax, "_gearhb_values", set()) | {"exact" if exact else "hb"}
    ax._gearhb_values = kinds
    text = {frozenset({"exact"}): "curves: exact orbit (HB corrected on the exact flow)",
            frozenset({"hb"}): "curves: harmonic balance",
            frozenset({"exact", "hb"}): "curves: exact orbit where available, else harmonic balance"}[frozenset(kinds)]
    if getattr(ax, "_gearhb_note", None) is None:
        ax._gearhb_note = ax.text(0.005, 0.995, text, transform=ax.transAxes, ha="left", va="top", fontsize=6,
                                  color="0.35")
    else:
        ax._gearhb_note.set_text(text)


def untrusted_stability(d, x="omega"):
    """Indices whose stability label is not trusted: where the shooting correction of the HB
    orbit did not converge (column `exact` = not_converged: the multipliers are those of an
    uncorrected orbit) and where the label flips between folds (flickering_stability)."""
    failed = [i for i, e in enumerate(d.get("exact", [])) if e == "not_converged"]
    return sorted(set(failed) | set(flickering_stability(d, x=x)))


# An HB point whose "stable" label rests on a failed shooting correction (ch. 6's S47, gearhb_gear, gearhb_frc).
UNRESOLVED_MARKER = dict(ls="none", marker="s", ms=5, mfc="none", mec="m", mew=0.9)


def unresolved_stable(d):
    """Indices of the rows of one branch d that lie in an unresolved stretch: a run of consecutive
    stable rows none of which has a converged shooting correction (exact = not_converged), so
    "stable" there rests on uncorrected multipliers (lib/gearhb/hb/period_doubling.hpp
    resolved_stable: the programs report such stretches as unresolved, not as stable)."""
    st, ex, out, i = [int(s) for s in d["stable"]], d.get("exact", []), [], 0
    while ex and i < len(st):
        j = i
        while st[i] and j + 1 < len(st) and st[j + 1]:
            j += 1
        if st[i] and all(ex[k] == "not_converged" for k in range(i, j + 1)):
            out += range(i, j + 1)
        i = j + 1
    return out


def mark_unresolved_stable(ax, d, y, x="omega", scale=1.0):
    """Magenta squares (UNRESOLVED_MARKER) at the HB values of d's unresolved_stable rows; one
    legend entry per axes. Whether any was drawn."""
    bad = unresolved_stable(d)
    if bad:
        first = not getattr(ax, "_gearhb_unresolved_marked", False)
        ax._gearhb_unresolved_marked = True
        ax.plot([d[x][i] for i in bad], [d[y][i] * scale for i in bad], zorder=7,
                label="HB point labelled stable whose shooting correction\nfails: stability unresolved" if first else None,
                **UNRESOLVED_MARKER)
    return bool(bad)


def unresolved_handle(H):
    """H: the harmonics (an int, or a text such as "1 and 5") whose stability is not resolved."""
    from matplotlib.lines import Line2D
    return Line2D([], [], color=UNRESOLVED, lw=2.4, label="stability not resolved at H = %s:\nthe shooting correction fails or the label\n"
                  "flips between folds (the H-harmonic orbit\nis too far from the exact one)" % H)


# The thesis' torques in every chapter (N m) and their colours: blue, orange, red.
THESIS_TORQUES = (100.0, 200.0, 300.0)
TORQUE_PALETTE = ("#1f77b4", "#ff7f0e", "#d62728")
# Curves that are not torques (models, backlash readings, methods, harmonics): never a torque colour.
COMPARISON_COLOURS = ("#9467bd", "#17becf", "#8c564b", "#2ca02c", "#e377c2", "#7f7f7f")
UNRESOLVED = "0.6"     # a branch whose stability label is not trusted

BIFURCATION_MARKERS = {"fold": "o", "branch_point": "D", "period_doubling": "v", "neimark_sacker": "*"}
# Their colours where one curve is drawn (where several are, a marker takes its curve's colour).
BIFURCATION_COLOURS = {"fold": "k", "branch_point": "#9467bd", "period_doubling": "#8c564b", "neimark_sacker": "#17becf"}

LINEAR_OPEN = dict(color="0.55", ls="-.", lw=1.0)
LINEAR_CLOSED = dict(color="0.2", ls="-.", lw=1.0)
NATURAL_OPEN = dict(color="0.6", ls=":", lw=0.9)
NATURAL_CLOSED = dict(color="0.25", ls=":", lw=0.9)
CONTACT_LEVEL = dict(color="#b22222", ls=":", lw=1.2)

CONTACT_COLOURS = {"intermittent": "#e6b800", "full": "0.55",
                   # a gear mesh with backlash (figures/gear_dynamics.py): the back flank hits
                   "back_impact": "#5e3c99", "drive_loss+back_impact": "#2d004b"}
RUG_HEIGHT = 0.022     # axes fraction per rug row


def rows_of(d, branch):
    """The rows of branch id `branch` of a frequency-response table (all rows of a table without
    the column): 0 the period-1 curve, k >= 1 period-2 branch k."""
    if "branch" not in d:
        return d if branch == 0 else {k: [] for k in d}
    keep = [i for i, b in enumerate(d["branch"]) if int(b) == branch]
    return {k: [v[i] for i in keep] for k, v in d.items()}


def branch_ids(d):
    """The ids of the period-2 (and higher) branches of a frequency-response table, in order."""
    return sorted({int(b) for b in d.get("branch", [])} - {0})


# Not red (the diagram draws chaos red), not green (its quasi-periodic points), not C0 or C1
# (period 1): a branch has the same colour over its response and under the Poincare points.
PERIOD2_COLOURS = ["C4", "C9", "C8", "C6", "C5"]


def plot_doubled_branches(ax, full, ys=("x_max", "x_min"), x="omega", scale=1.0, entry_per_branch=True, skip=(),
                          mark_unresolved=False):
    """The period-2 (and period-4) branches of a frequency-response table (its rows with branch
    id > 0, but the ids in `skip`: e.g. orbit branches, drawn by plot_orbit_branches), each in its
    own colour (PERIOD2_COLOURS, repeated beyond five), solid where stable and dashed where not;
    one legend entry per branch, or (entry_per_branch False) one per period. mark_unresolved:
    their unresolved_stable points as magenta squares (mark_unresolved_stable)."""
    named = set()
    for n, bid in enumerate(b for b in branch_ids(full) if b not in skip):
        d2 = rows_of(full, bid)
        period = int(d2["period"][0]) if "period" in d2 else 2
        label = "period %d (branch %d): max, min over %d periods" % (period, bid, period)
        if not entry_per_branch:
            label = None if period in named else "period-%d branches (a colour each): max, min over %d periods" % (
                period, period)
            named.add(period)
        for k, y in enumerate(ys):
            plot_branch(ax, d2, y, PERIOD2_COLOURS[n % len(PERIOD2_COLOURS)], x=x, scale=scale,
                        label=None if k else label)
            if mark_unresolved:
                mark_unresolved_stable(ax, d2, y, x=x, scale=scale)


ORBIT_BRANCH_COLOUR = "#8c510a"   # brown: a branch continued from a time-integrated orbit (no period-2 colour, not red)


def orbit_branches(kn, suffix=""):
    """The branches a run continued from time-integrated orbits off its curve (key numbers
    orbit_branches<suffix>, orbit_branch_id<suffix>_k, orbit_branch_omega<suffix>_k,
    orbit_branch_period<suffix>_k): [(branch id, omega of the orbit, period)]; none where the run
    did not write them."""
    n = int(kn.get("orbit_branches" + suffix, {"value": 0})["value"])
    get = lambda name, k: kn["%s%s_%d" % (name, suffix, k)]["value"]
    return [(int(get("orbit_branch_id", k)), get("orbit_branch_omega", k), int(get("orbit_branch_period", k)))
            for k in range(1, n + 1)]


def plot_orbit_branches(ax, full, branches, ys=("x_max", "x_min"), x="omega", scale=1.0, omega_scale=1.0,
                        unit="rad/s"):
    """The branches of orbit_branches (rows of their ids in the frequency-response table full) in
    their own style (ORBIT_BRANCH_COLOUR, thicker), solid where stable and dashed where not; one
    legend entry each, saying from which orbit it was continued."""
    for bid, w, period in branches:
        d = rows_of(full, bid)
        label = "period-%d branch %d, continued from the time-integrated\norbit at %.5g %s: max, min" % (
            period, bid, w * omega_scale, unit)
        for k, y in enumerate(ys):
            plot_branch(ax, d, y, ORBIT_BRANCH_COLOUR, x=x, scale=scale, label=None if k else label, lw=2.0)


def unstable_period1_ranges(kn, suffix="", what="unstable_period1", unit="omega"):
    """The frequency ranges [(from, to)] with no stable period-1 orbit, from the key numbers
    (key_numbers.json as read) <what>_ranges<suffix>, <what>_from_<unit><suffix>_k and
    <what>_to_<unit><suffix>_k; none where the run did not write them. what="unresolved_period1":
    the parts of those ranges whose stable labels are unresolved (lib period1_ranges)."""
    value = lambda v: v["value"] if isinstance(v, dict) else v
    n = int(value(kn.get(what + "_ranges" + suffix, 0)))
    return [(value(kn["%s_from_%s%s_%d" % (what, unit, suffix, k)]),
             value(kn["%s_to_%s%s_%d" % (what, unit, suffix, k)])) for k in range(1, n + 1)]


def unresolved_period1_ranges(kn, suffix="", unit="omega"):
    """unstable_period1_ranges' stretches whose stability is unresolved (unresolved_period1_* keys)."""
    return unstable_period1_ranges(kn, suffix, "unresolved_period1", unit)


def less(ranges, holes):
    """The parts of `ranges` [(a, b)] outside every interval of `holes`, in order."""
    out = []
    for a, b in ranges:
        at = a
        for c, d in sorted(holes):
            if d <= at or c >= b:
                continue
            if c > at:
                out.append((at, c))
            at = max(at, d)
        if at < b:
            out.append((at, b))
    return out


def range_text(ranges, scale, fmt="%.4g"):
    """"a-b, c-d" of up to three ranges, else "n ranges, from a to z" (x scaled by `scale`)."""
    if len(ranges) <= 3:
        return ", ".join((fmt + "-" + fmt) % (a * scale, b * scale) for a, b in ranges)
    return ("%d ranges, from " + fmt + " to " + fmt) % (len(ranges), ranges[0][0] * scale, ranges[-1][1] * scale)


def shade_unresolved_period1(axes, unresolved, scale=1.0, unit="rad/s", colour=UNRESOLVED_MARKER["mec"]):
    """Hatch (magenta: UNRESOLVED_MARKER's colour) the stretches where a period-1 orbit is labelled
    stable but no shooting correction converged (unresolved_period1_ranges) on every panel, with a
    dotted line at the middle of each so that a stretch narrower than the hatch is still seen; their
    legend entry (none without stretches)."""
    from matplotlib.patches import Patch
    for ax in axes:
        for a, b in unresolved:
            ax.axvspan(a * scale, b * scale, facecolor="none", edgecolor=colour, alpha=0.5, hatch="xxx", lw=0,
                       zorder=0)
            ax.axvline(0.5 * (a + b) * scale, color=colour, ls=":", lw=0.8, alpha=0.7, zorder=0)
    if not unresolved:
        return []
    return [Patch(facecolor="none", edgecolor=colour, alpha=0.6, hatch="xxx",
                  label="in a range with no stable period-1 orbit: labelled stable, but no\nshooting correction converged (stability unresolved: %s %s)"
                  % (range_text(unresolved, scale), unit))]


def shade_no_stable_period1(axes, ranges, unresolved=(), scale=1.0, unit="rad/s"):
    """Shade the ranges (unstable_period1_ranges) on every panel (x scaled by `scale`) grey, less
    their unresolved stretches (`unresolved`: unresolved_period1_ranges), which are hatched apart
    (shade_unresolved_period1); their legend entries, naming them in `unit` (none without ranges)."""
    from matplotlib.patches import Patch
    grey = less(ranges, unresolved)
    for ax in axes:
        for a, b in grey:
            ax.axvspan(a * scale, b * scale, color="0.5", alpha=0.12, lw=0, zorder=0)
    handles = [Patch(color="0.5", alpha=0.3, label="no stable period-1 orbit (%s %s)" % (range_text(ranges, scale), unit))] \
        if ranges else []
    return handles + shade_unresolved_period1(axes, unresolved, scale, unit)


def torque_colour(T, torques=THESIS_TORQUES):
    """The colour of torque T among the figure's `torques`: the thesis torques by value, others by
    rank (lightest blue, heaviest red; more than three from a sequential map)."""
    if float(T) in THESIS_TORQUES and all(float(t) in THESIS_TORQUES for t in torques):
        return TORQUE_PALETTE[THESIS_TORQUES.index(float(T))]
    ranked = sorted(float(t) for t in torques)
    i, n = ranked.index(float(T)), len(ranked)
    if n <= 3:
        return TORQUE_PALETTE[-1] if n == 1 else (TORQUE_PALETTE[0], TORQUE_PALETTE[-1])[i] if n == 2 else TORQUE_PALETTE[i]
    import matplotlib.cm
    return matplotlib.cm.plasma(0.1 + 0.75 * i / (n - 1))


def contact_rug(ax, d, x="omega", row=0, colour=None, scale=1.0):
    """The contact state along one curve as a thin band at the bottom of the axes (row `row`,
    counted upwards): gold where intermittent, grey where full, nothing where open. A short tick
    in the curve's colour at the left end names the row. Nothing hides the curves above."""
    from matplotlib.patches import Rectangle
    y0 = 0.004 + row * (RUG_HEIGHT + 0.006)
    tr = ax.get_xaxis_transform()
    xs = [v * scale for v in d[x]]
    for state, i0, i1 in runs(list(d["contact"])):
        if state in CONTACT_COLOURS:
            lo, hi = min(xs[i0:i1 + 1]), max(xs[i0:i1 + 1])
            if hi == lo:
                continue
            # a patch in (data x, axes y): it leaves the y autoscale alone (fill_between would add
            # y0..y0 + RUG_HEIGHT as data values and squash curves of millimetres to the bottom)
            ax.add_patch(Rectangle((lo, y0), hi - lo, RUG_HEIGHT, transform=tr, color=CONTACT_COLOURS[state],
                                   lw=0, zorder=1))
    if colour is not None:
        ax.plot([0.0, 0.012], [y0 + RUG_HEIGHT / 2] * 2, transform=ax.transAxes, color=colour, lw=3,
                solid_capstyle="butt", clip_on=False, zorder=2)


def rug_room(ax, rows=1):
    """Lower the y axis so the contact rug (rows at the bottom) lies below every curve."""
    lo, hi = ax.get_ylim()
    frac = 0.01 + rows * (RUG_HEIGHT + 0.006)
    if ax.get_yscale() == "log":
        import math
        llo, lhi = math.log10(lo), math.log10(hi)
        ax.set_ylim(10 ** ((llo - frac * lhi) / (1 - frac)), hi)
    else:
        ticks = [t for t in ax.get_yticks() if lo - 1e-12 * abs(hi - lo) <= t <= hi]
        ax.set_ylim((lo - frac * hi) / (1 - frac), hi)
        if lo == 0:   # a quantity that is never negative (an RMS): no tick below 0 beside the rug
            ax.set_yticks(ticks)


def legend_styles(ax=None):
    """Proxy legend entries explaining line styles and the contact rug."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    return [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
            Line2D([], [], color="k", ls="--", label="unstable (Floquet)"),
            Patch(color=CONTACT_COLOURS["intermittent"], label="intermittent contact (rug at the bottom)"),
            Patch(color=CONTACT_COLOURS["full"], label="full contact (rug at the bottom)")]


def bifurcation_handles(kinds, colour=None):
    """Legend entries for the bifurcation types drawn (colour None: each type's own colour)."""
    from matplotlib.lines import Line2D
    return [Line2D([], [], ls="none", marker=BIFURCATION_MARKERS[k], color=colour or BIFURCATION_COLOURS[k],
                   mfc="none", ms=7, label=k.replace("_", " ")) for k in kinds]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return str(path)
