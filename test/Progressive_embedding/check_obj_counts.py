"""check_obj_counts.py FILE.obj POSITIONS TEXCOORDS : exits 0 if the OBJ file has POSITIONS `v` lines and
TEXCOORDS `vt` lines (a seam written back keeps its two sides: more vt than v), 1 otherwise."""
import sys

counts = {"v": 0, "vt": 0}
with open(sys.argv[1]) as f:
    for line in f:
        key = line.split(" ", 1)[0]
        if key in counts:
            counts[key] += 1
expected = {"v": int(sys.argv[2]), "vt": int(sys.argv[3])}
print("v %d, vt %d (expected v %d, vt %d)" % (counts["v"], counts["vt"], expected["v"], expected["vt"]))
sys.exit(0 if counts == expected else 1)
