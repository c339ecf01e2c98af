#!/usr/bin/env python3
"""STE peak-to-peak of a helical pair against its helix angle at a fixed transverse section (issue 35).

    helical_ste.py GEARHB_GEAR DATA_DIR [FIG_DIR]

The thesis pair's transverse section (z 50/50, m_t 3 mm, alpha_t 20 deg, ha 3 mm, hf 3.75 mm,
b 20 mm: eps_alpha = 1.7547 at every beta) made helical: for each beta the file's normal module
m_t cos(beta), normal pressure angle atan(tan(alpha_t) cos(beta)) and rack coefficients over
cos(beta), so that the section (and eps_alpha) stays the same and only the overlap ratio
eps_beta = b sin(beta) / (pi m_n) = b tan(beta) / (pi m_t) grows. gearhb_gear (beam model,
consistent reading, 20 slices) runs each into DATA_DIR/beta_<deg>/; the STE peak-to-peak of the
file's three torques is drawn against beta, eps_beta on the top axis.

Beside it (right axis, dashed) the theory the slices must reproduce: the total length of the
contact lines on the path, sum over the tooth pairs of |[phi + q, phi + q + eps_beta] n
[0, eps_alpha]| (base pitches), its peak-to-peak over its mean - zero at whole eps_beta. Written
here from the geometry alone, no gearhb.

Writes DATA_DIR/helical_ste.csv (beta_deg, eps_beta, eps_alpha, ste_ptp_um_1..3,
contact_length_ptp_rel) and FIG_DIR/gear_helical_ste.png.
"""
import csv
import json
import math
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from style import save, torque_colour  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "programs" / "gearhb_gear" / "examples"
BETAS = [1.5 * i for i in range(31)]   # 0 .. 45 deg
MODEL = {"method": "beam", "hertz": "per_contact", "pair_hertz": "consistent", "pair_stiffness": "cantilevers",
         "tooth_force": "base_radius", "slices": 20}


def helical_file(base, beta_deg):
    f = {k: v for k, v in base.items() if k not in ("speed", "dynamics", "bifurcation_diagram", "backlash")}
    c = math.cos(math.radians(beta_deg))
    alpha_t = math.radians(base["pressure_angle_deg"])
    rack = base.get("basic_rack", {})
    f["name"] = "thesis section, beta = %g deg" % beta_deg
    f["module"] = base["module"] * c
    f["pressure_angle_deg"] = math.degrees(math.atan(math.tan(alpha_t) * c))
    f["helix_angle_deg"] = beta_deg
    f["basic_rack"] = {"addendum": rack.get("addendum", 1.0) / c, "dedendum": rack.get("dedendum", 1.25) / c,
                       "root_radius": rack.get("root_radius", 0.38) / c}
    f["model"] = dict(MODEL)
    f["harris"] = {"points": 2}
    return f


def contact_length_ptp(eps_alpha, eps_beta, samples=2000):
    """Peak-to-peak over mean of the total contact-line length on the path (base pitches)."""
    def length(phi):
        total = 0.0
        for q in range(-int(eps_beta) - 2, int(eps_alpha) + 2):
            lo, hi = max(0.0, phi + q), min(eps_alpha, phi + q + eps_beta)
            total += max(0.0, hi - lo)
        return total
    if eps_beta == 0:
        v = [sum(1 for q in range(-1, int(eps_alpha) + 2) if 0 <= phi / samples + q <= eps_alpha)
             for phi in range(samples)]
    else:
        v = [length(i / samples) for i in range(samples)]
    return (max(v) - min(v)) / (sum(v) / len(v))


def draw(gear, data_dir, fig_dir):
    data_dir, fig_dir = pathlib.Path(data_dir), pathlib.Path(fig_dir)
    data_dir.mkdir(parents=True, exist_ok=True)
    base = json.load(open(EXAMPLES / "thesis_pair.json"))
    torques = base["torques"]
    rows = []
    for beta in BETAS:
        f = helical_file(base, beta)
        path = data_dir / ("beta_%g.json" % beta)
        path.write_text(json.dumps(f, indent=2) + "\n")
        out = data_dir / ("beta_%g" % beta)
        subprocess.run([str(gear), str(path), "--quiet", "--set", "plot=0", "--out", str(out)], check=True,
                       stdout=subprocess.DEVNULL)
        kn = {k: v["value"] if isinstance(v, dict) else v for k, v in json.load(open(out / "key_numbers.json")).items()}
        rows.append([beta, kn["overlap_ratio"], kn["contact_ratio"]] +
                    [kn["ste_ptp_um_%d" % (i + 1)] for i in range(len(torques))] +
                    [contact_length_ptp(kn["contact_ratio"], kn["overlap_ratio"])])
    eps_alpha = [r[2] for r in rows]
    if max(eps_alpha) - min(eps_alpha) > 1e-9:
        sys.exit("helical_ste.py: eps_alpha moved with beta (%g .. %g): the section is not fixed"
                 % (min(eps_alpha), max(eps_alpha)))
    with open(data_dir / "helical_ste.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["beta_deg", "eps_beta", "eps_alpha"] + ["ste_ptp_um_%d" % (i + 1) for i in range(len(torques))] +
                   ["contact_length_ptp_rel"])
        w.writerows(rows)

    fig, ax = plt.subplots(figsize=(6.8, 4.6))
    beta = [r[0] for r in rows]
    for i, T in enumerate(torques):
        ax.plot(beta, [r[3 + i] for r in rows], "-", marker=".", color=torque_colour(T, torques),
                label="STE peak-to-peak, T1 = %g N m (beam model, 20 slices)" % T)
    right = ax.twinx()
    right.plot(beta, [100 * r[-1] for r in rows], "--", color="0.35",
               label="contact-line length on the path: peak-to-peak / mean (theory, right)")
    right.set_ylabel("contact-line length peak-to-peak / mean [%]")
    right.set_ylim(bottom=0)
    right.grid(False)
    eps_b = [r[1] for r in rows]
    for q in (1, 2):
        at = [b for b, e, e2 in zip(beta, eps_b, eps_b[1:]) if e <= q < e2]
        if at:
            j = beta.index(at[0])
            bq = beta[j] + (q - eps_b[j]) / (eps_b[j + 1] - eps_b[j]) * (beta[j + 1] - beta[j])
            ax.axvline(bq, color="0.6", ls=":", lw=1)
            ax.text(bq, 0.97, "eps_beta = %d " % q, transform=ax.get_xaxis_transform(), fontsize=7, va="top", ha="right")
    ax.set_xlabel("helix angle beta [deg] (the transverse section fixed: eps_alpha = %.4f)" % eps_alpha[0])
    ax.set_ylabel("STE peak-to-peak [um]")
    ax.set_xlim(0, max(beta))
    ax.set_ylim(bottom=0)
    k = 0.02 / (math.pi * 0.003)   # eps_beta = b tan(beta) / (pi m_t)
    top = ax.secondary_xaxis("top", functions=(lambda b: k * np.tan(np.radians(b)),
                                               lambda e: np.degrees(np.arctan(np.asarray(e) / k))))
    top.set_xlabel("overlap ratio eps_beta = b tan(beta) / (pi m_t)")
    ax.set_title("Helical thesis pair: the STE fluctuation falls with the overlap ratio\n"
                 "and is smallest near whole eps_beta (z 50/50, m_t 3 mm, b 20 mm)", fontsize=9)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = right.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=1, frameon=False)
    return [save(fig, fig_dir / "gear_helical_ste.png")]


if __name__ == "__main__":
    fig = sys.argv[3] if len(sys.argv) > 3 else sys.argv[2]
    for png in draw(sys.argv[1], sys.argv[2], fig):
        print(png)
