#!/usr/bin/env python3
# Checks the compatible meshes written by `pe cross A B LANDMARKS OUT.txt --compatible A_OUT.obj B_OUT.obj`
# (A and B OFF files): the same faces in the same order, as many vertices in both, every vertex of A a vertex
# of A_OUT and every vertex of B one of B_OUT (bit for bit: the writer prints 17 significant digits), and the
# area of A_OUT that of A, of B_OUT that of B (A_OUT refines A's triangles, B_OUT B's). With a fifth argument
# `closed` (two closed meshes): each compatible mesh a closed oriented surface of Euler characteristic 2 (every
# edge in two faces, once each way): the two sides of the cut joined, else the cut would be a border.
import sys
from collections import Counter

from check_cross_output import read_off


def read_obj(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == 'v':
                points.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == 'f':
                faces.append([int(x.split('/')[0]) - 1 for x in t[1:]])
    return points, faces


def area(points, faces):
    total = 0.0
    for f in faces:
        a, b, c = (points[i] for i in f)
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        total += 0.5 * (n[0] ** 2 + n[1] ** 2 + n[2] ** 2) ** 0.5
    return total


def main():
    a, b = read_off(sys.argv[1]), read_off(sys.argv[2])
    ca, cb = read_obj(sys.argv[3]), read_obj(sys.argv[4])
    problems = []
    if ca[1] != cb[1]:
        problems.append('the two meshes have different faces')
    if len(ca[0]) != len(cb[0]):
        problems.append('vertex counts differ: %d and %d' % (len(ca[0]), len(cb[0])))
    for name, original, compatible in (('A', a, ca), ('B', b, cb)):
        present = set(compatible[0])
        missing = sum(1 for p in original[0] if p not in present)
        if missing:
            problems.append('%d vertices of %s are not vertices of its compatible mesh' % (missing, name))
        ratio = area(*compatible) / area(*original)
        if abs(ratio - 1) > 1e-9:
            problems.append('the compatible mesh of %s has %.12g of its area' % (name, ratio))
    if len(sys.argv) > 5 and sys.argv[5] == 'closed':
        for name, (points, faces) in (("A'", ca), ("B'", cb)):
            directed = Counter((f[k], f[(k + 1) % 3]) for f in faces for k in range(3))
            if any(c != 1 for c in directed.values()) or any((v, u) not in directed for (u, v) in directed):
                problems.append('%s is not a closed oriented surface' % name)
            chi = len(points) - len(directed) // 2 + len(faces)
            if chi != 2:
                problems.append('%s has Euler characteristic %d' % (name, chi))
    if problems:
        print('\n'.join(problems))
        return 1
    print('compatible meshes: %d vertices, %d faces in both; every vertex of A and of B kept; areas as A and B%s'
          % (len(ca[0]), len(ca[1]), '; both closed, Euler characteristic 2' if len(sys.argv) > 5 else ''))
    return 0


if __name__ == '__main__':
    sys.exit(main())
