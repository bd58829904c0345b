#!/usr/bin/env python3
"""check_cross_svg.py PE A B LANDMARKS : runs `pe cross A B LANDMARKS OUT.txt --json` with and without
`--svg` (in the current folder) and checks that
  - both runs exit 0, their JSON objects are equal but for the times and the file names, and their OUT.txt files
    are identical: the picture changes nothing else;
  - the picture is well-formed SVG holding two panels, A's map (id pe-cross-a) on the left of B's (pe-cross-b),
    each with its faces, one point per landmark (class pe-constrained), and a legend with no flipped and no
    degenerate face; ids unique in the document; under 4 MB.
Exits 1 on any failure, printing what failed."""

import json
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_constrain_svg import SVG_NS, run  # noqa: E402


def comparable(obj):
    return {k: v for k, v in obj.items()
            if k not in ("seconds", "output", "svg") and not k.startswith("seconds_")}


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    pe, mesh_a, mesh_b, landmarks = sys.argv[1:]
    failures = []

    def check(cond, what):
        print(("ok: " if cond else "FAILED: ") + what)
        if not cond:
            failures.append(what)

    base = [pe, "cross", mesh_a, mesh_b, landmarks]
    rc_a, out_a = run(base + ["cross_plain.txt", "--json"])
    rc_b, out_b = run(base + ["cross_svg.txt", "--json", "--svg", "cross_maps.svg"])
    check(rc_a == 0 and rc_b == 0, "both runs exit 0")
    if rc_a != 0 or rc_b != 0:
        return 1
    ja, jb = json.loads(out_a), json.loads(out_b)
    check(comparable(ja) == comparable(jb), "the JSON objects are equal but for the times and the file names")
    check(jb.get("svg") == "cross_maps.svg", "the JSON names the picture")
    check(open("cross_plain.txt", "rb").read() == open("cross_svg.txt", "rb").read(), "the OUT.txt files are identical")
    count = jb["landmarks"]
    size = os.path.getsize("cross_maps.svg")
    check(size < 4 << 20, "the picture is under 4 MB (%d bytes)" % size)
    root = ET.parse("cross_maps.svg").getroot()
    check(root.tag == SVG_NS + "svg", "the picture is an SVG document")
    ids = [e.get("id") for e in root.iter() if e.get("id")]
    check(len(ids) == len(set(ids)), "the ids are unique (%d)" % len(ids))
    panels = {e.get("id"): e for e in root.findall(SVG_NS + "svg")}
    check(sorted(panels) == ["pe-cross-a", "pe-cross-b"], "two panels, A's and B's (%s)" % sorted(panels))
    if sorted(panels) != ["pe-cross-a", "pe-cross-b"]:
        return 1
    check(float(panels["pe-cross-a"].get("x")) == 0 and float(panels["pe-cross-b"].get("x")) > 0,
          "A's panel on the left of B's")
    for key, p in (("a", panels["pe-cross-a"]), ("b", panels["pe-cross-b"])):
        faces = [g for g in p.iter(SVG_NS + "g") if g.get("id") == "pe-%s-faces" % key]
        check(len(faces) == 1 and len(list(faces[0].iter(SVG_NS + "path"))) > 0, "panel %s: its faces" % key)
        points = [e for e in p.iter(SVG_NS + "circle") if e.get("class") == "pe-constrained"]
        check(len(points) == count, "panel %s: one point per landmark (%d of %d)" % (key, len(points), count))
        texts = {e.get("id"): (e.text or "") for e in p.iter(SVG_NS + "text") if e.get("id")}
        check(texts.get("pe-%s-count-flipped" % key) == "flipped: 0", "panel %s: the legend gives no flipped face" % key)
        check(texts.get("pe-%s-count-degenerate" % key) == "degenerate: 0",
              "panel %s: the legend gives no degenerate face" % key)
        check(texts.get("pe-%s-count-constrained" % key) == "constrained vertices: %d" % count,
              "panel %s: the legend gives the landmarks" % key)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
