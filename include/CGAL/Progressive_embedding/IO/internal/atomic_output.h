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
// - anything else (a character device such as /dev/null or /dev/stdout, a pipe, a socket): written
//   directly; the node itself is never replaced;
// - a folder: an error.
// No exception escapes. POSIX (open, stat, rename); the package targets POSIX systems.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <utility>

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

// Where a name that is a symbolic link finally points (the link is kept, its target replaced);
// `path` itself otherwise. Bounded like the kernel's own limit on link chains.
inline std::string atomic_output_resolve_links(std::string path)
{
  for(int depth = 0; depth < 40; ++depth)
  {
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

// Writes `filename` with `write(std::ostream&) -> Error_code`. Returns the writer's code if it is not
// `OK` (nothing is left behind), ERROR_CANNOT_WRITE_FILE if the file cannot be written, OK otherwise.
template <class Writer>
Error_code write_file_atomically(const std::string& filename, Writer&& write)
{
  try
  {
    if(filename.empty()) return ERROR_CANNOT_WRITE_FILE;
    const std::string target = atomic_output_resolve_links(filename);
    struct stat st;
    const bool exists = (::stat(target.c_str(), &st) == 0);
    if(exists && S_ISDIR(st.st_mode)) return ERROR_CANNOT_WRITE_FILE;

    if(exists && !S_ISREG(st.st_mode))
    {
      // a device, a pipe...: written in place (renaming onto it would replace the node)
      Error_code ec = ERROR_CANNOT_WRITE_FILE;
      {
        std::ofstream out(target, std::ios::binary);
        if(!out) return ERROR_CANNOT_WRITE_FILE;
        ec = write(static_cast<std::ostream&>(out));
        out.flush();
        if(ec == OK && !out) ec = ERROR_CANNOT_WRITE_FILE;
        out.close();
        if(ec == OK && out.fail()) ec = ERROR_CANNOT_WRITE_FILE;
      }
      return ec;
    }

    // a regular file or a new name: temporary file, then rename
    const mode_t mode = exists ? (st.st_mode & 07777) : 0666; // new files: 0666 minus the umask, as ofstream
    const std::string temporary = atomic_output_create_temporary(target, mode);
    if(temporary.empty()) return ERROR_CANNOT_WRITE_FILE;
    if(exists) (void)::chmod(temporary.c_str(), mode); // open() applied the umask; keep the old file's mode

    Error_code ec = ERROR_CANNOT_WRITE_FILE;
    try
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if(out)
      {
        ec = write(static_cast<std::ostream&>(out));
        out.flush();
        if(ec == OK && !out) ec = ERROR_CANNOT_WRITE_FILE;
        out.close(); // close() writes what is still buffered: check it too
        if(ec == OK && out.fail()) ec = ERROR_CANNOT_WRITE_FILE;
      }
    }
    catch(...) { ec = ERROR_CANNOT_WRITE_FILE; }

    if(ec == OK && std::rename(temporary.c_str(), target.c_str()) != 0)
      ec = ERROR_CANNOT_WRITE_FILE;
    if(ec != OK)
      std::remove(temporary.c_str());
    return ec;
  }
  catch(...)
  {
    return ERROR_CANNOT_WRITE_FILE;
  }
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_ATOMIC_OUTPUT_H
