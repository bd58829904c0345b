// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_ERROR_CODE_H
#define CGAL_PROGRESSIVE_EMBEDDING_ERROR_CODE_H

/// \file Error_code.h

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingEnums
///
/// Status returned by every function of the package. Data-dependent failures are
/// reported with these values, never asserted or thrown.
enum Error_code
{
  OK = 0,                          ///< Success; for embedding functions, the output map is certified valid
  ERROR_EMPTY_MESH,                ///< The input mesh has no face
  ERROR_NON_TRIANGULAR_MESH,       ///< The input mesh has a face that is not a triangle
  ERROR_NON_MANIFOLD,              ///< The input mesh is not a valid manifold polygon mesh
  ERROR_NOT_A_DISK,                ///< The input mesh is not a topological disk (one border cycle, Euler characteristic 1, connected)
  ERROR_BORDER_TOO_SHORT,          ///< The border has fewer vertices than the requested border shape needs
  ERROR_NON_CONVEX_BORDER,         ///< The border polygon is not strictly convex (or winds more than once)
  ERROR_DEGENERATE_BORDER,         ///< The border polygon has (near) zero area, repeated or collinear vertices
  ERROR_NON_FINITE_COORDINATES,    ///< An input coordinate is NaN or infinite
  ERROR_CANNOT_SOLVE_LINEAR_SYSTEM,///< The sparse linear solver failed
  ERROR_INVALID_EMBEDDING,         ///< The computed map failed the exact validity certificate
  ERROR_COLLAPSE_FAILED,           ///< Simplification could not remove every invalid face (e.g. the paper's Fig. 13 configuration)
  ERROR_INSERTION_FAILED,          ///< A vertex could not be re-inserted within the smoothing budget
  ERROR_BUDGET_EXHAUSTED,          ///< An iteration or time budget ran out before the algorithm finished
  ERROR_WRONG_PARAMETER,           ///< A function received an inconsistent parameter
  ERROR_CANNOT_READ_FILE,          ///< A file could not be opened for reading
  ERROR_MALFORMED_FILE,            ///< A file could be opened but its content is malformed
  ERROR_CANNOT_WRITE_FILE,         ///< A file could not be written
  ERROR_CONSTRAINT_OUTSIDE_DOMAIN, ///< A positional constraint lies outside the target domain
  ERROR_NO_FREE_VERTEX,            ///< Every vertex is fixed (border or constraint): there is nothing to optimize
  ERROR_DEGENERATE_3D_FACE,        ///< A 3D face has zero area (or non-finite points): its distortion is undefined
  ERROR_DUPLICATE_CONSTRAINT,      ///< Two positional constraints name the same vertex, or two vertices the same target
  ERROR_CONSTRAINT_ON_BORDER,      ///< A positional constraint names a border vertex (the border is given separately)
  ERROR_NOT_GENUS_ZERO,            ///< The input mesh is not a connected genus-0 surface with at least one border cycle
  ERROR_DEGENERATE_CHORD,          ///< An interior edge joins two border vertices on one straight side of a patch: no valid map keeps it
  ERROR_PATH_TRACING_FAILED,       ///< The patch borders could not be traced on the mesh within the refinement budget
  ERROR_NOT_SELF_OVERLAPPING,      ///< The polygon is neither simple nor weakly self-overlapping: it bounds no immersed disk
  ERROR_LANDMARK_ORDER             ///< Border landmarks come in another cyclic order along one border than along the other: no orientation-preserving bijection matches them
};

/// \ingroup PkgProgressiveEmbeddingEnums
/// returns a human-readable, one-line description of `code`; never a null pointer.
inline const char* get_error_message(Error_code code)
{
  // A switch rather than a table: an entry cannot silently shift (CGAL 5.5.1's SMP table is off by one).
  switch(code)
  {
    case OK: return "Success";
    case ERROR_EMPTY_MESH: return "Input mesh is empty";
    case ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangulated";
    case ERROR_NON_MANIFOLD: return "Input mesh is not a valid manifold polygon mesh";
    case ERROR_NOT_A_DISK: return "Input mesh is not a topological disk";
    case ERROR_BORDER_TOO_SHORT: return "The border has too few vertices for the requested border shape";
    case ERROR_NON_CONVEX_BORDER: return "The border polygon is not strictly convex";
    case ERROR_DEGENERATE_BORDER: return "The border polygon is degenerate (zero area, repeated or collinear vertices)";
    case ERROR_NON_FINITE_COORDINATES: return "A coordinate is NaN or infinite";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "The sparse linear system could not be solved";
    case ERROR_INVALID_EMBEDDING: return "The map failed the exact validity certificate";
    case ERROR_COLLAPSE_FAILED: return "Simplification could not remove every invalid face";
    case ERROR_INSERTION_FAILED: return "A vertex could not be re-inserted within the smoothing budget";
    case ERROR_BUDGET_EXHAUSTED: return "An iteration or time budget was exhausted";
    case ERROR_WRONG_PARAMETER: return "A parameter has an unexpected value";
    case ERROR_CANNOT_READ_FILE: return "The file cannot be opened for reading";
    case ERROR_MALFORMED_FILE: return "The file is malformed";
    case ERROR_CANNOT_WRITE_FILE: return "The file cannot be written";
    case ERROR_CONSTRAINT_OUTSIDE_DOMAIN: return "A positional constraint lies outside the target domain";
    case ERROR_NO_FREE_VERTEX: return "Every vertex is fixed: there is no free vertex to optimize";
    case ERROR_DEGENERATE_3D_FACE: return "A 3D face has zero area or a non-finite point: its distortion is undefined";
    case ERROR_DUPLICATE_CONSTRAINT: return "Two constraints name the same vertex, or two vertices the same target";
    case ERROR_CONSTRAINT_ON_BORDER: return "A positional constraint names a border vertex";
    case ERROR_NOT_GENUS_ZERO: return "Input mesh is not a connected genus-0 surface with a border";
    case ERROR_DEGENERATE_CHORD: return "An interior edge joins two border vertices on one straight side of a patch";
    case ERROR_PATH_TRACING_FAILED: return "The patch borders could not be traced on the mesh within the refinement budget";
    case ERROR_NOT_SELF_OVERLAPPING: return "The polygon is neither simple nor weakly self-overlapping";
    case ERROR_LANDMARK_ORDER: return "The border landmarks come in another order along one border than along the other";
  }
  return "Unknown error";
}

/// \ingroup PkgProgressiveEmbeddingEnums
/// returns the enumerator's name (e.g. `"ERROR_NOT_A_DISK"`), for logs and JSON output.
inline const char* get_error_name(Error_code code)
{
  switch(code)
  {
    case OK: return "OK";
    case ERROR_EMPTY_MESH: return "ERROR_EMPTY_MESH";
    case ERROR_NON_TRIANGULAR_MESH: return "ERROR_NON_TRIANGULAR_MESH";
    case ERROR_NON_MANIFOLD: return "ERROR_NON_MANIFOLD";
    case ERROR_NOT_A_DISK: return "ERROR_NOT_A_DISK";
    case ERROR_BORDER_TOO_SHORT: return "ERROR_BORDER_TOO_SHORT";
    case ERROR_NON_CONVEX_BORDER: return "ERROR_NON_CONVEX_BORDER";
    case ERROR_DEGENERATE_BORDER: return "ERROR_DEGENERATE_BORDER";
    case ERROR_NON_FINITE_COORDINATES: return "ERROR_NON_FINITE_COORDINATES";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM";
    case ERROR_INVALID_EMBEDDING: return "ERROR_INVALID_EMBEDDING";
    case ERROR_COLLAPSE_FAILED: return "ERROR_COLLAPSE_FAILED";
    case ERROR_INSERTION_FAILED: return "ERROR_INSERTION_FAILED";
    case ERROR_BUDGET_EXHAUSTED: return "ERROR_BUDGET_EXHAUSTED";
    case ERROR_WRONG_PARAMETER: return "ERROR_WRONG_PARAMETER";
    case ERROR_CANNOT_READ_FILE: return "ERROR_CANNOT_READ_FILE";
    case ERROR_MALFORMED_FILE: return "ERROR_MALFORMED_FILE";
    case ERROR_CANNOT_WRITE_FILE: return "ERROR_CANNOT_WRITE_FILE";
    case ERROR_CONSTRAINT_OUTSIDE_DOMAIN: return "ERROR_CONSTRAINT_OUTSIDE_DOMAIN";
    case ERROR_NO_FREE_VERTEX: return "ERROR_NO_FREE_VERTEX";
    case ERROR_DEGENERATE_3D_FACE: return "ERROR_DEGENERATE_3D_FACE";
    case ERROR_DUPLICATE_CONSTRAINT: return "ERROR_DUPLICATE_CONSTRAINT";
    case ERROR_CONSTRAINT_ON_BORDER: return "ERROR_CONSTRAINT_ON_BORDER";
    case ERROR_NOT_GENUS_ZERO: return "ERROR_NOT_GENUS_ZERO";
    case ERROR_DEGENERATE_CHORD: return "ERROR_DEGENERATE_CHORD";
    case ERROR_PATH_TRACING_FAILED: return "ERROR_PATH_TRACING_FAILED";
    case ERROR_NOT_SELF_OVERLAPPING: return "ERROR_NOT_SELF_OVERLAPPING";
    case ERROR_LANDMARK_ORDER: return "ERROR_LANDMARK_ORDER";
  }
  return "UNKNOWN";
}

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_ERROR_CODE_H
