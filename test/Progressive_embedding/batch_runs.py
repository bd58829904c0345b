#!/usr/bin/env python3
"""batch_runs.py PE DATA_DIR WORK_DIR GROUP : checks `pe batch` and `pe batch-merge` (the `pe` tool
PE) on inputs generated at test time into WORK_DIR/GROUP (DATA_DIR/meshes: libcgal-demo's meshes).

Groups:
  shards     a folder of 6 inputs (valid, repaired, a broken file, a closed mesh) run unsharded and
             as 3 shards; the two merges (--drop-timings) must be the same bytes; counts and
             statuses; --resume runs nothing
  limits     a list file (comments, blank lines, relative paths); --time-limit kills the bigger mesh
             (status timeout) and the batch goes on; --memory-limit (status memory)
  pipelines  constrain (a .fix beside one mesh), optimize, embed
  merge      batch-merge on hand-written results: a final status wins, nested keys, a cut line
  arguments  bad --shard values and pipelines (exit 2), a missing list (3), an OUTDIR that cannot
             be made (4)

PE_BAD_INPUT_MEMORY_LIMIT_MB=0 (sanitizer builds) turns the memory limit off: no memory check then."""

import json
import os
import resource
import shutil
import subprocess
import sys
import time

PE, DATA, WORK, GROUP = sys.argv[1:5]
MEMORY_LIMITS = os.environ.get("PE_BAD_INPUT_MEMORY_LIMIT_MB", "") != "0"
# instrumented builds run several times slower (scripts/sanitize.sh: 3): the time limits of `limits` scale with it
TIME_FACTOR = float(os.environ.get("PE_TEST_TIMEOUT_FACTOR") or "1")
failures = []


def check(cond, what):
    print(("ok: " if cond else "FAILED: ") + what)
    if not cond:
        failures.append(what)


def pe(*args, expect=None, cwd=None):
    p = subprocess.run([PE] + [str(a) for a in args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True, cwd=cwd, timeout=300)
    print("$ pe %s -> exit %d\n%s%s" % (" ".join(str(a) for a in args), p.returncode, p.stdout, p.stderr[-2000:]))
    if expect is not None:
        check(p.returncode == expect, "pe %s exits %d (got %d)" % (args[0], expect, p.returncode))
    return p


def smallest_address_space_mb(args, step=4, top=512):
    """The smallest address-space limit (MB, a multiple of `step`) under which `pe ARGS` exits 0: the tool's
    own libraries take a part of it that depends on the build (CHOLMOD's BLAS maps tens of MB)."""
    for mb in range(step, top + 1, step):
        def limit(mb=mb):
            resource.setrlimit(resource.RLIMIT_AS, (mb << 20, mb << 20))
        p = subprocess.run([PE] + [str(a) for a in args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           preexec_fn=limit, timeout=300)
        if p.returncode == 0:
            return mb
    return None


def records(folder):
    with open(os.path.join(folder, "results.jsonl"), encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def by_input(folder):
    return {r["input"]: r for r in records(folder)}


def same_file(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def memory_args():
    return [] if MEMORY_LIMITS else ["--memory-limit", "0"]

# ---- inputs ------------------------------------------------------------------------------------

# a closed mesh (a tetrahedron) with texture coordinates: not a disk
CLOSED_OBJ = """v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1
vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1
f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 2/2 3/3 4/4\nf 3/3 1/1 4/4
"""


def make_inputs(folder):
    os.makedirs(folder)
    meshes = os.path.join(DATA, "meshes")
    pe("generate", "grid", 5, os.path.join(folder, "grid5.obj"), expect=0)
    pe("generate", "grid", 12, os.path.join(folder, "grid12.obj"), expect=0)
    pe("generate", "stacked", 40, os.path.join(folder, "stacked40.obj"), expect=1)  # invalid in double
    pe("tutte", os.path.join(meshes, "mushroom.off"), os.path.join(folder, "mushroom.obj"), expect=0)  # a disk
    pe("thingi", os.path.join(meshes, "bull.off"), 4, os.path.join(folder, "bull-4.obj"), expect=1)
    with open(os.path.join(folder, "broken.obj"), "w") as f:
        f.write("this is not a mesh\n{ garbage }\n")
    with open(os.path.join(folder, "closed.obj"), "w") as f:
        f.write(CLOSED_OBJ)
    with open(os.path.join(folder, "notes.txt"), "w") as f:   # not a mesh file: not listed
        f.write("not an input\n")

# ---- groups ------------------------------------------------------------------------------------


def group_shards(w):
    inputs = os.path.join(w, "inputs")
    make_inputs(inputs)
    names = sorted(n for n in os.listdir(inputs) if n.endswith(".obj"))
    check(len(names) == 7, "7 inputs generated (%d)" % len(names))
    whole, shard_dirs = os.path.join(w, "whole"), [os.path.join(w, "shard%d" % k) for k in (1, 2, 3)]
    pe("batch", "untangle", inputs, whole, "--jobs", 2, "--no-progress", *memory_args(), expect=1)
    for k, d in enumerate(shard_dirs, 1):
        pe("batch", "untangle", inputs, d, "--shard", "%d/3" % k, "--jobs", 2, "--no-progress", *memory_args())
    # each shard takes the inputs of index % 3 == k-1 in the sorted list
    for k, d in enumerate(shard_dirs, 1):
        got = sorted(r["input"] for r in records(d))
        want = [os.path.join(inputs, n) for i, n in enumerate(names) if i % 3 == k - 1]
        check(got == want, "shard %d/3 ran exactly %s" % (k, [os.path.basename(p) for p in want]))
        check(all(r["shard"] == "%d/3" % k for r in records(d)), "shard %d/3 records say their shard" % k)

    rec = by_input(whole)
    check(len(records(whole)) == 7, "one line per mesh in results.jsonl (%d)" % len(records(whole)))
    check(sum(r["valid"] for r in rec.values()) == 5, "5 valid meshes")
    broken, closed = rec[os.path.join(inputs, "broken.obj")], rec[os.path.join(inputs, "closed.obj")]
    check(broken["status"] == "input_error" and broken["exit_status"] == 3 and broken["valid"] is False,
          "the broken file: status input_error, exit 3")
    check(closed["status"] == "input_error" and closed["code"] == "ERROR_NOT_A_DISK", "the closed mesh: ERROR_NOT_A_DISK")
    for n in ("grid5", "grid12", "stacked40", "mushroom", "bull-4"):
        r = rec[os.path.join(inputs, n + ".obj")]
        check(r["status"] == "done" and r["valid"] is True and r["flipped"] == 0 and r["degenerate"] == 0
              and r["exit_status"] == 0 and r["output"] == n + ".obj", n + ": done, valid, flipped 0, degenerate 0")
        check(os.path.isfile(os.path.join(whole, n + ".obj")), n + ": map written in OUTDIR")
    check(rec[os.path.join(inputs, "bull-4.obj")]["invalid_before"] > 0, "bull-4: invalid before the repair")

    m1, m2 = os.path.join(w, "merge_whole"), os.path.join(w, "merge_shards")
    pe("batch-merge", whole, "--out", m1, "--drop-timings", expect=1)
    pe("batch-merge", *shard_dirs, "--out", m2, "--drop-timings", expect=1)
    for f in ("results.jsonl", "results.csv", "summary.md"):
        check(same_file(os.path.join(m1, f), os.path.join(m2, f)), "merges of the whole run and of the shards: same " + f)
    merged = records(m1)
    check([r["input"] for r in merged] == sorted(r["input"] for r in merged), "merged records sorted by input")
    check(not any(k == "seconds" or k.endswith("_seconds") or k.startswith("seconds_") or k == "shard"
                  for r in merged for k in r), "--drop-timings: no timing key, no shard")
    with open(os.path.join(m1, "results.csv")) as f:
        header = f.readline().strip().split(",")
    check(header[:5] == ["input", "status", "valid", "exit_status", "seconds"] and header[5:] == sorted(header[5:]),
          "CSV columns: input,status,valid,exit_status,seconds, then sorted")
    with open(os.path.join(m1, "summary.md")) as f:
        summary = f.read()
    check("| input_error | 2 |" in summary and "| done | 5 |" in summary and "broken.obj" in summary,
          "summary.md: counts by status and the failures")

    p = pe("batch", "untangle", inputs, whole, "--resume", "--json", *memory_args(), expect=1)
    s = json.loads(p.stdout)
    check(s["run"] == 0 and s["skipped"] == 7 and s["meshes"] == 7 and s["valid"] == 5,
          "--resume: 0 meshes run, 7 skipped, 5 valid (from the earlier records)")
    p = pe("batch", "untangle", inputs, whole, "--resume", *memory_args(), expect=1)
    check("7 meshes (0 run, 7 skipped by --resume)" in p.stdout, "--resume: the summary line says 0 run")
    check(len(records(whole)) == 7, "--resume appends nothing")


def group_limits(w):
    inputs = os.path.join(w, "meshes")
    os.makedirs(inputs)
    pe("generate", "grid", 5, os.path.join(inputs, "grid5.obj"), expect=0)
    pe("thingi", os.path.join(DATA, "meshes", "bull.off"), 4, os.path.join(inputs, "bull-4.obj"), expect=1)
    lst = os.path.join(w, "list.txt")
    with open(lst, "w") as f:
        f.write("# relative to the list's folder\nmeshes/grid5.obj\n\n   meshes/bull-4.obj  \nmeshes/missing.obj\n")
    out = os.path.join(w, "timeout")
    # bull-4's optimization made long whatever the machine's speed (tolerance 0 never converges: 5000 iterations,
    # about 10 s on the development machine), grid5's short (its 5000 iterations about 0.15 s; 1.15 s under the
    # sanitizers, where the limit is 4.5 s)
    p = pe("batch", "untangle", lst, out, "--time-limit", 1.5 * TIME_FACTOR, "--iterations", 5000, "--tolerance", 0, "--optimize-time", 120,
           "--no-progress", "--json", *memory_args(), expect=1)
    rec = by_input(out)
    check(sorted(rec) == ["meshes/bull-4.obj", "meshes/grid5.obj", "meshes/missing.obj"], "list entries as written")
    check(rec["meshes/bull-4.obj"]["status"] == "timeout" and rec["meshes/bull-4.obj"]["valid"] is False
          and rec["meshes/bull-4.obj"]["seconds"] < 10 * TIME_FACTOR, "bull-4 killed at --time-limit: status timeout")
    check(rec["meshes/grid5.obj"]["status"] == "done" and rec["meshes/grid5.obj"]["valid"] is True,
          "the batch goes on: grid5 done and valid")
    check(rec["meshes/missing.obj"]["status"] == "input_error", "a missing entry: input_error")
    s = json.loads(p.stdout)
    check(s["timeouts"] == 1 and s["valid"] == 1 and s["failed"] == 2 and s["statuses"]["timeout"] == 1,
          "JSON summary: 1 timeout, 1 valid, 2 failed")
    # a timeout is final: --resume does not run it again
    p = pe("batch", "untangle", lst, out, "--resume", "--json", *memory_args(), expect=1)
    check(json.loads(p.stdout)["run"] == 0, "--resume skips the timeout")
    check_killed_batch(w, inputs)
    if MEMORY_LIMITS:
        # a limit just above what grid5 needs (the tool's libraries included): grid5 fits, bull-4 does not
        need = smallest_address_space_mb(["untangle", os.path.join(inputs, "grid5.obj"), os.path.join(w, "grid5-alone.obj")])
        check(need is not None, "grid5 runs alone in some address space (%s MB)" % need)
        mb = (need or 0) + 4
        out = os.path.join(w, "memory")
        pe("batch", "untangle", lst, out, "--memory-limit", mb, "--no-progress", expect=1)
        rec = by_input(out)
        check(rec["meshes/bull-4.obj"]["status"] == "memory", "bull-4 in %d MB of address space: status memory" % mb)
        check(rec["meshes/grid5.obj"]["status"] == "done" and rec["meshes/grid5.obj"]["valid"] is True,
              "grid5 in %d MB: done and valid" % mb)


def processes_naming(text):
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                if text.encode() in f.read():
                    found.append(pid)
        except OSError:
            pass
    return found


# the batch killed (SIGKILL) while its second mesh runs: the first line is on disk, the child
# is gone with its parent, and --resume runs the second mesh only
def check_killed_batch(w, meshes):
    inputs, out = os.path.join(w, "crash_in"), os.path.join(w, "crash_out")
    os.makedirs(inputs)
    shutil.copy(os.path.join(meshes, "grid5.obj"), os.path.join(inputs, "a.obj"))
    shutil.copy(os.path.join(meshes, "bull-4.obj"), os.path.join(inputs, "b.obj"))
    batch = subprocess.Popen([PE, "batch", "untangle", inputs, out, "--no-progress"] + memory_args(),
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    results = os.path.join(out, "results.jsonl")
    for _ in range(600):
        if os.path.isfile(results) and os.path.getsize(results) > 0:
            break
        time.sleep(0.05)
    batch.kill()
    batch.wait()
    time.sleep(0.5)
    check([r["input"] for r in records(out)] == [os.path.join(inputs, "a.obj")], "killed batch: the first line kept")
    check(processes_naming(os.path.join(out, "b.obj")) == [], "killed batch: its child is gone too")
    p = pe("batch", "untangle", inputs, out, "--resume", "--json", "--no-progress", *memory_args(), expect=0)
    s = json.loads(p.stdout)
    check(s["run"] == 1 and s["skipped"] == 1 and s["valid"] == 2, "--resume after the kill: b run, a skipped")
    check(sorted(r["input"] for r in records(out)) == [os.path.join(inputs, n) for n in ("a.obj", "b.obj")],
          "one line per mesh after the resume")


def group_pipelines(w):
    inputs = os.path.join(w, "in")
    os.makedirs(inputs)
    pe("generate", "grid", 5, os.path.join(inputs, "a.obj"), expect=0)
    pe("generate", "grid", 6, os.path.join(inputs, "b.obj"), expect=0)
    with open(os.path.join(inputs, "a.fix"), "w") as f:
        f.write("# the centre vertex, moved\n12 0.3 0.6\n")
    out = os.path.join(w, "constrain")
    pe("batch", "constrain", inputs, out, "--no-progress", *memory_args(), expect=0)
    rec = by_input(out)
    a, b = rec[os.path.join(inputs, "a.obj")], rec[os.path.join(inputs, "b.obj")]
    check(a["valid"] and a["constrained"] == 1 and a["constraints_exact"] is True, "constrain: a.fix used, exact")
    check(b["valid"] and b["constrained"] == 0, "constrain: no b.fix, border only")
    out = os.path.join(w, "optimize")
    pe("batch", "optimize", inputs, out, "--iterations", 5, "--no-progress", *memory_args(), expect=0)
    check(all(r["command"] == "optimize" and r["valid"] and r["iterations"] <= 5 for r in records(out)),
          "optimize: valid, --iterations passed through")
    out = os.path.join(w, "embed")
    pe("batch", "embed", inputs, out, "--no-optimize", "--no-progress", *memory_args(), expect=0)
    check(all(r["command"] == "embed" and r["valid"] and r["optimized"] is False for r in records(out)),
          "embed: valid, --no-optimize passed through")
    pe("batch", "optimize", inputs, os.path.join(w, "x"), "--no-optimize", expect=2)
    pe("batch", "optimize", inputs, inputs, expect=2)   # the maps would replace the inputs


def group_merge(w):
    d1, d2 = os.path.join(w, "r1"), os.path.join(w, "r2")
    os.makedirs(d1)
    os.makedirs(d2)
    with open(os.path.join(d1, "results.jsonl"), "w") as f:
        f.write('{"input": "b", "status": "done", "valid": true, "exit_status": 0, "seconds": 1.5, "shard": "1/2", "m": {"x": 1, "y": [1, 2]}}\n')
        f.write('{"input": "a", "status": "timeout", "valid": false, "exit_status": null, "seconds": 9, "shard": "1/2"}\n')
        f.write('{"input": "c", "status": "done", "valid": false, "exit_status": 1, "seconds": 2, "message": "a, \\"quoted\\" | one"}\n')
        f.write('{"input": "d", "status": "do')   # cut short by a crash
    with open(os.path.join(d2, "results.jsonl"), "w") as f:
        f.write('{"input": "a", "status": "output_error", "valid": false, "exit_status": 4, "seconds": 1, "shard": "2/2"}\n')
        f.write('{"input": "c", "status": "done", "valid": true, "exit_status": 0, "seconds": 3, "shard": "2/2", "z_time": 5}\n')
        # not JSON, or not strict JSON: skipped, with a warning naming the line
        for bad in ('{"input": "e", "status": "done", "valid": tru}', '{"input": "f", "status": "done", "input": "g"}',
                    '{"input": "h", "status": "done", "x": 01}', '{"input": "i", "status": "done"} trailing',
                    '{"input": "j", "status": "done", "s": "\\x"}', '["input", "k"]', '{"status": "done"}'):
            f.write(bad + "\n")
        f.write('{"input": "\\u00e9\\ud83d\\ude00", "status": "done", "valid": true, "exit_status": 0, "seconds": 1e0}\n')
    out = os.path.join(w, "merged")
    p = pe("batch-merge", d1, d2, "--out", out, expect=1)
    check(p.stderr.count(" skipped: ") == 8 and "r2/results.jsonl: line 4 skipped: not a JSON object: the key \"input\" twice"
          in p.stderr, "8 lines skipped, each named with its reason")
    rec = records(out)
    check([r["input"] for r in rec] == ["a", "b", "c", "\u00e9\U0001F600"],
          "one record per input, sorted; the cut line and the lines that are not strict JSON skipped")
    check(rec[0]["status"] == "timeout", "a final status (timeout) wins over a later non-final one (output_error)")
    check(rec[2]["valid"] is True and rec[2]["z_time"] == 5, "two final statuses: the later record wins")
    with open(os.path.join(out, "results.csv"), encoding="utf-8") as f:
        csv = f.read()
    want = ("input,status,valid,exit_status,seconds,m.x,m.y,shard,z_time\n"
            "a,timeout,false,,9,,,1/2,\n"
            "b,done,true,0,1.5,1,\"[1, 2]\",1/2,\n"
            "c,done,true,0,3,,,2/2,5\n"
            "\u00e9\U0001F600,done,true,0,1e0,,,,\n")
    check(csv == want, "results.csv: fixed columns, then sorted, nested keys as m.x, arrays as JSON")
    with open(os.path.join(out, "summary.md"), encoding="utf-8") as f:
        md = f.read()
    check("| a | timeout | null |" in md and "total 14.5, median 2.25" in md, "summary.md: failures and seconds")
    out = os.path.join(w, "dropped")
    pe("batch-merge", d1, d2, "--out", out, "--drop-timings", expect=1)
    check(all(set(r) & {"seconds", "shard", "z_time"} == set() for r in records(out)), "--drop-timings drops them")
    pe("batch-merge", d1, os.path.join(w, "none"), "--out", out, expect=3)
    pe("batch-merge", d1, expect=2)


def group_arguments(w):
    os.makedirs(w)
    pe("generate", "grid", 3, os.path.join(w, "g.obj"), expect=0)
    for shard in ("0/3", "4/3", "x", "1/0", "1/", "/3", "-1/3", "1/3/3"):
        p = pe("batch", "untangle", w, os.path.join(w, "out"), "--shard", shard, expect=2)
        check("--shard" in p.stderr, "--shard %s: the message names the option" % shard)
    pe("batch", "flatten", w, os.path.join(w, "out"), expect=2)
    pe("batch", "untangle", w, os.path.join(w, "out"), "--jobs", 0, expect=2)
    pe("batch", "untangle", w, os.path.join(w, "out"), "--fix", "f.fix", expect=2)
    pe("batch", "untangle", os.path.join(w, "no_such_list.txt"), os.path.join(w, "out"), expect=3)
    pe("batch", "untangle", w, os.path.join(w, "g.obj", "sub"), expect=4)   # under a file: cannot be made
    check(not os.path.exists(os.path.join(w, "out")), "no OUTDIR made by a refused command")


def main():
    groups = {"shards": group_shards, "limits": group_limits, "pipelines": group_pipelines,
              "merge": group_merge, "arguments": group_arguments}
    w = os.path.join(WORK, GROUP)
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(WORK, exist_ok=True)
    groups[GROUP](w)
    print("%d failed check(s)" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
