// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_TURN_CUTS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_TURN_CUTS_H

// Polygons whose interior angle exceeds 2 pi at some vertices: the border of an immersed disk may wrap
// around one of its vertices more than once (a border vertex of a seamless parametrization cut through
// a cone, for instance). The positions alone give each interior angle only modulo 2 pi; the rotation
// index r_v says how many full turns to add: the angle at v is its angle in (0, 2 pi) (counterclockwise
// from v -> next to v -> prev) plus 2 pi r_v. Such a polygon bounds an immersed disk only if its
// rotation number minus the sum of the r_v is 1.
//
// The search cuts the polygon at a vertex v with r_v > 0 by a chord (v, w): in any triangulation of
// the immersed disk, v has chords (its angle exceeds that of one triangle), and every chord splits the
// triangulation into triangulations of the two sub-polygons, whose angles at v and w are the two parts
// of the original ones, lifted to whole numbers of turns. So trying every chord at v with every lift
// (and every lift at w) and solving both sides recursively is complete; a side without turns goes to
// the ordinary program (CGAL's constrained Delaunay triangulation if simple, else Shor-Van Wyk). The
// candidates are filtered first by exact necessary conditions (the chord is not along an edge at v or
// w and leaves w inside its angle when w has no turn; each side's rotation number minus its turns is 1);
// the cuts that leave fewer turns at v on both sides are tried first, and the pieces found without a
// triangulation are remembered. Exponential in the number of turned vertices in the worst case; the
// caller's time budget bounds it.
//
//   Error_code triangulate_with_turns(Q, r, orient, timer, max_seconds, triangles, st)
//       Q: counterclockwise polygon (no repeated consecutive point, no reversal; checked by the caller),
//       r: rotation index per vertex (>= 0); OK with n - 2 triangles (indices into Q, counterclockwise),
//       ERROR_NOT_SELF_OVERLAPPING, or ERROR_BUDGET_EXHAUSTED.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/polygon_turns.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/shor_van_wyk.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/simple_polygon_cdt.h>

#include <CGAL/Real_timer.h>
#include <CGAL/enum.h>

#include <array>
#include <cstddef>
#include <algorithm>
#include <string>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {
namespace self_overlapping {

template <class Point_2, class Orientation_2>
class Turn_cuts
{
public:
  Turn_cuts(const std::vector<Point_2>& Q, const Orientation_2& orient, const CGAL::Real_timer& timer, double max_seconds)
    : Q_(Q), orient_(orient), timer_(timer), max_seconds_(max_seconds)
  { }

  // the sub-polygon idx (indices into Q, in order) with rotation indices r
  Error_code solve(const std::vector<std::size_t>& idx, const std::vector<int>& r,
                   std::vector<std::array<std::size_t, 3> >& out, Dp_statistics& st)
  {
    if(timer_.time() > max_seconds_) return ERROR_BUDGET_EXHAUSTED;
    const std::size_t m = idx.size();
    if(m < 3) return ERROR_NOT_SELF_OVERLAPPING;
    std::size_t p = m;
    for(std::size_t k = 0; k < m; ++k) if(r[k] > 0) { p = k; break; }
    if(p == m) return solve_plain(idx, out, st);

    // a sub-polygon already found without a triangulation (the cuts of a polygon commute: the same
    // pieces come back in many orders)
    std::string key(reinterpret_cast<const char*>(idx.data()), idx.size() * sizeof(std::size_t));
    key.append(reinterpret_cast<const char*>(r.data()), r.size() * sizeof(int));
    if(failed_.count(key)) return ERROR_NOT_SELF_OVERLAPPING;

    // v at position 0
    std::vector<std::size_t> I(m);
    std::vector<int> R(m);
    for(std::size_t k = 0; k < m; ++k) { I[k] = idx[(p + k) % m]; R[k] = r[(p + k) % m]; }
    const Point_2& a = Q_[I[m - 1]];
    const Point_2& b = Q_[I[0]];
    const Point_2& c = Q_[I[1]];
    const Corner_kind kv = kind(a, b, c);
    struct Cut { std::size_t q; int va, vb, wa, wb; };
    std::vector<Cut> cuts;
    std::vector<int> rho_a(m, 0), rho_b(m, 0);
    std::vector<int> prefix(m + 1, 0); // turns of positions < k
    for(std::size_t k = 0; k < m; ++k) prefix[k + 1] = prefix[k] + R[k];
    for(std::size_t q = 2; q + 1 < m; ++q)
    {
      const Point_2& d = Q_[I[q]];
      // a chord along an edge at v or w leaves a side with an angle of 0 there; a chord opposite to an
      // edge (an angle of pi on one side) is fine
      if(same_point(b, d) || same_direction(b, c, d, orient_) || same_direction(b, a, d, orient_)) continue;
      const Point_2& wp = Q_[I[q - 1]];
      const Point_2& wn = Q_[I[q + 1]];
      if(same_direction(d, wn, b, orient_) || same_direction(d, wp, b, orient_)) continue;
      const bool in_v = in_open_sector(a, b, c, kv, d, orient_);   // chord at v before v -> prev (first turn)
      const bool in_w = in_open_sector(wp, d, wn, kind(wp, d, wn), b, orient_); // at w, from w -> next
      if(R[q] == 0 && !in_w) continue;
      // side A = positions 0..q (closed by w -> v), side B = q..m-1, 0 (closed by v -> w)
      int ra = 0, rb = 0;
      if(!rotation_of_side(I, 0, q, ra) || !rotation_of_side(I, q, m, rb)) continue;
      const int turns_a = prefix[q] - prefix[1], turns_b = prefix[m] - prefix[q + 1]; // strictly inside each side
      for(int lv = 0; lv <= R[0]; ++lv) // v's part in A: angle < 2 pi (lv + 1)
      {
        if(lv == R[0] && !in_v) break;
        const int va = lv, vb = in_v ? R[0] - lv : R[0] - lv - 1;
        for(int lw = 0; lw <= R[q]; ++lw) // w's part in B
        {
          if(lw == R[q] && !in_w) break;
          const int wb = lw, wa = in_w ? R[q] - lw : R[q] - lw - 1;
          if(ra - (turns_a + va + wa) != 1 || rb - (turns_b + vb + wb) != 1) continue;
          cuts.push_back(Cut{ q, va, vb, wa, wb });
        }
      }
    }
    // cuts that leave fewer turns at v on both sides first: they lower the turns of both pieces, so the
    // search goes down in turns rather than chopping one small piece after another
    std::stable_partition(cuts.begin(), cuts.end(), [&](const Cut& x) { return x.va < R[0] && x.vb < R[0]; });
    for(const Cut& cut : cuts)
    {
      const std::size_t q = cut.q;
      std::vector<std::size_t> IA(I.begin(), I.begin() + static_cast<std::ptrdiff_t>(q) + 1);
      std::vector<std::size_t> IB(I.begin() + static_cast<std::ptrdiff_t>(q), I.end());
      IB.push_back(I[0]);
      std::vector<int> RA(R.begin(), R.begin() + static_cast<std::ptrdiff_t>(q) + 1);
      RA.front() = cut.va; RA.back() = cut.wa;
      std::vector<int> RB(R.begin() + static_cast<std::ptrdiff_t>(q), R.end());
      RB.push_back(cut.vb);
      RB.front() = cut.wb;
      // the piece with fewer turns first: the ordinary program fails fast
      const int ta = prefix[q] - prefix[1] + cut.va + cut.wa, tb = prefix[m] - prefix[q + 1] + cut.vb + cut.wb;
      const bool a_first = ta <= tb;
      std::vector<std::array<std::size_t, 3> > TA, TB;
      const Error_code e1 = a_first ? solve(IA, RA, TA, st) : solve(IB, RB, TB, st);
      if(e1 == ERROR_BUDGET_EXHAUSTED) return e1;
      if(e1 != OK) continue;
      const Error_code e2 = a_first ? solve(IB, RB, TB, st) : solve(IA, RA, TA, st);
      if(e2 == ERROR_BUDGET_EXHAUSTED) return e2;
      if(e2 != OK) continue;
      out.insert(out.end(), TA.begin(), TA.end());
      out.insert(out.end(), TB.begin(), TB.end());
      return OK;
    }
    failed_.insert(key);
    return ERROR_NOT_SELF_OVERLAPPING;
  }

private:
  Corner_kind kind(const Point_2& a, const Point_2& b, const Point_2& c) const
  {
    const CGAL::Orientation o = orient_(a, b, c);
    return o == CGAL::LEFT_TURN ? Corner_kind::CONVEX : (o == CGAL::RIGHT_TURN ? Corner_kind::REFLEX : Corner_kind::FLAT);
  }

  // rotation number of the side I[from..to] (to == I.size(): I[from..] then I[0]), closed by its chord
  bool rotation_of_side(const std::vector<std::size_t>& I, std::size_t from, std::size_t to, int& rho) const
  {
    std::vector<std::size_t> side(I.begin() + static_cast<std::ptrdiff_t>(from),
                                  I.begin() + static_cast<std::ptrdiff_t>((std::min)(to + 1, I.size())));
    if(to == I.size()) side.push_back(I[0]);
    return rotation(side, rho);
  }

  // rotation number of the closed sub-polygon; false on a repeated point or a reversal
  bool rotation(const std::vector<std::size_t>& idx, int& rho) const
  {
    const std::size_t m = idx.size();
    rho = 0;
    for(std::size_t k = 0; k < m; ++k)
    {
      const Point_2& a = Q_[idx[(k + m - 1) % m]];
      const Point_2& b = Q_[idx[k]];
      const Point_2& c = Q_[idx[(k + 1) % m]];
      if(same_point(a, b)) return false;
      int cr = 0;
      if(!turn_crossing(a, b, c, orient_, cr)) return false;
      rho += cr;
    }
    return true;
  }

  // no turn: simple polygons by the constrained Delaunay triangulation, the others by Shor-Van Wyk
  Error_code solve_plain(const std::vector<std::size_t>& idx, std::vector<std::array<std::size_t, 3> >& out,
                         Dp_statistics& st)
  {
    int rho = 0;
    if(!rotation(idx, rho) || rho != 1) return ERROR_NOT_SELF_OVERLAPPING;
    std::vector<Point_2> S;
    S.reserve(idx.size());
    for(std::size_t k : idx) S.push_back(Q_[k]);
    std::vector<std::array<std::size_t, 3> > T;
    if(cdt_triangulate_simple_polygon(S, T) != Cdt_result::SIMPLE)
    {
      T.clear();
      Dp_statistics s;
      Shor_van_wyk<Point_2, Orientation_2> dp(S, orient_);
      const Error_code ec = dp.run(timer_, max_seconds_, T, s);
      st.chords_tested += s.chords_tested;
      st.chords_valid += s.chords_valid;
      st.triangles_tested += s.triangles_tested;
      if(ec != OK) return ec;
    }
    for(const auto& t : T) out.push_back(std::array<std::size_t, 3>{{ idx[t[0]], idx[t[1]], idx[t[2]] }});
    return OK;
  }

  const std::vector<Point_2>& Q_;
  Orientation_2 orient_;
  const CGAL::Real_timer& timer_;
  double max_seconds_;
  std::unordered_set<std::string> failed_;
};

} // namespace self_overlapping
} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
