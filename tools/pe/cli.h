// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe`, the command-line tool of the package: the command line, the result, the failure report,
// the exit status, the timer. No CGAL here: main.cpp, which holds the table of commands and
// options, includes only this file (pe.h adds the meshes and the algorithm steps).
//
//   main.cpp               the table of commands and options, parsing, usage, the JSON result,
//                          the failure report, the exit status of each Error_code, timer, progress
//   input_output.cpp       reading meshes (and their topology), writing maps and pictures
//   commands_tutte.cpp     tutte, thingi, random-init (and the Tutte step of the others)
//   commands_repair.cpp    untangle, embed, optimize (and the repair and optimization steps)
//   commands_constrain.cpp constrain (maps with positional constraints)
//   commands_polygon.cpp   polygon (simple and weakly self-overlapping polygons)
//   commands_check.cpp     check, svg (and the certificate of every other command)
//   commands_generate.cpp  generate
//   commands_demo.cpp      demo
//   commands_batch.cpp     batch, batch-merge (many meshes, each in a child process)
//
// Exit status of every command (one mapping, exit_status()): 0 the map written is certified
// valid (check: the map read is valid [and matches REF]; svg: the picture was written), 1 it is
// not or the algorithm failed, 2 bad arguments, 3 input error, 4 output error.

#ifndef PE_TOOL_CLI_H
#define PE_TOOL_CLI_H

#include <CGAL/Progressive_embedding/Error_code.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pe_tool {

// pe constrain's default optimization budget (--optimize-time), in seconds. Maps with a few constraints
// converge well within it (9 of the 10 runs of benchmark/results/constrained_embedding_optimized.csv in
// 0.39-3.3 s); maps refined around many random targets never converge, and 30 s instead of 5 lowered their
// energy only 1.1 to 4 times (constrained_default_command.csv), far above the few-constraint maps' either way.
constexpr double default_constrain_optimize_seconds = 5.;
// The default optimization budget (--optimize-time) of pe embed, untangle and optimize, in seconds: a user who
// runs the default command on a large map gets a certified, improved map in bounded time, and the output says
// when the budget stopped the optimization (JSON: ERROR_BUDGET_EXHAUSTED). Maps of up to a few hundred thousand
// vertices reach the stopping rule well within it (a 262k-vertex grid disk in 17 s,
// benchmark/results/optimizer_scale.md); a 1M-vertex map needs about twice as long and stops there: 0.25% above the
// converged energy on a quiet machine (optimizer_scale_budget.md), 14% above on a loaded one
// (optimizer_scale_default_budget.md).
constexpr double default_optimize_seconds = 60.;

namespace PE = CGAL::Progressive_embedding;

// ---- exit status --------------------------------------------------------------------------

enum Exit_status { EXIT_VALID = 0, EXIT_INVALID = 1, EXIT_USAGE = 2, EXIT_INPUT = 3, EXIT_OUTPUT = 4 };

// The exit status of a failure with code `ec`, the same in every command: faults of the input
// data give EXIT_INPUT, a file that cannot be written EXIT_OUTPUT, an invalid map or a failed
// algorithm EXIT_INVALID.
int exit_status(PE::Error_code ec);

// ---- command line -------------------------------------------------------------------------

// The parsed and checked command line; option values are checked against the option table
// (type, range, overflow) before any command runs.
struct Arguments
{
  std::string command;
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;          // as given; flags map to ""
  std::map<std::string, unsigned long long> counts;    // the checked values of integer options
  std::map<std::string, double> reals;                 // the checked values of real options
  std::map<std::string, std::string> second_values;    // the second value of options that take two
  bool json = false;

  bool has(const std::string& o) const { return options.count(o) != 0; }
  std::string get(const std::string& o, const std::string& def = std::string()) const;
  unsigned long long count(const std::string& o, unsigned long long def) const;
  double real(const std::string& o, double def) const;
  bool progress() const { return !has("--no-progress"); }
};

// prints `pe: why` and the usage to stderr; returns EXIT_USAGE
int usage(const std::string& why);

// whether the table lets `command` take `option` (batch passes options through to its children)
bool command_accepts(const std::string& command, const std::string& option);

// parses `s` as a whole decimal integer in [lo, hi] (no sign, no space, no overflow);
// on failure `why` says what is wrong
bool parse_count(const std::string& s, unsigned long long lo, unsigned long long hi,
                 unsigned long long& out, std::string& why);

// ---- timer, time budget and progress ------------------------------------------------------

// The one timer of the tool: wall-clock seconds since construction or the last restart().
class Timer
{
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  void restart() { start_ = std::chrono::steady_clock::now(); }
};

// What the long steps of a command may spend: what is left of --time-limit (shared by the
// steps of a command), and whether they draw a progress bar.
class Budget
{
  Timer timer_;
  double limit_;
  bool progress_;
public:
  explicit Budget(const Arguments& a)
    : limit_(a.real("--time-limit", std::numeric_limits<double>::infinity())), progress_(a.progress()) {}
  // seconds left, for the `maximum_running_time` named parameter (infinite without --time-limit)
  double remaining() const { const double r = limit_ - timer_.seconds(); return r > 0 ? r : 0; }
  bool limited() const { return limit_ < std::numeric_limits<double>::infinity(); }
  double limit() const { return limit_; }
  bool progress() const { return progress_; }
};

// A progress bar on stderr, for runs longer than a second, on terminals only.
class Progress
{
  Timer timer_;
  bool enabled_;
  bool shown_ = false;
  double last_ = 0;
  std::string label_;
public:
  Progress(const std::string& label, bool enabled);
  ~Progress() { finish(); }
  bool update(double fraction); // never cancels
  void set_label(const std::string& label) { label_ = label; }
  std::function<bool(double)> callback() { return [this](double f) { return update(f); }; }
  void finish();
};

// ---- the result: one summary line or one JSON object --------------------------------------

// the text of a JSON string, without its quotes
std::string json_escape(const std::string& s);

struct Result
{
  std::vector<std::pair<std::string, std::string> > fields; // key, JSON value

  void set(const std::string& k, const std::string& raw);
  void add(const std::string& k, bool b) { set(k, b ? "true" : "false"); }
  void add(const std::string& k, double d);
  void add(const std::string& k, std::size_t n) { set(k, std::to_string(n)); }
  void add(const std::string& k, const char* s);
  void add(const std::string& k, const std::string& s) { add(k, s.c_str()); }
  std::string json() const;
};

// What a command run carries from start to end: the arguments, the result, the summary line.
struct Run
{
  const Arguments& args;
  Result result;
  std::ostringstream summary;
  Timer timer;
  bool summary_to_stderr = false; // an output goes to the standard output: the summary must not mix with it
  std::vector<std::string> notes;  // printed to stderr by finish() as `pe: note: ...` unless the input was refused

  explicit Run(const Arguments& a) : args(a) { result.add("command", a.command); }
  // prints the notes (unless `code` says the input or the arguments were refused), then the summary line (or the JSON
  // object) to stdout (stderr with `summary_to_stderr`); returns `code`
  int finish(int code);
  // The one failure report: prints `pe: <what>: <message> (<ERROR_NAME>)` to stderr, marks the
  // result as neither valid nor written, ends the summary with `<ERROR_NAME>, nothing written`
  // and returns exit_status(ec), or `code` when it is not negative (an error that the input file caused
  // whatever its code). `detail` replaces the generic message of `ec` when not empty.
  int fail(PE::Error_code ec, const std::string& what, const std::string& detail = std::string(), int code = -1);
};

// formats a measure: `%.6g`, or inf, -inf, nan (never "-nan")
std::string format_number(double d);
std::string seconds_string(double s);

// ---- files ----------------------------------------------------------------------------------

// Checks, before any long computation, that `path` can be an output file (not a directory, in
// an existing directory), or with `directory`, that it is an existing directory. `role` names
// the option. Returns EXIT_VALID or reports the failure through `run` (output error).
int check_output_path(Run& run, const std::string& path, const std::string& role = std::string(), bool directory = false);

// whether `path` names the file, device or pipe that is this process's standard output (e.g. /dev/stdout)
bool is_standard_output(const std::string& path);

// why `path` cannot be read as an input file (missing, not a regular file, unreadable); empty if it can
std::string input_file_problem(const std::string& path);

// ---- the commands ----------------------------------------------------------------------------

int cmd_tutte(const Arguments& a);
int cmd_thingi(const Arguments& a);
int cmd_random_init(const Arguments& a);
int cmd_check(const Arguments& a);
int cmd_svg(const Arguments& a);
int cmd_untangle(const Arguments& a);
int cmd_embed(const Arguments& a);
int cmd_optimize(const Arguments& a);
int cmd_constrain(const Arguments& a);
int cmd_cross(const Arguments& a);
int cmd_polygon(const Arguments& a);
int cmd_generate(const Arguments& a);
int cmd_demo(const Arguments& a);
int cmd_batch(const Arguments& a);
int cmd_batch_merge(const Arguments& a);

} // namespace pe_tool

#endif // PE_TOOL_CLI_H
