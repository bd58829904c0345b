// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_ATOMIC_OUTPUT_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_ATOMIC_OUTPUT_H

// The one way every writer of the package writes a named file, so that a failure never leaves a
// partial file:
// - a regular file, or a name that does not exist yet: the content goes to a temporary file in the
//   same folder, which replaces the target (rename) only once it is completely written, flushed
//   and closed; on failure the temporary is removed and an existing target is left untouched;
// - a name for one of this process's file descriptors (/dev/stdout, /dev/fd/N, /proc/self/fd/N,
//   or a link to one): written through that descriptor, so that what it reaches (a pipe, a
//   socket, a file that a shell opened with `>` or `>>`) gets the content where the descriptor
//   stands, as a write to it would; nothing is replaced;
// - anything else that is not a regular file (a character device such as /dev/null, a named
//   pipe): written in place; the node itself is never replaced;
// - a folder: an error.
// Several files can be written all or none (write_files_atomically()): every name is checked and
// every temporary written before any of them replaces its target; what is written in place cannot
// be taken back. No exception escapes. POSIX (open, stat, rename, dup); the package targets POSIX
// systems.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

// the folder part of `path`, with its trailing '/', or "" for a bare name
inline std::string atomic_output_folder(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// The descriptor N when `path` names one of this process's file descriptors: /dev/fd/N,
// /proc/self/fd/N, /proc/thread-self/fd/N, /proc/<this process>/fd/N; -1 otherwise.
inline int atomic_output_own_descriptor(const std::string& path)
{
  std::string rest;
  const std::string pid = "/proc/" + std::to_string(static_cast<long long>(::getpid())) + "/fd/";
  for(const std::string& prefix : { std::string("/dev/fd/"), std::string("/proc/self/fd/"), std::string("/proc/thread-self/fd/"), pid })
    if(path.compare(0, prefix.size(), prefix) == 0) { rest = path.substr(prefix.size()); break; }
  if(rest.empty() || rest.size() > 9 || rest.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stoi(rest);
}

// Where a name that is a symbolic link finally points (the link is kept, its target replaced);
// `path` itself otherwise. Bounded like the kernel's own limit on link chains. `descriptor` is set
// to N when the name or a link on the way names this process's descriptor N (its target, e.g.
// "pipe:[12]", is reached only through the descriptor), to -1 otherwise.
inline std::string atomic_output_resolve_links(std::string path, int* descriptor = nullptr)
{
  if(descriptor) *descriptor = -1;
  for(int depth = 0; depth < 40; ++depth)
  {
    if(descriptor && *descriptor < 0) *descriptor = atomic_output_own_descriptor(path);
    struct stat ls;
    if(::lstat(path.c_str(), &ls) != 0 || !S_ISLNK(ls.st_mode)) return path;
    std::string target(std::size_t(ls.st_size > 0 ? ls.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(path.c_str(), &target[0], target.size());
    if(n <= 0) return path;
    target.resize(std::size_t(n));
    path = (target[0] == '/') ? target : atomic_output_folder(path) + target;
  }
  return path;
}

// An output stream buffer on a file descriptor (its own duplicate, closed with it): what is written
// goes where the descriptor stands and moves it on, as a write() to the original would. After a
// failed write nothing more is written (no byte twice).
class Atomic_output_descriptor_buffer : public std::streambuf
{
public:
  explicit Atomic_output_descriptor_buffer(int fd) : fd_(fd), buffer_(std::size_t(1) << 16) { reset(); }
  ~Atomic_output_descriptor_buffer() { if(fd_ >= 0) ::close(fd_); }
  Atomic_output_descriptor_buffer(const Atomic_output_descriptor_buffer&) = delete;
  Atomic_output_descriptor_buffer& operator=(const Atomic_output_descriptor_buffer&) = delete;
  // flushes and closes: false if a write or the close failed
  bool close()
  {
    const bool flushed = (sync() == 0);
    const bool closed = (::close(fd_) == 0);
    fd_ = -1;
    return flushed && closed;
  }

protected:
  int_type overflow(int_type c) override
  {
    if(sync() != 0) return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof())) { *pptr() = traits_type::to_char_type(c); pbump(1); }
    return traits_type::not_eof(c);
  }
  int sync() override
  {
    const char* p = pbase();
    while(!failed_ && p < pptr())
    {
      const ssize_t n = ::write(fd_, p, std::size_t(pptr() - p));
      if(n < 0 && errno == EINTR) continue;
      if(n <= 0) failed_ = true;
      else p += n;
    }
    reset(); // written, or dropped after a failure
    return failed_ ? -1 : 0;
  }

private:
  void reset() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int fd_;
  std::vector<char> buffer_; // on the heap: 64 KiB is too much for the stacks of some threads
  bool failed_ = false;
};

// Creates a new, empty file next to `target` (same folder, hence same file system for rename).
// Returns its name, or "" if none could be created.
inline std::string atomic_output_create_temporary(const std::string& target, mode_t mode)
{
  const std::string folder = atomic_output_folder(target);
  const std::string base = target.substr(folder.size());
  std::random_device rd;
  std::mt19937_64 rng((static_cast<unsigned long long>(rd()) << 32) ^ static_cast<unsigned long long>(::getpid()));
  for(int attempt = 0; attempt < 100; ++attempt) // bounded: a name collision is rare
  {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp-%012llx", static_cast<unsigned long long>(rng() & 0xffffffffffffull));
    const std::string name = folder + "." + base.substr(0, 200) + suffix;
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if(fd >= 0)
    {
      ::close(fd);
      return name;
    }
    if(errno != EEXIST) return std::string();
  }
  return std::string();
}

// Writes the open stream `out` with `write`, flushes it and closes it with `close()` (true if what
// was still buffered went out): the writer's code if it is not `OK`, ERROR_CANNOT_WRITE_FILE if the
// stream or the close failed, OK otherwise. Exceptions go to the caller.
template <class Writer, class Close>
Error_code atomic_output_send(std::ostream& out, Writer& write, Close close)
{
  Error_code ec = write(out);
  out.flush();
  if(ec == OK && !out) ec = ERROR_CANNOT_WRITE_FILE;
  if(!close() && ec == OK) ec = ERROR_CANNOT_WRITE_FILE;
  return ec;
}

// Writes `out` (opened on `name`) with `write`, flushed and closed (atomic_output_send()).
// (libstdc++'s filebuf may throw std::bad_cast from close() after a failed write: every exception
// is a failure.)
template <class Writer>
Error_code atomic_output_write_stream(const std::string& name, std::ios::openmode mode, Writer& write)
{
  try
  {
    std::ofstream out(name, std::ios::binary | mode);
    if(!out) return ERROR_CANNOT_WRITE_FILE;
    // close() writes what is still buffered: checked too
    return atomic_output_send(out, write, [&out]() { out.close(); return !out.fail(); });
  }
  catch(...) { return ERROR_CANNOT_WRITE_FILE; }
}

// One file of write_files_atomically(): its name, and what writes its content (`OK` or a code).
struct Atomic_output_file
{
  std::string name;
  std::function<Error_code(std::ostream&)> write;
};

// What write_files_atomically() did: `code` is `OK`, or the first failure's code (the writer's own,
// or ERROR_CANNOT_WRITE_FILE) with `failed` the index of the file it concerns.
struct Atomic_output_result
{
  Error_code code = OK;
  std::size_t failed = 0;
};

// Writes `files` all or none: every name is checked first (a folder, an empty name or a descriptor
// that is not open fails before anything is written); each regular file (or new name) goes to a
// temporary file beside its target, and the temporaries replace their targets only once all of
// them are written; on a failure every temporary is removed and the targets are left as they were.
// What is written in place (descriptors, devices: see the top of this file) is written first, so
// that a failing one comes before any file is touched, but what went to it stays. A rename that fails (the folder
// changed during the run) leaves the targets renamed before it replaced. Two names of one regular
// file are the caller's to refuse (the last would win).
inline Atomic_output_result write_files_atomically(const std::vector<Atomic_output_file>& files)
{
  enum class Way { DESCRIPTOR, IN_PLACE, TEMPORARY };
  struct Plan { Way way = Way::TEMPORARY; int descriptor = -1; std::string target; bool exists = false; mode_t mode = 0666; };
  struct Pending { std::string temporary, target; std::size_t index; };
  std::vector<Pending> pending; // the temporaries written so far
  Atomic_output_result result;
  auto abandon = [&](Error_code ec, std::size_t index) {
    for(const Pending& p : pending) std::remove(p.temporary.c_str());
    result.code = ec;
    result.failed = index;
    return result;
  };
  std::size_t current = 0;
  try
  {
    // every name checked before anything is written
    std::vector<Plan> plans(files.size());
    for(current = 0; current < files.size(); ++current)
    {
      const std::string& name = files[current].name;
      Plan& plan = plans[current];
      if(name.empty()) return abandon(ERROR_CANNOT_WRITE_FILE, current);
      plan.target = atomic_output_resolve_links(name, &plan.descriptor);
      struct stat st;
      plan.exists = (::stat(name.c_str(), &st) == 0); // the kernel follows every link, descriptor links too
      if(plan.exists && S_ISDIR(st.st_mode)) return abandon(ERROR_CANNOT_WRITE_FILE, current);
      if(plan.descriptor >= 0)
      {
        const int flags = ::fcntl(plan.descriptor, F_GETFL);
        if(flags < 0 || (flags & O_ACCMODE) == O_RDONLY) return abandon(ERROR_CANNOT_WRITE_FILE, current); // not open for writing
        plan.way = Way::DESCRIPTOR;
      }
      else if(plan.exists && !S_ISREG(st.st_mode)) plan.way = Way::IN_PLACE;
      else if(plan.exists) plan.mode = st.st_mode & 07777; // new files: 0666 minus the umask, as ofstream
    }
    pending.reserve(files.size());
    // what is written in place first (a failing one comes before any file is touched), then the temporaries
    for(int pass = 0; pass < 2; ++pass)
      for(current = 0; current < files.size(); ++current)
      {
        const Plan& plan = plans[current];
        const auto& write = files[current].write;
        if((plan.way == Way::TEMPORARY) != (pass == 1)) continue;
        if(plan.way == Way::DESCRIPTOR)
        {
          Error_code ec = ERROR_CANNOT_WRITE_FILE;
          try
          {
            const int fd = ::fcntl(plan.descriptor, F_DUPFD_CLOEXEC, 0);
            if(fd < 0) return abandon(ERROR_CANNOT_WRITE_FILE, current);
            Atomic_output_descriptor_buffer buffer(fd);
            std::ostream out(&buffer);
            ec = atomic_output_send(out, write, [&buffer]() { return buffer.close(); });
          }
          catch(...) { ec = ERROR_CANNOT_WRITE_FILE; }
          if(ec != OK) return abandon(ec, current);
          continue;
        }
        if(plan.way == Way::IN_PLACE)
        {
          const Error_code ec = atomic_output_write_stream(files[current].name, std::ios::out, write);
          if(ec != OK) return abandon(ec, current);
          continue;
        }
        pending.push_back({ std::string(), plan.target, current }); // before the file exists: cannot throw after it
        pending.back().temporary = atomic_output_create_temporary(plan.target, plan.mode);
        if(pending.back().temporary.empty()) { pending.pop_back(); return abandon(ERROR_CANNOT_WRITE_FILE, current); }
        if(plan.exists) (void)::chmod(pending.back().temporary.c_str(), plan.mode); // open() applied the umask; keep the old mode
        const Error_code ec = atomic_output_write_stream(pending.back().temporary, std::ios::trunc, write);
        if(ec != OK) return abandon(ec, current);
      }
    for(std::size_t k = 0; k < pending.size(); ++k)
      if(std::rename(pending[k].temporary.c_str(), pending[k].target.c_str()) != 0)
      {
        const std::size_t index = pending[k].index;
        pending.erase(pending.begin(), pending.begin() + std::ptrdiff_t(k)); // renamed: no longer temporaries
        return abandon(ERROR_CANNOT_WRITE_FILE, index);
      }
    return result;
  }
  catch(...)
  {
    // (std::random_device, std::bad_alloc, a writer's copy...): no temporary left behind
    return abandon(ERROR_CANNOT_WRITE_FILE, current < files.size() ? current : 0);
  }
}

// Writes `filename` with `write(std::ostream&) -> Error_code` (the one-file case of
// write_files_atomically()). Returns the writer's code if it is not `OK` (nothing is left behind),
// ERROR_CANNOT_WRITE_FILE if the file cannot be written, OK otherwise.
template <class Writer>
Error_code write_file_atomically(const std::string& filename, Writer&& write)
{
  try
  {
    std::vector<Atomic_output_file> one(1);
    one[0].name = filename;
    one[0].write = [&write](std::ostream& out) { return write(out); };
    return write_files_atomically(one).code;
  }
  catch(...) { return ERROR_CANNOT_WRITE_FILE; }
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_ATOMIC_OUTPUT_H
