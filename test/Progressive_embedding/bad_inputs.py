#!/usr/bin/env python3
"""bad_inputs.py PE GROUP : runs the `pe` tool PE on generated malformed inputs and bad command lines
and checks each run's exact exit status and a regular expression on its stdout + stderr.

GROUP is one of the groups below, or `all`. Every run has a time limit (TIME_LIMIT seconds) and
an address-space limit (PE_BAD_INPUT_MEMORY_LIMIT_MB, default 2048 MB; 0 disables it, which
sanitizer builds need), so that an input that makes `pe` allocate without bound fails its check
instead of exhausting the machine. The inputs are written into a temporary folder.

Exit status of `pe`: 0 valid, 1 invalid map or failed algorithm, 2 bad arguments, 3 input error,
4 output error."""

import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile

TIME_LIMIT = 10  # seconds per run; every input here is tiny
MEMORY_LIMIT_MB = int(os.environ.get("PE_BAD_INPUT_MEMORY_LIMIT_MB", "2048"))

# ---- inputs --------------------------------------------------------------------------------

def off(vertices, faces, header=None):
    lines = ["OFF", header or "%d %d 0" % (len(vertices), len(faces))]
    lines += [" ".join(str(c) for c in v) for v in vertices]
    lines += [" ".join(str(i) for i in [len(f)] + list(f)) for f in faces]
    return "\n".join(lines) + "\n"

def obj(vertices, faces, uv=None):
    lines = ["v %s" % " ".join(str(c) for c in v) for v in vertices]
    if uv is None:
        lines += ["f %s" % " ".join(str(i + 1) for i in f) for f in faces]
    else:
        lines += ["vt %s" % " ".join(str(c) for c in t) for t in uv]
        lines += ["f %s" % " ".join("%d/%d" % (i + 1, i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"

def ply(vertices, faces, vertex_count=None, face_count=None):
    lines = ["ply", "format ascii 1.0",
             "element vertex %d" % (len(vertices) if vertex_count is None else vertex_count),
             "property float x", "property float y", "property float z",
             "element face %d" % (len(faces) if face_count is None else face_count),
             "property list uchar int vertex_indices", "end_header"]
    lines += [" ".join(str(c) for c in v) for v in vertices]
    lines += [" ".join(str(i) for i in [len(f)] + list(f)) for f in faces]
    return "\n".join(lines) + "\n"

def stl(vertices, faces):
    lines = ["solid s"]
    for f in faces:
        lines += ["facet normal 0 0 1", "outer loop"]
        lines += ["vertex %s" % " ".join(str(c) for c in vertices[i]) for i in f]
        lines += ["endloop", "endfacet"]
    return "\n".join(lines + ["endsolid s"]) + "\n"

# a square of two triangles (a disk) and variants
SQ_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
SQ_F = [(0, 1, 2), (0, 2, 3)]
SQ_UV = [(0, 0), (1, 0), (1, 1), (0, 1)]
# a fan of 4 triangles around an interior vertex (a disk with a free vertex)
FAN_V = SQ_V + [(0.5, 0.5, 0.25)]
FAN_F = [(0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
FAN_UV = SQ_UV + [(0.5, 0.5)]
# the closed tetrahedron (a sphere)
TET_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
# two disjoint triangles
TWO_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (5, 0, 0), (6, 0, 0), (5, 1, 0)]
TWO_F = [(0, 1, 2), (3, 4, 5)]
TWO_UV = [(0, 0), (1, 0), (0, 1), (5, 0), (6, 0), (5, 1)]
# an annulus: a square ring of 8 triangles around a square hole
ANN_V = [(0, 0, 0), (3, 0, 0), (3, 3, 0), (0, 3, 0), (1, 1, 0), (2, 1, 0), (2, 2, 0), (1, 2, 0)]
ANN_F = [(0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
# three triangles on one edge (a non-manifold edge)
NME_V = [(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -1, 0), (0.5, 0, 1)]
NME_F = [(0, 1, 2), (1, 0, 3), (0, 1, 4)]
# two fans sharing one vertex (a non-manifold vertex)
NMV_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0)]
NMV_F = [(0, 1, 2), (0, 3, 4)]
# the fan with one quad instead of two triangles
QUAD_F = [(0, 1, 2, 3)]
# the octahedron: the poles 0 and 5, the equator 1 2 3 4 (a closed genus-0 mesh where every vertex is a landmark)
OCT_V = [(0, 0, 1), (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (0, 0, -1)]
OCT_F = [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 1), (5, 2, 1), (5, 3, 2), (5, 4, 3), (5, 1, 4)]

def inputs():
    huge = 1e308
    return {
        # OFF
        "empty.off": "",
        "blank.off": "\n\n   \n",
        "truncated.off": "OFF\n4 2 0\n0 0 0\n1 0 0\n",
        "truncated_face.off": "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2\n",
        "huge_counts.off": "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "huge_degree.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n",
        "nan.off": off([(0, 0, 0), (1, "nan", 0), (1, 1, 0), (0, 1, 0)], SQ_F),
        "inf.off": off([(0, 0, 0), (1, 0, "inf"), (1, 1, 0), (0, 1, 0)], SQ_F),
        "huge_coordinates.off": off([(x * huge, y * huge, z * huge) for (x, y, z) in FAN_V], FAN_F),
        "bad_index.off": off(SQ_V, [(0, 1, 2), (0, 2, 7)]),
        "negative_index.off": off(SQ_V, [(0, 1, 2), (0, 2, -1)]),
        "quad.off": off(SQ_V, QUAD_F),
        "closed.off": off(TET_V, TET_F),
        "two_components.off": off(TWO_V, TWO_F),
        "annulus.off": off(ANN_V, ANN_F),
        "nonmanifold_edge.off": off(NME_V, NME_F),
        "nonmanifold_vertex.off": off(NMV_V, NMV_F),
        "duplicate_face.off": off(SQ_V, SQ_F + [SQ_F[0]]),
        "unreferenced.off": off(FAN_V + [(9, 9, 9)], FAN_F),
        "degenerate_3d.off": off([(0, 0, 0), (1, 0, 0), (2, 0, 0), (1, 1, 0)], [(0, 1, 2), (0, 2, 3)]),
        # OBJ without and with uv
        "truncated.obj": "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 3 4\n",
        "nan.obj": obj([(0, 0, 0), (1, "nan", 0), (1, 1, 0), (0, 1, 0)], SQ_F),
        "quad.obj": obj(SQ_V, QUAD_F),
        "closed.obj": obj(TET_V, TET_F),
        "huge_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
        "empty.obj": "",
        "fan_uv.obj": obj(FAN_V, FAN_F, FAN_UV),
        "quad_uv.obj": obj(SQ_V, QUAD_F, SQ_UV),
        "nan_uv.obj": obj(FAN_V, FAN_F, [(0, 0), (1, 0), ("nan", 1), (0, 1), (0.5, 0.5)]),
        "huge_uv.obj": obj(FAN_V, FAN_F, [(u * huge, v * huge) for (u, v) in FAN_UV]),
        "two_components_uv.obj": obj(TWO_V, TWO_F, TWO_UV),
        "bad_vt_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n",
        "square_uv.obj": obj(SQ_V, SQ_F, SQ_UV),
        # PLY (ascii)
        "huge_counts.ply": ply(SQ_V, SQ_F, vertex_count=1000000000, face_count=1000000000),
        "truncated.ply": ply(SQ_V, SQ_F, face_count=5),
        "nan.ply": ply([(0, 0, 0), ("nan", 0, 0), (1, 1, 0), (0, 1, 0)], SQ_F),
        "quad.ply": ply(SQ_V, QUAD_F),
        "closed.ply": ply(TET_V, TET_F),
        "empty.ply": "",
        # STL (ascii)
        "truncated.stl": "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n",
        "nan.stl": stl([(0, 0, 0), (1, 0, "nan"), (0, 1, 0)], [(0, 1, 2)]),
        "closed.stl": stl(TET_V, TET_F),
        "annulus.stl": stl(ANN_V, ANN_F),
        "empty.stl": "",
        # constraints for optimize --fix
        "fix_bad_line.txt": "4 0.5 0.5\n4 0.5\n",
        "fix_out_of_range.txt": "99999999999999999999 0 0\n",
        "fix_nan.txt": "4 nan 0.5\n",
        "fix_ok.txt": "# the interior vertex\n4 0.4 0.4\n",
        # constraints for constrain --fix on grid6.obj (6 x 6 vertices on [0,1]^2, uv = xy, vertex j * 6 + i at
        # (i/5, j/5): 7, 8, 13, 22 are interior, 0 and 6 on the border)
        "cfix_ok.txt": "# two interior vertices\n7 0.3 0.3\n22 0.7 0.6\n",
        "cfix_text.txt": "7 0.3 0.3\n8 abc 0.5\n",
        "cfix_missing_coordinate.txt": "7 0.3 0.3\n8 0.5\n",
        "cfix_extra_token.txt": "7 0.3 0.3 0.1\n",
        "cfix_out_of_range.txt": "36 0.5 0.5\n",
        "cfix_negative.txt": "-1 0.5 0.5\n",
        "cfix_nan.txt": "7 nan 0.5\n",
        "cfix_inf.txt": "7 0.5 inf\n",
        "cfix_overflow.txt": "7 0.5 1e400\n",
        "cfix_duplicate_vertex.txt": "7 0.3 0.3\n13 0.5 0.5\n7 0.4 0.4\n",
        "cfix_duplicate_target.txt": "7 0.3 0.3\n8 0.3 0.3\n",
        "cfix_border.txt": "8 0.5 0.5\n6 0.5 0.4\n",
        "cfix_outside.txt": "7 1.5 0.5\n",
        "cfix_on_domain_border.txt": "7 1 0.5\n",
        "cfix_fan.txt": "4 0.1 0.05\n",
        # landmark files for cross (the fan's inner vertex; the tetrahedron's vertices, all joined by edges; border
        # landmarks on grid6.obj whose arcs leave no place for the square's corners: A's border from 1 to 2 and B's
        # from 0 to 1 are single edges; and landmarks whose arc of A from 1 to 2 is too short for B's corner 5 at
        # the quarter of B's border, which then goes elsewhere: to corners that leave B's edge from 4 to 11 on one
        # side, split on B's copy)
        "fan.off": off(FAN_V, FAN_F),
        "lm_fan.txt": "4 4\n",
        "lm_one.txt": "0 0\n",
        "lm_edge.txt": "0 0\n1 1\n",
        "lm_border_short.txt": "1 1\n2 0\n",
        "lm_border_short_arc.txt": "1 1\n2 17\n",
        # the octahedron's chain 1 2 3 4 5 then 0: every edge path from 5 to 0 goes through a landmark
        "octahedron.off": off(OCT_V, OCT_F),
        "lm_trap.txt": "1 1\n2 2\n3 3\n4 4\n5 5\n0 0\n",
        "lm_closed_duplicate.txt": "1 1\n5 5\n3 1\n",
        "cfix_tet.txt": "0 0.1 0.1\n",
        "closed_uv.obj": obj(TET_V, TET_F, [(0, 0), (1, 0), (0, 1), (1, 1)]),
    }

# ---- cases: (group, name, arguments, exit status, regex) -------------------------------------
# In arguments, {t} is the folder of the inputs.

READ = "ERROR_MALFORMED_FILE"

CASES = [
    # OFF, for every command that reads a mesh without uv
    ("off", "empty", ["tutte", "{t}/empty.off", "{t}/o.obj"], 3, r"empty.off.*ERROR_EMPTY_MESH"),
    ("off", "blank", ["tutte", "{t}/blank.off", "{t}/o.obj"], 3, r"blank.off.*ERROR_EMPTY_MESH"),
    ("off", "truncated", ["tutte", "{t}/truncated.off", "{t}/o.obj"], 3, r"truncated.off.*line [0-9]+.*" + READ),
    ("off", "truncated_face", ["embed", "{t}/truncated_face.off", "{t}/o.obj"], 3, r"line 8.*" + READ),
    ("off", "huge_counts_tutte", ["tutte", "{t}/huge_counts.off", "{t}/o.obj"], 3, r"huge_counts.off.*line [0-9]+.*" + READ),
    ("off", "huge_counts_embed", ["embed", "{t}/huge_counts.off", "{t}/o.obj"], 3, r"line [0-9]+.*" + READ),
    ("off", "huge_counts_thingi", ["thingi", "{t}/huge_counts.off", "0", "{t}/o.obj"], 3, r"line [0-9]+.*" + READ),
    ("off", "huge_degree", ["tutte", "{t}/huge_degree.off", "{t}/o.obj"], 3, r"line 6.*ERROR_"),
    ("off", "nan", ["tutte", "{t}/nan.off", "{t}/o.obj"], 3, r"line 4.*ERROR_NON_FINITE_COORDINATES"),
    ("off", "inf", ["random-init", "{t}/inf.off", "{t}/o.obj", "--seed", "1"], 3, r"line 4.*ERROR_NON_FINITE_COORDINATES"),
    ("off", "bad_index", ["tutte", "{t}/bad_index.off", "{t}/o.obj"], 3, r"line 8.*out of range.*" + READ),
    ("off", "negative_index", ["tutte", "{t}/negative_index.off", "{t}/o.obj"], 3, r"line 8.*" + READ),
    ("off", "quad_tutte", ["tutte", "{t}/quad.off", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("off", "quad_embed", ["embed", "{t}/quad.off", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("off", "quad_random_init", ["random-init", "{t}/quad.off", "{t}/o.obj", "--seed", "2"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("off", "quad_thingi", ["thingi", "{t}/quad.off", "0", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("off", "huge_coordinates", ["tutte", "{t}/huge_coordinates.off", "{t}/o.obj"], 3,
     r"3D coordinates are too large.*not finite.*ERROR_NON_FINITE_COORDINATES"),
    ("off", "huge_coordinates_embed", ["embed", "{t}/huge_coordinates.off", "{t}/o.obj"], 3, r"ERROR_NON_FINITE_COORDINATES"),
    ("off", "degenerate_3d", ["tutte", "{t}/degenerate_3d.off", "{t}/o.obj"], 3,
     r"face 0 has zero 3D area.*ERROR_DEGENERATE_3D_FACE"),
    ("off", "unreferenced", ["tutte", "{t}/unreferenced.off", "{t}/o.obj"], 0, r"^tutte .*valid: faces 4"),
    # topology: not a disk where a disk is needed, not closed where the protocol needs it
    ("topology", "closed_tutte", ["tutte", "{t}/closed.off", "{t}/o.obj"], 3,
     r"not a topological disk: 1 component, 0 border cycles, Euler characteristic 2.*ERROR_NOT_A_DISK"),
    ("topology", "closed_embed", ["embed", "{t}/closed.off", "{t}/o.obj"], 3, r"not a topological disk.*ERROR_NOT_A_DISK"),
    ("topology", "two_components", ["embed", "{t}/two_components.off", "{t}/o.obj"], 3,
     r"not a topological disk: 2 components, 2 border cycles.*ERROR_NOT_A_DISK"),
    ("topology", "annulus", ["embed", "{t}/annulus.off", "{t}/o.obj"], 3,
     r"not a topological disk: 1 component, 2 border cycles, Euler characteristic 0.*ERROR_NOT_A_DISK"),
    ("topology", "annulus_random_init", ["random-init", "{t}/annulus.off", "{t}/o.obj", "--seed", "0"], 3, r"ERROR_NOT_A_DISK"),
    ("topology", "thingi_disk", ["thingi", "{t}/annulus.off", "0", "{t}/o.obj"], 3, r"not a closed genus-0 mesh.*ERROR_NOT_A_DISK"),
    ("topology", "thingi_closed", ["thingi", "{t}/closed.off", "0", "{t}/o.obj"], 0, r"^thingi .*valid: faces 3"),
    ("topology", "nonmanifold_edge", ["tutte", "{t}/nonmanifold_edge.off", "{t}/o.obj"], 3, r"ERROR_NON_MANIFOLD|ERROR_NOT_A_DISK"),
    ("topology", "nonmanifold_vertex", ["tutte", "{t}/nonmanifold_vertex.off", "{t}/o.obj"], 3, r"ERROR_NON_MANIFOLD|ERROR_NOT_A_DISK"),
    ("topology", "duplicate_face", ["tutte", "{t}/duplicate_face.off", "{t}/o.obj"], 3, r"ERROR_(NON_MANIFOLD|MALFORMED_FILE|NOT_A_DISK)"),
    ("topology", "uv_two_components_check", ["check", "{t}/two_components_uv.obj"], 3, r"not a topological disk: 2 components"),
    ("topology", "uv_two_components_untangle", ["untangle", "{t}/two_components_uv.obj", "{t}/o.obj"], 3, r"ERROR_NOT_A_DISK"),
    # OBJ: the same faults give the same status in every command
    ("obj", "empty", ["tutte", "{t}/empty.obj", "{t}/o.obj"], 3, r"ERROR_EMPTY_MESH"),
    ("obj", "truncated", ["tutte", "{t}/truncated.obj", "{t}/o.obj"], 3, r"line 5.*" + READ),
    ("obj", "nan", ["tutte", "{t}/nan.obj", "{t}/o.obj"], 3, r"line 2.*ERROR_NON_FINITE_COORDINATES"),
    ("obj", "huge_index", ["tutte", "{t}/huge_index.obj", "{t}/o.obj"], 3, r"line 4.*" + READ),
    ("obj", "quad_tutte", ["tutte", "{t}/quad.obj", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "quad_uv_tutte", ["tutte", "{t}/quad_uv.obj", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "quad_uv_check", ["check", "{t}/quad_uv.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "quad_uv_untangle", ["untangle", "{t}/quad_uv.obj", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "quad_uv_optimize", ["optimize", "{t}/quad_uv.obj", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "quad_uv_svg", ["svg", "{t}/quad_uv.obj", "{t}/o.svg"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("obj", "nan_uv_check", ["check", "{t}/nan_uv.obj"], 3, r"line [0-9]+.*ERROR_NON_FINITE_COORDINATES"),
    ("obj", "nan_uv_untangle", ["untangle", "{t}/nan_uv.obj", "{t}/o.obj"], 3, r"ERROR_NON_FINITE_COORDINATES"),
    ("obj", "huge_uv_check", ["check", "{t}/huge_uv.obj"], 3, r"uv coordinates are too large.*ERROR_NON_FINITE_COORDINATES"),
    ("obj", "bad_vt_index", ["check", "{t}/bad_vt_index.obj"], 3, r"line 6.*" + READ),
    ("obj", "closed_tutte", ["tutte", "{t}/closed.obj", "{t}/o.obj"], 3, r"ERROR_NOT_A_DISK"),
    ("obj", "no_free_vertex", ["optimize", "{t}/square_uv.obj", "{t}/o.obj"], 3, r"ERROR_NO_FREE_VERTEX"),
    ("obj", "valid_fan", ["untangle", "{t}/fan_uv.obj", "{t}/o.obj", "--json"], 0, r'"valid": true'),
    # PLY (ascii)
    ("ply", "empty", ["tutte", "{t}/empty.ply", "{t}/o.obj"], 3, r"ERROR_EMPTY_MESH"),
    ("ply", "huge_counts", ["tutte", "{t}/huge_counts.ply", "{t}/o.obj"], 3, r"huge_counts.ply.*line [0-9]+.*" + READ),
    ("ply", "truncated", ["embed", "{t}/truncated.ply", "{t}/o.obj"], 3, r"line [0-9]+.*" + READ),
    ("ply", "nan", ["tutte", "{t}/nan.ply", "{t}/o.obj"], 3, r"line 11.*ERROR_NON_FINITE_COORDINATES"),
    ("ply", "quad", ["tutte", "{t}/quad.ply", "{t}/o.obj"], 3, r"ERROR_NON_TRIANGULAR_MESH"),
    ("ply", "closed", ["embed", "{t}/closed.ply", "{t}/o.obj"], 3, r"ERROR_NOT_A_DISK"),
    # STL (ascii)
    ("stl", "empty", ["tutte", "{t}/empty.stl", "{t}/o.obj"], 3, r"ERROR_EMPTY_MESH"),
    ("stl", "truncated", ["tutte", "{t}/truncated.stl", "{t}/o.obj"], 3, r"line [0-9]+.*" + READ),
    ("stl", "nan", ["tutte", "{t}/nan.stl", "{t}/o.obj"], 3, r"line [0-9]+.*ERROR_NON_FINITE_COORDINATES"),
    ("stl", "closed", ["tutte", "{t}/closed.stl", "{t}/o.obj"], 3, r"not a topological disk.*ERROR_NOT_A_DISK"),
    ("stl", "annulus", ["embed", "{t}/annulus.stl", "{t}/o.obj"], 3, r"2 border cycles.*ERROR_NOT_A_DISK"),
    # files that are not regular files, missing files
    ("files", "missing", ["tutte", "{t}/no_such_file.off", "{t}/o.obj"], 3, r"no_such_file.off.*cannot open.*ERROR_CANNOT_READ_FILE"),
    ("files", "directory", ["tutte", "{t}/folder.off", "{t}/o.obj"], 3, r"folder.off.*directory.*ERROR_CANNOT_READ_FILE"),
    ("files", "directory_check", ["check", "{t}/folder.off"], 3, r"directory.*ERROR_CANNOT_READ_FILE"),
    ("files", "device", ["tutte", "/dev/zero", "{t}/o.obj"], 3, r"not a regular file.*ERROR_CANNOT_READ_FILE"),
    ("files", "unknown_format", ["tutte", "{t}/fix_ok.txt", "{t}/o.obj"], 3, r"unknown format.*" + READ),
    ("files", "fix_directory", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/folder.off"], 3,
     r"--fix.*directory.*ERROR_CANNOT_READ_FILE"),
    ("files", "fix_missing", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/no_such_file.txt"], 3,
     r"--fix.*No such file.*ERROR_CANNOT_READ_FILE"),
    ("files", "fix_bad_line", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/fix_bad_line.txt"], 3,
     r"--fix.*line 2.*" + READ),
    ("files", "fix_out_of_range", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/fix_out_of_range.txt"], 3,
     r"line 1.*vertex_index.*" + READ),
    ("files", "fix_nan", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/fix_nan.txt"], 3, r"line 1.*" + READ),
    ("files", "fix_every_vertex", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--fix", "{t}/fix_ok.txt"], 3,
     r"no free vertex.*ERROR_NO_FREE_VERTEX"),
    ("files", "fix_ok", ["optimize", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/fix_grid6.txt", "--json"], 0,
     r'"constrained": 1.*"valid": true'),
    # constrain: the --fix file, the constraints and the mesh; never a crash or exit 0 on bad data
    ("constrain", "ok", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_ok.txt", "--svg", "{t}/o.svg", "--json"], 0,
     r'"constrained": 2.*"constraints_exact": true.*"valid": true'),
    ("constrain", "fix_missing", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/no_such_file.txt"], 3,
     r"--fix.*no_such_file.txt.*No such file.*ERROR_CANNOT_READ_FILE"),
    ("constrain", "fix_directory", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/folder.off"], 3,
     r"--fix.*directory.*ERROR_CANNOT_READ_FILE"),
    ("constrain", "fix_device", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "/dev/zero"], 3,
     r"--fix.*not a regular file.*ERROR_CANNOT_READ_FILE"),
    ("constrain", "fix_text", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_text.txt"], 3,
     r"--fix.*cfix_text.txt.*line 2: u 'abc' is not a number \(expected 'vertex_index u v'.*" + READ),
    ("constrain", "fix_missing_coordinate", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_missing_coordinate.txt"], 3,
     r"--fix.*line 2: 2 fields \(expected 'vertex_index u v'.*" + READ),
    ("constrain", "fix_extra_token", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_extra_token.txt"], 3,
     r"--fix.*line 1: more than 3 fields.*" + READ),
    ("constrain", "fix_out_of_range", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_out_of_range.txt"], 3,
     r"--fix.*line 1: vertex_index '36' is out of range \(0 to 35\).*0 <= vertex_index < 36.*" + READ),
    ("constrain", "fix_negative", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_negative.txt"], 3,
     r"--fix.*line 1: vertex_index '-1' is not a non-negative integer.*" + READ),
    ("constrain", "fix_nan", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_nan.txt"], 3,
     r"--fix.*line 1: u 'nan' is not finite.*" + READ),
    ("constrain", "fix_inf", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_inf.txt"], 3,
     r"--fix.*line 1: v 'inf' is not finite.*" + READ),
    ("constrain", "fix_overflow", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_overflow.txt"], 3,
     r"--fix.*line 1: v '1e400' is not finite.*" + READ),
    ("constrain", "duplicate_vertex", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_duplicate_vertex.txt"], 3,
     r"vertex 7 is constrained twice.*ERROR_DUPLICATE_CONSTRAINT"),
    ("constrain", "duplicate_target", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_duplicate_target.txt"], 3,
     r"vertex 8 and vertex 7 have the same target \(0.3, 0.3\).*ERROR_DUPLICATE_CONSTRAINT"),
    ("constrain", "on_border", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_border.txt"], 3,
     r"vertex 6 is on the border.*ERROR_CONSTRAINT_ON_BORDER"),
    ("constrain", "outside", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_outside.txt"], 3,
     r"constrained embedding failed.*ERROR_CONSTRAINT_OUTSIDE_DOMAIN"),
    ("constrain", "on_domain_border", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_on_domain_border.txt"], 3,
     r"ERROR_CONSTRAINT_OUTSIDE_DOMAIN"),
    ("constrain", "outside_triangle", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_ok.txt", "--border", "triangle"], 3,
     r"ERROR_CONSTRAINT_OUTSIDE_DOMAIN"),
    ("constrain", "no_uv_no_border", ["constrain", "{t}/unreferenced.off", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt"], 2,
     r"constrain needs a border: an input OBJ with texture coordinates \(vt\), or --border"),
    ("constrain", "no_uv_border_fixed", ["constrain", "{t}/unreferenced.off", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt", "--border", "fixed"], 2,
     r"--border fixed needs an input OBJ with texture coordinates"),
    ("constrain", "fix_unreferenced", ["constrain", "{t}/unreferenced.off", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt", "--border",
                                       "circle"], 3, r"1 vertex of the file is in no face: the vertex indices of --fix.*ERROR_NOT_A_DISK"),
    ("constrain", "no_uv_circle", ["constrain", "{t}/fan.off", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt", "--border", "circle", "--json"], 0,
     r'"constrained": 1.*"constraints_exact": true.*"valid": true'),
    ("constrain", "closed", ["constrain", "{t}/closed.off", "{t}/o.obj", "--fix", "{t}/cfix_tet.txt", "--border", "circle"], 3,
     r"not a topological disk: 1 component, 0 border cycles, Euler characteristic 2.*ERROR_NOT_A_DISK"),
    ("constrain", "closed_uv", ["constrain", "{t}/closed_uv.obj", "{t}/o.obj", "--fix", "{t}/cfix_tet.txt"], 3,
     r"not a topological disk.*ERROR_NOT_A_DISK"),
    ("constrain", "quad_uv", ["constrain", "{t}/quad_uv.obj", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt"], 3,
     r"line 9: face with 4 corners.*ERROR_NON_TRIANGULAR_MESH"),
    ("constrain", "quad", ["constrain", "{t}/quad.off", "{t}/o.obj", "--fix", "{t}/cfix_fan.txt", "--border", "square"], 3,
     r"ERROR_NON_TRIANGULAR_MESH"),
    ("constrain", "svg_missing_folder", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_ok.txt", "--svg",
                                         "{t}/no_such_folder/o.svg"], 4, r"--svg.*no_such_folder/o.svg.*ERROR_CANNOT_WRITE_FILE"),
    ("constrain", "svg_dev_full", ["constrain", "{t}/grid6.obj", "{t}/o.obj", "--fix", "{t}/cfix_ok.txt", "--svg", "/dev/full"], 4,
     r"cannot write '/dev/full'.*ERROR_CANNOT_WRITE_FILE"),
    # argument values: exit 2 with a message naming the option
    ("arguments", "iterations_ok", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations", "1000"], 0, r"^optimize .*valid"),
    ("arguments", "iterations_overflow", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations", "99999999999999999999"], 2,
     r"option --iterations: '99999999999999999999' is out of range"),
    ("arguments", "iterations_zero", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations", "0"], 2, r"--iterations.*out of range"),
    ("arguments", "iterations_negative", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations", "-5"], 2,
     r"--iterations.*not a non-negative integer"),
    ("arguments", "iterations_text", ["untangle", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations", "12abc"], 2,
     r"--iterations.*not a non-negative integer"),
    ("arguments", "iterations_missing", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--iterations"], 2,
     r"option --iterations needs a value"),
    ("arguments", "tolerance_negative", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--tolerance", "-1e-3"], 2, r"--tolerance.*out of range"),
    ("arguments", "tolerance_nan", ["embed", "{t}/quad.off", "{t}/o.obj", "--tolerance", "nan"], 2, r"--tolerance.*out of range"),
    ("arguments", "tolerance_overflow", ["embed", "{t}/quad.off", "{t}/o.obj", "--tolerance", "1e400"], 2, r"--tolerance.*out of range"),
    ("arguments", "tolerance_text", ["optimize", "{t}/fan_uv.obj", "{t}/o.obj", "--tolerance", "small"], 2, r"--tolerance.*not a number"),
    ("arguments", "time_limit_negative", ["tutte", "{t}/quad.off", "{t}/o.obj", "--time-limit", "-1"], 2, r"--time-limit.*out of range"),
    ("arguments", "time_limit_inf", ["tutte", "{t}/quad.off", "{t}/o.obj", "--time-limit", "inf"], 2, r"--time-limit.*out of range"),
    ("arguments", "seed_overflow", ["random-init", "{t}/quad.off", "{t}/o.obj", "--seed", "4294967296"], 2, r"--seed.*out of range"),
    ("arguments", "seed_positional", ["thingi", "{t}/closed.off", "-1", "{t}/o.obj"], 2, r"SEED must be"),
    ("arguments", "mpfr_bits", ["tutte", "{t}/quad.off", "{t}/o.obj", "--number-type", "mpfr:52"], 2, r"unknown number type 'mpfr:52'"),
    ("arguments", "mpfr_overflow", ["tutte", "{t}/quad.off", "{t}/o.obj", "--number-type", "mpfr:99999999999999999999"], 2,
     r"unknown number type"),
    ("arguments", "border", ["embed", "{t}/quad.off", "{t}/o.obj", "--border", "hexagon"], 2, r"option --border: unknown border 'hexagon'"),
    ("arguments", "border_fixed", ["tutte", "{t}/closed.off", "{t}/o.obj", "--border", "fixed"], 3, r"ERROR_NOT_A_DISK"),
    ("arguments", "border_fixed_no_uv", ["tutte", "{t}/unreferenced.off", "{t}/o.obj", "--border", "fixed"], 2,
     r"--border fixed needs an input OBJ with texture coordinates"),
    ("arguments", "twice", ["embed", "{t}/quad.off", "{t}/o.obj", "--iterations", "3", "--iterations", "4"], 2, r"given twice"),
    ("arguments", "not_applicable", ["check", "{t}/fan_uv.obj", "--seed", "3"], 2, r"option --seed does not apply to check"),
    ("arguments", "unknown_option", ["check", "{t}/fan_uv.obj", "--frobnicate"], 2, r"unknown option --frobnicate"),
    ("arguments", "optimize_both", ["embed", "{t}/quad.off", "{t}/o.obj", "--optimize", "--no-optimize"], 2, r"exclude each other"),
    ("arguments", "positional_count", ["tutte", "{t}/quad.off"], 2, r"tutte takes IN OUT.obj"),
    ("arguments", "grid_overflow", ["generate", "grid", "99999999999999999999", "{t}/o.obj"], 2, r"N: .*out of range"),
    ("arguments", "time_limit_ok", ["embed", "{t}/unreferenced.off", "{t}/o.obj", "--time-limit", "60", "--json"], 0, r'"valid": true'),
    # outputs: exit 4 naming the file, and no partial file
    # cross: the faults of the landmarks and meshes said with the landmark's line, exit 3; every output or none
    ("cross", "ok", ["cross", "{t}/fan.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx.txt", "--json"], 0,
     r'"landmarks_exact": true.*"written": true'),
    ("cross", "unreferenced", ["cross", "{t}/unreferenced.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx_unreferenced.txt"], 3,
     r"unreferenced.off.*1 vertex of the file is in no face: the vertex indices of LANDMARKS and the lines of OUT.txt.*ERROR_NOT_A_DISK"),
    ("cross", "closed_one_landmark", ["cross", "{t}/closed.off", "{t}/closed.off", "{t}/lm_one.txt", "{t}/cx_one.txt", "--json"], 3,
     r'"message": "[^"]*closed meshes need at least two landmarks.*"exit_status": 3.*\(ERROR_WRONG_PARAMETER\)'),
    ("cross", "closed_edge", ["cross", "{t}/closed.off", "{t}/closed.off", "{t}/lm_edge.txt", "{t}/cx_edge.txt"], 3,
     r"line 2: landmark 1 1: the vertex of A is joined to the previous landmark by an edge: a cut along one edge opens "
     r"nothing.*ERROR_NOT_A_DISK"),
    ("cross", "border_too_short", ["cross", "{t}/grid6.obj", "{t}/grid6.obj", "{t}/lm_border_short.txt", "{t}/cx_short.txt"], 3,
     r"line 2: landmark 2 0: the vertex of A leaves too few border vertices of A between it and the border landmark before it.*ERROR_BORDER_TOO_SHORT"),
    ("cross", "border_short_arc", ["cross", "{t}/grid6.obj", "{t}/grid6.obj", "{t}/lm_border_short_arc.txt", "{t}/cx_short_arc.txt", "--json"], 0,
     r'"chords_split_b": 1,.*"landmarks_exact": true.*"written": true'),
    ("cross", "closed_unreachable", ["cross", "{t}/octahedron.off", "{t}/octahedron.off", "{t}/lm_trap.txt", "{t}/cx_trap.txt"], 3,
     r"line 6: landmark 0 0: the vertex of A cannot be reached from the previous landmark.*another order may do.*"
     r"ERROR_PATH_TRACING_FAILED"),
    ("cross", "closed_duplicate", ["cross", "{t}/octahedron.off", "{t}/octahedron.off", "{t}/lm_closed_duplicate.txt",
                                   "{t}/cx_cdup.txt"], 3,
     r"line 3: landmark 3 1: the vertex of B is used by an earlier landmark.*ERROR_DUPLICATE_CONSTRAINT"),
    ("cross", "quad", ["cross", "{t}/quad.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx_quad.txt"], 3,
     r"quad.off.*ERROR_NON_TRIANGULAR_MESH"),
    ("cross", "empty", ["cross", "{t}/fan.off", "{t}/empty.off", "{t}/lm_fan.txt", "{t}/cx_empty.txt"], 3,
     r"empty.off.*ERROR_EMPTY_MESH"),
    ("cross", "svg_dev_full", ["cross", "{t}/fan.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx_full.txt", "--compatible",
                               "{t}/cx_a.obj", "{t}/cx_b.obj", "--svg", "/dev/full"], 4, r"cannot write '/dev/full'.*ERROR_CANNOT_WRITE_FILE"),
    ("cross", "same_output", ["cross", "{t}/fan.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx_same.txt", "--svg", "{t}/cx_same.txt"], 2,
     r"the output and --svg name the same file"),
    ("cross", "same_output_spelled", ["cross", "{t}/fan.off", "{t}/fan.off", "{t}/lm_fan.txt", "{t}/cx_same2.txt", "--svg",
                                      "{t}/./cx_same2.txt"], 2, r"the output and --svg name the same file"),
    # the standard output as an output (a pipe here): the map alone there, the note and the JSON on stderr; a vertex in
    # no face is left out with a note and counted
    ("outputs", "stdout", ["tutte", "{t}/unreferenced.off", "/dev/stdout", "--json"], 0,
     r'^# OBJ with texture coordinates.*1 vertex of the file is in no face, left out of the mesh and of the outputs.*'
     r'"unused_vertices": 1.*"written": true'),
    ("outputs", "dev_full", ["tutte", "{t}/unreferenced.off", "/dev/full"], 4, r"cannot write '/dev/full'.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "missing_folder", ["tutte", "{t}/unreferenced.off", "{t}/no_such_folder/o.obj"], 4,
     r"no_such_folder/o.obj.*does not exist.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "directory", ["embed", "{t}/unreferenced.off", "{t}/folder.off"], 4, r"folder.off.*directory.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "svg_dev_full", ["svg", "{t}/fan_uv.obj", "/dev/full"], 4, r"cannot write '/dev/full'.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "thingi_svg_missing_folder", ["thingi", "{t}/closed.off", "0", "{t}/o.obj", "--svg", "{t}/no_such_folder/o.svg"], 4,
     r"--svg.*no_such_folder/o.svg.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "out_dir_missing", ["demo", "{t}", "--out-dir", "{t}/no_such_folder"], 4, r"--out-dir.*no such directory.*ERROR_CANNOT_WRITE_FILE"),
    ("outputs", "file_size_limit", ["generate", "grid", "40", "{t}/big.obj"], 4, r"cannot write '.*big.obj'.*ERROR_CANNOT_WRITE_FILE"),
]

# the cases whose output must not exist afterwards (no partial file), and the size limits
NO_FILE_AFTER = {"file_size_limit": ["{t}/big.obj"], "missing_folder": ["{t}/no_such_folder/o.obj"],
                 "unreferenced": ["{t}/cx_unreferenced.txt"], "closed_one_landmark": ["{t}/cx_one.txt"],
                 "closed_edge": ["{t}/cx_edge.txt"], "border_too_short": ["{t}/cx_short.txt"],
                 "svg_dev_full": ["{t}/cx_full.txt", "{t}/cx_a.obj", "{t}/cx_b.obj"], "same_output": ["{t}/cx_same.txt"],
                 "same_output_spelled": ["{t}/cx_same2.txt"]}
FILE_SIZE_LIMIT = {"file_size_limit": 4096}
# what the standard output alone must match (the cases' regex sees it followed by the standard error)
STDOUT_ALONE = {"stdout": r"^# OBJ with texture coordinates(?![\s\S]*(pe: |\{))[\s\S]*\Z"}

def limits(file_size=None):
    def apply():
        if MEMORY_LIMIT_MB > 0:
            b = MEMORY_LIMIT_MB * 1024 * 1024
            resource.setrlimit(resource.RLIMIT_AS, (b, b))
        if file_size is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # the write fails instead of killing pe
            resource.setrlimit(resource.RLIMIT_FSIZE, (file_size, file_size))
    return apply

def run_case(pe, folder, case):
    group, name, args, expect, regex = case
    argv = [pe] + [a.replace("{t}", folder) for a in args]
    try:
        p = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=TIME_LIMIT,
                           preexec_fn=limits(FILE_SIZE_LIMIT.get(name)), cwd=folder)
    except subprocess.TimeoutExpired:
        return "%s/%s: no answer within %d s" % (group, name, TIME_LIMIT)
    out = p.stdout.decode(errors="replace") + p.stderr.decode(errors="replace")
    problems = []
    if p.returncode != expect:
        how = "killed by signal %d" % -p.returncode if p.returncode < 0 else "exit status %d" % p.returncode
        problems.append("expected exit status %d, got %s" % (expect, how))
    if not re.search(regex, out.replace("\n", " ")):
        problems.append("output does not match %r" % regex)
    if name in STDOUT_ALONE and not re.search(STDOUT_ALONE[name], p.stdout.decode(errors="replace")):
        problems.append("the standard output does not match %r" % STDOUT_ALONE[name])
    if any(os.path.exists(f.replace("{t}", folder)) for f in NO_FILE_AFTER.get(name, [])):
        problems.append("an output file was left")
    if "std::bad_cast" in out or "-nan" in out:
        problems.append("the output shows std::bad_cast or -nan")
    if problems:
        return "%s/%s: %s\n    $ %s\n    %s" % (group, name, "; ".join(problems), " ".join(argv),
                                                out.strip().replace("\n", "\n    "))
    return None

def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    pe, group = os.path.abspath(sys.argv[1]), sys.argv[2]
    cases = [c for c in CASES if group in ("all", c[0])]
    if not cases:
        print("unknown group", group, "among", sorted(set(c[0] for c in CASES)))
        return 2
    folder = tempfile.mkdtemp(prefix="pe_bad_input_")
    try:
        for name, text in inputs().items():
            with open(os.path.join(folder, name), "w") as f:
                f.write(text)
        os.mkdir(os.path.join(folder, "folder.off"))
        # demo reads DATA_DIR/meshes/dino.off: a folder without it
        os.mkdir(os.path.join(folder, "meshes"))
        # a valid map with interior vertices, and a constraint on one of them at its place
        subprocess.run([pe, "generate", "grid", "6", os.path.join(folder, "grid6.obj")], stdout=subprocess.DEVNULL,
                       timeout=TIME_LIMIT, check=True)
        vt = [l.split() for l in open(os.path.join(folder, "grid6.obj")) if l.startswith("vt ")]
        with open(os.path.join(folder, "fix_grid6.txt"), "w") as f:
            f.write("7 %s %s\n" % (vt[7][1], vt[7][2]))
        failures = [f for f in (run_case(pe, folder, c) for c in cases) if f]
        for f in failures:
            print("FAIL", f)
        print("%d of %d cases passed" % (len(cases) - len(failures), len(cases)))
        return 1 if failures else 0
    finally:
        shutil.rmtree(folder, ignore_errors=True)

if __name__ == "__main__":
    sys.exit(main())
