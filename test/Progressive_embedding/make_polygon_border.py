#!/usr/bin/env python3
"""make_polygon_border.py IN.obj OUT.obj SHAPE : copies an OBJ with texture coordinates (a disk in its
`vt` topology, faces `f a/a b/b c/c`) and puts its border `vt` on a polygon by 3D arc length: each
polygon corner on the border vertex nearest to its perimeter fraction, the vertices between two
corners on the side between them (the sides are axis-parallel: one coordinate is copied exactly).
Interior `vt` are kept (pe constrain recomputes them). SHAPE: `l` (the unit square without its upper
right quarter: simple, not convex) or `spiral` (a strip winding 1.25 times around a square, its last
part on its first one: weakly self-overlapping, not simple)."""
import math
import sys

SHAPES = {
    'l': [(0, 0), (1, 0), (1, 0.5), (0.5, 0.5), (0.5, 1), (0, 1)],
    'spiral': [(1, -0.5), (4.5, -0.5), (4.5, 4.5), (-0.5, 4.5), (-0.5, -0.5), (3, -0.5),
               (3, 0.5), (0.5, 0.5), (0.5, 3.5), (3.5, 3.5), (3.5, 0.5), (1, 0.5)],
}


def main():
    if len(sys.argv) != 4 or sys.argv[3] not in SHAPES:
        sys.exit(__doc__)
    Q = SHAPES[sys.argv[3]]
    lines = open(sys.argv[1]).read().splitlines()
    v, vt, faces = [], [], []
    for line in lines:
        p = line.split()
        if not p:
            continue
        if p[0] == 'v':
            v.append(tuple(map(float, p[1:4])))
        elif p[0] == 'vt':
            vt.append([float(p[1]), float(p[2])])
        elif p[0] == 'f':
            faces.append([tuple(int(x) - 1 for x in c.split('/')[:2]) for c in p[1:]])
    # border of the vt topology: directed edges without their reverse (interior on the left)
    directed = {}
    for f in faces:
        for k in range(len(f)):
            a, b = f[k][1], f[(k + 1) % len(f)][1]
            directed[(a, b)] = (f[k][0], f[(k + 1) % len(f)][0])
    nxt = {a: b for (a, b) in directed if (b, a) not in directed}
    start = min(nxt)
    loop = [start]
    while nxt[loop[-1]] != start and len(loop) <= len(nxt):
        loop.append(nxt[loop[-1]])
    pos = {}  # vt -> 3D point, through the faces
    for f in faces:
        for (vi, ti) in f:
            pos[ti] = v[vi]
    nb, nq = len(loop), len(Q)
    s = [0.0]
    for k in range(nb):
        s.append(s[-1] + math.dist(pos[loop[k]], pos[loop[(k + 1) % nb]]))
    t = [0.0]
    for j in range(nq):
        t.append(t[-1] + math.dist(Q[j], Q[(j + 1) % nq]))
    at = [0]
    for j in range(1, nq):
        f = t[j] / t[nq]
        best = at[-1] + 1
        for k in range(best, nb - (nq - j)):
            if abs(s[k] / s[nb] - f) < abs(s[best] / s[nb] - f):
                best = k
        at.append(best)
    for j in range(nq):
        a, b = at[j], at[j + 1] if j + 1 < nq else nb
        A, B = Q[j], Q[(j + 1) % nq]
        for k in range(a, b):
            u = (s[k] - s[a]) / (s[b] - s[a])
            x = A[0] if A[0] == B[0] else A[0] + u * (B[0] - A[0])
            y = A[1] if A[1] == B[1] else A[1] + u * (B[1] - A[1])
            vt[loop[k]] = [x, y]
    out, i = [], 0
    for line in lines:
        p = line.split()
        if p and p[0] == 'vt':
            out.append('vt %r %r' % (vt[i][0], vt[i][1]))
            i += 1
        else:
            out.append(line)
    open(sys.argv[2], 'w').write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
