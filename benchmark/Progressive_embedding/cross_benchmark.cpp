// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors
//
// cross_parameterization() under the remeshed-pair protocol (internal/cross/remeshed_pair_protocol.h):
// A a libcgal-demo disk, B its copy remeshed by CGAL's isotropic remeshing (target edge length 1.3
// times the mean), K landmarks (interior vertices of A spread out by farthest-point sampling, each
// matched to the nearest interior vertex of B). Per run: vertices of A and B, vertices added to A's
// copy, seconds (B's map, A's map, location, total), both certificates, landmarks exact, mean and max
// 3D distance between a vertex of A and its image on B relative to A's bounding-box diagonal (also split: at the
// landmarks, on the border, inside); the compatible
// meshes (the certified overlay of the two maps): their vertices, certificate and seconds (in the total).
//
//   cross_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--counts 5,20,50] [--pairs A1:B1,A2:B2]
//                   [--composed on|off|both] [--matched on|off|both]
//
// --composed: A's map optimized for the composed map's distortion (named parameter composed_distortion; on by
// default) or not; `both` runs every case without it, then with it (side by side in the tables). --matched: B's map
// made again with B's landmarks pinned, as A's is (named parameter matched_maps; on by default), or not; likewise.
//
// With --pairs, A and B are two given files (e.g. two resolutions of one surface: the true image of a vertex of
// A is then its own position, up to the distance between the two discretizations) instead of a mesh and its
// remeshed copy; K = 0 gives the map without landmarks (the borders matched by relative arc length only).
//
// Writes OUT_PREFIX.csv (one row per run) and OUT_PREFIX.md (the same as a table).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Progressive_embedding/cross_parameterization.h>
#include <CGAL/Progressive_embedding/internal/cross/remeshed_pair_protocol.h>

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <array>
#include <utility>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                        SM;

namespace {

struct Row
{
  std::string mesh;
  bool composed = true, matched = true, matched_b = false;
  std::size_t added_b = 0;
  std::size_t count = 0, landmarks = 0, va = 0, vb = 0, added = 0, vc = 0;
  std::string status;
  bool valid_a = false, valid_b = false, exact = false, valid_c = false;
  // the mean error split: at A's landmark vertices, at A's border vertices, at the other vertices (what the
  // landmarks and the border rule cannot fix: a landmark pair of two discretizations is apart by the distance between
  // the two vertices, and the border is matched by relative arc length, not by position)
  double error_landmarks = -1, error_border = 0, error_inside = 0;
  double mean_error = 0, max_error = 0, t_b = 0, t_a = 0, t_composed = 0, t_location = 0, t_compatible = 0, t_total = 0;
};

std::vector<std::string> split(const std::string& s, char separator = ',')
{
  std::vector<std::string> r;
  std::stringstream ss(s);
  for(std::string t; std::getline(ss, t, separator); ) if(!t.empty()) r.push_back(t);
  return r;
}

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// `file_b` empty: B is A remeshed
Row run(const std::string& file_a, const std::string& file_b, const std::string& name, std::size_t count, bool composed,
        bool matched)
{
  Row r;
  r.mesh = name;
  r.count = count;
  r.composed = composed;
  r.matched = matched;
  SM a, b;
  if(!CGAL::IO::read_polygon_mesh(file_a, a) || !CGAL::IO::read_polygon_mesh(file_b.empty() ? file_a : file_b, b))
  {
    r.status = "unreadable";
    return r;
  }
  if(file_b.empty())
  {
    PE::internal::remesh_isotropically(b);
    b.collect_garbage();
  }
  // the landmarks spread over the coarser mesh, each matched to the nearest vertex of the finer one (the other
  // way round, a landmark would be moved by up to half an edge of the coarser mesh)
  std::vector<std::pair<SM::Vertex_index, SM::Vertex_index> > landmarks;
  if(b.number_of_vertices() < a.number_of_vertices())
  {
    for(const auto& p : PE::internal::nearest_vertex_landmarks(b, a, PE::internal::spread_interior_vertices(b, count)))
      landmarks.emplace_back(p.second, p.first);
  }
  else landmarks = PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, count));
  r.landmarks = landmarks.size();
  SM::Property_map<SM::Vertex_index, PE::Cross_location<SM> > loc =
    a.add_property_map<SM::Vertex_index, PE::Cross_location<SM> >("v:cross").first;
  PE::Cross_parameterization_statistics st;
  SM compatible_a, compatible_b;
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, loc,
    PE::parameters::compatible_meshes(std::make_pair(&compatible_a, &compatible_b),
      PE::parameters::composed_distortion(composed, PE::parameters::matched_maps(matched, PE::parameters::statistics(&st)))));
  r.status = PE::get_error_name(ec);
  r.va = st.vertices_a;
  r.vb = st.vertices_b;
  r.added = st.vertices_added_a;
  r.matched_b = st.matched_b;
  r.added_b = st.vertices_added_b;
  r.valid_a = st.report_a.is_valid();
  r.valid_b = st.report_b.is_valid();
  r.exact = st.landmarks_exact;
  r.t_b = st.seconds_map_b;
  r.t_a = st.seconds_map_a;
  r.t_composed = st.seconds_composed;
  r.t_location = st.seconds_location;
  r.vc = st.compatible_vertices;
  r.valid_c = st.report_compatible.is_valid();
  r.t_compatible = st.seconds_compatible;
  r.t_total = st.seconds_total;
  if(ec != PE::OK) return r;
  // one pass of the AABB tree: the mean and max are taken from the same per-vertex errors as the split
  const std::vector<double> errors = PE::internal::correspondence_errors(a, b, loc);
  std::vector<char> landmark(a.num_vertices(), 0);
  for(const auto& p : landmarks) landmark[std::size_t(p.first)] = 1;
  std::array<double, 3> sum = {{ 0, 0, 0 }};
  std::array<std::size_t, 3> n = {{ 0, 0, 0 }};
  std::size_t i = 0;
  for(SM::Vertex_index v : vertices(a))
  {
    const double e = errors[i++];
    const int c = landmark[std::size_t(v)] ? 0 : CGAL::is_border(v, a) ? 1 : 2;
    sum[c] += e;
    ++n[c];
    r.max_error = (std::max)(r.max_error, e);
  }
  if(!errors.empty()) r.mean_error = (sum[0] + sum[1] + sum[2]) / double(errors.size());
  if(n[0] != 0) r.error_landmarks = sum[0] / double(n[0]);
  if(n[1] != 0) r.error_border = sum[1] / double(n[1]);
  if(n[2] != 0) r.error_inside = sum[2] / double(n[2]);
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: cross_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--counts 5,20,50] [--pairs A:B,...]"
                 " [--composed on|off|both] [--matched on|off|both]\n";
    return 2;
  }
  const std::string dir = argv[1], out = argv[2];
  std::vector<std::string> meshes = { "mushroom.off", "lion-head.off" };
  std::vector<std::size_t> counts = { 5, 20, 50 };
  std::vector<std::pair<std::string, std::string> > pairs;
  std::vector<bool> composed = { true }, matched = { true };
  for(int i = 3; i + 1 < argc; i += 2)
  {
    const std::string o = argv[i], v = argv[i + 1];
    if(o == "--meshes") meshes = split(v);
    else if(o == "--counts") { counts.clear(); for(const std::string& c : split(v)) counts.push_back(std::stoul(c)); }
    else if(o == "--pairs")
    {
      for(const std::string& p : split(v))
      {
        const std::vector<std::string> ab = split(p, ':');
        if(ab.size() != 2) { std::cerr << "--pairs: expected A:B, got " << p << "\n"; return 2; }
        pairs.emplace_back(ab[0], ab[1]);
      }
      meshes.clear();
    }
    else if(o == "--composed")
    {
      if(v == "on") composed = { true };
      else if(v == "off") composed = { false };
      else if(v == "both") composed = { false, true };
      else { std::cerr << "--composed: expected on, off or both, got " << v << "\n"; return 2; }
    }
    else if(o == "--matched")
    {
      if(v == "on") matched = { true };
      else if(v == "off") matched = { false };
      else if(v == "both") matched = { false, true };
      else { std::cerr << "--matched: expected on, off or both, got " << v << "\n"; return 2; }
    }
    else { std::cerr << "unknown option " << o << "\n"; return 2; }
  }
  std::vector<std::array<std::string, 3> > jobs; // A file, B file (empty: A remeshed), name
  for(const std::string& m : meshes) jobs.push_back({{ dir + "/meshes/" + m, std::string(), m }});
  for(const auto& p : pairs) jobs.push_back({{ p.first, p.second, base_name(p.first) + " -> " + base_name(p.second) }});
  std::vector<Row> rows;
  for(const auto& job : jobs)
    for(std::size_t k : counts)
      for(bool mt : matched)
      for(bool c : composed)
      {
        const std::string& m = job[2];
        rows.push_back(run(job[0], job[1], m, k, c, mt));
        const Row& r = rows.back();
        std::cout << m << " K=" << k << (mt ? " matched" : "") << (c ? " composed" : "") << ": " << r.status << ", mean error " << r.mean_error
                  << ", max " << r.max_error << ", added " << r.added << ", compatible " << r.vc
                  << " vertices (" << r.t_compatible << " s), " << r.t_total << " s" << std::endl;
      }

  std::ofstream csv(out + ".csv");
  csv << "mesh,landmarks_requested,landmarks,matched_maps,matched_b,vertices_added_b,composed_distortion,vertices_a,vertices_b,vertices_added_a,status,valid_a,valid_b,"
         "landmarks_exact,mean_error,max_error,mean_error_landmarks,mean_error_border,mean_error_inside,seconds_map_b,seconds_map_a,seconds_composed,seconds_location,"
         "compatible_vertices,compatible_certified,seconds_compatible,seconds_total\n";
  csv << std::setprecision(6);
  for(const Row& r : rows)
  {
    csv << r.mesh << ',' << r.count << ',' << r.landmarks << ',' << r.matched << ',' << r.matched_b << ',' << r.added_b << ','
        << r.composed << ',' << r.va << ',' << r.vb << ',' << r.added << ','
        << r.status << ',' << r.valid_a << ',' << r.valid_b << ',' << r.exact << ',' << r.mean_error << ','
        << r.max_error << ',';
    if(r.error_landmarks >= 0) csv << r.error_landmarks; // empty without landmarks
    csv << ',' << r.error_border << ',' << r.error_inside << ','
        << r.t_b << ',' << r.t_a << ',' << r.t_composed << ',' << r.t_location << ',' << r.vc << ',' << r.valid_c << ','
        << r.t_compatible << ',' << r.t_total << '\n';
  }

  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::ofstream md(out + ".md");
  md << std::setprecision(3)
     << (pairs.empty() ? "# cross_parameterization(): libcgal-demo disks against their remeshed copies\n\n"
                       : "# cross_parameterization(): pairs of meshes of one surface\n\n")
     << "Generated " << date << " by `cross_benchmark` (" << sysconf(_SC_NPROCESSORS_ONLN) << " cores). "
     << (pairs.empty() ? "A: the mesh as it is; B: its copy remeshed by CGAL's isotropic remeshing (target edge length "
                         "1.3 times the mean edge length, 3 iterations). "
                       : "A and B: two given meshes of one surface (command line below). ")
     << "K landmarks: interior vertices of the coarser mesh spread out by farthest-point "
        "sampling, each matched to the nearest interior vertex of the other. Error: the 3D distance between the point "
        "of B at the location of a vertex of A and the point of B nearest to that vertex, relative to the diagonal of "
        "A's bounding box. Vertices added: Steiner vertices of A's "
        "refined copy (A itself is not changed). Compatible meshes: the overlay of the two maps triangulated "
        "(`compatible_meshes`), certified in exact coordinates (filtered exact predicates: a triangulated disk, every "
        "triangle and the border counterclockwise, the border simple); its seconds are part of the total. K = 0: no landmark, the borders matched by "
        "relative arc length only. Composed: A's map optimized once more for the distortion of the composed map "
        "(`composed_distortion`, the default); its seconds (composed s) are part of A's map's. Matched: B's map made "
        "again by `constrained_embedding()` with B's landmarks pinned where its first map put them, as A's is "
        "(`matched_maps`, the default; with landmarks only; its seconds are part of B's map's); vertices added to "
        "B: Steiner vertices left in B's copy (B's map is then on that refined copy). "
        "The mean error is also given "
        "at A's landmark vertices (each lands on its partner, a vertex of the other discretization, so its error is "
        "about the distance between the two: the landmarks cannot bring the error below it), at A's other border "
        "vertices (placed by relative arc length, not by position) and at the other vertices.\n\n"
     << "| mesh | K | matched | vertices added to B | composed | vertices A | vertices B | status | both maps certified | landmarks exact | vertices added to A "
        "| mean error | max error | mean error at landmarks | mean error on the border | mean error inside | B's map s "
        "| A's map s | composed s | location s | compatible vertices | compatible certified "
        "| compatible s | total s |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& r : rows)
  {
    md << "| " << r.mesh << " | " << r.landmarks << " | " << (r.matched_b ? "yes" : r.matched && r.landmarks > 0 ? "failed" : "no")
       << " | " << r.added_b << " | " << (r.composed ? "yes" : "no") << " | " << r.va << " | " << r.vb << " | " << r.status << " | "
       << (r.valid_a && r.valid_b ? "yes" : "no") << " | " << (r.exact ? "yes" : "no") << " | " << r.added << " | "
       << r.mean_error << " | " << r.max_error << " | ";
    if(r.error_landmarks < 0) md << "-";
    else md << r.error_landmarks;
    md << " | " << r.error_border << " | " << r.error_inside << " | " << r.t_b << " | " << r.t_a << " | " << r.t_composed << " | " << r.t_location
       << " | "
       << r.vc << " | " << (r.valid_c ? "yes" : "no") << " | " << r.t_compatible << " | " << r.t_total << " |\n";
  }
  std::string command = "cross_benchmark";
  for(int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  md << "\nMachine: " << host << ". Command: `" << command << "`.\n";
  return 0;
}
