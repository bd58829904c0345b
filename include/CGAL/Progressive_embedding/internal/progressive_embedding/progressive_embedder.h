// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDER_H

// Progressive embedding on an indexed disk whose border is a counterclockwise convex polygon:
// builds the working mesh, runs the collapse stage (collapse.h) and the insertion stage
// (insertion.h, with the local smoothing of local_smoothing.h), and restarts with a higher
// area floor when an insertion fails in floating point.

#include <CGAL/Progressive_embedding/internal/progressive_embedding/working_mesh.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding/collapse.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding/insertion.h>

#include <CGAL/Real_timer.h>

#include <functional>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class Traits>
class Progressive_embedder
{
public:
  typedef typename Traits::FT                                  FT;
  typedef typename Traits::Point_2                             Point_2;
  typedef Working_mesh<Traits>                                 WMesh;
  typedef typename WMesh::vertex_descriptor                    vertex_descriptor;
  typedef Collapse_record<vertex_descriptor>                   Record;

  struct Options
  {
    double energy_threshold = 1e20;
    Insertion_options insertion;
    std::size_t expansion_budget = std::size_t(-1);
    double time_budget = std::numeric_limits<double>::infinity();
    bool verbose = false;
    std::function<bool(double)> callback;
    int restarts = 8;
    double initial_min_area_ratio = 1e-12;
    bool min_area_ratio_given = false;
  };

private:
  Traits traits;
  Options opt;
  WMesh wm;
  Validity_criteria<Traits> validity;
  std::vector<Record> history;
  CGAL::Real_timer timer;

public:
  Embedder_counters counters;

  Progressive_embedder(const Traits& traits, const Options& opt) : traits(traits), opt(opt)
  {
    validity.orient = traits.exact_orientation_2_object();
    validity.energy_threshold = opt.energy_threshold;
  }

  // the working mesh (after run(): the input connectivity again, see Working_mesh::input_faces())
  const WMesh& working_mesh() const { return wm; }

  // positions: by input index (in: the map to repair; out: the repaired map on OK); faces: input
  // faces; on_border: per input index; border_area: the area inside the border polygon.
  // When an insertion fails in floating point (the map has clusters of valid faces too
  // small for the precision left), the run restarts from the input with a higher area floor
  // (10^4 times, then from 1e-4 of the mean area 10 times: 1e-3 to 0.1), so that those clusters
  // are collapsed too (at most `restarts` times). The last floors matter for patches only a few
  // hundred ulps wide, whose faces are a few ulps^2 even where valid.
  template <class Face_range>
  Error_code run(std::vector<Point_2>& positions, const Face_range& faces, const std::vector<char>& on_border,
                 const FT& border_area)
  {
    timer.reset();
    timer.start();
    Error_code ec = ERROR_INSERTION_FAILED;
    // In floating point, faces below 1e-12 x the mean area leave too few bits for the
    // insertions around them: they are collapsed from the start (exact types: never).
    double min_area_ratio = (Traits::has_exact_constructions && !opt.min_area_ratio_given) ? 0 : opt.initial_min_area_ratio;
    for(int attempt = 0; attempt <= opt.restarts; ++attempt)
    {
      ec = run_once(positions, faces, on_border, border_area, min_area_ratio);
      if(ec != ERROR_INSERTION_FAILED) break;
      min_area_ratio = (min_area_ratio == 0) ? 1e-16 : min_area_ratio * (min_area_ratio < 1e-5 ? 1e4 : 10);
      if(min_area_ratio > 0.5) break;
      ++counters.restarts;
      if(opt.verbose) std::cerr << "[pe] restart: faces of area below " << min_area_ratio << " x mean are collapsed too\n";
    }
    return ec;
  }

private:
  bool over_time() const { return timer.time() > opt.time_budget; }

  template <class Face_range>
  Error_code run_once(std::vector<Point_2>& positions, const Face_range& faces, const std::vector<char>& on_border,
                      const FT& border_area, double min_area_ratio)
  {
    history.clear();
    const std::size_t restarts = counters.restarts;
    counters = Embedder_counters();
    counters.restarts = restarts;
    Error_code ec = wm.build(positions, faces, on_border);
    if(ec != OK) return ec;

    const FT mean_area = border_area / FT(double(faces.size()));
    validity.use_min_area = min_area_ratio > 0;
    validity.min_face_area = mean_area * make_ft<FT>(min_area_ratio);
    validity.set_mean_area(mean_area);
    auto out_of_time = [this]() { return over_time(); };

    const double t0 = timer.time();
    {
      Collapse_stage<Traits> collapse(wm, validity, counters, opt.expansion_budget, out_of_time, opt.verbose);
      ec = collapse.run(history);
    }
    counters.seconds_collapse = timer.time() - t0;
    if(ec != OK) return ec;

    const double t1 = timer.time();
    {
      Insertion_stage<Traits> insertion(wm, traits, validity, counters, opt.insertion, out_of_time, opt.callback, opt.verbose);
      ec = insertion.run(history, border_area);
    }
    counters.seconds_insertion = timer.time() - t1;
    if(ec != OK) return ec;

    wm.write_positions(positions);
    return OK;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDER_H
