#!/usr/bin/env python3
"""check_constrain_svg.py PE MESH FIX : runs `pe constrain MESH OUT.obj --fix FIX --no-optimize` with and without
`--svg` (in the current folder) and checks that
  - both runs exit 0, their JSON objects are equal but for the times, their OBJ files are identical
    and their summary lines are equal but for the times: the picture changes nothing else;
  - the picture is well-formed SVG that holds one filled path (class pe-patch) per patch that the
    JSON reports (`patches`), adjacent patches drawn apart by the lines between patches
    (class pe-patch-borders) and in different colors, one point (class pe-constrained) per constrained vertex (`constrained`),
    and the legend's counts; and that it stays small (under 1 MB).
Exits 1 on any failure, printing what failed."""

import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG_NS = "{http://www.w3.org/2000/svg}"
TIME_KEYS = ("seconds",)

def run(argv):
    p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
    print("$ " + " ".join(argv) + "\n" + p.stdout.decode(errors="replace") + p.stderr.decode(errors="replace")
          + "exit status: %d" % p.returncode)
    return p.returncode, p.stdout.decode(errors="replace")

def without_times(obj):
    return {k: v for k, v in obj.items() if k not in TIME_KEYS and not k.startswith("seconds_") and not k.endswith("_seconds")}

def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    pe, mesh, fix = sys.argv[1:]
    failures = []
    def check(cond, what):
        print(("ok: " if cond else "FAILED: ") + what)
        if not cond:
            failures.append(what)

    # without the optimization: it stops at its time budget, so where it stops depends on the machine's speed (under
    # sanitizers the two runs stopped after 91 and 99 iterations, two different maps)
    base = ["constrain", mesh, "--no-optimize"]
    rc_a, out_a = run([pe] + base + ["constrain_plain.obj", "--fix", fix, "--json"])
    rc_b, out_b = run([pe] + base + ["constrain_svg.obj", "--fix", fix, "--json", "--svg", "constrain_patches.svg"])
    check(rc_a == 0 and rc_b == 0, "both runs exit 0")
    if rc_a != 0 or rc_b != 0:
        return 1
    ja, jb = json.loads(out_a), json.loads(out_b)
    ja.pop("output", None)
    jb.pop("output", None)
    check(without_times(ja) == without_times(jb), "the JSON objects are equal but for the times and the output name")
    check(open("constrain_plain.obj", "rb").read() == open("constrain_svg.obj", "rb").read(), "the OBJ files are identical")
    rc_c, sum_a = run([pe] + base + ["constrain_plain.obj", "--fix", fix])
    rc_d, sum_b = run([pe] + base + ["constrain_svg.obj", "--fix", fix, "--svg", "constrain_patches.svg"])
    strip = lambda s: re.sub(r"\d[0-9.e+-]* ?m?s\b", "T", s.replace("constrain_svg.obj", "OUT").replace("constrain_plain.obj", "OUT"))
    check(rc_c == 0 and rc_d == 0 and strip(sum_a) == strip(sum_b), "the summary lines are equal but for the times")

    patches, constrained = jb["patches"], jb["constrained"]
    check(patches >= 2, "the constraints cut the domain into patches (%d)" % patches)
    size = os.path.getsize("constrain_patches.svg")
    check(size < 1 << 20, "the picture is under 1 MB (%d bytes)" % size)
    root = ET.parse("constrain_patches.svg").getroot()
    check(root.tag == SVG_NS + "svg", "the picture is an SVG document")
    faces = [g for g in root.iter(SVG_NS + "g") if g.get("id") == "pe-faces"]
    check(len(faces) == 1, "one group pe-faces")
    if not faces:
        return 1
    paths = [e for e in faces[0].iter(SVG_NS + "path") if e.get("class") == "pe-patch"]
    ids = sorted(int(e.get("data-patch")) for e in paths)
    check(ids == list(range(patches)), "one path per patch, patches 0 to %d (found %s)" % (patches - 1, ids))
    fills = [e.get("fill", "") for e in paths]
    check(all(re.match(r"^#[0-9a-f]{6}$", f) for f in fills), "every patch is filled with a color")
    check(len(set(fills)) >= 2, "the patches have several colors (%d)" % len(set(fills)))
    # adjacent patches (sharing a triangle edge: the same two points, printed alike) differ in color
    owners = {}
    for e in paths:
        for sub in re.findall(r"M([^MZ]*)Z", e.get("d", "")):
            pts = re.split(r"L", sub)
            for i in range(len(pts)):
                edge = tuple(sorted((pts[i].strip(), pts[(i + 1) % len(pts)].strip())))
                owners.setdefault(edge, set()).add(e.get("data-patch"))
    fill_of = {e.get("data-patch"): e.get("fill") for e in paths}
    pairs = set(tuple(sorted(o)) for o in owners.values() if len(o) == 2)
    check(len(pairs) >= patches - 1, "the patches share edges (%d adjacent pairs)" % len(pairs))
    check(all(fill_of[a] != fill_of[b] for a, b in pairs), "adjacent patches have different colors")
    borders = [e for e in faces[0].iter(SVG_NS + "path") if e.get("class") == "pe-patch-borders"]
    check(len(borders) == 1 and borders[0].get("d", "").count("M") > 0, "the lines between patches are drawn")
    points = [e for e in root.iter(SVG_NS + "circle") if e.get("class") == "pe-constrained"]
    check(len(points) == constrained, "one point per constrained vertex (%d of %d)" % (len(points), constrained))
    texts = {e.get("id"): (e.text or "") for e in root.iter(SVG_NS + "text") if e.get("id")}
    check(texts.get("pe-count-patches") == "patches: %d" % patches, "the legend gives the patches")
    check(texts.get("pe-count-constrained") == "constrained vertices: %d" % constrained, "the legend gives the constrained vertices")
    check(texts.get("pe-count-flipped") == "flipped: 0", "the legend gives no flipped face")
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
