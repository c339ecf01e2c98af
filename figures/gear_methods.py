#!/usr/bin/env python3
"""Beam model against potential-energy method, side by side: gear_methods.py DATA_ROOT [FIG_DIR]

DATA_ROOT holds the output folders of gearhb_gear runs named after the example files
(make figures writes them to build/data/gearhb_gear/<example>/):
  thesis_pair, thesis_pair_pe, fzg_c, fzg_c_pe, ross_pair, ross_pair_pe  (and, for the
  relief figure, thesis_pair_relief, thesis_pair_relief_pe).
Writes into FIG_DIR (default DATA_ROOT):
  gear_methods.png         for each gear (columns) at its file's largest torque: the mesh
                           stiffness k = F / STE (top) and the STE (bottom) over one mesh cycle,
                           beam model solid, potential-energy method dashed, ISO 6336-1
                           c_gamma_alpha b dotted (top);
  gear_methods_harris.png  the thesis gear's Harris map (STE peak-to-peak against torque) with
                           and without the long linear tip relief of thesis_pair_relief.json,
                           both methods.
and prints the comparison table (markdown) of programs/gearhb_gear/NOTES.md.
"""
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

from style import COMPARISON_COLOURS, read_csv, save  # noqa: E402

# Methods, not torques: comparison colours (style.py), never a torque colour.
BEAM, PE, FE = COMPARISON_COLOURS[0], COMPARISON_COLOURS[1], COMPARISON_COLOURS[3]

GEARS = [("thesis_pair", "thesis gear z 50/50, m 3 mm",
          "beam: thesis readings (Palmgren per tooth, fused pairs)"),
         ("fzg_c", "FZG type C z 16/24, m 4.5 mm",
          "beam: Palmgren per contact, cantilevers"),
         ("ross_pair", "ROSS test gear z 62/62, m 2 mm",
          "beam: Palmgren per contact, cantilevers")]


def run(root, name):
    d = root / name
    kn = {k: v["value"] for k, v in json.load(open(d / "key_numbers.json")).items()}
    params = json.load(open(d / "params.json"))
    i = max(range(len(params["torques"])), key=lambda j: params["torques"][j]) + 1
    return {"kn": kn, "params": params, "i": i, "T": params["torques"][i - 1],
            "ste": read_csv(d / ("ste_%d.csv" % i)), "harris": read_csv(d / "harris.csv")}


def table(root):
    """Rows: gear, T, then beam / PE / ISO mean k, STE ptp and max at the largest torque."""
    rows = []
    for name, label, _ in GEARS:
        b, p = run(root, name), run(root, name + "_pe")
        i = b["i"]
        rows.append((label, b["T"], b["kn"]["mesh_stiffness_mean_N_per_m_%d" % i] / 1e6,
                     p["kn"]["mesh_stiffness_mean_N_per_m_%d" % i] / 1e6, b["kn"]["iso6336_c_gamma_alpha_N_per_m"] / 1e6,
                     b["kn"]["ste_ptp_um_%d" % i], p["kn"]["ste_ptp_um_%d" % i],
                     b["kn"]["ste_max_um_%d" % i], p["kn"]["ste_max_um_%d" % i]))
    print("| gear | T1 [N m] | mean k beam / PE / ISO c_ga b [MN/m] | PE / beam, ISO / beam | STE ptp beam / PE [um] "
          "| STE max beam / PE [um] |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %g | %.1f / %.1f / %.1f | %.2f, %.2f | %.3f / %.3f | %.3f / %.3f |" % (
            r[0], r[1], r[2], r[3], r[4], r[3] / r[2], r[4] / r[2], r[5], r[6], r[7], r[8]))
    return rows


def methods_figure(root, fig_dir):
    fig, axes = plt.subplots(2, 3, figsize=(12.5, 7.2), sharex=True)
    for col, (name, label, beam_reading) in enumerate(GEARS):
        b, p, f = run(root, name), run(root, name + "_pe"), run(root, name + "_fe")
        ax_k, ax_e = axes[0][col], axes[1][col]
        for r, style, colour, what in ((f, "-", FE, "finite elements"), (b, "-", BEAM, "beam model"),
                                       (p, "--", PE, "potential energy")):
            ph = r["ste"]["phase"]
            i = r["i"]
            ax_k.plot(ph, [v / 1e6 for v in r["ste"]["k_N_per_m"]], style, color=colour, lw=2.2 if r is f else 1.5,
                      label="%s: mean %.0f MN/m" % (what, r["kn"]["mesh_stiffness_mean_N_per_m_%d" % i] / 1e6))
            ax_e.plot(ph, r["ste"]["ste_um"], style, color=colour, lw=2.2 if r is f else 1.5,
                      label="%s: peak-to-peak %.2f um" % (what, r["kn"]["ste_ptp_um_%d" % i]))
        iso = b["kn"]["iso6336_c_gamma_alpha_N_per_m"] / 1e6
        ax_k.axhline(iso, color="k", ls=":", lw=1.2, label="ISO 6336-1 c_gamma_alpha b = %.0f MN/m" % iso)
        out_of_fit = [str(j) for j in (1, 2) if p["kn"].get("pe_fillet_in_range_%d" % j, 1) == 0]
        ax_k.set_title("%s, T1 = %g N m\n%s\nPE: bore radius %s mm%s; FE: bores %s mm%s" % (
            label, b["T"], beam_reading,
            " / ".join("%g" % (g["rim_radius"] * 1e3) for g in p["params"]["gears"]),
            "" if name == "ross_pair" else " (assumed)",
            " / ".join("%.2f" % (f["kn"]["fe_bore_radius_%d_m" % j] * 1e3) for j in (1, 2)),
            "\nPE: Sainsot's fillet fit extrapolated on gear %s" % " and ".join(out_of_fit) if out_of_fit else ""),
            fontsize=8)
        ax_k.set_ylim(bottom=0)
        ax_e.set_ylim(bottom=0)
        ax_k.legend(fontsize=7, loc="lower center")
        ax_e.legend(fontsize=7, loc="lower center")
        ax_e.set_xlabel("mesh phase [mesh cycles] (0: a pair enters at A)")
        ax_e.set_xlim(0, 1)
    axes[0][0].set_ylabel("mesh stiffness k = F / STE [MN/m]")
    axes[1][0].set_ylabel("static transmission error STE [um]")
    fig.suptitle("Three tooth models, no tip relief, largest torque of each file: finite elements (thick), beam, "
                 "potential energy (dashed);\neach as its example file has it (force convention, readings, bores): "
                 "figures/tooth_model_chart.py compares them like for like", fontsize=10)
    fig.tight_layout()
    out = fig_dir / "gear_methods.png"
    save(fig, out)
    return out


def harris_figure(root, fig_dir):
    fig, ax = plt.subplots(figsize=(7.4, 4.6))
    for name, color, what in (("thesis_pair_relief", BEAM, "beam model"), ("thesis_pair_relief_pe", PE, "potential energy")):
        r = run(root, name)
        h, kn = r["harris"], r["kn"]
        ax.plot(h["torque_Nm"], h["ste_ptp_um_unmodified"], ":", color=color, marker=".", ms=4,
                label="%s, no relief" % what)
        ax.plot(h["torque_Nm"], h["ste_ptp_um"], "-", color=color, marker=".", ms=4,
                label="%s, with the relief: smallest %.2f um at %g N m" % (what, kn["harris_min_ptp_um"],
                                                                            kn["harris_min_ptp_torque_Nm"]))
        ax.plot([kn["harris_min_ptp_torque_Nm"]], [kn["harris_min_ptp_um"]], "o", mfc="none", color=color, ms=9)
        step = h["torque_Nm"][1] - h["torque_Nm"][0]
    ax.axvline(300, color="0.5", ls="--", lw=1, label="design torque of the relief, 300 N m")
    ax.set_xlabel("driver torque T1 [N m]")
    ax.set_ylabel("STE peak-to-peak [um]")
    ax.set_ylim(bottom=0)
    ax.set_title("Thesis gear, Harris map: long linear tip relief on both gears, Ca = 13.92 um\n"
                 "(the beam model's single-pair deflection at 300 N m), both tooth models; torques every %g N m"
                 % step, fontsize=9)
    ax.legend(fontsize=7, loc="upper left")
    out = fig_dir / "gear_methods_harris.png"
    save(fig, out)
    return out


def draw(root, fig_dir=None):
    root = pathlib.Path(root)
    fig_dir = pathlib.Path(fig_dir) if fig_dir else root
    table(root)
    return [methods_figure(root, fig_dir), harris_figure(root, fig_dir)]


if __name__ == "__main__":
    print("\n".join(str(p) for p in draw(*sys.argv[1:3])))
