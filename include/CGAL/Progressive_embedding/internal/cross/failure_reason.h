// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_FAILURE_REASON_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_FAILURE_REASON_H

// The words for a refusal of cross_parameterization(), shared by its front ends (`pe cross`, the Python
// module): each names the landmark or the mesh its own way (a line of the landmark file, a row of the array)
// and adds these words, so that both say the same thing about the same fault.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// What is wrong with the landmark that `failed_landmark` names, its vertex on the mesh `failed_mesh`: the words that
// follow "the vertex of A" (or "of B"). `closed`: the two meshes are closed (cut between landmarks);
// `border_vertex_pair`: the caller gave one.
inline std::string cross_landmark_fault(Error_code ec, bool closed, bool border_vertex_pair)
{
  switch(ec)
  {
    case ERROR_CONSTRAINT_ON_BORDER:
      return "is on the border, its partner is not (a border landmark needs both on their border)";
    case ERROR_DUPLICATE_CONSTRAINT:
      return border_vertex_pair ? "is used by an earlier landmark, or by the border vertex pair with another partner"
                                : "is used by an earlier landmark";
    case ERROR_BORDER_TOO_SHORT:
      return "leaves too few border vertices of A between it and the border landmark before it (counterclockwise) "
             "for the corners of the square, and no other place holds them: each corner needs a vertex at the same "
             "place along both borders, a border landmark or vertices inside an arc between two border landmarks on "
             "both, and the border landmarks leave fewer than three besides the first corner (move them apart, or give "
             "fewer)";
    case ERROR_LANDMARK_ORDER:
      return "is out of the order of the other border landmarks along B's border";
    case ERROR_WRONG_PARAMETER:
      return "is not a vertex of its mesh";
    case ERROR_NOT_A_DISK:
      if(closed)
        return "is joined to the previous landmark by an edge: a cut along one edge opens nothing (a third landmark, "
               "or two landmarks farther apart, make a cut through an inner vertex)";
      break;
    case ERROR_PATH_TRACING_FAILED:
      if(closed)
        return "cannot be reached from the previous landmark: every edge path to it crosses the cut made so far or "
               "another landmark (the cut joins the landmarks in their order; another order may do)";
      break;
    default:
      break;
  }
  return std::string("is where it failed: ") + get_error_message(ec);
}

// What is wrong with the mesh `failed_mesh` when no landmark is named, beyond the error's own message: for
// `ERROR_NOT_A_DISK` when that mesh is closed and the other is not (`closed_against_disk`), and for
// `ERROR_BORDER_TOO_SHORT` with border landmarks, what the landmarks have to do with it; an empty string when the
// error's own message (get_error_message()) says it all.
inline std::string cross_mesh_fault(Error_code ec, std::size_t border_landmarks, bool closed_against_disk)
{
  if(ec == ERROR_NOT_A_DISK && closed_against_disk)
    return "closed, and the other mesh is not (two disks or two closed genus-0 meshes)";
  if(ec == ERROR_BORDER_TOO_SHORT && border_landmarks > 0)
    return "the border landmarks leave too few border vertices: a border has fewer than four, or the border "
           "landmarks leave fewer than three places for the corners of the square after the first (a border "
           "landmark, or vertices inside an arc between two matched border vertices on both borders; move them apart, "
           "or give fewer)";
  return std::string();
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_FAILURE_REASON_H
