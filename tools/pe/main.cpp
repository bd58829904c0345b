// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe`: the command-line tool of the package. Run `pe` without arguments for the usage.
// This file holds the one table of commands and options (the usage text and the checks of the
// option values are generated from it), the exit status of each Error_code, the JSON result,
// the failure report, the timer and the progress bar.

#include "cli.h"

#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <system_error>

#include <cstring>
#include <string>

#include <sys/stat.h>
#include <unistd.h> // isatty, execv

namespace pe_tool {

// ---- exit status --------------------------------------------------------------------------

int exit_status(PE::Error_code ec)
{
  switch(ec)
  {
    case PE::OK:
      return EXIT_VALID;
    // faults of the input data (mesh, uv map or constraints), whatever command meets them
    case PE::ERROR_EMPTY_MESH:
    case PE::ERROR_NON_TRIANGULAR_MESH:
    case PE::ERROR_NON_MANIFOLD:
    case PE::ERROR_NOT_A_DISK:
    case PE::ERROR_BORDER_TOO_SHORT:
    case PE::ERROR_NON_CONVEX_BORDER:
    case PE::ERROR_DEGENERATE_BORDER:
    case PE::ERROR_NON_FINITE_COORDINATES:
    case PE::ERROR_CANNOT_READ_FILE:
    case PE::ERROR_MALFORMED_FILE:
    case PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN:
    case PE::ERROR_NO_FREE_VERTEX:
    case PE::ERROR_DEGENERATE_3D_FACE:
    case PE::ERROR_DUPLICATE_CONSTRAINT:
    case PE::ERROR_CONSTRAINT_ON_BORDER:
    case PE::ERROR_NOT_GENUS_ZERO:
    case PE::ERROR_NOT_SELF_OVERLAPPING:
    case PE::ERROR_LANDMARK_ORDER:
      return EXIT_INPUT;
    case PE::ERROR_CANNOT_WRITE_FILE:
      return EXIT_OUTPUT;
    // an invalid map, or an algorithm that failed or ran out of its budget
    case PE::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM:
    case PE::ERROR_INVALID_EMBEDDING:
    case PE::ERROR_COLLAPSE_FAILED:
    case PE::ERROR_INSERTION_FAILED:
    case PE::ERROR_BUDGET_EXHAUSTED:
    case PE::ERROR_WRONG_PARAMETER:
    case PE::ERROR_DEGENERATE_CHORD:
    case PE::ERROR_PATH_TRACING_FAILED:
      return EXIT_INVALID;
  }
  return EXIT_INVALID;
}

namespace {

// ---- the table of options and commands ----------------------------------------------------

enum class Kind { FLAG, COUNT, REAL, CHOICE, NUMBER_TYPE, TEXT, INPUT_FILE, OUTPUT_FILE, OUTPUT_FILE_PAIR, DIRECTORY };

struct Option_spec
{
  const char* name;
  Kind kind;
  const char* value;    // the value in the usage; for CHOICE, the choices separated by '|'
  const char* help;
  double lo = 0, hi = 0;   // COUNT: [lo, hi]; REAL: (lo, hi], or [lo, hi] with lo_closed
  bool lo_closed = false;
};

const double max_unsigned = double(std::numeric_limits<unsigned>::max());

static_assert(default_constrain_optimize_seconds == 5. && default_optimize_seconds == 60.,
              "--optimize-time's help gives the defaults");
const Option_spec option_table[] = {
  { "--json", Kind::FLAG, "", "print one JSON object instead of the summary line (both on the standard error when an output is /dev/stdout)" },
  { "--border", Kind::CHOICE, "fixed|circle|square|triangle",
    "border of the Tutte map (default: fixed for an OBJ with vt, circle otherwise)" },
  { "--weights", Kind::CHOICE, "uniform|mean-value", "Tutte (uniform) or Floater (mean-value) weights" },
  { "--number-type", Kind::NUMBER_TYPE, "double|exact|mpfr:BITS",
    "number type of the Tutte solve (BITS from 53 to 1048576); the map is written in double" },
  { "--seed", Kind::COUNT, "S", "seed of the random choices (0 to 4294967295)", 0, max_unsigned },
  { "--svg", Kind::OUTPUT_FILE, "OUT.svg", "also write a picture of the map" },
  { "--compatible", Kind::OUTPUT_FILE_PAIR, "A_OUT.obj B_OUT.obj",
    "cross: also write the compatible meshes, one connectivity (the overlay of the two maps, certified)\n"
    "with A_OUT on A's surface and B_OUT on B's, vertices and faces in the same order (closed meshes:\n"
    "the overlay of the cut disks' maps joined along the cut, certified closed genus 0)" },
  { "--mesh", Kind::TEXT, "NAME", "mesh of DATA_DIR/meshes (default dino.off)" },
  { "--out-dir", Kind::DIRECTORY, "DIR", "existing folder for the maps and pictures (default: the build folder)" },
  { "--fix", Kind::INPUT_FILE, "FILE", "vertices kept bit-exactly: lines 'vertex_index u v' (0-based uv-vertex indices)" },
  { "--turns-from", Kind::INPUT_FILE, "MAP.obj",
    "check: the full turns each border fan makes beyond the border's angle, read from MAP (vertex by index;\n"
    "e.g. the input of pe constrain whose border wraps around some of its vertices); default none" },
  { "--iterations", Kind::COUNT, "N",
    "iteration budget of the optimization (1 to 1000000000; default 1000, as optimize_distortion)", 1, 1e9 },
  { "--tolerance", Kind::REAL, "X",
    "the optimization has converged when two consecutive iterations each lower the energy by less\n"
    "than this fraction (0 <= X < 1, default 1e-5; 0 runs the whole iteration budget)",
    0, std::nextafter(1., 0.), true },
  { "--time-limit", Kind::REAL, "SECONDS",
    "time budget of the command's long steps: a Tutte solve or a repair that exceeds it fails (exit 1,\n"
    "ERROR_BUDGET_EXHAUSTED); an optimization stops there, with its valid map. batch: the wall time of\n"
    "each mesh (default 600), whose process is killed then (status timeout)",
    0, 1e9 },
  { "--optimize-time", Kind::REAL, "SECONDS",
    "seconds the optimization may take; it stops there with its certified map, and says so (JSON\n"
    "ERROR_BUDGET_EXHAUSTED); default 60 (embed, untangle, optimize), 5 (constrain)", 0, 1e9 },
  { "--no-progress", Kind::FLAG, "", "no progress bar (it is drawn on terminals only, for runs over a second)" },
  { "--no-optimize", Kind::FLAG, "", "repair only: skip the distortion optimization" },
  { "--no-composed", Kind::FLAG, "",
    "cross: skip the last optimization of A's map, for the distortion of the composed map A -> B" },
  { "--no-matched", Kind::FLAG, "",
    "cross: keep B's first map (Tutte, optimized) instead of making it again with B's landmarks pinned, as A's is" },
  { "--optimize", Kind::FLAG, "", "optimize the distortion after repairing (the default)" },
  { "--free-border", Kind::FLAG, "", "the border vertices move too (the border stays simple)" },
  { "--shard", Kind::TEXT, "K/N",
    "run shard K of N (1 <= K <= N): the inputs whose index in the sorted list is K-1 modulo N" },
  { "--jobs", Kind::COUNT, "J", "meshes run at once, each in its own process (1 to 1024, default 1)", 1, 1024 },
  { "--resume", Kind::FLAG, "",
    "skip the inputs that OUTDIR/results.jsonl already has with a final status (done, input_error,\n"
    "timeout, memory, crashed); output_error and error run again" },
  { "--memory-limit", Kind::COUNT, "MB",
    "address-space limit of each mesh's process (RLIMIT_AS, default 8192; 0: none; status memory)", 0, 16777216 },
  { "--out", Kind::TEXT, "DIR", "folder of the merged results (created if missing)" },
  { "--drop-timings", Kind::FLAG, "",
    "leave out the times (seconds, *_seconds, keys naming a time) and the shard, so that merges of\n"
    "the same inputs are the same bytes however they were sharded" },
};

struct Command_spec
{
  const char* name;
  const char* arguments;                 // positional arguments, in the usage
  std::size_t min_positional, max_positional;
  int output;                            // index of the positional output file, -1 if none
  std::vector<std::string> options;      // --json applies to every command
  const char* help;
  int (*run)(const Arguments&);
};

const std::vector<Command_spec>& command_table()
{
  static const std::vector<Command_spec> table = {
    { "tutte", "IN OUT.obj", 2, 2, 1, { "--border", "--weights", "--number-type", "--time-limit", "--no-progress" },
      "Tutte (uniform) or Floater (mean-value) map of the disk IN (OFF, OBJ, PLY, STL), computed in the\n"
      "number type and written in double; exact and mpfr runs also certify the map before rounding\n"
      "and show their progress", cmd_tutte },
    { "thingi", "MESH SEED OUT.obj", 3, 3, 2, { "--svg", "--time-limit" },
      "the Tutte-failure protocol: remove one face of the closed genus-0 mesh MESH (seed 0: the last),\n"
      "pin its vertices to (0,0), (1/2,sqrt(3)/2), (1,0), double Tutte, certify", cmd_thingi },
    { "random-init", "IN OUT.obj", 2, 2, 1, { "--seed", "--time-limit" },
      "border on a circle by arc length, interior vertices uniformly random inside the border (--seed needed)",
      cmd_random_init },
    { "check", "IN.obj [REF.obj]", 1, 2, -1, { "--turns-from" },
      "certify the uv map of IN; with REF, also require the same faces and a bit-exact border. A map that is not an\n"
      "embedding may be an immersion (JSON \"immersion\"): every border fan turning by the border's angle there (plus\n"
      "the full turns of --turns-from)", cmd_check },
    { "svg", "IN.obj OUT.svg", 2, 2, 1, {},
      "picture of the uv map of IN (faces coloured by distortion, flipped and degenerate faces highlighted)",
      cmd_svg },
    { "untangle", "IN.obj OUT.obj", 2, 2, 1, { "--no-optimize", "--iterations", "--tolerance", "--optimize-time", "--time-limit",
                                           "--no-progress" },
      "progressive embedding of the uv map of IN, border kept bit-exactly, then the distortion\n"
      "optimization (unless --no-optimize)", cmd_untangle },
    { "embed", "IN OUT.obj", 2, 2, 1,
      { "--border", "--weights", "--optimize", "--no-optimize", "--iterations", "--tolerance", "--optimize-time",
        "--time-limit", "--no-progress" },
      "Tutte, then progressive embedding if the Tutte map is not valid, then the distortion\n"
      "optimization (unless --no-optimize)", cmd_embed },
    { "optimize", "IN.obj OUT.obj", 2, 2, 1,
      { "--free-border", "--fix", "--iterations", "--tolerance", "--optimize-time", "--time-limit", "--no-progress" },
      "lower the symmetric Dirichlet distortion of the valid uv map of IN without leaving the valid maps;\n"
      "the border (unless --free-border) and the vertices of --fix are kept bit-exactly", cmd_optimize },
    { "constrain", "IN OUT.obj", 2, 2, 1,
      { "--fix", "--border", "--weights", "--no-optimize", "--optimize-time", "--svg", "--time-limit", "--no-progress" },
      "a map in which the vertices of --fix land bit-exactly on their targets (MatchMaker++: the mesh is\n"
      "refined by Steiner vertices on its edges where needed, new vertices written after the input's),\n"
      "certified, then optimized (unless --no-optimize; for at most --optimize-time seconds), then the added\n"
      "vertices that the map can do without removed again; the border from the vt of IN, or --border\n"
      "circle|square|triangle (needed without vt); --svg draws the patches, the paths between them and\n"
      "the constrained vertices. Without --fix (or with an empty file) only the border is prescribed; a vt\n"
      "border may be non-convex: simple (an embedding) or weakly self-overlapping (an immersion, certified\n"
      "locally injective, border only, optimized as an immersion; JSON \"immersion\": true)", cmd_constrain },
    { "cross", "A B LANDMARKS OUT.txt", 4, 4, 3, { "--compatible", "--svg", "--no-composed", "--no-matched", "--time-limit" },
      "the location on the disk B of every vertex of the disk A through a certified cross-parameterization\n"
      "(two closed genus-0 meshes are first cut into disks between two landmarks near each other on A, the\n"
      "others inside, JSON cut_landmarks; where no pair cuts both meshes, along the chain through all in file\n"
      "order; the maps are then those of the cut disks):\n"
      "both borders on the unit square by relative arc length (through the border landmarks), B mapped\n"
      "first, then again with its landmarks pinned where that map put them (unless --no-matched; kept only\n"
      "if at most 5% above the first map's distortion energy or A's map's, JSON matched_b, matched_more_distorted),\n"
      "A mapped\n"
      "with its landmarks pinned on their partners' uv, then optimized for the distortion of the composed\n"
      "map (unless --no-composed; LANDMARKS: 'a_index b_index' lines,\n"
      "0-based in file order, both interior or both on their borders); OUT.txt: one line per vertex of A in file order, 'face_index b0 b1 b2' (the face of B in B's\n"
      "file order, the barycentric coordinates of its vertices in the order the face lists them); --svg draws\n"
      "both certified maps side by side, A's on the left, the landmarks marked (closed meshes: the cut disks)", cmd_cross },
    { "polygon", "POLY.txt OUT.obj", 2, 2, 1, { "--svg", "--time-limit" },
      "is the polygon of POLY.txt ('x y' lines, one vertex each, the last joined to the first) simple,\n"
      "weakly self-overlapping (the border of an immersed disk) or neither (exit 3,\n"
      "ERROR_NOT_SELF_OVERLAPPING); writes its triangulation with its own vertices (z = 0, uv = xy),\n"
      "certified: an embedding if simple, else an immersion (JSON \"immersion\": true)", cmd_polygon },
    { "generate", "stacked DEPTH OUT.obj | grid N OUT.obj", 3, 3, 2, {},
      "test inputs: the deep stacked triangulation (DEPTH 0 to 100000; corners pinned as in the thingi\n"
      "protocol, interior at the first corner) or an N x N grid disk (N 2 to 4000; uv = xy)", cmd_generate },
    { "demo", "[DATA_DIR]", 0, 1, -1, { "--mesh", "--seed", "--out-dir", "--time-limit", "--no-progress" },
      "the README's main job: the thingi protocol on DATA_DIR/meshes/dino.off seed 8, its repair by\n"
      "progressive embedding and the optimized map, with pictures", cmd_demo },
    { "batch", "PIPELINE LIST_OR_FOLDER OUTDIR", 3, 3, -1,
      { "--shard", "--jobs", "--resume", "--time-limit", "--memory-limit", "--no-progress",
        "--no-optimize", "--iterations", "--tolerance", "--optimize-time", "--border", "--weights", "--free-border" },
      "PIPELINE (untangle, embed, optimize or constrain) on every mesh of LIST_OR_FOLDER (a folder: its\n"
      ".obj, .off, .ply, .stl files; a list: one path per line, relative to the list's folder, blank lines\n"
      "and # comments skipped), sorted by path, each in its own process: `pe PIPELINE IN OUTDIR/NAME.obj\n"
      "--json` with the options that PIPELINE takes (constrain: --fix NAME.fix beside the mesh if there\n"
      "is one). Appends one JSON line per mesh to OUTDIR/results.jsonl, on disk before the next: input,\n"
      "status (done, input_error, timeout, memory, crashed; output_error, error), valid, exit_status,\n"
      "seconds, shard and the keys of the mesh's JSON (its status as \"code\"). Exit 0 if every mesh of\n"
      "the shard is valid, 1 if not, 3 if the list or folder cannot be read, 4 if OUTDIR cannot be written",
      cmd_batch },
    { "batch-merge", "OUTDIR...", 1, 100000, -1, { "--out", "--drop-timings" },
      "merge the results.jsonl of batch runs (shards) into --out DIR: results.jsonl (one record per\n"
      "input, sorted by input; a final status wins over a non-final one, else the later record),\n"
      "results.csv (input,status,valid,exit_status,seconds, then the other keys sorted, a.b for nested\n"
      "keys) and summary.md. Exit 0 if every record is valid, 1 if not", cmd_batch_merge },
  };
  return table;
}

const Option_spec* find_option(const std::string& name)
{
  for(const Option_spec& o : option_table)
    if(name == o.name) return &o;
  return nullptr;
}

const Command_spec* find_command(const std::string& name)
{
  for(const Command_spec& c : command_table())
    if(name == c.name) return &c;
  return nullptr;
}

std::string option_synopsis(const Option_spec& o)
{
  return o.kind == Kind::FLAG ? std::string(o.name) : std::string(o.name) + " " + o.value;
}

// indents `text` (lines separated by '\n') by `indent` spaces
std::string indented(const std::string& text, std::size_t indent)
{
  std::string out(indent, ' ');
  for(char c : text)
  {
    out += c;
    if(c == '\n') out += std::string(indent, ' ');
  }
  return out + "\n";
}

// `words` joined by spaces, broken into lines of at most `width` characters after `first`
std::string wrap(const std::string& first, const std::vector<std::string>& words, std::size_t width, std::size_t indent)
{
  std::string out = first, line = first;
  for(const std::string& w : words)
  {
    if(line.size() + 1 + w.size() > width && line.size() > indent)
    {
      out += "\n" + std::string(indent, ' ');
      line = std::string(indent, ' ');
    }
    out += " " + w;
    line += " " + w;
  }
  return out + "\n";
}

std::string usage_text()
{
  std::string u = "usage: pe <command> [arguments] [options] [--json]\n\ncommands:\n";
  for(const Command_spec& c : command_table())
  {
    std::vector<std::string> words;
    for(const std::string& o : c.options) words.push_back("[" + option_synopsis(*find_option(o)) + "]");
    u += wrap(std::string("  ") + c.name + " " + c.arguments, words, 100, 8);
    u += indented(c.help, 8);
  }
  u += "\noptions:\n";
  for(const Option_spec& o : option_table)
  {
    u += "  " + option_synopsis(o) + "\n";
    u += indented(o.help, 8);
  }
  u += "\n"
    "exit status (the same fault gives the same status in every command and file format):\n"
    "  0  the map written is certified valid (check: the map read is valid and matches REF;\n"
    "     svg: the picture was written)\n"
    "  1  the map is not valid, or the algorithm failed or ran out of --time-limit\n"
    "  2  bad arguments: unknown command or option, bad option value (the message names the option)\n"
    "  3  input error: a file missing, not a regular file or unreadable; malformed (with the line);\n"
    "     a mesh that is empty, not triangular, not manifold, not a disk (thingi: not a closed genus-0\n"
    "     mesh), with non-finite coordinates or degenerate borders; constraints outside the mesh; a\n"
    "     valid map whose distortion is not finite (3D coordinates that overflow, zero-area 3D faces)\n"
    "  4  output error: a file cannot be written (no partial file is left)\n"
    "\n"
    "environment:\n"
    "  PE_HUGE_PAGES=1\n"
    "        run on 2 MB transparent huge pages (glibc's malloc and CHOLMOD's large blocks): fewer page\n"
    "        faults on meshes of a million vertices, faster or slower depending on the host (default: off)\n"
    "  CGAL_DATA_DIR\n"
    "        demo: the data folder when none is given\n";
  return u;
}

// parses `s` as a whole real number in (lo, hi] ([lo, hi] if lo_closed); `s` must stay alive while strtod reads it
bool parse_real(const std::string& s, double lo, double hi, bool lo_closed, double& out, std::string& why)
{
  errno = 0;
  char* end = nullptr;
  const char* begin = s.c_str();
  const double d = (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) ? 0 : std::strtod(begin, &end);
  if(end == nullptr || end == begin || *end != '\0') { why = "'" + s + "' is not a number"; return false; }
  if(errno == ERANGE || !std::isfinite(d) || !(lo_closed ? d >= lo : d > lo) || !(d <= hi))
  {
    std::ostringstream os;
    os << "'" << s << "' is out of range (a number " << (lo_closed ? ">= " : "> ") << lo << " and <= " << hi << " expected)";
    why = os.str();
    return false;
  }
  out = d;
  return true;
}

std::string unknown_value(const Option_spec& o, const std::string& v)
{
  std::string noun = std::string(o.name).substr(2);
  std::replace(noun.begin(), noun.end(), '-', ' ');
  std::string choices = o.value;
  std::replace(choices.begin(), choices.end(), '|', ',');
  return "option " + std::string(o.name) + ": unknown " + noun + " '" + v + "' (expected one of " + choices + ")";
}

// checks the value of option `o` and stores it; returns the error, empty on success
std::string check_value(const Option_spec& o, const std::string& v, Arguments& a)
{
  const std::string name = o.name;
  std::string why;
  switch(o.kind)
  {
    case Kind::FLAG:
      break;
    case Kind::COUNT:
    {
      unsigned long long n = 0;
      if(!parse_count(v, static_cast<unsigned long long>(o.lo), static_cast<unsigned long long>(o.hi), n, why))
        return "option " + name + ": " + why;
      a.counts[name] = n;
      break;
    }
    case Kind::REAL:
    {
      double d = 0;
      if(!parse_real(v, o.lo, o.hi, o.lo_closed, d, why)) return "option " + name + ": " + why;
      a.reals[name] = d;
      break;
    }
    case Kind::CHOICE:
    {
      const std::string choices = std::string("|") + o.value + "|";
      if(v.empty() || v.find('|') != std::string::npos || choices.find("|" + v + "|") == std::string::npos)
        return unknown_value(o, v);
      break;
    }
    case Kind::NUMBER_TYPE:
    {
      unsigned long long bits = 0;
      if(v == "double" || v == "exact") break;
      if(v.compare(0, 5, "mpfr:") == 0 && parse_count(v.substr(5), 53, 1u << 20, bits, why)) { a.counts[name] = bits; break; }
      return "option " + name + ": unknown number type '" + v + "' (double, exact or mpfr:BITS with BITS from 53 to 1048576)";
    }
    case Kind::TEXT:
    case Kind::INPUT_FILE:
    case Kind::OUTPUT_FILE:
    case Kind::OUTPUT_FILE_PAIR:
    case Kind::DIRECTORY:
      if(v.empty()) return "option " + name + " needs a non-empty " + o.value;
      break;
  }
  return std::string();
}

// returns an empty string on success, the error otherwise
std::string parse_arguments(int argc, char** argv, const Command_spec& c, Arguments& a)
{
  for(int i = 2; i < argc; ++i)
  {
    const std::string s = argv[i];
    if(s.size() <= 2 || s.compare(0, 2, "--") != 0) { a.positional.push_back(s); continue; }
    if(s == "--json") { a.json = true; continue; }
    const Option_spec* o = find_option(s);
    if(o == nullptr) return "unknown option " + s;
    if(std::find(c.options.begin(), c.options.end(), s) == c.options.end())
      return "option " + s + " does not apply to " + c.name;
    if(a.options.count(s)) return "option " + s + " given twice";
    if(o->kind == Kind::FLAG) { a.options[s] = ""; continue; }
    // a value that looks like an option is a forgotten value
    if(i + 1 >= argc || (std::string(argv[i + 1]).compare(0, 2, "--") == 0 && o->kind != Kind::REAL))
      return "option " + s + " needs a value (" + o->value + ")";
    const std::string value = argv[++i];
    std::string err = check_value(*o, value, a);
    if(!err.empty()) return err;
    a.options[s] = value;
    if(o->kind == Kind::OUTPUT_FILE_PAIR)
    {
      if(i + 1 >= argc || std::string(argv[i + 1]).compare(0, 2, "--") == 0)
        return "option " + s + " needs two values (" + o->value + ")";
      const std::string second = argv[++i];
      err = check_value(*o, second, a);
      if(!err.empty()) return err;
      if(second == value) return "option " + s + ": the two files are the same";
      a.second_values[s] = second;
    }
  }
  if(a.has("--optimize") && a.has("--no-optimize")) return "options --optimize and --no-optimize exclude each other";
  if(a.positional.size() < c.min_positional || a.positional.size() > c.max_positional)
    return std::string(c.name) + " takes " + c.arguments + " (" + std::to_string(a.positional.size()) + " arguments given)";
  // two outputs of one run naming one file: the later would silently replace the earlier. A name is compared
  // through its folder's real path, so that 'x.txt' and './x.txt' are one file even before it exists.
  auto canonical = [](const std::string& path) {
    const std::string folder = PE::IO::internal::atomic_output_folder(path); // with its '/', or "" for a bare name
    char* real = ::realpath(folder.empty() ? "." : folder.c_str(), nullptr);
    if(real == nullptr) return path;
    const std::string r = std::string(real) + "/" + path.substr(folder.size());
    std::free(real);
    return r;
  };
  std::vector<std::pair<std::string, std::string> > outputs; // (what, file)
  if(c.output >= 0 && std::size_t(c.output) < a.positional.size())
    outputs.emplace_back("the output", a.positional[std::size_t(c.output)]);
  for(const auto& kv : a.options)
  {
    const Option_spec* o = find_option(kv.first);
    if(o->kind == Kind::OUTPUT_FILE || o->kind == Kind::OUTPUT_FILE_PAIR) outputs.emplace_back(kv.first, kv.second);
    if(o->kind == Kind::OUTPUT_FILE_PAIR) outputs.emplace_back(kv.first, a.second_values.at(kv.first));
  }
  for(std::size_t i = 0; i < outputs.size(); ++i)
    for(std::size_t j = i + 1; j < outputs.size(); ++j)
    {
      // (a device such as /dev/null may take several outputs)
      struct stat si, sj;
      const bool ei = ::stat(outputs[i].second.c_str(), &si) == 0, ej = ::stat(outputs[j].second.c_str(), &sj) == 0;
      if(ei && !S_ISREG(si.st_mode)) continue;
      const bool same = outputs[i].second == outputs[j].second || canonical(outputs[i].second) == canonical(outputs[j].second) ||
                        (ei && ej && si.st_dev == sj.st_dev && si.st_ino == sj.st_ino);
      if(same)
        return (outputs[i].first == outputs[j].first ? "the two files of " + outputs[i].first
                                                     : outputs[i].first + " and " + outputs[j].first) +
               " name the same file '" + outputs[j].second + "'";
    }
  return std::string();
}

} // namespace

bool command_accepts(const std::string& command, const std::string& option)
{
  const Command_spec* c = find_command(command);
  return c != nullptr && std::find(c->options.begin(), c->options.end(), option) != c->options.end();
}

// ---- Arguments ----------------------------------------------------------------------------

std::string Arguments::get(const std::string& o, const std::string& def) const
{
  auto it = options.find(o);
  return it == options.end() ? def : it->second;
}

unsigned long long Arguments::count(const std::string& o, unsigned long long def) const
{
  auto it = counts.find(o);
  return it == counts.end() ? def : it->second;
}

double Arguments::real(const std::string& o, double def) const
{
  auto it = reals.find(o);
  return it == reals.end() ? def : it->second;
}

int usage(const std::string& why)
{
  if(!why.empty()) std::cerr << "pe: " << why << "\n\n";
  std::cerr << usage_text();
  return EXIT_USAGE;
}

bool parse_count(const std::string& s, unsigned long long lo, unsigned long long hi,
                 unsigned long long& out, std::string& why)
{
  unsigned long long n = 0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  // from_chars accepts no sign, no space, no base prefix: digits only
  const bool digits = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  const auto res = digits ? std::from_chars(first, last, n) : std::from_chars_result{ first, std::errc::invalid_argument };
  if(!digits || res.ptr != last || res.ec == std::errc::invalid_argument)
  {
    why = "'" + s + "' is not a non-negative integer";
    return false;
  }
  if(res.ec == std::errc::result_out_of_range || n < lo || n > hi)
  {
    why = "'" + s + "' is out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + ")";
    return false;
  }
  out = n;
  return true;
}

// ---- progress bar -------------------------------------------------------------------------

Progress::Progress(const std::string& label, bool enabled) : enabled_(enabled && isatty(2)), label_(label) {}

bool Progress::update(double fraction)
{
  const double now = timer_.seconds();
  if(!enabled_ || now < 1.0 || (shown_ && now - last_ < 0.1)) return true; // short runs: no bar; 10 redraws a second
  last_ = now;
  if(!(fraction >= 0)) fraction = 0;
  if(fraction > 1) fraction = 1;
  const int width = 40, done = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r%s [%s%s] %3d%% %6.1f s", label_.c_str(), std::string(done, '#').c_str(),
               std::string(width - done, '.').c_str(), static_cast<int>(100 * fraction), now);
  std::fflush(stderr);
  shown_ = true;
  return true;
}

void Progress::finish()
{
  if(shown_) { std::fprintf(stderr, "\r%*s\r", 80, ""); std::fflush(stderr); }
  shown_ = false;
}

// ---- result -------------------------------------------------------------------------------

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

void Result::set(const std::string& k, const std::string& raw)
{
  for(auto& f : fields) if(f.first == k) { f.second = raw; return; }
  fields.emplace_back(k, raw);
}

void Result::add(const std::string& k, double d)
{
  if(!std::isfinite(d)) { set(k, "null"); return; } // JSON has no inf or nan
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", d);
  set(k, b);
}

void Result::add(const std::string& k, const char* s) { set(k, "\"" + json_escape(s) + "\""); }

std::string Result::json() const
{
  std::string o = "{";
  for(std::size_t i = 0; i < fields.size(); ++i)
    o += (i ? ", \"" : "\"") + fields[i].first + "\": " + fields[i].second;
  return o + "}";
}

int Run::finish(int code)
{
  bool has_seconds = false;
  for(const auto& f : result.fields) has_seconds = has_seconds || f.first == "seconds";
  if(!has_seconds) result.add("seconds", timer.seconds());
  result.add("exit_status", static_cast<std::size_t>(code));
  if(code != EXIT_INPUT && code != EXIT_USAGE)
    for(const std::string& note : notes) std::cerr << "pe: note: " << note << std::endl;
  std::ostream& out = summary_to_stderr ? std::cerr : std::cout;
  if(args.json) out << result.json() << std::endl;
  else out << summary.str() << std::endl;
  return code;
}

int Run::fail(PE::Error_code ec, const std::string& what, const std::string& detail, int code)
{
  const std::string message = detail.empty() ? std::string(PE::get_error_message(ec)) : detail;
  std::cerr << "pe: " << what << ": " << message << " (" << PE::get_error_name(ec) << ")" << std::endl;
  bool written = false;
  for(const auto& f : result.fields) written = written || (f.first == "written" && f.second == "true");
  result.add("status", PE::get_error_name(ec));
  result.add("message", message);
  result.add("valid", false);
  if(!written) result.add("written", false);
  summary << PE::get_error_name(ec) << (written ? "" : ", nothing written");
  return finish(code >= 0 ? code : exit_status(ec));
}

std::string format_number(double d)
{
  if(std::isnan(d)) return "nan";
  if(std::isinf(d)) return d > 0 ? "inf" : "-inf";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", d == 0 ? 0. : d); // no "-0"
  return b;
}

std::string seconds_string(double s)
{
  char b[32];
  std::snprintf(b, sizeof b, "%.3g s", s);
  return b;
}

} // namespace pe_tool

namespace {

// On request (PE_HUGE_PAGES=1), the whole process on transparent huge pages. Large meshes touch
// gigabytes of fresh memory page by page, and on a virtual machine a fault may be expensive. glibc's
// malloc asks for 2 MB pages (under Linux's default policy, transparent_hugepage=madvise) only when its
// tunable glibc.malloc.hugetlb is 1, and it reads its tunables once, at start: pe therefore starts
// itself again, once, with the tunable added to GLIBC_TUNABLES. Not when the tunable is already set
// either way, nor under valgrind (its tools follow no exec by default), nor where /proc/self/exe
// cannot be run: pe then simply goes on. Not by default: whether 2 MB pages are cheaper than 4 KB ones
// depends on the host (internal/cholmod_runtime.h, benchmark/results/large_meshes_pe.md).
void restart_with_huge_pages(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  const char* requested = std::getenv("PE_HUGE_PAGES");
  if(requested == nullptr || std::strcmp(requested, "1") != 0) return;
  const char* preload = std::getenv("LD_PRELOAD");
  if(preload != nullptr && std::strstr(preload, "vgpreload") != nullptr) return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::string t = tunables == nullptr ? std::string() : std::string(tunables);
  if(t.find("glibc.malloc.hugetlb") != std::string::npos) return;
  t = t.empty() ? "glibc.malloc.hugetlb=1" : t + ":glibc.malloc.hugetlb=1";
  if(::setenv("GLIBC_TUNABLES", t.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // the exec failed: go on as we are, without a tunable that this process does not have
  if(tunables == nullptr) ::unsetenv("GLIBC_TUNABLES");
  else ::setenv("GLIBC_TUNABLES", tunables, 1);
#else
  (void)argv;
#endif
}

} // namespace

int main(int argc, char** argv)
{
  using namespace pe_tool;
  restart_with_huge_pages(argv);
  if(argc < 2) return usage(std::string());
  const std::string cmd = argv[1];
  if(cmd == "-h" || cmd == "--help" || cmd == "help") { std::cout << usage_text(); return EXIT_VALID; }
  const Command_spec* c = find_command(cmd);
  if(c == nullptr) return usage("unknown command '" + cmd + "'");
  Arguments a;
  a.command = cmd;
  const std::string err = parse_arguments(argc, argv, *c, a);
  if(!err.empty()) return usage(err);
  try
  {
    // the files named by options, before any long computation: inputs must be regular files
    // (input error), outputs writable places (output error)
    for(const auto& kv : a.options)
    {
      const Option_spec* o = find_option(kv.first);
      Run run(a);
      run.summary << cmd << ": ";
      int status = EXIT_VALID;
      if(o->kind == Kind::INPUT_FILE)
      {
        const std::string why = input_file_problem(kv.second);
        if(!why.empty()) status = run.fail(PE::ERROR_CANNOT_READ_FILE, "cannot use " + kv.first + " '" + kv.second + "'", why);
      }
      else if(o->kind == Kind::OUTPUT_FILE || o->kind == Kind::DIRECTORY)
        status = check_output_path(run, kv.second, kv.first, o->kind == Kind::DIRECTORY);
      else if(o->kind == Kind::OUTPUT_FILE_PAIR)
      {
        status = check_output_path(run, kv.second, kv.first);
        if(status == EXIT_VALID) status = check_output_path(run, a.second_values.at(kv.first), kv.first);
      }
      if(status != EXIT_VALID) return status;
    }
    if(c->output >= 0)
    {
      Run run(a);
      run.summary << cmd << ": ";
      const int status = check_output_path(run, a.positional[std::size_t(c->output)]);
      if(status != EXIT_VALID) return status;
    }
    return c->run(a);
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "pe: out of memory" << std::endl;
    return EXIT_INVALID;
  }
  catch(const std::exception& e)
  {
    std::cerr << "pe: unexpected error: " << e.what() << std::endl;
    return EXIT_INVALID;
  }
}
