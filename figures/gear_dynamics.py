"""The dynamics figures of a gearhb_gear run with a speed range (called by gearhb_gear.py).

Writes into DIR:
  response.png      DTE RMS and the dynamic factor K_v against the speed of gear 1, one colour
                    per torque, stable solid and unstable dashed (Floquet), bifurcations marked
                    (fold o, period doubling s, Neimark-Sacker D) on the curve of their branch,
                    the period-2 branches (frc_<i>.csv rows of period 2) in colours of their own,
                    each branch continued from a time-integrated orbit of the diagram that lies on
                    none of the others (key numbers orbit_branch_*_<i>_<k>) in brown, thicker
                    (style.ORBIT_BRANCH_COLOUR), and its section under the Poincare points;
                    the speed ranges with no stable period-1 orbit shaded in the torque's colour
                    (key numbers unstable_period1_*; where the run continued such branches, the
                    ranges with none on any branch: unstable_period1_*_all_branches_<i>), the
                    contact class along each curve (each torque's period-1 curve and each other
                    branch) as a thin band under the
                    panel (drive-flank loss gold, back-flank impact purple), ISO 6336-1 method B's
                    K_v dotted where iso_kv.csv exists;
                    with bifurcation_diagram.csv (by default over the speed bands around each range
                    with no stable period-1 orbit, column band) one more panel per torque whose
                    period-1 branch has an unstable stretch and a diagram: the Poincare DTE (once
                    per mesh period) over the HB branch at the same phase (poincare.py);
  bifurcation_diagram.png  the diagram of every torque that has one, sweep up (left) and down (right);
                    in both figures the rows of sweep from_hb (the integration started on a stable
                    HB orbit that no sweep reached at its speed) as hollow diamonds in every diagram
                    panel, in the legend and the titles only where the torque has such rows;
  campbell.png      mesh orders 1..4 against speed with the closed-contact natural frequencies;
  time_history.png  DTE and flank forces over two mesh periods at one impact / loss point;
  dte_spectrum.png  the DTE per mesh order at three speeds, per torque.
"""
import math

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from style import BIFURCATION_MARKERS as BIF_MARKER
from style import (CONTACT_COLOURS, ORBIT_BRANCH_COLOUR, PERIOD2_COLOURS, UNRESOLVED_MARKER, branch_ids, less,
                   mark_unresolved_stable, orbit_branches, plot_branch, read_csv, rows_of, save,
                   shade_unresolved_period1, torque_colour, unresolved_period1_ranges, unstable_period1_ranges)
from poincare import (bands_text, draw_hb_section, draw_poincare, hb_starts_text, value_limits, window, with_hb_starts,
                      within)

# The drive flank opening is the mesh's intermittent contact (the rug colour of every chapter).
CONTACT_COLOUR = {"drive_loss": CONTACT_COLOURS["intermittent"], "back_impact": CONTACT_COLOURS["back_impact"],
                  "drive_loss+back_impact": CONTACT_COLOURS["drive_loss+back_impact"]}


def torque_label(T):
    return "T1 = %g N m" % T


def nearest(d, omega, y):
    i = min(range(len(d["omega"])), key=lambda k: abs(d["omega"][k] - omega))
    return d["speed_rpm"][i], d[y][i]


def contact_rugs(ax, curves):
    """Thin bands below y = 0, one row per curve (labelled: each torque's period-1 curve and each
    of its period-2 branches, so that on coexisting branches the reader sees which one loses
    contact), coloured by each point's contact class (nothing where the drive flank stays closed).
    curves: (label, colour, rows of frc_<i>.csv) per row."""
    top = ax.get_ylim()[1]
    h = 0.035 * top
    for row, (label, colour, d) in enumerate(curves):
        y0 = -(row + 1) * 1.25 * h
        for kind in CONTACT_COLOUR:   # in this order: an impact is drawn over a loss where the branch folds
            for i in range(len(d["speed_rpm"]) - 1):
                if d["contact"][i] == kind or (kind != "drive_loss" and d["contact"][i + 1] == kind):
                    ax.fill_between([d["speed_rpm"][i], d["speed_rpm"][i + 1]], y0, y0 + h,
                                    color=CONTACT_COLOUR[kind], lw=0)
        ax.text(1.005, y0 + 0.5 * h, label, transform=ax.get_yaxis_transform(), fontsize=6, va="center", color=colour)
    ax.axhline(0.0, color="0.5", lw=0.8)
    ax.set_ylim(-(len(curves) * 1.25 + 0.3) * h, top)


def torque_orbit_branches(kn, i):
    """[(branch id, omega of the orbit, period)] of the branches torque i (0-based) continued from
    time-integrated orbits (style.orbit_branches; kn: the key numbers' values by name)."""
    return orbit_branches({name: {"value": v} for name, v in kn.items()}, "_%d" % (i + 1))


def branches(torques, frc, kn, z1):
    """(label, colour, rows, short rug label, line width) of every curve: per torque its period-1
    curve (torque colour), its period-2 (and period-4) branches (PERIOD2_COLOURS, counted over the
    figure) and its branches continued from a time-integrated orbit (ORBIT_BRANCH_COLOUR, thicker)."""
    out, n = [], 0
    for i, (T, d) in enumerate(zip(torques, frc)):
        out.append((torque_label(T), torque_colour(T, torques), rows_of(d, 0), "T1 = %g" % T, 1.4))
        orbit = {bid: w for bid, w, _ in torque_orbit_branches(kn, i)}
        for bid in branch_ids(d):
            rows = rows_of(d, bid)
            p = int(rows["period"][0])
            if bid in orbit:
                out.append(("%s: period %d (branch %d), continued from the\ntime-integrated orbit at %.0f rpm" % (
                    torque_label(T), p, bid, orbit[bid] / (2.0 * math.pi) * 60.0 / z1), ORBIT_BRANCH_COLOUR, rows,
                    "T1 = %g, p%d b%d" % (T, p, bid), 2.0))
                continue
            out.append(("%s: period %d (branch %d), over %d mesh periods" % (torque_label(T), p, bid, p),
                        PERIOD2_COLOURS[n % len(PERIOD2_COLOURS)], rows, "T1 = %g, p%d b%d" % (T, p, bid), 1.4))
            n += 1
    return out


def no_stable_period1(kn, i):
    """The speed ranges [rpm] of torque i (0-based) with no stable period-1 orbit and, of them, the
    stretches whose stability is unresolved (key numbers unstable_period1_*, unresolved_period1_*): on
    any period-1 branch where the run continued branches from the diagram's orbits
    (*_all_branches_<i>), else on its period-1 curve."""
    tag = "_all_branches" if "unstable_period1_ranges_all_branches_%d" % (i + 1) in kn else ""
    suffix = "%s_%d" % (tag, i + 1)
    return unstable_period1_ranges(kn, suffix, unit="rpm"), unresolved_period1_ranges(kn, suffix, unit="rpm")


def mark_no_stable_period1(axes, kn, torques):
    """A light band in the torque's colour over every range with no stable period-1 orbit, on every
    panel, less its stretches whose stability is unresolved (hatched magenta:
    shade_unresolved_period1); their legend entries."""
    handles = []
    for i, T in enumerate(torques):
        ranges, unresolved = no_stable_period1(kn, i)
        plain = less(ranges, unresolved)
        for ax in axes:
            for a, b in plain:
                ax.axvspan(a, b, color=torque_colour(T, torques), alpha=0.09, lw=0, zorder=0)
        if ranges:
            handles.append(Patch(color=torque_colour(T, torques), alpha=0.25,
                                 label="no stable period-1 orbit, %s (%s rpm)" % (
                                     torque_label(T), ", ".join("%.0f-%.0f" % r for r in ranges))))
        handles += shade_unresolved_period1(axes, unresolved, unit="rpm, " + torque_label(T))
    return handles


def torque_rows(d, i):
    """The rows of torque i (0-based) of a bifurcation_diagram*.csv, as a table of their own."""
    keep = [k for k in range(len(d["torque_index"])) if int(d["torque_index"][k]) == i + 1]
    return {c: [v[k] for k in keep] for c, v in d.items()}


def diagram_panel(ax, p, h, sweeps, title, orbit=()):
    handles = draw_hb_section(ax, h, "speed_rpm", "dte_um", orbit=orbit) + draw_poincare(ax, p, "speed_rpm", "dte_um",
                                                                                          sweeps=sweeps)
    ax.set_ylabel("DTE at phase 0 of each\nmesh period [um]")
    ax.set_title(title, fontsize=8)
    return handles


def read_diagram(d_dir):
    """(diagram, HB section) of the run, or None without a bifurcation diagram."""
    if not (d_dir / "bifurcation_diagram.csv").exists() or not (d_dir / "bifurcation_diagram_hb.csv").exists():
        return None
    return read_csv(d_dir / "bifurcation_diagram.csv"), read_csv(d_dir / "bifurcation_diagram_hb.csv")


def response_figure(d_dir, params, kn, torques, frc, bif):
    diagram = read_diagram(d_dir)
    unstable = [i for i, d in enumerate(frc) if diagram and torque_rows(diagram[0], i)["speed_rpm"]
                and any(int(s) == 0 for s in rows_of(d, 0)["stable"])]
    curves = branches(torques, frc, kn, params["gears"][0]["z"])
    fig, axes = plt.subplots(2 + len(unstable), 1, figsize=(9.6, 7.4 + 3.0 * len(unstable)), sharex=True)
    iso = read_csv(d_dir / "iso_kv.csv") if (d_dir / "iso_kv.csv").exists() else None
    unresolved = False   # a "stable" point on a failed shooting correction: magenta square, not stable
    for ax, y, scale, label in ((axes[0], "x_rms_ac", 1e6, "DTE RMS (oscillating part) [um]"),
                                (axes[1], "dynamic_factor", 1.0, "dynamic factor K_v = max |mesh force| / F0")):
        for label_c, col, d, _, lw in curves:
            plot_branch(ax, d, y=y, x="speed_rpm", color=col, label=label_c, scale=scale, lw=lw)
            unresolved = mark_unresolved_stable(ax, d, y, x="speed_rpm", scale=scale) or unresolved
        for i, T in enumerate(torques):   # each event on the curve of its branch
            for k, t in enumerate(bif[i]["type"] if bif[i]["type"] else []):
                on = rows_of(frc[i], int(bif[i]["branch"][k]) if "branch" in bif[i] else 0)
                if on["omega"]:
                    xb, yb = nearest(on, bif[i]["omega"][k], y)
                    ax.plot([xb], [yb * scale], BIF_MARKER.get(t, "x"), mfc="none", color=torque_colour(T, torques), ms=7)
        if iso is not None and y == "dynamic_factor":   # before the rugs, so that the axis holds it whole
            for i, T in enumerate(torques):
                ax.plot(iso["speed_rpm"], iso["K_v_%d" % (i + 1)], ":", color=torque_colour(T, torques), lw=1.5)
        ax.set_ylabel(label)
        ax.set_ylim(bottom=0)
        contact_rugs(ax, [(short, col, d) for _, col, d, short, _ in curves])
    axes[1].axhline(1.0, color="0.5", lw=0.8, ls="-.")
    extra = {}
    for ax, i in zip(axes[2:], unstable):
        p = torque_rows(diagram[0], i)
        for hd in diagram_panel(ax, p, torque_rows(diagram[1], i), with_hb_starts(),
                                "%s: bifurcation diagram by time integration (sweeps up and down)\n%s%s"
                                % (torque_label(torques[i]), bands_text(p, "speed_rpm", "rpm"), hb_starts_text(p)),
                                [bid for bid, _, _ in torque_orbit_branches(kn, i)]):
            extra.setdefault(hd.get_label(), hd)
    shaded = mark_no_stable_period1(axes, kn, torques)
    axes[-1].set_xlabel("speed of gear 1 n1 [rpm]   (mesh frequency = z1 n1 / 60, z1 = %d)" % params["gears"][0]["z"])
    handles = [Line2D([], [], color=col, lw=lw, label=label_c) for label_c, col, _, _, lw in curves]
    handles += [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
                Line2D([], [], color="k", ls="--", label="unstable (Floquet)")]
    handles += [Line2D([], [], label="HB point labelled stable whose shooting correction\nfails: stability unresolved",
                       **UNRESOLVED_MARKER)] if unresolved else []
    handles += [Line2D([], [], color="k", ls="none", marker=m, mfc="none", label=t.replace("_", " "))
                for t, m in BIF_MARKER.items() if any(t in (b["type"] or []) for b in bif)]
    handles += [Patch(color=c, label=k.replace("+", " + ").replace("_", " ") + " (bands below 0, one row per curve)")
                for k, c in CONTACT_COLOUR.items() if any(k in d["contact"] for d in frc)]
    handles += shaded
    if iso is not None:
        handles.append(Line2D([], [], color="k", ls=":", label="ISO 6336-1 method B K_v: ISO 1328-1 grade %d,\n"
                              "C_a = %.1f um%s, K_A = 1 (one curve per torque)"
                              % (kn["iso_quality_grade"], kn["iso_tip_relief_um"],
                                 " (running-in: no relief)" if kn["iso_tip_relief_from_running_in"] else "")))
    axes[0].legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.19, 1.0))   # right of the rug labels
    if extra:
        axes[2].legend(handles=list(extra.values()), fontsize=7, loc="upper left", bbox_to_anchor=(1.19, 1.0))
    dyn = params.get("dynamics", {})
    model = dyn.get("model", "one_dof")
    if model == "six_dof" and params.get("helix_angle_deg", 0) > 0 and "double_helical" not in params:
        model = "six_dof + axial z1, z2"   # a single helix on bearings: the axial DOFs are on
    axes[0].set_title("%s\n%s model, %s mesh,\nzeta = %g, H = %d, normal backlash %.1f um" % (
        params.get("name", "gear pair"), model, dyn.get("mesh", "constant"),
        dyn.get("zeta", 0.08), dyn.get("harmonics", 5), kn["normal_backlash_m"] * 1e6), fontsize=8)
    save(fig, d_dir / "response.png")


def diagram_figure(d_dir, params, kn, torques, diagram):
    """bifurcation_diagram.png: one row per torque with a diagram, sweep up (left) and down (right)."""
    drawn = [i for i in range(len(torques)) if torque_rows(diagram[0], i)["speed_rpm"]]
    fig, grid = plt.subplots(len(drawn), 2, figsize=(12.0, 3.4 * len(drawn) + 1.2), sharex=True, sharey="row",
                             squeeze=False)
    lo, hi = window({c: [v[k] for k in range(len(v)) if int(diagram[0]["torque_index"][k]) - 1 in drawn]
                     for c, v in diagram[0].items()}, "speed_rpm")
    labels = {}
    for row, i in enumerate(drawn):
        T = torques[i]
        p, h = torque_rows(diagram[0], i), torque_rows(diagram[1], i)
        ylim = value_limits(p, h, "speed_rpm", "dte_um", lo, hi)
        h = within(h, "speed_rpm", lo, hi)
        grid[row][0].set_ylim(*ylim)   # the row shares y
        for ax, sweep in zip(grid[row], ("up", "down")):
            for hd in diagram_panel(ax, p, h, with_hb_starts((sweep,)), "%s, sweep %s, %s%s" % (
                    torque_label(T), sweep, bands_text(p, "speed_rpm", "rpm"), hb_starts_text(p)),
                    [bid for bid, _, _ in torque_orbit_branches(kn, i)]):
                labels.setdefault(hd.get_label(), hd)
    for ax in grid[-1]:
        ax.set_xlim(lo, hi)
        ax.set_xlabel("speed of gear 1 n1 [rpm]")
    fig.suptitle("%s: bifurcation diagram by time integration\n(each speed but a sweep's first starts from the "
                 "previous speed's final state; the DTE once per mesh period, at phase 0)" % params.get("name", "gear pair"),
                 fontsize=9)
    # room under the axes for the legend's rows (0.16 in each) and the x label (0.45 in)
    legend_in = 0.16 * -(-len(labels) // 3)
    fig.set_figheight(3.4 * len(drawn) + 0.9 + legend_in)
    fig.legend(handles=list(labels.values()), fontsize=7, loc="lower center", ncol=3, frameon=False)
    fig.tight_layout(rect=(0, (legend_in + 0.45) / fig.get_figheight(), 1, 0.97))
    fig.savefig(d_dir / "bifurcation_diagram.png")
    plt.close(fig)


def equal_groups(values, rel=1e-9):
    """[(indices, value)] of the lists in `values` grouped where they are equal (to rel): lines
    that would lie on one another are drawn once."""
    groups = []
    for i, v in enumerate(values):
        for members, w in groups:
            if len(v) == len(w) and all(abs(a - b) <= rel * max(abs(a), abs(b), 1e-300) for a, b in zip(v, w)):
                members.append(i)
                break
        else:
            groups.append(([i], v))
    return groups


def torques_label(torques, members):
    """T1 = 100 N m, or T1 = 100, 200, 300 N m (one line) for torques whose lines coincide."""
    if len(members) == 1:
        return torque_label(torques[members[0]])
    return "T1 = %s N m (one line)" % ", ".join("%g" % torques[i] for i in members)


def campbell_figure(d_dir, params, kn, torques, frc):
    modes = read_csv(d_dir / "modes.csv")
    z1 = params["gears"][0]["z"]
    n_max = max(max(d["speed_rpm"]) for d in frc)
    fig, ax = plt.subplots(figsize=(7.2, 5.4))
    for k in range(1, 5):
        ax.plot([0, n_max], [0, k * z1 * n_max / 60.0], color="0.3", lw=1)
        f_top = 1.8 * max(modes["f_hz"])
        n_end = min(n_max, 60.0 * (1.02 - 0.08 * k) * f_top / (k * z1))   # inside the axes, staggered
        ax.text(n_end, k * z1 * n_end / 60.0, "%d x mesh " % k, fontsize=7, va="top", ha="right")
    naturals = [[modes["f_hz"][j] for j in range(len(modes["f_hz"])) if int(modes["torque_index"][j]) == i + 1]
                for i in range(len(torques))]
    peaked = [i for i in range(len(torques)) if "dte_rms_peak_f_mesh_hz_%d" % (i + 1) in kn]   # a stable period-1 point
    peaks = [[kn["dte_rms_peak_f_mesh_hz_%d" % (i + 1)] * 60.0 / z1] for i in peaked]
    for members, f in equal_groups(naturals):   # torques whose lines coincide: drawn and named once
        for j, fj in enumerate(f):
            ax.axhline(fj, color=torque_colour(torques[members[-1]], torques), ls=":", lw=1.2,
                       label="closed-contact natural frequencies, %s" % torques_label(torques, members) if j == 0 else None)
    for members, n in equal_groups(peaks):
        members = [peaked[m] for m in members]
        ax.axvline(n[0], color=torque_colour(torques[members[-1]], torques), ls="-", lw=0.6, alpha=0.6,
                   label="DTE RMS peak, %s" % torques_label(torques, members))
    ax.set_xlim(0, n_max * 1.12)
    ax.set_ylim(0, 1.8 * max(modes["f_hz"]))   # the orders that can meet a mode
    ax.set_xlabel("speed of gear 1 [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title("%s\nCampbell diagram: mesh orders against the mesh natural frequencies" % params.get("name", ""),
                 fontsize=8)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)   # off the orders
    save(fig, d_dir / "campbell.png")


def time_history_figure(d_dir, params, kn):
    if not (d_dir / "time_history.csv").exists():
        return
    h = read_csv(d_dir / "time_history.csv")
    i = int(h["torque_index"][0])
    F0 = kn["tooth_force_N_%d" % i]
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 5.8), sharex=True)
    a1.plot(h["t_ms"], h["dte_um"], color="C0")
    a1.set_ylabel("DTE [um]")
    a2.plot(h["t_ms"], h["drive_force_N"], color="C0", label="drive flank")
    a2.plot(h["t_ms"], [-v for v in h["back_force_N"]], color="C3", label="back flank (drawn negative)")
    a2.axhline(F0, color="0.4", ls=":", label="static tooth force F0 = %.0f N" % F0)
    a2.axhline(0.0, color="0.6", lw=0.8)
    a2.set_xlabel("time [ms] (two mesh periods)")
    a2.set_ylabel("mesh force [N]")
    a2.legend(fontsize=7, loc="upper right")
    a1.set_title("%s\nT1 = %g N m at f_mesh = %.1f Hz: %s" % (
        params.get("name", ""), params["torques"][i - 1], h["f_mesh_hz"][0],
        "back-flank impacts" if max(h["back_force_N"]) > 0 else "drive-flank loss"), fontsize=8)
    save(fig, d_dir / "time_history.png")


def spectrum_figure(d_dir, params, torques):
    s = read_csv(d_dir / "dte_spectrum.csv")
    n = min(len(torques), 3)
    fig, axes = plt.subplots(1, n, figsize=(4.0 * n, 3.8), squeeze=False)
    for i in range(n):
        ax = axes[0][i]
        rows = [j for j in range(len(s["order"])) if int(s["torque_index"][j]) == i + 1]
        speeds = sorted({s["f_mesh_hz"][j] for j in rows})
        width = 0.8 / max(len(speeds), 1)
        for k, f in enumerate(speeds):
            o = [s["order"][j] for j in rows if s["f_mesh_hz"][j] == f]
            a = [s["amplitude_um"][j] for j in rows if s["f_mesh_hz"][j] == f]
            ax.bar([x - 0.4 + width * (k + 0.5) for x in o], a, width, label="f_mesh = %.0f Hz" % f)
        ax.set_xlabel("mesh order")
        ax.set_ylabel("DTE amplitude [um]")
        ax.set_title(torque_label(torques[i]), fontsize=9)
        ax.legend(fontsize=7)
    fig.suptitle("%s: DTE per mesh order at three speeds" % params.get("name", ""), fontsize=9)
    save(fig, d_dir / "dte_spectrum.png")


def draw(d_dir, params, kn, torques):
    frc = [read_csv(d_dir / ("frc_%d.csv" % (i + 1))) for i in range(len(torques))]
    bif = [read_csv(d_dir / ("bifurcations_%d.csv" % (i + 1))) for i in range(len(torques))]
    for b in bif:
        b.setdefault("type", [])
        b.setdefault("omega", [])
    response_figure(d_dir, params, kn, torques, frc, bif)
    diagram = read_diagram(d_dir)
    if diagram:
        diagram_figure(d_dir, params, kn, torques, diagram)
    campbell_figure(d_dir, params, kn, torques, frc)
    time_history_figure(d_dir, params, kn)
    spectrum_figure(d_dir, params, torques)
