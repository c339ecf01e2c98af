"""Figures of thesis chapter 7 (static transmission error), Figs. 48-64.

draw(data_dir, fig_dir) reads the CSV files written by build/bin/ch07_ste and
writes one PNG per thesis figure, named figNN_short_name.png, plus one extra
figure (ch07_extra_convergence.png) for the convergence study. Not drawn: the
curves of Parker, Vijayakar & Imajo in Fig. 60 (their data are not available).
Run with Debian's /usr/bin/python3 (matplotlib, Agg backend).
"""
import csv
import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


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


def save(fig, fig_dir, name, made):
    path = os.path.join(fig_dir, name)
    fig.tight_layout()
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


def deflection_figure(d, title, fig_dir, name, made, exact=None):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for b, (x, w) in sorted(beams_of(d).items()):
        role = "driving" if b % 2 == 1 else "driven"
        ax.plot(x, w, "o-", ms=4, label="beam %d (%s tooth, nodes %d-%d)" % (
            b, role, (b - 1) * len(x) + 1, b * len(x)))
    if exact is not None:
        for (xe, ye, lab) in exact:
            ax.plot(xe, ye, "k--", lw=1, label=lab)
    ax.axhline(0, color="grey", lw=0.5)
    ax.set_xlabel("distance from the tooth root x [mm]")
    ax.set_ylabel("transverse deflection w [um]")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=7, loc="best")
    ax.grid(alpha=0.3)
    save(fig, fig_dir, name, made)


def draw(data_dir, fig_dir):
    data_dir, fig_dir = str(data_dir), str(fig_dir)
    made = []
    D = lambda n: read(os.path.join(data_dir, n))  # noqa: E731

    # Figs. 48-49: one pair, constant 6 mm thickness, 300 Nm.
    singles = sorted(glob.glob(os.path.join(data_dir, "deflection_const_single_*.csv")))
    for fig_no, path in zip((48, 49), singles):
        pair = os.path.basename(path)[len("deflection_const_single_"):-4]
        deflection_figure(read(path), "Fig. %d: one pair in contact, nodes %s, constant 6 mm "
                          "thickness, T = 300 Nm\n(both roots clamped, force -T/r on both contact nodes)"
                          % (fig_no, pair), fig_dir, "fig%d_deflection_single_pair_%s.png" % (fig_no, pair), made)

    # Figs. 50-51: exact cantilever elastic line (force at node 7, node 6) with the FE nodes.
    fe = read(singles[0]) if singles else None
    for fig_no, node in ((50, 7), (51, 6)):
        e = D("elastic_line_exact_node%d.csv" % node)
        fig, ax = plt.subplots(figsize=(7, 4))
        ax.plot(e["x_mm"], e["y_exact_um"], "k-", label="exact: y = -F x^2 (3a - x)/(6EI), x <= a;"
                "\n           -F a^2 (3x - a)/(6EI), x > a")
        if fe is not None:
            # FE nodal values of the beam loaded at this node in the 6-18 / 7-17 cases.
            for path in singles:
                d = read(path)
                for b, (x, w) in beams_of(d).items():
                    first = (b - 1) * len(x) + 1
                    loaded = [n for n in range(first, first + len(x))
                              if os.path.basename(path).find("%d" % n) >= 0]
                    if node in [n - first + 1 for n in loaded]:
                        ax.plot(x, w, "o", ms=5, mfc="none", label="FE nodes (beam %d, %s)" % (
                            b, os.path.basename(path)[24:-4]))
                        break
        a = e["x_mm"][-1] * (node - 1) / 10.0
        ax.axvline(a, color="grey", ls=":", lw=1)
        ax.text(a, 0.5 * min(e["y_exact_um"]), " force at node %d\n a = %.3f mm" % (node, a), fontsize=8,
                va="center")
        ax.set_xlabel("distance from the clamped root x [mm]")
        ax.set_ylabel("deflection y [um]")
        ax.set_title("Fig. %d: exact elastic line of the cantilever, force 4000 N at node %d"
                     % (fig_no, node), fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
        ax.grid(alpha=0.3)
        save(fig, fig_dir, "fig%d_exact_cantilever_node%d.png" % (fig_no, node), made)

    # Figs. 52-55: two fused pairs, constant thickness.
    twos = sorted(glob.glob(os.path.join(data_dir, "deflection_const_two_*.csv")),
                  key=lambda p: int(os.path.basename(p).split("_")[3].split("-")[0]))
    for fig_no, path in zip(range(52, 56), twos):
        pairs = os.path.basename(path)[len("deflection_const_two_"):-4].replace("_", " and ")
        deflection_figure(read(path), "Fig. %d: two pairs, nodes %s fused, constant 6 mm, T = 300 Nm\n"
                          "(driving roots guided and moved by -X_STE, driven roots clamped)" % (fig_no, pairs),
                          fig_dir, "fig%d_deflection_two_pairs_%s.png" % (
                              fig_no, pairs.split(" ")[0]), made)

    # Fig. 56: moment along the fused beam.
    m = D("moment_const_two_pair.csv")
    fig, ax = plt.subplots(figsize=(7, 4))
    for tooth, col in (("driving", "C0"), ("driven", "C1")):
        xs = [s for s, t in zip(m["s_mm"], m["tooth"]) if t == tooth]
        ms = [v for v, t in zip(m["moment_N_m"], m["tooth"]) if t == tooth]
        ax.plot(xs, ms, "o-", color=col, ms=3, label="%s tooth part" % tooth)
    ax.axhline(0, color="grey", lw=0.5)
    ax.axvline(m["s_mm"][-1] / 2, color="grey", ls=":", lw=1)
    ax.set_xlabel("position along the fused beam from the guided root (node 1) to the clamped root (node 12) [mm]",
                  fontsize=8)
    ax.set_ylabel("bending moment M [N m]")
    ax.set_title("Fig. 56: bending moment along the fused pair 2-22, constant 6 mm, T = 300 Nm\n"
                 "linear from +F L/4 to -F L/4 (F/2 = 2000 N, L = 7.425 mm), zero at mid-span", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig56_moment_fused_beam.png", made)

    # Fig. 57: tooth profile and the stepped beam thickness.
    tp = D("tooth_profile.csv")
    fig, ax = plt.subplots(figsize=(5.5, 5.5))
    ax.plot([s / 2 for s in tp["thickness_mm"]], tp["height_mm"], "k-", label="involute flank, s(r)/2")
    ax.plot([-s / 2 for s in tp["thickness_mm"]], tp["height_mm"], "k-")
    for P, col in ((6, "C0"), (8, "C1")):
        path = os.path.join(data_dir, "beam_thickness_P%d.csv" % P)
        if not os.path.exists(path):
            continue
        b = read(path)
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

    # Figs. 58-59: deformed teeth, involute thickness, 300 Nm.
    for fig_no, name, title in ((58, "deflection_var_single.csv", "one pair in contact (6-18)"),
                                (59, "deflection_var_two.csv", "two pairs in contact (2-22 and 30-38)")):
        d = D(name)
        beams = {}
        for b, x, w, th in zip(d["beam"], d["x_mm"], d["w_um"], d["thickness_mm"]):
            beams.setdefault(int(b), []).append((x, w, th))
        fig, axes = plt.subplots(1, len(beams), figsize=(max(7.5, 2.4 * len(beams)), 4.4), sharey=True)
        scale = 200.0  # deflection magnification
        for ax, (b, pts) in zip(axes, sorted(beams.items())):
            x = [p[0] for p in pts]
            w = [p[1] for p in pts]
            th = [p[2] for p in pts]
            ax.plot([t / 2 for t in th], x, color="grey", lw=0.8)
            ax.plot([-t / 2 for t in th], x, color="grey", lw=0.8, label="undeformed")
            ax.plot([wi * 1e-3 * scale + t / 2 for wi, t in zip(w, th)], x, "C3-", lw=1)
            ax.plot([wi * 1e-3 * scale - t / 2 for wi, t in zip(w, th)], x, "C3-", lw=1,
                    label="deformed (x%d)" % scale)
            ax.plot([wi * 1e-3 * scale for wi in w], x, "C3.", ms=3)
            ax.set_title("beam %d (%s)\nmax |w| = %.2f um" % (b, "driving" if b % 2 else "driven",
                                                               max(abs(v) for v in w)), fontsize=8)
            ax.set_xlabel("transverse position [mm]", fontsize=8)
            ax.set_xlim(-4.5, 4.5)
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("height above the root [mm]")
        axes[0].legend(fontsize=6, loc="upper left")
        fig.suptitle("Fig. %d: deformed teeth, involute thickness, T = 300 Nm, %s\n"
                     "(each tooth in its own frame; deflections magnified %d times)" % (fig_no, title, scale),
                     fontsize=9)
        save(fig, fig_dir, "fig%d_deformed_teeth_%s.png" % (fig_no, "single" if fig_no == 58 else "two"), made)

    # Figs. 60/63: STE over the mesh cycle; Figs. 61/64 its Fourier coefficients.
    def ste_figures(prefix, fig_ste, fig_four, label):
        files = sorted(glob.glob(os.path.join(data_dir, prefix + "T*.csv")),
                       key=lambda p: float(os.path.basename(p)[len(prefix) + 1:-4]))
        files = [f for f in files if "fourier" not in f]
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for f in files:
            d = read(f)
            T = os.path.basename(f)[len(prefix) + 1:-4]
            ph = d["phase"] + [1.0]
            ste = d["ste_um"] + [d["ste_um"][0]]
            ax.step(ph, ste, where="post", label="T = %s Nm" % T)
            ax.plot(d["phase"], d["ste_um"], "k.", ms=4)
        n = len(read(files[0])["phase"])
        pairs = read(files[0])["pairs_in_contact"]
        for j, pr in enumerate(pairs):
            if pr == 1:
                ax.axvspan(j / n, (j + 1) / n, color="grey", alpha=0.12, lw=0)
        ax.set_xlabel("mesh phase (fraction of one base pitch); shaded: one pair in contact")
        ax.set_ylabel("static transmission error [um]")
        ax.set_title("Fig. %d: STE over one mesh cycle, involute thickness + Hertz, %s\n"
                     "(Parker, Vijayakar & Imajo's curve of the thesis figure: data not available)"
                     % (fig_ste, label), fontsize=9)
        ax.set_xlim(0, 1)
        ax.legend(fontsize=8, loc="center left")
        ax.grid(alpha=0.3)
        save(fig, fig_dir, "fig%d_ste_mesh_cycle%s.png" % (fig_ste, "" if fig_ste == 60 else "_14_nodes"), made)

        fig, ax = plt.subplots(figsize=(7, 4.2))
        four = sorted(glob.glob(os.path.join(data_dir, prefix + "fourier_T*.csv")),
                      key=lambda p: float(os.path.basename(p)[len(prefix) + 9:-4]))
        width = 0.8 / max(1, len(four))
        for i, f in enumerate(four):
            d = read(f)
            T = os.path.basename(f)[len(prefix) + 9:-4]
            h = [k for k in d["harmonic"] if k > 0]
            a = [v for k, v in zip(d["harmonic"], d["amplitude_um"]) if k > 0]
            ax.bar([k + (i - (len(four) - 1) / 2) * width for k in h], a, width, label="T = %s Nm" % T)
        ax.set_xlabel("harmonic of the mesh frequency k")
        ax.set_ylabel("amplitude sqrt(a_k^2 + b_k^2) [um]")
        ax.set_xticks(h)
        ax.set_title("Fig. %d: Fourier coefficients of the STE (FFTW, %d samples per cycle;\n"
                     "harmonic 0 = mean not shown), %s" % (fig_four, n, label), fontsize=9)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3, axis="y")
        save(fig, fig_dir, "fig%d_ste_fourier%s.png" % (fig_four, "" if fig_four == 61 else "_14_nodes"), made)

    ste_figures("ste_first_model_", 60, 61, "10 elements, 6 positions per base pitch")
    ste_figures("ste_", 63, 64, "14 elements, 8 positions per base pitch")

    # Fig. 62: the 14-node model, contact nodes per position.
    sch = glob.glob(os.path.join(data_dir, "mesh_scheme_P*.csv"))[0]
    s = read(sch)
    tooth = read(os.path.join(data_dir, "beam_thickness_P%s.csv" % sch.split("_P")[-1][:-4]))
    ne = len(tooth["element"])
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
    ax.set_xlabel("position in the mesh cycle (8 per base pitch);  * = one pair in contact")
    ax.set_ylabel("contact node on the driving tooth\n(elements from its root)")
    ax.set_title("Fig. 62: %d-element tooth model: contact node pairs (global numbers,\n"
                 "beams of %d nodes) at each position of the mesh cycle" % (ne, ne + 1), fontsize=9)
    ax.set_xlim(0.5, len(s["position"]) + 1.5)
    ax.set_ylim(0, ne + 1)
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    save(fig, fig_dir, "fig62_model_14_nodes.png", made)

    # Extra (not a thesis figure): convergence in the number of positions per base pitch.
    c = D("convergence.csv")
    fig, ax1 = plt.subplots(figsize=(7, 4))
    ax1.semilogx(c["positions_per_base_pitch"], c["ste_max_T3_um"], "C0o-", base=2, label="max STE (left)")
    ax1.set_xlabel("positions per base pitch P (tooth elements = floor(1.7547 P))")
    ax1.set_ylabel("max STE at 300 Nm [um]", color="C0")
    ax2 = ax1.twinx()
    ax2.semilogx(c["positions_per_base_pitch"], c["mean_stiffness_T3_MN_per_m"], "C1s-", base=2,
                 label="mean stiffness (right)")
    ax2.set_ylabel("mean mesh stiffness mean(F/STE) [MN/m]", color="C1")
    ax1.set_title("STE model convergence beyond the 14-node model (T = 300 Nm)", fontsize=10)
    h1, l1 = ax1.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax1.legend(h1 + h2, l1 + l2, fontsize=8, loc="center right")
    ax1.grid(alpha=0.3)
    save(fig, fig_dir, "ch07_extra_convergence.png", made)
    return made
