#!/usr/bin/env python3
"""The default `pe constrain` command (optimization included) with many random constraints, as a user runs it.

    python3 benchmark/constrained_default_command.py BUILD_DIR [--meshes a.off,b.off] [--counts 50]
            [--seeds 3] [--optimize-time SECONDS ...] [--out benchmark/results/constrained_default_command]

For each libcgal-demo disk (BUILD_DIR/cgal_data/data/meshes), count and seed: `count` random interior vertices
(Python's random.Random(seed)) with targets uniformly random in the disk of radius 0.5 (the border on the unit
circle, `--border circle`), written as a `--fix` file; then `pe constrain IN OUT.obj --fix FILE --border circle
--json --no-progress`, with the default optimization budget and with each `--optimize-time` given. Wall time
and peak memory come from /usr/bin/time; the rest from pe's JSON (the certificate of the written map).
Writes OUT.csv and OUT.md. Standard library only.
"""

import argparse
import csv
import datetime
import json
import os
import platform
import random
import subprocess
import sys
import tempfile


def read_off(path):
    with open(path) as f:
        tokens = f.read().split()
    i = 1 if tokens[0] == "OFF" else 0
    nv, nf = int(tokens[i]), int(tokens[i + 1])
    o = i + 3 + 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[o])
        faces.append([int(x) for x in tokens[o + 1:o + 1 + n]])
        o += 1 + n
    return nv, faces


def interior_vertices(nv, faces):
    count = {}
    for f in faces:
        for k in range(len(f)):
            e = tuple(sorted((f[k], f[(k + 1) % len(f)])))
            count[e] = count.get(e, 0) + 1
    border = {v for e, c in count.items() if c == 1 for v in e}
    return [v for v in range(nv) if v not in border]


def fix_file(path, interior, count, seed):
    rnd = random.Random(seed)
    chosen = rnd.sample(interior, count)
    with open(path, "w") as f:
        for v in chosen:
            while True:
                x, y = rnd.uniform(-1, 1), rnd.uniform(-1, 1)
                if x * x + y * y < 1:
                    break
            f.write("%d %r %r\n" % (v, 0.5 * x, 0.5 * y))


def run(pe, mesh, fix, optimize_time, tmp):
    out = os.path.join(tmp, "out.obj")
    cmd = ["/usr/bin/time", "-f", "TIME %e %M", pe, "constrain", mesh, out, "--fix", fix, "--border", "circle", "--json",
           "--no-progress"]
    if optimize_time is not None:
        cmd += ["--optimize-time", str(optimize_time)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall, rss = float("nan"), float("nan")
    for line in p.stderr.splitlines():
        if line.startswith("TIME "):
            wall, rss = float(line.split()[1]), float(line.split()[2]) / 1024
    j = {}
    for line in p.stdout.splitlines():
        if line.startswith("{"):
            j = json.loads(line)
    return p.returncode, wall, rss, j


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--meshes", default="lion-head.off,mannequin-devil.off")
    ap.add_argument("--counts", default="50")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--optimize-time", type=float, action="append", default=[])
    ap.add_argument("--out", default="benchmark/results/constrained_default_command")
    a = ap.parse_args()
    pe = os.path.join(a.build, "bin", "pe")
    data = os.path.join(a.build, "cgal_data", "data", "meshes")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for mesh in a.meshes.split(","):
            path = os.path.join(data, mesh)
            nv, faces = read_off(path)
            interior = interior_vertices(nv, faces)
            for count in (int(c) for c in a.counts.split(",")):
                for seed in range(a.seeds):
                    fix = os.path.join(tmp, "fix.txt")
                    fix_file(fix, interior, count, seed)
                    for budget in [None] + a.optimize_time:
                        code, wall, rss, j = run(pe, path, fix, budget, tmp)
                        row = dict(mesh=mesh, vertices_in=nv, constraints=count, seed=seed,
                                   optimize_time="default" if budget is None else budget, exit_status=code,
                                   status=j.get("status", "-"), valid=j.get("valid", False),
                                   constraints_exact=j.get("constraints_exact", False), vertices_out=j.get("vertices", 0),
                                   steiner=j.get("steiner_vertices", 0), optimization_budget=j.get("optimization_budget", "-"),
                                   optimization_seconds=j.get("optimization_seconds", float("nan")),
                                   optimization_converged=j.get("optimization_converged", "-"),
                                   mean_sd=j.get("mean_energy_3d", float("nan")), seconds_pe=j.get("seconds", float("nan")),
                                   wall_s=wall, peak_rss_mb=rss)
                        rows.append(row)
                        print("%s K=%d seed %d optimize-time %s: %s, %d -> %d vertices, %.1f s wall (optimization %.1f s), "
                              "%.0f MB, valid %s" % (mesh, count, seed, row["optimize_time"], row["status"], nv,
                                                     row["vertices_out"], wall, row["optimization_seconds"], rss, row["valid"]),
                              flush=True)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    now = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M")
    load = os.getloadavg()[0]
    with open(a.out + ".md", "w") as f:
        f.write("# The default `pe constrain` command with many random constraints\n\n")
        f.write("Generated %s UTC by `benchmark/constrained_default_command.py` on %s (%d cores; load average %.2f at the "
                "end): `pe constrain IN OUT.obj --fix FILE --border circle --json`, the default optimization budget "
                "(and `--optimize-time` where given); targets uniformly random in the disk of radius 0.5. Wall time and "
                "peak memory of the whole command (/usr/bin/time); `valid`: the certificate of the written map.\n\n"
                % (now, platform.node(), os.cpu_count(), load))
        f.write("| mesh | vertices | K | seed | optimize time | status | valid | exact | vertices out | wall s | "
                "optimization s | converged | peak MB | mean sym. Dirichlet |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s | %d | %d | %d | %s | %s | %s | %s | %d | %.1f | %.1f | %s | %.0f | %.3g |\n" % (
                r["mesh"], r["vertices_in"], r["constraints"], r["seed"], r["optimize_time"], r["status"], r["valid"],
                r["constraints_exact"], r["vertices_out"], r["wall_s"], r["optimization_seconds"],
                r["optimization_converged"], r["peak_rss_mb"], r["mean_sd"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
