#!/usr/bin/env python3
"""The comparison study's smoke test (ctest: comparison_study_quick): runs `run_study.py --quick`, then
checks what it wrote against known values of the quick input set (bull.off seeds 0 and 1, dino.off
seeds 0 and 8, the disks patch-23.off and blob.off):
  - the published layout: exactly the expected files, no raw CSV, no SVG (PNG pictures under 300 KB
    that show a picture, not a blank page);
  - study_runs.csv.gz: the driver's columns, the six inputs, every run of ours (progressive embedding
    in double and MPFR, Progressive_embedding_parameterizer_3) returned OK and certified valid;
  - the known failures: double Tutte, CGAL's Barycentric_mapping and Mean_value_coordinates
    parameterizers return OK with an invalid map on bull.off seed 0 and dino.off seed 8 only, with the
    invalid-face counts of the double Tutte map; MPFR Tutte is valid there, and invalid once rounded;
  - study_tutte_failures.tsv lists the two failing runs;
  - study_methods.csv and study_summary.md agree with a recount of the runs; the gallery is dino.off
    seed 8 (2230 invalid faces), repaired and certified;
  - `--report-only --redraw-gallery` regenerates the same tables and pictures from the published files.
Exit status 0 when every check passes; each failed check is printed.

    test_study_quick.py --build BUILD --out DIR [--no-png]
--no-png: no SVG renderer is installed, the pictures are expected as SVG.
"""

import argparse
import csv
import gzip
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import run_study  # noqa: E402  (the PNG reader and the column lists)

RUNS_COLUMNS = ["kind", "mesh", "seed", "vertices", "faces", "interior_vertices", "tutte_flipped", "tutte_degenerate",
                "method", "bits", "input", "status", "returned_ok", "certified_valid", "flipped", "degenerate",
                "non_finite", "border_simple", "overlapping_pairs", "overlap_checked", "seconds", "peak_rss_mb",
                "extra_mb", "max_sd", "mean_sd", "note"]
METHODS_COLUMNS = ["method", "runs", "certified_valid", "returned_ok_invalid", "returned_error", "timeout_or_crash",
                   "skipped", "failing_runs", "failing_certified_valid", "failing_returned_ok_invalid",
                   "median_seconds", "median_extra_mb", "median_mean_sd_valid"]
GALLERY_COLUMNS = ["rank", "mesh", "seed", "tutte_invalid_faces", "zoom_faces", "tutte_zoom_picture",
                   "repaired_zoom_picture", "tutte_full_picture", "repaired_status", "repaired_valid"]
INPUTS = {("corpus", "bull.off", "0"), ("corpus", "bull.off", "1"), ("corpus", "dino.off", "0"),
          ("corpus", "dino.off", "8"), ("disk", "patch-23.off", "1"), ("disk", "blob.off", "1")}
# the double Tutte map of the failing runs: (flipped, degenerate)
FAILING = {("corpus", "bull.off", "0"): (35, 49), ("corpus", "dino.off", "8"): (1836, 394)}
# flipped + degenerate faces of CGAL's Barycentric_mapping_parameterizer_3 map there (it returns OK)
CGAL_BARYCENTRIC_INVALID = {("corpus", "bull.off", "0"): 157, ("corpus", "dino.off", "8"): 1632}
OURS = ("pe_double", "pe_parameterizer", "pe_mpfr128", "pe_mpfr256", "pe_mpfr128_rounded", "pe_mpfr256_rounded")
# runs (not skipped) per method on the quick set
RUNS = {"cgal_barycentric": 6, "cgal_mvc": 6, "tutte_double": 6, "tutte_mpfr128": 5, "tutte_mpfr256": 5,
        "tutte_gmpq": 2, "pe_double": 6, "pe_mpfr128": 2, "pe_mpfr256": 2, "pe_parameterizer": 6}
GALLERY_STEM = "study_gallery_1_dino_8"

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAILED: " + what, flush=True)
    return cond


def run(cmd):
    print("running:", " ".join(cmd), flush=True)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(p.stdout)
    return p


def read_csv(path):
    with (gzip.open(path, "rt", newline="") if path.endswith(".gz") else open(path, newline="")) as f:
        r = csv.DictReader(f)
        return r.fieldnames, list(r)


def check_picture(path, ext):
    name = os.path.basename(path)
    if not check(os.path.exists(path), "%s exists" % name):
        return
    if ext == ".svg":
        check(open(path).read(200).lstrip().startswith("<?xml"), "%s is an SVG file" % name)
        return
    size = os.path.getsize(path)
    check(size < run_study.MAX_PNG_BYTES, "%s: %d bytes, under %d" % (name, size, run_study.MAX_PNG_BYTES))
    try:
        w, h = run_study.png_info(path)[:2]
        colours, ink = run_study.png_ink(path)
    except ValueError as e:
        check(False, str(e))
        return
    check(w >= 400 and h >= 400, "%s: %dx%d pixels, at least 400x400" % (name, w, h))
    # a map or a plot: many colours, and more than lines on a white page
    check(colours >= 16, "%s: %d distinct pixel values, at least 16" % (name, colours))
    check(ink >= 0.02, "%s: %.1f%% of the pixels differ from the background, at least 2%%" % (name, 100 * ink))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--no-png", action="store_true")
    args = ap.parse_args()
    out = os.path.abspath(args.out)
    ext = ".svg" if args.no_png else ".png"
    if os.path.realpath(out) == os.path.realpath(os.path.join(run_study.REPO, "benchmark", "results")):
        sys.exit("--out must not be the published results: they would be replaced by the quick run's")
    # outputs of an earlier run must not satisfy the checks
    if os.path.isdir(out):
        for name in os.listdir(out):
            if name.startswith("study_"):
                os.remove(os.path.join(out, name))

    t0 = time.time()
    study = [sys.executable, os.path.join(HERE, "run_study.py")]
    p = run(study + ["--quick", "--no-build", "--build", args.build, "--out", out])
    if not check(p.returncode == 0, "run_study.py --quick exits 0 (got %d)" % p.returncode):
        return 1
    print("quick study: %.1f s" % (time.time() - t0), flush=True)
    check("ours certified: 12 / 12" in p.stdout, "run_study.py prints 'ours certified: 12 / 12'")

    # ---- the layout
    pictures = ["study_time_vs_size" + ext] + [GALLERY_STEM + s + ext for s in ("_tutte", "_repaired", "_tutte_full")]
    expected = {"study_summary.md", "study_methods.csv", "study_runs.csv.gz", "study_meta.txt", "study_gallery.csv",
                "study_tutte_failures.tsv", "study_log.txt"} | set(pictures)
    found = set(os.listdir(out))
    check(found == expected, "files written: %s (missing %s, unexpected %s)" % (
        sorted(found), sorted(expected - found), sorted(found - expected)))
    for name in pictures:
        check_picture(os.path.join(out, name), ext)

    # ---- the runs
    check(run_study.RUNS_COLUMNS == RUNS_COLUMNS, "run_study.py reads the driver's columns")
    cols, rows = read_csv(os.path.join(out, "study_runs.csv.gz"))
    check(cols == RUNS_COLUMNS, "study_runs.csv.gz columns: %s" % cols)
    key = lambda r: (r["kind"], r["mesh"], r["seed"])  # noqa: E731
    check({key(r) for r in rows} == INPUTS, "inputs: %s" % sorted({key(r) for r in rows}))
    ran = [r for r in rows if r["status"] != "SKIPPED"]
    for m, n in RUNS.items():
        got = sum(r["method"] == m for r in ran)
        check(got == n, "%s: %d runs, %d expected" % (m, got, n))
    ours = [r for r in ran if r["method"] in OURS]
    check(len(ours) == 6 + 6 + 4 * 2, "runs of ours: %d, 20 expected" % len(ours))
    for r in ours:
        check(r["status"] == "OK" and r["certified_valid"] == "1",
              "%s on %s seed %s: status %s, certified_valid %s" % (r["method"], r["mesh"], r["seed"], r["status"], r["certified_valid"]))
    for r in rows:
        if r["method"] != "tutte_double":
            continue
        k = key(r)
        fd = (int(r["tutte_flipped"]), int(r["tutte_degenerate"]))
        check(fd == FAILING.get(k, (0, 0)), "double Tutte on %s: (flipped, degenerate) %s, expected %s" % (k, fd, FAILING.get(k, (0, 0))))
    for m in ("tutte_double", "cgal_barycentric", "cgal_mvc", "tutte_mpfr128_rounded", "tutte_mpfr256_rounded"):
        bad = {key(r) for r in ran if r["method"] == m and r["status"] == "OK" and r["certified_valid"] == "0"}
        check(bad == set(FAILING), "%s returns OK with an invalid map on %s, expected %s" % (m, sorted(bad), sorted(FAILING)))
    for r in ran:
        if r["method"] == "cgal_barycentric" and key(r) in FAILING:
            n = int(r["flipped"]) + int(r["degenerate"])
            check(n == CGAL_BARYCENTRIC_INVALID[key(r)], "cgal_barycentric on %s: %d invalid faces, expected %d" % (
                key(r), n, CGAL_BARYCENTRIC_INVALID[key(r)]))
    for m in ("tutte_mpfr128", "tutte_mpfr256"):
        ok = {key(r) for r in ran if r["method"] == m and r["certified_valid"] == "1"}
        check(set(FAILING) <= ok, "%s is certified valid on the failing runs" % m)

    tsv = open(os.path.join(out, "study_tutte_failures.tsv")).read()
    check(tsv == "mesh\tseed\tvertices\tflipped\tdegenerate\nbull.off\t0\t6200\t35\t49\ndino.off\t8\t3916\t1836\t394\n",
          "study_tutte_failures.tsv lists bull.off seed 0 and dino.off seed 8: %r" % tsv)

    # ---- the per-method table
    cols, methods = read_csv(os.path.join(out, "study_methods.csv"))
    check(cols == METHODS_COLUMNS, "study_methods.csv columns: %s" % cols)
    by_method = {t["method"]: t for t in methods}
    for m, n in RUNS.items():
        t = by_method.get(m)
        if not check(t is not None, "study_methods.csv has %s" % m):
            continue
        rs = [r for r in ran if r["method"] == m]
        check(int(t["runs"]) == n, "study_methods.csv: %s runs %s" % (m, t["runs"]))
        check(int(t["certified_valid"]) == sum(r["certified_valid"] == "1" for r in rs),
              "study_methods.csv: %s certified_valid %s" % (m, t["certified_valid"]))
        expected_bad = 2 if m in ("tutte_double", "cgal_barycentric", "cgal_mvc") else 0
        check(int(t["returned_ok_invalid"]) == expected_bad and int(t["failing_returned_ok_invalid"]) == expected_bad,
              "study_methods.csv: %s returned_ok_invalid %s, expected %d" % (m, t["returned_ok_invalid"], expected_bad))
        check(int(t["failing_runs"]) == sum(key(r) in FAILING for r in rs), "study_methods.csv: %s failing_runs" % m)

    # ---- the gallery
    cols, gallery = read_csv(os.path.join(out, "study_gallery.csv"))
    check(cols == GALLERY_COLUMNS, "study_gallery.csv columns: %s" % cols)
    if check(len(gallery) == 1, "one gallery run (got %d)" % len(gallery)):
        g = gallery[0]
        check((g["mesh"], g["seed"], g["tutte_invalid_faces"]) == ("dino.off", "8", "2230"),
              "gallery: %s seed %s, %s invalid faces; expected dino.off seed 8, 2230" % (g["mesh"], g["seed"], g["tutte_invalid_faces"]))
        check(g["repaired_status"] == "OK" and g["repaired_valid"] == "1", "gallery: repaired map OK and certified")
        check([g["tutte_zoom_picture"], g["repaired_zoom_picture"], g["tutte_full_picture"]] == pictures[1:],
              "gallery pictures: %s" % [g["tutte_zoom_picture"], g["repaired_zoom_picture"], g["tutte_full_picture"]])

    # ---- the summary
    summary = open(os.path.join(out, "study_summary.md"), encoding="utf-8").read()
    for line in ("## Robustness: every run", "## On the 2 corpus runs where double Tutte fails",
                 "## Table 1: the failing runs (paper-style)", "of which **2 fail** with double Tutte",
                 "| Progressive_embedding_parameterizer_3 `pe_parameterizer` | 6 | 6 (100.0%) | 0 |",
                 "| CGAL Barycentric_mapping_parameterizer_3 `cgal_barycentric` | 6 | 4 (66.7%) | **2** |",
                 "| CGAL Mean_value_coordinates_parameterizer_3 `cgal_mvc` | 6 | 4 (66.7%) | **2** |",
                 "| bull.off | 0 | 6200 | 12395 | 84 | 35 |", "| dino.off | 8 | 3916 | 7827 | 2230 | 1836 |",
                 " | OK, **157** |", " | OK, **1632** |"):
        check(line in summary, "study_summary.md contains %r" % line)
    for name in pictures:
        check("](%s)" % name in summary, "study_summary.md shows %s" % name)
    if ext == ".png":
        check(".svg)" not in summary, "study_summary.md links no SVG")

    # ---- the tables and the gallery again from the published files: the same bytes
    before = {n: open(os.path.join(out, n), "rb").read()
              for n in ["study_summary.md", "study_methods.csv", "study_gallery.csv", "study_runs.csv.gz",
                        "study_tutte_failures.tsv"] + pictures[1:]}
    p = run(study + ["--report-only", "--redraw-gallery", "--no-build", "--build", args.build, "--out", out])
    check(p.returncode == 0, "run_study.py --report-only --redraw-gallery exits 0 (got %d)" % p.returncode)
    for n, data in before.items():
        check(os.path.exists(os.path.join(out, n)) and open(os.path.join(out, n), "rb").read() == data,
              "--report-only --redraw-gallery writes the same %s" % n)
    check(set(os.listdir(out)) == expected, "--report-only keeps the layout")
    check_picture(os.path.join(out, "study_time_vs_size" + ext), ext)

    print("comparison_study_quick: %d failed check(s), %.1f s" % (len(failures), time.time() - t0))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
