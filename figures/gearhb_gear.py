#!/usr/bin/env python3
"""Draw the figures of a gearhb_gear run: gearhb_gear.py DIR

Writes into DIR (the run's own folder; gearhb_gear calls this with plot=1):
  ste.png       the loaded static transmission error STE over one mesh cycle, one
                curve per torque of the file, the number of loaded pairs shaded;
  stiffness.png the mesh stiffness k = F / STE over the mesh cycle, its mean dotted;
  shares.png    the share of the tooth force each pair carries, per torque;
  spectrum.png  the STE amplitude per mesh order (order 0, the mean, left out);
  harris.png    the Harris map: STE peak-to-peak against torque, with and without
                the file's tip relief, the file's torques marked;
  root_stress.png  (method fe) the root stress of a tooth of each gear over the path of
                contact per torque, ISO 6336-3's sigma_F0 dotted (top), and along both
                fillets at the peak of the largest torque, ISO's 30-degree point marked (below);
and, for a file with a speed range, the dynamics figures of gear_dynamics.py
(response.png, campbell.png, time_history.png, dte_spectrum.png).
The mesh phase runs over one base pitch: pair 1 is the pair nearest the start of
contact A (it enters at A at phase 0), pair 2 the one a base pitch ahead of it.
"""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

import gear_dynamics  # noqa: E402
from style import read_csv, save, torque_colour  # noqa: E402


def load(d_dir):
    params = json.load(open(d_dir / "params.json"))
    kn = {k: v["value"] for k, v in json.load(open(d_dir / "key_numbers.json")).items()}
    torques = params["torques"]
    ste = [read_csv(d_dir / ("ste_%d.csv" % (i + 1))) for i in range(len(torques))]
    return params, kn, torques, ste


def title(ax, params, kn, what):
    ax.set_title("%s\n%s\neps_alpha = %.4f, a = %.3f mm, alpha_w = %.3f deg" % (
        params.get("name", "gear pair"), what, kn["contact_ratio"], kn["centre_distance_m"] * 1e3,
        kn["operating_pressure_angle_deg"]), fontsize=8)


def shade_loaded(ax, d, label=True):
    """Grey bands where two or more pairs carry load (from the last torque's column); none for a
    helical face in slices (several tooth pairs always share its load)."""
    if "loaded_contacts" in d:
        return
    ph, n = d["phase"], d["loaded_pairs"]
    step = ph[1] - ph[0] if len(ph) > 1 else 1.0
    first = True
    for i, p in enumerate(ph):
        if n[i] >= 2:
            ax.axvspan(p - step / 2, p + step / 2, color="0.88", lw=0,
                       label="two pairs loaded (highest torque)" if label and first else None)
            first = False


def ste_figure(d_dir, params, kn, torques, ste):
    fig, ax = plt.subplots(figsize=(6.8, 4.4))
    shade_loaded(ax, ste[-1])
    for i, (T, d) in enumerate(zip(torques, ste)):
        ax.plot(d["phase"], d["ste_um"], "-", color=torque_colour(T, torques), marker=".", ms=3,
                label="T1 = %g N m: peak-to-peak %.3f um" % (T, kn["ste_ptp_um_%d" % (i + 1)]))
    ax.set_xlabel("mesh phase [mesh cycles] (0: a pair enters at A)")
    ax.set_ylabel("static transmission error STE [um]")
    ax.set_xlim(0, 1)
    ax.set_ylim(bottom=0)   # from zero: the mean is part of the STE, the ripple is read against it
    title(ax, params, kn, "loaded STE over one mesh cycle")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    save(fig, d_dir / "ste.png")


def stiffness_figure(d_dir, params, kn, torques, ste):
    fig, ax = plt.subplots(figsize=(6.8, 4.4))
    shade_loaded(ax, ste[-1])
    for i, (T, d) in enumerate(zip(torques, ste)):
        k = kn["mesh_stiffness_mean_N_per_m_%d" % (i + 1)] / 1e6
        ax.plot(d["phase"], [v / 1e6 for v in d["k_N_per_m"]], "-", color=torque_colour(T, torques),
                label="T1 = %g N m (mean %.2f MN/m, dotted)" % (T, k))
        ax.axhline(k, color=torque_colour(T, torques), ls=":", lw=1)
    iso = kn.get("iso6336_c_gamma_alpha_N_per_m")
    if iso:
        ax.axhline(iso / 1e6, color="k", ls="--", lw=1, label="ISO 6336-1 c_gamma_alpha b = %.1f MN/m" % (iso / 1e6))
    ax.set_xlabel("mesh phase [mesh cycles] (0: a pair enters at A)")
    ax.set_ylabel("mesh stiffness k = F / STE [MN/m]")
    ax.set_xlim(0, 1)
    ax.set_ylim(bottom=0)   # from zero: the note below sits under every curve, none is clipped
    title(ax, params, kn, "mesh stiffness over one mesh cycle")
    relieved = any(g.get("tip_relief", {}).get("amount", 0) > 0 for g in params["gears"])
    if kn.get("method_potential_energy") == 1 and not relieved and len(torques) > 1:
        ax.text(0.99, 0.62, "potential-energy method: k does not depend\non the torque, the curves lie on each other",
                transform=ax.transAxes, ha="right", fontsize=7, bbox=dict(fc="white", ec="0.7"))
    if relieved:
        ax.text(0.01, 0.02, "with tip relief the STE includes the relief separations:\n"
                "F / STE is a secant value, not the stiffness of the teeth", transform=ax.transAxes,
                fontsize=7, va="bottom", bbox=dict(fc="white", ec="0.7"))
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
    save(fig, d_dir / "stiffness.png")


def shares_figure(d_dir, params, kn, torques, ste):
    fig, ax = plt.subplots(figsize=(6.8, 4.4))
    styles = ["-", "--", ":", "-."]
    for i, (T, d) in enumerate(zip(torques, ste)):
        pairs = sorted(k for k in d if k.startswith("share_pair_"))
        for j, col in enumerate(pairs):
            ax.plot(d["phase"], d[col], styles[j % 4], color=torque_colour(T, torques),
                    label="T1 = %g N m, pair %d" % (T, j + 1))
    if "loaded_contacts" in ste[0]:
        ax.set_xlabel("mesh phase [mesh cycles] (helical: each tooth pair's share over the whole face)")
    else:
        ax.set_xlabel("mesh phase [mesh cycles] (pair 1 enters at A at phase 0; pair 2 is one base pitch ahead)")
    ax.set_ylabel("share of the tooth force F_i / F [-]")
    ax.set_xlim(0, 1)
    ax.set_ylim(-0.02, 1.02)
    title(ax, params, kn, "load sharing between the pairs in contact")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3, frameon=False)
    save(fig, d_dir / "shares.png")


def load_map_figure(d_dir, params, kn, torques):
    """A helical face in slices: the line load over face width and roll angle at the largest torque."""
    i = max(range(len(torques)), key=lambda j: torques[j])
    m = read_csv(d_dir / ("load_map_%d.csv" % (i + 1)))
    on = [j for j, q in enumerate(m["line_load_N_per_mm"]) if q > 0]
    fig, ax = plt.subplots(figsize=(6.8, 4.4))
    sc = ax.scatter([m["roll_angle_deg"][j] for j in on], [1e3 * m["y_m"][j] for j in on],
                    c=[m["line_load_N_per_mm"][j] for j in on], s=6, marker="s", cmap="viridis", lw=0)
    fig.colorbar(sc, ax=ax, label="line load [N/mm]")
    ax.set_xlabel("roll angle of gear 1 at the contact [deg] (A to E)")
    ax.set_ylabel("across the face y [mm]")
    ax.set_ylim(0, 1e3 * max(g["b"] for g in params["gears"]))
    title(ax, params, kn, "load over the face, T1 = %g N m (%d slices, eps_beta = %.3f)"
          % (torques[i], kn["slices"], kn["overlap_ratio"]))
    save(fig, d_dir / "load_map.png")


def spectrum_figure(d_dir, params, kn, torques):
    s = read_csv(d_dir / "spectrum.csv")
    orders = [int(k) for k in s["order"]][1:]
    n = len(torques)
    width = 0.8 / n
    fig, ax = plt.subplots(figsize=(6.8, 4.0))
    for i, T in enumerate(torques):
        ax.bar([k - 0.4 + width * (i + 0.5) for k in orders], s["amplitude_um_%d" % (i + 1)][1:], width,
               color=torque_colour(T, torques), label="T1 = %g N m (mean %.3f um)" % (T, s["amplitude_um_%d" % (i + 1)][0]))
    ax.set_xlabel("mesh order k (harmonic of the mesh frequency)")
    ax.set_ylabel("STE amplitude sqrt(a_k^2 + b_k^2) [um]")
    ax.set_xticks(orders)
    title(ax, params, kn, "STE spectrum per mesh order (the mean, order 0, in the legend)")
    ax.legend(fontsize=7)
    save(fig, d_dir / "spectrum.png")


def harris_figure(d_dir, params, kn, torques):
    h = read_csv(d_dir / "harris.csv")
    relieved = any(g.get("tip_relief", {}).get("amount", 0) > 0 for g in params["gears"])
    fig, ax = plt.subplots(figsize=(6.8, 4.2))
    ax.plot(h["torque_Nm"], h["ste_ptp_um_unmodified"], "-", color="C0", marker=".", label="without tip relief")
    if relieved:
        ax.plot(h["torque_Nm"], h["ste_ptp_um"], "-", color="C3", marker=".", label="with the file's tip relief")
        ax.plot([kn["harris_min_ptp_torque_Nm"]], [kn["harris_min_ptp_um"]], "o", mfc="none", color="C3", ms=9,
                label="smallest peak-to-peak (%.3f um at %g N m)" % (kn["harris_min_ptp_um"],
                                                                      kn["harris_min_ptp_torque_Nm"]))
    for i, T in enumerate(torques):
        ax.axvline(T, color="0.6", ls=":", lw=1, label="torques of the file" if i == 0 else None)
    ax.set_xlabel("driver torque T1 [N m]")
    ax.set_ylabel("STE peak-to-peak [um]")
    ax.set_ylim(bottom=0)
    title(ax, params, kn, "Harris map" + ("" if relieved else " (the file has no tip relief)"))
    ax.legend(fontsize=7)
    save(fig, d_dir / "harris.png")


def root_stress_figure(d_dir, params, kn, torques):
    """Method fe: the root stress of a tooth of each gear over the path of contact (the largest
    tension on the fillet below its loaded flank while its pair is at s), one curve per torque,
    ISO 6336-3 method B's nominal sigma_F0 of the same torque dotted."""
    fig, grid = plt.subplots(2, 2, figsize=(11.5, 8.6))
    axes = grid[0]
    path = read_csv(d_dir / "path_of_contact.csv")
    last = len(torques)
    along = read_csv(d_dir / ("fillet_stress_%d.csv" % last))
    for g, ax in ((1, grid[1][0]), (2, grid[1][1])):
        for side, style in (("loaded", "-"), ("other", "--")):
            rows = [k for k in range(len(along["gear"])) if along["gear"][k] == g and along["side"][k] == side]
            r = [1e3 * along["radius_m"][k] for k in rows]
            ax.plot(r, [along["stress_MPa"][k] for k in rows], style, marker=".", ms=3,
                    color=torque_colour(torques[-1], torques),
                    label="fillet below the %s flank" % ("loaded" if side == "loaded" else "unloaded"))
            if side == "loaded":   # ISO's 30-degree point: where the tangent crosses 30 deg (first from the root)
                t = [along["tangent_deg"][k] for k in rows]
                for a in range(len(t) - 1):
                    if (t[a] - 30) * (t[a + 1] - 30) <= 0 and t[a] != t[a + 1]:
                        x = r[a] + (r[a + 1] - r[a]) * (30 - t[a]) / (t[a + 1] - t[a])
                        ax.axvline(x, color="0.4", ls=":", lw=1.2, label="tangent at 30 deg (ISO 6336-3's section)")
                        break
        ax.axhline(0, color="0.7", lw=0.8)
        ax.set_xlabel("radius on the fillet [mm] (root circle at the left end)")
        ax.set_title("gear %d along its fillets, T1 = %g N m, the tooth's pair at s = %.2f mm (its peak)"
                     % (g, torques[-1], 1e3 * kn["fe_root_stress_max_s_m_%d_%d" % (g, last)]), fontsize=9)
        ax.legend(fontsize=7, loc="center right")   # between the tension (above) and the compression (below)
    grid[1][0].set_ylabel("sigma_tt on the fillet surface [MPa]")
    for g, ax in ((1, axes[0]), (2, axes[1])):
        for i, T in enumerate(torques):
            n = "%d_%d" % (g, i + 1)
            d = read_csv(d_dir / ("root_stress_%d.csv" % (i + 1)))
            c = torque_colour(T, torques)
            ax.plot([1e3 * s for s in d["s_from_A_m"]], d["root_stress_MPa_%d" % g], "-", color=c, marker=".", ms=3,
                    label="T1 = %g N m: peak %.1f MPa" % (T, kn["fe_root_stress_max_MPa_" + n]))
            ax.axhline(kn["iso6336_root_stress_MPa_" + n], color=c, ls=":", lw=1.2)
        for name, s in zip(path["point"], path["s_from_A_m"]):
            ax.axvline(1e3 * s, color="0.6", lw=0.8, ls="--")
            ax.text(1e3 * s, 1.0, " " + name, transform=ax.get_xaxis_transform(), fontsize=8, va="top", color="0.4")
        ax.plot([], [], ":", color="0.3", label="ISO 6336-3 method B sigma_F0 (dotted, same colour)")
        ax.set_xlabel("contact position of the tooth's pair, s from A [mm]")
        ax.set_title("gear %d (%s): the fillet below the loaded flank" % (g, "driver" if g == 1 else "driven"),
                     fontsize=9)
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=1, frameon=False)
    axes[0].set_ylabel("root stress, largest tension on the fillet [MPa]")
    axes[1].sharey(axes[0])
    fig.suptitle("%s\nroot stress over the mesh by finite elements" % params.get("name", "gear pair"), fontsize=9)
    save(fig, d_dir / "root_stress.png")


def main():
    d_dir = pathlib.Path(sys.argv[1])
    params, kn, torques, ste = load(d_dir)
    ste_figure(d_dir, params, kn, torques, ste)
    stiffness_figure(d_dir, params, kn, torques, ste)
    shares_figure(d_dir, params, kn, torques, ste)
    spectrum_figure(d_dir, params, kn, torques)
    if (d_dir / "load_map_1.csv").exists():
        load_map_figure(d_dir, params, kn, torques)
    harris_figure(d_dir, params, kn, torques)
    if (d_dir / "root_stress_1.csv").exists():
        root_stress_figure(d_dir, params, kn, torques)
    if (d_dir / "frc_1.csv").exists():
        gear_dynamics.draw(d_dir, params, kn, torques)


if __name__ == "__main__":
    main()
