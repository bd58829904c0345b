# Copyright (c) 2026 Progressive_embedding contributors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
"""Tests of the Python module `progressive_embedding` (pytest).

The module is found through PYTHONPATH (the build's python/ directory), libcgal-demo's meshes through
PE_DATA_DIR (the build's cgal_data/data); ctest's `python_module` sets both.

The helpers (OFF reader, grid disk, the Tutte-failure protocol) are also used by
benchmark/Progressive_embedding/python_timings.py.
"""

import os
import threading
import time

import numpy as np
import pytest

import progressive_embedding as pe


# ---- helpers --------------------------------------------------------------------------------

def read_off(path):
    """V (n x 3 float64) and F (m x 3 int64) of a triangle OFF file (COFF colours, comments ignored)."""
    with open(path) as f:
        lines = [line.split('#', 1)[0].split() for line in f]
    lines = [line for line in lines if line]
    header, rest = lines[0], lines[1:]
    if not header[0].endswith('OFF'):
        raise ValueError(path + ': not an OFF file')
    counts = header[1:] if len(header) > 1 else rest.pop(0)
    nv, nf = int(counts[0]), int(counts[1])
    V = np.array([[float(x) for x in line[:3]] for line in rest[:nv]], dtype=np.float64)
    faces = rest[nv:nv + nf]
    if any(int(line[0]) != 3 for line in faces):
        raise ValueError(path + ': triangles expected')
    F = np.array([[int(x) for x in line[1:4]] for line in faces], dtype=np.int64)
    return V, F


def grid_disk(n):
    """n x n grid on [0,1]^2 (z = 0), each square split along a diagonal (as `pe generate grid`)."""
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    V = np.c_[x.ravel(), y.ravel(), np.zeros(n * n)]
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1))
    a = (j * n + i).ravel()
    b, c, d = a + 1, a + n + 1, a + n
    F = np.r_[np.c_[a, b, c], np.c_[a, c, d]].astype(np.int64)
    return V, F


def border_vertices(F):
    """The vertices on an edge that only one face has."""
    E = np.sort(np.r_[F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]], axis=1)
    edges, count = np.unique(E, axis=0, return_counts=True)
    return np.unique(edges[count == 1])


class Mt19937:
    """std::mt19937 (32-bit Mersenne twister seeded as the C++ constructor does)."""

    def __init__(self, seed):
        self.mt = [seed & 0xffffffff]
        for i in range(1, 624):
            prev = self.mt[-1]
            self.mt.append((1812433253 * (prev ^ (prev >> 30)) + i) & 0xffffffff)
        self.index = 624

    def __call__(self):
        if self.index >= 624:
            mt = self.mt
            for i in range(624):
                y = (mt[i] & 0x80000000) | (mt[(i + 1) % 624] & 0x7fffffff)
                mt[i] = mt[(i + 397) % 624] ^ (y >> 1) ^ (0x9908b0df if y & 1 else 0)
            self.index = 0
        y = self.mt[self.index]
        self.index += 1
        y ^= y >> 11
        y ^= (y << 7) & 0x9d2c5680
        y ^= (y << 15) & 0xefc60000
        return y ^ (y >> 18)


def uniform_index(gen, n):
    """std::uniform_int_distribution<size_t>(0, n - 1)(gen) of GCC's libstdc++ (Lemire's method)."""
    product = gen() * n
    if (product & 0xffffffff) < n:
        threshold = (1 << 32) % n
        while (product & 0xffffffff) < threshold:
            product = gen() * n
    return product >> 32


def thingi_cut(V, F, seed):
    """The Tutte-failure protocol (`pe thingi`): removes one face of the closed mesh (seed 0: the last,
    else drawn from mt19937(seed)) and pins its three vertices at (0,0), (1/2, sqrt(3)/2), (1,0).
    Returns the faces left and the fixed border as an (n, 2) array (zero off the border)."""
    k = len(F) - 1 if seed == 0 else uniform_index(Mt19937(seed), len(F))
    pinned = F[k]
    border = np.zeros((len(V), 2))
    border[pinned[0]] = (0, 0)
    border[pinned[1]] = (0.5, np.sqrt(3) / 2)
    border[pinned[2]] = (1, 0)
    return np.delete(F, k, axis=0), border


def data_mesh(name):
    data = os.environ.get('PE_DATA_DIR')
    if not data:
        pytest.skip('PE_DATA_DIR is not set (the build sets it to its cgal_data/data)')
    return read_off(os.path.join(data, 'meshes', name))


CERTIFICATE_KEYS = {'valid', 'flipped', 'degenerate', 'faces', 'vertices', 'border_vertices', 'non_finite',
                    'border_simple', 'overlapping_pairs', 'clockwise', 'min_signed_area', 'max_energy_3d',
                    'mean_energy_3d'}


def assert_certified(V, F, UV):
    r = pe.check(V, F, UV)
    assert r['valid'] is True
    assert r['flipped'] == 0 and r['degenerate'] == 0 and r['non_finite'] == 0
    assert r['border_simple'] is True and r['overlapping_pairs'] == 0
    assert r['min_signed_area'] > 0
    assert r['faces'] == len(F) and r['vertices'] == len(V)
    return r


@pytest.fixture(scope='module')
def mushroom():
    return data_mesh('mushroom.off')


@pytest.fixture(scope='module')
def dino_seed8():
    V, F = data_mesh('dino.off')
    F2, border = thingi_cut(V, F, 8)
    return V, F2, border


# ---- the module ------------------------------------------------------------------------------

def test_module():
    assert isinstance(pe.__version__, str) and pe.__version__.count('.') == 2
    assert issubclass(pe.Error, RuntimeError)
    for f in (pe.tutte, pe.check, pe.untangle, pe.embed, pe.optimize, pe.measure, pe.constrain):
        assert f.__doc__ and len(f.__doc__) > 100
    assert pe.__doc__ and pe.Error.__doc__


# ---- tutte and check -------------------------------------------------------------------------

@pytest.mark.parametrize('weights', ['uniform', 'mean_value'])
def test_tutte_grid(weights):
    V, F = grid_disk(20)
    UV = pe.tutte(V, F, weights=weights)
    assert UV.shape == (400, 2) and UV.dtype == np.float64
    r = assert_certified(V, F, UV)
    assert CERTIFICATE_KEYS <= set(r)
    assert r['border_vertices'] == 4 * 19 and r['faces'] == 2 * 19 * 19
    b = border_vertices(F)
    assert np.allclose(np.hypot(UV[b, 0], UV[b, 1]), 1)


def test_tutte_fixed_border_and_index_dtypes():
    V, F = grid_disk(15)  # 225 vertices: uint8 indices
    UV = pe.tutte(V, F)
    for dtype in (np.int32, np.uint32, np.int16, np.uint16, np.uint8):
        assert np.array_equal(pe.tutte(V, F.astype(dtype)), UV)
    # Python lists are converted like np.asarray
    assert np.array_equal(pe.tutte(V.tolist(), F.tolist()), UV)
    # a uint64 index beyond int64 is refused and named as it was given
    huge = F.astype(np.uint64)
    huge[3, 1] = np.uint64(2**64 - 1)
    with pytest.raises(ValueError, match='holds the index 18446744073709551615, out of range'):
        pe.tutte(V, huge)
    # a fixed border: the border rows of the array, bit-exactly; interior rows ignored
    border = UV.copy()
    interior = np.setdiff1d(np.arange(len(V)), border_vertices(F))
    border[interior] = np.nan
    UV2 = pe.tutte(V, F, border=border)
    b = border_vertices(F)
    assert np.array_equal(UV2[b], UV[b])
    assert_certified(V, F, UV2)


@pytest.mark.parametrize('border', ['circle', 'square', 'triangle'])
def test_tutte_mushroom(mushroom, border):
    V, F = mushroom
    assert V.shape == (2337, 3) and F.shape == (4608, 3)
    UV = pe.tutte(V, F, border=border)
    r = assert_certified(V, F, UV)
    assert r['border_vertices'] == len(border_vertices(F))
    assert r['has_3d_energy'] and np.isfinite(r['mean_energy_3d']) and r['mean_energy_3d'] >= 4
    b = border_vertices(F)
    if border == 'circle':
        assert np.allclose(np.hypot(UV[b, 0], UV[b, 1]), 1)
    if border == 'square':
        assert UV.min() == 0 and UV.max() == 1


def test_check_counts_a_flipped_face():
    V, F = grid_disk(6)
    UV = V[:, :2].copy()
    assert_certified(V, F, UV)
    UV[14] = UV[21] + (UV[21] - UV[14])  # an interior vertex thrown past its neighbour
    r = pe.check(V, F, UV)
    assert r['valid'] is False and r['flipped'] > 0
    UV[14] = np.nan
    r = pe.check(V, F, UV)
    assert r['valid'] is False and r['non_finite'] == 1


# ---- the Tutte failure: dino.off seed 8 ------------------------------------------------------

def test_thingi_dino_seed8_untangle(dino_seed8):
    V, F, border = dino_seed8
    b = border_vertices(F)
    assert len(b) == 3
    UV = pe.tutte(V, F, border=border)
    r = pe.check(V, F, UV)
    # the README's main job: double Tutte flips 1836 faces and flattens 394
    assert r['valid'] is False and r['flipped'] == 1836 and r['degenerate'] == 394
    assert np.array_equal(UV[b], border[b])

    repaired = pe.untangle(V, F, UV, optimize=False)
    assert_certified(V, F, repaired)
    assert np.array_equal(repaired[b], UV[b])

    # the default untangle (repair, then optimization) runs without the GIL: Python keeps running
    result = {}
    worker = threading.Thread(target=lambda: result.setdefault('uv', pe.untangle(V, F, UV)))
    ticks = 0
    start = time.perf_counter()
    worker.start()
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    seconds = time.perf_counter() - start
    worker.join()
    optimized = result['uv']
    r = assert_certified(V, F, optimized)
    assert np.array_equal(optimized[b], UV[b])
    if seconds > 0.5:
        assert ticks > 50, 'the main thread was blocked during untangle()'
    energy_repaired = pe.measure(V, F, repaired)['mean_symmetric_dirichlet']
    energy_optimized = pe.measure(V, F, optimized)['mean_symmetric_dirichlet']
    assert energy_optimized < energy_repaired / 1000 and 4 <= energy_optimized < 200


def test_embed_dino_seed8(dino_seed8):
    V, F, border = dino_seed8
    b = border_vertices(F)
    UV = pe.embed(V, F, border=border, optimize=False)
    assert_certified(V, F, UV)
    assert np.array_equal(UV[b], border[b])


def test_embed_valid_tutte_is_kept(mushroom):
    V, F = mushroom
    # no repair needed and no optimization: embed() returns Tutte's map itself
    assert np.array_equal(pe.embed(V, F, optimize=False), pe.tutte(V, F))
    UV = pe.embed(V, F, border='square')
    assert_certified(V, F, UV)


# ---- optimize and measure --------------------------------------------------------------------

def test_optimize_keeps_fixed_vertices(mushroom):
    V, F = mushroom
    UV = pe.tutte(V, F)
    b = border_vertices(F)
    interior = np.setdiff1d(np.arange(len(V)), b)
    fixed = interior[::97].astype(np.int32)
    before = pe.measure(V, F, UV)['mean_symmetric_dirichlet']
    out = pe.optimize(V, F, UV, fixed=fixed, iterations=200)
    assert_certified(V, F, out)
    assert np.array_equal(out[fixed], UV[fixed])
    assert np.array_equal(out[b], UV[b])
    moved = np.setdiff1d(interior, fixed)
    assert np.any(out[moved] != UV[moved])
    after = pe.measure(V, F, out)['mean_symmetric_dirichlet']
    assert after < before

    free = pe.optimize(V, F, UV, free_border=True, iterations=200)
    assert_certified(V, F, free)
    assert np.any(free[b] != UV[b])
    assert pe.measure(V, F, free)['mean_symmetric_dirichlet'] < after


def test_measure(mushroom):
    V, F = grid_disk(10)
    m = pe.measure(V, F, V[:, :2])  # the grid's own layout: an isometry
    keys = {'faces', 'max_symmetric_dirichlet', 'mean_symmetric_dirichlet', 'symmetric_dirichlet_median',
            'symmetric_dirichlet_p90', 'symmetric_dirichlet_p99', 'max_conformal', 'mean_conformal', 'max_area',
            'mean_area', 'max_energy_3d', 'mean_energy_3d'}
    assert keys <= set(m)
    assert m['faces'] == len(F)
    assert m['mean_symmetric_dirichlet'] == pytest.approx(4) and m['max_symmetric_dirichlet'] == pytest.approx(4)
    assert m['mean_conformal'] == pytest.approx(2) and m['mean_area'] == pytest.approx(1)

    V, F = mushroom
    UV = pe.tutte(V, F)
    m, c = pe.measure(V, F, UV), pe.check(V, F, UV)
    assert m['mean_energy_3d'] == c['mean_energy_3d'] == m['mean_symmetric_dirichlet']
    assert m['max_energy_3d'] == c['max_energy_3d']
    assert 4 < m['symmetric_dirichlet_median'] <= m['symmetric_dirichlet_p90'] <= m['max_symmetric_dirichlet']


# ---- constrain -------------------------------------------------------------------------------

def test_constrain_mushroom(mushroom):
    V, F = mushroom
    interior = np.setdiff1d(np.arange(len(V)), border_vertices(F))
    idx = np.random.default_rng(0).choice(interior, 3, replace=False)
    targets = np.array([[0.0, 0.0], [0.3, 0.0], [0.0, 0.3]])
    V2, F2, UV2, info = pe.constrain(V, F, border='circle', constraints=(idx, targets))
    n = len(V)
    assert info['valid'] is True and info['flipped'] == 0 and info['degenerate'] == 0
    assert info['constraints_exact'] is True and info['constraint_error'] == 0
    assert np.array_equal(UV2[idx], targets)
    assert_certified(V2, F2, UV2)  # certified again, independently
    # the original vertices first, unchanged; the Steiner vertices after, on the input surface
    assert len(V2) == n + info['steiner_vertices'] and np.array_equal(V2[:n], V)
    assert F2.dtype == np.int64 and len(F2) == len(F) + 2 * info['steiner_vertices']
    s = info['steiner_indices']
    assert len(s) == info['steiner_vertices'] and np.array_equal(s, np.arange(n, len(V2)))
    for k, row in enumerate(s):
        corners, weights = info['steiner_corners'][k], info['steiner_weights'][k]
        used = corners >= 0
        assert weights[used].sum() == pytest.approx(1)
        assert np.allclose(V2[row], weights[used] @ V[corners[used]])
    assert info['patches'] >= 1 and info['paths'] >= 3

    # the border of a given map, kept bit-exactly (interior rows ignored)
    UV = pe.tutte(V, F, border='square')
    UV[interior] = 7.0
    V3, F3, UV3, info3 = pe.constrain(V, F, UV, constraints=(idx, targets + 0.5))
    b = border_vertices(F)
    assert np.array_equal(UV3[b], UV[b]) and np.array_equal(UV3[idx], targets + 0.5)
    assert info3['constraints_exact'] is True
    assert_certified(V3, F3, UV3)


def test_constrain_errors(mushroom):
    V, F = mushroom
    b = border_vertices(F)
    interior = np.setdiff1d(np.arange(len(V)), b)
    with pytest.raises(pe.Error) as e:
        pe.constrain(V, F, border='circle', constraints=([b[0]], [[0.0, 0.0]]))
    assert e.value.code == 'ERROR_CONSTRAINT_ON_BORDER'
    with pytest.raises(pe.Error) as e:
        pe.constrain(V, F, border='circle', constraints=(interior[:2], [[0.0, 0.0], [0.0, 0.0]]))
    assert e.value.code == 'ERROR_DUPLICATE_CONSTRAINT'
    with pytest.raises(pe.Error) as e:
        pe.constrain(V, F, border='square', constraints=(interior[:1], [[2.0, 0.5]]))
    assert e.value.code == 'ERROR_CONSTRAINT_OUTSIDE_DOMAIN'
    with pytest.raises(ValueError):
        pe.constrain(V, F, constraints=(interior[:1], [[0.0, 0.0]]))  # no border given
    with pytest.raises(ValueError):
        pe.constrain(V, F, border='circle', constraints=(interior[:2], [[0.0, 0.0]]))  # 2 indices, 1 target


# ---- errors ----------------------------------------------------------------------------------

TETRAHEDRON_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
TETRAHEDRON_F = np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])


def test_closed_mesh_is_not_a_disk():
    V, F = TETRAHEDRON_V, TETRAHEDRON_F
    UV = np.zeros((4, 2))
    calls = [lambda: pe.tutte(V, F), lambda: pe.embed(V, F), lambda: pe.check(V, F, UV),
             lambda: pe.untangle(V, F, UV), lambda: pe.measure(V, F, UV),
             lambda: pe.constrain(V, F, border='circle')]
    for call in calls:
        with pytest.raises(pe.Error) as e:
            call()
        assert e.value.code == 'ERROR_NOT_A_DISK'
        assert str(e.value).startswith('ERROR_NOT_A_DISK: ')
        assert isinstance(e.value, RuntimeError)


def test_non_finite_and_non_manifold():
    V, F = grid_disk(5)
    V[7, 2] = np.nan
    with pytest.raises(pe.Error) as e:
        pe.tutte(V, F)
    assert e.value.code == 'ERROR_NON_FINITE_COORDINATES'
    V, F = grid_disk(5)
    V[3, 0] = np.inf
    with pytest.raises(pe.Error) as e:
        pe.embed(V, F)
    assert e.value.code == 'ERROR_NON_FINITE_COORDINATES'
    # a NaN on the border of the map to repair
    V, F = grid_disk(5)
    UV = V[:, :2].copy()
    UV[0] = np.nan
    with pytest.raises(pe.Error) as e:
        pe.untangle(V, F, UV)
    assert e.value.code == 'ERROR_NON_FINITE_COORDINATES'
    # a third face on one edge, a face repeating a vertex
    V, F = grid_disk(5)
    V = np.r_[V, [[0.5, 0.5, 1.0]]]
    with pytest.raises(pe.Error) as e:
        pe.tutte(V, np.r_[F, [[F[0, 0], F[0, 1], 25]]])
    assert e.value.code == 'ERROR_NON_MANIFOLD'
    with pytest.raises(pe.Error) as e:
        pe.tutte(V[:25], np.r_[F, [[3, 3, 4]]])
    assert e.value.code == 'ERROR_NON_MANIFOLD'


def test_optimize_refuses_an_invalid_map(dino_seed8):
    V, F, border = dino_seed8
    UV = pe.tutte(V, F, border=border)
    with pytest.raises(pe.Error) as e:
        pe.optimize(V, F, UV)
    assert e.value.code == 'ERROR_INVALID_EMBEDDING'


def test_value_errors():
    V, F = grid_disk(4)
    UV = V[:, :2].copy()
    with pytest.raises(ValueError):
        pe.tutte(V[:, :2], F)  # V must be n x 3
    with pytest.raises(ValueError):
        pe.tutte(V, F[:, :2])  # F must be m x 3
    with pytest.raises(ValueError):
        pe.tutte(V, F.astype(np.float64))  # F must be integer
    with pytest.raises(ValueError):
        pe.tutte(V.astype(np.complex128), F)
    with pytest.raises(ValueError):
        pe.tutte(V, np.r_[F, [[0, 1, 16]]])  # index out of range
    with pytest.raises(ValueError):
        pe.tutte(V, F - 1)  # negative index
    with pytest.raises(ValueError):
        pe.tutte(V, F, border='hexagon')
    with pytest.raises(ValueError):
        pe.tutte(V, F, weights='cotangent')
    with pytest.raises(ValueError):
        pe.check(V, F, UV[:-1])  # one row per vertex
    with pytest.raises(ValueError):
        pe.check(V, F, V)  # UV must be n x 2
    with pytest.raises(ValueError):
        pe.optimize(V, F, UV, fixed=[0, 16])
    with pytest.raises(ValueError):
        pe.optimize(V, F, UV, fixed=[[0, 1]])
    with pytest.raises(ValueError):
        pe.optimize(V, F, UV, tolerance=-1)
    with pytest.raises(ValueError):
        pe.check(V, 'faces', UV)
