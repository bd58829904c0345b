// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_READ_RESULT_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_READ_RESULT_H

/// \file Read_result.h
/// The outcome of every reader of the package.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

/// \ingroup PkgProgressiveEmbeddingIO
///
/// The outcome of `read_polygon_mesh()` and `read_OBJ_with_uv()`: a status, and where and why
/// reading failed.
struct Read_result
{
  /// `OK`, or the reason of the failure
  Error_code status = OK;
  /// the 1-based number of the offending line; 0 on success, when the error concerns no
  /// line (`ERROR_EMPTY_MESH`, `ERROR_CANNOT_READ_FILE`), or in a binary file (the message
  /// then gives the byte offset)
  std::size_t line = 0;
  /// a human-readable explanation; empty on success
  std::string message;
  /// the number of vertex entries read (`v` lines of an OBJ file, vertices of OFF and PLY files,
  /// distinct corner points of an STL file), unreferenced ones included
  std::size_t number_of_positions = 0;
  /// the number of `vt` lines read (OBJ files; 0 for the other formats)
  std::size_t number_of_texture_coordinates = 0;
  /// the number of faces read
  std::size_t number_of_faces = 0;
  /// the number of vertex entries that no face uses, and that are therefore not vertices of the mesh
  /// (for `read_OBJ_with_uv()`, the unused `vt` entries)
  std::size_t number_of_unreferenced_vertices = 0;
  /// `true` if `read_polygon_mesh()` reversed some faces to orient the mesh consistently
  bool reoriented = false;

  /// returns `true` if and only if `status == OK`
  explicit operator bool() const { return status == OK; }
};

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_READ_RESULT_H
