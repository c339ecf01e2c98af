"""Chapter 2: the method, speed against accuracy, and where each method fails.

figM1  error of x_max against CPU time, one series per method and scene (log-log)
figM2  CPU time of one Newton step against the number of HB unknowns n(2H+1), with the n^3 H^3 model,
       and the exact-flow correction's CPU time per grid point of each scene
figM3  natural continuation stops at the first fold, arc length goes round it
figM4  time-integration sweeps up and down against the HB curve: jumps at the folds
figM5  sampled AFT: spurious folds at the contact, against the exact projection
figM6  too few harmonics: the gear's superharmonic resonances
figM7  Hill (truncated, selection rule) against Floquet on the Mathieu and Meissner charts
figM8  arc length without scaling on the micrometre gear problem
figM9  grazing: each method's error as the contact interval shrinks to zero
Everything (titles, parameters) comes from the run's files.
"""
import json
import math

from style import plot_branch, plt, read_csv, read_params, save

FAMILY_STYLE = {"hb_exact": ("C0", "o", "HB exact contact, arc length (H)"),
                "hb_stepped": ("C2", "s", "HB exact contact, stepped on the grid (H)"),
                "hb_sampled": ("C1", "^", "HB sampled AFT, H = 10 (N)"),
                "ti_rk8pd": ("C3", "D", "time integration rk8pd (tol)"),
                "ti_rkf45": ("C4", "v", "time integration rkf45 (tol)"),
                "hb_corrected": ("C5", "*", "HB at H + exact-flow correction (H)")}
SCENE_TITLE = {"mass_wall": "mass against wall (ch. 3), g = -0.6 m, F = 0.01 N",
               "nlvib_ex03": "NLvib example 03 (x1)",
               "gear_300Nm": "gear at 300 N m (ch. 8), DTE"}


def key_numbers(data_dir):
    with open(data_dir / "key_numbers.json") as f:
        return {k: v["value"] for k, v in json.load(f).items()}


def accuracy_vs_cost(data_dir, fig_dir, params):
    d = read_csv(data_dir / "accuracy_cost.csv")
    scenes = list(dict.fromkeys(d["scene"]))
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.6), squeeze=False)
    for ax, sc in zip(axes[0], scenes):
        for fam, (color, marker, label) in FAMILY_STYLE.items():
            idx = [i for i in range(len(d["scene"])) if d["scene"][i] == sc and d["method"][i] == fam]
            if not idx:
                continue
            xs = [d["cpu_s"][i] for i in idx]
            ys = [max(d["error"][i], 1e-13) for i in idx]
            ax.plot(xs, ys, color=color, marker=marker, ms=4, lw=1, label=label)
            if fam == "hb_corrected":   # which H each star is
                for i, x, y in zip(idx, xs, ys):
                    ax.annotate(d["setting"][i].replace("H=", ""), (x, y), xytext=(3, -9),
                                textcoords="offset points", fontsize=6, color=color)
            # Settings that missed a stable solution: hollow marker.
            miss = [i for i in idx if d["missed"][i] > 0]
            if miss:
                ax.plot([d["cpu_s"][i] for i in miss], [max(d["error"][i], 1e-13) for i in miss], ls="none",
                        marker="o", ms=9, mfc="none", mec="k", mew=0.8)
        for level in (1e-3, 1e-6):
            ax.axhline(level, color="0.5", ls=":", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU time for the grid [s]")
        ax.set_ylabel("max relative error of x_max over the stable grid solutions")
        ax.set_title(SCENE_TITLE.get(sc, sc), fontsize=9)
    # the legend where the middle panel is empty (right, between 1e-5 and 1e-10)
    leg = axes[0][min(1, len(scenes) - 1)]
    leg.plot([], [], ls="none", marker="o", ms=9, mfc="none", mec="k", label="missed a stable solution")
    leg.legend(loc="center right", fontsize=7)
    fig.suptitle("Accuracy against cost: %d grid frequencies per scene, reference rk8pd tol %.0e started on HB"
                 % (int(params["grid_points"]), params["ti_ref_tol"]), fontsize=10)
    return save(fig, fig_dir / "figM1_accuracy_vs_cost.png")


SCENE_DOFS = {"mass_wall": 1, "nlvib_ex03": 2, "gear_300Nm": 1}


def correction_cost(ax, data_dir):
    """The exact-flow correction per grid point (accuracy_cost.csv), at the HB unknowns n(2H+1) it corrects."""
    a = read_csv(data_dir / "accuracy_cost.csv")
    if "cpu_s_correction" not in a:
        return
    for k, sc in enumerate(dict.fromkeys(a["scene"])):
        idx = [i for i in range(len(a["scene"])) if a["scene"][i] == sc and a["method"][i] == "hb_corrected"
               and a["corrected"][i] + a["not_corrected"][i] > 0]
        if not idx:
            continue
        xs = [SCENE_DOFS[sc] * (2 * int(a["setting"][i].split("=")[1]) + 1) for i in idx]
        ys = [a["cpu_s_correction"][i] / (a["corrected"][i] + a["not_corrected"][i]) for i in idx]
        ax.plot(xs, ys, ls="none", marker="*", ms=8, color="C%d" % (5 + k),
                label="exact-flow correction per point, %s (n = %d)" % (sc, SCENE_DOFS[sc]))


def cost_growth(data_dir, fig_dir):
    d = read_csv(data_dir / "cost_per_point.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    correction_cost(ax, data_dir)
    ns = sorted(set(int(n) for n in d["n"]))
    for j, n in enumerate(ns):
        idx = [i for i in range(len(d["n"])) if int(d["n"][i]) == n]
        ax.plot([d["unknowns"][i] for i in idx], [d["cpu_s_per_step"][i] for i in idx], marker="o", ms=4,
                color="C%d" % j, label="n = %d DOF (H = %s)" % (n, ", ".join(str(int(d["H"][i])) for i in idx)))
        if "cpu_s_condensed" in d and n > 1:
            ax.plot([d["unknowns"][i] for i in idx], [d["cpu_s_condensed"][i] for i in idx], marker="s", ms=3,
                    mfc="none", ls=":", color="C%d" % j)
    big = max(range(len(d["n"])), key=lambda i: d["unknowns"][i])
    c = d["cpu_s_per_step"][big] / d["unknowns"][big] ** 3
    # the model only over the measured sizes: extended to 1 unknown it would drag the axis to 1e-10 s
    lo = min(d["unknowns"])
    xs = [lo * (d["unknowns"][big] / lo) ** (k / 40) for k in range(0, 41)]
    ax.plot(xs, [c * x ** 3 for x in xs], "k--", lw=1, label="model c (n(2H+1))^3 through the largest point")
    measured = [v for k in ("cpu_s_per_step", "cpu_s_condensed") if k in d for v in d[k] if v == v and v > 0]
    ax.set_ylim(min(measured) / 3, max(measured) * 3)
    ax.set_xscale("log")
    ax.set_yscale("log")
    if "cpu_s_condensed" in d:
        ax.plot([], [], "k:", marker="s", ms=3, mfc="none",
                label="dotted: condensed on the contact (continuation step, LU of 2H+2 rows)")
    ax.set_xlabel("HB unknowns n(2H+1)")
    ax.set_ylabel("CPU time of one Newton step (stars: one correction) [s]")
    ax.set_title("Cost of a Newton step (residual + Jacobian + LU): chain of n masses, one contact;\n"
                 "stars: the exact-flow correction of one grid point of a chapter-2 scene (shooting + measures)", fontsize=8)
    ax.legend(fontsize=6.5)
    return save(fig, fig_dir / "figM2_cost_per_point.png")


def natural_vs_arclength(data_dir, fig_dir, kn):
    d = read_csv(data_dir / "natural_vs_arclength.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for method, color in (("arc_length", "C0"), ("natural", "C3")):
        idx = [i for i in range(len(d["method"])) if d["method"][i] == method]
        sub = {k: [d[k][i] for i in idx] for k in ("omega", "x_max", "stable")}
        plot_branch(ax, sub, color=color, label=method.replace("_", " "))
    ax.axvline(kn["natural_stop_omega"], color="C3", ls=":", lw=0.8)
    nat = [i for i in range(len(d["method"])) if d["method"][i] == "natural"]
    last = max(nat, key=lambda i: d["omega"][i])   # the last point natural continuation reached
    ax.plot([d["omega"][last]], [d["x_max"][last]], "o", mfc="none", color="C3", ms=9)
    ax.annotate("natural continuation stops here,\nat %.4f rad/s (the first fold)" % kn["natural_stop_omega"],
                (d["omega"][last], d["x_max"][last]), xytext=(1.2, 0.45), arrowprops={"arrowstyle": "->"},
                fontsize=8)
    ax.set_xlim(0.8, 1.4)
    ax.set_xlabel("omega [rad/s]")
    ax.set_ylabel("x_max [m]")
    ax.set_title("Mass against wall, g = -0.6 m, F = 0.01 N, H = 10: natural vs arc-length continuation")
    ax.legend(title="dashed: unstable (Floquet)", fontsize=8)
    return save(fig, fig_dir / "figM3_natural_vs_arclength.png")


def sweep_jumps(data_dir, fig_dir):
    scenes = [("mass_wall", 1.0, "omega [rad/s]", (0.85, 1.25)), ("nlvib_ex03", 1.0, "omega [rad/s]", None)]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, (sc, fx, xl, lim) in zip(axes, scenes):
        c = read_csv(data_dir / ("curve_%s_hb_exact_H20.csv" % sc))
        plot_branch(ax, c, color="0.3", label="HB H = 20, arc length (dashed: unstable, Hill)")
        s = read_csv(data_dir / ("sweep_%s_ti_rk8pd_tol1e-07.csv" % sc))
        for direction, color, marker in (("up", "C3", "^"), ("down", "C0", "v")):
            idx = [i for i in range(len(s["omega"])) if s["direction"][i] == direction]
            per = [i for i in idx if s["periodic"][i] == 1]
            non = [i for i in idx if s["periodic"][i] != 1]
            ax.plot([s["omega"][i] for i in per], [s["x_max"][i] for i in per], ls="none", marker=marker, color=color,
                    label="rk8pd sweep %s (periodic)" % direction)
            if non:
                ax.plot([s["omega"][i] for i in non], [s["x_max"][i] for i in non], ls="none", marker="x",
                        color=color, label="rk8pd sweep %s: not periodic" % direction)
        if lim:
            ax.set_xlim(*lim)
        ax.set_xlabel(xl)
        ax.set_ylabel("x_max [m]")
        ax.set_title(SCENE_TITLE[sc], fontsize=9)
        ax.legend(fontsize=7, loc="center right")
    fig.suptitle("Time integration swept up and down the grid (tol 1e-7): it jumps at the folds and never sees "
                 "the unstable branch", fontsize=10)
    return save(fig, fig_dir / "figM4_ti_sweep_jumps.png")


def turning_points(d):
    """(omega, x_max) where the branch turns back in omega (a fold of the continuation)."""
    xs, ys = d["omega"], d["x_max"]
    return [(xs[i], ys[i]) for i in range(1, len(xs) - 1) if (xs[i] - xs[i - 1]) * (xs[i + 1] - xs[i]) < 0]


def spurious_window(ref, curves):
    """Box around the turning points of the sampled curves that are not folds of the exact curve
    (1e-3 relative in omega), padded by a third of its size: where the spurious folds are."""
    true = [w for w, _ in turning_points(ref)]
    pts = [(w, y) for d in curves for w, y in turning_points(d) if all(abs(w - t) > 1e-3 * t for t in true)]
    if not pts:
        return None
    (w0, w1), (y0, y1) = [(min(v), max(v)) for v in zip(*pts)]
    pw, py = max(w1 - w0, 1e-3 * w1) / 3, max(y1 - y0, 1e-2 * y1) / 3
    return (w0 - pw, w1 + pw), (y0 - py, y1 + py)


def sampled_aft(data_dir, fig_dir):
    fig, grid = plt.subplots(2, 2, figsize=(11, 8.6), gridspec_kw={"height_ratios": [1, 1]})
    for col, (sc, lim) in enumerate((("mass_wall", (0.95, 1.1)), ("nlvib_ex03", (0.55, 0.8)))):
        ax, zoom = grid[0][col], grid[1][col]
        f = read_csv(data_dir / ("folds_%s.csv" % sc))
        folds = {f["setting"][i]: (int(f["folds"][i]), int(f["complete"][i])) for i in range(len(f["setting"]))}
        ref = read_csv(data_dir / ("curve_%s_hb_exact_H10.csv" % sc))   # the same H as the sampled curves
        curves = []
        for a in (ax, zoom):
            a.plot(ref["omega"], ref["x_max"], color="k", lw=2.2, alpha=0.4,
                   label="exact projection H = 10: %d folds (H = 20: %d)" % (folds["hb_exact_H10"][0],
                                                                              folds["hb_exact_H20"][0]))
        for j, N in enumerate((2, 4, 8, 32)):
            tag = "hb_sampled_H10_N%d" % N
            d = read_csv(data_dir / ("curve_%s_%s.csv" % (sc, tag)))
            curves.append(d)
            nf, complete = folds[tag]
            for a in (ax, zoom):
                a.plot(d["omega"], d["x_max"], color="C%d" % (j + 1), lw=1,
                       label="sampled H = 10, N = %d(2H+1): %d folds%s" % (N, nf, "" if complete else ", STOPPED"))
        ax.set_xlim(*lim)
        ax.set_xlabel("omega [rad/s]")
        ax.set_ylabel("x_max [m]")
        ax.set_title(SCENE_TITLE[sc], fontsize=9)
        win = spurious_window(ref, curves)
        if win:
            zoom.set_xlim(*win[0])
            zoom.set_ylim(*win[1])
            ax.add_patch(plt.Rectangle((win[0][0], win[1][0]), win[0][1] - win[0][0], win[1][1] - win[1][0],
                                       fill=False, ec="0.3", lw=0.8, ls="--"))
            zoom.set_title("zoom (dashed box above): the spurious folds", fontsize=9)
        zoom.set_xlabel("omega [rad/s]")
        zoom.set_ylabel("x_max [m]")
        zoom.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=1, frameon=False)
    fig.suptitle("Sampled AFT: the residual is piecewise linear with a kink per sample crossing: spurious folds "
                 "and stalled continuation", fontsize=10)
    return save(fig, fig_dir / "figM5_sampled_aft.png")


def harmonics(data_dir, fig_dir, params):
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    # H = 20 first, wide and light, as the converged reference; the others thin on top, so H = 5
    # (on H = 20 within the line width but for the small-amplitude end) stays visible.
    for H, color, lw, alpha in ((20, "k", 5.0, 0.25), (1, "C7", 1.3, 1.0), (3, "C1", 1.3, 1.0), (5, "C3", 1.0, 1.0)):
        d = read_csv(data_dir / ("curve_gear_300Nm_hb_exact_H%d.csv" % H))
        fhz = {"omega": [w / (2 * math.pi) for w in d["omega"]], "x_max": [x * 1e6 for x in d["x_max"]],
               "stable": d["stable"]}
        plot_branch(ax, fhz, color=color, label="H = %d%s" % (H, " (reference, wide)" if H == 20 else ""),
                    lw=lw, alpha=alpha)
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("x_max (DTE) [um]")
    ax.set_title("Gear at %.0f N m, STE with %d harmonics: too few harmonics miss the superharmonic resonances"
                 % (params["torque"], int(params["ste_harmonics"])), fontsize=9)
    ax.legend(title="HB exact contact (dashed: unstable, Hill)", fontsize=8)
    return save(fig, fig_dir / "figM6_harmonics.png")


def hill_vs_floquet(data_dir, fig_dir, kn):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8))
    for ax, name in zip(axes, ("mathieu", "meissner")):
        d = read_csv(data_dir / ("%s_chart.csv" % name))
        unst = [i for i in range(len(d["a"])) if d["floquet_stable"][i] == 0]
        ax.plot([d["q"][i] for i in unst], [d["a"][i] for i in unst], ls="none", marker="s", ms=3.5, color="0.8",
                label="unstable (Floquet, GSL)")
        for H, color, marker in ((1, "C3", "x"), (2, "C1", "+")):
            bad = [i for i in range(len(d["a"])) if d["hill_H%d" % H][i] != d["floquet_stable"][i]]
            ax.plot([d["q"][i] for i in bad], [d["a"][i] for i in bad], ls="none", marker=marker, ms=5, color=color,
                    label="Hill H = %d disagrees (%.0f %%)" % (H, 100 * kn["%s_hill_H%d_disagreement" % (name, H)]))
        if name == "mathieu":
            qs = [0.02 * k for k in range(0, 76)]
            series = {0: lambda q: -q * q / 2 + 7 * q ** 4 / 128, 1: lambda q: 1 - q - q * q / 8 + q ** 3 / 64,
                      2: lambda q: 1 + q - q * q / 8 - q ** 3 / 64, 3: lambda q: 4 - q * q / 12,
                      4: lambda q: 4 + 5 * q * q / 12}
            for k, fn in series.items():
                ax.plot(qs, [fn(q) for q in qs], "k-", lw=0.8, label="transition curves, small-q series" if k == 0 else None)
            ax.set_xlabel("q")
            ax.set_title("Mathieu y'' + (a - 2q cos 2t) y = 0", fontsize=9)
        else:
            ax.set_xlabel("b")
            ax.set_title("Meissner y'' + (a + b sgn(cos t)) y = 0 (trace GSL vs closed form: %.1e)"
                         % kn["meissner_trace_gsl_vs_exact"], fontsize=9)
        ax.set_ylabel("a")
        ax.set_ylim(-1.5, 10)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("Stability charts: Hill's method truncated at H (selection by smallest |Im|) against Floquet "
                 "(H = 4, 8 in the key numbers)", fontsize=10)
    return save(fig, fig_dir / "figM7_hill_vs_floquet.png")


def unscaled(data_dir, fig_dir, kn):
    d = read_csv(data_dir / "unscaled_arclength.csv")
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    for s, color, label in (("automatic", "C0", "automatic scaling: complete"),
                            ("none", "C3", "no scaling: stuck at %.0f Hz" % kn["arclength_reached_hz_unscaled"])):
        idx = [i for i in range(len(d["scaling"])) if d["scaling"][i] == s]
        ax.plot([d["omega"][i] / (2 * math.pi) for i in idx], [d["x_max"][i] * 1e6 for i in idx], color=color,
                marker="." if s == "none" else None, lw=1.2, label=label)
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("x_max (DTE) [um]")
    ax.set_title("Gear, H = 5: arc-length continuation with and without scaling (Newton failures: scaled %.0f %%, "
                 "unscaled %.0f %%)" % (100 * kn["newton_failure_rate_scaled"], 100 * kn["newton_failure_rate_unscaled"]),
                 fontsize=8)
    ax.legend(fontsize=8)
    return save(fig, fig_dir / "figM8_unscaled_arclength.png")


def grazing(data_dir, fig_dir, kn):
    d = read_csv(data_dir / "grazing.csv")
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6))
    F = [f / kn["grazing_force"] for f in d["Fa"]]
    for col, color, label in (("err_hb_exact", "C0", "HB exact contact, H = 10"),
                              ("err_hb_sampled", "C1", "HB sampled AFT, H = 10, N = 84"),
                              ("err_ti", "C3", "time integration rk8pd, tol 1e-6"),
                              ("err_hb_corrected", "C5", "HB H = 10 + exact-flow correction")):
        if col not in d:
            continue
        ax.plot(F, [max(e, 1e-14) for e in d[col]], marker=".", color=color, label=label,
                ls="--" if col == "err_hb_corrected" else "-")   # dashed: the HB lines below it show
        failed = [f for f, e in zip(F, d[col]) if math.isnan(e)]
        if failed:   # no exact value there (correction failed or inconsistent): marked at the bottom
            ax.plot(failed, [1e-14] * len(failed), ls="none", marker="x", color=color,
                    label="correction failed (no exact value)")
    ax.set_yscale("log")
    ax.axvline(1.0, color="0.5", ls=":")
    ax.set_xlabel("Fa / F_graze (harmonic force amplitude over the grazing one)")
    ax.set_ylabel("relative error of x_max (vs rk8pd tol 1e-12)")
    ax.legend(fontsize=8)
    bx.plot(F, d["contact_rad"], "k.-", label="contact duration [rad]")
    bx.set_xlabel("Fa / F_graze")
    bx.set_ylabel("contact duration per period [rad]")
    b2 = bx.twinx()
    b2.plot(F, d["floquet_modulus"], "C2.-", label="largest Floquet multiplier |mu|")
    b2.set_ylabel("|mu| (Floquet)", color="C2")
    bx.legend(loc="upper left", fontsize=8)
    b2.legend(loc="lower right", fontsize=8)
    fig.suptitle("Grazing: mass against wall at omega = 0.8 rad/s, amplitude Fa through F_graze = %.5f N" % kn["grazing_force"],
                 fontsize=10)
    return save(fig, fig_dir / "figM9_grazing.png")


def draw(data_dir, fig_dir):
    params = read_params(data_dir)
    kn = key_numbers(data_dir)
    made = [accuracy_vs_cost(data_dir, fig_dir, params)]
    if (data_dir / "cost_per_point.csv").exists():
        made += [cost_growth(data_dir, fig_dir), natural_vs_arclength(data_dir, fig_dir, kn),
                 hill_vs_floquet(data_dir, fig_dir, kn), unscaled(data_dir, fig_dir, kn), grazing(data_dir, fig_dir, kn)]
    if (data_dir / "curve_nlvib_ex03_hb_exact_H20.csv").exists():
        made += [sweep_jumps(data_dir, fig_dir), sampled_aft(data_dir, fig_dir)]
    if (data_dir / "curve_gear_300Nm_hb_exact_H20.csv").exists():
        made.append(harmonics(data_dir, fig_dir, params))
    return made
