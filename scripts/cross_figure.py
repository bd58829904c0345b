#!/usr/bin/env python3
"""The manual's cross-parameterization figure: `pe cross A B LANDMARKS` on two closed surfaces, then A painted
with B's texture through the map.

    cross_figure.py PE A.off B.off LANDMARKS OUT_PREFIX [--yaw-a R] [--yaw-b R]

Runs `pe cross A B LANDMARKS OUT_PREFIX_locations.txt --json` (the map is certified by pe: exit status 0),
then draws OUT_PREFIX.svg (and OUT_PREFIX.png with rsvg-convert, reduced by pngquant, when installed; the
manual's doc/Progressive_embedding/fig/cross_cow_bull.png is this picture for cow.off and bull.off of
libcgal-demo with test/Progressive_embedding/data/cow_bull_landmarks.txt), two views side by side:
  - B with a texture defined on its surface: a hue along B's longest side, a 3D checkerboard on top
    (each face coloured at its centroid);
  - A with every face coloured by the texture at the mean of the points of B its vertices are mapped to (the
    face of B and the barycentric coordinates that pe wrote), i.e. B's texture carried onto A;
  - the landmarks, one colour per pair, on both.
Each view is an orthographic projection drawn back to front (painter's order), shaded by the face normal.
Prints one line: the vertex counts, the landmarks, and where the figure was written. Exit status 0, or 1
with the reason (pe failed, a file is unreadable, the output is malformed).
"""

import argparse
import colorsys
import json
import math
import os
import shutil
import subprocess
import sys


def read_off(path):
    with open(path) as f:
        tokens = [t for line in f for t in line.split('#', 1)[0].split()]
    i = 1 if tokens[0].upper().startswith('OFF') else 0
    nv, nf = int(tokens[i]), int(tokens[i + 1])
    i += 3
    points = [tuple(float(x) for x in tokens[i + 3 * k:i + 3 * k + 3]) for k in range(nv)]
    i += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[i])
        faces.append(tuple(int(x) for x in tokens[i + 1:i + 1 + n]))
        i += 1 + n
    return points, faces


def read_landmarks(path):
    pairs = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if line:
                pairs.append((int(line[0]), int(line[1])))
    return pairs


def read_locations(path, faces_b, count):
    """one (face of B, barycentric coordinates) per vertex of A"""
    out = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            fb = int(w[0])
            if not 0 <= fb < len(faces_b) or len(w) != 4:
                raise ValueError('malformed location line: ' + line.strip())
            out.append((fb, (float(w[1]), float(w[2]), float(w[3]))))
    if len(out) != count:
        raise ValueError('%d locations for %d vertices' % (len(out), count))
    return out


class Texture:
    """a colour for every point of space near B: hue along B's longest bounding-box side, a 3D checkerboard"""

    def __init__(self, points):
        lo = [min(p[k] for p in points) for k in range(3)]
        hi = [max(p[k] for p in points) for k in range(3)]
        self.axis = max(range(3), key=lambda k: hi[k] - lo[k])
        self.lo, self.size = lo[self.axis], hi[self.axis] - lo[self.axis]
        self.cell = self.size / 7

    def colour(self, p):
        t = (p[self.axis] - self.lo) / self.size
        r, g, b = colorsys.hsv_to_rgb(0.8 * min(max(t, 0.), 1.), 0.55, 1.)
        if sum(int(math.floor(c / self.cell)) for c in p) % 2:
            r, g, b = 0.72 * r, 0.72 * g, 0.72 * b
        return r, g, b


def draw(points, faces, texture, texture_points, landmarks, landmark_colours, yaw, x0, title):
    """SVG elements of one view, 400 x 400 from x0, each face coloured by the texture at the mean of its
    vertices' texture points, shaded by its normal"""
    cy, sy = math.cos(yaw), math.sin(yaw)
    pitch = 0.25
    cp, sp = math.cos(pitch), math.sin(pitch)
    proj = []
    for x, y, z in points:
        x, z = cy * x + sy * z, -sy * x + cy * z
        y, z = cp * y - sp * z, sp * y + cp * z
        proj.append((x, y, z))
    xs, ys = [p[0] for p in proj], [p[1] for p in proj]
    scale = 380 / max(max(xs) - min(xs), max(ys) - min(ys))
    ox, oy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    screen = [(x0 + 210 + (p[0] - ox) * scale, 230 - (p[1] - oy) * scale) for p in proj]
    order = []
    for f in faces:
        a, b, c = proj[f[0]], proj[f[1]], proj[f[2]]
        nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
        vx, vy, vz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
        n = math.sqrt((uy * vz - uz * vy) ** 2 + (uz * vx - ux * vz) ** 2 + nz ** 2) or 1.
        order.append(((a[2] + b[2] + c[2]) / 3, f, abs(nz) / n))
    order.sort(key=lambda e: -e[0])  # farthest first: the viewer looks down -z after the rotation
    out = ['<text x="%d" y="24" font-family="sans-serif" font-size="15">%s</text>' % (x0 + 20, title)]
    for _, f, shade in order:
        col = texture.colour(tuple(sum(texture_points[i][k] for i in f) / len(f) for k in range(3)))
        light = 0.45 + 0.55 * shade
        rgb = tuple(int(255 * min(1., c * light)) for c in col)
        pts = ' '.join('%.1f,%.1f' % screen[i] for i in f)
        out.append('<polygon points="%s" fill="rgb(%d,%d,%d)" stroke="rgb(%d,%d,%d)" stroke-width="0.3"/>'
                   % ((pts,) + rgb + rgb))
    for v, col in zip(landmarks, landmark_colours):
        out.append('<circle cx="%.1f" cy="%.1f" r="5.5" fill="%s" stroke="black" stroke-width="1.2"/>'
                   % (screen[v] + (col,)))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('pe')
    ap.add_argument('a')
    ap.add_argument('b')
    ap.add_argument('landmarks')
    ap.add_argument('out_prefix')
    ap.add_argument('--yaw-a', type=float, default=-0.5)
    ap.add_argument('--yaw-b', type=float, default=-0.5)
    args = ap.parse_args()
    locations = args.out_prefix + '_locations.txt'
    run = subprocess.run([args.pe, 'cross', args.a, args.b, args.landmarks, locations, '--json'],
                         capture_output=True, text=True)
    if run.returncode != 0:
        print('cross_figure: pe cross failed (exit %d): %s' % (run.returncode, run.stderr.strip() or run.stdout.strip()))
        return 1
    report = json.loads(run.stdout.strip().splitlines()[-1])
    try:
        pa, fa = read_off(args.a)
        pb, fb = read_off(args.b)
        pairs = read_landmarks(args.landmarks)
        loc = read_locations(locations, fb, len(pa))
    except (OSError, ValueError, IndexError) as e:
        print('cross_figure: %s' % e)
        return 1
    tex = Texture(pb)
    # A's vertex: the point of B it is mapped to (B's texture is read there)
    on_b = [tuple(sum(w[k] * pb[fb[face][k]][c] for k in range(3)) for c in range(3)) for face, w in loc]
    marks = ['#%02x%02x%02x' % tuple(int(255 * c) for c in colorsys.hsv_to_rgb(k / len(pairs), 0.9, 0.85))
             for k in range(len(pairs))]
    name_a, name_b = os.path.basename(args.a), os.path.basename(args.b)
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="840" height="440" viewBox="0 0 840 440">',
           '<rect width="840" height="440" fill="white"/>']
    svg += draw(pb, fb, tex, pb, [p[1] for p in pairs], marks, args.yaw_b, 0, 'B: %s, its texture' % name_b)
    svg += draw(pa, fa, tex, on_b, [p[0] for p in pairs], marks, args.yaw_a, 420,
                'A: %s, painted through the map' % name_a)
    svg.append('<text x="20" y="430" font-family="sans-serif" font-size="12">%d landmarks (one colour per pair); '
               'certified: %s</text>' % (len(pairs), 'yes' if report.get('valid') else 'no'))
    svg.append('</svg>')
    with open(args.out_prefix + '.svg', 'w') as f:
        f.write('\n'.join(svg) + '\n')
    written = [args.out_prefix + '.svg']
    if shutil.which('rsvg-convert'):
        subprocess.run(['rsvg-convert', args.out_prefix + '.svg', '-o', args.out_prefix + '.png'], check=True)
        if shutil.which('pngquant'):  # a third of the size, as the other figures of the manual
            subprocess.run(['pngquant', '--force', '--quality=70-90', '--output', args.out_prefix + '.png',
                            args.out_prefix + '.png'], check=True)
        written.append(args.out_prefix + '.png')
    print('cross_figure: A %s %d vertices, B %s %d vertices, %d landmarks, map certified %s; wrote %s'
          % (name_a, len(pa), name_b, len(pb), len(pairs), report.get('valid'), ', '.join(written)))
    return 0 if report.get('valid') else 1


if __name__ == '__main__':
    sys.exit(main())
