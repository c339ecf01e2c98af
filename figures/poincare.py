"""The bifurcation diagram by time integration (issue 34 section 3), shared by frc.py and
gearhb_gear.py: the Poincare points (the coordinate once per forcing period, at phase 0)
of bifurcation_diagram.csv over the HB branch at the same phase (bifurcation_diagram_hb.csv,
solid where stable, dashed where unstable).

One convention: the motion's colour (MOTION_COLOURS), the sweep's marker (up: dot, down:
small x; from_hb, the time integration started on a stable HB orbit that no sweep reached at its
speed: a hollow diamond, drawn in every panel with sweeps=with_hb_starts(...), its legend entry
only where the table has such rows); a period-n speed draws its n points, any other speed its
whole cloud. The diagram covers
its bands (column band: by default the ranges with no stable period-1 orbit, padded), the HB
section the whole branch."""
from matplotlib.lines import Line2D

from style import ORBIT_BRANCH_COLOUR, PERIOD2_COLOURS, plot_branch

MOTION_COLOURS = {"periodic_1": "0.15", "periodic_n": "C0", "quasi_periodic": "C2", "chaotic": "C3",
                  "unsettled": "C1"}
MOTION_LABELS = {"periodic_1": "period 1", "periodic_n": "period n >= 2 (n points)",
                 "quasi_periodic": "quasi-periodic (|Lyapunov| < 0.02, no attracting cycle)", "chaotic": "chaotic (Lyapunov > 0)",
                 "unsettled": "not settled (no period <= limit, Lyapunov < 0)"}
SWEEP_MARKERS = {"up": ".", "down": "x", "from_hb": "D"}
SWEEP_LABELS = {"up": "time integration, sweep up", "down": "time integration, sweep down",
                "from_hb": "time integration started on a stable HB orbit\nno sweep reached (hollow)"}
BRANCH_COLOURS = PERIOD2_COLOURS   # the response panels' colours, none the diagram's green
ZORDER = {"chaotic": 4, "periodic_1": 5, "periodic_n": 5, "quasi_periodic": 6, "unsettled": 6}   # the rare ones on top


def with_hb_starts(sweeps=("up", "down")):
    """The sweeps to draw and the starts on HB orbits (sweep from_hb): they belong to no sweep,
    so every panel of a diagram draws them beside its own sweep(s)."""
    return tuple(sweeps) + ("from_hb",)


def hb_starts_text(d):
    """A panel title's second line where the table d has from_hb rows, else ''."""
    return "\nhollow diamonds: started on a stable HB orbit no sweep reached" if "from_hb" in d["sweep"] else ""


def motion_key(motion, n):
    if motion == "periodic":
        return "periodic_1" if int(n) == 1 else "periodic_n"
    return motion


def draw_poincare(ax, d, x, y, scale=1.0, sweeps=("up", "down"), keep=None):
    """The Poincare points of the table d (columns x, y, sweep, motion, n), y times scale;
    keep(i) (optional) selects rows. Returns the legend handles of what was drawn."""
    drawn = set()
    for sweep in sweeps:
        groups = {}
        for i in range(len(d[x])):
            if d["sweep"][i] != sweep or (keep and not keep(i)):
                continue
            groups.setdefault(motion_key(d["motion"][i], d["n"][i]), []).append(i)
        for key, idx in groups.items():
            hollow = {"mfc": "none", "ms": 5.0, "mew": 0.9} if sweep == "from_hb" else {}
            ax.plot([d[x][i] for i in idx], [d[y][i] * scale for i in idx], ls="none",
                    **{"marker": SWEEP_MARKERS[sweep], "ms": 2.5 if sweep == "up" else 2.2, "mew": 0.6,
                       "color": MOTION_COLOURS[key], "zorder": ZORDER[key], **hollow})
            drawn.add((key, sweep))
    handles = [Line2D([], [], ls="none", marker="s", ms=5, color=MOTION_COLOURS[k], label=MOTION_LABELS[k])
               for k in MOTION_COLOURS if any(k == key for key, _ in drawn)]
    handles += [Line2D([], [], ls="none", marker=SWEEP_MARKERS[s], color="0.3", mfc="none" if s == "from_hb" else "0.3",
                       label=SWEEP_LABELS[s]) for s in sweeps if any(s == sw for _, sw in drawn)]
    return handles


def subset(h, keep):
    return {c: [v[i] for i in range(len(v)) if keep(i)] for c, v in h.items()}


def draw_hb_section(ax, h, x, y, scale=1.0, colour="0.55", label="HB period 1 at the same phase", unresolved=(),
                    orbit=()):
    """The HB branches' values at phase 0 (bifurcation_diagram_hb.csv), solid stable, dashed
    unstable: period 1 (branch 0) in grey; where the table has the period and branch columns,
    each period-p branch's p values per orbit (the rows of a point come p at a time: its forcing
    periods j = 0..p-1) as p lines in the branch's colour (the response panel's). Legend entries only for the styles drawn:
    one per branch up to three branches, else one per period ("a colour each", as the response
    panel says it: the colours repeat beyond five). The period-1 line is grey at
    the indices `unresolved` of its rows (style.plot_branch). The branch ids in `orbit` (branches
    continued from a time-integrated orbit, style.orbit_branches) in ORBIT_BRANCH_COLOUR, thicker,
    a legend entry each."""
    h = subset(h, lambda i: h["point"][i] == "branch") if "point" in h else h   # the speed rows are for checks
    branch = [int(float(b)) for b in h["branch"]] if "branch" in h else [0] * len(h[x])
    one = subset(h, lambda i: branch[i] == 0)
    handles = []
    if one[x]:
        plot_branch(ax, one, y, colour, None, x=x, scale=scale, values="hb", unresolved=unresolved)
        drawn = {int(float(s)) for s in one["stable"]}
        handles += [Line2D([], [], color=colour, ls=ls, label="%s (%s)" % (label, word))
                    for flag, ls, word in ((1, "-", "stable"), (0, "--", "unstable")) if flag in drawn]
    for bid in sorted(set(orbit) & set(branch)):
        rows = subset(h, lambda i: branch[i] == bid)
        period = int(float(rows["period"][0]))
        for j in range(period):
            plot_branch(ax, subset(rows, lambda i: i % period == j), y, ORBIT_BRANCH_COLOUR, None, x=x, scale=scale,
                        values="hb", lw=1.8)
        handles.append(Line2D([], [], color=ORBIT_BRANCH_COLOUR, lw=1.8, label="HB period %d (branch %d) continued from "
                              "a time-integrated orbit%s" % (period, bid, ", its %d points" % period if period > 1 else "")))
    ids = sorted({b for b in branch if b > 0} - set(orbit))
    named = set()
    for n, bid in enumerate(ids):
        rows = subset(h, lambda i: branch[i] == bid)
        period, c = int(float(rows["period"][0])), BRANCH_COLOURS[n % len(BRANCH_COLOURS)]
        for j in range(period):
            plot_branch(ax, subset(rows, lambda i: i % period == j), y, c, None, x=x, scale=scale, values="hb", lw=1.1)
        for flag, ls, word in ((1, "-", "stable"), (0, "--", "unstable")):
            if flag not in {int(float(s)) for s in rows["stable"]}:
                continue
            if len(ids) <= 3:
                handles.append(Line2D([], [], color=c, ls=ls, label="HB period %d (branch %d), its %d points (%s)"
                                      % (period, bid, period, word)))
            elif (period, flag) not in named:
                named.add((period, flag))
                handles.append(Line2D([], [], color="0.35", ls=ls, label="HB period-%d branches (a colour each), "
                                      "their %d points (%s)" % (period, period, word)))
    return handles


def band_spans(d, x):
    """[(lo, hi)] of the diagram's x per band (column band, 1, 2, ...; one span without it)."""
    bands = d["band"] if "band" in d else [1] * len(d[x])
    spans = {}
    for b, v in zip(bands, d[x]):
        lo, hi = spans.get(b, (v, v))
        spans[b] = (min(lo, v), max(hi, v))
    return [spans[b] for b in sorted(spans)]


def number(v):
    """4 digits, whole numbers from 1000 up (no exponent)."""
    return "%.0f" % v if abs(v) >= 1000 else "%.4g" % v


def bands_text(d, x, unit):
    """'over 0.33-0.41 rad/s' or 'over 2 bands: 0.33-0.41, 0.9-1.2 rad/s': where the diagram was computed."""
    spans = band_spans(d, x)
    text = ", ".join("%s-%s" % (number(a), number(b)) for a, b in spans)
    return "over %s%s %s" % ("%d bands: " % len(spans) if len(spans) > 1 else "", text, unit)


def within(h, x, lo, hi):
    """The rows of table h with x in [lo, hi] and their neighbours (the HB section over a diagram's own
    window: its line runs on to the window's edges, where the axis clips it)."""
    inside = [lo <= v <= hi for v in h[x]]
    keep = [i for i in range(len(inside)) if any(inside[max(i - 1, 0):i + 2])]
    return {c: [v[i] for i in keep] for c, v in h.items()}


def window(d, x, margin=0.02):
    """(lo, hi): the diagram's span of x (all its bands), widened by margin of it on either side."""
    lo, hi = min(d[x]), max(d[x])
    return lo - margin * (hi - lo), hi + margin * (hi - lo)


def value_limits(d, h, x, y, lo, hi, margin=0.05):
    """y limits that hold the diagram's points and the HB section's values with x in [lo, hi]."""
    ys = list(d[y]) + [v for u, v in zip(h[x], h[y]) if lo <= u <= hi]
    a, b = min(ys), max(ys)
    pad = margin * (b - a) if b > a else 0.05 * abs(a) + 1e-12
    return a - pad, b + pad
