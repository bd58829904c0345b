// Comparison study driver (run_study.py drives it; ctest runs its --quick mode): on the same
// inputs and in one run, CGAL 5.5's Surface_mesh_parameterization
// (Barycentric_mapping_parameterizer_3 and Mean_value_coordinates_parameterizer_3, default
// solver, through SMP::parameterize), our tutte_embedding in double / MPFR / exact Gmpq,
// progressive_embedding (double and MPFR) and Progressive_embedding_parameterizer_3. Every output
// map is certified with check_embedding.
//
// Inputs (the OFF meshes of DATA_DIR/meshes, the libcgal-demo data):
//   corpus : every closed genus-0 mesh x seeds, Tutte-failure protocol (thingi_cut: one face,
//            chosen by the seed, removed; its vertices pinned to (0,0), (1/2, sqrt(3)/2), (1,0));
//   disk   : every disk of DATA_DIR/meshes, border on the unit circle (3D arc length), and the
//            random-init protocol as the input of progressive_embedding.
// Every method gets the same fixed border: CGAL's parameterizers through a border parameterizer
// that writes the protocol's positions (Fixed_positions_border_parameterizer_3 below).
//
// Each run is executed in a forked child: a per-run time budget (SIGALRM), an isolated
// peak-memory measurement (getrusage after resetting the high-water mark) and no state shared
// between runs. Writes OUT/study_runs.csv (one row per run), OUT/study_meta.txt (machine, date,
// command), and the before/after uv SVG gallery of the worst corpus runs with its index
// OUT/study_gallery.csv (run_study.py renders the SVGs to PNG and compresses the CSV).
//
//   comparison_study DATA_DIR OUT_DIR [options]
//     --quick                 a handful of inputs (bull.off seeds 0 and 1, dino.off seeds 0 and 8, 2 disks)
//     --seeds A-B             corpus seeds (default 0-40)
//     --meshes a.off,b.off    restrict the meshes (corpus and disks)
//     --no-corpus / --no-disks
//     --budget S              time budget of one run, seconds (default 150)
//     --methods a,b           run only these methods (cgal_barycentric, cgal_mvc, tutte_double, tutte_mpfr128,
//                             tutte_mpfr256, tutte_gmpq, pe_double, pe_mpfr128, pe_mpfr256, pe_parameterizer)
//     --mpfr-max-vertices N   no MPFR Tutte above N vertices (default 25000)
//     --mpfr-all-seeds-max-vertices N   MPFR Tutte at every seed up to N vertices (default 500) ...
//     --mpfr-sweep-max-vertices N       ... at seed 0 and every failing run up to N (default 10000),
//                                       at the first failing run of each mesh above
//     --mpfr-pe-max-vertices N  MPFR progressive embedding (every disk, the first failing run of each
//                             closed mesh) up to N vertices (default 10000)
//     --mpfr-pe-bits a,b      precisions of MPFR progressive embedding (default 128,256)
//     --gmpq-max-interior N   exact Gmpq Tutte only up to N interior vertices (default 1500) ...
//     --gmpq-all-seeds-max-interior N   ... at every seed up to N (default 400), seed 0 only above
//     --gmpq-budget S         time budget of one Gmpq run (default 180)
//     --gallery N             SVG pictures (Tutte map, repaired map) of the N worst corpus runs (default 5)
//     --gallery-runs m:s,...  only the gallery, of these corpus runs (mesh:seed, worst first): no study
//                             run, study_runs.csv and study_meta.txt are left as they are
//     --command "..."         the command that launched the study, recorded in the outputs
//     --list                  print the classification of the meshes and exit

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Real_timer.h>
#include <CGAL/version.h>

#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_parameterizer_3.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>

#include <Eigen/Core>

#include <sys/resource.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <dirent.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Simple_cartesian<CGAL::Gmpfr> KF;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> KQ;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Vertex_index vd;
typedef SM::Halfedge_index hd;

// ---------------------------------------------------------------------------------------------
// A model of Parameterizer_3 for the border: puts the border vertices at given positions and
// marks them parameterized. Used as BorderParameterizer of CGAL's fixed-border parameterizers and
// of Progressive_embedding_parameterizer_3, so that every method sees the same border.
template <class TriangleMesh_>
class Fixed_positions_border_parameterizer_3
{
public:
  typedef TriangleMesh_                                                          TriangleMesh;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor          vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor        halfedge_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type VPM;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<VPM>::value_type>::Kernel Kernel;
  typedef typename Kernel::Point_2                                               Point_2;
  typedef std::map<vertex_descriptor, Point_2>                                   Positions;

  Fixed_positions_border_parameterizer_3(const Positions* positions = nullptr) : m_positions(positions) { }

  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(const TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                               VertexIndexMap /* vimap */, VertexParameterizedMap vpmap)
  {
    if(m_positions == nullptr) return SMP::ERROR_WRONG_PARAMETER;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(bhd, mesh))
    {
      const vertex_descriptor v = target(h, mesh);
      auto it = m_positions->find(v);
      if(it == m_positions->end()) return SMP::ERROR_WRONG_PARAMETER; // not one of the fixed vertices
      put(uvmap, v, it->second);
      put(vpmap, v, true);
    }
    return SMP::OK;
  }

  /// the positions are the protocol's convex polygon
  bool is_border_convex() const { return true; }

private:
  const Positions* m_positions;
};
typedef Fixed_positions_border_parameterizer_3<SM> Border_param;

// CGAL 5.5.1's own message table is off by one: name the codes here.
static const char* smp_error_name(SMP::Error_code e)
{
  switch(e)
  {
    case SMP::OK: return "OK";
    case SMP::ERROR_EMPTY_MESH: return "ERROR_EMPTY_MESH";
    case SMP::ERROR_NON_TRIANGULAR_MESH: return "ERROR_NON_TRIANGULAR_MESH";
    case SMP::ERROR_NO_TOPOLOGICAL_DISC: return "ERROR_NO_TOPOLOGICAL_DISC";
    case SMP::ERROR_NO_TOPOLOGICAL_BALL: return "ERROR_NO_TOPOLOGICAL_BALL";
    case SMP::ERROR_BORDER_TOO_SHORT: return "ERROR_BORDER_TOO_SHORT";
    case SMP::ERROR_NON_CONVEX_BORDER: return "ERROR_NON_CONVEX_BORDER";
    case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM";
    case SMP::ERROR_NO_1_TO_1_MAPPING: return "ERROR_NO_1_TO_1_MAPPING";
    case SMP::ERROR_WRONG_PARAMETER: return "ERROR_WRONG_PARAMETER";
  }
  return "UNKNOWN";
}

// ---------------------------------------------------------------------------------------------
// memory: reset the high-water mark of this (child) process, then read the peak with getrusage

static double current_rss_mb()
{
  std::ifstream in("/proc/self/statm");
  long pages = 0, resident = 0;
  in >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024. * 1024.);
}
static bool reset_peak_rss()
{
  std::ofstream out("/proc/self/clear_refs");
  if(!out) return false;
  out << "5" << std::flush; // Linux >= 4.0: reset the peak RSS to the current RSS
  return bool(out);
}
static double peak_rss_mb()
{
  struct rusage ru; getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0; // Linux: KiB
}

// ---------------------------------------------------------------------------------------------

struct Instance
{
  std::string kind, mesh;           // kind: "corpus" (Tutte-failure protocol) or "disk" (random-init protocol)
  unsigned seed = 0;
  SM m;
  hd bhd;
  Border_param::Positions border;   // the fixed border (double, used exactly by every method)
  std::vector<K::Point_2> pe_input; // by vertex index: the double Tutte map (corpus) or the random init (disk)
  std::string pe_input_name;
  std::size_t V = 0, F = 0, interior = 0;
  std::size_t tutte_flipped = 0, tutte_degenerate = 0; // of the double Tutte map
};

struct Row
{
  std::string method, status, input, note;
  int bits = 53;
  bool ran = true;
  double seconds = 0, peak_mb = 0, extra_mb = 0;
  PE::Embedding_report rep;
  bool has_rep = false;
};

static std::string csv_escape(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string r = "\"";
  for(char c : s) { if(c == '"') r += '"'; r += c; }
  return r + "\"";
}

static std::string fmt(double x)
{
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if(std::isnan(x)) return "nan";
  std::ostringstream os; os << std::setprecision(6) << x; return os.str();
}

static const char* csv_header =
  "kind,mesh,seed,vertices,faces,interior_vertices,tutte_flipped,tutte_degenerate,method,bits,input,"
  "status,returned_ok,certified_valid,flipped,degenerate,non_finite,border_simple,overlapping_pairs,overlap_checked,"
  "seconds,peak_rss_mb,extra_mb,max_sd,mean_sd,note";

static std::string row_to_csv(const Instance& in, const Row& r)
{
  std::ostringstream os;
  const bool returned_ok = r.ran && r.status == "OK";
  os << in.kind << ',' << csv_escape(in.mesh) << ',' << in.seed << ',' << in.V << ',' << in.F << ',' << in.interior << ','
     << in.tutte_flipped << ',' << in.tutte_degenerate << ',' << r.method << ',' << r.bits << ',' << r.input << ','
     << r.status << ',' << (r.ran ? (returned_ok ? "1" : "0") : "") << ',';
  if(r.has_rep)
    os << (r.rep.is_valid() ? 1 : 0) << ',' << r.rep.flipped << ',' << r.rep.degenerate << ',' << r.rep.non_finite << ','
       << (r.rep.border_simple ? 1 : 0) << ',' << r.rep.overlapping_pairs << ',' << (r.rep.overlap_checked ? 1 : 0) << ',';
  else
    os << ",,,,,,,";
  os << (r.ran ? fmt(r.seconds) : "") << ',' << (r.ran ? fmt(r.peak_mb) : "") << ',' << (r.ran ? fmt(r.extra_mb) : "") << ','
     << (r.has_rep ? fmt(r.rep.max_energy_3d) : "") << ',' << (r.has_rep ? fmt(r.rep.mean_energy_3d) : "") << ','
     << csv_escape(r.note);
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// the methods; each runs in a child process and returns one or more rows

template <class Kt>
static typename Kt::Point_2 to_kernel(const K::Point_2& p, int bits)
{
  if constexpr(std::is_same<typename Kt::FT, CGAL::Gmpfr>::value)
    return typename Kt::Point_2(CGAL::Gmpfr(p.x(), bits), CGAL::Gmpfr(p.y(), bits)); // exact (bits >= 53)
  else
  { (void)bits; return typename Kt::Point_2(typename Kt::FT(p.x()), typename Kt::FT(p.y())); }
}

template <class UV>
static SM::Property_map<vd, K::Point_2> rounded_copy(SM& m, UV uv, const std::string& name)
{
  auto r = m.add_property_map<vd, K::Point_2>(name, K::Point_2(0, 0)).first;
  for(vd v : m.vertices()) r[v] = K::Point_2(CGAL::to_double(uv[v].x()), CGAL::to_double(uv[v].y()));
  return r;
}

static std::vector<Row> run_cgal(Instance& in, bool mvc)
{
  Row r; r.method = mvc ? "cgal_mvc" : "cgal_barycentric"; r.input = "fixed_border";
  SM& m = in.m;
  auto uv = m.add_property_map<vd, K::Point_2>("v:study_uv", K::Point_2(0, 0)).first;
  Border_param bp(&in.border);
  CGAL::Real_timer t; t.start();
  SMP::Error_code ec;
  if(mvc) { SMP::Mean_value_coordinates_parameterizer_3<SM, Border_param> p(bp); ec = SMP::parameterize(m, p, in.bhd, uv); }
  else    { SMP::Barycentric_mapping_parameterizer_3<SM, Border_param> p(bp);    ec = SMP::parameterize(m, p, in.bhd, uv); }
  r.seconds = t.time();
  r.status = smp_error_name(ec);
  r.rep = PE::check_embedding(m, uv); r.has_rep = true;
  return { r };
}

template <class Kt>
static std::vector<Row> run_tutte(Instance& in, const std::string& method, int bits)
{
  if constexpr(std::is_same<typename Kt::FT, CGAL::Gmpfr>::value) CGAL::Gmpfr::set_default_precision(bits);
  Row r; r.method = method; r.bits = bits; r.input = "fixed_border";
  SM& m = in.m;
  auto uv = m.add_property_map<vd, typename Kt::Point_2>("v:study_uvk").first;
  for(const auto& b : in.border) uv[b.first] = to_kernel<Kt>(b.second, bits);
  CGAL::Real_timer t; t.start();
  PE::Error_code ec = PE::tutte_embedding(m, in.bhd, uv);
  r.seconds = t.time();
  r.status = PE::get_error_name(ec);
  r.rep = PE::check_embedding(m, uv); r.has_rep = true;
  if(std::is_same<Kt, K>::value) return { r };
  // the same map rounded to double, re-certified
  Row rr = r; rr.method = method + "_rounded"; rr.note = "the " + method + " map rounded to double";
  auto uvd = rounded_copy(m, uv, "v:study_rounded");
  rr.rep = PE::check_embedding(m, uvd);
  return { r, rr };
}

template <class Kt>
static std::vector<Row> run_pe(Instance& in, const std::string& method, int bits)
{
  if constexpr(std::is_same<typename Kt::FT, CGAL::Gmpfr>::value) CGAL::Gmpfr::set_default_precision(bits);
  Row r; r.method = method; r.bits = bits; r.input = in.pe_input_name;
  SM& m = in.m;
  auto uv = m.add_property_map<vd, typename Kt::Point_2>("v:study_uvk").first;
  for(vd v : m.vertices()) uv[v] = to_kernel<Kt>(in.pe_input[v], bits);
  PE::Progressive_embedding_statistics st;
  CGAL::Real_timer t; t.start();
  PE::Error_code ec = PE::progressive_embedding(m, uv, PE::parameters::statistics(&st));
  r.seconds = t.time();
  r.status = PE::get_error_name(ec);
  r.rep = PE::check_embedding(m, uv); r.has_rep = true; // our own output is re-certified too
  r.note = "collapses " + std::to_string(st.collapses) + ", restarts " + std::to_string(st.restarts);
  if(std::is_same<Kt, K>::value) return { r };
  Row rr = r; rr.method = method + "_rounded"; rr.note = "the " + method + " map rounded to double";
  auto uvd = rounded_copy(m, uv, "v:study_rounded");
  rr.rep = PE::check_embedding(m, uvd);
  return { r, rr };
}

static std::vector<Row> run_pe_parameterizer(Instance& in)
{
  Row r; r.method = "pe_parameterizer"; r.input = "fixed_border";
  SM& m = in.m;
  auto uv = m.add_property_map<vd, K::Point_2>("v:study_uv", K::Point_2(0, 0)).first;
  PE::Progressive_embedding_parameterizer_3<SM, Border_param> p{Border_param(&in.border)}; // copied by SMP::parameterize
  CGAL::Real_timer t; t.start();
  SMP::Error_code ec = SMP::parameterize(m, p, in.bhd, uv);
  r.seconds = t.time();
  r.status = smp_error_name(ec);
  r.rep = PE::check_embedding(m, uv); r.has_rep = true;
  return { r };
}

// runs `f` in a forked child with a time budget; the child sends its rows through a pipe
static std::vector<Row> run_isolated(Instance& in, const std::string& method, int bits, double budget,
                                     const std::function<std::vector<Row>(Instance&)>& f)
{
  int fd[2];
  if(pipe(fd) != 0) { perror("pipe"); std::exit(1); }
  std::cout.flush(); std::cerr.flush();
  pid_t pid = fork();
  if(pid < 0) { perror("fork"); std::exit(1); }
  if(pid == 0)
  {
    close(fd[0]);
    const double rss0 = current_rss_mb();
    const bool reset = reset_peak_rss();
    alarm(static_cast<unsigned>(std::ceil(budget)));
    std::vector<Row> rows = f(in);
    alarm(0);
    const double peak = reset ? peak_rss_mb() : std::numeric_limits<double>::quiet_NaN();
    std::string out;
    for(Row& r : rows)
    {
      r.peak_mb = peak; r.extra_mb = peak - rss0;
      out += row_to_csv(in, r) + "\n";
    }
    std::size_t done = 0;
    while(done < out.size()) { ssize_t k = write(fd[1], out.data() + done, out.size() - done); if(k <= 0) break; done += k; }
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string text; char buf[4096]; ssize_t k;
  while((k = read(fd[0], buf, sizeof buf)) > 0) text.append(buf, k);
  close(fd[0]);
  int wstatus = 0; waitpid(pid, &wstatus, 0);
  std::vector<Row> rows;
  if(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && !text.empty())
  {
    Row r; r.method = "__raw__"; r.note = text; rows.push_back(r);
    return rows;
  }
  Row r; r.method = method; r.bits = bits; r.ran = true; r.seconds = budget;
  r.input = (method.rfind("pe_", 0) == 0 && method != "pe_parameterizer") ? in.pe_input_name : "fixed_border";
  if(WIFSIGNALED(wstatus) && WTERMSIG(wstatus) == SIGALRM) { r.status = "TIMEOUT"; r.note = "time budget " + fmt(budget) + " s"; }
  else if(WIFSIGNALED(wstatus)) { r.status = "CRASH"; r.note = std::string("signal ") + strsignal(WTERMSIG(wstatus)); r.seconds = 0; }
  else { r.status = "CRASH"; r.note = "exit status " + std::to_string(WEXITSTATUS(wstatus)); r.seconds = 0; }
  r.peak_mb = std::numeric_limits<double>::quiet_NaN(); r.extra_mb = r.peak_mb;
  rows.push_back(r);
  return rows;
}

static Row skipped(const Instance& in, const std::string& method, int bits, const std::string& why)
{
  Row r; r.method = method; r.bits = bits; r.ran = false; r.status = "SKIPPED"; r.note = why;
  r.input = (method.rfind("pe_", 0) == 0 && method != "pe_parameterizer") ? in.pe_input_name : "fixed_border";
  return r;
}

// ---------------------------------------------------------------------------------------------

struct Options
{
  std::string data, out;
  bool quick = false, corpus = true, disks = true, list = false;
  unsigned seed_min = 0, seed_max = 40;
  std::vector<std::string> meshes;
  double budget = 150;
  std::size_t mpfr_max_vertices = 25000, mpfr_all_seeds_max_vertices = 500, mpfr_sweep_max_vertices = 10000, mpfr_pe_max_vertices = 10000;
  std::size_t gmpq_max_interior = 1500, gmpq_all_seeds_max_interior = 400;
  std::vector<int> mpfr_pe_bits = { 128, 256 };
  double gmpq_budget = 180;
  int gallery = 5;
  std::string command;
  std::vector<std::string> methods; // empty: all
  std::vector<std::pair<std::string, unsigned> > gallery_runs; // non-empty: the gallery of these runs only
  bool wants(const std::string& m) const { return methods.empty() || std::find(methods.begin(), methods.end(), m) != methods.end(); }
};

enum class Mesh_class { CLOSED_GENUS_0, DISK, OTHER };

static Mesh_class classify(const SM& m, std::string& why)
{
  if(m.number_of_faces() == 0) { why = "empty"; return Mesh_class::OTHER; }
  if(!CGAL::is_valid_polygon_mesh(m)) { why = "invalid"; return Mesh_class::OTHER; }
  if(!CGAL::is_triangle_mesh(m)) { why = "not triangulated"; return Mesh_class::OTHER; }
  auto fcc = const_cast<SM&>(m).add_property_map<SM::Face_index, std::size_t>("f:study_cc").first;
  const std::size_t ncc = CGAL::Polygon_mesh_processing::connected_components(m, fcc);
  const_cast<SM&>(m).remove_property_map(fcc);
  const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  if(ncc != 1) { why = std::to_string(ncc) + " components"; return Mesh_class::OTHER; }
  if(CGAL::is_closed(m))
  {
    if(chi == 2) return Mesh_class::CLOSED_GENUS_0;
    why = "closed, genus " + std::to_string((2 - chi) / 2); return Mesh_class::OTHER;
  }
  PE::internal::Indexed_disk<SM> disk;
  const PE::Error_code ec = PE::internal::make_indexed_disk(m, SM::null_halfedge(), disk);
  if(ec == PE::OK && disk.border.size() >= 3) return Mesh_class::DISK;
  why = std::string("open, not a disk (") + PE::get_error_name(ec) + ")";
  return Mesh_class::OTHER;
}

static hd some_border_halfedge(const SM& m)
{
  for(hd h : m.halfedges()) if(m.is_border(h)) return h;
  return SM::null_halfedge();
}

// random init of pe_benchmark.cpp: interior vertices uniformly inside the polygon inscribed in the unit circle
static void random_init(const SM& m, std::vector<K::Point_2>& uv, unsigned seed)
{
  std::size_t nb = 0; for(vd v : m.vertices()) if(m.is_border(v)) ++nb;
  const double radius = std::cos(CGAL_PI / double(nb)) * 0.999;
  std::mt19937 gen(seed); std::uniform_real_distribution<double> U(-1, 1);
  for(vd v : m.vertices())
    if(!m.is_border(v))
    {
      double x, y; do { x = U(gen); y = U(gen); } while(x * x + y * y > 1);
      uv[v] = K::Point_2(radius * x, radius * y);
    }
}

static std::string shell_out(const std::string& cmd)
{
  std::string r; char buf[512];
  if(FILE* p = popen(cmd.c_str(), "r")) { while(fgets(buf, sizeof buf, p)) r += buf; pclose(p); }
  while(!r.empty() && (r.back() == '\n' || r.back() == '\r')) r.pop_back();
  return r;
}

// the gallery's pictures: faces colored by their distortion, so that the repaired maps show where the
// repair squeezed faces; a zoom that is not a disk (the coloring needs one) is drawn in one color.
// A failed write is reported and the study goes on without that picture.
static void write_picture(const std::string& filename, const SM& m, SM::Property_map<vd, K::Point_2> uv, const std::string& title)
{
  PE::IO::SVG_options options;
  options.title = title;
  options.color_by_distortion = true;
  PE::Error_code ec = PE::IO::write_SVG(filename, m, uv, options);
  if(ec != PE::OK && ec != PE::ERROR_CANNOT_WRITE_FILE)
  {
    options.color_by_distortion = false;
    ec = PE::IO::write_SVG(filename, m, uv, options);
  }
  if(ec != PE::OK) std::cerr << "cannot write " << filename << ": " << PE::get_error_name(ec) << "\n";
}

// writes the uv picture of the faces `sel` of `m` only (a copy of them), framed on those faces
static void write_zoom_SVG(const SM& m, SM::Property_map<vd, K::Point_2> uv, const std::vector<SM::Face_index>& sel,
                           const std::string& filename, const std::string& title)
{
  SM z;
  auto zuv = z.add_property_map<vd, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
  std::map<vd, vd> to_z;
  for(SM::Face_index f : sel)
  {
    std::vector<vd> t;
    for(vd v : CGAL::vertices_around_face(m.halfedge(f), m))
    {
      auto it = to_z.find(v);
      if(it == to_z.end()) { vd w = z.add_vertex(m.point(v)); zuv[w] = uv[v]; it = to_z.emplace(v, w).first; }
      t.push_back(it->second);
    }
    z.add_face(t); // a face that would make the copy non-manifold is left out
  }
  write_picture(filename, z, zuv, title);
}

// the faces whose three uv vertices lie in a square window on the invalid faces (exact orientation
// different from `expected`): centered at the coordinate-wise median of their vertices, of half-size
// 1.5 x the median distance of those vertices to the center (the invalid faces span many orders of
// magnitude; this frames the scale at which half of them are seen)
static std::vector<SM::Face_index> faces_around_invalid(const SM& m, SM::Property_map<vd, K::Point_2> uv, CGAL::Orientation expected)
{
  std::vector<K::Point_2> pts;
  for(SM::Face_index f : m.faces())
  {
    const hd h = m.halfedge(f);
    const K::Point_2 &a = uv[m.source(h)], &b = uv[m.target(h)], &c = uv[m.target(m.next(h))];
    if(CGAL::orientation(a, b, c) == expected) continue;
    pts.push_back(a); pts.push_back(b); pts.push_back(c);
  }
  std::vector<SM::Face_index> sel;
  if(pts.empty()) return sel;
  std::vector<double> xs, ys, d;
  for(const K::Point_2& p : pts) { xs.push_back(p.x()); ys.push_back(p.y()); }
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  std::nth_element(ys.begin(), ys.begin() + ys.size() / 2, ys.end());
  const double cx = xs[xs.size() / 2], cy = ys[ys.size() / 2];
  for(const K::Point_2& p : pts) d.push_back((std::max)(std::abs(p.x() - cx), std::abs(p.y() - cy)));
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  const double r = (std::max)(1.5 * d[d.size() / 2], 1e-15 * ((std::max)(std::abs(cx), std::abs(cy)) + 1e-300));
  for(SM::Face_index f : m.faces())
  {
    bool in = true;
    for(vd v : CGAL::vertices_around_face(m.halfedge(f), m))
      in = in && std::abs(uv[v].x() - cx) <= r && std::abs(uv[v].y() - cy) <= r;
    if(in) sel.push_back(f);
  }
  return sel;
}

int main(int argc, char** argv)
{
  Options o;
  if(argc < 3) { std::cerr << "usage: comparison_study DATA_DIR OUT_DIR [--quick] [--seeds A-B] [--meshes a,b] [--budget S] ...\n"; return 2; }
  o.data = argv[1]; o.out = argv[2];
  std::string argv_line;
  for(int i = 0; i < argc; ++i)
  {
    std::string a = argv[i];
    if(a.find_first_of(" '\"$\\&;|<>()*?") != std::string::npos)
    { std::string q = "'"; for(char c : a) { if(c == '\'') q += "'\\''"; else q += c; } a = q + "'"; }
    argv_line += std::string(i ? " " : "") + a;
  }
  for(int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { if(i + 1 >= argc) { std::cerr << a << " needs a value\n"; std::exit(2); } return argv[++i]; };
    if(a == "--quick") o.quick = true;
    else if(a == "--list") o.list = true;
    else if(a == "--no-corpus") o.corpus = false;
    else if(a == "--no-disks") o.disks = false;
    else if(a == "--seeds") { std::string s = next(); auto d = s.find('-'); o.seed_min = std::stoul(s.substr(0, d)); o.seed_max = (d == std::string::npos) ? o.seed_min : std::stoul(s.substr(d + 1)); }
    else if(a == "--meshes") { std::stringstream ss(next()); std::string x; while(std::getline(ss, x, ',')) if(!x.empty()) o.meshes.push_back(x); }
    else if(a == "--budget") o.budget = std::stod(next());
    else if(a == "--mpfr-max-vertices") o.mpfr_max_vertices = std::stoul(next());
    else if(a == "--mpfr-pe-max-vertices") o.mpfr_pe_max_vertices = std::stoul(next());
    else if(a == "--mpfr-all-seeds-max-vertices") o.mpfr_all_seeds_max_vertices = std::stoul(next());
    else if(a == "--mpfr-sweep-max-vertices") o.mpfr_sweep_max_vertices = std::stoul(next());
    else if(a == "--mpfr-pe-bits") { o.mpfr_pe_bits.clear(); std::stringstream ss(next()); std::string x; while(std::getline(ss, x, ',')) if(!x.empty()) o.mpfr_pe_bits.push_back(std::stoi(x)); }
    else if(a == "--gmpq-budget") o.gmpq_budget = std::stod(next());
    else if(a == "--gmpq-max-interior") o.gmpq_max_interior = std::stoul(next());
    else if(a == "--gmpq-all-seeds-max-interior") o.gmpq_all_seeds_max_interior = std::stoul(next());
    else if(a == "--gallery") o.gallery = std::stoi(next());
    else if(a == "--command") o.command = next();
    else if(a == "--gallery-runs")
    {
      std::stringstream ss(next()); std::string x;
      while(std::getline(ss, x, ','))
      {
        const std::size_t c = x.rfind(':');
        // a seed of 1 to 9 digits: std::stoul below cannot throw
        if(c == std::string::npos || c == 0 || c + 1 == x.size() || x.find_first_not_of("0123456789", c + 1) != std::string::npos
           || x.size() - c > 10) { std::cerr << "--gallery-runs: expected mesh:seed, got " << x << "\n"; return 2; }
        o.gallery_runs.push_back({ x.substr(0, c), unsigned(std::stoul(x.substr(c + 1))) });
      }
    }
    else if(a == "--methods") { std::stringstream ss(next()); std::string x; while(std::getline(ss, x, ',')) if(!x.empty()) o.methods.push_back(x); }
    else { std::cerr << "unknown option " << a << "\n"; return 2; }
  }

  // ---- the meshes
  std::vector<std::string> names;
  if(DIR* dir = opendir((o.data + "/meshes").c_str()))
  {
    while(dirent* e = readdir(dir))
    {
      std::string n = e->d_name;
      // OFF files only: 48 closed genus-0 meshes and 25 disks in libcgal-demo 5.5
      // (sphere.ply, sphere.stl and colored_tetra.ply repeat OFF meshes)
      if(n.size() > 4 && n.substr(n.size() - 4) == ".off") names.push_back(n);
    }
    closedir(dir);
  }
  else { std::cerr << "cannot open " << o.data << "/meshes\n"; return 1; }
  std::sort(names.begin(), names.end());
  std::vector<std::pair<std::string, std::size_t> > closed, disks;
  const bool gallery_only = !o.gallery_runs.empty();
  if(gallery_only) names.clear(); // the gallery reads its own meshes; classifying every mesh takes seconds
  for(const std::string& n : names)
  {
    SM m; std::string why;
    const bool read = CGAL::IO::read_polygon_mesh(o.data + "/meshes/" + n, m);
    Mesh_class c = read ? classify(m, why) : Mesh_class::OTHER;
    if(!read) why = "unreadable";
    if(c == Mesh_class::CLOSED_GENUS_0) closed.emplace_back(n, m.number_of_vertices());
    if(c == Mesh_class::DISK) disks.emplace_back(n, m.number_of_vertices());
    if(o.list)
      std::cout << n << "\t" << m.number_of_vertices() << "\t" << m.number_of_faces() << "\t"
                << (c == Mesh_class::CLOSED_GENUS_0 ? "closed-genus-0" : c == Mesh_class::DISK ? "disk" : "other: " + why) << "\n";
  }
  if(!gallery_only) std::cerr << closed.size() << " closed genus-0 meshes, " << disks.size() << " disks\n";
  if(o.list) return 0;

  auto selected = [&](const std::string& n) { return o.meshes.empty() || std::find(o.meshes.begin(), o.meshes.end(), n) != o.meshes.end(); };
  std::vector<std::pair<std::string, std::vector<unsigned> > > corpus_jobs;
  std::vector<std::string> disk_jobs;
  if(gallery_only)
  {
    // the gallery only: no study job, and the outputs of the study that produced the list stay as they are
  }
  else if(o.quick && o.meshes.empty())
  {
    // bull.off seeds 0 (fails in double) and 1, dino.off seeds 0 and 8 (the worst corpus run), two small disks;
    // MPFR progressive embedding on the disks only, one gallery pair
    if(o.corpus) { corpus_jobs.push_back({ "bull.off", { 0, 1 } }); corpus_jobs.push_back({ "dino.off", { 0, 8 } }); }
    o.mpfr_pe_max_vertices = (std::min)(o.mpfr_pe_max_vertices, std::size_t(2000));
    o.gallery = (std::min)(o.gallery, 1);
    std::vector<std::pair<std::string, std::size_t> > d = disks;
    std::sort(d.begin(), d.end(), [](auto& a, auto& b) { return a.second < b.second; });
    for(auto& x : d) if(o.disks && x.second >= 100 && disk_jobs.size() < 2) disk_jobs.push_back(x.first);
  }
  else
  {
    std::vector<unsigned> seeds;
    for(unsigned s = o.seed_min; s <= o.seed_max; ++s) seeds.push_back(s);
    if(o.corpus) for(auto& c : closed) if(selected(c.first)) corpus_jobs.push_back({ c.first, seeds });
    if(o.disks) for(auto& d : disks) if(selected(d.first)) disk_jobs.push_back(d.first);
  }

  // ---- machine, date, command
  if(!gallery_only)
  {
    struct utsname u; uname(&u);
    std::time_t now = std::time(nullptr);
    char date[64]; std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
    std::ofstream meta(o.out + "/study_meta.txt");
    meta << "date: " << date << "\n"
         << "machine: " << u.sysname << " " << u.nodename << " " << u.release << " " << u.version << " " << u.machine << "\n"
         << "nproc: " << sysconf(_SC_NPROCESSORS_ONLN) << "\n"
         << "cpu: " << shell_out("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'") << "\n"
         << "memory: " << shell_out("grep -m1 MemTotal /proc/meminfo | sed 's/MemTotal: *//'") << "\n"
         << "compiler: " << __VERSION__ << "\n"
         << "CGAL: " << CGAL_VERSION_STR << ", Eigen: " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION << "\n"
         << "driver command: " << argv_line << "\n"
         << "study command: " << (o.command.empty() ? argv_line : o.command) << "\n"
         << "budget per run (s): " << o.budget << "\n"
         << "MPFR Tutte up to vertices: " << o.mpfr_max_vertices << " (every disk; closed meshes: every seed up to " << o.mpfr_all_seeds_max_vertices
         << " vertices, seed 0 and every failing run up to " << o.mpfr_sweep_max_vertices << ", the first failing run above)\n"
         << "MPFR progressive embedding up to vertices: " << o.mpfr_pe_max_vertices << " (every disk, the first failing run of each closed mesh)\n"
         << "Gmpq budget per run (s): " << o.gmpq_budget << "\n"
         << "Gmpq Tutte up to interior vertices: " << o.gmpq_max_interior << " (every seed up to " << o.gmpq_all_seeds_max_interior << ", seed 0 only above)\n"
         << "closed genus-0 meshes: " << closed.size() << ", disks: " << disks.size() << "\n"
         << "corpus meshes run: " << corpus_jobs.size() << ", disks run: " << disk_jobs.size() << "\n";
    if(!meta) { std::cerr << "cannot write " << o.out << "/study_meta.txt\n"; return 1; }
  }

  std::ofstream csv;
  if(!gallery_only)
  {
    csv.open(o.out + "/study_runs.csv");
    if(!csv) { std::cerr << "cannot write " << o.out << "/study_runs.csv\n"; return 1; }
    csv << csv_header << "\n";
  }

  CGAL::Real_timer total; total.start();
  struct Worst { std::size_t bad; std::string mesh; unsigned seed; };
  std::vector<Worst> worst;

  std::map<std::string, int> failing_seen; // per mesh: failing corpus runs so far
  auto run_all = [&](Instance& in) {
    std::vector<Row> rows;
    const double B = o.budget;
    auto go = [&](const std::string& name, int bits, double budget, const std::function<std::vector<Row>(Instance&)>& f) {
      if(o.wants(name)) for(Row& r : run_isolated(in, name, bits, budget, f)) rows.push_back(r);
    };
    auto skip = [&](const std::string& name, int bits, const std::string& why) {
      if(!o.wants(name)) return;
      rows.push_back(skipped(in, name, bits, why)); rows.push_back(skipped(in, name + "_rounded", bits, why));
    };
    const bool corpus = in.kind == "corpus";
    const bool tutte_invalid = in.tutte_flipped + in.tutte_degenerate > 0;
    go("cgal_barycentric", 53, B, [](Instance& x) { return run_cgal(x, false); });
    go("cgal_mvc", 53, B, [](Instance& x) { return run_cgal(x, true); });
    go("tutte_double", 53, B, [](Instance& x) { return run_tutte<K>(x, "tutte_double", 53); });
    // MPFR Tutte (each run costs 100-1000 times the double solve): every disk; closed meshes at every
    // seed up to mpfr_all_seeds_max_vertices, seed 0 up to mpfr_sweep_max_vertices, every failing run up to
    // mpfr_sweep_max_vertices and the first failing run of each larger mesh; nothing above mpfr_max_vertices
    const bool first_failing = tutte_invalid && failing_seen[in.mesh] == 0;
    for(int bits : { 128, 256 })
    {
      const std::string name = "tutte_mpfr" + std::to_string(bits);
      if(in.V > o.mpfr_max_vertices)
        skip(name, bits, "skipped (budget): more than " + std::to_string(o.mpfr_max_vertices) + " vertices");
      else if(!corpus || in.V <= o.mpfr_all_seeds_max_vertices || first_failing
              || ((in.seed == 0 || tutte_invalid) && in.V <= o.mpfr_sweep_max_vertices))
        go(name, bits, B, [bits, name](Instance& x) { return run_tutte<KF>(x, name, bits); });
      else
        skip(name, bits, "skipped (budget): above " + std::to_string(o.mpfr_all_seeds_max_vertices) + " vertices, seed 0 and failing runs only");
    }
    // exact Tutte: small meshes only (a naive Gmpq SparseLU is about cubic)
    if(in.interior > o.gmpq_max_interior)
      skip("tutte_gmpq", 0, "skipped (budget): more than " + std::to_string(o.gmpq_max_interior) + " interior vertices");
    else if(corpus && in.seed != 0 && in.interior > o.gmpq_all_seeds_max_interior)
      skip("tutte_gmpq", 0, "skipped (budget): seed 0 only above " + std::to_string(o.gmpq_all_seeds_max_interior) + " interior vertices");
    else
      go("tutte_gmpq", 0, o.gmpq_budget, [](Instance& x) { return run_tutte<KQ>(x, "tutte_gmpq", 0); });
    go("pe_double", 53, B, [](Instance& x) { return run_pe<K>(x, "pe_double", 53); });
    // MPFR progressive embedding, from the same input as pe_double, where there is something to
    // repair: every disk (random init) and the first failing run of each closed mesh
    if(!corpus || tutte_invalid)
      for(int bits : o.mpfr_pe_bits)
      {
        const std::string name = "pe_mpfr" + std::to_string(bits);
        if(in.V > o.mpfr_pe_max_vertices) skip(name, bits, "skipped (budget): more than " + std::to_string(o.mpfr_pe_max_vertices) + " vertices");
        else if(corpus && !first_failing) skip(name, bits, "skipped (budget): the first failing run of each mesh only");
        else go(name, bits, B, [bits, name](Instance& x) { return run_pe<KF>(x, name, bits); });
      }
    if(tutte_invalid) ++failing_seen[in.mesh];
    go("pe_parameterizer", 53, B, [](Instance& x) { return run_pe_parameterizer(x); });
    std::ostringstream log;
    log << in.kind << " " << in.mesh << " seed " << in.seed << " (V " << in.V << "):";
    for(const Row& r : rows)
    {
      if(r.method == "__raw__") csv << r.note; else csv << row_to_csv(in, r) << "\n";
      if(r.method == "__raw__")
      {
        // status and validity for the log
        std::stringstream ss(r.note); std::string line;
        while(std::getline(ss, line))
        {
          std::vector<std::string> f; std::string cell; std::stringstream ls(line);
          while(std::getline(ls, cell, ',')) f.push_back(cell);
          if(f.size() > 20) log << " " << f[8] << "=" << (f[11] == "OK" ? "" : f[11] + "/") << (f[13] == "1" ? "valid" : "INVALID") << "(" << f[20] << "s)";
        }
      }
      else log << " " << r.method << "=" << r.status;
    }
    csv.flush();
    std::cerr << log.str() << "  [" << fmt(total.time()) << " s]\n";
  };

  // ---- corpus: Tutte-failure protocol
  for(auto& job : corpus_jobs)
  {
    SM base;
    if(!CGAL::IO::read_polygon_mesh(o.data + "/meshes/" + job.first, base)) { std::cerr << "cannot read " << job.first << "\n"; return 1; }
    for(unsigned seed : job.second)
    {
      Instance in; in.kind = "corpus"; in.mesh = job.first; in.seed = seed;
      in.m = base;
      std::array<vd, 3> pin;
      if(PE::internal::thingi_cut(in.m, seed, pin) != PE::OK) { std::cerr << "cut failed on " << job.first << "\n"; return 1; }
      // (no garbage collection: the vertex indices stay those of the input, the removed face is skipped)
      in.bhd = some_border_halfedge(in.m);
      const K::Point_2 P[3] = { K::Point_2(0, 0), K::Point_2(0.5, std::sqrt(3.) / 2), K::Point_2(1, 0) };
      for(int k = 0; k < 3; ++k) in.border[pin[k]] = P[k];
      for(hd h : CGAL::halfedges_around_face(in.bhd, in.m))
        if(!in.border.count(in.m.target(h))) { std::cerr << "border is not the removed triangle\n"; return 1; }
      in.V = in.m.number_of_vertices(); in.F = in.m.number_of_faces(); in.interior = in.V - 3;
      // the input of progressive embedding: the double Tutte map (the protocol)
      in.pe_input.assign(in.m.number_of_vertices(), K::Point_2(0, 0));
      {
        auto uv = in.m.add_property_map<vd, K::Point_2>("v:study_input", K::Point_2(0, 0)).first;
        for(const auto& b : in.border) uv[b.first] = b.second;
        PE::tutte_embedding(in.m, in.bhd, uv);
        const PE::Embedding_report rep = PE::check_embedding(in.m, uv, PE::parameters::check_overlap(false));
        in.tutte_flipped = rep.flipped; in.tutte_degenerate = rep.degenerate;
        for(vd v : in.m.vertices()) in.pe_input[v] = uv[v];
        in.m.remove_property_map(uv);
      }
      in.pe_input_name = "tutte_double";
      worst.push_back({ in.tutte_flipped + in.tutte_degenerate, in.mesh, seed });
      run_all(in);
    }
  }

  // ---- disks: border on the unit circle, random-init protocol
  for(const std::string& name : disk_jobs)
  {
    Instance in; in.kind = "disk"; in.mesh = name; in.seed = 1;
    if(!CGAL::IO::read_polygon_mesh(o.data + "/meshes/" + name, in.m)) { std::cerr << "cannot read " << name << "\n"; return 1; }
    in.bhd = some_border_halfedge(in.m);
    auto uv = in.m.add_property_map<vd, K::Point_2>("v:study_input", K::Point_2(0, 0)).first;
    PE::Error_code ec = PE::tutte_embedding(in.m, in.bhd, uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE));
    if(ec != PE::OK) { std::cerr << name << ": circle border failed: " << PE::get_error_name(ec) << "\n"; continue; }
    const PE::Embedding_report rep = PE::check_embedding(in.m, uv, PE::parameters::check_overlap(false));
    in.tutte_flipped = rep.flipped; in.tutte_degenerate = rep.degenerate;
    std::size_t nb = 0;
    for(hd h : CGAL::halfedges_around_face(in.bhd, in.m)) { in.border[in.m.target(h)] = uv[in.m.target(h)]; ++nb; }
    in.V = in.m.number_of_vertices(); in.F = in.m.number_of_faces(); in.interior = in.V - nb;
    in.pe_input.assign(in.m.number_of_vertices(), K::Point_2(0, 0));
    for(vd v : in.m.vertices()) in.pe_input[v] = uv[v];
    random_init(in.m, in.pe_input, 1);
    in.m.remove_property_map(uv);
    in.pe_input_name = "random_init";
    run_all(in);
  }
  if(!gallery_only) csv.close();

  // ---- gallery: the double Tutte map and its repair for the worst corpus runs
  if(gallery_only)
  {
    // in the given order; the invalid-face counts are computed below
    o.gallery = int(o.gallery_runs.size());
    for(const auto& g : o.gallery_runs) worst.push_back({ 1, g.first, g.second });
  }
  else
    std::sort(worst.begin(), worst.end(), [](const Worst& a, const Worst& b) { return a.bad > b.bad || (a.bad == b.bad && a.mesh < b.mesh); });
  std::ofstream gal(o.out + "/study_gallery.csv");
  gal << "rank,mesh,seed,tutte_invalid_faces,zoom_faces,tutte_zoom_svg,repaired_zoom_svg,tutte_full_svg,repaired_status,repaired_valid\n";
  for(int k = 0; k < o.gallery && k < int(worst.size()) && worst[k].bad > 0; ++k)
  {
    SM m;
    if(!CGAL::IO::read_polygon_mesh(o.data + "/meshes/" + worst[k].mesh, m) || !CGAL::is_closed(m) || m.is_empty())
    { std::cerr << "gallery: cannot read " << worst[k].mesh << " as a closed mesh\n"; return 1; }
    std::array<vd, 3> pin;
    if(PE::internal::thingi_cut(m, worst[k].seed, pin) != PE::OK) { std::cerr << "gallery: cut failed on " << worst[k].mesh << "\n"; return 1; }
    auto uv = m.add_property_map<vd, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
    uv[pin[0]] = K::Point_2(0, 0); uv[pin[1]] = K::Point_2(0.5, std::sqrt(3.) / 2); uv[pin[2]] = K::Point_2(1, 0);
    PE::tutte_embedding(m, SM::null_halfedge(), uv);
    if(gallery_only)
    {
      const PE::Embedding_report rep = PE::check_embedding(m, uv, PE::parameters::check_overlap(false));
      worst[k].bad = rep.flipped + rep.degenerate;
      if(worst[k].bad == 0) { std::cerr << "gallery: " << worst[k].mesh << " seed " << worst[k].seed << ": the Tutte map is valid, no picture\n"; continue; }
    }
    const std::string what = worst[k].mesh + " seed " + std::to_string(worst[k].seed);
    const std::string stem = "study_gallery_" + std::to_string(k + 1) + "_" + worst[k].mesh.substr(0, worst[k].mesh.rfind('.')) + "_" + std::to_string(worst[k].seed);
    // the pinned corners are clockwise: so is every face of a valid map
    const std::vector<SM::Face_index> sel = faces_around_invalid(m, uv, CGAL::RIGHT_TURN);
    std::string full_svg;
    if(k == 0) { full_svg = stem + "_tutte_full.svg"; write_picture(o.out + "/" + full_svg, m, uv, what + ": Tutte in double (whole map)"); }
    write_zoom_SVG(m, uv, sel, o.out + "/" + stem + "_tutte.svg", what + ": Tutte in double, zoom on the invalid faces");
    const PE::Error_code ec = PE::progressive_embedding(m, uv);
    const bool valid = PE::check_embedding(m, uv).is_valid();
    write_zoom_SVG(m, uv, sel, o.out + "/" + stem + "_repaired.svg", what + ": the same faces after progressive embedding");
    gal << k + 1 << ',' << worst[k].mesh << ',' << worst[k].seed << ',' << worst[k].bad << ',' << sel.size() << ','
        << stem + "_tutte.svg" << ',' << stem + "_repaired.svg" << ',' << full_svg << ',' << PE::get_error_name(ec) << ',' << (valid ? 1 : 0) << "\n";
  }
  std::cerr << "done in " << fmt(total.time()) << " s\n";
  if(!gallery_only)
    std::ofstream(o.out + "/study_meta.txt", std::ios::app) << "driver wall-clock seconds: " << fmt(total.time()) << "\n";
  return 0;
}
