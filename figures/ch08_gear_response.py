"""Chapter 8: the gear mesh driven by its own static transmission error.

fig67  k(t) = F0/e(t) over one mesh cycle, T = 100/200/300 N m, with the mean
fig69  RMS of the oscillating part of x vs mesh frequency, H = 1
fig70  the same with H = 5
fig70s_time_history    x(t), e(t) and the contact force at a contact-loss point
fig70s_H_convergence   the 300 N m curve for H = 1, 5, 10, 20
fig70s_parametric      the 300 N m curve of the thesis' model and of the parametric one
Everything (titles, parameters) comes from the run's files.
The curves are harmonic balance (values="hb"): these figures are about HB at H = 1 and 5 (the
thesis figures) and its convergence in H; the tables hold the exact orbit beside them (x_rms_ac_exact).
"""
import json

from matplotlib.lines import Line2D

from style import (COMPARISON_COLOURS, LINEAR_CLOSED, THESIS_TORQUES, case_rows, contact_rug, untrusted_stability,
                   legend_styles, plot_branch, plt, read_csv, read_params, rug_room, save, torque_colour,
                   unresolved_handle)

UM = 1e6
COLORS = {T: torque_colour(T) for T in THESIS_TORQUES}   # the torque colours of every chapter
# Harmonic counts of one torque: comparison colours (never a torque colour, never black, which is
# the stable/unstable legend's colour).
H_COLORS = {1: COMPARISON_COLOURS[0], 5: COMPARISON_COLOURS[1], 10: COMPARISON_COLOURS[2], 20: COMPARISON_COLOURS[3]}
MODEL_COLOURS = {"constant": torque_colour(300.0), "parametric": COMPARISON_COLOURS[0]}


def key_numbers(data_dir):
    with open(data_dir / "key_numbers.json") as f:
        return {k: v["value"] for k, v in json.load(f).items()}


def style_legend(extra):
    return [Line2D([], [], color="k", ls="-", label="stable (Floquet)"),
            Line2D([], [], color="k", ls="--", label="unstable (Floquet)")] + extra


def fig67(data_dir, fig_dir, kn):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for T, col in COLORS.items():
        tag = "T%d" % T
        d = read_csv(data_dir / ("fig67_%s.csv" % tag))
        p8 = read_csv(data_dir / ("fig67_p8_%s.csv" % tag))
        ph = d["phase"] + [1.0]
        k = [v / 1e6 for v in d["k"]] + [d["k"][0] / 1e6]
        ax.plot(ph, k, color=col, lw=1.4, label="T = %d N m (load moving continuously)" % T)
        ax.plot(p8["phase"], [v / 1e6 for v in p8["k"]], ls="none", marker="o", ms=4, mfc="none", color=col)
        kc = kn["kc_" + tag] / 1e6
        ax.axhline(kc, color=col, ls=":", lw=1)
        ax.annotate("mean %.1f MN/m" % kc, (0.87, kc), xycoords=("axes fraction", "data"), ha="center",
                    va="bottom", fontsize=8, color=col)
    ax.plot([], [], ls="none", marker="o", mfc="none", color="k", label="ch. 7: 8 positions per base pitch")
    ax.set_xlabel("mesh phase [mesh cycles]")
    ax.set_ylabel("k(t) = F0 / e(t)  [MN/m]")
    ax.set_xlim(0, 1)
    ax.set_title("Fig. 67: mesh stiffness over one mesh cycle (thesis kc = 473.2 MN/m at 300 N m)")
    ax.legend(loc="lower left")
    return save(fig, fig_dir / "fig67_mesh_stiffness.png")


def response_figure(data_dir, fig_dir, name, fig_no, labels, params, cases, what="DTE response"):
    """RMS of x vs mesh frequency for the curves `labels` (torque colours), their
    the contact state as a rug (one row per torque), the linear closed-contact curve of the last one."""
    fig, ax = plt.subplots(figsize=(10.5, 5))
    ymax = max(read_csv(data_dir / ("linear_%s.csv" % labels[-1]))["x_rms_ac"]) * UM   # the linear peak too
    for lb in labels:
        d = read_csv(data_dir / ("frc_%s.csv" % lb))
        ymax = max(ymax, max(d["x_rms_ac"]) * UM)
    extra, flicker = [], False
    for i, lb in enumerate(labels):
        row = cases[lb]
        col = COLORS[row["torque"]]
        d = read_csv(data_dir / ("frc_%s.csv" % lb))
        bad = untrusted_stability(d, x="f_mesh_hz")
        flicker = flicker or bool(bad)
        plot_branch(ax, d, y="x_rms_ac", x="f_mesh_hz", color=col, scale=UM, unresolved=bad, values="hb",
                    label="T = %d N m (kc %.1f MN/m)" % (row["torque"], row["kc"] / 1e6))
        contact_rug(ax, d, x="f_mesh_hz", row=i, colour=col)
    lin = read_csv(data_dir / ("linear_%s.csv" % labels[-1]))
    ax.plot(lin["f_mesh_hz"], [v * UM for v in lin["x_rms_ac"]], **LINEAR_CLOSED, zorder=1,
            label="linear, contact always closed (%d N m)" % cases[labels[-1]]["torque"])
    extra += legend_styles()[2:]   # the contact rug: one row per torque, the torque's tick at its left end
    H = int(cases[labels[0]]["H"])
    if flicker:
        extra.append(unresolved_handle(H))
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("RMS of the oscillating part of x  [um]")
    ax.set_xlim(params["f_min_hz"], params["f_max_hz"])
    ax.set_ylim(0, ymax * 1.08)
    rug_room(ax, len(labels))
    ax.set_title("Fig. %s: %s, H = %d (STE truncated to %d harmonic%s),\nme = %.3f kg, zeta = %g"
                 % (fig_no, what, H, H, "" if H == 1 else "s", cases[labels[0]]["me"], params["zeta"]), fontsize=10)
    h, _ = ax.get_legend_handles_labels()
    # right of the axes: inside, it would cover the curves' descent
    ax.legend(handles=h + style_legend(extra), loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5)
    return save(fig, fig_dir / name)


def time_history(data_dir, fig_dir, kn, cases):
    d = read_csv(data_dir / "time_history.csv")
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.5, 5.5), sharex=True)
    a1.plot(d["t_ms"], d["x_um"], color="C3", label="x (dynamic transmission error)")
    a1.plot(d["t_ms"], d["e_um"], color="C0", ls="--", label="e (STE, 5 harmonics)")
    a1.plot(d["t_ms"], [x + e for x, e in zip(d["x_um"], d["e_um"])], color="k", lw=0.9,
            label="x + e (mesh deflection; contact lost where < 0)")
    a1.axhline(0, color="0.5", lw=0.6)
    a1.set_ylabel("[um]")
    lo, hi = a1.get_ylim()
    a1.set_ylim(lo, hi + 0.6 * (hi - lo))
    a1.legend(fontsize=7.5, loc="upper center", ncol=2)
    a2.plot(d["t_ms"], [f / 1e3 for f in d["contact_force"]], color="k")
    F0 = cases["T300_H5"]["F0"]
    a2.axhline(F0 / 1e3, color="C1", ls=":", label="F0 = T/r = %.0f N (the mean)" % F0)
    a2.set_ylabel("contact force [kN]")
    a2.set_xlabel("time [ms] (two mesh periods)")
    a2.legend(fontsize=7.5)
    a1.set_title("Supplement: T = 300 N m, H = 5, f_mesh = %.0f Hz (stable, contact lost)"
                 % kn["time_history_f_hz"])
    return save(fig, fig_dir / "fig70s_time_history.png")


def convergence(data_dir, fig_dir, params, cases):
    fig, ax = plt.subplots(figsize=(10.5, 5))
    unresolved = []
    for lb, row in cases.items():
        if row["torque"] != 300.0 or row["model"] != "constant":
            continue
        H = int(row["H"])
        d = read_csv(data_dir / ("frc_%s.csv" % lb))
        bad = untrusted_stability(d, x="f_mesh_hz")   # the same rule as Figs. 69-70
        if bad:
            unresolved.append(H)
        plot_branch(ax, d, y="x_rms_ac", x="f_mesh_hz", color=H_COLORS.get(H, COMPARISON_COLOURS[4]), scale=UM, values="hb",
                    unresolved=bad, label="H = %d (peak %.2f um at %.0f Hz)" % (H, row["peak_rms_um"], row["peak_f_hz"]))
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("RMS of the oscillating part of x  [um]")
    ax.set_xlim(params["f_min_hz"], params["f_max_hz"])
    ax.set_title("Supplement: H-convergence of the 300 N m curve (STE truncated to H harmonics)")
    h, _ = ax.get_legend_handles_labels()
    extra = [unresolved_handle(" and ".join(map(str, unresolved)))] if unresolved else []
    # right of the axes: inside, it would cover the peaks the figure compares
    ax.legend(handles=h + style_legend(extra), loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7.5)
    return save(fig, fig_dir / "fig70s_H_convergence.png")


def parametric(data_dir, fig_dir, params, cases, labels):
    """Both models' 300 N m curves (same H, same STE), the contact state as a rug (one row per model)."""
    fig, ax = plt.subplots(figsize=(8, 6))
    styles = {"constant": (MODEL_COLOURS["constant"], "thesis model, kc constant (RMS of x)"),
              "parametric": (MODEL_COLOURS["parametric"], "parametric, k(t) = F0/e(t) (RMS of d)")}
    curves = [(lb, cases[lb]) for lb in labels]
    ymax = max(max(read_csv(data_dir / ("frc_%s.csv" % lb))["x_rms_ac"]) for lb, _ in curves) * UM
    for i, (lb, row) in enumerate(curves):
        col, text = styles[row["model"]]
        d = read_csv(data_dir / ("frc_%s.csv" % lb))
        plot_branch(ax, d, y="x_rms_ac", x="f_mesh_hz", color=col, scale=UM, values="hb",
                    label="%s (peak %.2f um at %.0f Hz)" % (text, row["peak_rms_um"], row["peak_f_hz"]))
        contact_rug(ax, d, x="f_mesh_hz", row=i, colour=col)
    extra = legend_styles()[2:]
    row = curves[0][1]
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("RMS of the oscillating part of the DTE  [um]")
    ax.set_xlim(params["f_min_hz"], params["f_max_hz"])
    ax.set_ylim(0, ymax * 1.08)
    rug_room(ax, len(curves))
    ax.set_title("Supplement: T = %d N m, H = %d, the thesis' model and the parametric one (k(t) = F0/e(t))"
                 % (row["torque"], row["H"]), fontsize=10)
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + style_legend(extra), loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, fontsize=7.5)
    fig.subplots_adjust(bottom=0.27)
    return save(fig, fig_dir / "fig70s_parametric.png")


def draw(data_dir, fig_dir):
    params = read_params(data_dir)
    cases = case_rows(data_dir)
    kn = key_numbers(data_dir)
    made = []
    if (data_dir / "fig67_T300.csv").exists():
        made.append(fig67(data_dir, fig_dir, kn))
    thesis = {lb: r for lb, r in cases.items() if r["figure"] in ("69", "70", "H-convergence")}
    for fig_no, H, name in (("69", 1, "fig69_response_H1.png"), ("70", 5, "fig70_response_H5.png")):
        labels = [lb for lb, r in thesis.items() if int(r["H"]) == H]
        if labels:
            made.append(response_figure(data_dir, fig_dir, name, fig_no, labels, params, cases))
    if (data_dir / "time_history.csv").exists():
        made.append(time_history(data_dir, fig_dir, kn, cases))
    if sum(1 for r in thesis.values() if r["torque"] == 300.0) > 1:
        made.append(convergence(data_dir, fig_dir, params, thesis))
    # the parametric case and the thesis-model curve with the same torque and H
    for lb, r in cases.items():
        if r["figure"] != "parametric model":
            continue
        same = [m for m, q in cases.items() if m != lb and q["model"] == "constant"
                and q["torque"] == r["torque"] and q["H"] == r["H"]]
        if same:
            made.append(parametric(data_dir, fig_dir, params, cases, same[:1] + [lb]))
    return made
