"""Figures 7-18 of thesis ch. 3 (mass against a wall) from build/data/ch03_mass_wall."""
import math

import matplotlib.pyplot as plt

from style import (CONTACT_LEVEL, case_rows, contact_rug, legend_styles, plot_branch, read_csv, read_params,
                   rug_room, save)


def frc_figure(data_dir, fig_dir, name, title, cases, vary):
    """cases: labels of the case table; vary: the column ("gap" or "Fa") that tells them
    apart in the legend. Plots x_max and x_min vs omega and the gap levels."""
    rows = case_rows(data_dir)
    unit = {"gap": "m", "Fa": "N"}[vary]
    sym = {"gap": "g", "Fa": "Fa"}[vary]
    fig, ax = plt.subplots(figsize=(6.4, 5.0))
    drawn, walls = set(), []   # gap levels already drawn (Figs. 11-12 share one gap)
    for n, label in enumerate(cases):
        d = read_csv(data_dir / ("frc_%s.csv" % label))
        c = "C%d" % n
        text = "%s = %g %s" % (sym, rows[label][vary], unit)
        plot_branch(ax, d, "x_max", c, text + ": $x_{max}$")
        plot_branch(ax, d, "x_min", c)
        contact_rug(ax, d, row=n, colour=c)
        g = rows[label]["gap"]
        if g in drawn:
            continue
        drawn.add(g)
        ax.axhline(-g, **dict(CONTACT_LEVEL, color=c))
        walls.append((g, c))
    ax.set_xlim(0.8, 1.6)   # the data span 0.5-2 rad/s; nothing happens outside this window
    rug_room(ax, len(cases))
    for g, c in walls:   # the wall's label right of the axes, where no curve runs
        ax.annotate("wall\nx = -g\n= %g m" % -g, (1.0, -g), xycoords=("axes fraction", "data"), color=c,
                    fontsize=7, xytext=(3, 0), textcoords="offset points", va="center", annotation_clip=False)
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s] (zoom; data 0.5-2)")
    ax.set_ylabel(r"displacement $x_{max}$ (upper), $x_{min}$ (lower) [m]")
    p = read_params(data_dir)
    ax.set_title("%s (H = %d, m = %g kg, k = %g N/m, kc = %g N/m)" % (title, p["H"], p["m"], p["k"], p["kc"]),
                 fontsize=9)
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + legend_styles(ax), loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=3,
              fontsize=7, frameon=False)
    return save(fig, fig_dir / name)


def pair_title(data_dir, fig, cases, vary):
    """Title from the case table: what the two cases share and what they vary."""
    rows = case_rows(data_dir)
    r0, r1 = rows[cases[0]], rows[cases[1]]
    if vary == "gap":
        return "Fig. %s: g = %g and %g m (Fa = %g N)" % (fig, r0["gap"], r1["gap"], r0["Fa"])
    return "Fig. %s: g = %g m, Fa = %g and %g N" % (fig, r0["gap"], r0["Fa"], r1["Fa"])


POINT_RULE = {"A": "the last point at least 0.02 rad/s before the contact state first changes",
              "B": "the largest response on the curve",
              "C": "the first point at least 0.05 rad/s after the last change of contact state"}


def time_figures(data_dir, fig_dir, label, first_fig, names):
    row = case_rows(data_dir)[label]
    gap, F0 = row["gap"], row["F0"]
    d = read_csv(data_dir / ("frc_%s.csv" % label))
    marks = read_csv(data_dir / "marks.csv")
    out = []
    for k, mark in enumerate("ABC"):
        i = [j for j in range(len(marks["label"])) if marks["label"][j] == label and marks["mark"][j] == mark][0]
        w = marks["omega"][i]
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(9.5, 4.6))
        plot_branch(a1, d, "x_max", "C0", r"$x_{max}$ (upper), $x_{min}$ (lower)")
        plot_branch(a1, d, "x_min", "C0")
        a1.axhline(-gap, **dict(CONTACT_LEVEL, label="wall: x = -g = %g m" % -gap))
        a1.plot([w], [marks["x_max"][i]], "o", color="k", ms=8, mfc="none", mew=1.5, label="current point %s" % mark)
        t = read_csv(data_dir / ("time_%s_%s.csv" % (label, mark)))
        a1.plot([w], [min(t["x"])], "o", color="k", ms=8, mfc="none", mew=1.5)
        a1.set_xlim(0.8, 1.6)
        contact_rug(a1, d)
        rug_room(a1)
        a1.set_xlabel(r"$\omega$ [rad/s] (zoom; data 0.5-2)")
        a1.set_ylabel(r"$x_{max}$, $x_{min}$ [m]")
        a1.set_title("frequency response (g = %g m, F0 = %g N)" % (gap, F0))
        h, _ = a1.get_legend_handles_labels()
        # below the axes: inside, it would sit on the x_min excursion the figure is about
        a1.legend(handles=h + legend_styles(a1), fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2),
                  ncol=2, frameon=False)
        a2.plot(t["t"], t["x"], color="C0", label="x(t), %s contact" % marks["contact"][i])
        a2.axhline(-gap, **dict(CONTACT_LEVEL, label="wall: x = -g"))
        a2.set_xlabel("time t [s]  (two periods)")
        a2.set_ylabel("x [m]")
        a2.set_title(r"time history at $\omega$ = %.4f rad/s" % w)
        a2.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, frameon=False)
        fig.suptitle("Fig. %d: point %s, %s" % (first_fig + k, mark, POINT_RULE[mark]), fontsize=10)
        out.append(save(fig, fig_dir / ("fig%02d_%s.png" % (first_fig + k, names[k]))))
    return out


def draw(data_dir, fig_dir):
    out = []
    p = read_params(data_dir)
    # Fig. 7: linear FRFs
    d = read_csv(data_dir / "fig07_linear.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.semilogy(d["omega"], d["x_open"], label="open contact (k), resonance %.4g rad/s" % math.sqrt(p["k"] / p["m"]))
    ax.semilogy(d["omega"], d["x_full"], label=r"full contact (k + k$_c$), resonance %.4g rad/s"
                % math.sqrt((p["k"] + p["kc"]) / p["m"]))
    ax.set_xlabel(r"$\omega$ [rad/s]")
    ax.set_ylabel("amplitude |X| [m]")
    ax.set_title("Fig. 7: linear response, Fa = %g N, c = %g N s/m" % (case_rows(data_dir)["g-1.2_F0.01"]["Fa"], p["c"]))
    ax.legend()
    out.append(save(fig, fig_dir / "fig07_linear_open_full.png"))
    # Fig. 8: contact force
    d = read_csv(data_dir / "fig08_contact_force.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    th = [v * 180 / math.pi for v in d["theta"]]
    ax.plot(th, d["F_full"], label=r"full: $N_0$ = 1.5 N")
    ax.plot(th, d["F_intermittent"], label=r"intermittent: $N_0$ = 0.5 N")
    ax.plot(th, d["F_open"], label=r"open: $N_0$ = -1.5 N (always 0)")
    ax.set_xlabel(r"phase $\vartheta$ [deg]")
    ax.set_ylabel(r"$F_c = \max(N_0 + k_c x_0 \cos\vartheta, 0)$ [N]")
    ax.set_title(r"Fig. 8: contact force, $k_c$ = %g N/m, $x_0$ = 1 m" % p["kc"])
    ax.legend()
    out.append(save(fig, fig_dir / "fig08_contact_force.png"))
    figs = [("fig09_masswall_gap.png", "9", ["g-1.2_F0.01", "g-0.6_F0.01"], "gap"),
            ("fig10_masswall_preload.png", "10", ["g1_F0.01", "g0.4_F0.01"], "gap"),
            ("fig11_masswall_force_g-0.6.png", "11", ["g-0.6_F0.01", "g-0.6_F0.001"], "Fa"),
            ("fig12_masswall_force_g-1.2.png", "12", ["g-1.2_F0.01", "g-1.2_F0.03"], "Fa")]
    for name, num, cases, vary in figs:
        out.append(frc_figure(data_dir, fig_dir, name, pair_title(data_dir, num, cases, vary), cases, vary))
    out += time_figures(data_dir, fig_dir, "g-1.5_F0.01_F01", 13,
                        ["static_gap_before_contact", "static_gap_in_contact", "static_gap_after_contact"])
    out += time_figures(data_dir, fig_dir, "g-0.5_F0.01_F01", 16,
                        ["static_contact_before_separation", "static_contact_separating", "static_contact_after"])
    # Supplementary: the AFT sample study
    d = read_csv(data_dir / "sample_study.csv")
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    sampled = [i for i, q in enumerate(d["quadrature"]) if q == "sampled"]
    ax.semilogx([d["N"][i] for i in sampled], [d["folds"][i] for i in sampled], "o-", label="sampled AFT")
    ex = [i for i, q in enumerate(d["quadrature"]) if q == "exact"]
    ax.axhline(d["folds"][ex[0]], color="C2", ls="--", label="exact projection of the contact law (any N)")
    ax.set_xlabel("time samples per period N")
    ax.set_ylabel("folds found on the g = -0.6 m curve")
    ax.set_title("Supplement: spurious folds of sampled AFT vs N (H = %d); exact projection: %d"
                 % (d["H"][ex[0]], d["folds"][ex[0]]))
    ax.legend()
    out.append(save(fig, fig_dir / "figS1_ch03_aft_samples.png"))
    return out
