// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: clocks, number formatting, option lists,
// and the mesh specs "name.off+loopK" / "name.off+midK" (K steps of Loop or
// midpoint subdivision of a mesh of CGAL's data set).

#ifndef DLF_BENCHMARK_UTILITIES_H
#define DLF_BENCHMARK_UTILITIES_H

#include <CGAL/subdivision_method_3.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Kernel_traits.h>

#include <boost/program_options.hpp>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace dlf_benchmark {

typedef std::chrono::steady_clock Clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// CPU time of the process (all threads): less sensitive than wall time to
/// the other jobs of a shared machine, but it counts idle-spinning threads.
inline double cpu_now()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

inline double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline std::string fmt(double x, int prec = 3)
{
  if(!std::isfinite(x)) return "nan";
  std::ostringstream s;
  const double a = std::abs(x);
  if(a != 0 && (a < 1e-3 || a >= 1e6)) s << std::setprecision(prec) << x;
  else s << std::fixed << std::setprecision(prec) << x;
  return s.str();
}

inline std::string fmt_time(double t)
{
  std::ostringstream s;
  s << std::setprecision(3) << t;
  return s.str();
}

inline std::string loadavg()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

/// "a, b,,c" → {"a", "b", "c"} (blanks dropped).
inline std::vector<std::string> split(const std::string& s, char sep = ',')
{
  std::vector<std::string> out;
  std::string cur;
  for(char c : s) {
    if(c == sep) { if(!cur.empty()) out.push_back(cur); cur.clear(); }
    else if(c != ' ') cur += c;
  }
  if(!cur.empty()) out.push_back(cur);
  return out;
}

/// Parses the command line into `vm`. Returns −1 to go on, or the exit
/// status: 0 after printing the help (--help), 2 after reporting an error.
inline int parse_options(const char* program, const boost::program_options::options_description& desc,
                         int argc, char** argv, boost::program_options::variables_map& vm)
{
  try {
    boost::program_options::store(boost::program_options::parse_command_line(argc, argv, desc), vm);
    boost::program_options::notify(vm);
  } catch(const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  }
  if(vm.count("help")) { std::cout << desc << "\n"; return 0; }
  return -1;
}

/// `data_dir`/meshes, absolute; empty (and reported) when it is no directory.
inline std::filesystem::path mesh_directory(const char* program, const std::string& data_dir)
{
  const std::filesystem::path dir = std::filesystem::absolute(std::filesystem::path(data_dir) / "meshes");
  if(std::filesystem::is_directory(dir)) return dir;
  std::cerr << program << ": no directory " << dir << "\n";
  return std::filesystem::path();
}

/// A mesh spec: "name.off", then "+loopK" or "+midK" (subdivided), then
/// "+scramble" (a share of the interior edges flipped and the interior
/// vertices moved inside their rings: no longer a subdivision).
struct Mesh_spec
{
  std::string file;
  int loops = 0, midpoints = 0;
  bool scramble = false;
};

/// False, with `why`, for an unknown suffix.
inline bool parse_mesh_spec(const std::string& spec, Mesh_spec& out, std::string& why)
{
  out = Mesh_spec();
  std::size_t plus = spec.find('+');
  out.file = spec.substr(0, plus);
  while(plus != std::string::npos) {
    const std::size_t next = spec.find('+', plus + 1);
    const std::string how = spec.substr(plus + 1, next == std::string::npos ? std::string::npos : next - plus - 1);
    if(how.rfind("loop", 0) == 0) out.loops = std::atoi(how.c_str() + 4);
    else if(how.rfind("mid", 0) == 0) out.midpoints = std::atoi(how.c_str() + 3);
    else if(how == "scramble") out.scramble = true;
    else { why = "unknown mesh suffix '" + how + "'"; return false; }
    plus = next;
  }
  return true;
}

/// Flips about 30% of the interior edges (those whose quad is convex about
/// its normal and whose new triangles are not needles) and moves each
/// interior vertex by up to 15% of its shortest edge: the same surface, the
/// regular valences and nested structure of a subdivision gone. A fixed
/// seed: the same mesh every run.
template <class SurfaceMesh>
void scramble(SurfaceMesh& mesh)
{
  typedef typename SurfaceMesh::Point Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::vector<typename SurfaceMesh::Edge_index> edges(mesh.edges().begin(), mesh.edges().end());
  for(const auto e : edges) {
    if(unit(random) > 0.3 || mesh.is_border(e)) continue;
    const auto h = mesh.halfedge(e);
    const auto a = mesh.target(h), b = mesh.source(h), c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(mesh.opposite(h)));
    bool joined = c == d;
    for(const auto x : CGAL::vertices_around_target(c, mesh)) joined = joined || x == d;
    if(joined) continue;
    const Point &pa = mesh.point(a), &pb = mesh.point(b), &pc = mesh.point(c), &pd = mesh.point(d);
    const Vector n = CGAL::cross_product(pb - pa, pc - pa) + CGAL::cross_product(pa - pb, pd - pb);
    const auto side = [&](const Point& p, const Point& q, const Point& r) { return CGAL::cross_product(q - p, r - p) * n; };
    const auto twice_area = [](const Point& p, const Point& q, const Point& r) {
      return std::sqrt(CGAL::to_double(CGAL::cross_product(q - p, r - p).squared_length()));
    };
    const double cd = CGAL::to_double((pc - pd).squared_length());
    if(!(side(pc, pd, pa) * side(pc, pd, pb) < 0 && side(pa, pb, pc) * side(pa, pb, pd) < 0)) continue;
    if(twice_area(pc, pd, pa) < 0.2 * cd || twice_area(pd, pc, pb) < 0.2 * cd) continue;
    CGAL::Euler::flip_edge(h, mesh);
  }
  for(const auto v : mesh.vertices()) {
    if(mesh.is_border(v)) continue;
    double shortest = std::numeric_limits<double>::infinity();
    for(const auto h : CGAL::halfedges_around_target(v, mesh))
      shortest = (std::min)(shortest, CGAL::to_double((mesh.point(mesh.source(h)) - mesh.point(v)).squared_length()));
    const double r = 0.15 * std::sqrt(shortest);
    mesh.point(v) = mesh.point(v) + Vector(r * (2 * unit(random) - 1), r * (2 * unit(random) - 1), r * (2 * unit(random) - 1));
  }
}

/// Splits every triangle into four at its edges' midpoints: the same surface,
/// with triangles similar to the input's (Loop subdivision also smooths).
template <class SurfaceMesh>
void midpoint_subdivision(SurfaceMesh& mesh)
{
  typedef typename SurfaceMesh::Vertex_index Vertex;
  SurfaceMesh out;
  std::map<Vertex, Vertex> old;
  std::map<std::pair<Vertex, Vertex>, Vertex> middle;
  for(Vertex v : vertices(mesh)) old[v] = out.add_vertex(mesh.point(v));
  const auto mid = [&](Vertex a, Vertex b) {
    const auto key = std::minmax(a, b);
    const auto it = middle.find(key);
    if(it != middle.end()) return it->second;
    return middle[key] = out.add_vertex(CGAL::midpoint(mesh.point(a), mesh.point(b)));
  };
  for(typename SurfaceMesh::Face_index f : faces(mesh)) {
    const typename SurfaceMesh::Halfedge_index h = halfedge(f, mesh);
    const Vertex a = source(h, mesh), b = target(h, mesh), c = target(next(h, mesh), mesh);
    const Vertex ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.add_face(old[a], ab, ca);
    out.add_face(ab, old[b], bc);
    out.add_face(ca, bc, old[c]);
    out.add_face(ab, bc, ca);
  }
  mesh = std::move(out);
}

/// The subdivision steps of `spec`, applied to the mesh read from its file.
template <class SurfaceMesh>
void subdivide(SurfaceMesh& mesh, const Mesh_spec& spec)
{
  if(spec.loops > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(spec.loops));
  for(int k = 0; k < spec.midpoints; ++k) midpoint_subdivision(mesh);
  if(spec.scramble) scramble(mesh);
}

} // namespace dlf_benchmark

#endif
