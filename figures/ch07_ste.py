"""Figures of thesis chapter 7 (static transmission error), Figs. 48-64.

draw(data_dir, fig_dir) reads the CSV files written by build/bin/ch07_ste and
writes one PNG per thesis figure, named figNN_short_name.png, plus one extra
figure (ch07_extra_convergence.png) for the convergence study. Not drawn: the
curves of Parker, Vijayakar & Imajo in Fig. 60 (their data are not available).
Run with Debian's /usr/bin/python3 (matplotlib, Agg backend).
"""
import csv
import math
import os
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import mesh_geometry  # noqa: E402
from style import COMPARISON_COLOURS, read_params, torque_colour  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = {k: [] for k in rows[0].keys()}
    for r in rows:
        for k, v in r.items():
            try:
                out[k].append(float(v))
            except ValueError:
                out[k].append(v)
    return out


def save(fig, fig_dir, name, made, rect=(0, 0, 1, 1)):
    path = os.path.join(fig_dir, name)
    fig.tight_layout(rect=rect)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    made.append(path)


def beams_of(d):
    beams = {}
    for b, x, w in zip(d["beam"], d["x_mm"], d["w_um"]):
        beams.setdefault(int(b), ([], []))
        beams[int(b)][0].append(x)
        beams[int(b)][1].append(w)
    return beams


def node_pairs(nodes):
    """'6-18' -> [(6, 18)]; '2-22_30-38' -> [(2, 22), (30, 38)]."""
    return [tuple(int(n) for n in p.split("-")) for p in nodes.split("_")]


def mark_contact_nodes(ax, d, pairs, fused):
    """Hollow circles on the contact (or fused) node pairs, each pair labelled."""
    at = {int(n): (x, w) for n, x, w in zip(d["node"], d["x_mm"], d["w_um"])}
    for k, (a, b) in enumerate(pairs):
        pts = [at[n] for n in (a, b) if n in at]
        ax.plot(*zip(*pts), ls="none", marker="o", ms=11, mfc="none", mec="k", mew=1.3,
                label=("fused node pairs (common transmission error)" if fused else "contact node pair") if k == 0
                else None)
        x, w = pts[-1]
        ax.annotate("%d-%d" % (a, b), (x, w), xytext=(6, -12 if w < 0 else 6), textcoords="offset points", fontsize=8)
    return at


def deflection_figure(d, title, fig_dir, name, made, pairs=(), fused=False):
    fig, ax = plt.subplots(figsize=(7.4, 5.0))
    for b, (x, w) in sorted(beams_of(d).items()):
        role = "driving" if b % 2 == 1 else "driven"
        nodes = [int(n) for n, bb in zip(d["node"], d["beam"]) if int(bb) == b]
        ax.plot(x, w, "o-", ms=4, label="beam %d (%s tooth, nodes %d-%d)" % (b, role, min(nodes), max(nodes)))
    at = mark_contact_nodes(ax, d, pairs, fused)
    if len(pairs) == 1:   # one pair: the STE is the sum of the two teeth's deflections at the contact
        (a, b), = pairs
        ax.text(0.02, 0.04, "STE = |w(%d)| + |w(%d)| = %.4f + %.4f = %.4f um" % (
            a, b, abs(at[a][1]), abs(at[b][1]), abs(at[a][1]) + abs(at[b][1])), transform=ax.transAxes, fontsize=9,
            bbox=dict(fc="white", ec="0.6"))
    elif pairs:           # fused pairs: the driving roots are moved by -X_STE
        roots = [w for x, w in zip(d["x_mm"], d["w_um"]) if x == 0 and w != 0]
        if roots:
            ax.text(0.02, 0.96, "driving roots moved by -X_STE: X_STE = %.4f um" % abs(roots[0]),
                    transform=ax.transAxes, fontsize=9, va="top", bbox=dict(fc="white", ec="0.6"))
    ax.axhline(0, color="grey", lw=0.5)
    ax.set_xlabel("distance from the tooth root x [mm]")
    ax.set_ylabel("transverse deflection w [um]")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, frameon=False)
    ax.grid(alpha=0.3)
    save(fig, fig_dir, name, made)


def rows(d):
    """Columns -> list of row dicts."""
    keys = list(d.keys())
    return [{k: d[k][i] for k in keys} for i in range(len(d[keys[0]]))]


def thickness_text(r):
    return "constant %g mm thickness" % r["constant_thickness_mm"] if r["thickness"] == "constant" else \
        "involute thickness"


def single_pair_deflections(D, index, fig_dir, made):
    """Figs. 48-49: one pair, constant thickness, torque_3."""
    for fig_no in (48, 49):
        r = index.get(fig_no)
        if r is None:
            continue
        deflection_figure(D(r["file"]), "Fig. %d: one pair in contact, nodes %s, %s, T = %g Nm\n(both roots clamped, "
                          "force -T/r on both contact nodes)" % (fig_no, r["nodes"], thickness_text(r), r["torque_N_m"]),
                          fig_dir, "fig%d_deflection_single_pair_%s.png" % (fig_no, r["nodes"]), made,
                          pairs=node_pairs(r["nodes"]))


def exact_cantilevers(D, index, fig_dir, made):
    """Figs. 50-51: exact cantilever elastic line with the FE nodes of the loaded beam."""
    for fig_no in (50, 51):
        r = index.get(fig_no)
        if r is None:
            continue
        e = D(r["file"])
        node = int(r["node_of_force"])
        ex = [(x, y) for k, x, y in zip(e["kind"], e["x_mm"], e["y_um"]) if k == "exact"]
        fe = [(x, y) for k, x, y in zip(e["kind"], e["x_mm"], e["y_um"]) if k == "fe"]
        fig, ax = plt.subplots(figsize=(7, 4))
        ax.plot(*zip(*ex), "k-", label="exact: y = -F x^2 (3a - x)/(6EI), x <= a;"
                "\n           -F a^2 (3x - a)/(6EI), x > a")
        ax.plot(*zip(*fe), "o", ms=5, mfc="none", label="FE nodes (beam 1, pair %s)" % r["nodes"])
        a = r["a_mm"]
        ymin = min(y for _, y in ex)
        ax.axvline(a, color="grey", ls=":", lw=1)
        ax.text(a, 0.5 * ymin, " force at node %d\n a = %.3f mm" % (node, a), fontsize=8, va="center")
        ax.set_xlabel("distance from the clamped root x [mm]")
        ax.set_ylabel("deflection y [um]")
        ax.set_title("Fig. %d: exact elastic line of the cantilever, force %g N at node %d"
                     % (fig_no, r["force_N"], node), fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
        ax.grid(alpha=0.3)
        save(fig, fig_dir, "fig%d_exact_cantilever_node%d.png" % (fig_no, node), made)


def fused_pairs(D, index, fig_dir, made):
    """Figs. 52-55: two fused pairs, constant thickness."""
    for fig_no in range(52, 56):
        r = index.get(fig_no)
        if r is None:
            continue
        pairs = r["nodes"].replace("_", " and ")
        deflection_figure(D(r["file"]), "Fig. %d: two pairs, nodes %s fused, %s, T = %g Nm\n"
                          "(driving roots guided and moved by -X_STE, driven roots clamped)"
                          % (fig_no, pairs, thickness_text(r).replace(" thickness", ""), r["torque_N_m"]),
                          fig_dir, "fig%d_deflection_two_pairs_%s.png" % (fig_no, pairs.split(" ")[0]), made,
                          pairs=node_pairs(r["nodes"]), fused=True)


def fused_beam_moment(D, index, fig_dir, made):
    """Fig. 56: moment along the fused beam."""
    r = index[56]
    m = D(r["file"])
    fig, ax = plt.subplots(figsize=(7, 4))
    for tooth, col in (("driving", "C0"), ("driven", "C1")):
        xs = [s for s, t in zip(m["s_mm"], m["tooth"]) if t == tooth]
        ms = [v for v, t in zip(m["moment_N_m"], m["tooth"]) if t == tooth]
        ax.plot(xs, ms, "o-", color=col, ms=3, label="%s tooth part" % tooth)
    ax.axhline(0, color="grey", lw=0.5)
    L = max(m["s_mm"])
    ax.axvline(L / 2, color="grey", ls=":", lw=1)
    ax.set_xlabel("position along the fused beam from the guided root to the clamped root [mm]", fontsize=8)
    ax.set_ylabel("bending moment M [N m]")
    ax.set_title("Fig. 56: bending moment along the fused pair %s, %s, T = %g Nm\n"
                 "linear from +F L/4 to -F L/4 (F/2 = %g N, L = %g mm), zero at mid-span"
                 % (r["nodes"], thickness_text(r).replace(" thickness", ""), r["torque_N_m"], r["force_N"] / 2, L),
                 fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig56_moment_fused_beam.png", made)


def tooth_profile(D, fig_dir, made):
    """Fig. 57: tooth profile and the stepped beam thickness."""
    tp = D("tooth_profile.csv")
    fig, ax = plt.subplots(figsize=(5.5, 5.5))
    ax.plot([s / 2 for s in tp["thickness_mm"]], tp["height_mm"], "k-", label="involute flank, s(r)/2")
    ax.plot([-s / 2 for s in tp["thickness_mm"]], tp["height_mm"], "k-")
    for name, col in (("first", "C0"), ("refined", "C1")):
        b = D("beam_thickness_%s.csv" % name)
        xs, ys = [], []
        for x0, x1, s in zip(b["x_start_mm"], b["x_end_mm"], b["thickness_mm"]):
            xs += [s / 2, s / 2]
            ys += [x0, x1]
        ax.plot(xs, ys, "-", color=col, lw=1, label="beam thickness, %d elements" % len(b["element"]))
        ax.plot([-v for v in xs], ys, "-", color=col, lw=1)
    ax.set_xlabel("half thickness, +-s/2 [mm]")
    ax.set_ylabel("height above the root circle [mm]")
    ax.set_title("Fig. 57: tooth profile, s(r) = r s0/r0 + 2r[inv(a0) - inv(a)]", fontsize=9)
    ax.set_aspect("equal")
    ax.legend(fontsize=7, loc="lower center")
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig57_tooth_profile.png", made)


def deformed_teeth(D, index, fig_dir, made):
    """Figs. 58-59: deformed teeth, involute thickness, torque_3."""
    for fig_no in (58, 59):
        r = index.get(fig_no)
        if r is None:
            continue
        d = D(r["file"])
        title = "%s in contact (%s)" % ("one pair" if r["pairs"] == 1 else "two pairs", r["nodes"].replace("_", " and "))
        beams, contact = {}, {n for pair in node_pairs(r["nodes"]) for n in pair}
        for b, n, x, w, th in zip(d["beam"], d["node"], d["x_mm"], d["w_um"], d["thickness_mm"]):
            beams.setdefault(int(b), []).append((x, w, th, int(n)))
        fig, axes = plt.subplots(1, len(beams), figsize=(max(7.5, 2.4 * len(beams)), 4.8), sharey=True)
        scale = 200.0  # deflection magnification
        for ax, (b, pts) in zip(axes, sorted(beams.items())):
            deformed_tooth(ax, b, pts, contact, scale, r["pairs"])
        axes[0].set_ylabel("height above the root [mm]")
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, fontsize=7, loc="lower center", ncol=3, frameon=False)   # off the teeth
        fig.suptitle("Fig. %d: deformed teeth, involute thickness, T = %g Nm, %s\n"
                     "(each tooth in its own frame; deflections magnified %d times)"
                     % (fig_no, r["torque_N_m"], title, scale),
                     fontsize=9)
        save(fig, fig_dir, "fig%d_deformed_teeth_%s.png" % (fig_no, "single" if fig_no == 58 else "two"), made,
             rect=(0, 0.07, 1, 1))


def deformed_tooth(ax, b, pts, contact, scale, pairs):
    """One beam of Figs. 58-59: undeformed and magnified deformed outline, its contact nodes."""
    x = [p[0] for p in pts]
    w = [p[1] for p in pts]
    th = [p[2] for p in pts]
    ax.plot([t / 2 for t in th], x, color="grey", lw=0.8)
    ax.plot([-t / 2 for t in th], x, color="grey", lw=0.8, label="undeformed")
    ax.plot([wi * 1e-3 * scale + t / 2 for wi, t in zip(w, th)], x, "C3-", lw=1)
    ax.plot([wi * 1e-3 * scale - t / 2 for wi, t in zip(w, th)], x, "C3-", lw=1,
            label="deformed (x%d)" % scale)
    ax.plot([wi * 1e-3 * scale for wi in w], x, "C3.", ms=3)
    hit = [(wi * 1e-3 * scale, xi, n) for xi, wi, _, n in pts if n in contact]
    for u, xi, n in hit:
        ax.plot([u], [xi], "o", ms=9, mfc="none", mec="k", mew=1.2,
                label=("contact node" if pairs == 1 else "fused contact node") if n == hit[0][2] else None)
        ax.annotate("node %d" % n, (u, xi), xytext=(6, 4), textcoords="offset points", fontsize=7)
    ax.set_title("beam %d (%s)\nmax |w| = %.2f um" % (b, "driving" if b % 2 else "driven",
                                                       max(abs(v) for v in w)), fontsize=8)
    ax.set_xlabel("transverse position [mm]", fontsize=8)
    ax.set_xlim(-4.5, 4.5)
    ax.grid(alpha=0.3)


def ste_cycle(D, mine, fig_ste, fig_dir, made):
    """Figs. 60/63: the STE over the mesh cycle, one curve per torque."""
    torques = [c["torque_N_m"] for c in mine]
    label = model_label(mine)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for c in mine:
        d = D(c["file"])
        ph = d["phase"] + [1.0]
        ste = d["ste_um"] + [d["ste_um"][0]]
        ax.step(ph, ste, where="post", color=torque_colour(c["torque_N_m"], torques),
                label="T = %g Nm" % c["torque_N_m"])
        ax.plot(d["phase"], d["ste_um"], "k.", ms=4)
    n = len(D(mine[0]["file"])["phase"])
    pairs = D(mine[0]["file"])["pairs_in_contact"]
    for j, pr in enumerate(pairs):
        if pr == 1:
            ax.axvspan(j / n, (j + 1) / n, color="grey", alpha=0.12, lw=0)
    ax.set_xlabel("mesh phase (fraction of one base pitch); shaded: one pair in contact")
    ax.set_ylabel("static transmission error [um]")
    # Only the thesis' Fig. 60 carries Parker, Vijayakar & Imajo's curve; Fig. 63 has none.
    note = "\n(Parker, Vijayakar & Imajo's curve of the thesis figure: data not available)" if fig_ste == 60 else ""
    ax.set_title("Fig. %d: STE over one mesh cycle, involute thickness + Hertz, %s%s"
                 % (fig_ste, label, note), fontsize=9)
    ax.set_xlim(0, 1)
    ax.legend(fontsize=8, loc="upper left")   # above the two-pair zone, clear of the curves
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig%d_ste_mesh_cycle%s.png" % (fig_ste, "" if fig_ste == 60 else "_14_nodes"), made)


def ste_fourier(D, mine, fig_four, fig_dir, made):
    """Figs. 61/64: the STE's Fourier amplitudes k >= 1 per torque (the mean, k = 0, in the title)."""
    torques = [c["torque_N_m"] for c in mine]
    n = len(D(mine[0]["file"])["phase"])
    fig, ax = plt.subplots(figsize=(7, 4.2))
    width = 0.8 / len(mine)
    means = []
    for i, c in enumerate(mine):
        d = D(c["fourier_file"])
        h = [k for k in d["harmonic"] if k > 0]
        a = [v for k, v in zip(d["harmonic"], d["amplitude_um"]) if k > 0]
        means += [v for k, v in zip(d["harmonic"], d["amplitude_um"]) if k == 0]
        ax.bar([k + (i - (len(mine) - 1) / 2) * width for k in h], a, width,
               color=torque_colour(c["torque_N_m"], torques), label="T = %g Nm" % c["torque_N_m"])
    ax.set_xlabel("harmonic of the mesh frequency k")
    ax.set_ylabel("amplitude sqrt(a_k^2 + b_k^2) [um]")
    ax.set_xticks(h)
    ax.set_title("Fig. %d: Fourier coefficients of the STE (FFTW, %d samples per cycle),\n%s; "
                 "harmonic 0 (the mean, not drawn): %s um" % (fig_four, n, model_label(mine),
                                                               ", ".join("%.3f" % m for m in means)), fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    save(fig, fig_dir, "fig%d_ste_fourier%s.png" % (fig_four, "" if fig_four == 61 else "_14_nodes"), made)


def model_label(mine):
    return "%d elements, %d positions per base pitch" % (mine[0]["tooth_elements"], mine[0]["positions_per_base_pitch"])


def contact_node_scheme(D, fig_dir, made):
    """Fig. 62: the refined model, contact nodes per position."""
    s = D("mesh_scheme.csv")
    ne, P = int(s["tooth_elements"][0]), int(s["positions_per_base_pitch"][0])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for j, (pr, a1, b1) in enumerate(zip(s["pairs_in_contact"], s["driving_node_A"], s["driving_node_B"])):
        ax.plot(j + 1, a1 - 1, "C0o", ms=7)
        ax.annotate("%d-%d%s" % (a1, s["driven_node_A"][j], " *" if pr == 1 else ""), (j + 1, a1 - 1),
                    textcoords="offset points", xytext=(6, -3), fontsize=7)
        if pr == 2:
            k = b1 - 2 * (ne + 1) - 1
            ax.plot(j + 1, k, "C1s", ms=7)
            ax.annotate("%d-%d" % (b1, s["driven_node_B"][j]), (j + 1, k), textcoords="offset points",
                        xytext=(6, -3), fontsize=7)
    ax.plot([], [], "C0o", label="pair entering at A (beams 1-2)")
    ax.plot([], [], "C1s", label="second pair (beams 3-4)")
    ax.set_xlabel("position in the mesh cycle (%d per base pitch);  * = one pair in contact" % P)
    ax.set_ylabel("contact node on the driving tooth\n(elements from its root)")
    ax.set_title("Fig. 62: %d-element tooth model: contact node pairs (global numbers,\n"
                 "beams of %d nodes) at each position of the mesh cycle" % (ne, ne + 1), fontsize=9)
    ax.set_xlim(0.5, len(s["position"]) + 1.5)
    ax.set_ylim(0, ne + 1)
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig62_model_14_nodes.png", made)


def position_convergence(D, par, fig_dir, made):
    """Extra (not a thesis figure): convergence in the number of positions per base pitch."""
    c = D("convergence.csv")
    g = D("geometry.csv")
    eps = g["value"][g["quantity"].index("contact_ratio")]
    T3 = par["torque_3"]
    fig, ax1 = plt.subplots(figsize=(7, 4))
    ax1.semilogx(c["positions_per_base_pitch"], c["ste_max_T3_um"], "C0o-", base=2, label="max STE (left)")
    ax1.set_xlabel("positions per base pitch P (tooth elements = floor(%.4f P))" % eps)
    ax1.set_ylabel("max STE at %g Nm [um]" % T3, color="C0")
    ax2 = ax1.twinx()
    ax2.semilogx(c["positions_per_base_pitch"], c["mean_stiffness_T3_MN_per_m"], "C1s-", base=2,
                 label="mean stiffness (right)")
    ax2.set_ylabel("mean mesh stiffness mean(F/STE) [MN/m]", color="C1")
    ax1.set_title("STE model convergence beyond the %d-element model (T = %g Nm)"
                  % (int(c["tooth_elements"][0]), T3), fontsize=10)
    h1, l1 = ax1.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax1.legend(h1 + h2, l1 + l2, fontsize=8, loc="center right")
    ax1.grid(alpha=0.3)
    save(fig, fig_dir, "ch07_extra_convergence.png", made)


def draw(data_dir, fig_dir):
    data_dir, fig_dir = pathlib.Path(data_dir), str(fig_dir)
    made = []
    D = lambda n: read(os.path.join(data_dir, n))  # noqa: E731
    index = {int(r["figure"]): r for r in rows(D("deflection_cases.csv"))}
    single_pair_deflections(D, index, fig_dir, made)
    exact_cantilevers(D, index, fig_dir, made)
    fused_pairs(D, index, fig_dir, made)
    fused_beam_moment(D, index, fig_dir, made)
    tooth_profile(D, fig_dir, made)
    deformed_teeth(D, index, fig_dir, made)
    cases = rows(D("cases.csv"))
    for model, fig_ste, fig_four in (("first", 60, 61), ("refined", 63, 64)):
        mine = sorted([c for c in cases if c["model"] == model], key=lambda c: c["torque_N_m"])
        if mine:
            ste_cycle(D, mine, fig_ste, fig_dir, made)
            ste_fourier(D, mine, fig_four, fig_dir, made)
    contact_node_scheme(D, fig_dir, made)
    position_convergence(D, read_params(data_dir), fig_dir, made)
    four_beam_model(D, index, fig_dir, made)
    base_pitch_figure(D("geometry.csv"), fig_dir, made)
    tooth_axis(D, fig_dir, made)
    return made


def four_beam_model(D, index, fig_dir, made):
    """Fig. 46: the four beams of the 10-element model (two tooth pairs), nodes numbered, the
    contact node pairs of every position the thesis lists (deflection_cases.csv). Node heights
    from the run's deflection files; a driven tooth hangs from its root above, so a contact pair
    (i, j) is at one height: x_i + x_j is the same for every pair (the beams' common span)."""
    two = D(index[52]["file"])
    x = {int(n): v for n, v in zip(two["node"], two["x_mm"])}
    beam = {int(n): int(b) for n, b in zip(two["node"], two["beam"])}
    cases = sorted((r for r in index.values() if r["file"].startswith("deflection_") and r["thickness"] == "constant"),
                   key=lambda r: r["figure"])
    a0, b0 = node_pairs(cases[0]["nodes"])[0]
    span = x[a0] + x[b0]
    column = {1: 0.0, 2: 1.0, 3: 3.2, 4: 4.2}

    def height(n):
        return x[n] if beam[n] % 2 else span - x[n]

    fig, ax = plt.subplots(figsize=(8.6, 6.4))
    for b, cx in column.items():
        nodes = sorted(n for n in beam if beam[n] == b)
        ax.plot([cx] * len(nodes), [height(n) for n in nodes], "-o", color="0.3", ms=4, lw=2)
        for n in nodes:
            ax.annotate("%d" % n, (cx, height(n)), xytext=(-20 if b % 2 else 8, -3), textcoords="offset points",
                        fontsize=7)
        root = height(nodes[0])
        ax.plot([cx - 0.1, cx + 0.1], [root, root], color="k", lw=3)
        ax.annotate("root (%s)" % ("driving tooth, clamped; guided with two pairs" if b % 2 else
                                   "driven tooth, clamped"), (cx, root), xytext=(0, -14 if b % 2 else 8),
                    textcoords="offset points", ha="center", fontsize=7)
        ax.text(cx, span + 1.0, "beam %d" % b, ha="center", fontsize=8)
    for k, r in enumerate(cases):
        col = COMPARISON_COLOURS[k % len(COMPARISON_COLOURS)]
        for a, b in node_pairs(r["nodes"]):
            xa, xb = column[beam[a]], column[beam[b]]
            ax.plot([xa, xb], [height(a)] * 2, color=col, lw=1.6, ls="--")
        ax.plot([], [], color=col, ls="--", label="Fig. %d: %s" % (int(r["figure"]), r["nodes"].replace("_", " and ")))
    ax.set_xlim(-1.2, 6.8)
    ax.set_ylim(-1.2, span + 1.6)
    ax.set_xticks([])
    ax.set_ylabel("height along the tooth [mm] (driving root at 0)")
    ax.set_title("Fig. 46: the four-beam tooth model (10 elements per tooth, nodes 1-%d) and the contact node\n"
                 "pairs along the path of contact (one pair: 6-18, 7-17; two pairs: the fused pairs)" % max(beam),
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper right", title="contact node pairs (dashed)", title_fontsize=7)
    ax.grid(alpha=0.2)
    save(fig, fig_dir, "fig46_four_beam_model.png", made)


def tooth_axis(D, fig_dir, made):
    """Fig. 65 (figures/mesh_geometry.py) from geometry.csv and tooth_axis_angles.csv."""
    g, t = D("geometry.csv"), D("tooth_axis_angles.csv")
    geometry = dict(zip(g["quantity"], g["value"]))
    angles = {v: {k: t[k][i] for k in t if k != "variant"} for i, v in enumerate(t["variant"])}
    alpha = math.degrees(math.atan(geometry["T1C"] / geometry["base_radius"]))
    made.append(mesh_geometry.tooth_axis_figure(angles, geometry, alpha, os.path.join(fig_dir, "fig65_tooth_axis.png")))


def base_pitch_figure(g, fig_dir, made):
    """Fig. 73: the path of contact A-E with the pitch point C and one base pitch laid from each
    end: two pairs in contact on A-A' and E'-E, one pair on A'-E' (geometry.csv, mm)."""
    v = {q: val * 1e3 for q, val in zip(g["quantity"], g["value"]) if g["unit"][g["quantity"].index(q)] == "m"}
    pb, AC, AE = v["base_pitch"], v["AC"], v["AE"]
    pts = {"A": 0.0, "A'": AE - pb, "C": AC, "E'": pb, "E": AE}
    fig, ax = plt.subplots(figsize=(8.4, 3.6))
    ax.plot([0, AE], [0, 0], color="k", lw=2)
    two, one = COMPARISON_COLOURS[0], COMPARISON_COLOURS[1]
    ax.axvspan(0, AE - pb, ymin=0.45, ymax=0.62, color=two, alpha=0.25, lw=0, label="two pairs in contact")
    ax.axvspan(pb, AE, ymin=0.45, ymax=0.62, color=two, alpha=0.25, lw=0)
    ax.axvspan(AE - pb, pb, ymin=0.45, ymax=0.62, color=one, alpha=0.3, lw=0, label="one pair in contact (A'-E')")
    for k, (name, s) in enumerate(pts.items()):
        ax.plot([s], [0], "ko", ms=5)
        ax.annotate(name, (s, 0), xytext=(0, 8), textcoords="offset points", ha="center", fontsize=10,
                    fontweight="bold")
        ax.annotate("%.3f" % s, (s, 0), xytext=(0, -14 if k % 2 == 0 else -26), textcoords="offset points",
                    ha="center", fontsize=8)
    for y, (s0, s1) in ((-0.55, (0.0, pb)), (-0.85, (AE - pb, AE))):
        ax.annotate("", (s1, y), (s0, y), arrowprops=dict(arrowstyle="<->", lw=1))
        ax.text((s0 + s1) / 2, y + 0.05, "base pitch p_b = %.3f mm" % pb, ha="center", va="bottom", fontsize=8)
    ax.set_ylim(-1.1, 1.0)
    ax.set_xlim(-1.0, AE + 1.0)
    ax.set_yticks([])
    ax.set_xlabel("position along the path of contact from A [mm] (AE = %.3f mm, contact ratio AE/p_b = %.4f)"
                  % (AE, AE / pb))
    ax.set_title("Fig. 73: one base pitch laid along the path of contact A-E (thesis gears, geometry.csv)",
                 fontsize=9)
    ax.legend(fontsize=8, loc="upper right")
    save(fig, fig_dir, "fig73_base_pitch.png", made)
