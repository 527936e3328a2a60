// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Robustness study: a deterministic corpus of hostile inputs derived
// from CGAL's data set and from generated meshes, run through `dlf disk`,
// `dlf sphere` (subprocesses with a timeout and a memory limit), CGAL's
// iterative authalic, ARAP and mean-value parameterizers and the DLF library
// API with folding initial maps (in forked children, so that a crash or hang
// of one method is recorded instead of ending the study).
//
//   robustness_corpus --dlf build/examples/dlf --data build/data/meshes \
//       --scratch /tmp/dlf_robustness --json results.json --markdown table.md
//
// Every case is written as an OFF file in <scratch>/corpus/ (kept, so a
// failure can be replayed by hand). Per case x method it records: status
// (ok, an error name, crash(SIGNAL), hang), the error message, faces whose
// orientation (exact CGAL::orientation on the output doubles) differs from
// the majority or is zero, non-finite output values, d_area of the output
// (computed here the same way for every method), time, and a stray output
// file left by a failed CLI run.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace SMP = CGAL::Surface_mesh_parameterization;
using json = nlohmann::json;

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<SM>::halfedge_descriptor halfedge_descriptor;
typedef CGAL::Epick EK; // exact predicates on doubles

namespace {

typedef std::array<double, 3> P3;
struct Mesh
{
  std::vector<P3> V;
  std::vector<std::vector<int> > F;
};

// ---------------------------------------------------------------- mesh I/O
Mesh read_off_plain(const std::string& path)
{
  std::ifstream in(path);
  std::string h;
  in >> h;
  std::size_t nv, nf, ne;
  in >> nv >> nf >> ne;
  Mesh m;
  m.V.resize(nv);
  for(P3& p : m.V) in >> p[0] >> p[1] >> p[2];
  for(std::size_t f = 0; f < nf; ++f) {
    int k;
    in >> k;
    std::vector<int> t(static_cast<std::size_t>(k));
    for(int& i : t) in >> i;
    m.F.push_back(t);
  }
  if(!in) throw std::runtime_error("cannot read " + path);
  return m;
}

std::string num(double x)
{
  if(std::isnan(x)) return "nan";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string off_text(const Mesh& m)
{
  std::ostringstream s;
  s << "OFF\n" << m.V.size() << " " << m.F.size() << " 0\n";
  for(const P3& p : m.V) s << num(p[0]) << " " << num(p[1]) << " " << num(p[2]) << "\n";
  for(const auto& f : m.F) {
    s << f.size();
    for(int i : f) s << " " << i;
    s << "\n";
  }
  return s.str();
}

// ---------------------------------------------------------------- generators
Mesh grid(int n) // (n+1)^2 vertices on [0,n]^2, z = 0, exactly representable
{
  Mesh m;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) m.V.push_back({{ double(i), double(j), 0.25 * ((i * 7 + j * 3) % 5) }});
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      m.F.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.F.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  return m;
}

Mesh torus(int a, int b)
{
  Mesh m;
  for(int j = 0; j < b; ++j)
    for(int i = 0; i < a; ++i) {
      const double u = 2 * M_PI * i / a, v = 2 * M_PI * j / b;
      m.V.push_back({{ (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v) }});
    }
  auto id = [a, b](int i, int j) { return (j % b) * a + (i % a); };
  for(int j = 0; j < b; ++j)
    for(int i = 0; i < a; ++i) {
      m.F.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.F.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  return m;
}

std::set<int> boundary_vertices(const Mesh& m)
{
  std::map<std::pair<int, int>, int> e;
  for(const auto& f : m.F)
    for(std::size_t k = 0; k < f.size(); ++k) e[{ std::min(f[k], f[(k + 1) % f.size()]), std::max(f[k], f[(k + 1) % f.size()]) }]++;
  std::set<int> b;
  for(const auto& x : e)
    if(x.second == 1) { b.insert(x.first.first); b.insert(x.first.second); }
  return b;
}

// The k-th interior vertex counted from the middle of the index range (deterministic).
int interior_vertex(const Mesh& m, int k = 0)
{
  const std::set<int> b = boundary_vertices(m);
  std::vector<bool> used(m.V.size(), false);
  for(const auto& f : m.F) for(int i : f) used[std::size_t(i)] = true;
  int seen = 0;
  for(std::size_t s = 0; s < m.V.size(); ++s) {
    const int v = int((m.V.size() / 2 + s * 37) % m.V.size());
    if(!b.count(v) && used[std::size_t(v)] && seen++ == k) return v;
  }
  return 0;
}

std::vector<int> star(const Mesh& m, int v)
{
  std::vector<int> s;
  for(std::size_t f = 0; f < m.F.size(); ++f)
    if(std::find(m.F[f].begin(), m.F[f].end(), v) != m.F[f].end()) s.push_back(int(f));
  return s;
}

// The two other corners of face f, in face order after v.
std::pair<int, int> others(const std::vector<int>& f, int v)
{
  const std::size_t k = std::size_t(std::find(f.begin(), f.end(), v) - f.begin());
  return { f[(k + 1) % 3], f[(k + 2) % 3] };
}

double mean_edge(const Mesh& m)
{
  double s = 0;
  std::size_t n = 0;
  for(const auto& f : m.F)
    for(std::size_t k = 0; k < f.size(); ++k) {
      const P3 &a = m.V[std::size_t(f[k])], &b = m.V[std::size_t(f[(k + 1) % f.size()])];
      s += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
      ++n;
    }
  return n ? s / double(n) : 1;
}

P3 lerp(const P3& a, const P3& b, double t) { return {{ a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t }}; }

Mesh transform(Mesh m, const std::function<void(P3&)>& f) { for(P3& p : m.V) f(p); return m; }

// Remove `count` interior faces that share no vertex with each other or the boundary (new holes).
Mesh punch(Mesh m, int count)
{
  const std::set<int> b = boundary_vertices(m);
  std::set<int> touched(b.begin(), b.end());
  std::vector<std::size_t> drop;
  for(std::size_t s = 0; s < m.F.size() && int(drop.size()) < count; ++s) {
    const std::size_t f = (m.F.size() / 3 + s * 53) % m.F.size();
    bool ok = true;
    for(int i : m.F[f]) {
      if(touched.count(i)) ok = false;
      for(int g : star(m, i)) for(int j : m.F[std::size_t(g)]) if(touched.count(j)) ok = false;
    }
    if(!ok) continue;
    drop.push_back(f);
    for(int i : m.F[f]) for(int g : star(m, i)) for(int j : m.F[std::size_t(g)]) touched.insert(j);
  }
  std::sort(drop.rbegin(), drop.rend());
  for(std::size_t f : drop) m.F.erase(m.F.begin() + long(f));
  return m;
}

// Split interior vertex v: half of its fan uses a copy at v + offset (a slit / extra boundary).
Mesh split_vertex(Mesh m, double offset)
{
  const int v = interior_vertex(m);
  const std::vector<int> s = star(m, v);
  const int w = int(m.V.size());
  P3 p = m.V[std::size_t(v)];
  p[0] += offset;
  m.V.push_back(p);
  // walk the fan in order so that the first half is contiguous
  std::vector<int> order(1, s[0]);
  std::set<int> left(s.begin() + 1, s.end());
  while(!left.empty()) {
    const int last = others(m.F[std::size_t(order.back())], v).second;
    int next = -1;
    for(int g : left) if(others(m.F[std::size_t(g)], v).first == last) next = g;
    if(next < 0) break;
    order.push_back(next);
    left.erase(next);
  }
  for(std::size_t k = 0; k < order.size() / 2; ++k)
    for(int& i : m.F[std::size_t(order[k])]) if(i == v) i = w;
  return m;
}

struct Case
{
  std::string cls, name, kind, file; // kind: disk | sphere | api
  std::string text;                  // OFF (or raw bytes)
  int api_variant = -1;              // for kind api: which folding initial map
  std::string base;                  // for kind api: the base OFF file
};

std::vector<Case> make_corpus(const std::string& data)
{
  std::vector<Case> C;
  const Mesh nef = read_off_plain(data + "/nefertiti.off");
  const Mesh mush = read_off_plain(data + "/mushroom.off");
  const Mesh sph = read_off_plain(data + "/sphere.off");
  const Mesh cow = read_off_plain(data + "/cow.off");
  const Mesh g = grid(8);
  auto add = [&C](const std::string& cls, const std::string& name, const std::string& kind, const std::string& text) {
    Case c;
    c.cls = cls; c.name = name; c.kind = kind; c.text = text;
    C.push_back(c);
  };
  struct Base { std::string name; const Mesh* m; std::string kind; };
  const std::vector<Base> disks = { { "nefertiti", &nef, "disk" }, { "grid8", &g, "disk" } };
  const std::vector<Base> all = { { "nefertiti", &nef, "disk" }, { "grid8", &g, "disk" }, { "sphere", &sph, "sphere" } };

  add("baseline", "nefertiti", "disk", off_text(nef));
  add("baseline", "mushroom", "disk", off_text(mush));
  add("baseline", "grid8", "disk", off_text(g));
  add("baseline", "sphere", "sphere", off_text(sph));
  add("baseline", "cow", "sphere", off_text(cow));

  for(const Base& b : all) {
    const Mesh& m = *b.m;
    const int v = interior_vertex(m);
    const std::vector<int> s = star(m, v);
    const std::pair<int, int> bc = others(m.F[std::size_t(s[0])], v);
    const P3 pb = m.V[std::size_t(bc.first)], pc = m.V[std::size_t(bc.second)];
    for(double eps : { 1e-4, 1e-9, 1e-14 }) {
      Mesh x = m; // needle: edge (v, b) collapses towards b
      x.V[std::size_t(v)] = lerp(pb, m.V[std::size_t(v)], eps);
      add("needle", b.name + "_eps" + num(eps), b.kind, off_text(x));
      Mesh y = m; // cap: v flattened onto the opposite edge (b, c)
      y.V[std::size_t(v)] = lerp(lerp(pb, pc, 0.5), m.V[std::size_t(v)], eps);
      add("cap", b.name + "_eps" + num(eps), b.kind, off_text(y));
    }
    { Mesh x = m; x.V[std::size_t(v)] = pb; add("zero_area", b.name + "_coincident", b.kind, off_text(x)); }
    { Mesh x = m; x.V[std::size_t(v)] = lerp(pb, pc, 0.5); add("zero_area", b.name + "_collinear_mid", b.kind, off_text(x)); }
    { // several zero-area faces at once (3 vertices collapsed onto a neighbour)
      Mesh x = m;
      for(int k = 0; k < 3; ++k) {
        const int w = interior_vertex(m, 5 * k + 1);
        x.V[std::size_t(w)] = m.V[std::size_t(others(m.F[std::size_t(star(m, w)[0])], w).first)];
      }
      add("zero_area", b.name + "_three", b.kind, off_text(x));
    }
    { Mesh x = m; x.V.push_back(m.V[0]); add("duplicate_vertex", b.name + "_unreferenced_copy", b.kind, off_text(x)); }
    add("duplicate_vertex", b.name + "_split_exact", b.kind, off_text(split_vertex(m, 0)));
    add("duplicate_vertex", b.name + "_split_1e-12", b.kind, off_text(split_vertex(m, 1e-12)));
    add("aspect", b.name + "_x1e4", b.kind, off_text(transform(m, [](P3& p) { p[0] *= 1e4; })));
    add("aspect", b.name + "_z1e-6", b.kind, off_text(transform(m, [](P3& p) { p[2] *= 1e-6; })));
    add("aspect", b.name + "_y1e-9", b.kind, off_text(transform(m, [](P3& p) { p[1] *= 1e-9; })));
    for(double sc : { 1e-8, 1e8, 1e-160, 1e160 })
      add("scale", b.name + "_" + num(sc), b.kind, off_text(transform(m, [sc](P3& p) { for(double& c : p) c *= sc; })));
    for(double off : { 1e6, 1e12 })
      add("offset", b.name + "_" + num(off), b.kind, off_text(transform(m, [off](P3& p) { for(double& c : p) c += off; })));
    const double h = mean_edge(m);
    for(double amp : { 0.01, 0.3 }) {
      std::mt19937_64 rng(20260 + std::uint64_t(amp * 1000));
      std::normal_distribution<double> N(0, amp * h);
      add("noise", b.name + "_" + num(amp), b.kind, off_text(transform(m, [&](P3& p) { for(double& c : p) c += N(rng); })));
    }
    const double bad[] = { std::nan(""), HUGE_VAL, -HUGE_VAL };
    const char* bad_name[] = { "nan", "inf", "-inf" };
    for(int k = 0; k < 3; ++k) { Mesh x = m; x.V[std::size_t(v)][1] = bad[k]; add("nonfinite", b.name + "_" + bad_name[k], b.kind, off_text(x)); }
    { std::string t = off_text(m); const std::string key = "\n" + num(m.V[0][0]) + " ";
      t.replace(t.find(key), key.size(), "\n1e400 "); add("nonfinite", b.name + "_1e400_text", b.kind, t); }
    { Mesh x = m; const int w = int(x.V.size()); P3 p = lerp(pb, pc, 0.5); p[2] += h; x.V.push_back(p);
      x.F.push_back({ bc.second, bc.first, w }); add("nonmanifold", b.name + "_edge3faces", b.kind, off_text(x)); }
    { Mesh x = m; const int w = int(x.V.size()); P3 p = m.V[std::size_t(v)];
      x.V.push_back({{ p[0] + h, p[1], p[2] + h }}); x.V.push_back({{ p[0], p[1] + h, p[2] + h }});
      x.F.push_back({ v, w, w + 1 }); add("nonmanifold", b.name + "_vertex_bowtie", b.kind, off_text(x)); }
    add("holes", b.name + "_1", b.kind, off_text(punch(m, 1)));
    add("holes", b.name + "_3", b.kind, off_text(punch(m, 3)));
    { Mesh x = m; for(int k = 0; k < 3; ++k) x.V.push_back({{ 10.0 + k, 0.0, 0.0 }}); add("isolated_vertex", b.name + "_3", b.kind, off_text(x)); }
    { Mesh x = m; x.F.push_back(m.F[std::size_t(s[0])]); add("duplicate_face", b.name + "_same", b.kind, off_text(x)); }
    { Mesh x = m; std::vector<int> f = m.F[std::size_t(s[0])]; std::swap(f[1], f[2]); x.F.push_back(f);
      add("duplicate_face", b.name + "_reversed", b.kind, off_text(x)); }
    { Mesh x = m; std::swap(x.F[std::size_t(s[0])][1], x.F[std::size_t(s[0])][2]); add("orientation", b.name + "_one_flipped", b.kind, off_text(x)); }
    { Mesh x = m; for(std::size_t f = 0; f < x.F.size() / 2; ++f) std::swap(x.F[f][1], x.F[f][2]);
      add("orientation", b.name + "_half_flipped", b.kind, off_text(x)); }
    { Mesh x = m; for(auto& f : x.F) std::swap(f[1], f[2]); add("orientation", b.name + "_all_flipped", b.kind, off_text(x)); }
    { const std::string t = off_text(m); add("malformed", b.name + "_truncated_60pct", b.kind, t.substr(0, t.size() * 6 / 10));
      add("malformed", b.name + "_truncated_in_header_of_faces", b.kind, t.substr(0, t.find('\n', t.size() * 9 / 10)) + "\n3 1"); }
  }
  // Sphere-only and disk-only topology classes.
  { Mesh x = punch(sph, 1); add("holes", "sphere_as_disk_input", "disk", off_text(x)); }
  add("topology", "sphere_to_disk", "disk", off_text(sph));
  add("topology", "grid_to_sphere", "sphere", off_text(g));
  add("topology", "torus_to_sphere", "sphere", off_text(torus(12, 8)));
  { Mesh t = torus(12, 8); t.F.erase(t.F.begin()); add("topology", "holed_torus_to_disk", "disk", off_text(t)); }
  { Mesh x = sph; const std::size_t n = x.V.size();
    for(std::size_t i = 0; i < n; ++i) x.V.push_back({{ sph.V[i][0] + 5, sph.V[i][1], sph.V[i][2] }});
    for(std::size_t f = 0; f < sph.F.size(); ++f) x.F.push_back({ sph.F[f][0] + int(n), sph.F[f][1] + int(n), sph.F[f][2] + int(n) });
    add("topology", "two_spheres", "sphere", off_text(x));
    Mesh y = g; const std::size_t m = y.V.size();
    for(std::size_t i = 0; i < m; ++i) y.V.push_back({{ g.V[i][0] + 20, g.V[i][1], g.V[i][2] }});
    for(std::size_t f = 0; f < g.F.size(); ++f) y.F.push_back({ g.F[f][0] + int(m), g.F[f][1] + int(m), g.F[f][2] + int(m) });
    add("topology", "two_disks", "disk", off_text(y)); }
  { Mesh x; x.V = { {{0,0,0}}, {{1,0,0}}, {{0,1,0}} }; x.F = { {0,1,2} }; add("tiny", "one_triangle", "disk", off_text(x));
    x.V.push_back({{1,1,0}}); x.F.push_back({1,3,2}); add("tiny", "two_triangles", "disk", off_text(x));
    Mesh q; q.V = x.V; q.F = { {0,1,3,2} }; add("tiny", "one_quad", "disk", off_text(q));
    Mesh t; t.V = { {{0,0,0}}, {{1,0,0}}, {{0,1,0}}, {{0,0,1}} }; t.F = { {0,2,1}, {0,1,3}, {0,3,2}, {1,2,3} };
    add("tiny", "tetrahedron", "sphere", off_text(t));
    Mesh f3; f3.V = { {{0,0,0}}, {{1,0,0}}, {{2,0,0}} }; f3.F = { {0,1,2} }; add("tiny", "one_flat_triangle", "disk", off_text(f3)); }
  { Mesh x = g; x.F.push_back({ 0, 1, 2, 3 }); add("malformed", "grid8_quad_face", "disk", off_text(x)); }
  // Hand-made malformed files.
  const std::vector<std::pair<std::string, std::string> > bad_files = {
    { "empty", "" }, { "header_only", "OFF\n" }, { "counts_only", "OFF\n3 1 0\n" },
    { "index_out_of_range", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n" },
    { "negative_index", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n" },
    { "two_vertex_face", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n" },
    { "repeated_index_face", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n" },
    { "garbage_coordinate", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n" },
    { "huge_counts", "OFF\n2000000000 2000000000 0\n0 0 0\n" },
    { "negative_counts", "OFF\n-3 -1 0\n" },
    { "no_faces", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n" },
    { "face_count_too_high", "OFF\n3 5 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" },
  };
  for(const auto& bf : bad_files) { add("malformed", bf.first, "disk", bf.second); add("malformed", bf.first, "sphere", bf.second); }
  { std::mt19937_64 rng(7); std::string t = "OFF\n"; for(int i = 0; i < 512; ++i) t += char(rng() & 0xff);
    add("malformed", "binary_garbage", "disk", t); add("malformed", "binary_garbage", "sphere", t); }
  // Initial maps that already fold (library API, Tutte map then perturbed).
  const char* api_names[] = { "vertex_reflected", "two_vertices_coincide", "all_collapsed", "nan_uv", "mirrored", "identity_tutte" };
  for(int k = 0; k < 6; ++k) {
    Case c;
    c.cls = "folded_initial_map"; c.name = std::string("nefertiti_") + api_names[k]; c.kind = "api";
    c.api_variant = k; c.text = off_text(nef);
    C.push_back(c);
  }
  // Exact-certification ablation: a cap whose 3D height is far below the
  // rounding level of the map's coordinates (grid8 moved so that the cap's
  // base midpoint is the origin, where 1e-30 is representable), with an
  // initial map that already has the cap at the rounding level.
  for(double eps : { 1e-20, 1e-30 }) {
    Mesh x = g;
    const int v = interior_vertex(x);
    const std::pair<int, int> bc = others(x.F[std::size_t(star(x, v)[0])], v);
    const P3 mid = lerp(x.V[std::size_t(bc.first)], x.V[std::size_t(bc.second)], 0.5);
    for(P3& p : x.V) for(int i = 0; i < 3; ++i) p[std::size_t(i)] -= mid[std::size_t(i)];
    for(double& q : x.V[std::size_t(v)]) q *= eps;
    Case c;
    c.cls = "rounding_level_sliver"; c.name = "grid8_cap_origin_eps" + num(eps); c.kind = "api";
    c.api_variant = 6; c.text = off_text(x);
    C.push_back(c);
  }
  return C;
}

// ---------------------------------------------------------------- processes
struct Proc { int code = -1; int sig = 0; bool timeout = false; double seconds = 0; };

void limit_child()
{
  struct rlimit r;
  r.rlim_cur = r.rlim_max = rlim_t(4) << 30; // 4 GiB of address space
  setrlimit(RLIMIT_AS, &r);
}

// Waits for pid for at most `timeout` seconds; kills it (SIGKILL) after that.
Proc wait_for(pid_t pid, double timeout, std::chrono::steady_clock::time_point t0)
{
  Proc p;
  int st = 0;
  for(;;) {
    const pid_t r = waitpid(pid, &st, WNOHANG);
    if(r == pid) break;
    if(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout) {
      kill(pid, SIGKILL);
      waitpid(pid, &st, 0);
      p.timeout = true;
      break;
    }
    usleep(2000);
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if(WIFEXITED(st)) p.code = WEXITSTATUS(st);
  if(WIFSIGNALED(st)) p.sig = WTERMSIG(st);
  return p;
}

Proc run_command(const std::vector<std::string>& argv, double timeout, const std::string& err_file)
{
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid == 0) {
    limit_child();
    const int dn = open("/dev/null", O_WRONLY);
    const int ef = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(dn, 1);
    dup2(ef, 2);
    std::vector<char*> a;
    for(const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    execv(a[0], a.data());
    _exit(127);
  }
  return wait_for(pid, timeout, t0);
}

// Runs f in a forked child (cwd = dir, stdout silenced); its JSON comes back through a file.
json run_forked(const std::function<json()>& f, double timeout, const std::string& dir)
{
  const std::string out = dir + "/child_result.json";
  fs::remove(out);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid == 0) {
    limit_child();
    if(chdir(dir.c_str()) != 0) _exit(126);
    const int dn = open("/dev/null", O_WRONLY);
    dup2(dn, 1);
    dup2(dn, 2);
    json r;
    try { r = f(); } catch(const std::exception& e) { r = { { "status", "exception" }, { "message", e.what() } }; }
    catch(...) { r = { { "status", "exception" }, { "message", "unknown exception" } }; }
    std::ofstream(out) << r.dump();
    _exit(0);
  }
  const Proc p = wait_for(pid, timeout, t0);
  json r;
  if(p.timeout) r = { { "status", "hang" } };
  else if(p.sig) r = { { "status", std::string("crash(") + strsignal(p.sig) + ")" } };
  else {
    std::ifstream in(out);
    try { in >> r; } catch(...) { r = { { "status", "crash(no result)" } }; }
  }
  r["seconds"] = p.seconds;
  return r;
}

// ---------------------------------------------------------------- measures
struct Map_check { std::size_t inverted = 0, degenerate = 0; bool nonfinite = false; bool mirrored = false; double d_area = 0; };

// Faces of the map are counted against the majority orientation (a globally
// mirrored map is a bijection too); zero-orientation faces count as degenerate.
Map_check check_planar(const std::vector<std::array<double, 2> >& uv, const std::vector<P3>& xyz,
                       const std::vector<std::array<int, 3> >& F)
{
  Map_check c;
  for(const auto& p : uv) if(!std::isfinite(p[0]) || !std::isfinite(p[1])) c.nonfinite = true;
  if(c.nonfinite) return c;
  std::size_t pos = 0, neg = 0;
  std::vector<double> a2(F.size()), a3(F.size());
  for(std::size_t f = 0; f < F.size(); ++f) {
    const auto &a = uv[std::size_t(F[f][0])], &b = uv[std::size_t(F[f][1])], &d = uv[std::size_t(F[f][2])];
    const CGAL::Orientation o = CGAL::orientation(EK::Point_2(a[0], a[1]), EK::Point_2(b[0], b[1]), EK::Point_2(d[0], d[1]));
    if(o == CGAL::POSITIVE) ++pos; else if(o == CGAL::NEGATIVE) ++neg; else ++c.degenerate;
    a2[f] = 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    const P3 &p = xyz[std::size_t(F[f][0])], &q = xyz[std::size_t(F[f][1])], &r = xyz[std::size_t(F[f][2])];
    const double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] }, v[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    a3[f] = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  c.mirrored = neg > pos;
  c.inverted = std::min(pos, neg);
  double s2 = 0, s3 = 0;
  for(std::size_t f = 0; f < F.size(); ++f) { s2 += (c.mirrored ? -a2[f] : a2[f]); s3 += a3[f]; }
  for(std::size_t f = 0; f < F.size(); ++f) {
    const double r = ((c.mirrored ? -a2[f] : a2[f]) / s2) / (a3[f] / s3);
    c.d_area += (a3[f] / s3) * (r > 0 ? r + 1 / r : HUGE_VAL);
  }
  if(!std::isfinite(c.d_area)) c.d_area = -1; // undefined (a face with non-positive area)
  return c;
}

Map_check check_sphere(const std::vector<P3>& p, const std::vector<std::array<int, 3> >& F)
{
  Map_check c;
  for(const auto& x : p) for(double v : x) if(!std::isfinite(v)) c.nonfinite = true;
  if(c.nonfinite) return c;
  std::size_t pos = 0, neg = 0;
  const EK::Point_3 O(0, 0, 0);
  for(const auto& f : F) {
    const P3 &a = p[std::size_t(f[0])], &b = p[std::size_t(f[1])], &d = p[std::size_t(f[2])];
    const CGAL::Orientation o = CGAL::orientation(O, EK::Point_3(a[0], a[1], a[2]), EK::Point_3(b[0], b[1], b[2]), EK::Point_3(d[0], d[1], d[2]));
    if(o == CGAL::POSITIVE) ++pos; else if(o == CGAL::NEGATIVE) ++neg; else ++c.degenerate;
  }
  c.mirrored = neg > pos;
  c.inverted = std::min(pos, neg);
  c.d_area = -1;
  return c;
}

// Reads an OBJ written by dlf: v (xyz or sphere points), vt (uv), f a/a b/b c/c.
bool read_obj(const std::string& path, std::vector<P3>& v, std::vector<std::array<double, 2> >& vt,
              std::vector<std::array<int, 3> >& F)
{
  std::ifstream in(path);
  if(!in) return false;
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream s(line);
    std::string k;
    s >> k;
    auto rd = [&s]() { std::string t; s >> t; return std::strtod(t.c_str(), nullptr); };
    if(k == "v") { P3 p; p[0] = rd(); p[1] = rd(); p[2] = rd(); v.push_back(p); }
    else if(k == "vt") { std::array<double, 2> p; p[0] = rd(); p[1] = rd(); vt.push_back(p); }
    else if(k == "f") {
      std::array<int, 3> t;
      for(int& i : t) { std::string w; s >> w; i = std::atoi(w.c_str()) - 1; }
      F.push_back(t);
    }
  }
  for(const auto& t : F) for(int i : t) if(i < 0 || std::size_t(i) >= v.size()) return false;
  return true;
}

// ---------------------------------------------------------------- methods
json run_dlf(const std::string& dlf, const Case& c, const std::string& file, const std::string& dir,
             const std::string& mode, double timeout)
{
  const std::string out = dir + "/out.obj", rep = dir + "/report.json", err = dir + "/stderr.txt";
  const std::string domain = dir + "/domain.obj";
  fs::remove(out); fs::remove(rep); fs::remove(domain);
  std::vector<std::string> argv = { dlf, c.kind == "sphere" ? "sphere" : "disk", file, "-o", out, "--report", rep };
  // The paper mode certifies its flowing (flipped) triangulation and reports
  // the caller's triangles that fold (doc/design.md): check the former.
  const bool paper = c.kind == "disk" && mode == "paper";
  if(paper) for(const char* a : { "--mode", "paper", "--domain-mesh" }) argv.push_back(a);
  if(paper) argv.push_back(domain);
  const Proc p = run_command(argv, timeout, err);
  json r;
  r["exit"] = p.code;
  r["seconds"] = p.seconds;
  std::string msg;
  { std::ifstream e(err); std::getline(e, msg); }
  if(p.timeout) r["status"] = "hang";
  else if(p.sig) r["status"] = std::string("crash(") + strsignal(p.sig) + ")";
  else {
    json R;
    bool have = false;
    { std::ifstream in(rep); if(in) { try { in >> R; have = true; } catch(...) { r["bad_report"] = true; } } }
    if(have) { r["status"] = R.value("status", "?"); if(R.contains("message")) msg = R["message"].get<std::string>(); }
    else r["status"] = p.code == 0 ? "ok(no report)" : "cli_error";
    if(have && R.contains("rejected_by_exact_check")) r["rejected_by_exact_check"] = R["rejected_by_exact_check"];
    if(have && R.contains("iterations")) r["iterations"] = R["iterations"];
    if(have && R.contains("stop_reason")) r["stop_reason"] = R["stop_reason"];
    // Exit 0: "ok"; exit 3: "not_converged", a valid map written all the same.
    const bool wrote = p.code == 0 || p.code == 3;
    if(!wrote && fs::exists(out)) r["stray_output"] = true;
    if((p.code == 0) != (r["status"] == "ok") || (p.code == 3) != (r["status"] == "not_converged"))
      r["exit_status_mismatch"] = true;
    if(wrote) {
      std::vector<P3> v;
      std::vector<std::array<double, 2> > vt;
      std::vector<std::array<int, 3> > F;
      if(!read_obj(out, v, vt, F)) r["unreadable_output"] = true;
      else {
        Map_check mc = c.kind == "sphere" ? check_sphere(v, F) : check_planar(vt, v, F);
        if(paper) {
          r["caller_folds"] = mc.inverted + mc.degenerate; // information, not a violation
          std::vector<P3> dv;
          std::vector<std::array<double, 2> > dvt;
          std::vector<std::array<int, 3> > dF;
          if(!read_obj(domain, dv, dvt, dF)) r["unreadable_output"] = true;
          else mc = check_planar(dvt, dv, dF);
        }
        if(c.kind == "sphere") {
          // the sphere contract is stricter: every face positive (det[p, q, r] > 0)
          r["inverted"] = mc.mirrored ? F.size() - mc.inverted - mc.degenerate : mc.inverted;
        } else r["inverted"] = mc.mirrored ? F.size() - mc.inverted - mc.degenerate : mc.inverted; // dlf promises positive uv
        r["degenerate"] = mc.degenerate;
        r["nonfinite"] = mc.nonfinite;
        if(c.kind != "sphere" && mc.d_area > 0) r["d_area"] = mc.d_area;
        if(c.kind == "sphere" && R.contains("final")) r["d_area"] = R["final"].value("d_area", -1.0);
      }
    }
  }
  r["message"] = msg;
  return r;
}

bool load_cgal(const std::string& file, SM& sm, std::string& why)
{
  std::vector<Point_3> pts;
  std::vector<std::vector<std::size_t> > polys;
  if(!CGAL::IO::read_polygon_soup(file, pts, polys)) { why = "read_polygon_soup failed"; return false; }
  if(polys.empty()) { why = "no faces"; return false; }
  for(const auto& p : polys) {
    if(p.size() != 3) { why = "not triangles"; return false; }
    for(std::size_t i : p) if(i >= pts.size()) { why = "index out of range"; return false; }
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polys))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(pts, polys);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polys)) { why = "not a polygon mesh"; return false; }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, sm);
  if(CGAL::is_closed(sm)) { why = "closed (no border)"; return false; }
  return true;
}

json check_sm_uv(SM& sm, SM::Property_map<vertex_descriptor, Point_2> uv, halfedge_descriptor bhd)
{
  // The connected component of bhd (what SMP parameterizes).
  std::vector<std::size_t> idx(sm.number_of_vertices() + sm.number_of_removed_vertices(), std::size_t(-1));
  std::vector<std::array<double, 2> > u;
  std::vector<P3> x;
  std::vector<std::array<int, 3> > F;
  std::set<SM::Face_index> seen;
  std::vector<SM::Face_index> stack(1, face(opposite(bhd, sm), sm));
  seen.insert(stack[0]);
  while(!stack.empty()) {
    const SM::Face_index f = stack.back(); stack.pop_back();
    std::array<int, 3> t;
    int k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, sm), sm)) {
      const vertex_descriptor v = target(h, sm);
      if(idx[v] == std::size_t(-1)) {
        idx[v] = u.size();
        u.push_back({{ uv[v].x(), uv[v].y() }});
        const Point_3& p = sm.point(v);
        x.push_back({{ p.x(), p.y(), p.z() }});
      }
      if(k < 3) t[std::size_t(k++)] = int(idx[v]);
      const halfedge_descriptor o = opposite(h, sm);
      if(!is_border(o, sm) && seen.insert(face(o, sm)).second) stack.push_back(face(o, sm));
    }
    F.push_back(t);
  }
  const Map_check mc = check_planar(u, x, F);
  json r = { { "inverted", mc.inverted }, { "degenerate", mc.degenerate }, { "nonfinite", mc.nonfinite } };
  if(mc.d_area > 0) r["d_area"] = mc.d_area;
  return r;
}

json run_cgal(const std::string& method, const std::string& file)
{
  SM sm;
  std::string why;
  if(!load_cgal(file, sm, why)) return { { "status", "skipped" }, { "message", "not loadable as a disk: " + why } };
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  SM::Property_map<vertex_descriptor, Point_2> uv = sm.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  SMP::Error_code e;
  if(method == "cgal_iterative_authalic") e = SMP::parameterize(sm, SMP::Iterative_authalic_parameterizer_3<SM>(), bhd, uv);
  else if(method == "cgal_arap") e = SMP::parameterize(sm, SMP::ARAP_parameterizer_3<SM>(), bhd, uv);
  else e = SMP::parameterize(sm, SMP::Mean_value_coordinates_parameterizer_3<SM>(), bhd, uv);
  json r = { { "status", SMP::discrete_lie_flow_error_name(e) }, { "message", SMP::discrete_lie_flow_error_message(e) } };
  if(e == SMP::OK) r.update(check_sm_uv(sm, uv, bhd));
  return r;
}

// An "initial parameterizer" that writes a Tutte map and then spoils it.
struct Spoiled_tutte
{
  int variant = 0;
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  SMP::Error_code parameterize(SM& sm, halfedge_descriptor bhd, VertexUVmap uvmap, VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    SMP::Barycentric_mapping_parameterizer_3<SM> tutte;
    const SMP::Error_code e = tutte.parameterize(sm, bhd, uvmap, vimap, vpmap);
    if(e != SMP::OK) return e;
    std::vector<vertex_descriptor> inner;
    for(vertex_descriptor v : vertices(sm)) if(!CGAL::is_border(v, sm)) inner.push_back(v);
    const vertex_descriptor a = inner[inner.size() / 2], b = inner[inner.size() / 3];
    switch(variant) {
    case 0: { const Point_2 p = get(uvmap, a); put(uvmap, a, Point_2(-1.5 * p.x(), -1.5 * p.y() + 0.3)); break; }
    case 1: put(uvmap, a, get(uvmap, b)); break;
    case 2: for(vertex_descriptor v : vertices(sm)) put(uvmap, v, Point_2(0.25, 0.25)); break;
    case 3: put(uvmap, a, Point_2(std::nan(""), 0)); break;
    case 4: for(vertex_descriptor v : vertices(sm)) { const Point_2 p = get(uvmap, v); put(uvmap, v, Point_2(p.x(), -p.y())); } break;
    case 6: sliver_at_rounding_level(sm, uvmap); break;
    default: break;
    }
    return SMP::OK;
  }

  // The face of smallest 3D area (a cap) gets the same shape in the map: its
  // apex goes onto the midpoint of the opposite uv edge, then a few ulps off
  // it, to the first double where the exact predicate calls it positive. Its
  // area is then at the rounding level of the coordinates, the one place
  // where the doubles' sign of an area and the exact sign can differ.
  template <class VertexUVmap>
  static void sliver_at_rounding_level(SM& sm, VertexUVmap uvmap)
  {
    SM::Face_index smallest;
    double best = HUGE_VAL;
    for(SM::Face_index f : faces(sm)) {
      const halfedge_descriptor h = halfedge(f, sm);
      const double a = std::sqrt(CGAL::squared_area(sm.point(source(h, sm)), sm.point(target(h, sm)), sm.point(target(next(h, sm), sm))));
      if(a < best) { best = a; smallest = f; }
    }
    // apex: the corner opposite the longest 3D edge
    halfedge_descriptor h = halfedge(smallest, sm), longest = h;
    for(int k = 0; k < 3; ++k, h = next(h, sm))
      if(CGAL::squared_distance(sm.point(source(h, sm)), sm.point(target(h, sm))) >
         CGAL::squared_distance(sm.point(source(longest, sm)), sm.point(target(longest, sm)))) longest = h;
    const vertex_descriptor b = source(longest, sm), c = target(longest, sm), apex = target(next(longest, sm), sm);
    if(CGAL::is_border(apex, sm)) return;
    const Point_2 pb = get(uvmap, b), pc = get(uvmap, c);
    double x = 0.5 * (pb.x() + pc.x()), y = 0.5 * (pb.y() + pc.y());
    // normal pointing to the positive side of (b, c, apex)
    const double nx = -(pc.y() - pb.y()), ny = pc.x() - pb.x();
    for(int k = 0; k < 64; ++k) {
      if(CGAL::orientation(EK::Point_2(pb.x(), pb.y()), EK::Point_2(pc.x(), pc.y()), EK::Point_2(x, y)) == CGAL::POSITIVE) break;
      x = std::nextafter(x, nx > 0 ? HUGE_VAL : -HUGE_VAL);
      y = std::nextafter(y, ny > 0 ? HUGE_VAL : -HUGE_VAL);
    }
    put(uvmap, apex, Point_2(x, y));
  }
};

json run_api(const Case& c, const std::string& file)
{
  SM sm;
  std::string why;
  if(!load_cgal(file, sm, why)) return { { "status", "skipped" }, { "message", why } };
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  SM::Property_map<vertex_descriptor, Point_2> uv = sm.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  Spoiled_tutte init;
  init.variant = c.api_variant;
  SMP::Discrete_lie_flow_parameterizer_3<SM, Spoiled_tutte> dlf(init);
  // The rounding-level sliver only matters once the flow pushes it; run to the plateau.
  if(c.api_variant == 6) dlf.options().tolerance = 0;
  const SMP::Error_code e = SMP::parameterize(sm, dlf, bhd, uv);
  const SMP::Discrete_lie_flow_report& R = dlf.report();
  json r = { { "status", SMP::discrete_lie_flow_error_name(e) }, { "message", R.message },
             { "rejected_by_exact_check", R.rejected_by_exact_check }, { "iterations", R.iterations } };
  if(e == SMP::OK) {
    json m = check_sm_uv(sm, uv, bhd);
    r.update(m);
    // The library keeps the orientation of the initial map (a clockwise
    // start gives a clockwise result, every face the same way): count the
    // faces against the majority, and the flat ones.
    std::size_t pos = 0, neg = 0, flat = 0;
    for(SM::Face_index f : faces(sm)) {
      const halfedge_descriptor h = halfedge(f, sm);
      const Point_2 &p = uv[source(h, sm)], &q = uv[target(h, sm)], &s = uv[target(next(h, sm), sm)];
      const CGAL::Orientation o = CGAL::orientation(EK::Point_2(p.x(), p.y()), EK::Point_2(q.x(), q.y()), EK::Point_2(s.x(), s.y()));
      if(o == CGAL::POSITIVE) ++pos; else if(o == CGAL::NEGATIVE) ++neg; else ++flat;
    }
    r["inverted"] = std::min(pos, neg);
    r["degenerate"] = flat;
  }
  return r;
}

bool is_violation(const json& r, std::string& what)
{
  const std::string s = r.value("status", "");
  if(s.rfind("crash", 0) == 0) { what = "crash"; return true; }
  if(s == "hang") { what = "hang"; return true; }
  if(s == "exception") { what = "exception escaped"; return true; }
  if(r.value("nonfinite", false)) { what = "NaN/Inf in output"; return true; }
  if((s == "ok" || s == "not_converged") && (r.value("inverted", 0) > 0 || r.value("degenerate", 0) > 0)) { what = "inverted/degenerate faces in an ok result"; return true; }
  if(r.value("stray_output", false)) { what = "output file left by a failed run"; return true; }
  if(r.value("exit_status_mismatch", false)) { what = "exit code disagrees with report status"; return true; }
  if(r.value("unreadable_output", false)) { what = "unreadable output"; return true; }
  return false;
}

} // namespace

int main(int argc, char** argv)
{
  namespace po = boost::program_options;
  std::string dlf, data, scratch, json_out, md_out, only, corpus_only;
  double timeout;
  bool no_cgal = false;
  po::options_description desc("robustness_corpus: hostile-input study of dlf and CGAL's parameterizers");
  desc.add_options()("help,h", "help")
    ("dlf", po::value(&dlf)->default_value("build/examples/dlf"), "the dlf binary")
    ("data", po::value(&data)->default_value(std::string(DLF_DATA_DIR) + "/meshes"), "CGAL data meshes")
    ("scratch", po::value(&scratch)->default_value("/tmp/dlf_robustness"), "scratch folder (corpus and runs)")
    ("json", po::value(&json_out)->default_value(""), "write all results as JSON")
    ("markdown", po::value(&md_out)->default_value(""), "write the tables as Markdown")
    ("timeout", po::value(&timeout)->default_value(60.0), "seconds per run")
    ("only", po::value(&only)->default_value(""), "run only the classes whose name contains this")
    ("no-cgal", po::bool_switch(&no_cgal), "skip CGAL's parameterizers")
    ("corpus-only", po::value(&corpus_only)->value_name("DIR"),
     "write the mesh cases (not the library-API ones) as DIR/disk/*.off and DIR/sphere/*.off, by the command "
     "each is meant for, run nothing (for dlf-study, benchmark/robustness_study.sh)");
  po::variables_map vm;
  try { po::store(po::parse_command_line(argc, argv, desc), vm); po::notify(vm); }
  catch(const std::exception& e) { std::cerr << "robustness_corpus: " << e.what() << "\n"; return 1; }
  if(vm.count("help")) { std::cout << desc << "\n"; return 0; }
  if(!corpus_only.empty()) {
    std::size_t written = 0;
    for(const Case& c : make_corpus(data)) {
      if(c.kind == "api" || (!only.empty() && c.cls.find(only) == std::string::npos)) continue;
      fs::create_directories(corpus_only + "/" + c.kind);
      std::ofstream(corpus_only + "/" + c.kind + "/" + c.cls + "__" + c.name + ".off", std::ios::binary) << c.text;
      ++written;
    }
    std::cout << "robustness_corpus: " << written << " cases written under " << corpus_only << "\n";
    return 0;
  }
  dlf = fs::absolute(dlf).string();
  fs::create_directories(scratch + "/corpus");
  fs::create_directories(scratch + "/run");
  const std::string run_dir = fs::absolute(scratch + "/run").string();

  const std::vector<Case> corpus = make_corpus(data);
  json all = json::array();
  std::size_t violations = 0, rejected_total = 0, dlf_ok = 0, dlf_runs = 0;
  std::vector<std::string> violation_lines;
  for(const Case& c : corpus) {
    if(!only.empty() && c.cls.find(only) == std::string::npos) continue;
    const std::string file = fs::absolute(scratch + "/corpus/" + c.cls + "__" + c.name + "__" + c.kind + ".off").string();
    { std::ofstream o(file, std::ios::binary); o << c.text; }
    std::vector<std::pair<std::string, json> > res;
    if(c.kind == "api") {
      res.push_back({ "dlf_api", run_forked([&]() { return run_api(c, file); }, timeout, run_dir) });
    } else {
      res.push_back({ c.kind == "sphere" ? "dlf_sphere" : "dlf_disk", run_dlf(dlf, c, file, run_dir, "certified", timeout) });
      if(c.kind == "disk") {
        res.push_back({ "dlf_disk_paper", run_dlf(dlf, c, file, run_dir, "paper", timeout) });
        if(!no_cgal)
          for(const char* m : { "cgal_iterative_authalic", "cgal_arap", "cgal_mvc" }) {
            const std::string ms = m;
            res.push_back({ ms, run_forked([&]() { return run_cgal(ms, file); }, timeout, run_dir) });
          }
      }
    }
    for(auto& mr : res) {
      json& r = mr.second;
      r["class"] = c.cls; r["case"] = c.name; r["kind"] = c.kind; r["method"] = mr.first; r["file"] = file;
      if(mr.first.rfind("dlf", 0) == 0) {
        ++dlf_runs;
        if(r.value("status", "") == "ok") ++dlf_ok;
        rejected_total += r.value("rejected_by_exact_check", std::size_t(0));
      }
      std::string what;
      if(is_violation(r, what)) {
        r["violation"] = what;
        if(mr.first.rfind("dlf", 0) == 0) {
          ++violations;
          violation_lines.push_back(mr.first + " on " + c.cls + "/" + c.name + " (" + file + "): " + what + " [" + r.value("status", "") + "]");
        }
      }
      std::cerr << c.cls << "/" << c.name << " [" << c.kind << "] " << mr.first << ": " << r.value("status", "?")
                << (r.contains("violation") ? "  VIOLATION: " + r["violation"].get<std::string>() : "") << "\n";
      all.push_back(r);
    }
  }

  if(!json_out.empty()) std::ofstream(json_out) << all.dump(1) << "\n";

  // ---- Markdown
  std::ostringstream md;
  std::vector<std::string> methods = { "dlf_disk", "dlf_disk_paper", "dlf_sphere", "dlf_api", "cgal_iterative_authalic", "cgal_arap", "cgal_mvc" };
  md << "Corpus: " << corpus.size() << " cases; " << all.size() << " runs; " << dlf_runs << " DLF runs, " << dlf_ok << " ok.\n\n";
  md << "**DLF violations (crash, hang, NaN output, folds in an ok result, exception, stray output file, exit code vs report): "
     << violations << "**\n\n";
  for(const std::string& v : violation_lines) md << "- " << v << "\n";
  md << "\nAblation: trial steps that the double-precision test accepted and the exact predicate refused, summed over all DLF runs "
        "(`rejected_by_exact_check`): **" << rejected_total << "**\n\n";
  // Summary per class x method.
  md << "### Per class and method\n\nEach cell: ok runs / runs; then `inv` = runs with inverted or degenerate faces in the output "
        "(counted for every output, also from CGAL's methods that return OK), `crash`/`hang`, and the distinct error statuses.\n\n";
  md << "| class |";
  for(const std::string& m : methods) md << " " << m << " |";
  md << "\n|---|";
  for(std::size_t i = 0; i < methods.size(); ++i) md << "---|";
  md << "\n";
  std::vector<std::string> classes;
  for(const json& r : all) if(std::find(classes.begin(), classes.end(), r["class"].get<std::string>()) == classes.end()) classes.push_back(r["class"]);
  for(const std::string& cl : classes) {
    md << "| " << cl << " |";
    for(const std::string& m : methods) {
      std::size_t n = 0, ok = 0, inv = 0, crash = 0, hang = 0, nan = 0;
      std::set<std::string> errs;
      for(const json& r : all) {
        if(r["class"] != cl || r["method"] != m) continue;
        ++n;
        const std::string s = r.value("status", "");
        if(s == "ok") ++ok;
        else if(s.rfind("crash", 0) == 0) ++crash;
        else if(s == "hang") ++hang;
        else if(s != "skipped") errs.insert(s == "cli_error" ? "cli_error" : s);
        if(r.value("inverted", 0) > 0 || r.value("degenerate", 0) > 0) ++inv;
        if(r.value("nonfinite", false)) ++nan;
      }
      if(!n) { md << " |"; continue; }
      md << " " << ok << "/" << n;
      if(inv) md << ", **inv " << inv << "**";
      if(nan) md << ", **NaN " << nan << "**";
      if(crash) md << ", **crash " << crash << "**";
      if(hang) md << ", **hang " << hang << "**";
      for(const std::string& e : errs) md << ", " << e;
      md << " |";
    }
    md << "\n";
  }
  // Detail per case.
  md << "\n### Per case\n\nstatus (exit code for the CLI) · inverted+degenerate faces · d_area of the output (optimum 2; computed here "
        "alike for all planar methods, from the report for the sphere) · seconds. `skipped`: CGAL cannot load the file as a "
        "mesh with a border.\n\n| class | case | kind | method | status | inv | d_area | s | message |\n|---|---|---|---|---|---|---|---|---|\n";
  for(const json& r : all) {
    std::string msg = r.value("message", "");
    std::replace(msg.begin(), msg.end(), '|', '/');
    const std::string file = r.value("file", "");
    if(msg.find(file) != std::string::npos && !file.empty()) msg.replace(msg.find(file), file.size(), "INPUT");
    if(msg.size() > 110) msg = msg.substr(0, 107) + "...";
    char d[32] = "";
    if(r.contains("d_area")) std::snprintf(d, sizeof d, "%.4f", r["d_area"].get<double>());
    char t[32];
    std::snprintf(t, sizeof t, "%.3f", r.value("seconds", 0.0));
    std::string st = r.value("status", "");
    if(r.contains("exit")) st += " (" + std::to_string(r["exit"].get<int>()) + ")";
    if(r.contains("violation")) st = "**" + st + ": " + r["violation"].get<std::string>() + "**";
    const std::size_t inv = r.value("inverted", std::size_t(0)) + r.value("degenerate", std::size_t(0));
    md << "| " << r["class"].get<std::string>() << " | " << r["case"].get<std::string>() << " | " << r["kind"].get<std::string>() << " | "
       << r["method"].get<std::string>() << " | " << st << " | " << (r.contains("inverted") ? std::to_string(inv) : "") << " | " << d
       << " | " << t << " | " << msg << " |\n";
  }
  if(!md_out.empty()) std::ofstream(md_out) << md.str();
  std::cout << "runs " << all.size() << ", DLF runs " << dlf_runs << " (ok " << dlf_ok << "), DLF violations " << violations
            << ", rejected_by_exact_check total " << rejected_total << "\n";
  for(const std::string& v : violation_lines) std::cout << "  " << v << "\n";
  return violations == 0 ? 0 : 3;
}
