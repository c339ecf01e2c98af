#!/usr/bin/env python3
"""Draw the figures of a gearhb_planetary run: gearhb_planetary.py DIR

Writes into DIR (the run's own folder; gearhb_planetary calls this with plot=1):
  modes.png     one mode shape of each type (the lowest nonzero rotational, translational
                and planet mode): every body drawn at rest (grey) and displaced (colour),
                its rotation as the turned spoke; the displacement scaled to be seen;
  response.png  (with a `response` section) the sun's vibration over the mesh frequency
                (AC RMS of its rotation u_s, response.csv's x_rms_ac, and of its centre), solid
                where stable and dashed where not (Floquet), and the largest dynamic factor K_v
                of the sun-planet and ring-planet meshes, the frequencies where a mesh loses
                contact as a rug per branch; the period-2 (4) branches switched at the period
                doublings (rows with branch > 0) each in its own colour, over two mesh periods;
                the ranges with no stable period-1 orbit shaded (key numbers unstable_period1_*);
                with a bifurcation diagram (bifurcation_diagram.csv) a third panel: the sun's
                rotation u_s at phase 0 of every mesh period by time integration (poincare.py) over
                the HB orbits at the same phase (bifurcation_diagram_hb.csv: period 1 grey, each
                period-2 (4) branch in its colour, one line per Poincare point of its orbit);
  bifurcation_diagram.png  (with a diagram) the same Poincare points and HB orbits, the up sweep
                above and the down sweep below, over the diagram's bands only;
  meshes.png    (with `response`) every mesh over the mesh frequency: its dynamic factor K_v
                (one line per planet, sun-planet and ring-planet meshes in two panels) and its
                contact class along the curve as one band per mesh (drive-flank loss, back-flank
                impact); a period-2 branch's meshes as dotted lines with its own contact bands;
  load_sharing.png  (with `response`) the planet load-sharing factor of every planet over the
                mesh frequency (a period-2 branch dotted);
  campbell.png  (with `campbell`) the natural frequencies over carrier speed;
  mesh_stiffness.png  (with mesh.stiffness tooth_model) k(theta) of the sun-planet and the
                ring-planet meshes over one mesh cycle, their means dotted;
  phasing.png   (with `response`) the largest amplitude over the curve of each mesh harmonic
                of the sun's rotation and centre, with the mode family mesh phasing lets the
                harmonic drive (sun_harmonics.csv's phasing column).
"""
import json
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

from poincare import BRANCH_COLOURS, draw_hb_section, draw_poincare  # noqa: E402
from style import (BIFURCATION_COLOURS, BIFURCATION_MARKERS, CONTACT_COLOURS, RUG_HEIGHT,  # noqa: E402
                   bifurcation_handles, branch_ids, plot_branch, read_csv, rows_of, rug_room, runs, save,
                   shade_no_stable_period1, unresolved_period1_ranges, unstable_period1_ranges)

COLOURS = {"rotational": "C0", "translational": "C1", "planet": "C2"}
# The period-2 (4) branches' colours: the project's, without the diagram's quasi-periodic colour (the
# Poincare points are drawn under the same branches).



def geometry(params):
    t, m = params["teeth"], params["module"]
    return {"sun": 0.5 * t["sun"] * m, "planet": 0.5 * t["planet"] * m, "ring": 0.5 * t["ring"] * m,
            "a": 0.5 * (t["sun"] + t["planet"]) * m}


def body_circle(ax, cx, cy, r, colour, ls="-", lw=1.0):
    ax.add_patch(plt.Circle((cx, cy), r, fill=False, color=colour, ls=ls, lw=lw))


def spoke(ax, cx, cy, r, angle, colour):
    ax.plot([cx, cx + r * math.cos(angle)], [cy, cy + r * math.sin(angle)], color=colour, lw=1.0)


def draw_shape(ax, rows, g, colour):
    """rows: the mode_shapes.csv rows of one mode; shapes scaled so the largest move is 0.15 a."""
    largest = max(max(abs(r["x"]), abs(r["y"]), abs(r["u"])) for r in rows) or 1.0
    s = 0.15 * g["a"] / largest
    for r in rows:
        name = r["body"]
        if name.startswith("planet"):
            psi = math.radians(r["psi_deg"])
            cx, cy, rad = g["a"] * math.cos(psi), g["a"] * math.sin(psi), g["planet"]
        else:
            cx, cy, rad = 0.0, 0.0, g["a"] if name == "carrier" else g[name]
        ls = "--" if name == "carrier" else "-"
        body_circle(ax, cx, cy, rad, "0.75", ls)
        spoke(ax, cx, cy, rad, math.pi / 2, "0.75")
        dx, dy, turn = s * r["x"], s * r["y"], s * r["u"] / rad
        body_circle(ax, cx + dx, cy + dy, rad, colour, ls, 1.3)
        spoke(ax, cx + dx, cy + dy, rad, math.pi / 2 + turn, colour)


def modes_figure(d_dir, params):
    modes, shapes = read_csv(d_dir / "modes.csv"), read_csv(d_dir / "mode_shapes.csv")
    g = geometry(params)
    chosen = []
    for kind in ("rotational", "translational", "planet"):
        for i, t in enumerate(modes["mode_type"]):
            if t == kind and modes["frequency_hz"][i] > 1e-3 * max(modes["frequency_hz"]):
                chosen.append((kind, i))
                break
    fig, axes = plt.subplots(1, len(chosen), figsize=(3.6 * len(chosen), 4.0))
    axes = [axes] if len(chosen) == 1 else axes
    for ax, (kind, i) in zip(axes, chosen):
        number = modes["mode"][i]
        rows = [{k: shapes[k][j] for k in shapes} for j in range(len(shapes["mode"])) if shapes["mode"][j] == number]
        draw_shape(ax, rows, g, COLOURS[kind])
        lim = 1.15 * g["ring"]
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("%s mode %d: %.1f Hz\nmultiplicity %d" % (kind, number, modes["frequency_hz"][i],
                                                               modes["multiplicity"][i]), fontsize=9)
    fig.suptitle("%s, N = %d (carrier speed 0, as in modes.csv):\nrest grey, mode shape in colour (scaled)"
                 % (params.get("name", "planetary set"), params["planets"]), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    fig.savefig(d_dir / "modes.png")
    plt.close(fig)
    return str(d_dir / "modes.png")


def read_response(d_dir):
    """response.csv split by branch: the period-1 curve (branch 0) and the period-doubled branches
    [(id, period, rows)]."""
    full = read_csv(d_dir / "response.csv")
    doubled = []
    for bid in branch_ids(full):
        rows = rows_of(full, bid)
        doubled.append((bid, int(rows["period"][0]), rows))
    return rows_of(full, 0), doubled


def shade_unstable_period1(d_dir, axes):
    """Shade the mesh-frequency ranges with no stable period-1 orbit on every panel (their unresolved
    stretches hatched apart); the legend entries."""
    kn_file = d_dir / "key_numbers.json"
    kn = json.load(open(kn_file)) if kn_file.exists() else {}
    return shade_no_stable_period1(axes, unstable_period1_ranges(kn), scale=1.0 / (2.0 * math.pi), unit="Hz",
                                   unresolved=unresolved_period1_ranges(kn))


def largest_kv(d, kind, N):
    return [max(d["dynamic_factor_%s_%d" % (kind, n + 1)][i] for n in range(N)) for i in range(len(d["f_mesh_hz"]))]


RUG_ROW = 0.04   # axes fraction per row of the loss rug (its ticks of 6 points)


def loss_rug(ax, d, kind, N, colour, row, label):
    """Ticks at the frequencies where a drive flank of a `kind` mesh loses contact, in rug row `row`."""
    hz = d["f_mesh_hz"]
    loss = [hz[i] for i in range(len(hz)) if any("drive_loss" in d["contact_%s_%d" % (kind, n + 1)][i] for n in range(N))]
    ax.plot(loss, [0.02 + RUG_ROW * row] * len(loss), "|", color=colour, ms=6, transform=ax.get_xaxis_transform(),
            label=label if loss else None)


def read_diagram(d_dir):
    """(diagram, HB section) of the run, or None without a bifurcation diagram."""
    if not (d_dir / "bifurcation_diagram.csv").exists():
        return None
    return read_csv(d_dir / "bifurcation_diagram.csv"), read_csv(d_dir / "bifurcation_diagram_hb.csv")


def diagram_panel(ax, p, h, sweeps, title=None):
    """The Poincare points of u_s over the HB orbits at phase 0 (poincare.draw_hb_section: period 1
    and each period-p branch's p points per orbit)."""
    handles = draw_hb_section(ax, h, "f_mesh_hz", "u_s_um")
    handles += draw_poincare(ax, p, "f_mesh_hz", "u_s_um", sweeps=sweeps)
    ax.set_ylabel("sun rotation u_s at phase 0\nof each mesh period [um]")
    if title:
        ax.set_title(title, fontsize=8)
    return handles


def diagram_figure(d_dir, params, diagram):
    """bifurcation_diagram.png: the up sweep above, the down sweep below."""
    p, h = diagram
    fig, axes = plt.subplots(2, 1, figsize=(7.4, 7.0), sharex=True)
    labels = {}
    for ax, sweep in zip(axes, ("up", "down")):
        for hd in diagram_panel(ax, p, h, (sweep,), "sweep %s (each speed but its first from the previous speed's final state)"
                                % sweep):
            labels.setdefault(hd.get_label(), hd)
    lo, hi = min(p["f_mesh_hz"]), max(p["f_mesh_hz"])
    axes[-1].set_xlim(lo - 0.02 * (hi - lo), hi + 0.02 * (hi - lo))
    axes[-1].set_xlabel("mesh frequency [Hz]")
    for ax in axes:   # the y range of what is drawn inside the bands (the HB lines run over the whole curve)
        ys = list(p["u_s_um"]) + [y for x, y in zip(h["f_mesh_hz"], h["u_s_um"]) if lo <= x <= hi]
        pad = 0.05 * (max(ys) - min(ys)) or 1e-3
        ax.set_ylim(min(ys) - pad, max(ys) + pad)
    fig.suptitle("%s, N = %d planets: bifurcation diagram by time integration\n(Poincare section at phase 0 of the mesh cycle)"
                 % (params.get("name", "planetary set"), params["planets"]), fontsize=9)
    axes[-1].legend(handles=list(labels.values()), fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2),
                    ncol=2, frameon=False)
    fig.tight_layout()
    fig.savefig(d_dir / "bifurcation_diagram.png", bbox_inches="tight")
    plt.close(fig)


def response_figure(d_dir, params):
    d, doubled = read_response(d_dir)
    N = params["planets"]
    diagram = read_diagram(d_dir)
    fig, axes = plt.subplots(3 if diagram else 2, 1, figsize=(7.4, 9.6 if diagram else 6.8), sharex=True)
    top, bottom = axes[0], axes[1]
    bif = read_bifurcations(d_dir)
    curve(top, d, "x_rms_ac", "C0", "sun rotation u_s (AC RMS)", scale=1e6)
    curve(top, d, "sun_xy_rms_um", "C1", "sun centre x, y (AC RMS)")
    for n, (bid, period, d2) in enumerate(doubled):
        colour = BRANCH_COLOURS[n % len(BRANCH_COLOURS)]
        curve(top, d2, "x_rms_ac", colour, "period %d (branch %d): u_s and x, y,\nover %d mesh periods" % (period, bid, period),
              scale=1e6)
        curve(top, d2, "sun_xy_rms_um", colour)
    bifurcation_marks(top, bif)
    top.set_ylabel("um")
    top.set_yscale("log")
    shaded = shade_unstable_period1(d_dir, axes)
    top.legend(handles=top.get_legend_handles_labels()[0] + stability_handles(d, bif, doubled) + shaded,
               loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    rows = 0
    for kind, colour in (("sun", "C0"), ("ring", "C3")):
        bottom.plot(d["f_mesh_hz"], largest_kv(d, kind, N), color=colour, label="%s-planet meshes: largest K_v" % kind)
        loss_rug(bottom, d, kind, N, colour, rows, "%s-planet drive flank loses contact" % kind)
        rows += 1
    for n, (bid, period, d2) in enumerate(doubled):
        colour = BRANCH_COLOURS[n % len(BRANCH_COLOURS)]
        for kind, ls in (("sun", "-"), ("ring", "-.")):
            bottom.plot(d2["f_mesh_hz"], largest_kv(d2, kind, N), color=colour, ls=ls,
                        label="period %d (branch %d): %s-planet K_v" % (period, bid, kind))
            loss_rug(bottom, d2, kind, N, colour, rows, "branch %d: %s-planet drive flank loses contact" % (bid, kind))
            rows += 1
    rug_room(bottom, rows=math.ceil(rows * RUG_ROW / (RUG_HEIGHT + 0.006)))
    bottom.set_ylabel("K_v: largest force / static force")
    axes[-1].set_xlabel("mesh frequency [Hz]")
    bottom.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
                  title="rug: one row per branch and mesh kind" if doubled else None, title_fontsize=8)
    if diagram:
        handles = diagram_panel(axes[2], *diagram, ("up", "down"))
        p = diagram[0]
        ys = list(p["u_s_um"])
        pad = 0.1 * (max(ys) - min(ys)) or 1e-3
        axes[2].set_ylim(min(ys) - pad, max(ys) + pad)   # the Poincare points' range (HB lines run beyond)
        axes[2].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7)
    fig.suptitle("%s, N = %d planets, %g N m on the %s" % (params.get("name", "planetary set"), N,
                                                           params["response"]["torque"],
                                                           params["response"]["input"]), fontsize=10)
    return save(fig, d_dir / "response.png")


def phasing_figure(d_dir, params):
    d = read_csv(d_dir / "sun_harmonics.csv")
    H = int(max(d["harmonic"]))
    u = [max(v for v, l in zip(d["u_um"], d["harmonic"]) if l == k) for k in range(1, H + 1)]
    xy = [max(v for v, l in zip(d["xy_um"], d["harmonic"]) if l == k) for k in range(1, H + 1)]
    family = [next(f for f, l in zip(d["phasing"], d["harmonic"]) if l == k) for k in range(1, H + 1)]
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    ls = list(range(1, H + 1))
    floor = 1e-10 * max(u + xy)   # a harmonic that phasing cancels is round-off: drawn at the floor
    ax.bar([l - 0.18 for l in ls], [max(v, floor) for v in u], width=0.36, color="C0", label="sun rotation u_s")
    ax.bar([l + 0.18 for l in ls], [max(v, floor) for v in xy], width=0.36, color="C1", label="sun centre x, y")
    ax.set_yscale("log")
    ax.set_ylim(floor / 3, max(u + xy) * 30)
    for l, f in zip(ls, family):
        if f == f and f:
            ax.text(l, max(u + xy) * 3, {"rotational": "rot.", "translational": "transl.", "none": "none"}[f],
                    ha="center", fontsize=7)
    ax.set_xticks(ls)
    ax.set_xlabel("mesh harmonic l")
    ax.set_ylabel("largest amplitude over the curve [um]\n(bottom: below 1e-10 of the largest)")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ruled = any(f == f and f for f in family)
    ax.set_title("%s, N = %d, z_s = %d\n%s"
                 % (params.get("name", "planetary set"), params["planets"], params["teeth"]["sun"],
                    "above the bars: the family harmonic l may drive (l z_s mod N)" if ruled else
                    "not cyclically symmetric (unequal spacing, pin errors or unequal backlash): no phasing rule"),
                 fontsize=9)
    return save(fig, d_dir / "phasing.png")


# A mesh's contact class as the rug's state: drive-flank loss drawn as intermittent contact,
# full contact left blank (the figure says so).
RUG_STATE = {"drive_loss": "intermittent", "back_impact": "back_impact", "drive_loss+back_impact": "drive_loss+back_impact"}


def evaluated(d):
    return any(s == s for s in d["stable"])


def curve(ax, d, y, colour, label=None, lw=1.1, scale=1.0):
    """Column y (x scale) over the mesh frequency: solid where stable, dashed where unstable
    (Floquet at every point); one solid line where the run computed no stability."""
    if evaluated(d):
        plot_branch(ax, d, y=y, color=colour, label=label, x="f_mesh_hz", lw=lw, scale=scale)
    else:
        ax.plot(d["f_mesh_hz"], [v * scale for v in d[y]], color=colour, lw=lw, label=label)


def doubled_curve(ax, d2, y, colour, label=None):
    """A period-2 branch's column y: dotted, thin, with its points (its own style beside the
    period-1 lines of the same colour); unstable points hollow."""
    ax.plot(d2["f_mesh_hz"], d2[y], color=colour, ls=":", lw=1.0, label=label)
    for stable, fill in ((1, colour), (0, "none")):
        keep = [i for i, s in enumerate(d2["stable"]) if s == stable]
        ax.plot([d2["f_mesh_hz"][i] for i in keep], [d2[y][i] for i in keep], ls="none", marker="o", ms=3.5,
                color=colour, mfc=fill)


def read_bifurcations(d_dir):
    path = d_dir / "bifurcations.csv"
    return read_csv(path) if path.exists() else {"type": [], "omega": []}


def bifurcation_marks(ax, bif):
    """The located bifurcations as marks just above the axes at their frequencies.
    Not on the curves: bifurcations.csv does not say on which step of the curve each lies,
    and on a folded curve several steps share a frequency (the dashed stretches show where
    the curve is unstable)."""
    for t, w in zip(bif["type"], bif["omega"]):
        ax.plot(w / (2.0 * math.pi), 1.025, ls="none", marker=BIFURCATION_MARKERS[t], color=BIFURCATION_COLOURS[t],
                mfc="none", ms=6, transform=ax.get_xaxis_transform(), clip_on=False, zorder=4)


def stability_handles(d, bif, doubled=()):
    """Legend entries: the line styles present (if stability was computed; over the period-1 rows d
    and the period-doubled branches' rows) and the bifurcation kinds drawn (of every branch)."""
    from matplotlib.lines import Line2D
    if not evaluated(d):
        return [Line2D([], [], ls="none", label="(no stability computed)")]
    flags = list(d["stable"]) + [x for _, _, d2 in doubled for x in d2["stable"]]
    stable, unstable = any(x == 1 for x in flags), any(x == 0 for x in flags)
    return (([Line2D([], [], color="0.3", ls="-", label="stable (Floquet)" if unstable else "stable (Floquet) everywhere")]
             if stable else []) +
            ([Line2D([], [], color="0.3", ls="--", label="unstable (Floquet)" if stable else "unstable (Floquet) everywhere")]
             if unstable else []) +
            [h for h in bifurcation_handles([k for k in BIFURCATION_MARKERS if k in bif["type"]])
             if not h.set_label(h.get_label() + (" (above the axes; of every branch)" if doubled else " (above the axes)"))])


def contact_on_curve(ax, d, y, column, colour):
    """A mesh's contact class drawn on its own curve (y over the mesh frequency), point by point
    along the branch: a broad translucent stroke under the line where the class is not full
    contact. It follows the branch through a fold, so the stretches of a folded curve never lie
    on one another as bands over the frequency axis would."""
    xs, ys, states = d["f_mesh_hz"], d[y], d[column]
    for state, i0, i1 in runs(list(states)):
        if state in RUG_STATE:
            j0, j1 = max(i0 - 1, 0), min(i1 + 1, len(xs) - 1)   # half a step on either side
            px = [0.5 * (xs[j0] + xs[i0])] + list(xs[i0:i1 + 1]) + [0.5 * (xs[i1] + xs[j1])]
            py = [0.5 * (ys[j0] + ys[i0])] + list(ys[i0:i1 + 1]) + [0.5 * (ys[i1] + ys[j1])]
            ax.plot(px, py, color=CONTACT_COLOURS[RUG_STATE[state]], lw=7, alpha=0.55, solid_capstyle="butt",
                    zorder=1)


def meshes_figure(d_dir, params):
    d, doubled = read_response(d_dir)
    hz, N = d["f_mesh_hz"], params["planets"]
    fig, axes = plt.subplots(2, 1, figsize=(7.6, 7.0), sharex=True)
    bif = read_bifurcations(d_dir)
    for ax, kind in zip(axes, ("sun", "ring")):
        for n in range(N):
            y = "dynamic_factor_%s_%d" % (kind, n + 1)
            contact_on_curve(ax, d, y, "contact_%s_%d" % (kind, n + 1), "C%d" % n)
            curve(ax, d, y, "C%d" % n, "planet %d" % (n + 1))
            for bid, period, d2 in doubled:
                contact_on_curve(ax, d2, y, "contact_%s_%d" % (kind, n + 1), "C%d" % n)
                doubled_curve(ax, d2, y, "C%d" % n)
        bifurcation_marks(ax, bif)
        ax.set_ylabel("%s-planet meshes: K_v" % kind)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, title="mesh of", title_fontsize=8)
    from matplotlib.patches import Patch
    seen = {c for rows in [d] + [d2 for _, _, d2 in doubled] for k in ("sun", "ring") for n in range(N)
            for c in rows["contact_%s_%d" % (k, n + 1)]}
    classes = [(c, text) for c, text in (("drive_loss", "drive flank loses contact"), ("back_impact", "back flank hits"),
                                         ("drive_loss+back_impact", "both")) if c in seen]
    axes[1].legend(handles=stability_handles(d, bif, doubled) + doubled_handles(doubled) +
                   [Patch(color=CONTACT_COLOURS[RUG_STATE[c]], alpha=0.55, label=text) for c, text in classes] +
                   [Patch(color="white", ec="0.6", label="no stroke: full contact" if classes
                          else "full contact everywhere (no stroke)")],
                   loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
                   title="stability; contact class:\na broad stroke under\nthe mesh's own curve", title_fontsize=8)
    axes[1].set_xlabel("mesh frequency [Hz]\n(sun speed relative to the carrier: 60 f / z_s rpm)")
    back = params["mesh"].get("sun_planet_backlash", params["mesh"].get("ring_planet_backlash"))
    alike = all(abs(d["dynamic_factor_%s_%d" % (k, n + 1)][i] - d["dynamic_factor_%s_1" % k][i]) < 5e-3
                for k in ("sun", "ring") for n in range(N) for i in range(len(hz)))
    fig.suptitle("%s, %g N m on the %s:\nK_v = largest |drive - back force| / static force, %s"
                 % (params.get("name", "planetary set"), params["response"]["torque"], params["response"]["input"],
                    ("back flanks at the file's backlash" if back is not None else "drive flanks only (no backlash given)") +
                    ("\nevery planet's mesh alike (to the 1e-3 of the sampled maxima): the lines lie on one another"
                     if alike else "")),
                 fontsize=9)
    return save(fig, d_dir / "meshes.png")


def doubled_handles(doubled):
    """Legend entry of the period-doubled branches' style (none without them)."""
    from matplotlib.lines import Line2D
    periods = sorted({period for _, period, _ in doubled})
    return [Line2D([], [], color="0.3", ls=":", marker="o", ms=3.5, mfc="none",
                   label="period-%s branches: dotted, points\n(hollow: unstable), over %s mesh periods"
                   % ("/".join(map(str, periods)), "/".join(map(str, periods))))] if doubled else []


def load_sharing_figure(d_dir, params):
    d, doubled = read_response(d_dir)
    N = params["planets"]
    errors = params.get("planet", {}).get("pin_errors")
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    for n in range(N):
        label = "planet %d" % (n + 1) + ("" if errors is None else ", pin error %g um" % (1e6 * errors[n]))
        curve(ax, d, "load_sharing_planet_%d" % (n + 1), "C%d" % n, label)
        for _, _, d2 in doubled:
            doubled_curve(ax, d2, "load_sharing_planet_%d" % (n + 1), "C%d" % n)
    ax.axhline(1.0, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("planet load-sharing factor L_n")
    ax.legend(handles=ax.get_legend_handles_labels()[0] + doubled_handles(doubled),
              loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    stability = ("no stability computed" if not evaluated(d) else
                 "dashed where unstable" if any(x == 0 for x in d["stable"]) else "stable everywhere (Floquet)")
    ax.set_title("%s:\nL_n = N max F_sn / sum_m max F_sm (F_sn the drive-flank force\nof sun-planet mesh n over the period;"
                 " %s)" % (params.get("name", "planetary set"), stability), fontsize=9, loc="left")
    return save(fig, d_dir / "load_sharing.png")


def mesh_stiffness_figure(d_dir, params):
    """mesh_stiffness.png: k(theta) of both mesh kinds over one mesh cycle, as computed from the teeth."""
    d = read_csv(d_dir / "mesh_stiffness.csv")
    mesh = params["mesh"]
    sun_model = mesh["sun_planet_pair"].get("model", {}).get("method", "fe")
    ring_model = mesh.get("ring_planet_stiffness", "potential_energy")
    names = {"potential_energy": "potential energy", "beam": "beam model", "fe": "finite elements",
             "iso6336": "ISO 6336-1 rectangular wave"}
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    for col, colour, label in (("k_sun_planet_N_per_m", "C0", "sun-planet (%s, gearhb_gear's pair)" % names[sun_model]),
                               ("k_ring_planet_N_per_m", "C3", "ring-planet (%s, internal)" % names[ring_model])):
        k = [v / 1e9 for v in d[col]]
        ax.step(d["phase"] + [1.0], k + [k[-1]], where="post", color=colour, lw=1.2, label=label)
        mean = sum(k) / len(k)
        ax.axhline(mean, color=colour, lw=0.8, ls=":")
    ax.set_xlim(0.0, 1.0)
    ax.set_xlabel("phase of the mesh cycle (0: a pair enters at A)")
    ax.set_ylabel("mesh stiffness k [GN/m]")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=1, fontsize=8)
    ax.set_title("%s\nmesh stiffness from the teeth at the static load (dotted: the means, the linear model's "
                 "k_sp and k_rp)" % params.get("name", "planetary set"), fontsize=9)
    return save(fig, d_dir / "mesh_stiffness.png")


def campbell_figure(d_dir, params):
    d = read_csv(d_dir / "campbell.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for mode in sorted(set(d["mode"])):
        rows = [i for i, m in enumerate(d["mode"]) if m == mode]
        ax.plot([d["carrier_rpm"][i] for i in rows], [d["frequency_hz"][i] for i in rows], color="C0", lw=1.0)
    ax.set_xlabel("carrier speed [rpm]")
    ax.set_ylabel("natural frequency in the carrier frame [Hz]")
    ax.set_title("%s, N = %d: Campbell diagram\n(gyroscopic and centripetal terms; each line the k-th\n"
                 "frequency at each speed, not a mode followed)"
                 % (params.get("name", "planetary set"), params["planets"]), fontsize=9)
    return save(fig, d_dir / "campbell.png")


def main():
    d_dir = pathlib.Path(sys.argv[1])
    params = json.load(open(d_dir / "params.json"))
    modes_figure(d_dir, params)
    if (d_dir / "campbell.csv").exists():
        campbell_figure(d_dir, params)
    if (d_dir / "mesh_stiffness.csv").exists():
        mesh_stiffness_figure(d_dir, params)
    if "response" in params and (d_dir / "response.csv").exists():
        response_figure(d_dir, params)
        if (d_dir / "bifurcation_diagram.csv").exists():
            diagram_figure(d_dir, params, read_diagram(d_dir))
        meshes_figure(d_dir, params)
        load_sharing_figure(d_dir, params)
        phasing_figure(d_dir, params)


if __name__ == "__main__":
    main()
