"""The maps of a design study (studies/Snakefile rule maps): every key number named in the study's
"maps" over its first two axes, one row of panels per value of a third axis; the design that
minimises each (best.txt); and the best design's STE and DTE response beside the unmodified
one's (amount 0 on the first axis, the same other axes), best_vs_unmodified.png."""
import csv
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import study  # noqa: E402


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def draw(study_path, out):
    out = pathlib.Path(out)
    spec = study.load(study_path)
    axes, keys = spec.axes, spec.maps
    rows = read(out / "table.csv")
    px, py = axes[0][0], axes[1][0]
    groups = sorted({r[axes[2][0]] for r in rows}, key=num) if len(axes) > 2 else [None]
    fig, grid = plt.subplots(len(groups), max(1, len(keys)), figsize=(5.2 * max(1, len(keys)), 3.6 * len(groups)),
                             squeeze=False)
    best = ["study %s: %d designs, %d failed" % (spec.name or study_path, len(rows),
                                                 sum(r["status"] != "ok" for r in rows))]
    for gi, g in enumerate(groups):
        sub = [r for r in rows if g is None or r[axes[2][0]] == g]
        xs, ys = sorted({num(r[px]) for r in sub}), sorted({num(r[py]) for r in sub})
        for ki, key in enumerate(keys):
            ax = grid[gi][ki]
            z = [[math.nan] * len(xs) for _ in ys]
            for r in sub:
                z[ys.index(num(r[py]))][xs.index(num(r[px]))] = num(r.get(key))
            im = ax.pcolormesh([x * 1e6 for x in xs] if max(xs) < 1e-3 else xs, ys, z, shading="nearest", cmap="viridis")
            fig.colorbar(im, ax=ax, label=key)
            ok = [r for r in sub if not math.isnan(num(r.get(key)))]
            for y in ys:   # the minimising x per y: the optimum depends on the load
                row = [r for r in ok if num(r[py]) == y]
                if row:
                    m = min(row, key=lambda r: num(r[key]))
                    ax.plot(num(m[px]) * (1e6 if max(xs) < 1e-3 else 1), y, "w*", ms=10, mec="k")
                    best.append("%s%s, %s = %g: minimum %.4g at %s = %.4g (design %s)" % (
                        key, "" if g is None else " (%s = %.6g)" % (axes[2][0], num(g)), py, y, num(m[key]), px,
                        num(m[px]), m["design"]))
            ax.set_xlabel(px + (" [um]" if max(xs) < 1e-3 else ""))
            ax.set_ylabel(py)
            ax.set_title("%s%s (star: minimum per %s)" % (key, "" if g is None else "\n%s = %.6g" % (axes[2][0], num(g)), py),
                         fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "maps.png.tmp.png", dpi=110)
    plt.close(fig)
    (out / "maps.png.tmp.png").replace(out / "maps.png")
    (out / "best.txt").write_text("\n".join(best) + "\n")
    compare(out, rows, axes, keys)


def compare(out, rows, axes, keys):
    """The design with the smallest last-mapped key number at the largest value of the second
    axis, beside the design with the first axis at 0 and the same other axes."""
    if not keys:
        return
    key, px, py = keys[-1], axes[0][0], axes[1][0]
    top = max(num(r[py]) for r in rows)
    ok = [r for r in rows if num(r[py]) == top and not math.isnan(num(r.get(key)))]
    if not ok:
        return
    b = min(ok, key=lambda r: num(r[key]))
    same = [r for r in rows if num(r[px]) == 0 and all(r[p] == b[p] for p, _ in axes[1:]) and r["status"] == "ok"]
    if not same:
        return
    u = same[0]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    for r, label, style in ((u, "unmodified (%s = 0)" % px, "--"), (b, "best: %s = %.3g" % (px, num(b[px])), "-")):
        d = out / "designs" / r["design"] / "run"
        ste = read(d / "ste_1.csv")
        a1.plot([num(s["phase"]) for s in ste], [num(s["ste_um"]) for s in ste], style, label=label)
        frc = read(d / "frc_1.csv")
        a2.plot([num(s["f_mesh_hz"]) for s in frc], [1e6 * num(s["x_rms_ac"]) for s in frc], style, label=label)
    a1.set_xlabel("mesh phase")
    a1.set_ylabel("STE [um]")
    a1.set_title("loaded STE at %s = %g" % (py, top), fontsize=9)
    a2.set_xlabel("mesh frequency [Hz]")
    a2.set_ylabel("DTE RMS [um]")
    a2.set_title("DTE over speed (smallest %s)" % key, fontsize=9)
    a1.legend(fontsize=8, loc="center left")
    a2.legend(fontsize=8, loc="upper right")
    for a in (a1, a2):
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "best_vs_unmodified.png", dpi=110)
    plt.close(fig)
