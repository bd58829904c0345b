#!/usr/bin/env python3
# Checks the output of `pe cross A B LANDMARKS OUT.txt` (A and B OFF files): one line per vertex of A,
# `face_index b0 b1 b2` with a face of B, coordinates in [0, 1] summing to 1 up to rounding, and every
# landmark of A exactly on its partner: coordinate 1 at the partner's place in the face's vertex list of B's file.
import os
import sys

# the OFF reader of the manual's cross-parameterization figure
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts'))
from cross_figure import read_off  # noqa: E402


def main():
    a, b, landmarks, out = sys.argv[1:5]
    nva = len(read_off(a)[0])
    _, faces_b = read_off(b)
    rows = [line.split() for line in open(out) if line.strip()]
    assert len(rows) == nva, "%d lines for %d vertices" % (len(rows), nva)
    for n, r in enumerate(rows):
        f = int(r[0])
        w = [float(x) for x in r[1:4]]
        assert 0 <= f < len(faces_b), "line %d: face %d" % (n + 1, f)
        assert all(0 <= x <= 1 for x in w) and abs(sum(w) - 1) < 1e-12, "line %d: %s" % (n + 1, r)
    count = 0
    for line in open(landmarks):
        t = line.split()
        if not t or t[0].startswith('#'):
            continue
        va, vb = int(t[0]), int(t[1])
        r = rows[va]
        face = faces_b[int(r[0])]
        w = [float(x) for x in r[1:4]]
        assert vb in face and w[face.index(vb)] == 1.0, "landmark %d -> %d: %s, face %s" % (va, vb, r, face)
        count += 1
    print("%d lines, %d landmarks exactly on their partners" % (len(rows), count))


if __name__ == '__main__':
    main()
