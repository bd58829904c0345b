#!/usr/bin/env python3
"""Plot of benchmark/results/optimize_quality.csv (and slim_reference.csv when present): per corpus
run, the mean symmetric Dirichlet energy of the default repair, of the default optimize_distortion()
and of libigl's SLIM from the repaired map of its run (slim_reference.csv; its best final value), on a log scale. Writes an SVG and, if
rsvg-convert is installed, a PNG next to it.

    python3 benchmark/Progressive_embedding/plot_quality.py [RESULTS_DIR]
"""
import csv
import math
import os
import shutil
import subprocess
import sys

results = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "results")
runs = list(csv.DictReader(open(os.path.join(results, "optimize_quality.csv"))))
slim = {}
slim_path = os.path.join(results, "slim_reference.csv")
if os.path.exists(slim_path):
    for r in csv.DictReader(open(slim_path)):
        if r["checkpoint"] != "final":
            continue
        key = (r["mesh"].split(" ")[0], r["seed"])
        value = float(r["mean_energy_3d"]) if r["mean_energy_3d"] and r["valid"] == "True" else None
        if value is not None:
            slim[key] = min(value, slim.get(key, value))

W, H, left, right, top, bottom = 1000, 420, 70, 20, 40, 90
lo, hi = 1.0, 16.0  # log10 range of the y axis
def y(v):
    v = min(max(math.log10(v), lo), hi)
    return top + (hi - v) / (hi - lo) * (H - top - bottom)
n = len(runs)
step = (W - left - right) / max(n, 1)
out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (W, H),
       '<rect width="100%" height="100%" fill="white"/>',
       '<text x="%d" y="20" font-size="14">Mean symmetric Dirichlet energy per corpus run (log scale; 4 = isometry)</text>' % left]
for e in range(int(lo), int(hi) + 1, 3):
    yy = y(10 ** e)
    out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, yy, W - right, yy))
    out.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (left - 6, yy + 4, e))
for i, r in enumerate(runs):
    x = left + (i + 0.5) * step
    out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="#999"/>' % (x, y(float(r["repaired_mean"]))))
    key = (r["mesh"], r["seed"])
    if key in slim:
        out.append('<rect x="%.1f" y="%.1f" width="6" height="6" fill="#e8852a"/>' % (x - 3, y(slim[key]) - 3))
    out.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="#1f5fb4"/>' % (x, y(float(r["mean"]))))
    out.append('<text transform="translate(%.1f,%d) rotate(60)" font-size="8">%s %s</text>'
               % (x - 2, H - bottom + 6, r["mesh"].replace(".off", ""), r["seed"]))
legend = [("#999", "after the default repair"), ("#1f5fb4", "after the default optimize_distortion()"),
          ("#e8852a", "libigl SLIM from the repaired map of 2026-11-23 (best valid final value)")]
for k, (color, text) in enumerate(legend):
    out.append('<rect x="%d" y="%d" width="10" height="10" fill="%s"/><text x="%d" y="%d">%s</text>'
               % (left + 20, 160 + 16 * k, color, left + 35, 169 + 16 * k, text))
out.append("</svg>")
svg = os.path.join(results, "optimize_quality.svg")
open(svg, "w").write("\n".join(out))
if shutil.which("rsvg-convert"):
    png = os.path.join(results, "optimize_quality.png")
    subprocess.run(["rsvg-convert", "-w", str(W), svg, "-o", png], check=True)
    os.remove(svg)
    print("wrote", png)
else:
    print("wrote", svg)
