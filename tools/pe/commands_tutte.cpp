// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe tutte`, `pe thingi`, `pe random-init`, and the Tutte step of the other commands: the only
// file that instantiates tutte_embedding() (in double, Gmpq and Gmpfr).

#include "pe.h"

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace pe_tool {

namespace {

typedef CGAL::Simple_cartesian<CGAL::Gmpq>  Exact_kernel;
typedef CGAL::Simple_cartesian<CGAL::Gmpfr> Mpfr_kernel;

template <class FT>
FT ft_from_double(double d)
{
  if constexpr(std::is_same<FT, CGAL::Gmpfr>::value)
    return CGAL::Gmpfr(d, CGAL::Gmpfr::get_default_precision()); // exact: at least 53 bits
  else
    return FT(d);
}

const char* number_type_label(Number_type nt)
{
  return nt == Number_type::DOUBLE ? "Tutte" : (nt == Number_type::EXACT ? "exact Tutte" : "MPFR Tutte");
}

// Tutte in the number type of `Kernel2`; the result, rounded to double, goes to in.uv.
template <class Kernel2>
PE::Error_code tutte_in(Input& in, const Tutte_settings& s, const Budget& budget, PE::Embedding_report& exact_report)
{
  typedef typename Kernel2::FT FT;
  typedef typename Kernel2::Point_2 P2;
  auto uvx = in.mesh.add_property_map<vertex_descriptor, P2>("v:pe_uv_nt", P2(ft_from_double<FT>(0), ft_from_double<FT>(0))).first;
  for(vertex_descriptor v : vertices(in.mesh))
    uvx[v] = P2(ft_from_double<FT>(in.uv[v].x()), ft_from_double<FT>(in.uv[v].y())); // exact copy (fixed border)
  Progress bar(number_type_label(s.number_type), budget.progress());
  // both cores for the exact solve (the same result as the sequential one)
  const PE::Error_code ec = PE::tutte_embedding<CGAL::Parallel_tag>(in.mesh, Mesh::null_halfedge(), uvx,
    PE::parameters::weights(s.weights, PE::parameters::border_shape(s.border,
      CGAL::parameters::callback(bar.callback()).maximum_running_time(budget.remaining()))));
  bar.finish();
  if(ec == PE::OK)
  {
    exact_report = PE::check_embedding(in.mesh, uvx);
    for(vertex_descriptor v : vertices(in.mesh))
      in.uv[v] = Point_2(CGAL::to_double(uvx[v].x()), CGAL::to_double(uvx[v].y()));
  }
  in.mesh.remove_property_map(uvx);
  return ec;
}

} // namespace

int tutte_settings(Run& run, const Input& in, Tutte_settings& s)
{
  const Arguments& a = run.args;
  const std::string border = a.get("--border"), weights = a.get("--weights", "uniform"), nt = a.get("--number-type", "double");
  // the values were checked against the option table
  if(border.empty()) s.border = in.has_uv ? PE::Border_shape::FIXED : PE::Border_shape::CIRCLE;
  else if(border == "fixed") s.border = PE::Border_shape::FIXED;
  else if(border == "circle") s.border = PE::Border_shape::CIRCLE;
  else if(border == "square") s.border = PE::Border_shape::SQUARE;
  else s.border = PE::Border_shape::TRIANGLE;
  s.weights = weights == "mean-value" ? PE::Weights::MEAN_VALUE : PE::Weights::UNIFORM;
  s.number_type = nt == "double" ? Number_type::DOUBLE : (nt == "exact" ? Number_type::EXACT : Number_type::MPFR);
  s.bits = static_cast<unsigned long>(a.count("--number-type", 0));
  if(s.border == PE::Border_shape::FIXED && !in.has_uv)
    return usage("option --border fixed needs an input OBJ with texture coordinates");
  return EXIT_VALID;
}

PE::Error_code run_tutte(Input& in, const Tutte_settings& s, const Budget& budget, PE::Embedding_report& exact_report)
{
  if(s.number_type == Number_type::EXACT) return tutte_in<Exact_kernel>(in, s, budget, exact_report);
  if(s.number_type == Number_type::MPFR)
  {
    CGAL::Gmpfr::set_default_precision(static_cast<CGAL::Gmpfr::Precision_type>(s.bits));
    return tutte_in<Mpfr_kernel>(in, s, budget, exact_report);
  }
  Progress bar(number_type_label(s.number_type), budget.progress());
  return PE::tutte_embedding(in.mesh, Mesh::null_halfedge(), in.uv,
    PE::parameters::weights(s.weights, PE::parameters::border_shape(s.border,
      CGAL::parameters::callback(bar.callback()).maximum_running_time(budget.remaining()))));
}

PE::Error_code thingi_protocol(Input& in, unsigned seed, const Budget& budget)
{
  std::array<vertex_descriptor, 3> pinned;
  const PE::Error_code ec = PE::internal::thingi_cut(in.mesh, seed, pinned);
  if(ec != PE::OK) return ec;
  in.uv[pinned[0]] = Point_2(0, 0);
  in.uv[pinned[1]] = Point_2(0.5, std::sqrt(3.) / 2);
  in.uv[pinned[2]] = Point_2(1, 0);
  Tutte_settings s;
  s.border = PE::Border_shape::FIXED;
  PE::Embedding_report unused;
  return run_tutte(in, s, budget, unused);
}

int cmd_tutte(const Arguments& a)
{
  Run run(a);
  run.summary << "tutte " << a.positional[0] << ": ";
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::OPTIONAL);
  if(status != EXIT_VALID) return status;
  Tutte_settings s;
  status = tutte_settings(run, in, s);
  if(status != EXIT_VALID) return status;
  const std::string nts = a.get("--number-type", "double");
  run.result.add("output", a.positional[1]);
  run.result.add("number_type", nts);
  Budget budget(a);
  PE::Embedding_report exact_report;
  const PE::Error_code ec = run_tutte(in, s, budget, exact_report);
  if(ec != PE::OK)
  {
    run.result.add("faces", count_faces(in.mesh));
    run.result.add("vertices", std::size_t(num_vertices(in.mesh)));
    return run.fail(ec, "tutte failed on '" + in.filename + "'");
  }
  const Map_certificate cert = certify(in);
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary.str("");
  run.summary << "tutte " << in.filename << " (" << nts << ", " << seconds_string(run.timer.seconds()) << "): ";
  if(s.number_type != Number_type::DOUBLE)
  {
    run.result.add("valid_before_rounding", exact_report.is_valid());
    run.result.add("flipped_before_rounding", exact_report.flipped);
    run.result.add("degenerate_before_rounding", exact_report.degenerate);
    run.summary << "before rounding " << (exact_report.is_valid() ? "valid" : "INVALID") << " (flipped " << exact_report.flipped
                << ", degenerate " << exact_report.degenerate << "); written in double: ";
  }
  return write_and_finish(run, in, a.positional[1], cert);
}

int cmd_thingi(const Arguments& a)
{
  Run run(a);
  run.summary << "thingi " << a.positional[0] << ": ";
  unsigned long long seed = 0;
  std::string why;
  if(!parse_count(a.positional[1], 0, std::numeric_limits<unsigned>::max(), seed, why))
    return usage("SEED must be an integer from 0 to " + std::to_string(std::numeric_limits<unsigned>::max()) + ": " + why);
  Input in;
  // the protocol cuts a closed mesh: uv entries of an OBJ are ignored
  int status = read_input(run, a.positional[0], in, Uv_mode::IGNORED, Shape::CLOSED_SPHERE);
  if(status != EXIT_VALID) return status;
  run.result.add("seed", static_cast<std::size_t>(seed));
  run.result.add("output", a.positional[2]);
  run.summary.str("");
  run.summary << "thingi " << in.filename << " seed " << seed << ": ";
  Budget budget(a);
  const PE::Error_code ec = thingi_protocol(in, static_cast<unsigned>(seed), budget);
  if(ec != PE::OK) return run.fail(ec, "thingi failed on '" + in.filename + "'");
  const Map_certificate cert = certify(in);
  const PE::Embedding_report& report = cert.report;
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary << "double Tutte (" << seconds_string(run.timer.seconds()) << "): ";
  Picture picture;
  picture.title = in.filename + " seed " + std::to_string(seed) + ", double Tutte map: " + (report.is_valid() ? "valid" : "INVALID");
  picture.inset = !report.is_valid();
  picture.has_3d_energy = report.has_3d_energy;
  return write_and_finish(run, in, a.positional[2], cert, a.get("--svg"), picture);
}

int cmd_random_init(const Arguments& a)
{
  Run run(a);
  run.summary << "random-init " << a.positional[0] << ": ";
  if(!a.has("--seed")) return usage("random-init needs --seed S");
  const unsigned long long seed = a.count("--seed", 0);
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::OPTIONAL);
  if(status != EXIT_VALID) return status;
  run.result.add("seed", static_cast<std::size_t>(seed));
  run.result.add("output", a.positional[1]);
  // the border: on the unit circle by arc length, placed directly (the interior is drawn at random:
  // a Tutte solve would be thrown away)
  {
    PE::internal::Indexed_disk<Mesh> disk;
    const PE::Error_code ec = PE::internal::make_indexed_disk(in.mesh, Mesh::null_halfedge(), disk);
    if(ec != PE::OK) return run.fail(ec, "random-init failed on '" + in.filename + "'");
    std::vector<Point_2> bpos;
    PE::internal::circle_border<double>(PE::internal::border_arc_length(disk, in.mesh.points()), bpos);
    for(std::size_t k = 0; k < disk.border.size(); ++k) in.uv[disk.vertices[disk.border[k]]] = bpos[k];
  }
  // Interior points uniformly in the disk inscribed in the border polygon: its radius is the
  // smallest distance from the center to a border edge (cos(pi/n) for n evenly spaced vertices;
  // smaller when the arc-length spacing is uneven), shrunk a little against rounding.
  double r_in = 1;
  for(auto h : halfedges(in.mesh))
  {
    if(!is_border(h, in.mesh)) continue;
    const Point_2 p = in.uv[source(h, in.mesh)], q = in.uv[target(h, in.mesh)];
    const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    if(len > 0) r_in = std::min(r_in, std::abs(p.x() * q.y() - p.y() * q.x()) / len);
  }
  r_in *= 1 - 1e-9;
  std::mt19937 gen(static_cast<unsigned>(seed));
  std::uniform_real_distribution<double> unif(-1., 1.);
  for(vertex_descriptor v : vertices(in.mesh))
  {
    if(CGAL::is_border(v, in.mesh)) continue;
    // rejection sampling, accepted with probability pi/4 per draw: 100 draws all fail with
    // probability 1e-67, then the vertex takes the center
    double x = 0, y = 0;
    for(int draw = 0; draw < 100; ++draw)
    {
      const double xd = unif(gen), yd = unif(gen);
      if(xd * xd + yd * yd < 1) { x = xd; y = yd; break; }
    }
    in.uv[v] = Point_2(r_in * x, r_in * y);
  }
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary.str("");
  run.summary << "random-init " << in.filename << " seed " << seed << " (" << seconds_string(run.timer.seconds()) << "): ";
  return write_and_finish(run, in, a.positional[1], certify(in));
}

} // namespace pe_tool
