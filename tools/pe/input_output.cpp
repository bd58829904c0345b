// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe`: reading meshes and constraints (with the checks every command needs: a regular file, a
// triangle mesh, manifold, finite, of the right topology) and writing maps and pictures.

#include "pe.h"

#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
#include <CGAL/Progressive_embedding/IO/read_polygon_mesh.h>
#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

#include <sys/stat.h>
#include <unistd.h>

namespace pe_tool {

std::size_t count_faces(const Mesh& m)
{
  return static_cast<std::size_t>(std::distance(faces(m).begin(), faces(m).end()));
}

bool is_standard_output(const std::string& path)
{
  // a character device (a terminal, /dev/null) takes both without harm: only a pipe, socket or file would mix them
  struct stat out;
  if(::fstat(STDOUT_FILENO, &out) != 0 || S_ISCHR(out.st_mode)) return false;
  // a descriptor name (/dev/stderr with 2>&1, /dev/fd/3 with 3>&1) is compared through the descriptor itself
  int descriptor = -1;
  PE::IO::internal::atomic_output_resolve_links(path, &descriptor);
  struct stat st;
  const int status = descriptor >= 0 ? ::fstat(descriptor, &st) : ::stat(path.c_str(), &st);
  return status == 0 && st.st_dev == out.st_dev && st.st_ino == out.st_ino;
}

std::string input_file_problem(const std::string& path)
{
  struct stat st;
  if(::stat(path.c_str(), &st) != 0) return std::string("cannot open the file: ") + std::strerror(errno);
  if(S_ISDIR(st.st_mode)) return "cannot open the file: it is a directory, not a regular file";
  // devices and pipes may never end (/dev/zero): only regular files are read
  if(!S_ISREG(st.st_mode)) return "cannot open the file: not a regular file";
  std::ifstream probe(path, std::ios::binary);
  if(!probe) return std::string("cannot open the file: ") + std::strerror(errno);
  return std::string();
}

int check_output_path(Run& run, const std::string& path, const std::string& role, bool directory)
{
  const std::string what = "cannot write " + (role.empty() ? std::string() : role + " ") + "'" + path + "'";
  struct stat st;
  const bool exists = ::stat(path.c_str(), &st) == 0;
  if(directory)
  {
    if(!exists) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, std::string("no such directory: ") + std::strerror(errno));
    if(!S_ISDIR(st.st_mode)) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, "not a directory");
    if(::access(path.c_str(), W_OK) != 0) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, std::strerror(errno));
    return EXIT_VALID;
  }
  if(exists && S_ISDIR(st.st_mode)) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, "it is a directory");
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? std::string(".") : (slash == 0 ? std::string("/") : path.substr(0, slash));
  struct stat fs;
  if(::stat(folder.c_str(), &fs) != 0 || !S_ISDIR(fs.st_mode))
    return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, "the folder '" + folder + "' does not exist");
  if(exists ? ::access(path.c_str(), W_OK) != 0 : ::access(folder.c_str(), W_OK) != 0)
    return run.fail(PE::ERROR_CANNOT_WRITE_FILE, what, std::strerror(errno));
  return EXIT_VALID;
}

namespace {

std::string lower_extension(const std::string& f)
{
  const std::size_t dot = f.find_last_of('.');
  if(dot == std::string::npos || f.find_first_of("/\\", dot) != std::string::npos) return std::string();
  std::string e = f.substr(dot + 1);
  for(char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Reads one line of at most `limit` characters (a file without line breaks must not be read
// into memory at once); false at the end of the file or on a longer line (`too_long` set).
bool bounded_getline(std::istream& in, std::string& line, std::size_t limit, bool& too_long)
{
  line.clear();
  too_long = false;
  std::istream::int_type c;
  bool any = false;
  while((c = in.get()) != std::istream::traits_type::eof())
  {
    any = true;
    if(c == '\n') return true;
    if(line.size() >= limit) { too_long = true; return false; }
    line += static_cast<char>(c);
  }
  return any;
}

// Whether some line of the OBJ file `f` is a `vt` entry. Read in large blocks, the lines scanned in
// place: a 1M-vertex file has a million `v` lines before its first `vt` (0.5 s character by character).
bool obj_has_texture_coordinates(const std::string& f)
{
  const std::size_t limit = 1 << 16; // a line too long for a vt entry ends the scan: the reader reports it
  std::ifstream in(f, std::ios::binary);
  std::vector<char> block(1 << 20);
  std::size_t length = 0; // characters of the current line so far
  enum { BLANKS, V, VT, OTHER } state = BLANKS; // what the line starts with, after blanks
  while(in)
  {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const char* c = block.data();
    const char* const end = c + in.gcount();
    while(c != end)
    {
      if(state == OTHER)
      {
        // to the end of the line
        const char* nl = static_cast<const char*>(std::memchr(c, '\n', static_cast<std::size_t>(end - c)));
        const std::size_t n = static_cast<std::size_t>((nl ? nl : end) - c);
        if(length + n > limit) return false;
        length += n;
        c += n;
        if(nl == nullptr) break;
      }
      if(*c == '\n') { length = 0; state = BLANKS; ++c; continue; }
      if(++length > limit) return false;
      const bool blank = (*c == ' ' || *c == '\t');
      if(state == BLANKS) state = blank ? BLANKS : (*c == 'v' ? V : OTHER);
      else if(state == V) state = (*c == 't') ? VT : OTHER;
      else if(blank) return true; // "vt" and a blank
      else state = OTHER;
      ++c;
    }
  }
  return false;
}

// The topology of a mesh: what a disk (1, 1, 1) and a closed genus-0 mesh (1, 0, 2) are told by.
struct Topology_counts
{
  std::size_t components = 0;
  std::size_t border_cycles = 0;
  std::size_t isolated_vertices = 0;
  long long euler = 0;
};

Topology_counts topology(const Mesh& m)
{
  Topology_counts t;
  // components: union-find over the vertices, joined along the edges
  std::vector<std::size_t> parent(m.num_vertices());
  for(std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t i) {
    while(parent[i] != i) { parent[i] = parent[parent[i]]; i = parent[i]; }
    return i;
  };
  std::size_t nv = 0, ne = 0;
  for(auto e : edges(m))
  {
    ++ne;
    const std::size_t a = find(std::size_t(source(halfedge(e, m), m))), b = find(std::size_t(target(halfedge(e, m), m)));
    if(a != b) parent[a] = b;
  }
  for(vertex_descriptor v : vertices(m))
  {
    if(m.is_isolated(v)) { ++t.isolated_vertices; continue; }
    ++nv;
    if(find(std::size_t(v)) == std::size_t(v)) ++t.components;
  }
  // border cycles: each border halfedge is on exactly one; the walk is bounded by their number
  std::vector<char> seen(m.num_halfedges(), 0);
  std::size_t border_halfedges = 0;
  for(auto h : halfedges(m)) if(is_border(h, m)) ++border_halfedges;
  for(auto h : halfedges(m))
  {
    if(!is_border(h, m) || seen[std::size_t(h)]) continue;
    ++t.border_cycles;
    auto g = h;
    for(std::size_t steps = 0; steps <= border_halfedges && !seen[std::size_t(g)]; ++steps)
    {
      seen[std::size_t(g)] = 1;
      g = next(g, m);
    }
  }
  t.euler = static_cast<long long>(nv) - static_cast<long long>(ne) + static_cast<long long>(count_faces(m));
  return t;
}

std::string plural(std::size_t n, const char* what)
{
  const std::string w(what);
  return std::to_string(n) + " " + (n == 1 ? w : w == "vertex" ? std::string("vertices") : w + "s");
}

// the faults of a mesh that no command accepts; EXIT_VALID if none
int check_mesh(Run& run, const std::string& what, const Mesh& m, Shape shape)
{
  if(count_faces(m) == 0) return run.fail(PE::ERROR_EMPTY_MESH, what);
  std::size_t index = 0;
  for(face_descriptor f : faces(m))
  {
    const std::size_t d = degree(f, m);
    if(d != 3)
      return run.fail(PE::ERROR_NON_TRIANGULAR_MESH, what, "face " + std::to_string(index) + " has " + std::to_string(d) +
                                                           " vertices: a triangle mesh is needed");
    ++index;
  }
  index = 0;
  for(vertex_descriptor v : vertices(m))
  {
    const Point_3& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return run.fail(PE::ERROR_NON_FINITE_COORDINATES, what, "vertex " + std::to_string(index) + " has a NaN or infinite coordinate");
    ++index;
  }
  // a non-manifold vertex: its faces form several fans, so the halfedges around it are fewer
  // than the halfedges that end at it
  std::vector<std::size_t> incoming(m.num_vertices(), 0);
  for(auto h : halfedges(m)) ++incoming[std::size_t(target(h, m))];
  for(vertex_descriptor v : vertices(m))
  {
    if(m.is_isolated(v)) continue;
    std::size_t around = 0;
    const auto h0 = halfedge(v, m);
    auto h = h0;
    do { ++around; h = opposite(next(h, m), m); } while(h != h0 && around <= incoming[std::size_t(v)]);
    if(around != incoming[std::size_t(v)])
      return run.fail(PE::ERROR_NON_MANIFOLD, what, "vertex " + std::to_string(std::size_t(v)) + " is not manifold (its faces form several fans)");
  }
  const Topology_counts t = topology(m);
  std::ostringstream found;
  found << plural(t.components, "component") << ", " << plural(t.border_cycles, "border cycle") << ", Euler characteristic "
        << t.euler;
  if(t.isolated_vertices) found << ", " << plural(t.isolated_vertices, "vertex") << " in no face";
  const bool disk = t.components == 1 && t.border_cycles == 1 && t.euler == 1 && !t.isolated_vertices;
  const bool sphere = t.components == 1 && t.border_cycles == 0 && t.euler == 2 && !t.isolated_vertices;
  if(shape == Shape::DISK && !disk)
    return run.fail(PE::ERROR_NOT_A_DISK, what, "not a topological disk: " + found.str() +
                    " (a disk has 1 component, 1 border cycle, Euler characteristic 1)");
  // a closed connected surface of another genus: the code the function gives it (ERROR_NOT_GENUS_ZERO)
  if(shape == Shape::DISK_OR_SPHERE && !disk && t.components == 1 && t.border_cycles == 0 && !t.isolated_vertices &&
     t.euler % 2 == 0 && t.euler < 2)
    return run.fail(PE::ERROR_NOT_GENUS_ZERO, what, "a closed mesh of genus " + std::to_string((2 - t.euler) / 2) + ": " +
                    found.str() + " (a closed mesh is used only if its genus is 0, Euler characteristic 2; or a disk)");
  if(shape == Shape::DISK_OR_SPHERE && !disk && !sphere)
    return run.fail(PE::ERROR_NOT_A_DISK, what, "neither a topological disk nor a closed genus-0 mesh: " + found.str() +
                    " (a disk has 1 component, 1 border cycle, Euler characteristic 1; a sphere no border, 2)");
  if(shape == Shape::CLOSED_SPHERE && !sphere)
    return run.fail(PE::ERROR_NOT_A_DISK, what, "not a closed genus-0 mesh: " + found.str() +
                    " (the protocol needs 1 component, no border, Euler characteristic 2)");
  return EXIT_VALID;
}

// A file without seams (one `vt` per `v`, in the same order, faces `f i/i`) is written back the same
// from the mesh alone: the seam map and the copy of the positions are dropped (32 MB at 1M vertices,
// held through the whole run otherwise).
void drop_trivial_seam_map(Input& in)
{
  if(in.vt_to_v.size() != in.mesh.number_of_vertices() || in.positions.size() != in.vt_to_v.size()) return;
  std::size_t i = 0;
  for(vertex_descriptor v : in.mesh.vertices())
  {
    const Point_3& p = in.positions[i], & q = in.mesh.point(v);
    if(in.vt_to_v[i] != i || !same_bits(p.x(), q.x()) || !same_bits(p.y(), q.y()) || !same_bits(p.z(), q.z())) return;
    ++i;
  }
  std::vector<std::size_t>().swap(in.vt_to_v);
  std::vector<Point_3>().swap(in.positions);
}

// "3 vertices of the file are in no face" (with texture coordinates the mesh's vertices are the file's `vt` entries)
std::string unused_vertices_phrase(const Input& in)
{
  const std::size_t n = in.dropped_vertices;
  const std::string what = in.has_uv ? (n == 1 ? "texture coordinate (vt)" : "texture coordinates (vt)") : (n == 1 ? "vertex" : "vertices");
  return std::to_string(n) + " " + what + " of the file " + (n == 1 ? "is" : "are") + " in no face";
}

// JSON `unused_vertices` (the main input), and a note when the reader left vertices out: the outputs have the mesh's
// vertices only (the commands whose inputs refer to vertex indices refuse such a file: require_file_vertex_order();
// the note is then not printed, see Run::notes)
void report_unused_vertices(Run& run, const Input& in, const std::string& role)
{
  if(role.empty()) run.result.add("unused_vertices", in.dropped_vertices);
  if(in.dropped_vertices > 0)
    run.notes.push_back("'" + in.filename + "': " + unused_vertices_phrase(in) + ", left out of the mesh and of the outputs");
}

} // namespace

int read_input(Run& run, const std::string& filename, Input& in, Uv_mode mode, Shape shape, const std::string& role)
{
  in.filename = filename;
  run.result.add(role.empty() ? std::string("input") : role, filename);
  const std::string what = "cannot use '" + filename + "'";
  auto fail = [&](PE::Error_code ec, std::size_t line, const std::string& msg) {
    return run.fail(ec, what, (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + msg);
  };
  const std::string problem = input_file_problem(filename);
  if(!problem.empty()) return fail(PE::ERROR_CANNOT_READ_FILE, 0, problem);
  const std::string ext = lower_extension(filename);
  if(mode != Uv_mode::IGNORED && ext == "obj" && obj_has_texture_coordinates(filename))
  {
    in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
    const PE::IO::Read_result r = PE::IO::read_OBJ_with_uv(filename, in.mesh, in.uv, &in.vt_to_v, &in.positions);
    if(!r) return fail(r.status, r.line, r.message.empty() ? PE::get_error_message(r.status) : r.message);
    in.dropped_vertices = r.number_of_unreferenced_vertices;
    in.has_uv = true;
    report_unused_vertices(run, in, role);
    drop_trivial_seam_map(in);
    return check_mesh(run, what, in.mesh, shape);
  }
  if(mode == Uv_mode::REQUIRED)
    return fail(PE::ERROR_MALFORMED_FILE, 0, "no texture coordinates: an OBJ file with vt entries and f v/vt faces is needed");
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    return fail(PE::ERROR_MALFORMED_FILE, 0, "unknown format '." + ext + "' (OFF, OBJ, PLY or STL expected)");
  // bounded memory, line numbers, the same error codes as the OBJ reader with uv
  const PE::IO::Read_result r = PE::IO::read_polygon_mesh(filename, in.mesh);
  if(!r) return fail(r.status, r.line, r.message.empty() ? PE::get_error_message(r.status) : r.message);
  in.dropped_vertices = r.number_of_unreferenced_vertices;
  report_unused_vertices(run, in, role);
  in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
  return check_mesh(run, what, in.mesh, shape);
}

// Reads the text file `filename` line by line for the small data files of the tool (--fix, polygons):
// each non-empty line that is not a `#` comment is split into at most `max_tokens` whitespace-separated
// tokens and passed to `line_fn(lineno, tokens)`, which returns EXIT_VALID to go on or a failure status.
// `what` starts the failure reports (unreadable file, a line over 4096 characters).
template <class Line_fn>
int for_each_data_line(Run& run, const std::string& filename, const std::string& what, std::size_t max_tokens, Line_fn line_fn)
{
  const std::string problem = input_file_problem(filename);
  if(!problem.empty()) return run.fail(PE::ERROR_CANNOT_READ_FILE, what, problem);
  std::ifstream f(filename, std::ios::binary);
  std::string line;
  bool too_long = false;
  for(std::size_t lineno = 1; ; ++lineno)
  {
    if(!bounded_getline(f, line, 4096, too_long))
    {
      if(too_long) return run.fail(PE::ERROR_MALFORMED_FILE, what, "line " + std::to_string(lineno) + ": line too long");
      return EXIT_VALID;
    }
    if(!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> tokens;
    std::istringstream ls(line);
    for(std::string t; ls >> t && tokens.size() < max_tokens; ) tokens.push_back(t);
    if(tokens.empty() || tokens[0][0] == '#') continue;
    const int status = line_fn(lineno, tokens);
    if(status != EXIT_VALID) return status;
  }
}

int require_file_vertex_order(Run& run, const Input& in, const std::string& indices)
{
  if(in.dropped_vertices == 0) return EXIT_VALID;
  return run.fail(PE::ERROR_NOT_A_DISK, "cannot use '" + in.filename + "'",
                  unused_vertices_phrase(in) + ": " + indices + " count the file's " + (in.has_uv ? "vt entries" : "vertices") +
                  ", which the mesh read (without the unused ones) no longer has in that order; remove what no face uses");
}

int write_files_together(Run& run, const std::vector<Output_file>& files)
{
  // a summary on the standard output would mix with an output written there (also when a later file fails): it goes
  // to the standard error
  for(const Output_file& f : files)
    if(is_standard_output(f.name)) run.summary_to_stderr = true;
  const PE::IO::internal::Atomic_output_result r = PE::IO::internal::write_files_atomically(files);
  if(r.code != PE::OK)
    return run.fail(r.code, "cannot write '" + (r.failed < files.size() ? files[r.failed].name : std::string()) + "'");
  return EXIT_VALID;
}

int read_constraints(Run& run, const std::string& filename, Input& in, std::vector<vertex_descriptor>& fixed)
{
  {
    const int status = require_file_vertex_order(run, in, "the vertex indices of --fix");
    if(status != EXIT_VALID) return status;
  }
  const std::string what = "cannot use --fix '" + filename + "'";
  const std::size_t n = in.mesh.number_of_vertices();
  return for_each_data_line(run, filename, what, 4, [&](std::size_t lineno, const std::vector<std::string>& tokens) -> int
  {
    unsigned long long index = 0;
    std::string why;
    double u = 0, v = 0;
    // why a coordinate is refused, empty if it is a finite number
    auto real = [](const char* name, const std::string& s, double& d) -> std::string {
      char* end = nullptr;
      errno = 0;
      d = std::strtod(s.c_str(), &end);
      if(end == s.c_str() || *end != '\0') return std::string(name) + " '" + s + "' is not a number";
      if(!std::isfinite(d)) return std::string(name) + " '" + s + "' is not finite";
      return std::string();
    };
    // the line's fault, said precisely (the expected form is recalled in every message)
    if(tokens.size() != 3) why = tokens.size() < 3 ? plural(tokens.size(), "field") : std::string("more than 3 fields");
    else if(n == 0) why = "the mesh has no vertex";
    else if(!parse_count(tokens[0], 0, n - 1, index, why)) why = "vertex_index " + why;
    else
    {
      why = real("u", tokens[1], u);
      if(why.empty()) why = real("v", tokens[2], v);
    }
    if(!why.empty())
      return run.fail(PE::ERROR_MALFORMED_FILE, what, "line " + std::to_string(lineno) + ": " + why +
                      " (expected 'vertex_index u v' with 0 <= vertex_index < " + std::to_string(n) + " and finite u, v)");
    const vertex_descriptor vd(static_cast<Mesh::size_type>(index));
    in.uv[vd] = Point_2(u, v);
    fixed.push_back(vd);
    return EXIT_VALID;
  });
}

int read_polygon(Run& run, const std::string& filename, std::vector<Point_2>& points)
{
  const std::string what = "cannot read the polygon '" + filename + "'";
  return for_each_data_line(run, filename, what, 3, [&](std::size_t lineno, const std::vector<std::string>& tokens) -> int
  {
    std::string why;
    double xy[2] = { 0, 0 };
    if(tokens.size() != 2) why = tokens.size() < 2 ? plural(tokens.size(), "field") : std::string("more than 2 fields");
    for(int k = 0; k < 2 && why.empty(); ++k)
    {
      char* end = nullptr;
      xy[k] = std::strtod(tokens[k].c_str(), &end);
      if(end == tokens[k].c_str() || *end != '\0') why = std::string(k ? "y" : "x") + " '" + tokens[k] + "' is not a number";
      else if(!std::isfinite(xy[k]))
        return run.fail(PE::ERROR_NON_FINITE_COORDINATES, what, "line " + std::to_string(lineno) + ": " +
                        (k ? "y" : "x") + " '" + tokens[k] + "' is not finite");
    }
    if(!why.empty())
      return run.fail(PE::ERROR_MALFORMED_FILE, what, "line " + std::to_string(lineno) + ": " + why +
                      " (expected one vertex per line: 'x y', finite numbers; '#' starts a comment)");
    points.emplace_back(xy[0], xy[1]);
    return EXIT_VALID;
  });
}

namespace {

// draws the picture of the map to `out` (the package's SVG writer)
PE::Error_code draw_picture(std::ostream& out, const Input& in, const Picture& picture)
{
  PE::IO::SVG_options options;
  options.title = picture.title;
  options.inset = picture.inset;
  // the distortion colors need 3D triangles of non-zero area: without them, plain faces
  options.color_by_distortion = picture.color_by_distortion && picture.has_3d_energy;
  // with the caller's certificate the writer only draws; without it, it certifies first
  if(picture.report)
    return picture.has_patches
      ? PE::IO::write_SVG(out, in.mesh, in.uv, *picture.report, options,
          PE::parameters::face_patch_map(picture.patches, PE::parameters::constrained_vertices(picture.constrained)))
      : PE::IO::write_SVG(out, in.mesh, in.uv, *picture.report, options);
  return picture.has_patches
    ? PE::IO::write_SVG(out, in.mesh, in.uv, options,
        PE::parameters::face_patch_map(picture.patches, PE::parameters::constrained_vertices(picture.constrained)))
    : PE::IO::write_SVG(out, in.mesh, in.uv, options);
}

} // namespace

int write_picture(Run& run, const Input& in, const std::string& svg, const Picture& picture)
{
  return write_files_together(run, { { svg, [&](std::ostream& os) { return draw_picture(os, in, picture); } } });
}

int write_outputs(Run& run, const Input& in, const std::string& obj, const std::string& svg, const Picture& picture)
{
  // the map and its picture all or none
  std::vector<Output_file> files;
  files.push_back({ obj, [&](std::ostream& os) {
    return in.has_uv && !in.vt_to_v.empty() ? PE::IO::write_OBJ_with_uv(os, in.mesh, in.uv, &in.vt_to_v, &in.positions)
                                            : PE::IO::write_OBJ_with_uv(os, in.mesh, in.uv);
  } });
  if(!svg.empty()) files.push_back({ svg, [&](std::ostream& os) { return draw_picture(os, in, picture); } });
  return write_files_together(run, files);
}

} // namespace pe_tool
