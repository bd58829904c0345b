#!/usr/bin/env python3
"""Comparison study (issue 4): runs the comparison_study driver, then writes the Markdown summary
and the SVG plots from its CSV. Plain Python 3, no third-party module.

Full study (about 30 minutes on the project's 2-core machine), results in benchmark/results/:
    python3 benchmark/Progressive_embedding/run_study.py
Quick check (a handful of inputs, under 2 minutes), results in BUILD/study_quick/:
    python3 benchmark/Progressive_embedding/run_study.py --quick
Tables and plots again from an existing study_runs.csv, without running anything:
    python3 benchmark/Progressive_embedding/run_study.py --report-only [--out DIR]

Options: --build DIR (default: build), --binary PATH (default: BUILD/bin/comparison_study, built
with `cmake --build BUILD --target comparison_study` unless --no-build), --data DIR (default:
BUILD/cgal_data/data), --out DIR; anything after `--` goes to the driver (see comparison_study.cpp).
"""

import argparse
import csv
import math
import os
import shlex
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

METHODS = [
    ("cgal_barycentric", "CGAL Barycentric_mapping_parameterizer_3"),
    ("cgal_mvc", "CGAL Mean_value_coordinates_parameterizer_3"),
    ("tutte_double", "tutte_embedding, double"),
    ("tutte_mpfr128", "tutte_embedding, MPFR 128 bits"),
    ("tutte_mpfr128_rounded", "&nbsp;&nbsp;the same, rounded to double"),
    ("tutte_mpfr256", "tutte_embedding, MPFR 256 bits"),
    ("tutte_mpfr256_rounded", "&nbsp;&nbsp;the same, rounded to double"),
    ("tutte_gmpq", "tutte_embedding, exact Gmpq"),
    ("tutte_gmpq_rounded", "&nbsp;&nbsp;the same, rounded to double"),
    ("pe_double", "progressive_embedding, double"),
    ("pe_mpfr128", "progressive_embedding, MPFR 128 bits"),
    ("pe_mpfr128_rounded", "&nbsp;&nbsp;the same, rounded to double"),
    ("pe_mpfr256", "progressive_embedding, MPFR 256 bits"),
    ("pe_mpfr256_rounded", "&nbsp;&nbsp;the same, rounded to double"),
    ("pe_parameterizer", "Progressive_embedding_parameterizer_3"),
]
LABEL = dict(METHODS)
PLOT_METHODS = ["cgal_barycentric", "cgal_mvc", "tutte_double", "tutte_mpfr128", "tutte_mpfr256", "tutte_gmpq",
                "pe_double", "pe_mpfr128", "pe_mpfr256", "pe_parameterizer"]
COLOURS = {"cgal_barycentric": "#d62728", "cgal_mvc": "#ff7f0e", "tutte_double": "#7f7f7f", "tutte_mpfr128": "#9467bd",
           "tutte_mpfr256": "#8c564b", "tutte_gmpq": "#e377c2", "pe_double": "#1f77b4", "pe_mpfr128": "#17becf",
           "pe_mpfr256": "#bcbd22", "pe_parameterizer": "#2ca02c"}
BUCKETS = [(0, 100), (100, 1000), (1000, 5000), (5000, 10000), (10000, 40000)]


def median(xs):
    return statistics.median(xs) if xs else float("nan")


def fmt_s(x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    if x == 0:
        return "0"
    if x >= 1e4:
        return "%.3g" % x
    if x >= 100:
        return "%.0f" % x
    if x >= 1:
        return "%.2f" % x
    return "%.2g" % x


def fmt_ratio(x):
    return "–" if x is None or math.isnan(x) else ("%.2f" % x if x < 100 else "%.0f" % x)


def seed_range(seeds):
    if not seeds:
        return "none"
    if seeds == list(range(seeds[0], seeds[-1] + 1)):
        return "%d–%d" % (seeds[0], seeds[-1])
    return ", ".join(map(str, seeds))


def bucket_name(lo, hi):
    def k(n):
        return "%dk" % (n // 1000) if n >= 1000 else str(n)
    return "%s–%s" % (k(lo), k(hi))


# ----------------------------------------------------------------------------------------------

def run_driver(args, out):
    build = os.path.abspath(args.build)
    binary = args.binary or os.path.join(build, "bin", "comparison_study")
    if not args.binary and not args.no_build:
        subprocess.check_call(["cmake", "--build", build, "--target", "comparison_study"])
    data = args.data or os.path.join(build, "cgal_data", "data")
    command = "cd %s && %s" % (shlex.quote(os.getcwd()), " ".join(shlex.quote(a) for a in ["python3"] + sys.argv))
    cmd = [binary, data, out, "--command", command]
    if args.quick:
        cmd.append("--quick")
    cmd += args.driver_args
    print("running:", " ".join(shlex.quote(c) for c in cmd), flush=True)
    t0 = time.time()
    log_path = args.log or os.path.join(out if args.quick else build, "study_log.txt")
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
        for line in proc.stderr:
            log.write(line)
            log.flush()
            if args.verbose:
                sys.stderr.write(line)
        proc.wait()
    if proc.returncode != 0:
        sys.exit("comparison_study failed (exit %d), see %s" % (proc.returncode, log_path))
    print("driver finished in %.0f s" % (time.time() - t0), flush=True)


def read_rows(out):
    with open(os.path.join(out, "study_runs.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("vertices", "faces", "interior_vertices", "tutte_flipped", "tutte_degenerate", "seed", "bits"):
            r[k] = int(r[k])
        r["ran"] = r["status"] != "SKIPPED"
        r["ok"] = r["status"] == "OK"
        r["valid"] = r["certified_valid"] == "1"
        r["t"] = float(r["seconds"]) if r["seconds"] not in ("", None) else float("nan")
        for k in ("extra_mb", "peak_rss_mb", "max_sd", "mean_sd"):
            r[k] = float(r[k]) if r[k] not in ("", "nan") else float("nan")
        r["key"] = (r["kind"], r["mesh"], r["seed"])
    return rows


def read_meta(out):
    meta = {}
    path = os.path.join(out, "study_meta.txt")
    if os.path.exists(path):
        for line in open(path):
            if ":" in line:
                k, v = line.split(":", 1)
                meta[k.strip()] = v.strip()
    return meta


# ----------------------------------------------------------------------------------------------
# plots: plain SVG

def svg_text(x, y, s, size=13, anchor="start", extra=""):
    s = s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return '<text x="%.1f" y="%.1f" font-family="sans-serif" font-size="%d" text-anchor="%s" %s>%s</text>\n' % (x, y, size, anchor, extra, s)


def plot_time_vs_size(rows, path, title):
    # one point per (input, method): median over the seeds of a mesh (corpus) or the run (disk)
    series = {m: {} for m in PLOT_METHODS}
    for r in rows:
        if r["method"] in series and r["ran"] and r["status"] != "CRASH" and r["t"] > 0:
            series[r["method"]].setdefault((r["kind"], r["mesh"], r["vertices"]), []).append((r["t"], r["status"] == "TIMEOUT"))
    pts = {m: sorted((k[2], median([t for t, _ in v]), any(to for _, to in v), k[0] == "disk") for k, v in s.items()) for m, s in series.items()}
    allx = [p[0] for s in pts.values() for p in s]
    ally = [p[1] for s in pts.values() for p in s]
    if not allx:
        return
    x0, x1 = 10 ** math.floor(math.log10(max(1, min(allx)))), 10 ** math.ceil(math.log10(max(allx)))
    y0, y1 = 10 ** math.floor(math.log10(min(ally))), 10 ** math.ceil(math.log10(max(ally)))
    W, H, L, R, T, B = 980, 640, 80, 330, 50, 60
    pw, ph = W - L - R, H - T - B

    def X(x):
        return L + (math.log10(x) - math.log10(x0)) / (math.log10(x1) - math.log10(x0)) * pw

    def Y(y):
        return T + ph - (math.log10(y) - math.log10(y0)) / (math.log10(y1) - math.log10(y0)) * ph

    s = ['<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">\n' % (W, H, W, H),
         '<rect width="100%" height="100%" fill="white"/>\n', svg_text(L, 28, title, 16)]
    s.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>\n' % (L, T, pw, ph))
    e = int(math.log10(x0))
    while 10 ** e <= x1:
        x = X(10 ** e)
        s.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>\n' % (x, T, x, T + ph))
        s.append(svg_text(x, T + ph + 18, "1e%d" % e, 12, "middle"))
        e += 1
    e = int(math.log10(y0))
    while 10 ** e <= y1 * 1.0001:
        y = Y(10 ** e)
        s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>\n' % (L, y, L + pw, y))
        s.append(svg_text(L - 6, y + 4, "1e%d" % e, 12, "end"))
        e += 1
    s.append(svg_text(L + pw / 2, H - 15, "mesh vertices (log)", 13, "middle"))
    s.append(svg_text(20, T + ph / 2, "seconds (log)", 13, "middle", 'transform="rotate(-90 20 %.1f)"' % (T + ph / 2)))
    ly = T + 10
    for m in PLOT_METHODS:
        p = pts[m]
        if not p:
            continue
        c = COLOURS[m]
        corpus = [q for q in p if not q[3]]
        if len(corpus) > 1:
            s.append('<polyline fill="none" stroke="%s" stroke-width="1.2" stroke-opacity="0.6" points="%s"/>\n' % (c, " ".join("%.1f,%.1f" % (X(x), Y(y)) for x, y, _, _ in corpus)))
        for x, y, to, disk in p:
            if to:
                s.append('<path d="M%.1f %.1fl-4 -7h8z" fill="%s"/>\n' % (X(x), Y(y) - 2, c))
            elif disk:
                s.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="white" stroke="%s" stroke-width="1.5"/>\n' % (X(x), Y(y), c))
            else:
                s.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>\n' % (X(x), Y(y), c))
        s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="3"/>\n' % (L + pw + 15, ly, L + pw + 35, ly, c))
        s.append(svg_text(L + pw + 40, ly + 4, "%s (%d inputs)" % (m, len(p)), 12))
        ly += 20
    s.append(svg_text(L + pw + 15, ly + 10, "dots and lines: closed meshes, Tutte-failure", 11))
    s.append(svg_text(L + pw + 15, ly + 25, "protocol, median over the seeds run;", 11))
    s.append(svg_text(L + pw + 15, ly + 40, "rings: disks (PE: from a random init);", 11))
    s.append(svg_text(L + pw + 15, ly + 55, "triangles: time budget reached", 11))
    s.append("</svg>\n")
    open(path, "w").write("".join(s))


# ----------------------------------------------------------------------------------------------

def summary(rows, out, meta, gallery):
    L = []
    add = L.append
    by_key = {}
    for r in rows:
        by_key.setdefault(r["key"], {})[r["method"]] = r
    corpus_keys = sorted({k for k in by_key if k[0] == "corpus"})
    disk_keys = sorted({k for k in by_key if k[0] == "disk"})
    failing = [k for k in corpus_keys if "tutte_double" in by_key[k] and not by_key[k]["tutte_double"]["valid"]]
    failing_set = set(failing)
    meshes = sorted({k[1] for k in corpus_keys})

    add("# Comparison study: CGAL's parameterizers, high-precision and exact Tutte, progressive embedding\n")
    add("Generated by `benchmark/Progressive_embedding/run_study.py` from `study_runs.csv` (one row per run); "
        "do not edit by hand.\n")
    add("- command: `%s`" % meta.get("study command", "?"))
    add("- driver: `%s`" % meta.get("driver command", "?"))
    add("- date: %s; driver wall-clock: %s s" % (meta.get("date", "?"), meta.get("driver wall-clock seconds", "?")))
    add("- machine: %s; nproc %s; %s; memory %s" % (meta.get("machine", "?"), meta.get("nproc", "?"), meta.get("cpu", "?"), meta.get("memory", "?")))
    add("- software: g++ %s, CGAL %s (`-O3 -DNDEBUG`)" % (meta.get("compiler", "?"), meta.get("CGAL", "?")))
    add("- budgets: %s s per run (Gmpq: %s s); MPFR Tutte: %s; MPFR progressive embedding: %s; Gmpq Tutte: %s" % (
        meta.get("budget per run (s)", "?"), meta.get("Gmpq budget per run (s)", "?"), meta.get("MPFR Tutte up to vertices", "?"),
        meta.get("MPFR progressive embedding up to vertices", "?"), meta.get("Gmpq Tutte up to interior vertices", "?")))
    add("")
    add("Inputs: %d runs of the Tutte-failure protocol on %d closed genus-0 meshes (seeds %s; DESIGN.md section 6: "
        "one face removed, its vertices pinned to (0,0), (1/2, √3/2), (1,0)), of which **%d fail** with double Tutte (LDLT); "
        "%d disks with the border on the unit circle (3D arc length) and the random-init protocol as the input of "
        "progressive embedding. Every method gets the same border: CGAL's parameterizers through a border parameterizer "
        "that writes the protocol's positions. Every output map is certified by `check_embedding` (exact predicates: "
        "flipped, degenerate, border self-intersections, overlapping faces). Each run is a forked process "
        "(time budget, peak memory: getrusage after resetting the high-water mark; *extra MB* = peak − process size before the run)."
        % (len(corpus_keys), len(meshes), seed_range(sorted({k[2] for k in corpus_keys})), len(failing), len(disk_keys)))
    add("")

    # ---- robustness
    add("## Robustness: every run\n")
    add("| method | runs | certified valid | returned OK while invalid | returned an error | time-outs | skipped (budget) | median time (s) | median extra MB | median mean sym. Dirichlet (valid runs) |")
    add("|---|---|---|---|---|---|---|---|---|---|")
    for m, label in METHODS:
        rs = [r for r in rows if r["method"] == m]
        if not rs:
            continue
        ran = [r for r in rs if r["ran"]]
        valid = sum(r["valid"] for r in ran)
        ok_invalid = sum(r["ok"] and not r["valid"] for r in ran)
        err = sum(r["status"].startswith("ERROR") for r in ran)
        to = sum(r["status"] in ("TIMEOUT", "CRASH") for r in ran)
        rounded = m.endswith("_rounded")
        t = median([r["t"] for r in ran if r["status"] != "TIMEOUT"])
        mem = median([r["extra_mb"] for r in ran if not math.isnan(r["extra_mb"])])
        sd = median([r["mean_sd"] for r in ran if r["valid"] and math.isfinite(r["mean_sd"])])
        add("| %s `%s` | %d | %d (%.1f%%) | %s | %d | %d | %d | %s | %s | %s |" % (
            label, m, len(ran), valid, 100.0 * valid / max(1, len(ran)),
            ("**%d**" % ok_invalid) if ok_invalid else "0", err, to, len(rs) - len(ran),
            "(same run)" if rounded else fmt_s(t), "" if rounded else fmt_s(mem), fmt_s(sd)))
    add("")
    add("*returned OK while invalid*: the method's status is `OK` (`SMP::OK` for CGAL's parameterizers and ours through "
        "`SMP::parameterize`) but the exact certificate finds flipped or degenerate faces or overlaps. The `_rounded` rows "
        "certify the MPFR or exact map after rounding its coordinates to double (what a caller storing `double` uv gets); "
        "they are not separate computations.\n")

    # ---- on the failing runs
    add("## On the %d corpus runs where double Tutte fails\n" % len(failing))
    add("| method | runs | certified valid | returned OK while invalid | returned an error | median time (s) |")
    add("|---|---|---|---|---|---|")
    for m, label in METHODS:
        rs = [by_key[k][m] for k in failing if m in by_key[k] and by_key[k][m]["ran"]]
        if not rs:
            continue
        valid = sum(r["valid"] for r in rs)
        oi = sum(r["ok"] and not r["valid"] for r in rs)
        add("| %s `%s` | %d | %d | %s | %d | %s |" % (label, m, len(rs), valid, ("**%d**" % oi) if oi else "0", sum(r["status"].startswith("ERROR") for r in rs),
            "(same run)" if m.endswith("_rounded") else fmt_s(median([r["t"] for r in rs if r["status"] != "TIMEOUT"]))))
    add("")
    extra_fail = {}
    for m in ("cgal_barycentric", "cgal_mvc"):
        extra_fail[m] = [k for k in corpus_keys if m in by_key[k] and by_key[k][m]["ran"] and not by_key[k][m]["valid"]]
    add("CGAL's parameterizers (default solver: BiCGSTAB with an incomplete LU preconditioner) fail on more runs than "
        "double Tutte with a direct solver: Barycentric_mapping on %d corpus runs (%d of them outside the %d above), "
        "Mean_value_coordinates on %d (%d outside).\n" % (
            len(extra_fail["cgal_barycentric"]), len([k for k in extra_fail["cgal_barycentric"] if k not in failing_set]), len(failing),
            len(extra_fail["cgal_mvc"]), len([k for k in extra_fail["cgal_mvc"] if k not in failing_set])))

    # ---- Table 1
    add("## Table 1: the failing runs (paper-style)\n")
    add("#invalid = flipped + degenerate faces of the double Tutte map (exact predicates); our time: `progressive_embedding` "
        "from that map, and `Progressive_embedding_parameterizer_3` end to end (border, Tutte, certificate, repair); "
        "CGAL: what `Barycentric_mapping_parameterizer_3` returned and whether its map is valid.\n")
    add("| mesh | seed | #V | #F | #invalid | #flipped | PE time (s) | PE certified | parameterizer time (s) | parameterizer certified | CGAL barycentric: status, #flipped+degenerate |")
    add("|---|---|---|---|---|---|---|---|---|---|---|")
    for k in sorted(failing, key=lambda k: (k[1], k[2])):
        d = by_key[k]
        td, pe, pp, cb = d.get("tutte_double"), d.get("pe_double"), d.get("pe_parameterizer"), d.get("cgal_barycentric")
        if not cb or not cb["ran"]:
            cbs = "–"
        elif cb["valid"]:
            cbs = "%s, valid" % cb["status"]
        else:
            cbs = "%s, **%d**" % (cb["status"], int(cb["flipped"] or 0) + int(cb["degenerate"] or 0))
        add("| %s | %d | %d | %d | %d | %d | %s | %s | %s | %s | %s |" % (
            k[1], k[2], td["vertices"], td["faces"], int(td["flipped"]) + int(td["degenerate"]), int(td["flipped"]),
            fmt_s(pe["t"]) if pe else "–", ("yes" if pe["valid"] else "**NO**") if pe else "–",
            fmt_s(pp["t"]) if pp else "–", ("yes" if pp["valid"] else "**NO**") if pp else "–", cbs))
    add("")

    # ---- time ratios per size bucket
    add("## Time ratios per mesh size (medians over the runs of the bucket)\n")
    add("ours = `Progressive_embedding_parameterizer_3` through `SMP::parameterize` (certified; repairs when needed); "
        "CGAL Tutte = `Barycentric_mapping_parameterizer_3` through `SMP::parameterize`; same border, same process setup.\n")
    add("| #V | runs | ours / CGAL Tutte | ours / CGAL MVC | ours / CGAL Tutte, failing runs only | our double Tutte / CGAL Tutte | median CGAL Tutte (s) | median ours (s) |")
    add("|---|---|---|---|---|---|---|---|")
    for lo, hi in BUCKETS:
        ks = [k for k in corpus_keys + disk_keys if lo <= next(iter(by_key[k].values()))["vertices"] < hi]
        def ratio(a, b, keys):
            v = [by_key[k][a]["t"] / by_key[k][b]["t"] for k in keys if a in by_key[k] and b in by_key[k]
                 and by_key[k][a]["ran"] and by_key[k][b]["ran"] and by_key[k][b]["t"] > 0]
            return median(v), len(v)
        r1, n = ratio("pe_parameterizer", "cgal_barycentric", ks)
        if n == 0:
            continue
        r2, _ = ratio("pe_parameterizer", "cgal_mvc", ks)
        r3, n3 = ratio("pe_parameterizer", "cgal_barycentric", [k for k in ks if k in failing_set])
        r4, _ = ratio("tutte_double", "cgal_barycentric", ks)
        tc = median([by_key[k]["cgal_barycentric"]["t"] for k in ks if "cgal_barycentric" in by_key[k]])
        to = median([by_key[k]["pe_parameterizer"]["t"] for k in ks if "pe_parameterizer" in by_key[k]])
        add("| %s | %d | %s | %s | %s | %s | %s | %s |" % (bucket_name(lo, hi), n, fmt_ratio(r1), fmt_ratio(r2),
            ("%s (%d runs)" % (fmt_ratio(r3), n3)) if n3 else "–", fmt_ratio(r4), fmt_s(tc), fmt_s(to)))
    add("")

    # ---- MPFR vs double progressive embedding
    add("## Progressive embedding in MPFR vs in double (same input map)\n")
    add("| input | seed | #V | input | double (s) | MPFR 128 (s) | MPFR 256 (s) | MPFR 128 / double | MPFR 256 / double | certified (double, 128, 256, 128→double, 256→double) |")
    add("|---|---|---|---|---|---|---|---|---|---|")
    ratios = {128: [], 256: []}
    for k in corpus_keys + disk_keys:
        d = by_key[k]
        if not any(m in d and d[m]["ran"] for m in ("pe_mpfr128", "pe_mpfr256")):
            continue
        pe = d["pe_double"]
        cells, cert = [], ["yes" if pe["valid"] else "NO"]
        for b in (128, 256):
            r = d.get("pe_mpfr%d" % b)
            cells.append(fmt_s(r["t"]) + (" (time-out)" if r and r["status"] == "TIMEOUT" else "") if r and r["ran"] else "–")
        rr = []
        for b in (128, 256):
            r = d.get("pe_mpfr%d" % b)
            if r and r["ran"] and r["status"] == "OK" and pe["t"] > 0:
                rr.append(r["t"] / pe["t"]); ratios[b].append(r["t"] / pe["t"])
            else:
                rr.append(float("nan"))
        for m in ("pe_mpfr128", "pe_mpfr256", "pe_mpfr128_rounded", "pe_mpfr256_rounded"):
            r = d.get(m)
            cert.append(("yes" if r["valid"] else "NO") if r and r["ran"] and r["certified_valid"] != "" else "–")
        add("| %s %s | %d | %d | %s | %s | %s | %s | %s | %s | %s |" % (k[0], k[1], k[2], pe["vertices"], pe["input"], fmt_s(pe["t"]),
            cells[0], cells[1], fmt_ratio(rr[0]), fmt_ratio(rr[1]), ", ".join(cert)))
    add("")
    add("Median slowdown of MPFR progressive embedding over double: %s (128 bits), %s (256 bits).\n" % (
        fmt_ratio(median(ratios[128])), fmt_ratio(median(ratios[256]))))

    # ---- MPFR Tutte and rounding
    add("## High-precision Tutte and rounding\n")
    add("| method | runs | certified valid | of the failing runs: valid before rounding | valid after rounding to double | time / double Tutte: median over the failing runs | largest run: #V, seconds |")
    add("|---|---|---|---|---|---|---|")
    for m in ("tutte_mpfr128", "tutte_mpfr256", "tutte_gmpq"):
        rs = [r for r in rows if r["method"] == m and r["ran"]]
        if not rs:
            continue
        fk = [r["key"] for r in rs if r["key"] in failing_set]
        before = sum(by_key[k][m]["valid"] for k in fk)
        after = sum(by_key[k].get(m + "_rounded", {}).get("valid", False) for k in fk)
        rt = median([by_key[k][m]["t"] / by_key[k]["tutte_double"]["t"] for k in fk
                     if by_key[k][m]["status"] == "OK" and by_key[k]["tutte_double"]["t"] > 0])
        big = max((r for r in rs if r["status"] == "OK"), key=lambda r: (r["vertices"], r["t"]), default=None)
        add("| %s | %d | %d | %s | %s | %s | %s |" % (m, len(rs), sum(r["valid"] for r in rs),
            "%d / %d" % (before, len(fk)) if fk else "–", "%d / %d" % (after, len(fk)) if fk else "–",
            fmt_ratio(rt), ("%s: %d, %s" % (big["mesh"], big["vertices"], fmt_s(big["t"]))) if big else "–"))
    add("")
    nf = len([k for k in failing if "tutte_mpfr128" in by_key[k] and by_key[k]["tutte_mpfr128"]["ran"]])
    if nf < len(failing):
        add("%d of the %d failing runs were not run in MPFR (budget, see above).\n" % (len(failing) - nf, len(failing)))

    # ---- exact Tutte
    add("## Exact (Gmpq) Tutte: which sizes finish\n")
    gq = {}
    for r in rows:
        if r["method"] == "tutte_gmpq":
            gq.setdefault((r["interior_vertices"], r["mesh"]), []).append(r)
    add("| mesh | interior vertices | runs | finished | time-outs | skipped (budget) | median time (s) | certified valid | valid after rounding to double |")
    add("|---|---|---|---|---|---|---|---|---|")
    finished_sizes, timeout_sizes, skipped_only = [], [], []
    for (n, mesh), rs in sorted(gq.items()):
        ran = [r for r in rs if r["ran"]]
        if not ran:
            skipped_only.append(n)
            continue
        fin = [r for r in ran if r["status"] == "OK"]
        tos = [r for r in ran if r["status"] == "TIMEOUT"]
        if fin:
            finished_sizes.append(n)
        if tos:
            timeout_sizes.append(n)
        rounded = [by_key[r["key"]].get("tutte_gmpq_rounded") for r in fin]
        add("| %s | %d | %d | %d | %d | %d | %s | %d | %d |" % (mesh, n, len(ran), len(fin), len(tos), len(rs) - len(ran),
            fmt_s(median([r["t"] for r in fin])), sum(r["valid"] for r in fin), sum(bool(x and x["valid"]) for x in rounded)))
    add("")
    add("Exact Tutte finished up to %s interior vertices%s. Not run (budget): %d inputs with %s interior vertices." % (
        max(finished_sizes) if finished_sizes else "–", ("; time-outs from %d" % min(timeout_sizes)) if timeout_sizes else "; no time-out",
        len(skipped_only), ("%d to %d" % (min(skipped_only), max(skipped_only))) if skipped_only else "–"))
    add("")

    # ---- plots and gallery
    add("## Plots\n")
    add("![time vs mesh size](study_time_vs_size.svg)\n")
    if gallery:
        add("## Gallery: the worst corpus runs, before and after\n")
        add("Double Tutte map (left) and the same faces after `progressive_embedding` (right), framed on the invalid faces "
            "(red: flipped, magenta: degenerate; colour: symmetric Dirichlet energy against an equilateral triangle).\n")
        add("| run | #invalid | Tutte in double | progressive embedding |")
        add("|---|---|---|---|")
        for g in gallery:
            add("| %s seed %s | %s | ![](%s) | ![](%s) |" % (g["mesh"], g["seed"], g["tutte_invalid_faces"], g["tutte_zoom_svg"], g["repaired_zoom_svg"]))
        full = [g["tutte_full_svg"] for g in gallery if g.get("tutte_full_svg")]
        if full:
            add("\nThe whole double Tutte map of the worst run (the invalid faces are far below a pixel): ![](%s)" % full[0])
        add("")
    open(os.path.join(out, "study_summary.md"), "w").write("\n".join(L) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="a handful of inputs (the test suite runs this)")
    ap.add_argument("--build", default=os.path.join(REPO, "build"))
    ap.add_argument("--binary")
    ap.add_argument("--no-build", action="store_true")
    ap.add_argument("--data")
    ap.add_argument("--out")
    ap.add_argument("--report-only", action="store_true", help="only the tables and plots, from OUT/study_runs.csv")
    ap.add_argument("--verbose", action="store_true", help="echo the driver's log")
    ap.add_argument("--log", help="the driver's log (default: BUILD/study_log.txt; OUT/study_log.txt with --quick)")
    ap.add_argument("driver_args", nargs="*", help="after --: options of comparison_study")
    args = ap.parse_args()
    out = args.out or (os.path.join(os.path.abspath(args.build), "study_quick") if args.quick else os.path.join(REPO, "benchmark", "results"))
    os.makedirs(out, exist_ok=True)
    if not args.report_only:
        run_driver(args, out)
    rows = read_rows(out)
    meta = read_meta(out)
    gallery = []
    gpath = os.path.join(out, "study_gallery.csv")
    if os.path.exists(gpath):
        gallery = list(csv.DictReader(open(gpath)))
    plot_time_vs_size(rows, os.path.join(out, "study_time_vs_size.svg"),
                      "Time vs mesh size (%s)" % meta.get("date", "").split(" ")[0])
    summary(rows, out, meta, gallery)
    # the headline figures, for logs and the test suite
    ok_invalid = {m: sum(r["ok"] and not r["valid"] for r in rows if r["method"] == m and r["ran"]) for m in ("cgal_barycentric", "cgal_mvc", "pe_double", "pe_parameterizer")}
    ours = [r for r in rows if r["method"] in ("pe_double", "pe_parameterizer") and r["ran"]]
    print("returned OK while invalid: " + ", ".join("%s %d" % kv for kv in ok_invalid.items()))
    print("ours certified: %d / %d" % (sum(r["valid"] for r in ours), len(ours)))
    print("wrote %s" % os.path.join(out, "study_summary.md"))
    return 0 if all(r["valid"] for r in ours) else 1


if __name__ == "__main__":
    sys.exit(main())
