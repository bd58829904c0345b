#!/usr/bin/env python3
"""What the cross-parameterization benchmark's protocol allows on a pair of meshes of one surface, before any map.

    python3 benchmark/Progressive_embedding/cross_protocol_floor.py A1.obj:B1.obj [A2.obj:B2.obj ...]
            [--out benchmark/results/cross_protocol_floor]

`cross_benchmark --pairs` matches each landmark (a vertex of the coarser mesh) to the nearest vertex of the finer one
and matches the borders by relative arc length. A landmark lands exactly on its partner, so its error is the distance
between the two vertices; a border vertex lands where relative arc length puts it. This script measures both on the
meshes alone (relative to the diagonal of A's bounding box, as `cross_benchmark`): the distance from each vertex of the
coarser mesh to the nearest vertex of the other, and, for each border vertex of A, the distance between the point of
B's border at the same relative arc length (from the border vertex of B nearest to A's first border vertex) and the
point of B's border nearest to it. Also the mean edge length and the border edges. Needs NumPy (python3-numpy).
Writes OUT.csv and OUT.md.
"""

import argparse
import collections
import csv
import datetime
import os
import platform
import sys

import numpy as np


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            s = line.split()
            if not s:
                continue
            if s[0] == "v":
                vertices.append([float(x) for x in s[1:4]])
            elif s[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in s[1:]])
    return np.array(vertices), faces


def edges_and_border(faces):
    count = collections.Counter()
    for f in faces:
        for i in range(len(f)):
            count[(f[i], f[(i + 1) % len(f)])] += 1
    following = {a: b for (a, b) in count if (b, a) not in count}
    start = min(following)
    loop, v = [start], following[start]
    while v != start:
        loop.append(v)
        v = following[v]
    undirected = {tuple(sorted(e)) for e in count}
    return undirected, loop


def closest_on_segment(p, a, b):
    d = b - a
    t = np.clip(np.dot(p - a, d) / max(np.dot(d, d), 1e-300), 0.0, 1.0)
    return a + t * d


def measure(file_a, file_b):
    a, fa = read_obj(file_a)
    b, fb = read_obj(file_b)
    diag = np.linalg.norm(a.max(0) - a.min(0))
    edges_a, loop_a = edges_and_border(fa)
    edges_b, loop_b = edges_and_border(fb)
    # landmarks: vertices of the coarser mesh, each with the nearest vertex of the other
    coarse, fine = (b, a) if len(b) < len(a) else (a, b)
    mismatch = np.array([np.min(np.linalg.norm(fine - p, axis=1)) for p in coarse]) / diag
    # the border by relative arc length, from A's first border vertex and B's border vertex nearest to it
    i = loop_a.index(min(loop_a))
    loop_a = loop_a[i:] + loop_a[:i]
    j = min(range(len(loop_b)), key=lambda k: np.linalg.norm(b[loop_b[k]] - a[loop_a[0]]))
    loop_b = loop_b[j:] + loop_b[:j]
    pa, pb = a[loop_a + loop_a[:1]], b[loop_b + loop_b[:1]]
    la = np.r_[0, np.cumsum(np.linalg.norm(np.diff(pa, axis=0), axis=1))]
    lb = np.r_[0, np.cumsum(np.linalg.norm(np.diff(pb, axis=0), axis=1))]
    border = []
    for k, v in enumerate(loop_a):
        t = la[k] / la[-1] * lb[-1]
        s = min(int(np.searchsorted(lb, t, side="right")) - 1, len(loop_b) - 1)
        q = pb[s] + (pb[s + 1] - pb[s]) * ((t - lb[s]) / (lb[s + 1] - lb[s]))
        near = min((closest_on_segment(a[v], pb[m], pb[m + 1]) for m in range(len(loop_b))),
                   key=lambda x: np.linalg.norm(x - a[v]))
        border.append(np.linalg.norm(q - near) / diag)
    border = np.array(border)
    mean_edge = lambda p, e: np.mean([np.linalg.norm(p[u] - p[w]) for u, w in e]) / diag
    return {
        "pair": os.path.basename(file_a) + " -> " + os.path.basename(file_b),
        "vertices_a": len(a), "vertices_b": len(b),
        "mean_edge_a": mean_edge(a, edges_a), "mean_edge_b": mean_edge(b, edges_b),
        "border_edges_a": len(loop_a), "border_edges_b": len(loop_b),
        "landmark_mismatch_mean": mismatch.mean(), "landmark_mismatch_max": mismatch.max(),
        "landmark_within_0.5%": (mismatch < 0.005).mean(),
        "border_arc_length_mean": border.mean(), "border_arc_length_max": border.max(),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("pairs", nargs="+", help="A.obj:B.obj")
    parser.add_argument("--out", default="benchmark/results/cross_protocol_floor")
    args = parser.parse_args()
    rows = []
    for p in args.pairs:
        if p.count(":") != 1:
            sys.exit("expected A.obj:B.obj, got " + p)
        rows.append(measure(*p.split(":")))
        print(rows[-1])
    keys = list(rows[0].keys())
    with open(args.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    with open(args.out + ".md", "w") as f:
        f.write("# What the cross-parameterization protocol allows, before any map\n\n")
        f.write(f"Generated {now} by `cross_protocol_floor.py` on {platform.node()}. Distances relative to the "
                "diagonal of A's bounding box. Landmark mismatch: each vertex of the coarser mesh to the nearest vertex of "
                "the other (a landmark of `cross_benchmark --pairs` lands exactly on its partner, so this is its "
                "error); within 0.5%: the share of vertices with a partner that close. Border by arc length: each border "
                "vertex of A placed at its relative arc length on B's border, against the point of B's border nearest "
                "to it.\n\n")
        f.write("| pair | vertices A | vertices B | mean edge A | mean edge B | border edges A | border edges B "
                "| landmark mismatch mean | max | within 0.5% | border by arc length mean | max |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| " + " | ".join(f"{r[k]:.3g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + " |\n")
        f.write("\nCommand: `python3 benchmark/Progressive_embedding/cross_protocol_floor.py " + " ".join(sys.argv[1:]) + "`.\n")


if __name__ == "__main__":
    main()
