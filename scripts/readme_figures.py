#!/usr/bin/env python3
"""The result tables and quoted figures of README.md and of the user manual
(doc/Progressive_embedding/Progressive_embedding.txt), generated and checked from the measured data in
benchmark/results/*.csv. Python 3, standard library only.

    python3 scripts/readme_figures.py           # rewrite the tables and figures in place
    python3 scripts/readme_figures.py --check   # rewrite nothing; list every disagreement, exit 1 if any

Two mechanisms:

* Generated blocks: the text between
      <!-- begin generated: NAME from benchmark/results/FILE.csv[, benchmark/results/FILE2.csv] -->
      <!-- end generated: NAME -->
  is written by the function registered under NAME in BLOCKS (its sources must be the ones the
  marker names). Doxygen drops HTML comments, so the same markers work in the manual.
* Rules: a figure quoted in prose is found by a template (RULES), literal text with {name} fields,
  and compared with the text the rule computes from its CSV. A field matches a run of non-space
  characters (the longest that lets the rest match), {name:REGEX} what REGEX matches; a space matches
  any white space, line breaks included. The template must match exactly once: a sentence reworded so
  that it no longer matches is reported too, and the rule is then updated with it.

Medians are true medians (statistics.median: the mean of the two middle values for an even count).
After a benchmark run has rewritten its CSV, run this script without --check and review the diff.
"""

import argparse
import csv
import importlib.util
import math
import os
import re
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = "benchmark/results"
README = "README.md"
MANUAL = "doc/Progressive_embedding/Progressive_embedding.txt"
STRIPE_MD = RESULTS + "/stripe_embedding.md"  # the side-by-side table of Stripe Embedding, with its set-up
WORDS = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight", 9: "nine", 10: "ten"}


# ---------------------------------------------------------------------------------------------
# the data

class Data:
    """The files of benchmark/results, each read once."""

    def __init__(self, root):
        self.root = root
        self.dir = os.path.join(root, RESULTS)
        self.cache = {}

    def rows(self, name):
        """The rows of a CSV file as dicts (lines starting with '#' are comments)."""
        if name not in self.cache:
            with open(os.path.join(self.dir, name), newline="") as f:
                self.cache[name] = list(csv.DictReader(line for line in f if not line.startswith("#")))
        return self.cache[name]

    def comments(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return [line[1:].strip() for line in f if line.startswith("#")]

    def md_header(self, name, pattern):
        """A field of the header a driver writes into its Markdown table (the run's date, load, ...)."""
        with open(os.path.join(self.dir, name)) as f:
            m = re.search(pattern, f.read())
        if not m:
            raise ValueError("%s: no match for %r" % (name, pattern))
        return m.group(1)

    def study(self):
        """The rows of study_runs.csv.gz as the study's own script reads them, and its per-run index."""
        if "study" not in self.cache:
            path = os.path.join(self.root, "benchmark", "Progressive_embedding", "run_study.py")
            sys.dont_write_bytecode = True  # nothing written into the source tree
            spec = importlib.util.spec_from_file_location("run_study", path)
            run_study = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(run_study)
            rows = run_study.read_rows(self.dir)
            by_key = {}
            for r in rows:
                by_key.setdefault(r["key"], {})[r["method"]] = r
            self.cache["study"] = (run_study, rows, by_key, run_study.failing_keys(rows))
        return self.cache["study"]


def col(rows, name, kind=float):
    return [kind(r[name]) for r in rows]


def where(rows, **kw):
    return [r for r in rows if all(r[k] == v for k, v in kw.items())]


def one(rows, **kw):
    rs = where(rows, **kw)
    if len(rs) != 1:
        raise ValueError("%d rows for %s" % (len(rs), kw))
    return rs[0]


median = statistics.median


# ---------------------------------------------------------------------------------------------
# number formats

def sig(x, n=3):
    """x with n significant digits, trailing zeros kept, no exponent below 10^n (0.10, 0.0985, 28.8)."""
    x = float(x)
    if x == 0:
        return "0"
    if abs(x) >= 10 ** n:
        return "%d" % round(x)
    s = "%#.*g" % (n, x)
    if "e" in s:
        return sci(x, n)
    return s.rstrip(".")


def sci(x, n=2):
    """1.6e13, 2.5e10."""
    m, e = ("%.*e" % (n - 1, float(x))).split("e")
    return "%se%d" % (m, int(e))


def grouped(x, n=2):
    """n significant digits with thousands separators: 1,100 and 11,000."""
    x = float(x)
    digits = n - 1 - int(math.floor(math.log10(abs(x))))
    return "{:,}".format(int(round(x, digits))) if digits <= 0 else sig(x, n)


def kilo(n, digits=3):
    """1024 -> 1k, 17492 -> 17.5k, 23978 -> 24k, 1048576 -> 1M."""
    n = float(n)
    for div, unit in ((1e6, "M"), (1e3, "k")):
        if n >= div:
            s = "%.*g" % (digits, n / div)
            return s + unit
    return "%d" % n


def rng(a, b, fmt=sig, sep="–"):
    fa, fb = fmt(a), fmt(b)
    return fa if fa == fb else fa + sep + fb


def count(x):
    """A count or the median of counts: 4, 17.5."""
    return "%g" % float(x)


def integer(x):
    return "%d" % round(float(x))


def word(n):
    return WORDS.get(n, str(n))


def mesh_name(mesh):
    return mesh[:-4] if mesh.endswith(".off") else mesh


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["|" + "|".join(" %s " % c if str(c) else " " for c in r) + "|" for r in rows]
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# generated blocks: name -> (file, sources, function(data) -> text)

BLOCKS = {}


def block(name, path, *sources, inline=False):
    """A Markdown table stands apart from the text, between blank lines; an inline block continues its
    paragraph (or list item) on the lines of its markers."""
    def register(f):
        def text(d):
            return f(d) if inline else "\n" + f(d) + "\n"
        BLOCKS[name] = (path, tuple(RESULTS + "/" + s for s in sources), text)
        return f
    return register


@block("repair_speed", README, "progressive_embedding.csv")
def _(d):
    rows = d.rows("progressive_embedding.csv")
    corpus = where(rows, kind="corpus")
    dino = one(corpus, mesh="dino.off", seed="8")
    grids = [r for r in where(rows, kind="random-init") if r["mesh"].startswith("grid")]

    def spread(values, fmt):
        return "%s (%s)" % (fmt(median(values)), rng(min(values), max(values), fmt))
    out = [["dino.off seed 8 (%s flipped, %s degenerate)" % (dino["tutte_flipped"], dino["tutte_degenerate"]),
            dino["vertices"], sig(dino["pe_seconds"]), sig(dino["tutte_seconds"]), sig(dino["ratio_pe_tutte"]) + "×"],
           ["corpus, %d runs: median (range)" % len(corpus), rng(*(f(col(corpus, "vertices", int)) for f in (min, max)), fmt=str),
            spread(col(corpus, "pe_seconds"), sig), spread(col(corpus, "tutte_seconds"), sig),
            "%s× (%s×)" % (sig(median(col(corpus, "ratio_pe_tutte"))),
                           rng(min(col(corpus, "ratio_pe_tutte")), max(col(corpus, "ratio_pe_tutte"))))]]
    for g in grids:
        side = g["mesh"][len("grid"):].replace("x", "×")
        out.append(["random init, grid " + side, g["vertices"], sig(g["pe_seconds"]), "", ""])
    return table(["input", "vertices", "progressive embedding (s)", "Tutte solve (s)", "PE / Tutte"], out)


@block("large_meshes", README, "large_meshes.csv")
def _(d):
    rows = d.rows("large_meshes.csv")
    grids = [r for r in rows if r["case"].startswith("grid:") and r["blas"] != "reference"]
    out = []
    previous = None  # the default solver's row of the previous size
    for n in sorted({int(r["vertices"]) for r in grids}):
        rs = [r for r in grids if int(r["vertices"]) == n]

        def get(solver):
            got = [r for r in rs if r["solver"] == solver and r["status"] == "OK"]
            return got[0] if got else None
        ldlt, default = get("cholmod"), get("default")
        side = rs[0]["case"][len("grid:"):]
        growth = ""
        if default and previous:
            growth = sig((float(default["tutte_s"]) / float(previous["tutte_s"]))
                         ** (1 / math.log2(n / int(previous["vertices"]))), 3) + "×"
        previous = default
        out.append(["%s×%s" % (side, side), n,
                    sig(ldlt["tutte_s"]) if ldlt else "", sig(default["tutte_s"]) if default else "",
                    sig(float(ldlt["tutte_s"]) / float(default["tutte_s"]), 2) + "×" if ldlt and default else "",
                    growth, sig(default["certificate_s"]) if default else "",
                    integer(default["peak_rss_mb"]) if default else "",
                    ("yes" if default["valid"] == "true" else "**no**") if default else ""])
    return table(["grid disk", "vertices", "Tutte, CHOLMOD: the former default from 100,000 unknowns (s)",
                  "Tutte, default solver (s)", "speed-up",
                  "default: growth per doubling", "certificate (s)", "peak MB", "certified"], out)


@block("large_meshes_file", README, "large_meshes.csv", inline=True)
def _(d):
    r = [r for r in d.rows("large_meshes.csv") if not r["case"].startswith("grid:")][0]
    return ("read %s s, Tutte map %s s, certificate %s s, OBJ written %s s: **%s s** in all, peak %s MB"
            % (sig(r["make_s"]), sig(r["tutte_s"]), sig(r["certificate_s"]), sig(r["write_s"]), sig(r["total_s"]),
               integer(r["peak_rss_mb"])))


@block("large_meshes_pe", README, "large_meshes_pe.csv", inline=True)
def _(d):
    rows = d.rows("large_meshes_pe.csv")
    def med(hp, key):
        return statistics.median(float(r[key]) for r in rows if r["huge_pages"] == hp)
    return ("**%s s** (median of %d runs, peak %s MB; %s s with `PE_HUGE_PAGES=1`)"
            % (sig(med("no", "wall_s")), len([r for r in rows if r["huge_pages"] == "no"]),
               integer(med("no", "peak_mb")), sig(med("yes", "wall_s"))))


@block("optimizer_scale", README, "optimizer_scale.csv")
def _(d):
    rows = d.rows("optimizer_scale.csv")
    progs = list(dict.fromkeys(r["program"] for r in rows))
    ours, base = progs[0], progs[1]

    def stats(prog, grid):
        rs = [r for r in rows if r["program"] == prog and r["grid"] == grid]
        it = statistics.median(float(r["iterations"]) for r in rs)
        sec = statistics.median(float(r["seconds_optimization"]) for r in rs)
        return dict(it=it, sec=sec, per=sec / it, peak=statistics.median(float(r["peak_mb"]) for r in rs),
                    e=statistics.median(float(r["energy_after"]) for r in rs), n=len(rs),
                    conv=all(r["converged"] == "True" for r in rs), valid=all(r["valid"] == "True" for r in rs),
                    vertices=int(rs[0]["vertices"]))
    out = []
    for g in dict.fromkeys(r["grid"] for r in rows):
        a, b = stats(ours, g), stats(base, g)
        out.append(["%s×%s" % (g, g), a["vertices"], a["n"], "%g (%g)" % (a["it"], b["it"]),
                    "yes" if a["conv"] else "**no**", sig(a["e"], 5), "%s (%s)" % (sig(a["sec"]), sig(b["sec"])),
                    "%s (%s)" % (sig(a["per"]), sig(b["per"])), sig(a["sec"] / b["sec"], 2) + "×",
                    "%s (%s)" % (integer(a["peak"]), integer(b["peak"])), "yes" if a["valid"] else "**no**"])
    return table(["grid disk, random init repaired", "vertices", "runs", "iterations (before)", "stopping rule met",
                  "mean sym. Dirichlet", "optimization s (before)", "s per iteration (before)", "time ratio",
                  "peak MB (before)", "certified"], out)


@block("optimizer_budget", README, "optimizer_scale_budget.csv", "optimizer_scale.csv", inline=True)
def _(d):
    r = d.rows("optimizer_scale_budget.csv")[0]
    converged = [x for x in d.rows("optimizer_scale.csv") if x["grid"] == r["grid"] and x["commit"] == r["commit"]]
    full = statistics.median(float(x["energy_after"]) for x in converged)
    e = float(r["energy_after"])
    return ("`%s` on the %s×%s grid stops after %s iterations and %s s (the budget is checked between iterations), "
            "status `%s`, %s, mean %s: %.2f%% above the converged %s"
            % (r["command"].replace("un.obj out.obj --json ", "IN OUT "), r["grid"], r["grid"], r["iterations"],
               sig(r["seconds_optimization"]), r["status"], "certified" if r["valid"] == "True" else "**not certified**",
               sig(e, 5), 100 * (e / full - 1), sig(full, 5)))


@block("slim_scale", README, "slim_scale.csv", inline=True)
def _(d):
    parts = []
    for r in d.rows("slim_scale.csv"):
        if r["converged"] == "yes":
            slim = "converged in %s iterations and %s s, mean %s" % (r["iterations"], sig(r["seconds_total"]), sig(r["mean_energy_3d"], 5))
        else:
            slim = "%s iteration%s in %s s (a %s s budget), mean %s" % (r["iterations"], "" if r["iterations"] == "1" else "s",
                                                                       sig(r["seconds_total"]), r["budget_s"], sig(r["mean_energy_3d"], 5))
        if r["peak_mb"]:
            slim += ", peak %s MB" % integer(r["peak_mb"])
        parts.append("%s vertices: SLIM %s; `pe` converged in %s s, mean %s" % (
            "{:,}".format(int(r["vertices"])), slim, sig(r["comparison_pe_seconds"]), sig(r["comparison_pe_mean_energy_3d"], 5)))
    return "; ".join(parts)


def stripe_table(d):
    rows = d.rows("stripe_embedding.csv")
    se, pe = "Stripe Embedding (cinolib)", "Progressive_embedding"
    stages = "large_meshes_benchmark"

    def pick(case, program, nt, stage=False):
        return [r for r in rows if r["case"] == case and r["program"] == program and r["number_type"] == nt
                and (r["command"].startswith(stages) == stage)]

    def med(rs, key):
        return median(col(rs, key))

    out = []
    # (case, label, ours, theirs): ours as (number type, stages?), theirs as Stripe's number type
    pairs = [("grid512", "grid disk 512×512", ("double", True), "mpfr"),
             ("grid1024", "grid disk 1024×1024", ("double", True), "mpfr"),
             ("thingi-dino-8", "dino seed 8 (Tutte fails)", ("exact", False), "rational"),
             ("thingi-dino-8", "dino seed 8 (Tutte fails)", ("mpfr:256", False), "mpfr:256"),
             ("thingi-man-4", "man seed 4 (Tutte fails)", ("exact", False), "rational"),
             ("thingi-man-4", "man seed 4 (Tutte fails)", ("mpfr:256", False), "mpfr:256"),
             ("thingi-dino-8", "dino seed 8 (Tutte fails)", ("double", False), "double"),
             ("thingi-man-4", "man seed 4 (Tutte fails)", ("double", False), "double")]
    for case, label, (nt, stage), theirs in pairs:
        o, t, td = pick(case, pe, nt, stage), pick(case, se, theirs), pick(case, se, "double")
        if not o or not t:
            continue
        ours_ok = all(r["status"] in ("0", "1") and r["certified"] in ("yes", "before-rounding") for r in o)
        oursname = "double (Tutte + certificate)" if stage else (nt if nt != "double" else "double (Tutte, repair)")
        whole = pick(case, pe, nt, False)  # the whole `pe` process (for the grids: `pe embed`, not the stages)
        out.append([label, o[0]["vertices"], "%s: %s s" % (oursname, sig(med(o, "own_timer_s"), 3)),
                    "%s: %s s" % (theirs, sig(med(t, "own_timer_s"), 3)),
                    sig(med(o, "own_timer_s") / med(t, "own_timer_s"), 2) + "×",
                    "yes" if ours_ok else "no",
                    count(median(col(td, "flipped_double", int))) if td else "",
                    "%s / %s" % (sig(med(whole, "wall_s"), 3), sig(med(t, "wall_s"), 3))])
    return table(["input", "vertices", "ours (s)", "Stripe Embedding (s)", "ours / theirs",
                  "ours certified", "Stripe's double map: flipped faces",
                  "whole process, wall clock: ours / theirs (s)"], out)


block("stripe_embedding", README, "stripe_embedding.csv")(stripe_table)
block("stripe_embedding_results", STRIPE_MD, "stripe_embedding.csv")(stripe_table)


@block("constrained_3", README, "constrained_embedding.csv")
def _(d):
    rows = d.rows("constrained_embedding.csv")
    out = []
    vertices = {r["mesh"]: int(r["vertices_in"]) for r in rows}
    for m in sorted(vertices, key=vertices.get):
        rs = where(rows, mesh=m)
        good = [r for r in rs if r["status"] == "OK" and r["certified"] == "1" and r["constraint_error"] == "0"]
        out.append([mesh_name(m) + (" (cut)" if rs[0]["kind"] == "closed" else ""), rs[0]["vertices_in"],
                    "%d/%d" % (len(good), len(rs)), sig(median(col(rs, "s_certified_map")), 2),
                    count(median(col(rs, "steiner"))), sig(median(col(rs, "added_percent")), 2) + "%"])
    return table(["mesh", "vertices", "certified, constraints bit-exact", "time to the certified map (s)",
                  "Steiner vertices", "vertices added"], out)


@block("study_methods", README, "study_methods.csv", "study_runs.csv.gz")
def _(d):
    m = {r["method"]: r for r in d.rows("study_methods.csv")}
    _, rows, _, _ = d.study()
    gmpq = max(r["interior_vertices"] for r in rows if r["method"] == "tutte_gmpq" and r["status"] == "OK")

    def t(method):
        return "%.4f" % float(m[method]["median_seconds"])

    def row(label, method, bold_invalid=False, bold_valid=False, time=None):
        r = m[method]
        invalid = r["returned_ok_invalid"]
        return [label, r["runs"], "**%s**" % r["certified_valid"] if bold_valid else r["certified_valid"],
                "**%s**" % invalid if bold_invalid or bold_valid else invalid, t(method) if time is None else time]
    out = [row("CGAL `Barycentric_mapping_parameterizer_3`", "cgal_barycentric", bold_invalid=True),
           row("CGAL `Mean_value_coordinates_parameterizer_3`", "cgal_mvc", bold_invalid=True),
           row("`tutte_embedding`, double", "tutte_double")]
    same = all(m["tutte_mpfr128" + s][c] == m["tutte_mpfr256" + s][c]
               for s in ("", "_rounded") for c in ("runs", "certified_valid", "returned_ok_invalid"))
    if same:
        times = sorted({t("tutte_mpfr128"), t("tutte_mpfr256")})
        out += [row("`tutte_embedding`, MPFR 128/256 bits", "tutte_mpfr128", time=" / ".join(times)),
                row("&nbsp;&nbsp;rounded to double", "tutte_mpfr128_rounded", time="")]
    else:
        for b in ("128", "256"):
            out += [row("`tutte_embedding`, MPFR %s bits" % b, "tutte_mpfr" + b),
                    row("&nbsp;&nbsp;rounded to double", "tutte_mpfr%s_rounded" % b, time="")]
    out += [row("`tutte_embedding`, exact Gmpq (≤ %s interior vertices)" % kilo(gmpq, 2), "tutte_gmpq"),
            row("`progressive_embedding` (from the double Tutte map / random init)", "pe_double", bold_valid=True),
            row("`Progressive_embedding_parameterizer_3`", "pe_parameterizer", bold_valid=True)]
    return table(["method", "runs", "certified valid", "returned OK while invalid", "median time (s)"], out)


@block("failing_runs", README, "study_runs.csv.gz")
def _(d):
    _, _, by_key, failing = d.study()
    out = []
    for mesh in sorted({k[1] for k in failing}):
        ks = [k for k in failing if k[1] == mesh]
        td = [by_key[k]["tutte_double"] for k in ks]
        invalid = [int(r["flipped"]) + int(r["degenerate"]) for r in td]
        flipped = [int(r["flipped"]) for r in td]

        def t(method):
            return sig(median(by_key[k][method]["t"] for k in ks), 2)
        out.append([mesh_name(mesh), td[0]["vertices"], td[0]["faces"], len(ks), rng(min(invalid), max(invalid), str),
                    rng(min(flipped), max(flipped), str), "%s / %s" % (t("pe_double"), t("pe_parameterizer")),
                    t("cgal_barycentric")])
    return table(["mesh", "#V", "#F", "failing runs", "#invalid", "#flipped", "our time: PE / parameterizer",
                  "CGAL Barycentric"], out)


@block("study_gallery", README, "study_gallery.csv")
def _(d):
    g = d.rows("study_gallery.csv")
    pic = RESULTS + "/"
    first = g[0]
    lines = [table(["%s seed %s, Tutte in double (around the invalid faces)" % (mesh_name(first["mesh"]), first["seed"]),
                    "after progressive embedding"],
                   [["![](%s%s)" % (pic, first["tutte_zoom_picture"]), "![](%s%s)" % (pic, first["repaired_zoom_picture"])]]),
             "", "The other %s of the %s worst corpus runs, before and after:" % (word(len(g) - 1), word(len(g)))]
    for i, r in enumerate(g[1:]):
        lines.append("%s seed %s ([Tutte](%s%s), [repaired](%s%s))%s" % (
            r["mesh"], r["seed"], pic, r["tutte_zoom_picture"], pic, r["repaired_zoom_picture"], "," if i < len(g) - 2 else ";"))
    lines.append("the whole %s seed %s map: [full size](%s%s)." % (mesh_name(first["mesh"]), first["seed"], pic,
                                                                   first["tutte_full_picture"]))
    return "\n".join(lines)


def coarsening_effect(d):
    """The optimized energy with the coarsening against without it, in %, per run (mesh, constraints), the
    largest difference last."""
    opt, keep = d.rows("constrained_embedding_optimized.csv"), d.rows("constrained_embedding_optimized_no_coarsen.csv")
    if [(r["mesh"], r["constraints"]) for r in opt] != [(r["mesh"], r["constraints"]) for r in keep]:
        raise ValueError("the runs with and without the coarsening differ")
    return sorted(((100 * (float(a["mean_sd_after"]) / float(b["mean_sd_after"]) - 1), a) for a, b in zip(opt, keep)),
                  key=lambda x: abs(x[0]))


@block("manual_coarsening", MANUAL, "constrained_embedding_optimized.csv",
       "constrained_embedding_optimized_no_coarsen.csv", "constrained_coarsening_winding.csv", inline=True)
def _(d):
    opt = d.rows("constrained_embedding_optimized.csv")
    inserted = sum(col(opt, "steiner_inserted", int))
    removed = sum(col(opt, "steiner_removed", int))
    diff = [x for x, _ in coarsening_effect(d)]
    within = math.ceil(abs(diff[-2]) * 10) / 10
    last = "" if abs(diff[-1]) <= within else "; one run %s%% %s" % (sig(abs(diff[-1]), 2), "lower" if diff[-1] < 0 else "higher")
    wind = d.rows("constrained_coarsening_winding.csv")
    share = [100 * int(r["steiner_removed"]) / int(r["steiner_inserted"]) for r in wind]
    return ("On the %s meshes of `%s/constrained_embedding_optimized.csv` (%s constraints,\n"
            "optimized) it removes %d of the %d vertices inserted, the energies within %s%% of the runs without\n"
            "it (`constrained_embedding_optimized_no_coarsen.csv`%s); on winding refinements\n"
            "(%s random targets, not optimized: `constrained_coarsening_winding.csv`) it removes %s%% to %s%% of\n"
            "them, which the map still needs."
            % (word(len({r["mesh"] for r in opt})), RESULTS, " and ".join(sorted({r["constraints"] for r in opt}, key=int)),
               removed, inserted, sig(within, 1), last, "/".join(sorted({r["constraints"] for r in wind})),
               sig(min(share), 1), sig(max(share), 2)))


@block("manual_optimization", MANUAL, "optimize_quality.csv", "optimize_stability.csv", inline=True)
def _(d):
    q, s = d.rows("optimize_quality.csv"), d.rows("optimize_stability.csv")
    it = col(q, "iterations", int)
    imp = col(s, "improvement_percent")
    return ("On the repaired Tutte maps of the %d failing corpus runs (`%s/optimize_quality.csv`) this takes\n"
            "%d to %d iterations (median %s), and ten times more iterations lower the mean by %s%% (median),\n"
            "%s%% at most (`optimize_stability.csv`, measured before the Newton steps reused their factorization);" % (
                len(q), RESULTS, min(it), max(it), sig(median(it)),
                                                         sig(median(imp), 2), sig(max(imp), 2)))


# ---------------------------------------------------------------------------------------------
# rules: figures in prose, (file, template, sources, function(data) -> {field: text, "_errors": [...]})

RULES = []


def rule(path, template, *sources):
    def register(f):
        RULES.append((path, template, tuple(RESULTS + "/" + s for s in sources), f))
        return f
    return register


def _pe(d):
    return d.rows("progressive_embedding.csv")


for _template in ("double Tutte map: {f} flipped, {d} degenerate faces |",
                  "1. the double Tutte map: {f} flipped and {d} degenerate faces"):
    @rule(README, _template, "progressive_embedding.csv")
    def _(d):
        r = one(_pe(d), kind="corpus", mesh="dino.off", seed="8")
        return dict(f=r["tutte_flipped"], d=r["tutte_degenerate"])


@rule(README, "flipped or degenerate triangles on about {p}% of real meshes", "study_runs.csv.gz")
def _(d):
    _, _, by_key, failing = d.study()
    return dict(p=integer(100 * len(failing) / len([k for k in by_key if k[0] == "corpus"])))


@rule(README, "(a {n}-vertex self-overlapping spiral in {t} s and {mb} MB, simple polygons of {n2} vertices "
      "in under {b} s", "polygon_triangulation.csv")
def _(d):
    rows = d.rows("polygon_triangulation.csv")
    spiral = max(where(rows, shape="spiral"), key=lambda r: int(r["vertices"]))
    simple = [r for r in rows if r["shape"] in ("convex", "star") and r["vertices"] == spiral["vertices"]]
    return dict(n=spiral["vertices"], t=sig(spiral["seconds"], 2), mb=integer(spiral["peak_rss_mb"]), n2=spiral["vertices"],
                b=sig(10 ** math.ceil(math.log10(max(col(simple, "seconds")))), 1))


@rule(README, "all {n} runs of the Tutte-failure corpus (libcgal-demo meshes on which double Tutte flips up to {f} "
      "faces), the {k} disks of libcgal-demo and grid disks of {lo} to {hi} vertices (random initialization) end "
      "certified valid: **{c} / {t}**", "progressive_embedding.csv")
def _(d):
    rows = _pe(d)
    corpus, rand = where(rows, kind="corpus"), where(rows, kind="random-init")
    grids = [r for r in rand if r["mesh"].startswith("grid")]
    return dict(n=len(corpus), f=max(col(corpus, "tutte_flipped", int)), k=len(rand) - len(grids),
                lo=kilo(min(col(grids, "vertices", int)), 1), hi=kilo(max(col(grids, "vertices", int)), 1),
                c=sum(r["status"] == "OK" and r["certified"] == "1" for r in rows), t=len(rows))


@rule(README, "Random-init time grows by {r}× per doubling of the vertex count from {lo} to {hi}; the {n}-vertex grid "
      "peaks at {mb} MB.", "progressive_embedding.csv")
def _(d):
    grids = [r for r in where(_pe(d), kind="random-init") if r["mesh"].startswith("grid")]
    per_doubling = [(float(b["pe_seconds"]) / float(a["pe_seconds"])) ** (1 / math.log2(int(b["vertices"]) / int(a["vertices"])))
                    for a, b in zip(grids, grids[1:])]
    return dict(r=rng(min(per_doubling), max(per_doubling)), lo=kilo(grids[0]["vertices"], 1),
                hi=kilo(grids[-1]["vertices"], 1), n=kilo(grids[-1]["vertices"], 1), mb=integer(grids[-1]["peak_rss_mb"]))


@rule(README, "(mean symmetric Dirichlet {a} to {b}), the default `optimize_distortion()` converges (`OK`) on "
      "**{ok} / {n}** runs, certified, border bit-exact, after {it} iterations (median {itm}), at a mean of "
      "**{mean}** (median {mm}; 4 is an isometry).", "optimize_quality.csv")
def _(d):
    q = d.rows("optimize_quality.csv")
    rep, it, mean = col(q, "repaired_mean"), col(q, "iterations", int), col(q, "mean")
    ok = [r for r in q if r["status"] == "OK" and r["valid"] == "1" and r["border_exact"] == "1"]
    return dict(a=sci(min(rep)), b=sci(max(rep)), ok=len(ok), n=len(q), it=rng(min(it), max(it), str), itm=sig(median(it)),
                mean=rng(min(mean), max(mean), integer), mm=integer(median(mean)))


@rule(README, "Ten times more iterations improve the mean by {med}% (median) and at most {mx}% ({mesh} seed {seed}) "
      "over all {n} runs", "optimize_stability.csv")
def _(d):
    s = d.rows("optimize_stability.csv")
    worst = max(s, key=lambda r: float(r["improvement_percent"]))
    return dict(med=sig(median(col(s, "improvement_percent")), 2), mx=sig(worst["improvement_percent"], 2),
                mesh=mesh_name(worst["mesh"]), seed=worst["seed"], n=len(s))


@rule(README, "bull seed 0 is a test ({a} → {b}).", "optimize_stability.csv")
def _(d):
    r = one(d.rows("optimize_stability.csv"), mesh="bull.off", seed="0")
    return dict(a=sig(r["mean"], 4), b=sig(r["mean_10x"], 4))


def _slim(d):
    return d.rows("slim_reference.csv")


@rule(README, "libigl's energy is twice the mean printed here): on dino seed 8 SLIM needs {t1} CPU s to reach {e1}, "
      "{t2} s to reach {e2} and is at {fin} after {tf} s, still decreasing; ours converges at {ours}.",
      "slim_reference.csv", "optimize_quality.csv")
def _(d):
    rows = _slim(d)
    head = where(rows, mesh="dino.off (headline)", seed="8")
    ratios = [float(r["libigl_energy"]) / float(r["mean_energy_3d"]) for r in rows if r["mean_energy_3d"]]
    errors = [] if all(abs(x - 2) < 1e-3 for x in ratios) else ["libigl_energy / mean_energy_3d is not 2 in every row"]
    below = [r for r in head if r["checkpoint"].startswith("below")]
    below.sort(key=lambda r: -int(r["checkpoint"][5:]))
    final = one(head, checkpoint="final")
    before = max((r for r in head if r["checkpoint"] != "final"), key=lambda r: float(r["cpu_seconds"]))
    if not float(before["mean_energy_3d"]) > float(final["mean_energy_3d"]):
        errors.append("SLIM's headline run is no longer decreasing at its end")
    ours = one(d.rows("optimize_quality.csv"), mesh="dino.off", seed="8")
    return dict(t1=sig(below[0]["cpu_seconds"], 2), e1=below[0]["checkpoint"][5:], t2=sig(below[-1]["cpu_seconds"], 3),
                e2=below[-1]["checkpoint"][5:], fin=sig(final["mean_energy_3d"]), tf=integer(final["cpu_seconds"]),
                ours=sig(ours["mean"]), _errors=errors)


@rule(README, "ours ends **at or below SLIM's best value on all {n} runs** that SLIM finished valid (SLIM budget {b1} "
      "CPU s, {b2} s on the {k} hardest); SLIM's map is invalid on {m1} seed {s1} from {t1} CPU s on, and on {m2} seeds "
      "{s2:[0-9, and]+?} in the longer runs (valid at {v} CPU s, invalid at {i} s;",
      "slim_reference.csv", "optimize_quality.csv")
def _(d):
    rows = _slim(d)
    finals = [r for r in rows if r["checkpoint"] == "final" and "(headline)" not in r["mesh"]]
    best = {}
    for r in finals:
        if r["valid"] == "True":
            key = (r["mesh"].split(" ")[0], r["seed"])
            best[key] = min(best.get(key, float("inf")), float(r["mean_energy_3d"]))
    ours = {(r["mesh"], r["seed"]): float(r["mean"]) for r in d.rows("optimize_quality.csv")}
    errors = ["ours above SLIM's best on %s seed %s" % k for k in best if ours[k] > best[k]]
    short = [r for r in finals if "(long)" not in r["mesh"]]
    long_ = [r for r in finals if "(long)" in r["mesh"]]
    bad_short = [r for r in short if r["valid"] != "True"]
    bad_long = [r for r in long_ if r["valid"] != "True"]
    if len(bad_short) != 1 or len({r["mesh"] for r in bad_long}) != 1:
        errors.append("the runs SLIM leaves invalid are not one corpus run and one mesh of the longer runs")

    def first_invalid(mesh, seed):
        cps = sorted(where(rows, mesh=mesh, seed=seed), key=lambda r: float(r["cpu_seconds"]))
        return next(r for r in cps if r["valid"] != "True"), [r for r in cps if r["valid"] == "True"][-1]
    s1 = bad_short[0]
    seeds = sorted((r["seed"] for r in bad_long), key=int)
    pairs = [first_invalid(r["mesh"], r["seed"]) for r in bad_long]
    valid_at = sorted({sig(v["cpu_seconds"], 2) for _, v in pairs})
    return dict(n=len(best), b1=integer(max(float(r["cpu_seconds"]) for r in short)),
                b2=integer(max(float(r["cpu_seconds"]) for r in long_)), k=word(len(long_)),
                m1=mesh_name(s1["mesh"]), s1=s1["seed"], t1=integer(first_invalid(s1["mesh"], s1["seed"])[0]["cpu_seconds"]),
                m2=mesh_name(bad_long[0]["mesh"].split(" ")[0]),
                s2=", ".join(seeds[:-1]) + " and " + seeds[-1] if len(seeds) > 1 else seeds[0],
                v="/".join(valid_at), i=rng(min(float(i["cpu_seconds"]) for i, _ in pairs),
                                            max(float(i["cpu_seconds"]) for i, _ in pairs), integer),
                _errors=errors)


def _generated(d, md):
    return d.md_header(md, r"Generated (\S+ \S+) UTC")


def _certified(rows):
    return sum(r["status"] == "OK" and r["certified"] == "1" and r["constraint_error"] == "0" for r in rows)


def _seeds(rows):
    s = sorted({int(r["seed"]) for r in rows})
    return "%d–%d" % (s[0], s[-1])


@rule(README, "`benchmark/regenerate_results.sh --constrained` runs it, {date:\\S+ \\S+} UTC, patches in parallel, each "
      "run {rep} times and the run of median time kept): the MatchMaker++ protocol, {k} random interior vertices pinned "
      "to (0,0), (1,0), (0,1) with the border on a square, seeds {s}, on {nd} disks and {nc} closed meshes cut open: "
      "**{ok} / {n} certified, every constraint bit-exact**.", "constrained_embedding.csv")
def _(d):
    rows = d.rows("constrained_embedding.csv")
    meshes = {r["mesh"]: r["kind"] for r in rows}
    return dict(date=_generated(d, "constrained_embedding.md"),
                rep=d.md_header("constrained_embedding.md", r"each run (\d+) times"),
                k="/".join(sorted({r["constraints"] for r in rows})), s=_seeds(rows),
                nd=sum(k == "disk" for k in meshes.values()), nc=sum(k == "closed" for k in meshes.values()),
                ok=_certified(rows), n=len(rows))


def _many(d):
    return d.rows("constrained_embedding_many.csv")


@rule(README, "With 10 and 50 constraints ([`constrained_embedding_many.md`](benchmark/results/constrained_embedding_many.md), "
      "{date:\\S+ \\S+} UTC, seeds {s}, {r} runs per row, each {rep} times and the run of median time kept, **{ok} / {n} "
      "certified, every constraint bit-exact**): targets at the vertices' places in the Tutte map (`layout`) are certified "
      "in {l10} runs with 10 and {l50} with 50 constraints, with few Steiner vertices (50 constraints on the {v}-vertex "
      "diplodocus: +{lo} to +{hi} vertices, certified in {t} s); moved by up to 0.01 (`jittered`): {j10} and {j50}; random "
      "targets: {r10} and {r50}.", "constrained_embedding_many.csv")
def _(d):
    rows = _many(d)
    sizes = {len(where(rows, constraints=k, targets=t)) for k in ("10", "50") for t in ("layout", "jittered", "random")}
    out = dict(date=_generated(d, "constrained_embedding_many.md"), s=_seeds(rows),
               r="/".join(str(x) for x in sorted(sizes)),
               rep=d.md_header("constrained_embedding_many.md", r"each run (\d+) times"), ok=_certified(rows), n=len(rows))
    for t, key in (("layout", "l"), ("jittered", "j"), ("random", "r")):
        for k in ("10", "50"):
            rs = where(rows, constraints=k, targets=t)
            out[key + k] = "%d/%d" % (_certified(rs), len(rs))
    dl = where(rows, mesh="diplodocus.off", constraints="50", targets="layout")
    st = col(dl, "steiner", int)
    out.update(v=kilo(dl[0]["vertices_in"], 2), lo=min(st), hi=max(st), t=sig(median(col(dl, "s_certified_map")), 1))
    return out


@rule(README, "The mushroom with 50 random targets takes {lo}–{hi} Steiner vertices in {t1}–{t2} s.",
      "constrained_embedding_many.csv")
def _(d):
    rs = where(_many(d), mesh="mushroom.off", constraints="50", targets="random")
    st, t = col(rs, "steiner", int), col(rs, "s_certified_map")
    return dict(lo=kilo(min(st)), hi=kilo(max(st)), t1=sig(min(t), 2), t2=sig(max(t), 2))


@rule(README, "Side by side with it off ([`constrained_embedding_many_no_kinetic.md`](benchmark/results/constrained_embedding_many_no_kinetic.md), "
      "same runs), the kinetic tracing is kept in {kk} of the {kn} runs with 50 random targets and cuts the median "
      "Steiner vertices per mesh from {a}–{b} to {c}–{e} (up to {f}-fold on one run; {never:never more vertices|more vertices in \\d+ runs?}), at a "
      "median of {t} s {ml:more|less} to the certified map (at most {tm} s more).", "constrained_embedding_many.csv",
      "constrained_embedding_many_no_kinetic.csv")
def _(d):
    r50 = where(_many(d), constraints="50", targets="random")
    off = {(r["mesh"], r["seed"]): r for r in where(d.rows("constrained_embedding_many_no_kinetic.csv"), constraints="50", targets="random")}
    before, after = _per_mesh(list(off.values()), "steiner"), _per_mesh(r50, "steiner")
    ratios = [float(off[(r["mesh"], r["seed"])]["steiner"]) / max(1., float(r["steiner"])) for r in r50]
    extra = [float(r["s_certified_map"]) - float(off[(r["mesh"], r["seed"])]["s_certified_map"]) for r in r50]
    more = sum(x < 1 for x in ratios)
    return dict(kk=sum(r["tracing"] == "kinetic" for r in r50), kn=len(r50), a=kilo(min(before)), b=kilo(max(before)),
                c=kilo(min(after)), e=kilo(max(after)), f=integer(max(ratios)), t=sig(abs(median(extra)), 2),
                ml="more" if median(extra) >= 0 else "less", tm=sig(max(extra), 2),
                never="never more vertices" if more == 0 else "more vertices in %d run%s" % (more, "" if more == 1 else "s"))


@rule(README, "`python3 benchmark/constrained_default_command.py build --optimize-time 30`, {date:\\S+ \\S+} UTC): `pe constrain IN "
      "OUT.obj --fix FILE --border circle` with 50 random constraints on the lion-head ({v1} vertices) and mannequin-devil "
      "({v2}) disks, seeds {s}: every written map certified with its constraints exact, in {a}–{b} s and {c}–{e} MB, of "
      "which {f}–{g} s are the optimization's default budget of 5 s (it never converges on these maps of {h}–{i} "
      "vertices); with `--optimize-time 30`, the former default, {j}–{k} s, and a mean symmetric Dirichlet energy "
      "{l}–{m} times lower:", "constrained_default_command.csv")
def _(d):
    rows = d.rows("constrained_default_command.csv")
    assert all(r["valid"] == "True" and r["constraints_exact"] == "True" and r["status"] == "OK" for r in rows)
    default, longer = where(rows, optimize_time="default"), where(rows, optimize_time="30.0")
    assert all(r["optimization_converged"] == "False" for r in rows)
    wall, mem = col(default, "wall_s"), col(rows, "peak_rss_mb")
    opt, out = col(default, "optimization_seconds"), col(default, "vertices_out", int)
    seeds = sorted({int(r["seed"]) for r in rows})
    gain = [float(r["mean_sd"]) / float(one(longer, mesh=r["mesh"], seed=r["seed"])["mean_sd"]) for r in default]
    return dict(date=d.md_header("constrained_default_command.md", r"Generated (\S+ \S+) UTC"),
                v1=kilo(one(rows, mesh="lion-head.off", seed="0", optimize_time="default")["vertices_in"], 2),
                v2=kilo(one(rows, mesh="mannequin-devil.off", seed="0", optimize_time="default")["vertices_in"], 2),
                s="%d–%d" % (seeds[0], seeds[-1]), a=sig(min(wall), 3), b=sig(max(wall), 3), c=integer(min(mem)),
                e=integer(max(mem)), f=sig(min(opt), 3), g=sig(max(opt), 3), h=kilo(min(out)), i=kilo(max(out)),
                j=sig(min(col(longer, "wall_s")), 3), k=sig(max(col(longer, "wall_s")), 3),
                l=sig(min(gain), 2), m=sig(max(gain), 2))


@rule(README, "[`constrained_embedding_200.md`](benchmark/results/constrained_embedding_200.md), 120 s per run) {a} of {n} "
      "runs are certified in time ({b} of {m} without the kinetic tracing,", "constrained_embedding_200.csv",
      "constrained_embedding_200_no_kinetic.csv")
def _(d):
    k, nk = d.rows("constrained_embedding_200.csv"), d.rows("constrained_embedding_200_no_kinetic.csv")
    return dict(a=_certified(k), n=len(k), b=_certified(nk), m=len(nk))


def _per_mesh(rows, name, f=median):
    by = {}
    for r in rows:
        by.setdefault(r["mesh"], []).append(float(r[name]))
    return [f(v) for v in by.values()]


@rule(README, "Over the {k} meshes, 50 random targets take (medians per mesh) +{a}% to +{b}% vertices ({c}–{e} Steiner "
      "vertices), {f}–{g} s to the certified map and {h}–{i} MB of peak memory ({j} MB the largest run); 10 random "
      "targets +{a10}% to +{b10}% in at most {m} s ({n} s the slowest run).", "constrained_embedding_many.csv")
def _(d):
    r50 = where(_many(d), constraints="50", targets="random")
    r10 = where(_many(d), constraints="10", targets="random")
    added, steiner = _per_mesh(r50, "added_percent"), _per_mesh(r50, "steiner")
    t, mem = _per_mesh(r50, "s_certified_map"), _per_mesh(r50, "peak_rss_mb")
    a10, t10 = _per_mesh(r10, "added_percent"), _per_mesh(r10, "s_certified_map")
    return dict(k=word(len(added)), a=grouped(min(added)), b=grouped(max(added)), c=kilo(min(steiner)), e=kilo(max(steiner)),
                f=sig(min(t), 2), g=sig(max(t), 2), h=integer(min(mem)), i=integer(max(mem)),
                j=integer(max(col(r50, "peak_rss_mb"))), a10=sig(min(a10), 2), b10=sig(max(a10), 2), m=sig(max(t10), 2),
                n=sig(max(col(r10, "s_certified_map")), 2))


@rule(README, "median over the seeds: man ({v1} vertices) **{t1} s** and diplodocus ({v2}) **{t2} s** (seeds {a} s and "
      "{b} s: the time follows the Steiner vertices, {c} M on these two meshes, whose count varies {f1}-fold and "
      "{f2}-fold between the seeds;", "constrained_embedding_many.csv")
def _(d):
    both = where(_many(d), constraints="50", targets="random")
    man, dip = where(both, mesh="man.off"), where(both, mesh="diplodocus.off")
    st = col(man + dip, "steiner")

    def spread(rs):
        t = col(rs, "s_certified_map")
        return rng(min(t), max(t), lambda x: sig(x, 2))

    def fold(rs):
        s = col(rs, "steiner")
        return sig(max(s) / min(s), 2)
    return dict(v1=kilo(man[0]["vertices_in"]), t1=sig(median(col(man, "s_certified_map"))), v2=kilo(dip[0]["vertices_in"]),
                t2=sig(median(col(dip, "s_certified_map"))), a=spread(man), b=spread(dip),
                c=rng(min(st) / 1e6, max(st) / 1e6, lambda x: sig(x, 2)), f1=fold(man), f2=fold(dip))


@rule(README, "Path tracing is still about {p}% of the time.", "constrained_embedding_many.csv")
def _(d):
    rs = [r for r in where(_many(d), constraints="50", targets="random") if r["mesh"] in ("man.off", "diplodocus.off")]
    return dict(p=integer(round(median(float(r["s_tracing"]) / float(r["s_certified_map"]) for r in rs) * 10) * 10))


@rule(README, "with its neighbours into the union of their polygons ({n} Steiner vertices, certified in {t} s).",
      "constrained_embedding_many.csv")
def _(d):
    r = one(_many(d), mesh="dino.off", seed="2", constraints="50", targets="layout")
    return dict(n=r["steiner"], t=sig(r["s_certified_map"], 1))


@rule(README, "with 3 constraints the mean symmetric Dirichlet energy is {lo}–{hi}% above the unconstrained optimized map "
      "on the same border (dino {d1} vs {d2}, retinal {r1} vs {r2}, mushroom {m1} vs {m2}, homer {h1} vs {h2}, "
      "lion-head {l1} vs {l2}). Targets taken from the Tutte map inherit its compression: 10 such constraints give "
      "{a}–{b} on {k} meshes and {c} on dino", "constrained_embedding_optimized.csv")
def _(d):
    rows = d.rows("constrained_embedding_optimized.csv")
    three, ten = where(rows, constraints="3"), where(rows, constraints="10")
    above = [100 * (float(r["mean_sd_after"]) / float(r["unconstrained_mean_sd"]) - 1) for r in three]
    out = dict(lo=integer(min(above)), hi=integer(max(above)))
    for key, mesh in (("d", "dino.off"), ("r", "retinal.off"), ("m", "mushroom.off"), ("h", "homer.off"), ("l", "lion-head.off")):
        r = one(three, mesh=mesh)
        out[key + "1"], out[key + "2"] = sig(r["mean_sd_after"]), sig(r["unconstrained_mean_sd"])
    others = [float(r["mean_sd_after"]) for r in ten if r["mesh"] != "dino.off"]
    out.update(a=integer(min(others)), b=integer(max(others)), k=word(len(others)),
               c=sci(one(ten, mesh="dino.off")["mean_sd_after"]))
    return out


@rule(README, "The coarsening after the optimization keeps {k} of the {i} vertices these {n} runs insert",
      "constrained_embedding_optimized.csv")
def _(d):
    rows = d.rows("constrained_embedding_optimized.csv")
    return dict(k=sum(col(rows, "steiner", int)), i=sum(col(rows, "steiner_inserted", int)), n=word(len(rows)))


@rule(README, "with the same energies within {w}% ({m} with {k} constraints: {p}% {dir}; the map is optimized again after "
      "it; the two tables were generated at {d1:\\S+ \\S+} and {d2} UTC", "constrained_embedding_optimized.csv",
      "constrained_embedding_optimized_no_coarsen.csv")
def _(d):
    diff = coarsening_effect(d)
    worst, r = diff[-1]
    d2 = _generated(d, "constrained_embedding_optimized_no_coarsen.md")
    d1 = _generated(d, "constrained_embedding_optimized.md")
    return dict(w=sig(math.ceil(abs(diff[-2][0]) * 10) / 10, 1), m=mesh_name(r["mesh"]), k=r["constraints"],
                p=sig(abs(worst), 2), dir="lower" if worst < 0 else "higher", d1=d1,
                d2=d2.split(" ")[1] if d2.split(" ")[0] == d1.split(" ")[0] else d2)


@rule(README, "spirals winding twice (overlapping themselves, the dynamic program) of {n1}, {n2}, {n3} and {n4} vertices "
      "take {t1} s / {m1} MB, {t2} s / {m2} MB, {t3} s / {m3} MB and {t4} s / {m4} MB (the process's peak memory). "
      "Simple polygons go through the constrained Delaunay path: convex and star polygons of {n} vertices and the "
      "{h}-vertex Hilbert outline in {a}–{b} s.", "polygon_triangulation.csv")
def _(d):
    rows = d.rows("polygon_triangulation.csv")
    spirals = sorted(where(rows, shape="spiral"), key=lambda r: int(r["vertices"]))[-4:]
    out = {}
    for i, r in enumerate(spirals, 1):
        out["n%d" % i], out["t%d" % i], out["m%d" % i] = r["vertices"], sig(r["seconds"], 2), sig(r["peak_rss_mb"], 3)
    n = spirals[-1]["vertices"]
    hilbert = max(where(rows, shape="hilbert"), key=lambda r: int(r["vertices"]))
    t = [float(one(rows, shape=s, vertices=n)["seconds"]) for s in ("convex", "star")] + [float(hilbert["seconds"])]
    out.update(n=n, h=hilbert["vertices"], a=sig(min(t), 1), b=sig(max(t), 1))
    return out


def _maps(d):
    return d.rows("polygon_maps.csv")


@rule(README, "{date:\\S+ \\S+} UTC, the 2-core VM alone (load {l}); each run in its own process, the output certified "
      "again, border and constraints compared bit-exactly): **{ok}/{n} runs certified and bit-exact.**", "polygon_maps.csv")
def _(d):
    rows = _maps(d)
    ok = [r for r in rows if r["status"] == "OK" and r["border_exact"] == "1" and r["constraints_exact"] == "1"]
    return dict(date=_generated(d, "polygon_maps.md"), l=d.md_header("polygon_maps.md", r"load average (\S+) at the end"),
                ok=len(ok), n=len(rows))


@rule(README, "--obj retinal_vt.obj` (the authors' {v}-vertex retinal disk)", "polygon_maps.csv")
def _(d):
    return dict(v=where(_maps(d), mesh="retinal_vt.obj")[0]["vertices_in"])


@rule(README, "the paper's stress test: {a}/{b}, on every disk (a border with fewer than {c} vertices is first refined by "
      "splitting its longest edges, counted as added vertices). Median +{p}% vertices, certified map in {t} s (median; "
      "at most {m} s). The retinal disk: {v} → {o1} and {o2} vertices ({s1} and {s2} added) in {tr} s.", "polygon_maps.csv")
def _(d):
    rows = _maps(d)
    h = where(rows, shape="hilbert")
    ok = where(h, status="OK")
    errors = [] if {r["mesh"] for r in h} == {r["mesh"] for r in rows} else ["the Hilbert outline is not run on every disk"]
    ret = where(h, mesh="retinal_vt.obj")
    return dict(a=len(ok), b=len(h), c=h[0]["polygon_corners"], p=sig(median(col(ok, "added_percent")), 3),
                t=sig(median(col(ok, "certified_map_s")), 2), m=sig(max(col(ok, "certified_map_s")), 2),
                v=ret[0]["vertices_in"], o1=ret[0]["vertices_out"], o2=ret[1]["vertices_out"], s1=ret[0]["steiner"],
                s2=ret[1]["steiner"], tr=sig(median(col(ret, "certified_map_s")), 2), _errors=errors)


@rule(README, "Stars with 3 constraints: {a}/{b}, +{p}% vertices (median), certified map in {t} s (median).",
      "polygon_maps.csv")
def _(d):
    s = where(_maps(d), shape="star")
    ok = where(s, status="OK")
    return dict(a=len(ok), b=len(s), p=sig(median(col(ok, "added_percent")), 3), t=sig(median(col(ok, "certified_map_s")), 2))


@rule(README, "Spiral strips winding twice (border only, immersions, optimized as immersions): {a}/{b}, +{p}% (median).",
      "polygon_maps.csv")
def _(d):
    s = where(_maps(d), shape="spiral")
    ok = [r for r in s if r["status"] == "OK" and r["certificate"] == "immersion"]
    return dict(a=len(ok), b=len(s), p=sig(median(col(ok, "added_percent")), 2))


@rule(README, "**own uv border**: {a}/{b}, a certified immersion, {v} → {o} vertices in {t} s, mean symmetric Dirichlet "
      "{e} after optimization.", "polygon_maps.csv")
def _(d):
    s = where(_maps(d), shape="own")
    ok = [r for r in s if r["status"] == "OK" and r["certificate"] == "immersion"]
    outs = sorted({r["vertices_out"] for r in s})
    energies = sorted({sig(r["mean_sd_after"]) for r in s})
    return dict(a=len(ok), b=len(s), v=s[0]["vertices_in"], o="/".join(outs), t=sig(median(col(s, "certified_map_s")), 1),
                e="/".join(energies))


@rule(README, "the {m} closed genus-0 meshes of libcgal-demo × seeds {s} of the Tutte-failure protocol ({f} of {n} runs "
      "fail in double) and its {k} disks (random init).", "study_runs.csv.gz")
def _(d):
    _, _, by_key, failing = d.study()
    corpus = [k for k in by_key if k[0] == "corpus"]
    seeds = sorted({k[2] for k in corpus})
    return dict(m=len({k[1] for k in corpus}), s="%d–%d" % (seeds[0], seeds[-1]), f=len(failing), n=len(corpus),
                k=len([k for k in by_key if k[0] == "disk"]))


@rule(README, "run_study.py          # about {m} min, writes benchmark/results/study_*", "study_meta.txt")
def _(d):
    seconds = float(d.md_header("study_meta.txt", r"driver wall-clock seconds: (\S+)"))
    return dict(m=integer(round(seconds / 600) * 10))


@rule(README, "it returns `OK` for a solved system; its {n} invalid maps are the corpus.", "study_methods.csv")
def _(d):
    return dict(n=one(d.rows("study_methods.csv"), method="tutte_double")["returned_ok_invalid"])


@rule(README, "per size bucket: {b1} below 100 vertices, {b2} (100–1k), {b3} (1k–5k), {b4} (5k–10k), {b5} (10k–40k) over "
      "all runs — CGAL's default solver is iterative (BiCGSTAB + incomplete LU), ours a direct LDLT — and {f:[0-9. /]+?} on the "
      "failing runs, where ours also repairs the map.", "study_runs.csv.gz")
def _(d):
    run_study, _, by_key, failing = d.study()
    out, fail = {}, []
    for i, (lo, hi) in enumerate(run_study.BUCKETS, 1):
        keys = [k for k in by_key if lo <= next(iter(by_key[k].values()))["vertices"] < hi]

        def ratio(ks):
            return [by_key[k]["pe_parameterizer"]["t"] / by_key[k]["cgal_barycentric"]["t"] for k in ks
                    if by_key[k]["pe_parameterizer"]["ran"] and by_key[k]["cgal_barycentric"]["ran"]
                    and by_key[k]["cgal_barycentric"]["t"] > 0]
        out["b%d" % i] = "%.2f" % median(ratio(keys))
        f = ratio([k for k in keys if k in failing])
        if f:
            fail.append("%.2f" % median(f))
    out["f"] = " / ".join(fail)
    return out


@rule(README, "Tutte in MPFR is valid before rounding, but {a} of the {b} failing runs it covered break again once "
      "rounded to double. Exact Gmpq Tutte finishes up to {n} interior vertices ({t} s; the longest run, {n2} interior "
      "vertices, {t2} s). Progressive embedding in MPFR is {r1}× (128 bits) and {r2}× (256 bits) slower than in double "
      "(medians over the {k} inputs run in both).", "study_methods.csv", "study_runs.csv.gz")
def _(d):
    m = {r["method"]: r for r in d.rows("study_methods.csv")}
    _, rows, by_key, _ = d.study()
    gmpq = [r for r in rows if r["method"] == "tutte_gmpq" and r["status"] == "OK"]
    big = max(gmpq, key=lambda r: (r["interior_vertices"], r["t"]))
    slow = max(gmpq, key=lambda r: r["t"])
    ratios = {}
    for b in (128, 256):
        ratios[b] = [v["pe_mpfr%d" % b]["t"] / v["pe_double"]["t"] for v in by_key.values()
                     if "pe_mpfr%d" % b in v and v["pe_mpfr%d" % b]["ran"] and v["pe_mpfr%d" % b]["status"] == "OK"
                     and v["pe_double"]["t"] > 0]
    return dict(a=m["tutte_mpfr128_rounded"]["failing_returned_ok_invalid"], b=m["tutte_mpfr128"]["failing_runs"],
                n=big["interior_vertices"], t=integer(big["t"]), n2=slow["interior_vertices"], t2=integer(slow["t"]),
                r1=integer(median(ratios[128])), r2=integer(median(ratios[256])), k=min(len(ratios[128]), len(ratios[256])))


@rule(README, "dino seed 8 and a {v}-vertex grid, medians of {r} runs on the shared 2-core machine): from Python the repair "
      "takes {u}% and the optimization under {o}% more time than the C++ functions, `tutte` {t}% more and `check` about "
      "{c} as long, since building the `Surface_mesh` from the arrays costs about as much as the certificate; the NumPy "
      "conversion itself stays under {n} ms.", "python_vs_cpp.csv")
def _(d):
    rows = d.rows("python_vs_cpp.csv")
    runs = next(re.search(r"median of (\d+) runs", c).group(1) for c in d.comments("python_vs_cpp.csv") if "median of" in c)

    def over(op):
        return [float(r["overhead_percent"]) for r in rows if r["operation"].startswith(op)]
    check = [r for r in rows if r["operation"] == "check"]
    twice = [1 + float(r["overhead_percent"]) / 100 for r in check]
    mesh = [float(r["mesh_and_copy_s"]) / float(r["algorithm_s"]) for r in check]
    errors = [] if all(0.75 <= x <= 1.33 for x in mesh) else ["building the mesh does not cost about as much as the certificate"]
    words = {2: "twice", 3: "three times"}
    grid = max(rows, key=lambda r: int(r["vertices"]))
    return dict(v=kilo(grid["vertices"]), r=runs, u=rng(min(over("untangle")), max(over("untangle")), integer),
                o=integer(math.ceil(max(over("optimize")))), t=rng(min(over("tutte")), max(over("tutte")), integer),
                c=words.get(round(median(twice)), "%s times" % sig(median(twice), 2)),
                n=integer(math.ceil(1000 * max(col(rows, "conversion_s")))), _errors=errors)


@rule(MANUAL, "the same protocol (remove one face of a closed genus-0 mesh, pin its three vertices on a triangle, uniform "
      "weights, double precision) fails in {f} of {n} runs", "study_runs.csv.gz")
def _(d):
    _, _, by_key, failing = d.study()
    return dict(f=len(failing), n=len([k for k in by_key if k[0] == "corpus"]))


@rule(MANUAL, "On the {v}-vertex mushroom of `libcgal-demo` with 50 random targets this takes {lo} to {hi} Steiner "
      "vertices ({k} seeds, `benchmark/results/constrained_embedding_many.csv`), and the certified map in {t1} to {t2} "
      "seconds.", "constrained_embedding_many.csv")
def _(d):
    rs = where(_many(d), mesh="mushroom.off", constraints="50", targets="random")
    st, t = col(rs, "steiner", int), col(rs, "s_certified_map")
    return dict(v=kilo(rs[0]["vertices_in"], 2), lo=kilo(min(st)), hi=kilo(max(st)), k=word(len(rs)),
                t1=sig(min(t), 2), t2=sig(max(t), 2))


# ---------------------------------------------------------------------------------------------
# measurements of other programs quoted side by side: the provenance each row must carry

SIDE_BY_SIDE = {"slim_reference.csv": ("program", "repository", "commit", "command", "machine", "date"),
                "stripe_embedding.csv": ("program", "repository", "commit", "command", "machine", "date"),
                "slim_scale.csv": ("program", "repository", "commit", "command", "machine", "date")}


def check_provenance(data):
    problems = []
    for name, columns in SIDE_BY_SIDE.items():
        rows = data.rows(name)
        for c in columns:
            if not rows or c not in rows[0]:
                problems.append("%s/%s: no column '%s' (a side-by-side measurement names the other program's "
                                "repository, commit, command line, machine and date)" % (RESULTS, name, c))
            elif any(not r[c] for r in rows):
                problems.append("%s/%s: column '%s' is empty in some rows" % (RESULTS, name, c))
    return problems


# ---------------------------------------------------------------------------------------------
# matching and rewriting

MARKER = re.compile(r"<!-- begin generated: (\S+) from (.+?) -->(.*?)<!-- end generated: \1 -->", re.S)


def template_regex(template):
    out, pos = [], 0
    for m in re.finditer(r"\{(\w+)(?::((?:[^{}]|\{\d*,?\d*\})+))?\}", template):
        out.append(r"\s+".join(re.escape(w) for w in template[pos:m.start()].split(" ")))
        out.append("(?P<%s>%s)" % (m.group(1), m.group(2) or r"\S+"))
        pos = m.end()
    out.append(r"\s+".join(re.escape(w) for w in template[pos:].split(" ")))
    return re.compile("".join(out))


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def process(root, check):
    data = Data(root)
    texts = {p: open(os.path.join(root, p), encoding="utf-8").read() for p in (README, MANUAL, STRIPE_MD)}
    problems, edits = check_provenance(data), {p: [] for p in texts}
    fixed = []  # the problems that rewriting mends

    for path, text in texts.items():
        seen = set()
        for m in MARKER.finditer(text):
            name, sources = m.group(1), tuple(s.strip() for s in m.group(2).split(","))
            where_ = "%s:%d" % (path, line_of(text, m.start()))
            if name not in BLOCKS or BLOCKS[name][0] != path:
                problems.append("%s: unknown generated block '%s'" % (where_, name))
                continue
            if name in seen:
                problems.append("%s: generated block '%s' appears twice" % (where_, name))
                continue
            seen.add(name)
            _, declared, f = BLOCKS[name]
            if sources != declared:
                problems.append("%s: block '%s' says it is generated from %s, it is generated from %s"
                                % (where_, name, ", ".join(sources), ", ".join(declared)))
            line = text[text.rfind("\n", 0, m.start()) + 1:m.start()]
            indent = line[:len(line) - len(line.lstrip())]
            body = "\n".join((indent + l) if l else l for l in f(data).split("\n"))
            # markers on lines of their own, or at the end of the lines around the text (Doxygen starts a new
            # paragraph at a line that starts with a comment)
            new = "\n" + body + ("\n" + indent if line.strip() == "" else "")
            if m.group(3) != new:
                old_lines, new_lines = m.group(3).split("\n"), new.split("\n")
                i = next((k for k, (a, b) in enumerate(zip(old_lines, new_lines)) if a != b), min(len(old_lines), len(new_lines)))
                quoted = old_lines[i] if i < len(old_lines) else "(end of block)"
                expected = new_lines[i] if i < len(new_lines) else "(end of block)"
                if quoted.strip() != expected.strip():
                    quoted, expected = quoted.strip(), expected.strip()
                problems.append('%s:%d: block \'%s\': "%s" should be "%s" (%s)' % (
                    path, line_of(text, m.start(3)) + i, name, quoted, expected, ", ".join(declared)))
                fixed.append(problems[-1])
                edits[path].append((m.start(3), m.end(3), new))
        for name, (p, _, _) in BLOCKS.items():
            if p == path and name not in seen:
                problems.append("%s: generated block '%s' is missing (its markers were removed)" % (path, name))

    for path, template, sources, f in RULES:
        text = texts[path]
        matches = list(template_regex(template).finditer(text))
        if len(matches) != 1:
            problems.append('%s: the figures of "%s..." (%s) are found %d times: reworded? update scripts/readme_figures.py'
                            % (path, template[:60], ", ".join(sources), len(matches)))
            continue
        m = matches[0]
        expected = f(data)
        for e in expected.pop("_errors", []):
            problems.append("%s:%d: %s (%s)" % (path, line_of(text, m.start()), e, ", ".join(sources)))
        for name, value in expected.items():
            value = str(value)
            if m.group(name) != value:
                problems.append('%s:%d: "%s" should be "%s" (%s)' % (path, line_of(text, m.start(name)), m.group(name),
                                                                     value, ", ".join(sources)))
                fixed.append(problems[-1])
                edits[path].append((m.start(name), m.end(name), value))

    if not check:
        for path, es in edits.items():
            text = texts[path]
            for a, b, new in sorted(es, reverse=True):
                text = text[:a] + new + text[b:]
            if text != texts[path]:
                with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                    f.write(text)
    return problems, fixed


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="rewrite nothing; exit 1 on any disagreement")
    ap.add_argument("--root", default=ROOT, help="the repository (default: the one holding this script)")
    args = ap.parse_args()
    problems, fixed = process(args.root, args.check)
    if args.check:
        for p in problems:
            print(p)
        print("readme_figures: %d generated blocks and %d figure rules checked, %d disagreements"
              % (len(BLOCKS), len(RULES), len(problems)))
        return 1 if problems else 0
    left = [p for p in problems if p not in fixed]
    for p in fixed:
        print("rewritten: " + p)
    for p in left:
        print(p)
    print("readme_figures: %d tables and figures rewritten, %d problems left to mend by hand" % (len(fixed), len(left)))
    return 1 if left else 0


if __name__ == "__main__":
    sys.exit(main())
