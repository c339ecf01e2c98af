"""Chapter 9: backlash limits the static transmission error at high torque.

fig77  STE over one mesh cycle with and without backlash, T = 100/200/300 N m
fig77s the single-pair zone: local normal backlash b_n(phase) against the STE
fig78  Fourier coefficients with and without backlash, side by side
fig79  our coefficients with backlash (Parker et al.'s bars are not available)
fig80  RMS of x vs mesh frequency with backlash, H = 1, three torques
fig81  the same with H = 5
fig82  300 N m with and without backlash (both readings), H = 1 and 5
Everything (titles, parameters) comes from the run's files.
The curves are harmonic balance (values="hb"), as in chapter 8: HB at H = 1 and 5 is the subject.
"""
import json

import ch08_gear_response as ch08
import mesh_geometry  # noqa: E402
from style import (COMPARISON_COLOURS, case_rows, untrusted_stability, plot_branch, plt, read_csv, read_params, save,
                   unresolved_handle)

UM = 1e6
COLORS = ch08.COLORS
# Backlash readings of one torque: comparison colours, never a torque colour.
# "none" is chapter 8's 300 N m curve: its torque colour.
READING_STYLE = {"none": (ch08.COLORS[300.0], "-"), "clip": (COMPARISON_COLOURS[0], "-"),
                 "contact": (COMPARISON_COLOURS[1], "-")}


def key_numbers(data_dir):
    with open(data_dir / "key_numbers.json") as f:
        return {k: v["value"] for k, v in json.load(f).items()}


def reading_text(params):
    return "b = %g um, mu: %s, values: %s" % (params["backlash_um"], params["backlash_mu"], params["backlash_values"])


def closed(xs, ys):
    """One mesh cycle closed at phase 1 (periodic)."""
    return list(xs) + [1.0], list(ys) + [ys[0]]


def fig77(data_dir, fig_dir, params):
    fig, ax = plt.subplots(figsize=(8, 4.6))
    for T, col in COLORS.items():
        d = read_csv(data_dir / ("fig77_T%d.csv" % T))
        untouched = all(abs(a - b) < 1e-9 and abs(a - c) < 1e-9
                        for a, b, c in zip(d["ste_um"], d["ste_clip_um"], d["ste_contact_um"]))
        if untouched:   # one line, not three on top of each other that the legend would list
            ax.plot(*closed(d["phase"], d["ste_um"]), color=col, lw=1.5,
                    label="T = %d N m: backlash not reached (all readings = without)" % T)
            continue
        ax.plot(*closed(d["phase"], d["ste_um"]), color=col, lw=1.0, ls=":", label="T = %d N m, without backlash" % T)
        ax.plot(*closed(d["phase"], d["ste_clip_um"]), color=col, lw=1.5, label="T = %d N m, clip (thesis)" % T)
        ax.plot(*closed(d["phase"], d["ste_contact_um"]), color=col, lw=1.0, ls="--",
                label="T = %d N m, adjacent pair as a spring" % T)
        if T == 300.0:
            ax.plot(d["phase"], d["bn_um"], color="k", lw=1.0, label="local normal backlash b_n (single-pair zone)")
    ax.set_xlabel("mesh phase [mesh cycles]")
    ax.set_ylabel("STE [um]")
    ax.set_xlim(0, 1)
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo, hi + 0.45 * (hi - lo))
    ax.set_title("Fig. 77: STE with backlash (%s)" % reading_text(params))
    ax.legend(loc="upper left", ncol=2, fontsize=7.5)
    return save(fig, fig_dir / "fig77_ste_backlash.png")


def fig77s(data_dir, fig_dir, params, kn):
    fig, ax = plt.subplots(figsize=(8, 4.6))
    d = read_csv(data_dir / "fig77_T300.csv")
    single = [i for i, p in enumerate(d["pairs"]) if p == 1]
    ph = [d["phase"][i] for i in single]
    ax.plot(ph, [d["ste_um"][i] for i in single], color="0.3", ls=":", marker=".", ms=4,
            label="300 N m without backlash (ch. 8)")
    low = ", ".join("%d N m: %.2f um" % (T, kn["max_ste_free_um_T%d" % T]) for T in COLORS if T != 300.0)
    ax.plot(ph, [d["ste_clip_um"][i] for i in single], color=READING_STYLE["clip"][0], lw=3.0, alpha=0.8, zorder=3,
            label="300 N m, clip (= b_n where limited)")
    ax.plot(ph, [d["ste_contact_um"][i] for i in single], color=READING_STYLE["contact"][0], lw=1.2, ls="--",
            label="300 N m, adjacent pair as a spring")
    ax.plot(ph, [d["bn_um"][i] for i in single], color="k", lw=1.0, zorder=4, label="b_n = b cos(mu), mu as set (%s)" % params["backlash_mu"])
    for name, ls in (("thesis", "-."), ("exact", (0, (1, 1)))):
        ax.axhline(kn["bn_E_prime_um_" + name], color="0.45", lw=0.9, ls=ls,
                   label="b_n at E' = %.3f um (%s eps, eps')" % (kn["bn_E_prime_um_" + name], name))
    ax.axhline(kn["bn_C_um"], color="0.2", lw=0.9, ls="--", label="b cos(alpha) = %.4f um (at C; involute: everywhere)" % kn["bn_C_um"])
    ax.set_xlabel("mesh phase [mesh cycles] (single-pair zone A'E')")
    ax.set_ylabel("[um]")
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo, hi + 0.7 * (hi - lo))
    ax.set_title("Supplement: b_n(phase) against the 300 N m STE, single-pair zone (b = %g um)\n"
                 "(largest STE at %s: never reaches b_n)" % (params["backlash_um"], low))
    ax.legend(loc="upper center", ncol=2, fontsize=7)
    return save(fig, fig_dir / "fig77s_bn_vs_ste.png")


def fig78(data_dir, fig_dir, params):
    d = read_csv(data_dir / "fig78_spectrum.csv")
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.9), sharey=True)
    kmax = 8
    for ax, T in zip(axes, COLORS):
        rows = [i for i, t in enumerate(d["torque"]) if t == T and d["k"][i] <= kmax]
        k = [d["k"][i] for i in rows]
        for j, (col, name, lab) in enumerate((("free_um", "0.6", "without backlash"),
                                              ("clip_um", READING_STYLE["clip"][0], "clip"),
                                              ("contact_um", READING_STYLE["contact"][0], "adjacent pair as a spring"))):
            ax.bar([x + (j - 1) * 0.27 for x in k], [d[col][i] for i in rows], width=0.27, color=name, label=lab)
        ax.set_xlabel("harmonic k of the mesh frequency")
        ax.set_title("T = %d N m" % T)
        ax.set_xticks(range(1, kmax + 1))
    axes[0].set_ylabel("amplitude sqrt(a_k^2 + b_k^2) [um]")
    axes[0].legend(fontsize=7.5)
    fig.suptitle("Fig. 78: Fourier coefficients of the STE with and without backlash (%s)" % reading_text(params),
                 fontsize=10)
    return save(fig, fig_dir / "fig78_fourier_backlash.png")


def fig79(data_dir, fig_dir, params):
    d = read_csv(data_dir / "fig78_spectrum.csv")
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    kmax = 8
    for j, T in enumerate(COLORS):
        rows = [i for i, t in enumerate(d["torque"]) if t == T and d["k"][i] <= kmax]
        col = "clip_um" if params["backlash_model"] == "clip" else "contact_um"
        ax.bar([d["k"][i] + (j - 1) * 0.27 for i in rows], [d[col][i] for i in rows], width=0.27,
               color=COLORS[T], label="T = %d N m" % T)
    ax.text(0.98, 0.97, "Parker, Vijayakar & Imajo (2000): their coefficients\nare not available; nothing is drawn in their place",
            transform=ax.transAxes, ha="right", va="top", fontsize=8, color="0.3",
            bbox=dict(fc="white", ec="0.7"))
    ax.set_xlabel("harmonic k of the mesh frequency")
    ax.set_ylabel("amplitude [um]")
    ax.set_xticks(range(1, kmax + 1))
    ax.legend(loc="center right", fontsize=8)
    ax.set_title("Fig. 79: our STE coefficients with backlash (%s, %s)" % (params["backlash_model"], reading_text(params)))
    return save(fig, fig_dir / "fig79_fourier_backlash_ours.png")


def fig82(data_dir, fig_dir, params, cases):
    fig, grid = plt.subplots(2, 2, figsize=(12, 8), gridspec_kw={"height_ratios": [1.2, 1]})
    for ax, zoom, H in zip(grid[0], grid[1], (1, 5)):
        rows = [(lb, r) for lb, r in cases.items() if r["torque"] == 300.0 and int(r["H"]) == H]
        rows.sort(key=lambda lr: list(READING_STYLE).index(lr[1]["reading"]))
        flicker = False
        for lb, r in rows:
            col, _ = READING_STYLE[r["reading"]]
            d = read_csv(data_dir / ("frc_%s.csv" % lb))
            name = "without backlash" if r["reading"] == "none" else r["reading"]
            bad = untrusted_stability(d, x="f_mesh_hz")
            flicker = flicker or bool(bad)
            plot_branch(ax, d, y="x_rms_ac", x="f_mesh_hz", color=col, scale=UM, unresolved=bad, values="hb",
                        label="%s: kc %.2f MN/m, peak %.2f um at %.0f Hz" % (name, r["kc"] / 1e6, r["peak_rms_um"], r["peak_f_hz"]))
            plot_branch(zoom, d, y="x_rms_ac", x="f_mesh_hz", color=col, scale=UM, unresolved=bad, values="hb")
        peak = max(r["peak_rms_um"] for _, r in rows)
        f_peak = min(r["peak_f_hz"] for _, r in rows)
        zoom.set_xlim(f_peak - 60, f_peak + 200)
        zoom.set_ylim(peak - 2.0, peak + 0.3)
        zoom.set_title("H = %d: zoom on the peak" % H)
        zoom.set_xlabel("mesh frequency [Hz]")
        zoom.set_ylabel("RMS of the oscillating part of x  [um]")
        ax.set_xlabel("mesh frequency [Hz]")
        ax.set_ylabel("RMS of the oscillating part of x  [um]")
        ax.set_xlim(params["f_min_hz"], params["f_max_hz"])
        lo, hi = ax.get_ylim()
        ax.set_ylim(0, hi * 1.6)   # room for the legend above the peak
        ax.set_title("T = 300 N m, H = %d" % H)
        h, _ = ax.get_legend_handles_labels()
        ax.legend(handles=h + ch08.style_legend([unresolved_handle(H)] if flicker else []), loc="upper right",
                  fontsize=7)
    fig.suptitle("Fig. 82: with and without backlash at 300 N m (%s), zeta = %g" % (reading_text(params), params["zeta"]),
                 fontsize=10)
    return save(fig, fig_dir / "fig82_backlash_vs_none.png")


def draw(data_dir, fig_dir):
    params = read_params(data_dir)
    cases = case_rows(data_dir)
    kn = key_numbers(data_dir)
    made = []
    if (data_dir / "fig77_T300.csv").exists():
        made += [fig77(data_dir, fig_dir, params), fig77s(data_dir, fig_dir, params, kn),
                 fig78(data_dir, fig_dir, params), fig79(data_dir, fig_dir, params)]
    for fig_no, H, name in (("80", 1, "fig80_response_backlash_H1.png"), ("81", 5, "fig81_response_backlash_H5.png")):
        labels = [lb for lb, r in cases.items() if int(r["H"]) == H and r["figure"] == float(fig_no)]
        if labels:
            made.append(ch08.response_figure(data_dir, fig_dir, name, fig_no, labels, params, cases,
                                             what="DTE response with backlash (%s)" % params["backlash_model"]))
    if any(r["reading"] == "none" for r in cases.values()):
        made.append(fig82(data_dir, fig_dir, params, cases))
    if (data_dir / "backlash_geometry.csv").exists():   # Fig. 75 (figures/mesh_geometry.py)
        g = read_csv(data_dir / "backlash_geometry.csv")
        rows = {v: {k: g[k][i] for k in g if k != "values"} for i, v in enumerate(g["values"])}
        made.append(mesh_geometry.backlash_limit_figure(rows, fig_dir / "fig75_backlash_limit.png"))
    return made
