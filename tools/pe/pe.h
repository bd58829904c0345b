// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe`, the command-line tool of the package: the meshes and the algorithm steps that the command
// families share (see cli.h for the command line and the list of files).

#ifndef PE_TOOL_PE_H
#define PE_TOOL_PE_H

#include "cli.h"

#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstring>
#include <functional>
#include <ostream>
#include <CGAL/Surface_mesh.h>

namespace CGAL {
namespace Progressive_embedding {
struct Progressive_embedding_statistics;
struct Optimization_statistics;
struct Pipeline_statistics;
}
}

namespace pe_tool {

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef K::Point_2                                            Point_2;
typedef K::Point_3                                            Point_3;
typedef CGAL::Surface_mesh<Point_3>                           Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;
typedef Mesh::Face_index                                      face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>        UV_map;

// ---- input and output ---------------------------------------------------------------------

struct Input
{
  std::string filename;
  Mesh mesh;
  UV_map uv;
  bool has_uv = false;                  // read from `vt` entries
  std::vector<std::size_t> vt_to_v;     // with has_uv: to write the seams back; empty for a file without seams
  std::vector<Point_3> positions;       // the `v` lines, with vt_to_v
  std::size_t dropped_vertices = 0;     // vertices (or `vt` entries) of the file in no face, left out of `mesh`
};

enum class Uv_mode { REQUIRED, OPTIONAL, IGNORED };
enum class Shape { DISK, CLOSED_SPHERE, DISK_OR_SPHERE };

// Reads `filename` (OFF, OBJ, PLY, STL; the uv map from an OBJ with vt entries) and checks that
// it is a triangle mesh of the shape needed. Returns EXIT_VALID, or reports the failure through
// `run` and returns its exit status.
int read_input(Run& run, const std::string& filename, Input& in, Uv_mode mode, Shape shape = Shape::DISK,
               const std::string& role = std::string());

// Refuses (exit 3) an input whose file had vertices in no face, which the reader leaves out: `indices` (the
// vertex indices of some file, said as a plural subject) count the file's vertices, which the mesh no longer
// has in that order. Same return as read_input().
int require_file_vertex_order(Run& run, const Input& in, const std::string& indices);

// Reads `vertex_index u v` lines (--fix) into `in.uv` and `fixed` (refusing an input with vertices in no face,
// see require_file_vertex_order()); same return as read_input().
int read_constraints(Run& run, const std::string& filename, Input& in, std::vector<vertex_descriptor>& fixed);

// One output file of write_files_together(): its name, and what writes its content.
typedef CGAL::Progressive_embedding::IO::internal::Atomic_output_file Output_file;

// Writes several output files all or none (the library's write_files_atomically()): each content goes first to a
// temporary file beside its target, and the temporaries replace their targets only once all of them are written; on
// a failure every temporary is removed, the targets are left as they were, and the failure is reported through `run`
// naming the file (exit 4). EXIT_VALID otherwise. Two exceptions: a device such as /dev/null or /dev/tty, and a name
// such as /dev/stdout that reaches a file another program opened (a shell's redirection), are written in place,
// before the files (so a failing one comes first, but what went to it stays); a rename that fails (the folder changed
// during the run) leaves the targets renamed before it replaced. An output on the standard output sends the summary
// line (or the JSON) to the standard error.
int write_files_together(Run& run, const std::vector<Output_file>& files);

// Reads a polygon given as `x y` lines (blank lines and `#` comments skipped) into `points`; same
// return as read_input().
int read_polygon(Run& run, const std::string& filename, std::vector<Point_2>& points);

// What a picture shows.
struct Picture
{
  std::string title;
  bool color_by_distortion = true;  // faces coloured by their distortion, with a legend
  bool inset = false;               // an inset zoomed on the flipped faces
  bool has_3d_energy = true;        // the certificate has 3D energies (else no distortion colors)
  // constrain: faces filled by patch (adjacent patches in different colors), lines between
  // patches, the constrained vertices marked
  bool has_patches = false;
  Mesh::Property_map<face_descriptor, int> patches;   // -1: no patch
  std::vector<vertex_descriptor> constrained;
  // the certificate of the map drawn, when the caller has it (the writer then only draws); else it certifies
  const PE::Embedding_report* report = nullptr;
};

// writes the map (OBJ with uv) and, if `svg` is not empty, its picture; returns EXIT_VALID, or
// reports the failure through `run` (naming the file) and returns EXIT_OUTPUT
int write_outputs(Run& run, const Input& in, const std::string& obj, const std::string& svg = std::string(),
                  const Picture& picture = Picture());
int write_picture(Run& run, const Input& in, const std::string& svg, const Picture& picture);

// the two doubles have the same bits (bit-exact positions: -0 differs from 0, NaN equals itself)
inline bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; }

// faces(m).size(): num_faces(Surface_mesh) also counts removed faces
std::size_t count_faces(const Mesh& m);

// ---- certificate (commands_check.cpp) -----------------------------------------------------

// The certificate of the map of `in` as it stands: what write_and_finish() writes is what it certifies (a
// report computed on another copy of the map, e.g. a library's working copy, cannot be passed there).
struct Map_certificate
{
  PE::Embedding_report report;
  const Input* of = nullptr; // the input certified
};
Map_certificate certify(const Input& in);
// The certificate a library call took of the map it leaves in in.uv, on in.mesh itself (documented so:
// Pipeline_statistics::report), taken over instead of checking the same map twice.
Map_certificate certified_in_place(const Input& in, const PE::Embedding_report& report);
// the certificate's fields into the result; `prefix` distinguishes several maps ("tutte_")
void add_report(Result& r, const PE::Embedding_report& rep, const std::string& prefix = std::string());
// one line: `valid: faces 10, flipped 0, ...`; non-finite measures printed as inf or nan
std::string describe(const PE::Embedding_report& rep);
// the exit status of the map of `in` just certified: EXIT_VALID, EXIT_INVALID, or the input-error
// status when the map is valid but its distortion is not finite (a zero-area 3D face:
// ERROR_DEGENERATE_3D_FACE; coordinates whose products overflow double:
// ERROR_NON_FINITE_COORDINATES); `code` and `why` then say so
int map_status(const Input& in, const PE::Embedding_report& rep, PE::Error_code& code, std::string& why);
// ends `run` with map_status(): the message on stderr, the status in the result
int finish_with_map_status(Run& run, const Input& in, const PE::Embedding_report& rep);
// the common end of the commands that write a map: the file, then the exit status of map_status();
// `cert` is certify(in), taken after the last change to the map
int write_and_finish(Run& run, const Input& in, const std::string& obj, const Map_certificate& cert,
                     const std::string& svg = std::string(), const Picture& picture = Picture());

// ---- Tutte steps (commands_tutte.cpp) -----------------------------------------------------

enum class Number_type { DOUBLE, EXACT, MPFR };

struct Tutte_settings
{
  PE::Border_shape border = PE::Border_shape::CIRCLE;
  PE::Weights weights = PE::Weights::UNIFORM;
  Number_type number_type = Number_type::DOUBLE;
  unsigned long bits = 0;                     // with MPFR
};

// parses --border, --weights and --number-type; the default border is FIXED for an OBJ with uv
// (then `in` must be read first), CIRCLE otherwise. Returns EXIT_VALID or reports through `run`.
int tutte_settings(Run& run, const Input& in, Tutte_settings& s);
// Tutte in the number type of `s`, rounded to double into in.uv; `exact_report` certifies the
// map before rounding (not double only)
PE::Error_code run_tutte(Input& in, const Tutte_settings& s, const Budget& budget, PE::Embedding_report& exact_report);
// the Tutte-failure protocol on the closed mesh of `in`
PE::Error_code thingi_protocol(Input& in, unsigned seed, const Budget& budget);

// ---- repair and optimization steps (commands_repair.cpp) ----------------------------------

struct Optimize_settings
{
  bool free_border = false;
  std::vector<vertex_descriptor> fixed;
  std::size_t iterations = 200;
  double tolerance = 1e-4;
  double seconds = default_optimize_seconds; // --optimize-time
};

// the optimization settings of --free-border, --iterations and --tolerance (checked by the parser)
Optimize_settings optimize_settings(const Arguments& a, std::size_t default_iterations);
// progressive embedding of in.uv (border kept); `will_optimize` selects the repair parameters
PE::Error_code run_repair(Input& in, bool will_optimize, const Budget& budget, PE::Progressive_embedding_statistics& st);
// distortion optimization of the valid map in.uv
PE::Error_code run_optimize(Input& in, const Optimize_settings& s, const Budget& budget, PE::Optimization_statistics& os);
void add_statistics(Result& r, const PE::Progressive_embedding_statistics& st);
void add_statistics(Result& r, const PE::Pipeline_statistics& s);
std::string statistics_summary(const PE::Progressive_embedding_statistics& st);
void add_optimization(Result& r, const PE::Optimization_statistics& os);
// "N iterations (converged)", or "(stopped at its time budget)" / "(stopped at its iteration limit)" when `status`
// says a budget ran out
std::string optimization_summary(const PE::Optimization_statistics& os, PE::Error_code status = PE::OK);

} // namespace pe_tool

#endif // PE_TOOL_PE_H
