#!/usr/bin/env python3
# Copyright (c) 2026 Progressive_embedding contributors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
"""Cost of the Python module against the C++ functions it calls.

For each operation, the wall time of the Python call is compared with the time the module spends in
C++ in that same call (progressive_embedding.last_timing()): 'native' is everything done without the
GIL (building the Surface_mesh from the arrays, the algorithm, copying the result out), 'algorithm' the
package's C++ functions alone. So python - native is the cost of the NumPy conversion and validation,
native - algorithm the cost of building the mesh, and algorithm is what a C++ caller pays.

Inputs: the Tutte-failure protocol on dino.off seed 8 (as `pe thingi`: 1836 flipped faces) and a large
grid disk (border on the unit circle; the repair starts from a random interior). Operations: tutte,
check, untangle (the repair alone, optimize=False), optimize (a fixed number of iterations from the
repaired map, tolerance 0). Median of --runs runs each.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Progressive_embedding/python_timings.py \\
        --data-dir build/cgal_data/data

writes benchmark/results/python_vs_cpp.csv and .md.
"""

import argparse
import csv
import datetime
import os
import platform
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..'))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, 'python', 'tests'))  # the helpers of the module's tests

import progressive_embedding as pe  # noqa: E402
from test_progressive_embedding import read_off, grid_disk, thingi_cut, border_vertices  # noqa: E402


def cpu_model():
    try:
        with open('/proc/cpuinfo') as f:
            for line in f:
                if line.startswith('model name'):
                    return line.split(':', 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or 'unknown CPU'


def measure(call, runs):
    """Medians over `runs` calls: Python wall time, native and algorithm seconds; and the last result."""
    wall, native, algorithm = [], [], []
    result = None
    for _ in range(runs):
        start = time.perf_counter()
        result = call()
        wall.append(time.perf_counter() - start)
        t = pe.last_timing()
        native.append(t['native_seconds'])
        algorithm.append(t['algorithm_seconds'])
    return statistics.median(wall), statistics.median(native), statistics.median(algorithm), result


def random_interior(V, F, border_uv, seed):
    """The border of `border_uv`, interior vertices uniformly at random in the disk of radius 1/2
    (inside the border polygon of a circle border with at least 6 vertices)."""
    rng = np.random.default_rng(seed)
    uv = border_uv.copy()
    interior = np.setdiff1d(np.arange(len(V)), border_vertices(F))
    r = 0.5 * np.sqrt(rng.random(len(interior)))
    a = 2 * np.pi * rng.random(len(interior))
    uv[interior] = np.c_[r * np.cos(a), r * np.sin(a)]
    return uv


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--data-dir', default=os.environ.get('PE_DATA_DIR', os.path.join(ROOT, 'build', 'cgal_data', 'data')),
                        help="libcgal-demo's data (meshes/dino.off); default $PE_DATA_DIR or build/cgal_data/data")
    parser.add_argument('--grid', type=int, default=256, help='the large disk: an N x N grid (default 256)')
    parser.add_argument('--runs', type=int, default=5, help='runs per operation (default 5; the median is kept)')
    parser.add_argument('--iterations', type=int, default=50, help='optimization iterations per run (default 50)')
    parser.add_argument('--out', default=os.path.join(ROOT, 'benchmark', 'results', 'python_vs_cpp'),
                        help='output prefix (default benchmark/results/python_vs_cpp)')
    args = parser.parse_args()

    V, F = read_off(os.path.join(args.data_dir, 'meshes', 'dino.off'))
    F, dino_border = thingi_cut(V, F, 8)
    cases = [('dino.off seed 8 (thingi)', V, F, dino_border)]
    Vg, Fg = grid_disk(args.grid)
    cases.append(('grid %dx%d (circle border)' % (args.grid, args.grid), Vg, Fg, 'circle'))

    rows = []
    for name, V, F, border in cases:
        print(name, ': %d vertices, %d faces' % (len(V), len(F)), flush=True)
        ops = []
        t = measure(lambda: pe.tutte(V, F, border=border), args.runs)
        uv = t[3]
        ops.append(('tutte', t))
        c = measure(lambda: pe.check(V, F, uv), args.runs)
        ops.append(('check', c))
        start = uv if not c[3]['valid'] else random_interior(V, F, uv, 0)
        what = 'Tutte map' if not c[3]['valid'] else 'random interior'
        u = measure(lambda: pe.untangle(V, F, start, optimize=False), args.runs)
        ops.append(('untangle (repair of the %s)' % what, u))
        repaired = u[3]
        o = measure(lambda: pe.optimize(V, F, repaired, iterations=args.iterations, tolerance=0), args.runs)
        ops.append(('optimize (%d iterations)' % args.iterations, o))
        assert pe.check(V, F, o[3])['valid'], 'the optimized map must be valid'
        for op, (wall, native, algorithm, _) in ops:
            rows.append({'input': name, 'vertices': len(V), 'faces': len(F), 'operation': op,
                         'python_s': wall, 'native_s': native, 'algorithm_s': algorithm,
                         'conversion_s': wall - native, 'mesh_and_copy_s': native - algorithm,
                         'overhead_percent': 100.0 * (wall - algorithm) / algorithm if algorithm > 0 else float('nan')})
            print('  %-42s python %9.4f s  native %9.4f s  algorithm %9.4f s' % (op, wall, native, algorithm), flush=True)

    now = datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')
    load = ' '.join('%.2f' % x for x in os.getloadavg())
    command = ' '.join([sys.executable, os.path.relpath(os.path.abspath(sys.argv[0]), ROOT)] + sys.argv[1:])
    if os.environ.get('PYTHONPATH'):
        command = 'PYTHONPATH=%s %s' % (os.environ['PYTHONPATH'], command)
    header = [
        'machine: %s, %d cores, %s; load average at the end %s' % (cpu_model(), os.cpu_count(), platform.platform(), load),
        'Python %s, NumPy %s, progressive_embedding %s' % (platform.python_version(), np.__version__, pe.__version__),
        'date: %s' % now,
        'command (from the repository): %s' % command,
        'median of %d runs per operation' % args.runs,
    ]
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    fields = ['input', 'vertices', 'faces', 'operation', 'python_s', 'native_s', 'algorithm_s', 'conversion_s',
              'mesh_and_copy_s', 'overhead_percent']
    with open(args.out + '.csv', 'w', newline='') as f:
        for line in header:
            f.write('# ' + line + '\n')
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow({k: ('%.6g' % v if isinstance(v, float) else v) for k, v in r.items()})
    with open(args.out + '.md', 'w') as f:
        f.write('# Python module against the C++ functions it calls\n\n')
        for line in header:
            f.write('- ' + line + '\n')
        f.write('\nSeconds, medians. *python*: the wall time of the Python call; *native*: the part run in C++ without '
                'the GIL (building the `Surface_mesh` from the arrays, the algorithm, copying the result); '
                '*algorithm*: the package\'s C++ functions alone, what a C++ caller with a `Surface_mesh` pays. '
                '*overhead*: (python - algorithm) / algorithm.\n\n')
        f.write('| input | vertices | operation | python | native | algorithm | overhead |\n')
        f.write('|---|---|---|---|---|---|---|\n')
        for r in rows:
            f.write('| %s | %d | %s | %.4f | %.4f | %.4f | %.1f%% |\n' % (
                r['input'], r['vertices'], r['operation'], r['python_s'], r['native_s'], r['algorithm_s'],
                r['overhead_percent']))
    print('wrote %s.csv and %s.md' % (args.out, args.out))


if __name__ == '__main__':
    main()
