# Copyright (c) 2026 Progressive_embedding contributors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
"""Tests of progressive_embedding.cross_parameterization() (pytest): identical grids, two grids of one
square, a grid and its quarter turn (border_vertex_pair), mushroom.off against itself, every error.

The grids are flat squares: both certified maps are then the grids themselves up to rounding, so the image
of a vertex of A is known (its own 3D point) and the tolerances can be tight."""

import numpy as np
import pytest

import progressive_embedding as pe
from test_progressive_embedding import (TETRAHEDRON_F, TETRAHEDRON_V, border_vertices, data_mesh,
                                        grid_disk)


def interior_vertices(V, F):
    return np.setdiff1d(np.arange(len(V)), border_vertices(F))


def images(faces, barycentric, V_b, F_b):
    """The 3D points of the locations on B (rows of F_b, coordinates in the order of its columns)."""
    return np.einsum('ij,ijk->ik', barycentric, V_b[F_b[faces]])


def own_weight(faces, barycentric, F_b, partner):
    """The coordinate of vertex partner[i] of B in the location of vertex i of A (-1 if not a corner)."""
    w = np.full(len(faces), -1.0)
    for i, (f, p) in enumerate(zip(faces, partner)):
        column = np.flatnonzero(F_b[f] == p)
        if len(column):
            w[i] = barycentric[i, column[0]]
    return w


def assert_landmarks_exact(faces, barycentric, F_b, landmarks):
    for a, b in landmarks:
        row = barycentric[a]
        column = np.flatnonzero(F_b[faces[a]] == b)
        assert len(column) == 1 and row[column[0]] == 1.0
        assert np.count_nonzero(row) == 1  # the other two coordinates are exact zeros


def assert_result(faces, barycentric, info, n_a, F_b):
    assert faces.shape == (n_a,) and faces.dtype == np.int64
    assert barycentric.shape == (n_a, 3) and barycentric.dtype == np.float64
    assert faces.min() >= 0 and faces.max() < len(F_b)
    assert barycentric.min() >= 0 and np.abs(barycentric.sum(axis=1) - 1).max() <= 1e-15
    assert info['status'] == 'OK' and info['valid'] is True
    assert info['valid_a'] is True and info['valid_b'] is True and info['landmarks_exact'] is True
    assert info['certificate_a']['valid'] is True and info['certificate_b']['valid'] is True
    assert info['vertices_a'] == n_a and info['faces_b'] == len(F_b)
    assert info['in_face'] + info['on_edge'] + info['on_vertex'] == n_a
    assert 0 <= info['seconds_total'] and info['map_b']['optimization_status'] == 'OK'


def test_documented():
    doc = pe.cross_parameterization.__doc__
    assert 'cross_parameterization(V_a, F_a, V_b, F_b, landmarks=None' in doc and len(doc) > 1000


# ---- identical meshes ------------------------------------------------------------------------

def test_identical_grids_few_landmarks():
    V, F = grid_disk(9)
    interior = interior_vertices(V, F)
    landmarks = np.c_[interior[[3, 20, 40]], interior[[3, 20, 40]]]
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, landmarks, b_to_a=True)
    assert_result(faces, barycentric, info, len(V), F)
    assert info['landmarks'] == 3 and info['vertices_added_a'] == 0
    # every vertex in a face of B around its own vertex, its coordinate there 1 within 1e-9
    w = own_weight(faces, barycentric, F, np.arange(len(V)))
    assert w.min() >= 1 - 1e-9
    assert np.abs(images(faces, barycentric, V, F) - V).max() <= 1e-9
    assert_landmarks_exact(faces, barycentric, F, landmarks)
    # the border vertices too: both borders are placed alike
    assert np.all(w[border_vertices(F)] == 1.0)
    # the other direction, the same on the grid
    assert info['located_b_on_a'] == len(V)
    back_faces, back = info['b_to_a_faces'], info['b_to_a_barycentric']
    assert back_faces.shape == (len(V),) and back.shape == (len(V), 3)
    assert own_weight(back_faces, back, F, np.arange(len(V))).min() >= 1 - 1e-9
    assert_landmarks_exact(back_faces, back, F, landmarks[:, ::-1])


def test_identical_grids_every_interior_vertex_a_landmark():
    V, F = grid_disk(7)
    interior = interior_vertices(V, F)
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.c_[interior, interior])
    assert_result(faces, barycentric, info, len(V), F)
    # every vertex exactly on its own vertex
    assert np.all(own_weight(faces, barycentric, F, np.arange(len(V))) == 1.0)
    assert info['on_vertex'] == len(V)


def test_identical_mushroom():
    V, F = data_mesh('mushroom.off')
    interior = interior_vertices(V, F)
    chosen = interior[np.linspace(0, len(interior) - 1, 5).astype(int)]
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.c_[chosen, chosen])
    assert_result(faces, barycentric, info, len(V), F)
    assert_landmarks_exact(faces, barycentric, F, np.c_[chosen, chosen])
    assert np.all(own_weight(faces, barycentric, F, np.arange(len(V)))[border_vertices(F)] == 1.0)
    # the other vertices near themselves (the bound of the C++ test: 2e-3 of the diagonal on average)
    error = np.linalg.norm(images(faces, barycentric, V, F) - V, axis=1) / np.linalg.norm(np.ptp(V, axis=0))
    assert error.mean() < 2e-3
    # the composed distortion ran (the default) and measured an isometry (both maps made alike: it starts there);
    # composed=False skips it
    assert info['composed'] and info['composed_status'] == 'OK' and 4 <= info['composed_energy'] < 4.01
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.c_[chosen, chosen], composed=False)
    assert_result(faces, barycentric, info, len(V), F)
    assert not info['composed'] and 'composed_iterations' not in info
    # B's map made again with its landmarks pinned (the default, matched=True); matched=False keeps the first one
    assert info['matched_b'] and info['matched_status'] == 'OK' and info['vertices_added_b'] == 0
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.c_[chosen, chosen], matched=False)
    assert_result(faces, barycentric, info, len(V), F)
    assert_landmarks_exact(faces, barycentric, F, np.c_[chosen, chosen])
    assert not info['matched_b'] and info['vertices_added_b'] == 0


# ---- two different meshes --------------------------------------------------------------------

def test_two_grids_of_one_square():
    V_a, F_a = grid_disk(9)    # spacing 1/8
    V_b, F_b = grid_disk(13)   # spacing 1/12: the points at multiples of 1/4 are vertices of both
    landmarks = np.array([[2 * 9 + 2, 3 * 13 + 3], [4 * 9 + 4, 6 * 13 + 6], [6 * 9 + 2, 9 * 13 + 3]], dtype=np.int32)
    faces, barycentric, info = pe.cross_parameterization(V_a, F_a, V_b, F_b, landmarks, b_to_a=True)
    assert_result(faces, barycentric, info, len(V_a), F_b)
    assert_landmarks_exact(faces, barycentric, F_b, landmarks)
    # each vertex of A lands on its own 3D point of B, and each vertex of B on its own point of A
    assert np.abs(images(faces, barycentric, V_b, F_b) - V_a).max() <= 1e-9
    back_faces, back = info['b_to_a_faces'], info['b_to_a_barycentric']
    assert np.abs(back.sum(axis=1) - 1).max() <= 1e-12
    assert np.abs(images(back_faces, back, V_a, F_a) - V_b).max() <= 1e-9
    assert_landmarks_exact(back_faces, back, F_a, landmarks[:, ::-1])


def signed_areas(P, T):
    """Twice the signed area of each triangle T of the planar points P (the first two columns)."""
    a, b, c = P[T[:, 0], :2], P[T[:, 1], :2], P[T[:, 2], :2]
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def test_compatible_meshes_and_planar_maps():
    V_a, F_a = grid_disk(9)
    V_b, F_b = grid_disk(13)
    landmarks = np.array([[2 * 9 + 2, 3 * 13 + 3], [4 * 9 + 4, 6 * 13 + 6], [6 * 9 + 2, 9 * 13 + 3]])
    faces, barycentric, info = pe.cross_parameterization(V_a, F_a, V_b, F_b, landmarks, compatible=True,
                                                         planar_maps=True)
    assert_result(faces, barycentric, info, len(V_a), F_b)
    # the overlay: certified, one connectivity for both meshes
    assert info['valid_compatible'] is True and info['certificate_compatible']['valid'] is True
    assert info['certificate_compatible']['flipped'] == 0 and info['certificate_compatible']['degenerate'] == 0
    m, f = info['compatible_vertices'], info['compatible_faces']
    Va2, Vb2, F2 = info['compatible_V_a'], info['compatible_V_b'], info['compatible_F']
    assert Va2.shape == (m, 3) and Vb2.shape == (m, 3) and F2.shape == (f, 3) and F2.dtype == np.int64
    assert F2.min() == 0 and F2.max() == m - 1 and info['overlay_crossings'] > 0 and m > len(V_b)
    # every vertex of A is one of A', every vertex of B one of B', a landmark at one row of both
    rows_a = {tuple(p): i for i, p in enumerate(Va2)}
    rows_b = {tuple(p): i for i, p in enumerate(Vb2)}
    assert all(tuple(p) in rows_a for p in V_a) and all(tuple(p) in rows_b for p in V_b)
    assert all(rows_a[tuple(V_a[a])] == rows_b[tuple(V_b[b])] for a, b in landmarks)
    # two grids of one flat square: A' and B' are the same triangles, covering the square counterclockwise
    assert np.abs(Va2 - Vb2).max() <= 1e-9
    areas = signed_areas(Va2, F2)
    assert areas.min() > 0 and abs(areas.sum() / 2 - 1) <= 1e-12
    # the planar maps: the vertices of each mesh first, every face counterclockwise, landmarks at one point
    uv_a, T_a, uv_b, T_b = info['planar_uv_a'], info['planar_F_a'], info['planar_uv_b'], info['planar_F_b']
    assert uv_a.shape == (len(V_a) + info['vertices_added_a'], 2) and T_a.shape[1] == 3
    assert uv_b.shape == (len(V_b) + info['vertices_added_b'], 2) and len(T_b) >= len(F_b)
    assert signed_areas(uv_a, T_a).min() > 0 and signed_areas(uv_b, T_b).min() > 0
    assert all(np.array_equal(uv_a[a], uv_b[b]) for a, b in landmarks)
    assert uv_a.min() >= 0 and uv_a.max() <= 1 and uv_b.min() >= 0 and uv_b.max() <= 1
    # without the flags, none of these keys
    plain = pe.cross_parameterization(V_a, F_a, V_b, F_b, landmarks)[2]
    assert not any(k.startswith(('compatible_', 'planar_')) for k in plain)


def test_border_vertex_pair():
    V, F = grid_disk(9)
    # the default pair on identical meshes: vertex 0 of A (the first border vertex) and vertex 0 of B
    given = pe.cross_parameterization(V, F, V, F, [[10, 10]], border_vertex_pair=(0, 0))
    default = pe.cross_parameterization(V, F, V, F, [[10, 10]])
    assert np.array_equal(given[0], default[0]) and np.array_equal(given[1], default[1])
    # A's corner (0,0) matched to B's corner (1,0): a quarter turn about the square's center
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, border_vertex_pair=np.array([0, 8]))
    assert_result(faces, barycentric, info, len(V), F)
    turned = np.c_[1 - V[:, 1], V[:, 0], V[:, 2]]
    assert np.abs(images(faces, barycentric, V, F) - turned).max() <= 1e-9


# ---- errors ----------------------------------------------------------------------------------

def raises(code, *args, **kwargs):
    with pytest.raises(pe.Error) as e:
        pe.cross_parameterization(*args, **kwargs)
    assert e.value.code == code and str(e.value).startswith(code + ': ')
    return str(e.value)


def test_border_landmarks():
    # the grid's corners 0, 5, 30, 35 and the border vertex 2 at their own vertices, one interior landmark
    V, F = grid_disk(6)
    landmarks = np.array([[0, 0], [14, 14], [5, 5], [35, 35], [2, 2], [30, 30]])
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, landmarks, b_to_a=True)
    assert_result(faces, barycentric, info, len(V), F)
    assert info['landmarks'] == 6 and info['border_landmarks'] == 5
    assert_landmarks_exact(faces, barycentric, F, landmarks)
    assert np.abs(images(faces, barycentric, V, F) - V).max() <= 1e-9
    # arcs of A too short for the corners B's arcs hold at the quarters of B's border (A's border from 1 to 2 is one
    # edge, B's from 1 to 17 holds the corner 5): the corners go to the landmarks or to arcs with room on both
    # borders, and the maps are certified
    for marks in ([[1, 1], [2, 17]], [[0, 0], [35, 35], [2, 23], [1, 1]], [[1, 1], [0, 31]]):
        faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.array(marks))
        assert_result(faces, barycentric, info, len(V), F)
        assert info['border_landmarks'] == len(marks)
        assert_landmarks_exact(faces, barycentric, F, marks)
        # no square through these landmarks keeps B's edges between border vertices (at the grid's corners) off
        # its sides: B's first map is made on a copy with one such edge split
        assert info['chords_split_b'] == 1 and info['vertices_added_b'] == 1
    # with border_vertex_pair as the first corner, three border landmarks are three places: A's arcs 0-1-2-3 are single
    # edges where B's are long and the other way round, so the corners are the landmarks themselves; two are too few
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, np.array([[1, 18], [2, 12], [3, 6]]),
                                                         border_vertex_pair=(0, 0))
    assert_result(faces, barycentric, info, len(V), F)
    assert_landmarks_exact(faces, barycentric, F, [[1, 18], [2, 12], [3, 6]])
    assert 'landmarks[0] = (1, 12): the vertex 1 of A leaves too few' in raises(
        'ERROR_BORDER_TOO_SHORT', V, F, V, F, [[1, 12], [2, 6]], border_vertex_pair=(0, 0))
    # out of order along B's border: 5 and 35 swapped (no orientation-preserving bijection matches them)
    message = raises('ERROR_LANDMARK_ORDER', V, F, V, F, [[0, 0], [5, 35], [35, 5]])
    assert 'landmarks[' in message and 'is out of the order of the other border landmarks along B' in message
    # the border vertex pair (matched first, like a border landmark) and two border landmarks in another cyclic
    # order along B's border: the landmark out of order is named
    message = raises('ERROR_LANDMARK_ORDER', V, F, V, F, [[5, 5], [35, 35]], border_vertex_pair=(30, 17))
    assert 'landmarks[' in message and 'is out of the order of the other border landmarks along B' in message


def grid_border_cycle(n):
    """The border vertices of grid_disk(n), counterclockwise from the vertex 0."""
    return (list(range(n)) + [i * n + n - 1 for i in range(1, n)] + [(n - 1) * n + i for i in range(n - 2, -1, -1)]
            + [i * n for i in range(n - 2, 0, -1)])


@pytest.mark.parametrize('n_a,n_b,seed', [(6, 6, 1), (5, 8, 2), (8, 4, 3)])
def test_border_landmarks_corner_places(n_a, n_b, seed):
    # random border landmarks in the same cyclic order on both borders: the square's corners need three places
    # besides the first landmark (a border landmark, or a pair of vertices inside an arc between consecutive
    # landmarks on both borders); the call succeeds, certified, exactly when the landmarks leave them
    rng = np.random.default_rng(seed)
    (V_a, F_a), (V_b, F_b) = grid_disk(n_a), grid_disk(n_b)
    ring_a, ring_b = grid_border_cycle(n_a), grid_border_cycle(n_b)
    succeeded = refused = 0
    for _ in range(40):
        m = int(rng.integers(1, 7))
        pa = sorted(rng.choice(len(ring_a), m, replace=False))
        pb = sorted(rng.choice(len(ring_b), m, replace=False))
        shift = int(rng.integers(0, m))
        qb = [pb[(i + shift) % m] for i in range(m)]
        places = m - 1 + sum(min((pa[(j + 1) % m] - pa[j] - 1) % len(ring_a) if m > 1 else len(ring_a) - 1,
                                 (qb[(j + 1) % m] - qb[j] - 1) % len(ring_b) if m > 1 else len(ring_b) - 1)
                             for j in range(m))
        marks = np.array([[ring_a[pa[i]], ring_b[qb[i]]] for i in range(m)])
        if places >= 3:
            faces, barycentric, info = pe.cross_parameterization(V_a, F_a, V_b, F_b, marks)
            assert_result(faces, barycentric, info, len(V_a), F_b)
            assert_landmarks_exact(faces, barycentric, F_b, marks)
            succeeded += 1
        else:
            assert 'leaves too few border vertices of A' in raises('ERROR_BORDER_TOO_SHORT', V_a, F_a, V_b, F_b, marks)
            refused += 1
    assert succeeded > 30


def test_errors():
    V, F = grid_disk(6)  # 36 vertices, 7 and 8 interior, 0 and 5 on the border
    # an index that is no vertex: the library's ERROR_WRONG_PARAMETER, the landmark and the mesh named
    assert 'landmarks[0] = (36, 7): 36 is not a vertex of A' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, [[36, 7]])
    assert 'landmarks[1] = (8, -1): -1 is not a vertex of B' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, [[7, 7], [8, -1]])
    # a vertex used twice, in A or in B: the later landmark named
    assert 'landmarks[1] = (7, 8): the vertex 7 of A' in raises('ERROR_DUPLICATE_CONSTRAINT', V, F, V, F, [[7, 7], [7, 8]])
    assert 'landmarks[1] = (8, 7): the vertex 7 of B' in raises('ERROR_DUPLICATE_CONSTRAINT', V, F, V, F, [[7, 7], [8, 7]])
    # a landmark with one vertex on its border and the other inside is refused
    assert 'the vertex 0 of A is on the border' in raises('ERROR_CONSTRAINT_ON_BORDER', V, F, V, F, [[7, 7], [0, 8]])
    assert 'the vertex 5 of B is on the border' in raises('ERROR_CONSTRAINT_ON_BORDER', V, F, V, F, [[7, 7], [8, 5]])
    # a border pair that is not one
    assert 'the vertex 7 of A is not on its border' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, border_vertex_pair=(7, 0))
    assert 'the vertex 14 of B is not on its border' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, border_vertex_pair=(0, 14))
    assert '99 is not a vertex of B' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, border_vertex_pair=(0, 99))
    # not disks
    assert 'mesh A (V_a, F_a): closed, and the other mesh is not' in raises('ERROR_NOT_A_DISK', TETRAHEDRON_V, TETRAHEDRON_F, V, F)
    assert 'mesh B (V_b, F_b): closed, and the other mesh is not' in raises('ERROR_NOT_A_DISK', V, F, TETRAHEDRON_V, TETRAHEDRON_F)
    raises('ERROR_BORDER_TOO_SHORT', V[:3], [[0, 1, 2]], V, F)  # a triangle: 3 border vertices for 4 corners
    # border landmarks whose arcs leave no place for the square's corners: A's border from 1 to 2 and B's from 0
    # to 1 are single edges, so a corner can only be at the landmarks themselves (two of the four): said as in
    # `pe cross`, the landmark ending the arc of A found too short named
    assert 'landmarks[1] = (2, 0): the vertex 2 of A leaves too few border vertices of A' in raises(
        'ERROR_BORDER_TOO_SHORT', V, F, V, F, [[1, 1], [2, 0]])
    # the same with the landmarks given in another order (the landmark is named by its row)
    assert 'landmarks[0] = (2, 0): the vertex 2 of A leaves too few' in raises(
        'ERROR_BORDER_TOO_SHORT', V, F, V, F, [[2, 0], [1, 1]])
    # a vertex in no face (a row of V that F does not use)
    assert 'vertex 36 is in no face of F_a' in raises('ERROR_NOT_A_DISK', np.r_[V, [[9.0, 9.0, 9.0]]], F, V, F)
    assert 'F_b[50]' in raises('ERROR_NON_MANIFOLD', V, F, V, np.r_[F, [[3, 3, 4]]])
    V_nan = V.copy()
    V_nan[3, 1] = np.nan
    assert 'V_b[3]' in raises('ERROR_NON_FINITE_COORDINATES', V, F, V_nan, F)
    raises('ERROR_BUDGET_EXHAUSTED', V, F, V, F, [[7, 7]], time_limit=0)


def test_no_landmarks():
    V, F = grid_disk(6)
    for none in (None, [], np.zeros((0, 2), dtype=np.int64)):
        faces, barycentric, info = pe.cross_parameterization(V, F, V, F, none)
        assert_result(faces, barycentric, info, len(V), F)
        assert info['landmarks'] == 0


def test_value_errors():
    V, F = grid_disk(5)
    bad = [dict(landmarks=[[7.0, 7.0]]),           # landmarks must be integers
           dict(landmarks=[7, 7]),                  # ... of shape (k, 2)
           dict(landmarks=[[6, 7, 8]]),
           dict(landmarks='6 7'),
           dict(border_vertex_pair=(0, 1, 2)),     # a pair
           dict(border_vertex_pair=(0.0, 1.0)),
           dict(time_limit=-1), dict(time_limit='soon'), dict(optimization_time_limit=-1)]
    for kwargs in bad:
        with pytest.raises(ValueError):
            pe.cross_parameterization(V, F, V, F, **kwargs)
    with pytest.raises(ValueError, match='V_b'):
        pe.cross_parameterization(V, F, V[:, :2], F)
    with pytest.raises(ValueError, match='F_a'):
        pe.cross_parameterization(V, F.astype(np.float64), V, F)
    with pytest.raises(ValueError, match='F_b'):
        pe.cross_parameterization(V, F, V, np.r_[F, [[0, 1, 25]]])  # a face index out of range
    # uint64 indices beyond int64 are named as they were given
    huge = np.array([[2**64 - 1, 7]], dtype=np.uint64)
    message = raises('ERROR_WRONG_PARAMETER', V, F, V, F, huge)
    assert 'landmarks[0] = (18446744073709551615, 7): 18446744073709551615 is not a vertex of A' in message
    message = raises('ERROR_WRONG_PARAMETER', V, F, V, F, border_vertex_pair=np.array([0, 2**64 - 2], dtype=np.uint64))
    assert 'border_vertex_pair: 18446744073709551614 is not a vertex of B' in message


def test_closed_surface_errors():
    # the octahedron (poles 0 and 5, equator 1 2 3 4) against itself, every vertex a landmark
    V = np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0, 0, -1]], dtype=np.float64)
    F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1], [5, 2, 1], [5, 3, 2], [5, 4, 3], [5, 1, 4]])
    # the chain 1 2 3 4 5, then 0: every edge path from 5 to 0 goes through a landmark
    message = raises('ERROR_PATH_TRACING_FAILED', V, F, V, F, [[1, 1], [2, 2], [3, 3], [4, 4], [5, 5], [0, 0]])
    assert 'landmarks[5] = (0, 0): the vertex 0 of A cannot be reached from the previous landmark' in message
    # the same landmarks in another order make a chain (every two landmarks are next to each other: no two make a
    # cut of their own, so the cut runs through all of them)
    landmarks = [[1, 1], [0, 0], [2, 2], [3, 3], [4, 4], [5, 5]]
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, landmarks)
    assert info['closed'] and info['landmarks_exact'] and info['valid_a'] and info['valid_b']
    assert info['cut_landmarks'] == 6
    assert_landmarks_exact(faces, barycentric, F, landmarks)
    # a vertex used twice, of A or of B: the later landmark named
    assert 'landmarks[2] = (1, 3): the vertex 1 of A is used by an earlier landmark' in raises(
        'ERROR_DUPLICATE_CONSTRAINT', V, F, V, F, [[1, 1], [5, 5], [1, 3]])
    assert 'landmarks[2] = (3, 1): the vertex 1 of B is used by an earlier landmark' in raises(
        'ERROR_DUPLICATE_CONSTRAINT', V, F, V, F, [[1, 1], [5, 5], [3, 1]])
    # an empty mesh against a closed one is empty (not "a disk against a closed mesh")
    empty_V, empty_F = V[:0], np.zeros((0, 3), dtype=np.int64)
    assert 'mesh A (V_a, F_a)' in raises('ERROR_EMPTY_MESH', empty_V, empty_F, V, F)
    assert 'mesh B (V_b, F_b)' in raises('ERROR_EMPTY_MESH', V, F, empty_V, empty_F)


def test_closed_surfaces():
    # two closed genus-0 meshes: cut into disks between two landmarks near each other, the others inside
    V, F = data_mesh('blobby.off')
    landmarks = [[0, 0], [500, 500], [1000, 1000], [1500, 1500]]
    faces, barycentric, info = pe.cross_parameterization(V, F, V, F, landmarks)
    assert info['closed'] and info['landmarks_exact']
    assert info['landmarks'] == 4 and info['cut_landmarks'] == 2 and info['border_landmarks'] == 2
    assert_landmarks_exact(faces, barycentric, F, landmarks)
    assert np.abs(images(faces, barycentric, V, F) - V).max() < 1e-2 * np.ptp(V, axis=0).max()
    # one landmark is not a chain; a chain of one edge opens nothing
    raises('ERROR_WRONG_PARAMETER', V, F, V, F, [[0, 0]])
    joined = raises('ERROR_NOT_A_DISK', V, F, V, F, [[F[0][0], F[0][0]], [F[0][1], F[0][1]]])
    assert 'landmarks[1]' in joined and 'joined to the previous landmark by an edge' in joined
    # the compatible meshes: the cut disks' overlay joined along the cut, two closed meshes of one connectivity
    same, _, info = pe.cross_parameterization(V, F, V, F, landmarks, compatible=True)
    assert np.array_equal(same, faces) and info['valid_compatible'] and info['cut_vertices_welded'] > 0
    Va, Vb, T = info['compatible_V_a'], info['compatible_V_b'], info['compatible_F']
    assert len(Va) == len(Vb) == info['compatible_vertices'] and len(T) == info['compatible_faces']
    directed = {(int(t[k]), int(t[(k + 1) % 3])) for t in T for k in range(3)}
    assert len(directed) == 3 * len(T) and all((v, u) in directed for u, v in directed)  # closed, oriented
    assert len(Va) - len(directed) // 2 + len(T) == 2  # genus 0
    kept = {tuple(p) for p in Va}
    assert all(tuple(p) in kept for p in V)  # every vertex of A (joined along the cut, else the cut were a border)
    # the planar maps are those of the cut disks: the rows of V first, then the copies on the cut
    again, _, info = pe.cross_parameterization(V, F, V, F, landmarks, planar_maps=True)
    assert np.array_equal(again, faces)
    uv_a, T_a, uv_b, T_b = info['planar_uv_a'], info['planar_F_a'], info['planar_uv_b'], info['planar_F_b']
    assert len(uv_a) == len(V) + info['cut_edges_a'] - 1 + info['vertices_added_a'] and len(T_a) >= len(F)
    assert signed_areas(uv_a, T_a).min() > 0 and signed_areas(uv_b, T_b).min() > 0
    assert all(np.array_equal(uv_a[a], uv_b[b]) for a, b in landmarks)
    # the other direction: B's vertices on A's faces, the identity too; a border pair does not apply
    again, _, info = pe.cross_parameterization(V, F, V, F, landmarks, b_to_a=True)
    assert np.array_equal(again, faces) and info['located_b_on_a'] == len(V)
    back_faces, back = info['b_to_a_faces'], info['b_to_a_barycentric']
    assert_landmarks_exact(back_faces, back, F, [[b, a] for a, b in landmarks])
    assert np.abs(images(back_faces, back, V, F) - V).max() < 1e-2 * np.ptp(V, axis=0).max()
    assert 'no border' in raises('ERROR_WRONG_PARAMETER', V, F, V, F, landmarks, border_vertex_pair=[0, 0])
