#!/usr/bin/env python3
"""Free-border optimization, before and after the border barrier: benchmark/results/free_border.{csv,md}.

For each disk: `pe embed IN tutte.obj --border circle --no-optimize` (the circle Tutte map, made once
with --pe), then `PE optimize tutte.obj out.obj --free-border --json` with each program (the current
`pe` and the one built from an older commit), --runs times; the table keeps the medians of the CPU
time (user + system of the process: the machine is shared, wall times are inflated by other jobs) and
of the wall time, and the energy, iterations and certificate of the last run (they do not vary).
A reference row per disk gives libigl's SCAF figures where they were measured elsewhere (--scaf).

    python3 benchmark/Progressive_embedding/free_border_benchmark.py --pe build/bin/pe \\
        --pe-old OLD_BUILD/bin/pe --old-commit 895ab1d --data DIR [--runs 3] [--out benchmark/results/free_border] \\
        [--new-commit NAME] [--scaf DISK:ENERGY:SECONDS:SOURCE]

DIR holds the inputs (not part of this repository, see DISKS): retinal_miq.obj (its cone and seam lines
are dropped: the mesh of its texture coordinates is the retinal surface cut along its seams) and the
OptCuts disks. Energies: the certificate's area-weighted mean symmetric Dirichlet energy, against the 3D
triangles scaled to the map's border area (`mean_energy_3d`, 4 for an isometry), and its half (2 for an
isometry), the convention of the SCAF figures.
"""

import argparse
import csv
import datetime
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile

# name, file in --data, source repository, commit, path there
DISKS = [
    ("retinal_cut", "retinal_miq.obj", "hankstag/progressive_embedding", "737d818", "data/retinal_miq.obj"),
    ("bimba", "bimba_i_f10000.obj", "liminchen/OptCuts", "cd23026", "input/benchmark/bimba_i_f10000.obj"),
    ("face", "face_f10000.obj", "liminchen/OptCuts", "cd23026", "input/benchmark/face_f10000.obj"),
    ("camel", "camel_vova_f10000.obj", "liminchen/OptCuts", "cd23026", "input/benchmark/camel_vova_f10000.obj"),
    ("hencky", "hencky_f20000.obj", "liminchen/OptCuts", "cd23026", "input/benchmark/hencky_f20000.obj"),
]

COLUMNS = ["disk", "source_repository", "source_commit", "source_path", "vertices", "faces", "border_vertices",
           "program", "program_repository", "program_commit", "command", "runs", "iterations", "converged",
           "energy_isometry_2", "mean_energy_3d", "cpu_seconds", "wall_seconds", "valid", "machine", "date", "note"]


def git_commit(path):
    try:
        return subprocess.run(["git", "-C", path, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def run_timed(cmd):
    """runs cmd; returns (stdout, cpu seconds of the child, wall seconds)"""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = datetime.datetime.now()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = (datetime.datetime.now() - t0).total_seconds()
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p, cpu, wall


def last_json(text):
    for line in reversed(text.strip().splitlines()):
        if line.startswith("{"):
            return json.loads(line)
    raise ValueError("no JSON line in the output")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pe", required=True, help="the current pe")
    ap.add_argument("--pe-old", required=True, help="pe built from --old-commit")
    ap.add_argument("--old-commit", required=True)
    ap.add_argument("--new-commit", help="how to name the current pe's source (default: the checkout's HEAD)")
    ap.add_argument("--data", required=True, help="folder of the input files")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "results", "free_border"))
    ap.add_argument("--machine", default="the project's shared 2-core machine")
    ap.add_argument("--scaf", action="append", default=[],
                    help="DISK:ENERGY:SECONDS:SOURCE, a SCAF reference measured elsewhere (repeatable)")
    a = ap.parse_args()
    repo = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    new_commit = a.new_commit or git_commit(repo)
    machine = "%s (%s, %s)" % (a.machine, platform.machine(), platform.platform())
    date = datetime.date.today().isoformat()
    scaf = {}
    for s in a.scaf:
        disk, energy, seconds, source = s.split(":", 3)
        scaf[disk] = (energy, seconds, source)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, fname, src_repo, src_commit, src_path in DISKS:
            src = os.path.join(a.data, fname)
            if not os.path.exists(src):
                print("skipping %s: %s missing" % (name, src), file=sys.stderr)
                continue
            inp = os.path.join(tmp, name + ".obj")
            with open(src) as f, open(inp, "w") as g:  # cone ('c') and seam ('sm') lines are not OBJ
                for line in f:
                    if not (line.startswith("c ") or line.startswith("sm ")):
                        g.write(line)
            tutte = os.path.join(tmp, name + "_tutte.obj")
            p = subprocess.run([a.pe, "embed", inp, tutte, "--border", "circle", "--no-optimize", "--json"],
                               capture_output=True, text=True)
            info = last_json(p.stdout)
            if p.returncode != 0 or not info.get("valid"):
                print("skipping %s: no valid Tutte map" % name, file=sys.stderr)
                continue
            for label, exe, commit in (("pe (before)", a.pe_old, a.old_commit), ("pe (after)", a.pe, new_commit)):
                cpus, walls, res = [], [], None
                out = os.path.join(tmp, name + "_opt.obj")
                cmd = [exe, "optimize", tutte, out, "--free-border", "--no-progress", "--json"]
                for _ in range(a.runs):
                    p, cpu, wall = run_timed(cmd)
                    res = last_json(p.stdout)
                    cpus.append(cpu)
                    walls.append(wall)
                rows.append({
                    "disk": name, "source_repository": src_repo, "source_commit": src_commit, "source_path": src_path,
                    "vertices": info.get("vertices"), "faces": info.get("faces"),
                    "border_vertices": info.get("border_vertices"),
                    "program": label, "program_repository": "this repository", "program_commit": commit,
                    "command": "pe embed IN tutte.obj --border circle --no-optimize; pe optimize tutte.obj out.obj "
                               "--free-border --no-progress --json",
                    "runs": a.runs, "iterations": res["iterations"], "converged": res["converged"],
                    "energy_isometry_2": "%.4f" % (res["energy_after"] / 2),
                    "mean_energy_3d": "%.4f" % res["energy_after"],
                    "cpu_seconds": "%.3f" % statistics.median(cpus), "wall_seconds": "%.3f" % statistics.median(walls),
                    "valid": res["valid"], "machine": machine, "date": date, "note": ""})
                print(rows[-1]["disk"], label, rows[-1]["iterations"], rows[-1]["energy_isometry_2"],
                      rows[-1]["cpu_seconds"], file=sys.stderr)
            if name in scaf:
                energy, seconds, source = scaf[name]
                rows.append({
                    "disk": name, "source_repository": src_repo, "source_commit": src_commit, "source_path": src_path,
                    "vertices": info.get("vertices"), "faces": info.get("faces"),
                    "border_vertices": info.get("border_vertices"),
                    "program": "SCAF (libigl)", "program_repository": "libigl/libigl", "program_commit": "unknown",
                    "command": "not recorded: from the same circle Tutte map, same energy and scaling",
                    "runs": "", "iterations": "", "converged": "", "energy_isometry_2": energy,
                    "mean_energy_3d": "%.4f" % (2 * float(energy)), "cpu_seconds": "", "wall_seconds": seconds,
                    "valid": "", "machine": "2-core machine", "date": "", "note": source})
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    with open(a.out + ".md", "w") as f:
        f.write("# Free-border optimization: before and after the border barrier\n\n")
        f.write("Generated by `benchmark/Progressive_embedding/free_border_benchmark.py` (do not edit). ")
        f.write("Machine: %s; date %s; %d runs per program, medians of the CPU time (user + system: the machine is "
                "shared, wall times are inflated by other jobs) and of the wall time.\n\n" % (machine, date, a.runs))
        f.write("Every map: `pe embed IN tutte.obj --border circle --no-optimize`, then `pe optimize tutte.obj out.obj "
                "--free-border`; before: commit %s, after: %s. "
                "Energy: the certificate's mean symmetric Dirichlet energy against the 3D triangles scaled to the "
                "map's border area, halved (2 for an isometry, the convention of the SCAF figures).\n\n"
                % (a.old_commit, new_commit))
        f.write("| disk | vertices | border | program | iterations | converged | energy | CPU s | wall s | certified |\n")
        f.write("|---|---:|---:|---|---:|---|---:|---:|---:|---|\n")
        for r in rows:
            f.write("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n" % (
                r["disk"], r["vertices"], r["border_vertices"], r["program"], r["iterations"], r["converged"],
                r["energy_isometry_2"], r["cpu_seconds"] or "-", r["wall_seconds"] or "-",
                {True: "valid", False: "INVALID"}.get(r["valid"], "-")))
        notes = sorted({r["note"] for r in rows if r["note"]})
        if notes:
            f.write("\n" + "\n".join("- SCAF: " + n for n in notes) + "\n")
        f.write("\nInputs (not in this repository): %s.\n" % "; ".join(
            "%s: %s@%s `%s`" % (d[0], d[2], d[3], d[4]) for d in DISKS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
