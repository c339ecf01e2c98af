#!/usr/bin/env python3
"""Which tooth model a scene needs: accuracy against cost of the mesh-stiffness models (issue 33 §4).

    tooth_model_chart.py GEARHB_GEAR DATA_DIR [FIG_DIR]

For the three example pairs (the FE example files' geometry, bores and torques), runs
gearhb_gear (GEARHB_GEAR) with each tooth model into DATA_DIR/<pair>_<model>/ and compares,
at the file's largest torque, the mean mesh stiffness and the STE peak-to-peak with the
converged finite elements:

  truth       FE, Richardson limit of element sizes x 1, 1/sqrt 2, 1/2 (observed order from
              the three; reference/fe_tooth_contact.md section 1 does the same study)
  fe_coarse   FE, sizes x 2        fe_medium  FE, sizes x sqrt 2        fe  FE, default sizes
  pe          potential energy, the FE's bores (Sainsot's fillet foundation clamped there)
  pe_coupled  the same with the structural coupling of the bodies' torsion (model.pe_coupling)
  beam        chapter 7's beams in the physically consistent reading (Hertz once per contact
              and inside the sharing, cantilevers)
  beam_thesis chapter 7's beams in the thesis' reading (Palmgren per tooth, equal split, fused)
  iso         ISO 6336-1 method B, c_gamma_alpha b (a mean only: no STE)

Every run uses the tooth force T1 / rb1 along the line of action (the FE's), so the models and
not the force conventions are compared. Cost: the wall time of the tooth model and the STE at
the file's three torques (timings.csv: mesh_phases or fe_model, ste_1..3) on this machine; ISO
is a closed form (drawn at 1 us).

Writes DATA_DIR/tooth_models.csv (pair, model, time_s, k_mean_N_per_m, ste_ptp_um,
k_error, ptp_error) and FIG_DIR/gear_tooth_models.png; prints the table (markdown).
"""
import copy
import csv
import json
import math
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402

from style import COMPARISON_COLOURS, save  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "programs" / "gearhb_gear" / "examples"
PAIRS = [("thesis_pair", "thesis z 50/50, m 3", "o"), ("fzg_c", "FZG C z 16/24, m 4.5", "s"),
         ("ross_pair", "ROSS z 62/62, m 2", "^")]
BEAM_CONSISTENT = {"method": "beam", "hertz": "per_contact", "pair_hertz": "consistent",
                   "pair_stiffness": "cantilevers", "tooth_force": "base_radius"}
BEAM_THESIS = {"method": "beam", "hertz": "per_tooth", "pair_hertz": "equal_split", "pair_stiffness": "fused",
               "tooth_force": "base_radius"}
PE = {"method": "potential_energy", "hertz": "none", "tooth_force": "base_radius"}
PE_COUPLED = dict(PE, pe_coupling="body_torsion")
FE_SCALES = {"fe_coarse": 2.0, "fe_medium": math.sqrt(2.0), "fe": 1.0, "fe_fine": 1 / math.sqrt(2.0),
             "fe_finest": 0.5}
# Drawn: label and colour (methods: comparison colours; the FE meshes in shades of one green).
MODELS = {"iso": ("ISO 6336-1 c_gamma_alpha b (closed form, at 1 us)", "k"),
          "beam_thesis": ("beam, thesis reading", COMPARISON_COLOURS[2]),
          "beam": ("beam, consistent reading", COMPARISON_COLOURS[0]), "pe": ("potential energy", COMPARISON_COLOURS[1]),
          "pe_coupled": ("potential energy + body coupling", COMPARISON_COLOURS[4]),
          "fe_coarse": ("FE, sizes x 2", "#a6dba0"), "fe_medium": ("FE, sizes x 1.41", "#5aae61"),
          "fe": ("FE, default sizes", "#1b7837")}
TIMED = ("mesh_phases", "fe_model", "ste_1", "ste_2", "ste_3")


def run_file(gear, data, pair, model, settings):
    """Write the run file of one model of one pair, run it (no figures), return its numbers."""
    f = json.load(open(EXAMPLES / (pair + "_fe.json")))
    f.pop("speed", None), f.pop("dynamics", None)
    if model.startswith("fe"):
        f["model"]["fe_mesh"]["scale"] = settings
    else:
        bores = [g.get("rim_radius", 0.0) for g in f["gears"]]
        fe = json.load(open(data / (pair + "_fe") / "key_numbers.json"))
        for i, g in enumerate(f["gears"]):   # the FE's bores (its default rule where the file gives none)
            g["rim_radius"] = bores[i] or fe["fe_bore_radius_%d_m" % (i + 1)]["value"]
        f["model"] = dict(copy.deepcopy(settings), phases=f["model"]["phases"])
    out = data / ("%s_%s" % (pair, model))
    out.mkdir(parents=True, exist_ok=True)
    path = out.parent / ("%s_%s.json" % (pair, model))
    path.write_text(json.dumps(f, indent=1) + "\n")
    subprocess.run([str(gear), str(path), "--quiet", "--set", "plot=0", "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    kn = {k: v["value"] for k, v in json.load(open(out / "key_numbers.json")).items()}
    with open(out / "timings.csv") as t:
        seconds = sum(float(r["seconds"]) for r in csv.DictReader(t) if r["step"] in TIMED)
    return {"time_s": seconds, "k": kn["mesh_stiffness_mean_N_per_m_3"], "ptp": kn["ste_ptp_um_3"],
            "iso": kn["iso6336_c_gamma_alpha_N_per_m"]}


def richardson(f1, f2, f3, r):
    """Limit of f at sizes h, h / r, h / r^2 (observed order from the three)."""
    p = math.log((f1 - f2) / (f2 - f3)) / math.log(r)
    return f3 + (f3 - f2) / (r ** p - 1), p


def measure(gear, data):
    rows = []
    for pair, _, _ in PAIRS:
        r = {}
        for model in ("fe", "fe_coarse", "fe_medium", "fe_fine", "fe_finest"):   # "fe" first: the bores
            r[model] = run_file(gear, data, pair, model, FE_SCALES[model])
        for model, settings in (("pe", PE), ("pe_coupled", PE_COUPLED), ("beam", BEAM_CONSISTENT),
                                ("beam_thesis", BEAM_THESIS)):
            r[model] = run_file(gear, data, pair, model, settings)
        k_true, k_order = richardson(r["fe"]["k"], r["fe_fine"]["k"], r["fe_finest"]["k"], math.sqrt(2))
        p_true, p_order = richardson(r["fe"]["ptp"], r["fe_fine"]["ptp"], r["fe_finest"]["ptp"], math.sqrt(2))
        r["iso"] = {"time_s": 1e-6, "k": r["fe"]["iso"], "ptp": float("nan")}
        for model in MODELS:
            v = r[model]
            rows.append({"pair": pair, "model": model, "time_s": v["time_s"], "k_mean_N_per_m": v["k"],
                         "ste_ptp_um": v["ptp"], "k_error": v["k"] / k_true - 1, "ptp_error": v["ptp"] / p_true - 1,
                         "k_true_N_per_m": k_true, "ptp_true_um": p_true, "k_order": k_order, "ptp_order": p_order})
    return rows


def write_table(rows, data):
    keys = ["pair", "model", "time_s", "k_mean_N_per_m", "ste_ptp_um", "k_error", "ptp_error", "k_true_N_per_m",
            "ptp_true_um", "k_order", "ptp_order"]
    with open(data / "tooth_models.csv", "w", newline="") as f:
        w = csv.DictWriter(f, keys)
        w.writeheader()
        w.writerows(rows)
    print("| pair | model | time [s] | mean k [MN/m] | error | STE p-p [um] | error |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %.3g | %.1f | %+.1f %% | %s | %s |" % (
            r["pair"], MODELS[r["model"]][0], r["time_s"], r["k_mean_N_per_m"] / 1e6, 100 * r["k_error"],
            "-" if math.isnan(r["ste_ptp_um"]) else "%.3f" % r["ste_ptp_um"],
            "-" if math.isnan(r["ptp_error"]) else "%+.1f %%" % (100 * r["ptp_error"])))


def chart(rows, fig_dir):
    fig, axes = plt.subplots(1, 3, figsize=(14.5, 5.4), gridspec_kw={"width_ratios": [1, 1, 0.42]})
    for ax, key, what in ((axes[0], "k_error", "mean mesh stiffness"), (axes[1], "ptp_error", "STE peak-to-peak")):
        ax.set_xlim(3e-7, 20)
        for pair, label, marker in PAIRS:
            for model, (name, colour) in MODELS.items():
                r = next(x for x in rows if x["pair"] == pair and x["model"] == model)
                if math.isnan(r[key]):
                    continue
                ax.plot([r["time_s"]], [100 * abs(r[key])], marker, color=colour, ms=8, ls="none", mec="0.2",
                        mew=0.5)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.axhline(1.0, color="0.5", ls=":", lw=1)
        ax.set_xlabel("wall time: tooth model + STE at 3 torques [s]")
        ax.set_ylabel("|error| against the converged FE [%%] (%s)" % what)
        ax.set_title("%s, largest torque, T1 / rb1 for every model" % what, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    # Legend: models by colour, pairs by marker.
    handles = [plt.Line2D([], [], color=c, marker="o", ls="none", mec="0.2", mew=0.5, label=n)
               for n, c in MODELS.values()]
    handles += [plt.Line2D([], [], color="0.3", marker=mk, ls="none", mfc="none", label=lab) for _, lab, mk in PAIRS]
    axes[2].axis("off")   # the legend's own panel: it never covers a point
    axes[2].legend(handles=handles, loc="center left", fontsize=8, frameon=False)
    fig.suptitle("Which tooth model a scene needs: error against cost. Truth: the FE's Richardson limit (sizes x 1, "
                 "1/sqrt 2, 1/2); beam and PE with the FE's bores; dotted: 1 %", fontsize=10)
    out = pathlib.Path(fig_dir) / "gear_tooth_models.png"
    save(fig, out)
    return out


def draw(gear, data, fig_dir=None):
    data = pathlib.Path(data)
    data.mkdir(parents=True, exist_ok=True)
    rows = measure(gear, data)
    write_table(rows, data)
    return [chart(rows, fig_dir or data)]


if __name__ == "__main__":
    print("\n".join(str(p) for p in draw(*sys.argv[1:4])))
