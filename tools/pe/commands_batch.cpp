// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe batch` and `pe batch-merge`: one pipeline over many meshes, each mesh in a child process
// (this binary again, with --json) under a wall-time and an address-space limit, one line per
// mesh appended to OUTDIR/results.jsonl; and the merge of the results of several such runs
// (shards) into one sorted results.jsonl, a CSV table and a Markdown summary.
//
// No CGAL here: the parent only starts processes, reads their JSON and writes records.

#include "cli.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

// Sanitizers reserve terabytes of address space for their shadow memory: no RLIMIT_AS under them.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#  define PE_BATCH_NO_ADDRESS_LIMIT
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#    define PE_BATCH_NO_ADDRESS_LIMIT
#  endif
#endif

namespace pe_tool {

namespace {

// ---- a small strict JSON reader and writer --------------------------------------------------
// Enough for what pe prints with --json and for results.jsonl: objects, arrays, strings,
// numbers, true, false, null. Numbers keep their text, so that a record read and written again
// is the same bytes.

struct Json
{
  enum Type { NUL, BOOL, NUMBER, STRING, ARRAY, OBJECT };
  Type type = NUL;
  std::string text;                                  // BOOL, NUMBER: the token; STRING: decoded
  std::vector<std::pair<std::string, Json> > members; // OBJECT, in order
  std::vector<Json> items;                           // ARRAY

  static Json string_value(const std::string& s) { Json j; j.type = STRING; j.text = s; return j; }
  static Json bool_value(bool b) { Json j; j.type = BOOL; j.text = b ? "true" : "false"; return j; }
  static Json number_value(double d);
  static Json object_value() { Json j; j.type = OBJECT; return j; }

  const Json* find(const std::string& key) const
  {
    for(const auto& m : members) if(m.first == key) return &m.second;
    return nullptr;
  }
  void set(const std::string& key, const Json& value)
  {
    for(auto& m : members) if(m.first == key) { m.second = value; return; }
    members.emplace_back(key, value);
  }
  bool is_true() const { return type == BOOL && text == "true"; }
};

Json Json::number_value(double d)
{
  if(!std::isfinite(d)) return Json(); // JSON has no inf or nan
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", d);
  Json j;
  j.type = NUMBER;
  j.text = b;
  return j;
}

class Json_reader
{
  const std::string& s_;
  std::size_t i_ = 0;
  int depth_ = 0;

  void skip_space()
  {
    while(i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r' || s_[i_] == '\n')) ++i_;
  }
  bool eat(char c) { skip_space(); if(i_ < s_.size() && s_[i_] == c) { ++i_; return true; } return false; }
  void fail(const std::string& why) { if(error.empty()) error = why + " at character " + std::to_string(i_ + 1); }

  bool hex4(unsigned& u)
  {
    if(i_ + 4 > s_.size()) return false;
    u = 0;
    for(int k = 0; k < 4; ++k)
    {
      const char c = s_[i_++];
      u <<= 4;
      if(c >= '0' && c <= '9') u |= unsigned(c - '0');
      else if(c >= 'a' && c <= 'f') u |= unsigned(c - 'a' + 10);
      else if(c >= 'A' && c <= 'F') u |= unsigned(c - 'A' + 10);
      else return false;
    }
    return true;
  }

  static void append_utf8(std::string& o, unsigned u)
  {
    if(u < 0x80) o += char(u);
    else if(u < 0x800) { o += char(0xC0 | (u >> 6)); o += char(0x80 | (u & 0x3F)); }
    else if(u < 0x10000) { o += char(0xE0 | (u >> 12)); o += char(0x80 | ((u >> 6) & 0x3F)); o += char(0x80 | (u & 0x3F)); }
    else
    {
      o += char(0xF0 | (u >> 18)); o += char(0x80 | ((u >> 12) & 0x3F));
      o += char(0x80 | ((u >> 6) & 0x3F)); o += char(0x80 | (u & 0x3F));
    }
  }

  // \uXXXX, with a surrogate pair where needed; i_ is after the 'u'
  bool unicode_escape(std::string& o)
  {
    unsigned u = 0;
    if(!hex4(u)) return false;
    if(u >= 0xD800 && u < 0xDC00)
    {
      unsigned low = 0;
      if(i_ + 2 > s_.size() || s_[i_] != '\\' || s_[i_ + 1] != 'u') return false;
      i_ += 2;
      if(!hex4(low) || low < 0xDC00 || low >= 0xE000) return false;
      u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
    }
    else if(u >= 0xDC00 && u < 0xE000) return false;
    append_utf8(o, u);
    return true;
  }

  bool escape(std::string& o)
  {
    if(i_ >= s_.size()) return false;
    const char c = s_[i_++];
    const char* from = "\"\\/bfnrt";
    const char* to = "\"\\/\b\f\n\r\t";
    if(c == 'u') return unicode_escape(o);
    const char* p = std::strchr(from, c);
    if(p == nullptr || c == '\0') return false;
    o += to[p - from];
    return true;
  }

  bool string(std::string& o)
  {
    if(!eat('"')) { fail("a string expected"); return false; }
    while(i_ < s_.size())
    {
      const char c = s_[i_++];
      if(c == '"') return true;
      if(static_cast<unsigned char>(c) < 0x20) { fail("a control character in a string"); return false; }
      if(c == '\\' && !escape(o)) { fail("a bad escape in a string"); return false; }
      if(c != '\\') o += c;
    }
    fail("an unterminated string");
    return false;
  }

  std::size_t digits()
  {
    const std::size_t b = i_;
    while(i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
    return i_ - b;
  }

  // the JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
  bool number(Json& v)
  {
    const std::size_t b = i_;
    if(s_[i_] == '-') ++i_;
    const std::size_t first = i_;
    const std::size_t n = digits();
    bool ok = n > 0 && !(n > 1 && s_[first] == '0');
    if(ok && i_ < s_.size() && s_[i_] == '.') { ++i_; ok = digits() > 0; }
    if(ok && i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E'))
    {
      ++i_;
      if(i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      ok = digits() > 0;
    }
    if(!ok) { fail("a bad number"); return false; }
    v.type = Json::NUMBER;
    v.text = s_.substr(b, i_ - b);
    return true;
  }

  bool literal(Json& v)
  {
    for(const char* word : { "true", "false", "null" })
      if(s_.compare(i_, std::strlen(word), word) == 0)
      {
        i_ += std::strlen(word);
        v.type = word[0] == 'n' ? Json::NUL : Json::BOOL;
        v.text = word[0] == 'n' ? "" : word;
        return true;
      }
    fail("a value expected");
    return false;
  }

  bool object(Json& v)
  {
    v.type = Json::OBJECT;
    if(eat('}')) return true;
    do
    {
      std::string key;
      Json member;
      if(!string(key)) return false;
      if(!eat(':')) { fail("':' expected"); return false; }
      if(!value(member)) return false;
      if(v.find(key) != nullptr) { fail("the key \"" + key + "\" twice"); return false; }
      v.members.emplace_back(key, member);
    } while(eat(','));
    if(!eat('}')) { fail("',' or '}' expected"); return false; }
    return true;
  }

  bool array(Json& v)
  {
    v.type = Json::ARRAY;
    if(eat(']')) return true;
    do
    {
      Json item;
      if(!value(item)) return false;
      v.items.push_back(item);
    } while(eat(','));
    if(!eat(']')) { fail("',' or ']' expected"); return false; }
    return true;
  }

  bool value(Json& v)
  {
    skip_space();
    if(i_ >= s_.size()) { fail("a value expected"); return false; }
    if(++depth_ > 64) { fail("nested too deeply"); return false; }
    bool ok = false;
    const char c = s_[i_];
    if(c == '{') { ++i_; ok = object(v); }
    else if(c == '[') { ++i_; ok = array(v); }
    else if(c == '"') { v.type = Json::STRING; ok = string(v.text); }
    else if(c == '-' || (c >= '0' && c <= '9')) ok = number(v);
    else ok = literal(v);
    --depth_;
    return ok;
  }

public:
  std::string error;

  explicit Json_reader(const std::string& s) : s_(s) {}

  // one JSON object and nothing after it but white space
  bool read_object(Json& v)
  {
    skip_space();
    if(i_ >= s_.size() || s_[i_] != '{') { fail("an object expected"); return false; }
    if(!value(v)) return false;
    skip_space();
    if(i_ != s_.size()) { fail("text after the object"); return false; }
    return true;
  }
};

bool parse_object(const std::string& text, Json& out, std::string& why)
{
  Json_reader r(text);
  out = Json();
  if(r.read_object(out)) return true;
  why = r.error;
  return false;
}

std::string quoted(const std::string& s) { return "\"" + json_escape(s) + "\""; }

// the layout of pe's --json: {"key": value, "key": value}, one line
std::string to_text(const Json& v)
{
  switch(v.type)
  {
    case Json::NUL: return "null";
    case Json::BOOL:
    case Json::NUMBER: return v.text;
    case Json::STRING: return quoted(v.text);
    case Json::ARRAY:
    {
      std::string o = "[";
      for(std::size_t i = 0; i < v.items.size(); ++i) o += (i ? ", " : "") + to_text(v.items[i]);
      return o + "]";
    }
    case Json::OBJECT:
    {
      std::string o = "{";
      for(std::size_t i = 0; i < v.members.size(); ++i)
        o += (i ? ", " : "") + quoted(v.members[i].first) + ": " + to_text(v.members[i].second);
      return o + "}";
    }
  }
  return "null";
}

std::string string_of(const Json& record, const std::string& key)
{
  const Json* v = record.find(key);
  return v != nullptr && v->type == Json::STRING ? v->text : std::string();
}

double number_of(const Json& record, const std::string& key)
{
  const Json* v = record.find(key);
  return v != nullptr && v->type == Json::NUMBER ? std::strtod(v->text.c_str(), nullptr) : std::nan("");
}

// ---- files ----------------------------------------------------------------------------------

bool is_directory(const std::string& p) { struct stat st; return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode); }
bool is_regular(const std::string& p) { struct stat st; return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode); }

std::string folder_of(const std::string& p)
{
  const std::size_t slash = p.rfind('/');
  return slash == std::string::npos ? std::string() : p.substr(0, slash == 0 ? 1 : slash);
}

std::string join(const std::string& folder, const std::string& name)
{
  if(folder.empty() || name.empty() || name[0] == '/') return name;
  return folder.back() == '/' ? folder + name : folder + "/" + name;
}

// the file name without folder and extension
std::string base_name(const std::string& p)
{
  const std::size_t slash = p.rfind('/');
  std::string name = slash == std::string::npos ? p : p.substr(slash + 1);
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

std::string lower_extension(const std::string& p)
{
  const std::size_t dot = p.rfind('.');
  std::string e = dot == std::string::npos ? std::string() : p.substr(dot + 1);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string trimmed(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(" \t\r\n");
  if(b == std::string::npos) return std::string();
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// creates `dir` and its missing parents; false if it is not a directory afterwards
bool make_directories(const std::string& dir)
{
  if(dir.empty() || is_directory(dir)) return true;
  const std::string parent = folder_of(dir);
  if(!parent.empty() && parent != dir && !make_directories(parent)) return false;
  return ::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST ? is_directory(dir) : false;
}

// writes `content` into `path` through a temporary file and a rename: never a partial file
bool write_whole_file(const std::string& path, const std::string& content, std::string& why)
{
  const std::string tmp = path + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  bool ok = f != nullptr && std::fwrite(content.data(), 1, content.size(), f) == content.size();
  ok = f != nullptr && std::fflush(f) == 0 && ::fsync(fileno(f)) == 0 && ok;
  if(f != nullptr && std::fclose(f) != 0) ok = false;
  if(ok && std::rename(tmp.c_str(), path.c_str()) == 0) return true;
  why = "cannot write '" + path + "': " + std::strerror(errno);
  std::remove(tmp.c_str());
  return false;
}

// ---- the statuses of a mesh -----------------------------------------------------------------

// A final status is not run again by --resume; output_error and error (a full disk, a child
// that could not start) are.
bool is_final(const std::string& status)
{
  return status == "done" || status == "input_error" || status == "timeout" || status == "memory" ||
         status == "crashed";
}

// the keys that differ between two runs of the same inputs: times, and the shard that ran them
bool is_timing_key(const std::string& k)
{
  const auto ends_with = [&k](const std::string& e) { return k.size() >= e.size() && k.compare(k.size() - e.size(), e.size(), e) == 0; };
  return k == "seconds" || k.compare(0, 8, "seconds_") == 0 || ends_with("_seconds") || k.find("time") != std::string::npos ||
         k == "shard";
}

void drop_timings(Json& v)
{
  std::vector<std::pair<std::string, Json> > kept;
  for(auto& m : v.members)
  {
    if(is_timing_key(m.first)) continue;
    drop_timings(m.second);
    kept.push_back(m);
  }
  v.members.swap(kept);
}

// the records of a results.jsonl, in file order; lines that are not a JSON object with a string
// "input" (a line cut short by a crash) are skipped with a warning. False if unreadable.
bool read_records(const std::string& file, std::vector<Json>& records)
{
  std::ifstream in(file);
  if(!in) return false;
  std::string line;
  for(std::size_t n = 1; std::getline(in, line); ++n)
  {
    if(trimmed(line).empty()) continue;
    Json r;
    std::string why;
    if(!parse_object(line, r, why)) why = "not a JSON object: " + why;
    else if(string_of(r, "input").empty() || string_of(r, "status").empty()) why = "no \"input\" or \"status\"";
    else { records.push_back(r); continue; }
    std::cerr << "pe: " << file << ": line " << n << " skipped: " << why << std::endl;
  }
  return !in.bad();
}

// ---- batch: the list of inputs --------------------------------------------------------------

struct Item
{
  std::string input;   // as given (a line of the list, or FOLDER/NAME)
  std::string path;    // where to read it
  std::string output;  // file name of the map in OUTDIR
};

bool is_mesh_file(const std::string& name)
{
  const std::string e = lower_extension(name);
  return e == "obj" || e == "off" || e == "ply" || e == "stl";
}

bool list_folder(const std::string& folder, std::vector<Item>& items, std::string& why)
{
  DIR* d = ::opendir(folder.c_str());
  if(d == nullptr) { why = std::strerror(errno); return false; }
  std::string f = folder;
  while(f.size() > 1 && f.back() == '/') f.pop_back();
  while(const dirent* e = ::readdir(d))
  {
    const std::string p = join(f, e->d_name);
    if(is_mesh_file(e->d_name) && is_regular(p)) items.push_back({ p, p, std::string() });
  }
  ::closedir(d);
  return true;
}

bool list_file(const std::string& list, std::vector<Item>& items, std::string& why)
{
  std::ifstream in(list);
  if(!in) { why = std::strerror(errno); return false; }
  const std::string folder = folder_of(list);
  std::string line;
  while(std::getline(in, line))
  {
    const std::string entry = trimmed(line);
    if(entry.empty() || entry[0] == '#') continue;
    items.push_back({ entry, join(folder, entry), std::string() });
  }
  if(in.bad()) { why = "read error"; return false; }
  return true;
}

// the output file names: the input's base name, with its index in the sorted list when two
// inputs share it; computed on the whole list so that every shard names a mesh alike
void name_outputs(std::vector<Item>& items)
{
  std::map<std::string, std::size_t> uses;
  for(const Item& i : items) ++uses[base_name(i.input)];
  for(std::size_t k = 0; k < items.size(); ++k)
  {
    const std::string base = base_name(items[k].input);
    items[k].output = (uses[base] > 1 ? base + "-" + std::to_string(k + 1) : base) + ".obj";
  }
}

// all inputs, sorted and without repeats; false (and `why`) if the list or folder cannot be read
bool list_inputs(const std::string& source, std::vector<Item>& items, std::string& why)
{
  if(!(is_directory(source) ? list_folder(source, items, why) : is_regular(source) ? list_file(source, items, why)
                                                                                  : (why = "no such file or folder", false)))
    return false;
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.input < b.input; });
  items.erase(std::unique(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.input == b.input; }),
              items.end());
  name_outputs(items);
  return true;
}

// ---- batch: settings ------------------------------------------------------------------------

struct Batch_settings
{
  std::string pipeline, source, outdir;
  unsigned long long shard = 1, shards = 1;
  std::size_t jobs = 1;
  double time_limit = 600;
  unsigned long long memory_mb = 8192;
  std::vector<std::string> passed;   // options given to every child
};

const char* const pipelines[] = { "untangle", "embed", "optimize", "constrain" };

// "K/N" with 1 <= K <= N
bool parse_shard(const std::string& s, unsigned long long& k, unsigned long long& n, std::string& why)
{
  const std::size_t slash = s.find('/');
  std::string w;
  if(slash != std::string::npos && parse_count(s.substr(0, slash), 1, 1000000, k, w) &&
     parse_count(s.substr(slash + 1), 1, 1000000, n, w) && k <= n)
    return true;
  why = "option --shard: '" + s + "' is not K/N with 1 <= K <= N (N up to 1000000)";
  return false;
}

// the options of `batch` that are not its own go to every child, if the pipeline takes them
std::string passed_options(const Arguments& a, Batch_settings& s)
{
  const std::set<std::string> own = { "--shard", "--jobs", "--resume", "--time-limit", "--memory-limit", "--no-progress" };
  for(const auto& kv : a.options)
  {
    if(own.count(kv.first)) continue;
    if(!command_accepts(s.pipeline, kv.first)) return "option " + kv.first + " does not apply to batch " + s.pipeline;
    s.passed.push_back(kv.first);
    if(!kv.second.empty()) s.passed.push_back(kv.second); // flags have no value
  }
  return std::string();
}

// returns the usage error, empty if none
std::string batch_settings(const Arguments& a, Batch_settings& s)
{
  s.pipeline = a.positional[0];
  s.source = a.positional[1];
  s.outdir = a.positional[2];
  if(std::find_if(std::begin(pipelines), std::end(pipelines), [&s](const char* p) { return s.pipeline == p; }) ==
     std::end(pipelines))
    return "unknown pipeline '" + s.pipeline + "' (expected one of untangle,embed,optimize,constrain)";
  std::string why;
  if(a.has("--shard") && !parse_shard(a.get("--shard"), s.shard, s.shards, why)) return why;
  s.jobs = static_cast<std::size_t>(a.count("--jobs", 1));
  s.time_limit = a.real("--time-limit", s.time_limit);
  s.memory_mb = a.count("--memory-limit", s.memory_mb);
  // the maps are named after their inputs: written into the input folder, they could replace them
  char* in = is_directory(s.source) && is_directory(s.outdir) ? ::realpath(s.source.c_str(), nullptr) : nullptr;
  char* out = in != nullptr ? ::realpath(s.outdir.c_str(), nullptr) : nullptr;
  const bool same = in != nullptr && out != nullptr && std::strcmp(in, out) == 0;
  std::free(in);
  std::free(out);
  if(same) return "OUTDIR must not be the input folder";
  return passed_options(a, s);
}

std::string shard_name(const Batch_settings& s) { return std::to_string(s.shard) + "/" + std::to_string(s.shards); }

// ---- batch: the child processes -------------------------------------------------------------

struct Child
{
  Item item;
  pid_t pid = -1;
  int fd[2] = { -1, -1 };   // read ends of the child's stdout and stderr
  std::string out, err;
  Timer timer;
  double seconds = 0;
  bool timed_out = false;
  bool reaped = false;
  int wait_status = 0;

  bool finished() const { return reaped && fd[0] < 0 && fd[1] < 0; }
};

std::vector<std::string> child_command(const Batch_settings& s, const Item& item)
{
  std::vector<std::string> c = { "pe", s.pipeline, item.path, join(s.outdir, item.output), "--json", "--no-progress" };
  c.insert(c.end(), s.passed.begin(), s.passed.end());
  // constrain: the constraints beside the mesh, if any (else the border only)
  const std::string fix = join(folder_of(item.path), base_name(item.path) + ".fix");
  if(s.pipeline == "constrain" && is_regular(fix)) { c.push_back("--fix"); c.push_back(fix); }
  return c;
}

// In the child, between fork and exec: only system calls.
[[noreturn]] void exec_child(char* const* argv, int out, int err, unsigned long long memory_mb, pid_t parent)
{
  ::dup2(out, 1);
  ::dup2(err, 2);
  const int null = ::open("/dev/null", O_RDONLY);
  if(null >= 0) ::dup2(null, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);   // a killed batch leaves no child behind
  if(::getppid() != parent) ::_exit(127);
#if !defined(PE_BATCH_NO_ADDRESS_LIMIT)
  if(memory_mb > 0)
  {
    const rlim_t bytes = static_cast<rlim_t>(memory_mb) << 20;
    const struct rlimit limit = { bytes, bytes };
    ::setrlimit(RLIMIT_AS, &limit);
  }
#else
  (void)memory_mb;
#endif
  ::execv("/proc/self/exe", argv);
  const char* msg = "pe batch: cannot run /proc/self/exe: ";
  ::write(2, msg, std::strlen(msg));
  ::write(2, std::strerror(errno), std::strlen(std::strerror(errno)));
  ::_exit(127);
}

void close_fd(int& fd) { if(fd >= 0) ::close(fd); fd = -1; }

// starts the child of `item`; a child that cannot start ends at once (exit 127, the reason in err)
Child start_child(const Batch_settings& s, const Item& item)
{
  Child c;
  c.item = item;
  const std::vector<std::string> command = child_command(s, item);
  std::vector<char*> argv;
  for(const std::string& w : command) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  int out[2] = { -1, -1 }, err[2] = { -1, -1 };
  const pid_t parent = ::getpid();
  if(::pipe2(out, O_CLOEXEC) == 0 && ::pipe2(err, O_CLOEXEC) == 0 && (c.pid = ::fork()) >= 0)
  {
    if(c.pid == 0) exec_child(argv.data(), out[1], err[1], s.memory_mb, parent);
    close_fd(out[1]);
    close_fd(err[1]);
    c.fd[0] = out[0];
    c.fd[1] = err[0];
    return c;
  }
  c.err = std::string("cannot start a child process: ") + std::strerror(errno);
  for(int* fd : { &out[0], &out[1], &err[0], &err[1] }) close_fd(*fd);
  c.reaped = true;
  c.wait_status = 127 << 8; // as exit(127)
  return c;
}

// reads what is there; closes the descriptor at its end. Keeps at most `cap` bytes (the last ones).
void drain(int& fd, std::string& buffer, std::size_t cap)
{
  char b[65536];
  const ssize_t n = ::read(fd, b, sizeof b);
  if(n < 0 && (errno == EINTR || errno == EAGAIN)) return;
  if(n <= 0) { close_fd(fd); return; }
  buffer.append(b, std::size_t(n));
  if(buffer.size() > cap) buffer.erase(0, buffer.size() - cap);
}

// waits (at most 0.1 s) for output of the children and reads it
void read_children(std::vector<Child>& running)
{
  std::vector<pollfd> fds;
  std::vector<std::pair<std::size_t, int> > owner;
  bool exiting = false;   // a child has closed its output: it is ending, look again soon
  for(std::size_t c = 0; c < running.size(); ++c)
  {
    exiting = exiting || (running[c].fd[0] < 0 && running[c].fd[1] < 0);
    for(int k = 0; k < 2; ++k)
      if(running[c].fd[k] >= 0) { fds.push_back({ running[c].fd[k], POLLIN, 0 }); owner.emplace_back(c, k); }
  }
  if(::poll(fds.data(), fds.size(), exiting ? 5 : 100) <= 0) return;
  for(std::size_t i = 0; i < fds.size(); ++i)
  {
    if(fds[i].revents == 0) continue;
    Child& c = running[owner[i].first];
    const int k = owner[i].second;
    drain(c.fd[k], k == 0 ? c.out : c.err, k == 0 ? (std::size_t(1) << 24) : 65536);
  }
}

// kills the children past the time limit, reaps those that ended
void check_children(std::vector<Child>& running, double time_limit)
{
  for(Child& c : running)
  {
    if(c.reaped) continue;
    if(!c.timed_out && c.timer.seconds() > time_limit)
    {
      ::kill(c.pid, SIGKILL);
      c.timed_out = true;
    }
    if(::waitpid(c.pid, &c.wait_status, WNOHANG) == c.pid)
    {
      c.reaped = true;
      c.seconds = c.timer.seconds();
    }
  }
}

// ---- batch: the record of a mesh ------------------------------------------------------------

bool says_out_of_memory(const std::string& err)
{
  return err.find("out of memory") != std::string::npos || err.find("bad_alloc") != std::string::npos ||
         err.find("Cannot allocate memory") != std::string::npos;
}

// the status of an ended child (see is_final())
std::string child_status(const Child& c, bool has_json)
{
  if(c.timed_out) return "timeout";
  if(WIFSIGNALED(c.wait_status)) return says_out_of_memory(c.err) ? "memory" : "crashed";
  const int code = WEXITSTATUS(c.wait_status);
  if(!has_json && says_out_of_memory(c.err)) return "memory";
  if(code == EXIT_INPUT) return "input_error";
  if(code == EXIT_OUTPUT) return "output_error";
  if(code == EXIT_VALID || code == EXIT_INVALID) return has_json ? "done" : "crashed";
  return "error";
}

std::string last_line(const std::string& text)
{
  const std::string t = trimmed(text);
  const std::size_t nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

// the keys of the child's JSON, after the batch's: its "status" (an Error_code name) becomes
// "code", its "seconds" "command_seconds", its "output" the file name in OUTDIR
void add_child_keys(Json& record, const Json& child, const Item& item)
{
  for(const auto& m : child.members)
  {
    if(m.first == "valid" || m.first == "exit_status") continue;
    if(m.first == "status") record.set("code", m.second);
    else if(m.first == "seconds") record.set("command_seconds", m.second);
    else if(m.first == "output") record.set("output", Json::string_value(item.output));
    else if(record.find(m.first) == nullptr) record.set(m.first, m.second);
  }
}

Json child_record(const Batch_settings& s, const Child& c)
{
  Json child;
  std::string why;
  const bool has_json = parse_object(last_line(c.out), child, why);
  const std::string status = child_status(c, has_json);
  const Json* valid = has_json ? child.find("valid") : nullptr;
  Json r = Json::object_value();
  r.set("input", Json::string_value(c.item.input));
  r.set("status", Json::string_value(status));
  r.set("valid", Json::bool_value(status == "done" && valid != nullptr && valid->is_true()));
  r.set("exit_status", WIFEXITED(c.wait_status) && !c.timed_out ? Json::number_value(WEXITSTATUS(c.wait_status)) : Json());
  r.set("seconds", Json::number_value(c.seconds));
  r.set("shard", Json::string_value(shard_name(s)));
  if(WIFSIGNALED(c.wait_status)) r.set("signal", Json::number_value(WTERMSIG(c.wait_status)));
  if(!has_json && !trimmed(c.err).empty()) r.set("stderr", Json::string_value(last_line(c.err)));
  if(has_json) add_child_keys(r, child, c.item);
  return r;
}

// ---- batch: results.jsonl and the tally -----------------------------------------------------

// results.jsonl, opened for appending: one line per record, on disk before the next mesh ends
class Results_file
{
  FILE* f_ = nullptr;
public:
  ~Results_file() { if(f_ != nullptr) std::fclose(f_); }
  bool open(const std::string& path)
  {
    f_ = std::fopen(path.c_str(), "a+b");
    if(f_ == nullptr) return false;
    // a line cut short by a crash is ended, so that the next record starts a line of its own
    if(std::fseek(f_, -1, SEEK_END) == 0 && std::fgetc(f_) != '\n') std::fputc('\n', f_);
    return std::fflush(f_) == 0;
  }
  bool append(const Json& record)
  {
    const std::string line = to_text(record) + "\n";
    return std::fwrite(line.data(), 1, line.size(), f_) == line.size() && std::fflush(f_) == 0 && ::fsync(fileno(f_)) == 0;
  }
};

struct Tally
{
  std::size_t meshes = 0, run = 0, skipped = 0, valid = 0, timeouts = 0;
  std::map<std::string, std::size_t> statuses;
  double mesh_seconds = 0;

  void count(const Json& r, bool resumed)
  {
    const std::string status = string_of(r, "status");
    ++meshes;
    ++(resumed ? skipped : run);
    ++statuses[status];
    const Json* v = r.find("valid");
    if(v != nullptr && v->is_true()) ++valid;
    if(status == "timeout") ++timeouts;
    if(!resumed && std::isfinite(number_of(r, "seconds"))) mesh_seconds += number_of(r, "seconds");
  }
  std::string statuses_json() const
  {
    Json o = Json::object_value();
    for(const auto& kv : statuses) o.set(kv.first, Json::number_value(double(kv.second)));
    return to_text(o);
  }
};

// --resume: the final records of earlier runs in results.jsonl, by input
std::map<std::string, Json> finished_inputs(const std::string& results)
{
  std::vector<Json> records;
  std::map<std::string, Json> done;
  if(is_regular(results)) read_records(results, records);
  for(const Json& r : records)
    if(is_final(string_of(r, "status"))) done[string_of(r, "input")] = r;
  return done;
}

void report_mesh(const Json& r, std::size_t done, std::size_t total)
{
  const Json* v = r.find("valid");
  std::cerr << "pe batch: [" << done << "/" << total << "] " << string_of(r, "input") << ": " << string_of(r, "status")
            << (v != nullptr && v->is_true() ? ", valid" : ", not valid") << ", " << seconds_string(number_of(r, "seconds"))
            << std::endl;
}

// runs the children of `todo`, `jobs` at a time; returns false if results.jsonl cannot be written
bool run_children(const Batch_settings& s, const std::vector<Item>& todo, Results_file& results, Tally& tally,
                  bool progress)
{
  Progress bar("batch " + s.pipeline, progress);
  std::vector<Child> running;
  std::size_t next = 0, ended = 0;
  while(next < todo.size() || !running.empty())
  {
    while(running.size() < s.jobs && next < todo.size()) running.push_back(start_child(s, todo[next++]));
    read_children(running);
    check_children(running, s.time_limit);
    for(std::size_t c = 0; c < running.size();)
    {
      if(!running[c].finished()) { ++c; continue; }
      const Json r = child_record(s, running[c]);
      running.erase(running.begin() + std::ptrdiff_t(c));
      if(!results.append(r)) return false;
      tally.count(r, false);
      bar.finish();
      report_mesh(r, ++ended, todo.size());
    }
    bar.set_label("batch " + s.pipeline + " " + std::to_string(ended) + "/" + std::to_string(todo.size()));
    bar.update(todo.empty() ? 1. : double(ended) / double(todo.size()));
  }
  return true;
}

int finish_batch(Run& run, const Batch_settings& s, const Tally& t, const std::string& results)
{
  const std::size_t failed = t.meshes - t.valid;
  run.result.add("pipeline", s.pipeline);
  run.result.add("shard", shard_name(s));
  run.result.add("meshes", t.meshes);
  run.result.add("run", t.run);
  run.result.add("skipped", t.skipped);
  run.result.add("valid", t.valid);
  run.result.add("failed", failed);
  run.result.add("timeouts", t.timeouts);
  run.result.set("statuses", t.statuses_json());
  run.result.add("mesh_seconds", t.mesh_seconds);
  run.result.add("seconds", run.timer.seconds());
  run.result.add("results", results);
  run.summary << t.meshes << " meshes (" << t.run << " run, " << t.skipped << " skipped by --resume): " << t.valid
              << " valid, " << failed << " failed, " << t.timeouts << " timeouts (";
  for(auto it = t.statuses.begin(); it != t.statuses.end(); ++it)
    run.summary << (it == t.statuses.begin() ? "" : ", ") << it->first << " " << it->second;
  run.summary << "), " << seconds_string(run.timer.seconds()) << "; results: " << results;
  return run.finish(failed == 0 ? EXIT_VALID : EXIT_INVALID);
}

// the shard's items: index % N == K - 1 in the sorted list
std::vector<Item> shard_items(const std::vector<Item>& all, const Batch_settings& s)
{
  std::vector<Item> mine;
  for(std::size_t i = 0; i < all.size(); ++i)
    if(i % s.shards == s.shard - 1) mine.push_back(all[i]);
  return mine;
}

// ---- batch-merge ----------------------------------------------------------------------------

// one record per input: a final status wins over a non-final one, else the later record
void merge_record(std::map<std::string, Json>& merged, const Json& r)
{
  const std::string input = string_of(r, "input");
  const auto it = merged.find(input);
  if(it != merged.end() && is_final(string_of(it->second, "status")) && !is_final(string_of(r, "status"))) return;
  merged[input] = r;
}

// the cells of a record: nested objects flattened as a.b, arrays as their JSON text
void flatten(const Json& v, const std::string& prefix, std::map<std::string, std::string>& cells)
{
  for(const auto& m : v.members)
  {
    const std::string key = prefix.empty() ? m.first : prefix + "." + m.first;
    if(m.second.type == Json::OBJECT) flatten(m.second, key, cells);
    else if(m.second.type == Json::NUL) cells[key] = "";
    else if(m.second.type == Json::STRING) cells[key] = m.second.text;
    else cells[key] = to_text(m.second);
  }
}

std::string csv_cell(const std::string& s)
{
  if(s.find_first_of(",\"\r\n") == std::string::npos && trimmed(s) == s) return s;
  std::string o = "\"";
  for(char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::string csv_text(const std::vector<Json>& records)
{
  const std::vector<std::string> first = { "input", "status", "valid", "exit_status", "seconds" };
  std::vector<std::map<std::string, std::string> > rows(records.size());
  std::set<std::string> others;
  for(std::size_t i = 0; i < records.size(); ++i)
  {
    flatten(records[i], std::string(), rows[i]);
    for(const auto& kv : rows[i]) if(std::find(first.begin(), first.end(), kv.first) == first.end()) others.insert(kv.first);
  }
  std::vector<std::string> columns = first;
  columns.insert(columns.end(), others.begin(), others.end());
  std::string o;
  for(std::size_t c = 0; c < columns.size(); ++c) o += (c ? "," : "") + csv_cell(columns[c]);
  o += "\n";
  for(const auto& row : rows)
  {
    for(std::size_t c = 0; c < columns.size(); ++c)
    {
      const auto it = row.find(columns[c]);
      o += (c ? "," : "") + (it == row.end() ? std::string() : csv_cell(it->second));
    }
    o += "\n";
  }
  return o;
}

std::string markdown_cell(const std::string& s)
{
  std::string o;
  for(char c : s) o += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return o;
}

std::string seconds_lines(const std::vector<Json>& records)
{
  std::vector<double> t;
  for(const Json& r : records) if(std::isfinite(number_of(r, "seconds"))) t.push_back(number_of(r, "seconds"));
  if(t.empty()) return std::string();
  std::sort(t.begin(), t.end());
  double total = 0;
  for(double x : t) total += x;
  const std::size_t n = t.size();
  const double median = n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2;
  return "Seconds per mesh (wall time of its process): total " + format_number(total) + ", median " +
         format_number(median) + ", max " + format_number(t.back()) + ".\n\n";
}

std::string failures_table(const std::vector<Json>& records)
{
  std::string o;
  for(const Json& r : records)
  {
    const Json* v = r.find("valid");
    if(v != nullptr && v->is_true()) continue;
    const Json* e = r.find("exit_status");
    std::string message = string_of(r, "message");
    if(message.empty()) message = string_of(r, "stderr");
    o += "| " + markdown_cell(string_of(r, "input")) + " | " + string_of(r, "status") + " | " +
         (e != nullptr ? to_text(*e) : std::string("null")) + " | " + markdown_cell(string_of(r, "code")) + " | " +
         markdown_cell(message) + " |\n";
  }
  if(o.empty()) return "No failures: every mesh is certified valid.\n";
  return "| input | status | exit status | code | message |\n|---|---|---:|---|---|\n" + o;
}

std::string summary_markdown(const std::vector<Json>& records)
{
  std::map<std::string, std::size_t> statuses;
  std::size_t valid = 0;
  for(const Json& r : records)
  {
    ++statuses[string_of(r, "status")];
    const Json* v = r.find("valid");
    if(v != nullptr && v->is_true()) ++valid;
  }
  std::string o = "# Batch results\n\n" + std::to_string(records.size()) + " meshes, " + std::to_string(valid) +
                  " certified valid, " + std::to_string(records.size() - valid) + " not.\n\n| status | meshes |\n|---|---:|\n";
  for(const auto& kv : statuses) o += "| " + kv.first + " | " + std::to_string(kv.second) + " |\n";
  o += "| (valid) | " + std::to_string(valid) + " |\n\n" + seconds_lines(records) + "## Failures\n\n";
  return o + failures_table(records);
}

// the three files of the merge; false (and `why`) if one cannot be written
bool write_merge(const std::string& out, const std::vector<Json>& records, std::string& why)
{
  std::string jsonl;
  for(const Json& r : records) jsonl += to_text(r) + "\n";
  return write_whole_file(join(out, "results.jsonl"), jsonl, why) &&
         write_whole_file(join(out, "results.csv"), csv_text(records), why) &&
         write_whole_file(join(out, "summary.md"), summary_markdown(records), why);
}

} // namespace

int cmd_batch(const Arguments& a)
{
  Batch_settings s;
  const std::string err = batch_settings(a, s);
  if(!err.empty()) return usage(err);
  Run run(a);
  run.summary << "batch " << s.pipeline << " shard " << shard_name(s) << ": ";
  std::vector<Item> all;
  std::string why;
  if(!list_inputs(s.source, all, why)) return run.fail(PE::ERROR_CANNOT_READ_FILE, "cannot read the list or folder '" + s.source + "'", why);
  const std::string results = join(s.outdir, "results.jsonl");
  Results_file file;
  if(!make_directories(s.outdir) || ::access(s.outdir.c_str(), W_OK) != 0 || !file.open(results))
    return run.fail(PE::ERROR_CANNOT_WRITE_FILE, "cannot write into '" + s.outdir + "'", std::strerror(errno));
  Tally tally;
  const std::map<std::string, Json> earlier = a.has("--resume") ? finished_inputs(results) : std::map<std::string, Json>();
  std::vector<Item> todo;
  for(const Item& item : shard_items(all, s))
  {
    const auto it = earlier.find(item.input);
    if(it != earlier.end()) tally.count(it->second, true);
    else todo.push_back(item);
  }
  if(!run_children(s, todo, file, tally, a.progress()))
    return run.fail(PE::ERROR_CANNOT_WRITE_FILE, "cannot append to '" + results + "'", std::strerror(errno));
  return finish_batch(run, s, tally, results);
}

int cmd_batch_merge(const Arguments& a)
{
  if(!a.has("--out")) return usage("batch-merge needs --out DIR");
  Run run(a);
  run.summary << "batch-merge: ";
  std::map<std::string, Json> merged;
  for(const std::string& dir : a.positional)
  {
    std::vector<Json> records;
    const std::string file = join(dir, "results.jsonl");
    const std::string why = input_file_problem(file);
    if(!why.empty() || !read_records(file, records))
      return run.fail(PE::ERROR_CANNOT_READ_FILE, "cannot read '" + file + "'", why.empty() ? "read error" : why);
    for(const Json& r : records) merge_record(merged, r);
  }
  std::vector<Json> records;
  std::size_t valid = 0;
  for(auto& kv : merged)
  {
    if(a.has("--drop-timings")) drop_timings(kv.second);
    const Json* v = kv.second.find("valid");
    valid += v != nullptr && v->is_true();
    records.push_back(kv.second);
  }
  const std::string out = a.get("--out");
  std::string why;
  if(!make_directories(out)) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, "cannot create '" + out + "'", std::strerror(errno));
  if(!write_merge(out, records, why)) return run.fail(PE::ERROR_CANNOT_WRITE_FILE, "cannot write the merge", why);
  run.result.add("folders", a.positional.size());
  run.result.add("meshes", records.size());
  run.result.add("valid", valid);
  run.result.add("failed", records.size() - valid);
  run.result.add("out", out);
  run.summary << records.size() << " meshes from " << a.positional.size() << " folders, " << valid << " valid, "
              << records.size() - valid << " failed; " << join(out, "results.jsonl") << ", results.csv, summary.md";
  return run.finish(valid == records.size() ? EXIT_VALID : EXIT_INVALID);
}

} // namespace pe_tool
