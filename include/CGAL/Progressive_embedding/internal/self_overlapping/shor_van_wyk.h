// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_SHOR_VAN_WYK_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_SHOR_VAN_WYK_H

// The Shor-Van Wyk dynamic program: is a counterclockwise closed polygon the border of an immersed
// disk, and if so a triangulation of that disk with the polygon's vertices only.
//
// A triangulation of the abstract n-gon (indices 0..n-1 in border order) is the border of an immersed
// disk iff every triangle is strictly positive and, at every vertex v, the fan of its triangles turns
// monotonically inside v's angle: each diagonal leaves v strictly inside v's open sector, and at a
// reflex vertex no triangle's corner wraps past the first edge direction (internal/self_overlapping/
// polygon_turns.h). Then the fan at v covers exactly v's angle, the map is a local homeomorphism on the
// closed disk; conversely every immersed disk has such a triangulation (Shor and Van Wyk 1992).
//
// T(i, j), i < j, says that the sub-polygon i, i+1, ..., j closed by the chord (j, i) has such a
// triangulation in which (i, j) is a valid chord. T(i, i+1) holds (an edge); for j > i+1,
// T(i, j) = OR over i < k < j of T(i, k) and T(k, j) and triangle (i, k, j) valid. The answer is
// T(0, n-1), (0, n-1) being the closing edge.
//
// Pruning, exact and only by necessary conditions (so no valid triangulation is lost):
//  - a chord must leave both ends strictly inside their sectors;
//  - the sub-polygon i..j must have rotation number exactly 1 (the border of an immersed disk): the
//    signed crossings of the +x direction, prefix-summed along the polygon, give it in O(1) per chord.
// What is stored: for each j the list of k < j with T(k, j) (32-bit indices; one word per chord found
// valid), and for the current i a byte row T(i, .), reused. The split vertex is not stored: the
// reconstruction finds it again (n - 2 searches). No recursion anywhere.
//
// Order: i from n-2 down to 0, j from i+2 up: T(i, k) (same i, k < j) and T(k, j) (k > i) are known.
// For T(i, j) the candidates k are read from the list of j (all > i, in insertion order, so the edge
// (j-1, j) first) and kept when the row byte T(i, k) is set: the work is the candidate count, not n.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/polygon_turns.h>

#include <CGAL/Real_timer.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {
namespace self_overlapping {

// What the dynamic program did (for reports and benchmarks).
struct Dp_statistics
{
  std::size_t chords_tested = 0;  // chords (i, j) that passed the sector and rotation tests
  std::size_t chords_valid = 0;   // entries T(i, j) found true, edges included (the stored words)
  std::size_t triangles_tested = 0;
};

template <class Point_2, class Orientation_2>
class Shor_van_wyk
{
public:
  // P: counterclockwise (rotation number +1), no repeated consecutive point, no reversal (spike);
  // the caller checks these (triangulate_self_overlapping_polygon_2 does).
  Shor_van_wyk(const std::vector<Point_2>& P, const Orientation_2& orient)
    : P_(P), orient_(orient), n_(P.size())
  { }

  // OK with `triangles` filled (n - 2 index triples, counterclockwise), ERROR_NOT_SELF_OVERLAPPING,
  // or ERROR_BUDGET_EXHAUSTED when `timer` passes `max_seconds`.
  Error_code run(const CGAL::Real_timer& timer, double max_seconds, std::vector<std::array<std::size_t, 3> >& triangles,
                 Dp_statistics& st)
  {
    st = Dp_statistics();
    triangles.clear();
    const std::size_t n = n_;
    if(n < 3) return ERROR_NOT_SELF_OVERLAPPING;
    if(n > std::size_t((std::numeric_limits<std::uint32_t>::max)())) return ERROR_WRONG_PARAMETER;
    if(!prepare()) return ERROR_NOT_SELF_OVERLAPPING;

    col_.assign(n, std::vector<std::uint32_t>());
    std::vector<unsigned char> row(n, 0);
    std::vector<std::uint32_t> row_set; // the set bytes of `row`, to clear them
    std::size_t steps = 0;
    bool found = false;
    for(std::size_t ii = n - 1; ii-- > 0 && !found; ) // i = n-2 .. 0
    {
      const std::size_t i = ii;
      if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
      for(std::uint32_t k : row_set) row[k] = 0;
      row_set.clear();
      // the edge (i, i+1)
      row[i + 1] = 1; row_set.push_back(std::uint32_t(i + 1));
      col_[i + 1].push_back(std::uint32_t(i));
      ++st.chords_valid;
      for(std::size_t j = i + 2; j < n; ++j)
      {
        const bool closing = (i == 0 && j == n - 1);
        if(!closing && !chord_ok(i, j)) continue;
        ++st.chords_tested;
        bool ok = false;
        for(std::uint32_t k : col_[j]) // every k here is > i
        {
          if(++steps == (std::size_t(1) << 20)) // bound the time between two timer reads
          {
            steps = 0;
            if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
          }
          if(!row[k]) continue;
          ++st.triangles_tested;
          if(triangle_ok(i, k, j)) { ok = true; break; }
        }
        if(!ok) continue;
        row[j] = 1; row_set.push_back(std::uint32_t(j));
        col_[j].push_back(std::uint32_t(i));
        ++st.chords_valid;
        if(closing) found = true;
      }
    }
    if(!found) { release(); return ERROR_NOT_SELF_OVERLAPPING; }
    const Error_code ec = reconstruct(triangles);
    release();
    return ec;
  }

private:
  std::size_t next(std::size_t v) const { return v + 1 == n_ ? 0 : v + 1; }
  std::size_t prev(std::size_t v) const { return v == 0 ? n_ - 1 : v - 1; }

  bool prepare()
  {
    const std::size_t n = n_;
    kind_.assign(n, Corner_kind::CONVEX);
    prefix_.assign(n, 0);
    for(std::size_t v = 0; v < n; ++v)
    {
      const Point_2& a = P_[prev(v)];
      const Point_2& b = P_[v];
      const Point_2& c = P_[next(v)];
      if(same_point(a, b)) return false;
      int cr = 0;
      if(!turn_crossing(a, b, c, orient_, cr)) return false;
      const CGAL::Orientation o = orient_(a, b, c);
      kind_[v] = (o == CGAL::LEFT_TURN) ? Corner_kind::CONVEX : (o == CGAL::RIGHT_TURN ? Corner_kind::REFLEX : Corner_kind::FLAT);
      if(v >= 1 && v + 1 < n) prefix_[v] = prefix_[v - 1] + cr; // crossings at vertices 1..v
    }
    return true;
  }

  // the chord (i, j), i + 2 <= j, leaves both ends inside their sectors and closes the sub-polygon
  // i..j into a curve of rotation number 1
  bool chord_ok(std::size_t i, std::size_t j) const
  {
    const Point_2& pi = P_[i];
    const Point_2& pj = P_[j];
    if(!in_open_sector(P_[prev(i)], pi, P_[i + 1], kind_[i], pj, orient_)) return false;
    if(!in_open_sector(P_[j - 1], pj, P_[next(j)], kind_[j], pi, orient_)) return false;
    int cj = 0, ci = 0;
    if(!turn_crossing(P_[j - 1], pj, pi, orient_, cj)) return false;
    if(!turn_crossing(pj, pi, P_[i + 1], orient_, ci)) return false;
    return prefix_[j - 1] - prefix_[i] + cj + ci == 1;
  }

  // triangle (a, b, c), a < b < c, strictly positive and no fan wrapping at its reflex corners
  bool triangle_ok(std::size_t a, std::size_t b, std::size_t c) const
  {
    const Point_2& pa = P_[a];
    const Point_2& pb = P_[b];
    const Point_2& pc = P_[c];
    if(orient_(pa, pb, pc) != CGAL::LEFT_TURN) return false;
    // fan order: around a, b before c; around b, c before a; around c, a before b
    if(kind_[a] == Corner_kind::REFLEX && fan_wraps(pa, P_[next(a)], pb, pc, orient_)) return false;
    if(kind_[b] == Corner_kind::REFLEX && fan_wraps(pb, P_[next(b)], pc, pa, orient_)) return false;
    if(kind_[c] == Corner_kind::REFLEX && fan_wraps(pc, P_[next(c)], pa, pb, orient_)) return false;
    return true;
  }

  // T(i, k): i in the list of k (sorted decreasingly: filled while i decreases)
  bool has(std::size_t i, std::size_t k) const
  {
    const std::vector<std::uint32_t>& c = col_[k];
    return std::binary_search(c.begin(), c.end(), std::uint32_t(i), std::greater<std::uint32_t>());
  }

  Error_code reconstruct(std::vector<std::array<std::size_t, 3> >& triangles) const
  {
    std::vector<std::pair<std::size_t, std::size_t> > todo; // explicit stack: no recursion
    todo.push_back(std::make_pair(std::size_t(0), n_ - 1));
    triangles.reserve(n_ - 2);
    while(!todo.empty() && triangles.size() < n_ - 2) // at most n - 2 pops
    {
      const std::size_t i = todo.back().first, j = todo.back().second;
      todo.pop_back();
      std::size_t split = n_;
      for(std::uint32_t k : col_[j]) // decreasing: the k > i come first
      {
        if(k <= i) break;
        if(has(i, k) && triangle_ok(i, k, j)) { split = k; break; }
      }
      if(split == n_) return ERROR_NOT_SELF_OVERLAPPING; // cannot happen: T(i, j) was set this way
      triangles.push_back(std::array<std::size_t, 3>{{ i, split, j }});
      if(split >= i + 2) todo.push_back(std::make_pair(i, split));
      if(j >= split + 2) todo.push_back(std::make_pair(split, j));
    }
    if(triangles.size() != n_ - 2 || !todo.empty()) return ERROR_NOT_SELF_OVERLAPPING;
    return OK;
  }

  void release()
  {
    std::vector<std::vector<std::uint32_t> >().swap(col_);
  }

  const std::vector<Point_2>& P_;
  Orientation_2 orient_;
  std::size_t n_;
  std::vector<Corner_kind> kind_;
  std::vector<int> prefix_;
  std::vector<std::vector<std::uint32_t> > col_;
};

} // namespace self_overlapping
} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
