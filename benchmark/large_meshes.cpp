// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Large meshes against the solver's floor. Per mesh spec (e.g.
// mannequin-devil.off+loop3), the mesh is subdivided and written as OFF to a
// scratch directory, then:
//  - the default `dlf disk MESH -o OUT.obj --report R.json --history` runs as a user
//    runs it (whole process, no environment variable set by this program),
//    timed from outside, with its maximum resident set size (wait4), and the
//    split its report gives: read, check, initial map, the coarse levels
//    (each one's faces, iterations, seconds), the finest level's iterations,
//    write;
//  - with --floor: in this process, the cotangent stiffness of the interior
//    (the matrix every Sobolev iteration factorizes) on the Tutte map of the
//    same mesh, factorized once (symbolic analysis, numeric factorization)
//    and solved once for two right-hand sides, with the same threads as the
//    flow chooses (solver_threads.h).
// Beside it, the plain flow (`--coarse-to-fine-faces 0`) on the same mesh in
// the same run: the ratio is the default's whole process over the plain one's.
// With --floor, one factorization and solve of the finest level's stiffness.
//
//   large_meshes --dlf build/tools/dlf --work DIR mannequin-devil.off+loop2 ...
//
// benchmark/large_meshes.sh runs the sizes of doc/large_meshes.md.

#include <CGAL/Simple_cartesian.h>

#include "benchmark_utilities.h"

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/solver_threads.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/sobolev_direction.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <nlohmann/json.hpp>

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace dlf = CGAL::Surface_mesh_parameterization::internal::dlf;
using dlf_benchmark::Clock;
using dlf_benchmark::seconds_since;

struct Process_run
{
  int exit_code = -1;
  double seconds = 0, cpu_seconds = 0, max_rss_gib = 0;
  long max_rss_kib = 0;
};

// Runs `argv` as a child process; its wall time and maximum resident set.
Process_run run_process(const std::vector<std::string>& args)
{
  std::vector<char*> argv;
  for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  Process_run r;
  std::fflush(stdout);
  const Clock::time_point t0 = Clock::now();
  const pid_t pid = fork();
  if(pid < 0) return r;
  if(pid == 0) {
    if(std::freopen("/dev/null", "w", stdout) == nullptr) _exit(127);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  if(wait4(pid, &status, 0, &usage) != pid) return r;
  r.seconds = seconds_since(t0);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.cpu_seconds = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) +
                  double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
  r.max_rss_kib = usage.ru_maxrss; // kilobytes on Linux
  r.max_rss_gib = double(usage.ru_maxrss) / (1024. * 1024.);
  return r;
}

struct Floor
{
  std::size_t unknowns = 0;
  double analyse = 0, factorize = 0, solve = 0;
};

// Tutte's map (uniform weights, border on the unit circle by arc length),
// then the interior cotangent stiffness of that map: analysed, factorized
// and solved once, as a flow iteration does.
Floor measure_floor(const Mesh& mesh)
{
  const std::size_t n = num_vertices(mesh);
  std::vector<dlf::Vec3> xyz(n);
  std::vector<dlf::Face> triangles;
  for(Mesh::Vertex_index v : vertices(mesh)) xyz[v.idx()] = {{ mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z() }};
  for(Mesh::Face_index f : faces(mesh)) {
    dlf::Face t;
    int k = 0;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh)) t[std::size_t(k++)] = int(v.idx());
    triangles.push_back(t);
  }
  // The longest border loop.
  std::vector<int> loop;
  double loop_length = 0;
  std::vector<char> seen(num_halfedges(mesh), 0);
  for(Mesh::Halfedge_index h : halfedges(mesh)) {
    if(!is_border(h, mesh) || seen[h.idx()]) continue;
    std::vector<int> l;
    double length = 0;
    for(Mesh::Halfedge_index g : halfedges_around_face(h, mesh)) {
      seen[g.idx()] = 1;
      l.push_back(int(target(g, mesh).idx()));
      length += std::sqrt(CGAL::squared_distance(mesh.point(source(g, mesh)), mesh.point(target(g, mesh))));
    }
    if(length > loop_length) { loop_length = length; loop = l; }
  }
  std::vector<dlf::Vec2> uv(n, dlf::Vec2{{ 0, 0 }});
  std::vector<int> boundary_of(n, -1);
  double s = 0;
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const double a = 2 * M_PI * s / loop_length;
    uv[std::size_t(loop[k])] = {{ std::cos(a), std::sin(a) }};
    boundary_of[std::size_t(loop[k])] = int(k);
    const dlf::Vec3 &p = xyz[std::size_t(loop[k])], &q = xyz[std::size_t(loop[(k + 1) % loop.size()])];
    s += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  std::vector<int> interior(n, -1);
  int ni = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(boundary_of[v] < 0) interior[v] = ni++;
  std::vector<Eigen::Triplet<double> > trip;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  for(Mesh::Vertex_index v : vertices(mesh)) {
    const int i = interior[v.idx()];
    if(i < 0) continue;
    double degree = 0;
    for(Mesh::Vertex_index w : vertices_around_target(halfedge(v, mesh), mesh)) {
      ++degree;
      if(interior[w.idx()] >= 0) trip.emplace_back(i, interior[w.idx()], -1.);
      else { rhs(i, 0) += uv[w.idx()][0]; rhs(i, 1) += uv[w.idx()][1]; }
    }
    trip.emplace_back(i, i, degree);
  }
  const dlf::Scoped_blas_threads threads(0, n); // the flow's automatic choice
  {
    dlf::Sparse_matrix T(ni, ni);
    T.setFromTriplets(trip.begin(), trip.end());
    dlf::Default_spd_solver tutte;
    tutte.compute(T);
    const Eigen::MatrixXd x = tutte.solve(rhs);
    for(std::size_t v = 0; v < n; ++v)
      if(interior[v] >= 0) uv[v] = {{ x(interior[v], 0), x(interior[v], 1) }};
  }
  // Counter-clockwise faces, as the flow makes them (else the cotangents change sign).
  double twice_area = 0;
  for(const dlf::Face& t : triangles) {
    const dlf::Vec2 &a = uv[std::size_t(t[0])], &b = uv[std::size_t(t[1])], &c = uv[std::size_t(t[2])];
    twice_area += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  if(twice_area < 0)
    for(dlf::Vec2& p : uv) p[1] = -p[1];
  // The flow's own assembly of the interior stiffness, then its solver.
  dlf::Default_spd_solver eigen_solver;
  dlf::Split_sobolev_direction<dlf::Default_spd_solver> sobolev(boundary_of, eigen_solver);
  sobolev.assemble(uv, triangles);
  Floor f;
  f.unknowns = std::size_t(ni);
  // Analysis and factorization apart: the Pattern_reusing_solver analyses on
  // its first factorization, which is timed whole, then factorizes again.
  Clock::time_point t0 = Clock::now();
  if(!sobolev.factorize()) return f;
  const double first = seconds_since(t0);
  t0 = Clock::now();
  sobolev.factorize();
  f.factorize = seconds_since(t0);
  f.analyse = (std::max)(0., first - f.factorize);
  std::vector<dlf::Vec2> g(n, dlf::Vec2{{ 1, 0.5 }}), tangent(n, dlf::Vec2{{ 0, 0 }}), d;
  t0 = Clock::now();
  sobolev.solve(g, tangent, d); // two solves of two columns each, as in an iteration
  f.solve = seconds_since(t0) / 2;
  return f;
}

// One `dlf disk` run as a user runs it, and what its report says.
struct Dlf_run
{
  Process_run process;
  nlohmann::json report;
};

Dlf_run run_dlf(const std::string& dlf, const std::string& off, const std::string& stem, const std::vector<std::string>& extra)
{
  Dlf_run r;
  std::vector<std::string> args = { dlf, "disk", off, "-o", stem + ".obj", "--report", stem + ".json", "--history" };
  args.insert(args.end(), extra.begin(), extra.end());
  r.process = run_process(args);
  std::ifstream in(stem + ".json");
  if(in) r.report = nlohmann::json::parse(in, nullptr, false);
  std::error_code ignored;
  std::filesystem::remove(stem + ".obj", ignored);
  std::filesystem::remove(stem + ".json", ignored);
  return r;
}

// The row of a run: iterations of each level, D_area, folds, times.
nlohmann::ordered_json run_row(const Dlf_run& r)
{
  nlohmann::ordered_json row;
  row["whole_process_seconds"] = r.process.seconds;
  row["cpu_seconds"] = r.process.cpu_seconds;
  row["exit_code"] = r.process.exit_code;
  row["max_rss_gib"] = r.process.max_rss_gib;
  row["max_rss_kib"] = r.process.max_rss_kib;
  const nlohmann::json& R = r.report;
  if(!R.is_object() || !R.contains("seconds")) return row;
  row["iterations"] = R["iterations"];
  row["d_area"] = R["final"]["d_area"];
  row["inverted"] = R["final"]["inverted_faces"];
  row["seconds"] = R["seconds"];
  row["levels"] = R.value("levels", nlohmann::json::array());
  // Per iteration of the finest level: after the first (which carries the
  // solver's symbolic analysis), from the history's elapsed times.
  const nlohmann::json& h = R["history"];
  const std::size_t k = h.is_array() ? h.size() : 0;
  row["seconds_per_iteration"] = k >= 2 ? (h[k - 1]["seconds"].get<double>() - h[0]["seconds"].get<double>()) / double(k - 1) : 0.;
  return row;
}

// The number of faces an OFF file's header declares.
std::size_t off_face_count(const std::string& path)
{
  std::ifstream in(path);
  std::string word;
  std::size_t vertices = 0, faces = 0;
  while(in >> word && word[0] == '#') std::getline(in, word);
  if(word != "OFF") return 0;
  while(in >> std::ws && in.peek() == '#') std::getline(in, word);
  in >> vertices >> faces;
  return faces;
}

double seconds_of(const nlohmann::ordered_json& row, const char* key)
{
  return row.contains("seconds") && row["seconds"].contains(key) ? row["seconds"][key].get<double>() : 0.;
}

} // namespace

int main(int argc, char** argv)
{
  namespace po = boost::program_options;
  std::string data_dir = DLF_DATA_DIR, dlf_path = "build/tools/dlf", work, json_path;
  std::vector<std::string> specs;
  bool floor = false, plain = true, keep = false;
  po::options_description desc("large_meshes [options] SPEC...  (SPEC: name.off[+loopK|+midK][+scramble])");
  desc.add_options()("help,h", "show this help")
    ("data-dir", po::value<std::string>(&data_dir), "directory with meshes/ (CGAL's data set)")
    ("dlf", po::value<std::string>(&dlf_path), "the dlf tool to time")
    ("work", po::value<std::string>(&work)->required(), "scratch directory for the meshes and outputs")
    ("json", po::value<std::string>(&json_path), "write every number to this JSON file")
    ("floor", po::bool_switch(&floor), "also measure one factorization and solve of the finest level's stiffness")
    ("no-plain", "do not run the plain flow (--coarse-to-fine-faces 0) beside the default")
    ("keep-meshes", po::bool_switch(&keep), "keep the OFF files written in --work (a later run reads them instead of making them)")
    ("spec", po::value<std::vector<std::string> >(&specs), "mesh specs");
  po::positional_options_description pos;
  pos.add("spec", -1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(desc).positional(pos).run(), vm);
    if(vm.count("help")) { std::cout << desc << "\n"; return 0; }
    po::notify(vm);
  } catch(const std::exception& e) {
    std::cerr << "large_meshes: " << e.what() << "\n";
    return 2;
  }
  plain = vm.count("no-plain") == 0;
  const std::filesystem::path meshes = dlf_benchmark::mesh_directory("large_meshes", data_dir);
  if(meshes.empty()) return 2;
  std::filesystem::create_directories(work);
  dlf_path = std::filesystem::absolute(dlf_path).string();

  std::cout << "load " << dlf_benchmark::loadavg() << "\n";
  std::printf("%-34s %9s %6s %9s %4s %7s %3s %8s %8s %6s %6s | %7s %6s %6s %6s | %4s %8s %6s %6s\n", "mesh", "faces",
              "levels", "coarse it", "it", "d_area", "inv", "whole s", "cpu s", "GiB", "KiB/f", "levels", "read", "init",
              "write", "it", "plain s", "GiB", "ratio");
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for(const std::string& spec_text : specs) {
    dlf_benchmark::Mesh_spec spec;
    std::string why;
    if(!dlf_benchmark::parse_mesh_spec(spec_text, spec, why)) { std::cerr << "large_meshes: " << why << "\n"; return 2; }
    const std::string stem = (std::filesystem::path(work) / spec_text).string();
    const std::string off = stem + ".off";
    // A mesh already there (from an earlier run, or kept by --keep-meshes)
    // is used and kept; one written here is removed once measured, as are
    // the outputs.
    const bool written = !std::filesystem::exists(off);
    std::size_t face_count = 0;
    {
      // The mesh lives in this scope only: the child gets the memory back.
      Mesh mesh;
      if(written && !CGAL::IO::read_polygon_mesh((meshes / spec.file).string(), mesh)) {
        std::cerr << "large_meshes: cannot read " << spec.file << "\n";
        return 2;
      }
      if(written) {
        dlf_benchmark::subdivide(mesh, spec);
        if(!CGAL::IO::write_polygon_mesh(off, mesh, CGAL::parameters::stream_precision(17))) {
          std::cerr << "large_meshes: cannot write " << off << "\n";
          return 2;
        }
        face_count = num_faces(mesh);
      } else {
        face_count = off_face_count(off);
      }
    }
    malloc_trim(0);
    struct rusage self;
    getrusage(RUSAGE_SELF, &self);
    nlohmann::ordered_json row;
    row["mesh"] = spec_text;
    row["faces"] = face_count;
    row["generation_max_rss_kib"] = self.ru_maxrss; // this process so far (the largest mesh made yet)
    row["default"] = run_row(run_dlf(dlf_path, off, stem, {}));
    if(plain) row["plain"] = run_row(run_dlf(dlf_path, off, stem + ".plain", { "--coarse-to-fine-faces", "0" }));
    if(floor) {
      Mesh mesh;
      if(!CGAL::IO::read_polygon_mesh(off, mesh)) {
        std::cerr << "large_meshes: cannot read " << off << "\n";
        return 2;
      }
      const Floor f = measure_floor(mesh);
      row["floor"] = { { "unknowns", f.unknowns }, { "analyse", f.analyse }, { "factorize", f.factorize }, { "solve", f.solve } };
    }
    std::error_code ignored;
    if(written && !keep) std::filesystem::remove(off, ignored);
    // Copies: an ordered_json object is a vector, and the ratio added below moves it.
    const nlohmann::ordered_json d = row["default"];
    const auto num = [](const nlohmann::ordered_json& j, const char* key) {
      return j.contains(key) && j[key].is_number() ? j[key].get<double>() : 0.;
    };
    const nlohmann::ordered_json levels = d.contains("levels") ? d["levels"] : nlohmann::ordered_json::array();
    double level_seconds = seconds_of(d, "levels");
    for(const auto& l : levels) level_seconds += num(l, "seconds");
    const nlohmann::ordered_json none = nlohmann::ordered_json::object();
    const nlohmann::ordered_json p = plain ? row["plain"] : none;
    const double plain_seconds = num(p, "whole_process_seconds");
    row["ratio_to_plain"] = plain_seconds > 0 ? num(d, "whole_process_seconds") / plain_seconds : 0.;
    all.push_back(row);
    std::printf("%-34s %9zu %6zu %9d %4d %7.4f %3d %8.2f %8.2f %6.2f %6.3f | %7.2f %6.2f %6.2f %6.2f | %4d %8.2f %6.2f %6.3f\n",
                spec_text.c_str(), face_count, levels.size(), levels.empty() ? 0 : int(num(levels.front(), "iterations")),
                int(num(d, "iterations")), num(d, "d_area"), int(num(d, "inverted")), num(d, "whole_process_seconds"),
                num(d, "cpu_seconds"), num(d, "max_rss_gib"), face_count > 0 ? num(d, "max_rss_kib") / double(face_count) : 0., level_seconds, seconds_of(d, "read"), seconds_of(d, "initial"), seconds_of(d, "write"),
                int(num(p, "iterations")), plain_seconds, num(p, "max_rss_gib"), num(row, "ratio_to_plain"));
    if(written)
      std::printf("%-34s this process's max RSS after making it: %.2f GiB\n", "", double(self.ru_maxrss) / (1024. * 1024.));
    std::fflush(stdout);
  }
  std::cout << "load " << dlf_benchmark::loadavg() << "\n";
  if(!json_path.empty()) std::ofstream(json_path) << all.dump(2) << "\n";
  return 0;
}
