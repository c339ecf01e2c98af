"""Figures 7-18 of thesis ch. 3 (mass against a wall) from build/data/ch03_mass_wall."""
import math

import matplotlib.pyplot as plt

from style import legend_styles, mark_contact, plot_branch, read_csv, save


def frc_figure(data_dir, fig_dir, name, title, cases):
    """cases: list of (label, legend text). Plots x_max and x_min vs omega, gap levels."""
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    drawn = set()   # gap levels already drawn (Figs. 11-12 share one gap)
    for n, (label, text) in enumerate(cases):
        d = read_csv(data_dir / ("frc_%s.csv" % label))
        c = "C%d" % n
        plot_branch(ax, d, "x_max", c, text + ": $x_{max}$")
        plot_branch(ax, d, "x_min", c)
        mark_contact(ax, d, "x_max", c)
        g = float(label.split("_")[0][1:])
        if g in drawn:
            continue
        drawn.add(g)
        ax.axhline(-g, color=c, ls=":", lw=1)
        ax.annotate("in contact where x > -g = %g m" % -g, (1.25, -g), color=c, fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    ax.set_xlim(0.8, 1.6)   # the data span 0.5-2 rad/s; nothing happens outside this window
    ax.set_xlabel(r"forcing frequency $\omega$ [rad/s] (zoom; data 0.5-2)")
    ax.set_ylabel(r"displacement $x_{max}$ (upper), $x_{min}$ (lower) [m]")
    ax.set_title(title)
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + legend_styles(ax), loc="best", ncol=2, framealpha=0.9)
    return save(fig, fig_dir / name)


def time_figures(data_dir, fig_dir, label, gap, first_fig, names):
    d = read_csv(data_dir / ("frc_%s.csv" % label))
    marks = read_csv(data_dir / "marks.csv")
    out = []
    for k, mark in enumerate("ABC"):
        i = [j for j in range(len(marks["label"])) if marks["label"][j] == label and marks["mark"][j] == mark][0]
        w = marks["omega"][i]
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(9.5, 3.8))
        plot_branch(a1, d, "x_max", "C0", r"$x_{max}$")
        plot_branch(a1, d, "x_min", "C0")
        mark_contact(a1, d, "x_max", "C0")
        a1.axhline(-gap, color="C3", ls=":", lw=1, label="wall: x = -g = %g m" % -gap)
        a1.plot([w], [marks["x_max"][i]], "o", color="C3", ms=7, mfc="none", label="current point %s" % mark)
        a1.set_xlim(0.8, 1.6)
        a1.set_xlabel(r"$\omega$ [rad/s] (zoom; data 0.5-2)")
        a1.set_ylabel(r"$x_{max}$, $x_{min}$ [m]")
        a1.set_title("frequency response (g = %g m, F0 = 1 N)" % gap)
        h, _ = a1.get_legend_handles_labels()
        a1.legend(handles=h + legend_styles(a1), fontsize=7, loc="lower right", framealpha=0.9)
        t = read_csv(data_dir / ("time_%s_%s.csv" % (label, mark)))
        a2.plot(t["t"], t["x"], color="C0", label="x(t), %s contact" % marks["contact"][i])
        a2.axhline(-gap, color="C3", ls=":", lw=1, label="wall: x = -g")
        a2.set_xlabel("time t [s]  (two periods)")
        a2.set_ylabel("x [m]")
        a2.set_title(r"time history at $\omega$ = %.4f rad/s" % w)
        a2.legend(fontsize=7, loc="best", framealpha=0.9)
        out.append(save(fig, fig_dir / ("fig%02d_%s.png" % (first_fig + k, names[k]))))
    return out


def draw(data_dir, fig_dir):
    out = []
    # Fig. 7: linear FRFs
    d = read_csv(data_dir / "fig07_linear.csv")
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.semilogy(d["omega"], d["x_open"], label="open contact (k), resonance 1 rad/s")
    ax.semilogy(d["omega"], d["x_full"], label=r"full contact (k + k$_c$), resonance $\sqrt{2}$ rad/s")
    ax.set_xlabel(r"$\omega$ [rad/s]")
    ax.set_ylabel("amplitude |X| [m]")
    ax.set_title("Fig. 7: linear response, F = 0.01 N, c = 0.01 N s/m")
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
    ax.set_title(r"Fig. 8: contact force, $k_c$ = 1 N/m, $x_0$ = 1 m")
    ax.legend()
    out.append(save(fig, fig_dir / "fig08_contact_force.png"))
    out.append(frc_figure(data_dir, fig_dir, "fig09_masswall_gap.png", "Fig. 9: gap g = -1.2 and -0.6 m (F = 0.01 N)",
                          [("g-1.2_F0.01", "g = -1.2 m"), ("g-0.6_F0.01", "g = -0.6 m")]))
    out.append(frc_figure(data_dir, fig_dir, "fig10_masswall_preload.png", "Fig. 10: preload g = 1 and 0.4 m (F = 0.01 N)",
                          [("g1_F0.01", "g = 1 m"), ("g0.4_F0.01", "g = 0.4 m")]))
    out.append(frc_figure(data_dir, fig_dir, "fig11_masswall_force_g-0.6.png", "Fig. 11: g = -0.6 m, F = 0.01 and 0.001 N",
                          [("g-0.6_F0.01", "F = 0.01 N"), ("g-0.6_F0.001", "F = 0.001 N")]))
    out.append(frc_figure(data_dir, fig_dir, "fig12_masswall_force_g-1.2.png", "Fig. 12: g = -1.2 m, F = 0.01 and 0.03 N",
                          [("g-1.2_F0.01", "F = 0.01 N"), ("g-1.2_F0.03", "F = 0.03 N")]))
    out += time_figures(data_dir, fig_dir, "g-1.5_F0.01_F01", -1.5, 13,
                        ["static_gap_before_contact", "static_gap_in_contact", "static_gap_after_contact"])
    out += time_figures(data_dir, fig_dir, "g-0.5_F0.01_F01", -0.5, 16,
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
    ax.set_title("Supplement: spurious folds of sampled AFT vs N (H = 10); true count 2")
    ax.legend()
    out.append(save(fig, fig_dir / "figS1_ch03_aft_samples.png"))
    return out
