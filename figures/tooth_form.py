"""Generated tooth forms (lib/gearhb/gears/geometry/tooth_form.hpp) from the CSV that
tests/tooth_form/write_csv.cpp writes (columns gear,x_mm,y_mm,nx,ny,segment): three teeth of
each gear, the segments coloured, one panel a gear, and a close-up of the z = 10 pinion's
undercut (the trochoid cutting into the involute). Not part of `make figures`; the CTest
ToothForm.draws_png runs it.

Usage: /usr/bin/python3 figures/tooth_form.py FORMS.csv OUT.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SEGMENT_COLOURS = {"root": "0.45", "fillet": "C3", "involute": "C0", "relief": "C2",
                   "rounding": "C1", "tip": "k"}


def read(path):
    gears = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            gears.setdefault(row["gear"], []).append(row)
    return gears


def draw_form(ax, rows, title, normals=False):
    x = [float(r["x_mm"]) for r in rows]
    y = [float(r["y_mm"]) for r in rows]
    ax.plot(x, y, color="0.8", lw=0.6)
    for seg, colour in SEGMENT_COLOURS.items():
        pts = [(xi, yi) for xi, yi, r in zip(x, y, rows) if r["segment"] == seg]
        if pts:
            ax.plot(*zip(*pts), ".", ms=2, color=colour, label=seg)
    if normals:
        ax.quiver(x, y, [float(r["nx"]) for r in rows], [float(r["ny"]) for r in rows],
                  color="0.6", angles="xy", scale_units="xy", scale=1 / 0.08, width=0.004)
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")


def draw(csv_path, png_path):
    gears = read(csv_path)
    fig, axes = plt.subplots(2, 3, figsize=(12, 8))
    axes = axes.ravel()
    for ax, (name, rows) in zip(axes, gears.items()):
        draw_form(ax, rows, name)
    # One legend of every segment kind, below the panels (never over a tooth).
    handles = [plt.Line2D([], [], marker=".", ls="", ms=8, color=c, label=seg) for seg, c in SEGMENT_COLOURS.items()]
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), frameon=False)
    undercut = [rows for name, rows in gears.items() if "undercut" in name]
    if undercut and len(gears) < len(axes):
        ax = axes[len(gears)]
        # The middle tooth's right flank around the base circle (rb = 14.1 mm for m = 3 mm).
        rows = [r for r in undercut[0] if r["segment"] in ("fillet", "involute") and float(r["x_mm"]) > 0.5
                and 13.0 < math.hypot(float(r["x_mm"]), float(r["y_mm"])) < 15.0
                and abs(math.atan2(float(r["x_mm"]), float(r["y_mm"]))) < math.pi / 10]
        draw_form(ax, rows, "z10 undercut corner, normals", normals=True)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    fig.savefig(png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    draw(sys.argv[1], sys.argv[2])
