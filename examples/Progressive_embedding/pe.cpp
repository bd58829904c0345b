// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe`: the command-line tool of the package. Run `pe` without arguments for the usage.
//
// Every subcommand prints one summary line (or, with --json, one JSON object) and
// exits with 0 iff the map it wrote is certified valid by check_embedding() (`check`:
// iff the map read is valid and matches the reference; `svg`: iff the picture was written),
// 1 if it is not (or the algorithm failed), 2 on bad arguments (with the usage),
// 3 if an input cannot be read or is malformed, 4 if an output cannot be written.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
#include <CGAL/Progressive_embedding/internal/protocols.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h> // isatty

#ifndef PE_DEFAULT_DATA_DIR
#define PE_DEFAULT_DATA_DIR ""
#endif
#ifndef PE_DEFAULT_OUTPUT_DIR
#define PE_DEFAULT_OUTPUT_DIR "."
#endif

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef K::Point_2                                            Point_2;
typedef K::Point_3                                            Point_3;
typedef CGAL::Surface_mesh<Point_3>                           Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;
typedef Mesh::Face_index                                      face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>        UV_map;
typedef CGAL::Simple_cartesian<CGAL::Gmpq>                    Exact_kernel;
typedef CGAL::Simple_cartesian<CGAL::Gmpfr>                   Mpfr_kernel;

namespace {

enum Exit_status { EXIT_VALID = 0, EXIT_INVALID = 1, EXIT_USAGE = 2, EXIT_INPUT = 3, EXIT_OUTPUT = 4 };

const char* usage_text =
  "usage: pe <command> [arguments] [--json]\n"
  "\n"
  "commands:\n"
  "  tutte IN OUT.obj [--border fixed|circle|square|triangle] [--weights uniform|mean-value]\n"
  "                   [--number-type double|exact|mpfr:BITS]\n"
  "        Tutte (uniform) or Floater (mean-value) embedding of the disk IN (OFF, OBJ, PLY, STL);\n"
  "        an OBJ with vt keeps its border unless --border is given (default otherwise: circle);\n"
  "        computed in the number type, written in double; exact/mpfr runs also report the\n"
  "        certificate of the map before rounding\n"
  "  thingi MESH SEED OUT.obj [--svg OUT.svg]\n"
  "        the Tutte-failure protocol: remove one face of the closed mesh MESH (seed 0: the last),\n"
  "        pin its vertices to (0,0), (1/2,sqrt(3)/2), (1,0), double Tutte, certify\n"
  "  random-init IN OUT.obj --seed S\n"
  "        border on a circle by arc length, interior vertices uniformly random inside the border\n"
  "  check IN.obj [REF.obj]\n"
  "        certify the uv map of IN; with REF, also require the same faces and a bit-exact border\n"
  "  svg IN.obj OUT.svg\n"
  "        picture of the uv map of IN (flipped and degenerate faces highlighted)\n"
  "  untangle IN.obj OUT.obj [--no-progress]\n"
  "        progressive embedding of the uv map of IN, border kept bit-exactly\n"
  "  embed IN OUT.obj [--border ...] [--weights ...] [--optimize] [--no-progress]\n"
  "        Tutte, then progressive embedding if the Tutte map is not valid; with --optimize, the repair\n"
  "        also re-inserts faces below 1e-3 x the mean area, then optimize runs\n"
  "  optimize IN.obj OUT.obj [--free-border] [--fix FILE] [--iterations N] [--no-progress]\n"
  "        lower the symmetric Dirichlet distortion of the valid uv map of IN without leaving the\n"
  "        valid maps; the border (unless --free-border) and the vertices listed in FILE\n"
  "        (lines 'vertex_index u v', 0-based uv-vertex indices) are kept bit-exactly\n"
  "  generate stacked DEPTH OUT.obj | generate grid N OUT.obj\n"
  "        test inputs: the deep stacked triangulation (corners pinned as in the thingi protocol,\n"
  "        interior at the first corner) or an N x N grid disk (uv = its xy coordinates)\n"
  "  demo [DATA_DIR] [--mesh NAME] [--seed S] [--out-dir DIR] [--no-progress]\n"
  "        the README's main job: thingi protocol on DATA_DIR/meshes/dino.off seed 8, pictures\n"
  "        of the double Tutte map and of its repair by progressive embedding\n"
  "\n"
  "exit status: 0 the map written is certified valid (check: the map read is valid and matches REF;\n"
  "             svg: the picture was written), 1 it is not or the computation failed,\n"
  "             2 bad arguments, 3 unreadable or malformed input, 4 output not writable\n";

int usage(const std::string& why)
{
  if(!why.empty()) std::cerr << "pe: " << why << "\n\n";
  std::cerr << usage_text;
  return EXIT_USAGE;
}

// ---- command line -------------------------------------------------------------------

struct Arguments
{
  std::vector<std::string> positional;
  std::map<std::string, std::string> options; // "--border" -> "circle"; flags -> ""
  bool json = false;

  bool has(const std::string& o) const { return options.count(o) != 0; }
  std::string get(const std::string& o, const std::string& def = std::string()) const
  {
    auto it = options.find(o);
    return it == options.end() ? def : it->second;
  }
};

const std::set<std::string> valued_options = { "--border", "--weights", "--number-type", "--seed", "--svg",
                                               "--mesh", "--out-dir" , "--fix", "--iterations" };
const std::set<std::string> flag_options = { "--json", "--no-progress", "--optimize", "--free-border" };

// returns an empty string on success, the error otherwise
std::string parse_arguments(int argc, char** argv, int first, Arguments& a)
{
  for(int i = first; i < argc; ++i)
  {
    const std::string s = argv[i];
    if(s.size() > 2 && s.compare(0, 2, "--") == 0)
    {
      if(s == "--json") { a.json = true; continue; }
      if(flag_options.count(s)) { a.options[s] = ""; continue; }
      if(!valued_options.count(s)) return "unknown option " + s;
      if(i + 1 >= argc) return "option " + s + " needs a value";
      if(a.options.count(s)) return "option " + s + " given twice";
      a.options[s] = argv[++i];
    }
    else
      a.positional.push_back(s);
  }
  return std::string();
}

std::string check_options(const Arguments& a, const std::set<std::string>& allowed)
{
  for(const auto& o : a.options)
    if(!allowed.count(o.first)) return "option " + o.first + " does not apply to this command";
  return std::string();
}

bool parse_unsigned(const std::string& s, unsigned long& out)
{
  if(s.empty() || s.size() > 18) return false;
  for(char c : s) if(!std::isdigit(static_cast<unsigned char>(c))) return false;
  out = std::stoul(s);
  return true;
}

// ---- output: one summary line or one JSON object ----------------------------------

std::string json_escape(const std::string& s)
{
  std::string o;
  for(char c : s)
  {
    switch(c)
    {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if(static_cast<unsigned char>(c) < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", c); o += b; }
        else o += c;
    }
  }
  return o;
}

struct Result
{
  std::vector<std::pair<std::string, std::string> > fields; // key, JSON value

  void set(const std::string& k, const std::string& raw)
  {
    for(auto& f : fields) if(f.first == k) { f.second = raw; return; }
    fields.emplace_back(k, raw);
  }
  void add(const std::string& k, bool b) { set(k, b ? "true" : "false"); }
  template <class Integer, class = std::enable_if_t<std::is_integral<Integer>::value && !std::is_same<Integer, bool>::value> >
  void add(const std::string& k, Integer n) { set(k, std::to_string(n)); }
  void add(const std::string& k, double d)
  {
    if(!std::isfinite(d)) { set(k, "null"); return; }
    char b[64]; std::snprintf(b, sizeof b, "%.17g", d); set(k, b);
  }
  void add(const std::string& k, const char* s) { set(k, "\"" + json_escape(s) + "\""); }
  void add(const std::string& k, const std::string& s) { set(k, "\"" + json_escape(s) + "\""); }

  std::string json() const
  {
    std::string o = "{";
    for(std::size_t i = 0; i < fields.size(); ++i)
      o += (i ? ", \"" : "\"") + fields[i].first + "\": " + fields[i].second;
    return o + "}";
  }
};

// the certificate's fields; `prefix` distinguishes several maps ("tutte_", "before_rounding_")
void add_report(Result& r, const PE::Embedding_report& rep, const std::string& prefix = std::string())
{
  r.add(prefix + "valid", rep.is_valid());
  r.add(prefix + "flipped", rep.flipped);
  r.add(prefix + "degenerate", rep.degenerate);
  if(prefix.empty())
  {
    r.add("faces", rep.faces);
    r.add("vertices", rep.vertices);
    r.add("border_vertices", rep.border_vertices);
  }
  r.add(prefix + "non_finite", rep.non_finite);
  r.add(prefix + "border_simple", rep.border_simple);
  r.add(prefix + "overlapping_pairs", rep.overlapping_pairs);
  r.add(prefix + "clockwise", rep.clockwise);
  r.add(prefix + "min_signed_area", rep.min_signed_area);
  r.add(prefix + "max_energy_3d", rep.max_energy_3d);
  r.add(prefix + "mean_energy_3d", rep.mean_energy_3d);
  if(rep.status != PE::OK) r.add(prefix + "check_status", PE::get_error_name(rep.status));
}

int finish(const Arguments& a, Result& r, const std::string& summary, int code)
{
  if(a.json) std::cout << r.json() << std::endl;
  else std::cout << summary << std::endl;
  return code;
}

std::string seconds_string(double s)
{
  char b[32]; std::snprintf(b, sizeof b, "%.3g s", s); return b;
}

// ---- progress bar for long runs (stderr, terminals only) -----------------------------

struct Progress
{
  CGAL::Real_timer timer;
  bool enabled = false;
  bool shown = false;
  double last = 0;
  std::string label;

  Progress(const std::string& label, bool enabled) : enabled(enabled && isatty(2)), label(label) { timer.start(); }

  bool update(double fraction)
  {
    const double now = timer.time();
    if(!enabled || now < 1.0 || (shown && now - last < 0.1)) return true; // short runs: no bar; 10 redraws a second
    last = now;
    const int width = 40, done = static_cast<int>(std::max(0., std::min(1., fraction)) * width);
    std::fprintf(stderr, "\r%s [%s%s] %3d%% %6.1f s", label.c_str(), std::string(done, '#').c_str(),
                 std::string(width - done, '.').c_str(), static_cast<int>(100 * fraction), now);
    std::fflush(stderr);
    shown = true;
    return true; // never cancel
  }
  std::function<bool(double)> callback() { return [this](double f) { return update(f); }; }
  void finish()
  {
    if(shown) { std::fprintf(stderr, "\r%*s\r", 80, ""); std::fflush(stderr); }
    shown = false;
  }
};

// faces(m).size(): num_faces(Surface_mesh) also counts removed faces (thingi_cut removes one)
std::size_t count_faces(const Mesh& m) { return static_cast<std::size_t>(std::distance(faces(m).begin(), faces(m).end())); }

// ---- input ------------------------------------------------------------------------

struct Input
{
  std::string filename;
  Mesh mesh;
  UV_map uv;
  bool has_uv = false;                  // read from `vt` entries
  std::vector<std::size_t> vt_to_v;     // with has_uv: to write the seams back
  std::vector<Point_3> positions;
};

std::string lower_extension(const std::string& f)
{
  const std::size_t dot = f.find_last_of('.');
  if(dot == std::string::npos || f.find_first_of("/\\", dot) != std::string::npos) return std::string();
  std::string e = f.substr(dot + 1);
  for(char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

bool obj_has_texture_coordinates(const std::string& f)
{
  std::ifstream in(f, std::ios::binary);
  std::string line;
  while(std::getline(in, line))
  {
    std::size_t i = line.find_first_not_of(" \t");
    if(i != std::string::npos && line.compare(i, 2, "vt") == 0 && i + 2 < line.size()
       && (line[i + 2] == ' ' || line[i + 2] == '\t'))
      return true;
  }
  return false;
}

enum class Uv_mode { REQUIRED, OPTIONAL, IGNORED };

// prints the reason and returns false if the file cannot be used
bool read_input(const std::string& filename, Input& in, Uv_mode mode)
{
  const bool require_uv = (mode == Uv_mode::REQUIRED);
  in.filename = filename;
  auto fail = [&](PE::Error_code ec, std::size_t line, const std::string& msg) {
    std::cerr << "pe: cannot use '" << filename << "': ";
    if(line > 0) std::cerr << "line " << line << ": ";
    std::cerr << msg << " (" << PE::get_error_name(ec) << ")" << std::endl;
    return false;
  };
  {
    std::ifstream probe(filename, std::ios::binary);
    if(!probe) return fail(PE::ERROR_CANNOT_READ_FILE, 0, std::string("cannot open the file: ") + std::strerror(errno));
  }
  const std::string ext = lower_extension(filename);
  if(mode != Uv_mode::IGNORED && ext == "obj" && obj_has_texture_coordinates(filename))
  {
    in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
    const PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(filename, in.mesh, in.uv, &in.vt_to_v, &in.positions);
    if(!r) return fail(r.status, r.line, r.message.empty() ? PE::get_error_message(r.status) : r.message);
    in.has_uv = true;
    return true;
  }
  if(require_uv)
    return fail(PE::ERROR_MALFORMED_FILE, 0, "no texture coordinates: an OBJ file with vt entries and f v/vt faces is needed");
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    return fail(PE::ERROR_MALFORMED_FILE, 0, "unknown format '." + ext + "' (OFF, OBJ, PLY or STL expected)");
  bool ok = false;
  try { ok = CGAL::IO::read_polygon_mesh(filename, in.mesh); } catch(...) { ok = false; }
  if(!ok)
    return fail(PE::ERROR_MALFORMED_FILE, 0, "not a valid " + ext + " polygon mesh (CGAL::IO::read_polygon_mesh failed)");
  if(count_faces(in.mesh) == 0)
    return fail(PE::ERROR_EMPTY_MESH, 0, PE::get_error_message(PE::ERROR_EMPTY_MESH));
  in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
  return true;
}

int write_outputs(const Input& in, const std::string& obj, const std::string& svg, const std::string& title)
{
  PE::Error_code ec = in.has_uv ? PE::IO::write_OBJ_with_uv(obj, in.mesh, in.uv, &in.vt_to_v, &in.positions)
                                : PE::IO::write_OBJ_with_uv(obj, in.mesh, in.uv);
  if(ec != PE::OK)
  {
    std::cerr << "pe: cannot write '" << obj << "': " << PE::get_error_message(ec) << " (" << PE::get_error_name(ec) << ")" << std::endl;
    return EXIT_OUTPUT;
  }
  if(!svg.empty())
  {
    ec = PE::IO::write_SVG(svg, in.mesh, in.uv, title);
    if(ec != PE::OK)
    {
      std::cerr << "pe: cannot write '" << svg << "': " << PE::get_error_message(ec) << " (" << PE::get_error_name(ec) << ")" << std::endl;
      return EXIT_OUTPUT;
    }
  }
  return EXIT_VALID;
}

// ---- number types -----------------------------------------------------------------

enum class Number_type { DOUBLE, EXACT, MPFR };

template <class FT>
FT ft_from_double(double d)
{
  if constexpr(std::is_same<FT, CGAL::Gmpfr>::value)
    return CGAL::Gmpfr(d, CGAL::Gmpfr::get_default_precision()); // exact: at least 53 bits
  else
    return FT(d);
}

bool parse_border(const std::string& s, PE::Border_shape& b)
{
  if(s == "fixed") b = PE::Border_shape::FIXED;
  else if(s == "circle") b = PE::Border_shape::CIRCLE;
  else if(s == "square") b = PE::Border_shape::SQUARE;
  else if(s == "triangle") b = PE::Border_shape::TRIANGLE;
  else return false;
  return true;
}

bool parse_weights(const std::string& s, PE::Weights& w)
{
  if(s == "uniform") w = PE::Weights::UNIFORM;
  else if(s == "mean-value") w = PE::Weights::MEAN_VALUE;
  else return false;
  return true;
}

// Tutte in the number type of `Kernel2`; the result, rounded to double, goes to in.uv.
// `exact_report` is the certificate of the map before rounding.
template <class Kernel2>
PE::Error_code tutte_in(Input& in, PE::Border_shape border, PE::Weights weights, PE::Embedding_report& exact_report)
{
  typedef typename Kernel2::FT FT;
  typedef typename Kernel2::Point_2 P2;
  auto uvx = in.mesh.add_property_map<vertex_descriptor, P2>("v:pe_uv_nt", P2(ft_from_double<FT>(0), ft_from_double<FT>(0))).first;
  for(vertex_descriptor v : vertices(in.mesh))
    uvx[v] = P2(ft_from_double<FT>(in.uv[v].x()), ft_from_double<FT>(in.uv[v].y())); // exact copy (fixed border)
  const PE::Error_code ec = PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), uvx,
                                                PE::parameters::weights(weights, PE::parameters::border_shape(border)));
  if(ec == PE::OK)
  {
    exact_report = PE::check_embedding(in.mesh, uvx);
    for(vertex_descriptor v : vertices(in.mesh))
      in.uv[v] = Point_2(CGAL::to_double(uvx[v].x()), CGAL::to_double(uvx[v].y()));
  }
  in.mesh.remove_property_map(uvx);
  return ec;
}

// ---- commands ---------------------------------------------------------------------

int cmd_tutte(const Arguments& a)
{
  std::string err = check_options(a, { "--border", "--weights", "--number-type" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("tutte needs IN and OUT.obj");
  PE::Border_shape border = PE::Border_shape::CIRCLE;
  PE::Weights weights = PE::Weights::UNIFORM;
  if(a.has("--border") && !parse_border(a.get("--border"), border)) return usage("unknown border '" + a.get("--border") + "'");
  if(a.has("--weights") && !parse_weights(a.get("--weights"), weights)) return usage("unknown weights '" + a.get("--weights") + "'");
  Number_type nt = Number_type::DOUBLE;
  unsigned long bits = 0;
  const std::string nts = a.get("--number-type", "double");
  if(nts == "double") nt = Number_type::DOUBLE;
  else if(nts == "exact") nt = Number_type::EXACT;
  else if(nts.compare(0, 5, "mpfr:") == 0 && parse_unsigned(nts.substr(5), bits) && bits >= 53 && bits <= 1u << 20)
    nt = Number_type::MPFR;
  else return usage("unknown number type '" + nts + "' (double, exact or mpfr:BITS with BITS >= 53)");

  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::OPTIONAL)) return EXIT_INPUT;
  if(!a.has("--border")) border = in.has_uv ? PE::Border_shape::FIXED : PE::Border_shape::CIRCLE;
  else if(border == PE::Border_shape::FIXED && !in.has_uv)
    return usage("--border fixed needs an input OBJ with texture coordinates");

  CGAL::Real_timer timer;
  timer.start();
  PE::Embedding_report exact_report;
  PE::Error_code ec;
  if(nt == Number_type::DOUBLE)
    ec = PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), in.uv, PE::parameters::weights(weights, PE::parameters::border_shape(border)));
  else if(nt == Number_type::EXACT)
    ec = tutte_in<Exact_kernel>(in, border, weights, exact_report);
  else
  {
    CGAL::Gmpfr::set_default_precision(static_cast<CGAL::Gmpfr::Precision_type>(bits));
    ec = tutte_in<Mpfr_kernel>(in, border, weights, exact_report);
  }
  PE::Embedding_report report;
  if(ec == PE::OK) report = PE::check_embedding(in.mesh, in.uv);
  const double seconds = timer.time();

  Result r;
  r.add("command", "tutte");
  r.add("input", in.filename);
  r.add("output", a.positional[1]);
  r.add("number_type", nts);
  r.add("status", PE::get_error_name(ec));
  std::ostringstream s;
  if(ec != PE::OK)
  {
    r.add("valid", false); r.add("flipped", std::size_t(0)); r.add("degenerate", std::size_t(0));
    r.add("faces", count_faces(in.mesh)); r.add("vertices", num_vertices(in.mesh));
    r.add("seconds", seconds);
    std::cerr << "pe: tutte failed: " << PE::get_error_message(ec) << std::endl;
    s << "tutte " << in.filename << ": " << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  add_report(r, report);
  if(nt != Number_type::DOUBLE)
  {
    r.add("valid_before_rounding", exact_report.is_valid());
    r.add("flipped_before_rounding", exact_report.flipped);
    r.add("degenerate_before_rounding", exact_report.degenerate);
  }
  r.add("seconds", seconds);
  const int w = write_outputs(in, a.positional[1], std::string(), std::string());
  r.add("written", w == EXIT_VALID);
  s << "tutte " << in.filename << " (" << nts << "): ";
  if(nt != Number_type::DOUBLE)
    s << "before rounding " << (exact_report.is_valid() ? "valid" : "INVALID") << " (flipped " << exact_report.flipped
      << ", degenerate " << exact_report.degenerate << "); written in double: ";
  s << report.summary() << "; " << seconds_string(seconds);
  if(w != EXIT_VALID) return finish(a, r, s.str(), w);
  return finish(a, r, s.str(), report.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

// The Tutte-failure protocol (DESIGN.md section 6) on `in` (a closed mesh read without uv).
PE::Error_code thingi_protocol(Input& in, unsigned seed)
{
  std::array<vertex_descriptor, 3> pinned;
  PE::Error_code ec = PE::internal::thingi_cut(in.mesh, seed, pinned);
  if(ec != PE::OK) return ec;
  in.uv[pinned[0]] = Point_2(0, 0);
  in.uv[pinned[1]] = Point_2(0.5, std::sqrt(3.) / 2);
  in.uv[pinned[2]] = Point_2(1, 0);
  return PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), in.uv,
                             PE::parameters::weights(PE::Weights::UNIFORM, PE::parameters::border_shape(PE::Border_shape::FIXED)));
}

int cmd_thingi(const Arguments& a)
{
  std::string err = check_options(a, { "--svg" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 3) return usage("thingi needs MESH, SEED and OUT.obj");
  unsigned long seed = 0;
  if(!parse_unsigned(a.positional[1], seed) || seed > std::numeric_limits<unsigned>::max())
    return usage("SEED must be a non-negative integer, not '" + a.positional[1] + "'");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::IGNORED)) return EXIT_INPUT; // the protocol needs the closed mesh
  const std::size_t nv = num_vertices(in.mesh);

  CGAL::Real_timer timer;
  timer.start();
  const PE::Error_code ec = thingi_protocol(in, static_cast<unsigned>(seed));
  PE::Embedding_report report;
  if(ec == PE::OK) report = PE::check_embedding(in.mesh, in.uv);
  const double seconds = timer.time();

  Result r;
  r.add("command", "thingi");
  r.add("input", in.filename);
  r.add("seed", static_cast<std::size_t>(seed));
  r.add("output", a.positional[2]);
  r.add("status", PE::get_error_name(ec));
  std::ostringstream s;
  if(ec != PE::OK)
  {
    r.add("valid", false); r.add("flipped", std::size_t(0)); r.add("degenerate", std::size_t(0));
    r.add("faces", count_faces(in.mesh)); r.add("vertices", nv); r.add("seconds", seconds);
    std::cerr << "pe: thingi failed: " << PE::get_error_message(ec)
              << (ec == PE::ERROR_NOT_A_DISK ? " (the protocol needs a closed genus-0 mesh)" : "") << std::endl;
    s << "thingi " << in.filename << " seed " << seed << ": " << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  add_report(r, report);
  r.add("seconds", seconds);
  const std::string title = in.filename + " seed " + std::to_string(seed) + ", double Tutte: " +
                            (report.is_valid() ? "valid" : "INVALID");
  const int w = write_outputs(in, a.positional[2], a.get("--svg"), title);
  r.add("written", w == EXIT_VALID);
  s << "thingi " << in.filename << " seed " << seed << ", double Tutte: " << report.summary() << "; " << seconds_string(seconds);
  if(w != EXIT_VALID) return finish(a, r, s.str(), w);
  return finish(a, r, s.str(), report.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

int cmd_random_init(const Arguments& a)
{
  std::string err = check_options(a, { "--seed" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("random-init needs IN and OUT.obj");
  unsigned long seed = 0;
  if(!a.has("--seed")) return usage("random-init needs --seed S");
  if(!parse_unsigned(a.get("--seed"), seed) || seed > std::numeric_limits<unsigned>::max())
    return usage("--seed must be a non-negative integer, not '" + a.get("--seed") + "'");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::OPTIONAL)) return EXIT_INPUT;

  CGAL::Real_timer timer;
  timer.start();
  // the border: on the unit circle by arc length
  PE::Error_code ec = PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), in.uv,
                                          PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  PE::Embedding_report report;
  if(ec == PE::OK)
  {
    // Interior points uniformly in the disk inscribed in the border polygon: its radius is the
    // smallest distance from the center to a border edge (cos(pi/n) for n evenly spaced vertices;
    // smaller when the arc-length spacing is uneven), shrunk a little against rounding.
    double r_in = 1;
    for(auto h : halfedges(in.mesh))
    {
      if(!is_border(h, in.mesh)) continue;
      const Point_2 p = in.uv[source(h, in.mesh)], q = in.uv[target(h, in.mesh)];
      const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
      if(len > 0) r_in = std::min(r_in, std::abs(p.x() * q.y() - p.y() * q.x()) / len);
    }
    r_in *= 1 - 1e-9;
    std::mt19937 gen(static_cast<unsigned>(seed));
    std::uniform_real_distribution<double> unif(-1., 1.);
    for(vertex_descriptor v : vertices(in.mesh))
    {
      if(CGAL::is_border(v, in.mesh)) continue;
      double x, y;
      do { x = unif(gen); y = unif(gen); } while(x * x + y * y >= 1);
      in.uv[v] = Point_2(r_in * x, r_in * y);
    }
    report = PE::check_embedding(in.mesh, in.uv);
  }
  const double seconds = timer.time();
  Result r;
  r.add("command", "random-init");
  r.add("input", in.filename);
  r.add("seed", static_cast<std::size_t>(seed));
  r.add("output", a.positional[1]);
  r.add("status", PE::get_error_name(ec));
  std::ostringstream s;
  if(ec != PE::OK)
  {
    r.add("valid", false); r.add("flipped", std::size_t(0)); r.add("degenerate", std::size_t(0));
    r.add("faces", count_faces(in.mesh)); r.add("vertices", num_vertices(in.mesh)); r.add("seconds", seconds);
    std::cerr << "pe: random-init failed: " << PE::get_error_message(ec) << std::endl;
    s << "random-init " << in.filename << ": " << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  add_report(r, report);
  r.add("seconds", seconds);
  const int w = write_outputs(in, a.positional[1], std::string(), std::string());
  r.add("written", w == EXIT_VALID);
  s << "random-init " << in.filename << " seed " << seed << ": " << report.summary() << "; " << seconds_string(seconds);
  if(w != EXIT_VALID) return finish(a, r, s.str(), w);
  return finish(a, r, s.str(), report.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; }

int cmd_check(const Arguments& a)
{
  std::string err = check_options(a, {});
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 1 && a.positional.size() != 2) return usage("check needs IN.obj and optionally REF.obj");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::REQUIRED)) return EXIT_INPUT;
  CGAL::Real_timer timer;
  timer.start();
  const PE::Embedding_report report = PE::check_embedding(in.mesh, in.uv);
  const double seconds = timer.time();
  Result r;
  r.add("command", "check");
  r.add("input", in.filename);
  r.add("status", PE::get_error_name(report.status));
  add_report(r, report);
  r.add("seconds", seconds);
  std::ostringstream s;
  s << "check " << in.filename << ": " << report.summary();
  bool ok = report.is_valid();
  if(a.positional.size() == 2)
  {
    Input ref;
    if(!read_input(a.positional[1], ref, Uv_mode::REQUIRED)) return EXIT_INPUT;
    // the same faces: same vertex count and, face by face, the same vertex indices (up to rotation)
    std::vector<vertex_descriptor> vi(vertices(in.mesh).begin(), vertices(in.mesh).end());
    std::vector<vertex_descriptor> vr(vertices(ref.mesh).begin(), vertices(ref.mesh).end());
    auto face_list = [](const Mesh& m) {
      std::map<vertex_descriptor, std::size_t> id;
      for(vertex_descriptor v : vertices(m)) id.emplace(v, id.size());
      std::vector<std::vector<std::size_t> > F;
      for(face_descriptor f : faces(m))
      {
        std::vector<std::size_t> t;
        for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) t.push_back(id[v]);
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        F.push_back(t);
      }
      return F;
    };
    const bool same_faces = vi.size() == vr.size() && face_list(in.mesh) == face_list(ref.mesh);
    std::size_t border_differing = 0, border_count = 0;
    if(same_faces)
      for(std::size_t i = 0; i < vr.size(); ++i)
        if(CGAL::is_border(vr[i], ref.mesh))
        {
          ++border_count;
          if(!same_bits(in.uv[vi[i]].x(), ref.uv[vr[i]].x()) || !same_bits(in.uv[vi[i]].y(), ref.uv[vr[i]].y()))
            ++border_differing;
        }
    const bool border_exact = same_faces && border_differing == 0;
    r.add("reference", ref.filename);
    r.add("same_faces", same_faces);
    r.add("border_exact", border_exact);
    r.add("border_vertices_differing", border_differing);
    s << "; against " << ref.filename << ": " << (same_faces ? "same faces" : "DIFFERENT faces");
    if(same_faces) s << ", border " << (border_exact ? "bit-exact" : "CHANGED") << " (" << border_differing << " of "
                     << border_count << " border vertices differ)";
    ok = ok && same_faces && border_exact;
  }
  r.add("ok", ok);
  return finish(a, r, s.str(), ok ? EXIT_VALID : EXIT_INVALID);
}

int cmd_svg(const Arguments& a)
{
  std::string err = check_options(a, {});
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("svg needs IN.obj and OUT.svg");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::REQUIRED)) return EXIT_INPUT;
  const PE::Embedding_report report = PE::check_embedding(in.mesh, in.uv);
  Result r;
  r.add("command", "svg");
  r.add("input", in.filename);
  r.add("output", a.positional[1]);
  r.add("status", PE::get_error_name(report.status));
  add_report(r, report);
  r.add("seconds", 0.);
  const PE::Error_code ec = PE::IO::write_SVG(a.positional[1], in.mesh, in.uv, in.filename + ": " + report.summary());
  r.add("written", ec == PE::OK);
  if(ec != PE::OK)
  {
    std::cerr << "pe: cannot write '" << a.positional[1] << "': " << PE::get_error_message(ec) << " (" << PE::get_error_name(ec) << ")" << std::endl;
    return finish(a, r, "svg " + in.filename + ": nothing written", ec == PE::ERROR_CANNOT_WRITE_FILE ? EXIT_OUTPUT : EXIT_INVALID);
  }
  return finish(a, r, "svg " + in.filename + " -> " + a.positional[1] + ": " + report.summary(), EXIT_VALID);
}

// progressive embedding of in.uv (border fixed); fills `r` and the summary
PE::Error_code run_progressive_embedding(Input& in, bool progress, PE::Progressive_embedding_statistics& stats)
{
  Progress bar("progressive embedding", progress);
  const PE::Error_code ec = PE::progressive_embedding(in.mesh, in.uv,
                              PE::parameters::statistics(&stats, CGAL::parameters::callback(bar.callback())));
  bar.finish();
  return ec;
}

// distortion optimization of in.uv (valid map), with a progress bar
PE::Error_code run_optimize(Input& in, bool progress, bool free_border, const std::vector<vertex_descriptor>& fixed,
                            std::size_t iterations, PE::Optimization_statistics& stats)
{
  Progress bar("optimization", progress);
  const PE::Error_code ec = PE::optimize_distortion(in.mesh, in.uv,
    PE::parameters::free_border(free_border, PE::parameters::constrained_vertices(fixed,
    PE::parameters::optimization_statistics(&stats, CGAL::parameters::callback(bar.callback()).number_of_iterations(iterations)))));
  bar.finish();
  return ec;
}

void add_optimization(Result& r, const PE::Optimization_statistics& os)
{
  r.add("iterations", os.iterations);
  r.add("converged", os.converged);
  r.add("energy_before", os.energy_before);
  r.add("energy_after", os.energy_after);
  r.add("seconds_optimization", os.seconds);
}

void add_statistics(Result& r, const PE::Progressive_embedding_statistics& st)
{
  r.add("invalid_before", st.invalid_faces_before);
  r.add("collapses", st.collapses);
  r.add("insertions", st.insertions);
  r.add("extra_smoothing", st.insertions_with_extra_smoothing);
  r.add("expansion_rounds", st.expansion_rounds);
  r.add("seconds_collapse", st.seconds_collapse);
  r.add("seconds_insertion", st.seconds_insertion);
}

std::string statistics_summary(const PE::Progressive_embedding_statistics& st)
{
  std::ostringstream s;
  s << "invalid before " << st.invalid_faces_before << ", collapses " << st.collapses << ", insertions " << st.insertions;
  if(st.insertions_with_extra_smoothing) s << " (" << st.insertions_with_extra_smoothing << " with extra smoothing)";
  return s.str();
}

// The common end of the commands that write a map: on failure a message and nothing written,
// else the OBJ file; the exit status says whether the map written is certified valid.
int write_and_finish(const Arguments& a, Result& r, std::ostringstream& s, const Input& in, PE::Error_code ec,
                     const PE::Embedding_report& report, const char* failure)
{
  if(ec != PE::OK)
  {
    r.add("written", false);
    std::cerr << "pe: " << failure << ": " << PE::get_error_message(ec) << std::endl;
    s << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  const int w = write_outputs(in, a.positional[1], std::string(), std::string());
  r.add("written", w == EXIT_VALID);
  s << report.summary();
  if(w != EXIT_VALID) return finish(a, r, s.str(), w);
  return finish(a, r, s.str(), report.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

int cmd_untangle(const Arguments& a)
{
  std::string err = check_options(a, { "--no-progress" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("untangle needs IN.obj and OUT.obj");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::REQUIRED)) return EXIT_INPUT;
  CGAL::Real_timer timer;
  timer.start();
  PE::Progressive_embedding_statistics st;
  const PE::Error_code ec = run_progressive_embedding(in, !a.has("--no-progress"), st);
  const double seconds = timer.time();
  const PE::Embedding_report report = (ec == PE::OK) ? st.report : PE::check_embedding(in.mesh, in.uv);
  Result r;
  r.add("command", "untangle");
  r.add("input", in.filename);
  r.add("output", a.positional[1]);
  r.add("status", PE::get_error_name(ec));
  add_report(r, report);
  if(ec != PE::OK) r.add("valid", false);
  add_statistics(r, st);
  r.add("seconds", seconds);
  std::ostringstream s;
  s << "untangle " << in.filename << ": faces " << report.faces << ", " << statistics_summary(st) << ", " << seconds_string(seconds) << "; ";
  return write_and_finish(a, r, s, in, ec, report, "progressive embedding failed");
}

int cmd_embed(const Arguments& a)
{
  std::string err = check_options(a, { "--border", "--weights", "--no-progress", "--optimize" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("embed needs IN and OUT.obj");
  const bool optimize = a.has("--optimize");
  PE::Border_shape border = PE::Border_shape::CIRCLE;
  PE::Weights weights = PE::Weights::UNIFORM;
  if(a.has("--border") && !parse_border(a.get("--border"), border)) return usage("unknown border '" + a.get("--border") + "'");
  if(a.has("--weights") && !parse_weights(a.get("--weights"), weights)) return usage("unknown weights '" + a.get("--weights") + "'");
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::OPTIONAL)) return EXIT_INPUT;
  if(!a.has("--border")) border = in.has_uv ? PE::Border_shape::FIXED : PE::Border_shape::CIRCLE;
  else if(border == PE::Border_shape::FIXED && !in.has_uv)
    return usage("--border fixed needs an input OBJ with texture coordinates");

  CGAL::Real_timer timer;
  timer.start();
  PE::Error_code ec = PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), in.uv, PE::parameters::weights(weights, PE::parameters::border_shape(border)));
  PE::Embedding_report tutte_report, report;
  PE::Progressive_embedding_statistics st;
  bool repaired = false;
  if(ec == PE::OK)
  {
    tutte_report = PE::check_embedding(in.mesh, in.uv);
    report = tutte_report;
    if(!tutte_report.is_valid())
    {
      repaired = true;
      if(optimize)
      {
        // for quality, also re-insert faces far below the mean area (they cannot be optimized away)
        Progress bar("progressive embedding", !a.has("--no-progress"));
        ec = PE::progressive_embedding(in.mesh, in.uv, PE::parameters::minimum_area_ratio(1e-3,
               PE::parameters::statistics(&st, CGAL::parameters::callback(bar.callback()))));
        bar.finish();
      }
      else
        ec = run_progressive_embedding(in, !a.has("--no-progress"), st);
      report = (ec == PE::OK) ? st.report : PE::check_embedding(in.mesh, in.uv);
    }
  }
  PE::Optimization_statistics os;
  if(ec == PE::OK && optimize)
  {
    const PE::Error_code eo = run_optimize(in, !a.has("--no-progress"), false, std::vector<vertex_descriptor>(), 300, os);
    if(eo != PE::OK && eo != PE::ERROR_BUDGET_EXHAUSTED) ec = eo;
    else report = os.report;
  }
  const double seconds = timer.time();
  Result r;
  r.add("command", "embed");
  r.add("input", in.filename);
  r.add("output", a.positional[1]);
  r.add("status", PE::get_error_name(ec));
  add_report(r, report);
  if(ec != PE::OK) r.add("valid", false);
  r.add("tutte_valid", tutte_report.is_valid());
  r.add("tutte_flipped", tutte_report.flipped);
  r.add("tutte_degenerate", tutte_report.degenerate);
  r.add("repaired", repaired);
  add_statistics(r, st);
  if(optimize) add_optimization(r, os);
  r.add("seconds", seconds);
  std::ostringstream s;
  s << "embed " << in.filename << ": faces " << count_faces(in.mesh) << ", Tutte "
    << (tutte_report.is_valid() ? "valid" : "INVALID") << " (flipped " << tutte_report.flipped << ", degenerate "
    << tutte_report.degenerate << ")";
  if(repaired) s << ", progressive embedding: " << statistics_summary(st);
  if(optimize) s << ", optimization: " << os.iterations << " iterations, mean sym. Dirichlet " << os.energy_before << " -> " << os.energy_after;
  s << ", " << seconds_string(seconds) << "; ";
  return write_and_finish(a, r, s, in, ec, report, "embed failed");
}

int cmd_optimize(const Arguments& a)
{
  std::string err = check_options(a, { "--free-border", "--fix", "--iterations", "--no-progress" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 2) return usage("optimize needs IN.obj and OUT.obj");
  std::size_t iterations = 200;
  if(a.has("--iterations"))
  {
    char* end = nullptr;
    const long n = std::strtol(a.get("--iterations").c_str(), &end, 10);
    if(!end || *end != '\0' || n < 1) return usage("--iterations must be a positive integer, not '" + a.get("--iterations") + "'");
    iterations = std::size_t(n);
  }
  Input in;
  if(!read_input(a.positional[0], in, Uv_mode::REQUIRED)) return EXIT_INPUT;
  std::vector<vertex_descriptor> fixed;
  if(a.has("--fix"))
  {
    std::ifstream f(a.get("--fix"));
    if(!f) { std::cerr << "pe: " << a.get("--fix") << ": cannot open (ERROR_CANNOT_READ_FILE)" << std::endl; return EXIT_INPUT; }
    std::string line;
    std::size_t lineno = 0;
    while(std::getline(f, line))
    {
      ++lineno;
      std::istringstream ls(line);
      long idx; double u, v; std::string extra;
      if(line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
      if(!(ls >> idx >> u >> v) || (ls >> extra) || idx < 0 || std::size_t(idx) >= in.mesh.number_of_vertices()
         || !std::isfinite(u) || !std::isfinite(v))
      {
        std::cerr << "pe: " << a.get("--fix") << ": line " << lineno << ": expected 'vertex_index u v' with 0 <= vertex_index < "
                  << in.mesh.number_of_vertices() << " and finite u, v (ERROR_MALFORMED_FILE)" << std::endl;
        return EXIT_INPUT;
      }
      const vertex_descriptor vd(static_cast<Mesh::size_type>(idx));
      in.uv[vd] = Point_2(u, v);
      fixed.push_back(vd);
    }
  }
  CGAL::Real_timer timer;
  timer.start();
  PE::Optimization_statistics os;
  const PE::Error_code ec = run_optimize(in, !a.has("--no-progress"), a.has("--free-border"), fixed, iterations, os);
  const double seconds = timer.time();
  Result r;
  r.add("command", "optimize");
  r.add("input", in.filename);
  r.add("output", a.positional[1]);
  r.add("status", PE::get_error_name(ec));
  add_report(r, os.report);
  add_optimization(r, os);
  r.add("constrained", fixed.size());
  r.add("seconds", seconds);
  std::ostringstream s;
  s << "optimize " << in.filename << ": faces " << os.report.faces << ", " << os.iterations << " iterations"
    << (os.converged ? " (converged)" : "") << ", mean sym. Dirichlet " << os.energy_before << " -> " << os.energy_after
    << ", " << seconds_string(seconds) << "; ";
  if(ec == PE::ERROR_INVALID_EMBEDDING)
  {
    r.add("written", false);
    std::cerr << "pe: the input map is not valid" << (fixed.empty() ? "" : " with the constraints of --fix")
              << ": optimize needs a valid map (run pe untangle first)" << std::endl;
    s << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  // a budget that runs out still leaves a valid, improved map: it is written
  return write_and_finish(a, r, s, in, ec == PE::ERROR_BUDGET_EXHAUSTED ? PE::OK : ec, os.report, "optimization failed");
}

int cmd_generate(const Arguments& a)
{
  std::string err = check_options(a, {});
  if(!err.empty()) return usage(err);
  if(a.positional.size() != 3 || (a.positional[0] != "stacked" && a.positional[0] != "grid"))
    return usage("generate needs 'stacked DEPTH OUT.obj' or 'grid N OUT.obj'");
  unsigned long n = 0;
  if(!parse_unsigned(a.positional[1], n) || n > 100000 || (a.positional[0] == "grid" && (n < 2 || n > 4000)))
    return usage("bad size '" + a.positional[1] + "'");
  Input in;
  in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
  if(a.positional[0] == "stacked")
  {
    const auto c = PE::internal::make_stacked_triangulation(n, in.mesh);
    in.uv[c[0]] = Point_2(0, 0);
    in.uv[c[1]] = Point_2(0.5, std::sqrt(3.) / 2);
    in.uv[c[2]] = Point_2(1, 0);
  }
  else
  {
    PE::internal::make_grid_disk(n, in.mesh);
    for(vertex_descriptor v : vertices(in.mesh)) in.uv[v] = Point_2(in.mesh.point(v).x(), in.mesh.point(v).y());
  }
  const PE::Embedding_report report = PE::check_embedding(in.mesh, in.uv);
  Result r;
  r.add("command", "generate");
  r.add("output", a.positional[2]);
  r.add("status", "OK");
  add_report(r, report);
  r.add("seconds", 0.);
  const int w = write_outputs(in, a.positional[2], std::string(), std::string());
  r.add("written", w == EXIT_VALID);
  std::ostringstream s;
  s << "generate " << a.positional[0] << " " << n << " -> " << a.positional[2] << ": " << report.summary();
  if(w != EXIT_VALID) return finish(a, r, s.str(), w);
  return finish(a, r, s.str(), report.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

int cmd_demo(const Arguments& a)
{
  std::string err = check_options(a, { "--mesh", "--seed", "--out-dir", "--no-progress" });
  if(!err.empty()) return usage(err);
  if(a.positional.size() > 1) return usage("demo takes at most DATA_DIR");
  std::string data = a.positional.empty() ? std::string(PE_DEFAULT_DATA_DIR) : a.positional[0];
  if(a.positional.empty() && std::getenv("CGAL_DATA_DIR") && data.empty()) data = std::getenv("CGAL_DATA_DIR");
  const std::string mesh_name = a.get("--mesh", "dino.off");
  unsigned long seed = 8;
  if(a.has("--seed") && (!parse_unsigned(a.get("--seed"), seed) || seed > std::numeric_limits<unsigned>::max()))
    return usage("--seed must be a non-negative integer");
  const std::string out_dir = a.get("--out-dir", PE_DEFAULT_OUTPUT_DIR);
  std::string stem = mesh_name.substr(0, mesh_name.find_last_of('.'));
  stem = stem.substr(stem.find_last_of('/') + 1) + "_seed" + std::to_string(seed);
  const std::string base = out_dir + "/" + stem;

  Input in;
  const std::string path = data + "/meshes/" + mesh_name;
  if(!read_input(path, in, Uv_mode::IGNORED))
  {
    std::cerr << "pe: the demo needs libcgal-demo's meshes: install the Debian package libcgal-demo and configure with cmake,\n"
                 "    or give the folder that contains meshes/ (e.g. the data folder of /usr/share/doc/libcgal-demo/data.tar.gz)" << std::endl;
    return EXIT_INPUT;
  }
  const std::size_t nv = num_vertices(in.mesh), nf = count_faces(in.mesh);
  Result r;
  r.add("command", "demo");
  r.add("input", path);
  r.add("seed", static_cast<std::size_t>(seed));

  CGAL::Real_timer timer;
  timer.start();
  PE::Error_code ec = thingi_protocol(in, static_cast<unsigned>(seed));
  const double t_tutte = timer.time();
  if(ec != PE::OK)
  {
    std::cerr << "pe: the Tutte-failure protocol failed on " << path << ": " << PE::get_error_message(ec) << std::endl;
    r.add("status", PE::get_error_name(ec)); r.add("valid", false);
    return finish(a, r, "demo: " + std::string(PE::get_error_name(ec)), EXIT_INVALID);
  }
  const PE::Embedding_report before = PE::check_embedding(in.mesh, in.uv);
  const std::string svg_before = base + "_tutte.svg", obj_before = base + "_tutte.obj";
  int w = write_outputs(in, obj_before, svg_before, mesh_name + " seed " + std::to_string(seed) + ", double Tutte map: " +
                                                    (before.is_valid() ? "valid" : "INVALID"));
  if(w != EXIT_VALID) return w;
  if(!a.json)
  {
    std::cout << "[1/2] " << mesh_name << " (" << nv << " vertices, " << nf << " faces), Tutte-failure protocol seed " << seed
              << ", double Tutte map (" << seconds_string(t_tutte) << "):\n      " << before.summary() << "\n"
              << "      wrote " << svg_before << " and " << obj_before << std::endl;
  }

  timer.reset();
  PE::Progressive_embedding_statistics st;
  ec = run_progressive_embedding(in, !a.has("--no-progress"), st);
  const double t_pe = timer.time();
  const PE::Embedding_report after = (ec == PE::OK) ? st.report : PE::check_embedding(in.mesh, in.uv);
  r.add("status", PE::get_error_name(ec));
  add_report(r, after);
  if(ec != PE::OK) r.add("valid", false);
  add_report(r, before, "tutte_");
  add_statistics(r, st);
  r.add("seconds_tutte", t_tutte);
  r.add("seconds", t_pe);
  std::ostringstream s;
  s << "[2/2] progressive embedding (" << statistics_summary(st) << ", " << seconds_string(t_pe) << "):\n      ";
  if(ec != PE::OK)
  {
    std::cerr << "pe: progressive embedding failed: " << PE::get_error_message(ec) << std::endl;
    s << PE::get_error_name(ec) << ", nothing written";
    return finish(a, r, s.str(), EXIT_INVALID);
  }
  const std::string svg_after = base + "_repaired.svg", obj_after = base + "_repaired.obj";
  w = write_outputs(in, obj_after, svg_after, mesh_name + " seed " + std::to_string(seed) + ", after progressive embedding: " +
                                             (after.is_valid() ? "valid" : "INVALID"));
  if(w != EXIT_VALID) return w;
  r.add("svg_tutte", svg_before);
  r.add("svg_repaired", svg_after);
  s << after.summary() << "\n      wrote " << svg_after << " and " << obj_after;
  return finish(a, r, s.str(), after.is_valid() ? EXIT_VALID : EXIT_INVALID);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) return usage(std::string());
  const std::string cmd = argv[1];
  if(cmd == "-h" || cmd == "--help" || cmd == "help") { std::cout << usage_text; return EXIT_VALID; }
  Arguments a;
  const std::string err = parse_arguments(argc, argv, 2, a);
  if(!err.empty()) return usage(err);
  try
  {
    if(cmd == "tutte") return cmd_tutte(a);
    if(cmd == "thingi") return cmd_thingi(a);
    if(cmd == "random-init") return cmd_random_init(a);
    if(cmd == "check") return cmd_check(a);
    if(cmd == "svg") return cmd_svg(a);
    if(cmd == "untangle") return cmd_untangle(a);
    if(cmd == "embed") return cmd_embed(a);
    if(cmd == "optimize") return cmd_optimize(a);
    if(cmd == "generate") return cmd_generate(a);
    if(cmd == "demo") return cmd_demo(a);
  }
  catch(const std::exception& e)
  {
    std::cerr << "pe: unexpected error: " << e.what() << std::endl;
    return EXIT_INVALID;
  }
  return usage("unknown command '" + cmd + "'");
}
