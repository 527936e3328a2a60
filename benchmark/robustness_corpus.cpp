// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The robustness study's corpus and its in-process runner.
//
// A deterministic corpus of hostile inputs derived from CGAL's data set and
// from generated meshes:
//
//   robustness_corpus --corpus-only DIR      # DIR/{disk,sphere,api}/*.off, DIR/cases.json
//
// and one run of the library API (Discrete_lie_flow_parameterizer_3 with an
// initial map spoiled on purpose) or of CGAL's iterative authalic, ARAP or
// mean-value parameterizer on one case, in this process, with the checks of
// its output (faces against the majority orientation or flat, by the exact
// CGAL::orientation on the output doubles; non-finite values; d_area of the
// output), as a JSON report:
//
//   robustness_corpus --run cgal_arap --case DIR/disk/cap__grid8_eps1e-14.off --report out.json
//
// benchmark/robustness.sh runs every case through dlf-study, which gives each
// run its own process, timeout and memory limit (doc/robustness.md).

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

#include <algorithm>
#include <array>
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

// ---------------------------------------------------------------- methods
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

json run_api(int variant, const std::string& file)
{
  SM sm;
  std::string why;
  if(!load_cgal(file, sm, why)) return { { "status", "skipped" }, { "message", why } };
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  SM::Property_map<vertex_descriptor, Point_2> uv = sm.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  Spoiled_tutte init;
  init.variant = variant;
  SMP::Discrete_lie_flow_parameterizer_3<SM, Spoiled_tutte> dlf(init);
  // The rounding-level sliver only matters once the flow pushes it; run to the plateau.
  if(variant == 6) dlf.options().tolerance = 0;
  // CGAL's entry point returns CGAL's nearest code; the report holds the precise one.
  const SMP::Error_code cgal = SMP::parameterize(sm, dlf, bhd, uv);
  const SMP::Discrete_lie_flow_report& R = dlf.report();
  const SMP::Error_code e = R.status;
  if(cgal != SMP::discrete_lie_flow_cgal_error_code(e)) // a broken promise: the runner's error
    throw std::runtime_error("parameterize() returned " + std::to_string(int(cgal)) + ", the report's status is " +
                             SMP::discrete_lie_flow_error_name(e));
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

// The initial-map variant of a library-API case, from the file that the
// corpus writes beside it (<case>.json).
int api_variant_of(const std::string& file)
{
  const fs::path side = fs::path(file).replace_extension(".json");
  std::ifstream in(side);
  if(!in) throw std::runtime_error(side.string() + ": missing (the case's initial-map variant; write the corpus with --corpus-only)");
  const json j = json::parse(in);
  if(!j.contains("initial_map_variant") || !j["initial_map_variant"].is_number_integer())
    throw std::runtime_error(side.string() + ": no integer initial_map_variant");
  return j["initial_map_variant"].get<int>();
}

// Writes the report beside its final name, then renames it: a run killed
// while writing leaves no report rather than half of one.
bool write_report(const std::string& path, const json& r)
{
  const std::string tmp = path + ".part";
  {
    std::ofstream o(tmp);
    o << r.dump(1) << "\n";
    if(!o) return false;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  return !ec;
}

} // namespace

int main(int argc, char** argv)
{
  namespace po = boost::program_options;
  std::string data, only, corpus_only, method, case_file, report;
  po::options_description desc(
    "robustness_corpus: the hostile-input corpus of the robustness study, and its runner for the library API and "
    "CGAL's parameterizers (benchmark/robustness.sh runs both through dlf-study)");
  desc.add_options()("help,h", "help")
    ("data", po::value(&data)->default_value(std::string(DLF_DATA_DIR) + "/meshes"), "CGAL data meshes")
    ("only", po::value(&only)->default_value(""), "with --corpus-only: only the classes whose name contains this")
    ("corpus-only", po::value(&corpus_only)->value_name("DIR"),
     "write every case as DIR/KIND/CLASS__CASE.off, KIND the method family it is meant for (disk: dlf disk in both "
     "modes and CGAL's parameterizers; sphere: dlf sphere; api: the library API, with its initial-map variant in "
     "CLASS__CASE.json), and the cases in corpus order in DIR/cases.json; run nothing")
    ("run", po::value(&method)->value_name("METHOD"),
     "run one case in this process: dlf_api, cgal_iterative_authalic, cgal_arap or cgal_mvc")
    ("case", po::value(&case_file)->value_name("FILE"), "with --run: the case's mesh file")
    ("report", po::value(&report)->value_name("OUT.json"),
     "with --run: the JSON report (status, message, inverted, degenerate, nonfinite, d_area, iterations, "
     "rejected_by_exact_check)");
  po::variables_map vm;
  try { po::store(po::parse_command_line(argc, argv, desc), vm); po::notify(vm); }
  catch(const std::exception& e) { std::cerr << "robustness_corpus: " << e.what() << "\n"; return 1; }
  if(vm.count("help") || (corpus_only.empty() && method.empty())) { std::cout << desc << "\n"; return vm.count("help") ? 0 : 1; }

  if(!corpus_only.empty()) {
    json index = json::array();
    for(const Case& c : make_corpus(data)) {
      if(!only.empty() && c.cls.find(only) == std::string::npos) continue;
      const std::string rel = c.kind + "/" + c.cls + "__" + c.name + ".off";
      fs::create_directories(corpus_only + "/" + c.kind);
      std::ofstream(corpus_only + "/" + rel, std::ios::binary) << c.text;
      if(c.kind == "api")
        std::ofstream(corpus_only + "/" + c.kind + "/" + c.cls + "__" + c.name + ".json") << json{ { "initial_map_variant", c.api_variant } }.dump() << "\n";
      index.push_back({ { "class", c.cls }, { "case", c.name }, { "kind", c.kind }, { "file", rel } });
    }
    std::ofstream(corpus_only + "/cases.json") << index.dump(1) << "\n";
    std::cout << "robustness_corpus: " << index.size() << " cases written under " << corpus_only << "\n";
    return 0;
  }

  const std::set<std::string> methods = { "dlf_api", "cgal_iterative_authalic", "cgal_arap", "cgal_mvc" };
  if(!methods.count(method)) {
    std::cerr << "robustness_corpus: error: --run " << method << ": unknown method (dlf_api, cgal_iterative_authalic, cgal_arap, cgal_mvc)\n";
    return 1;
  }
  if(case_file.empty() || report.empty()) {
    std::cerr << "robustness_corpus: error: --run needs --case FILE and --report OUT.json\n";
    return 1;
  }
  // CGAL's iterative authalic prints every iteration on stdout.
  if(!std::freopen("/dev/null", "w", stdout)) std::cerr << "robustness_corpus: warning: stdout not silenced\n";
  json r;
  try {
    r = method == "dlf_api" ? run_api(api_variant_of(case_file), case_file) : run_cgal(method, case_file);
  } catch(const std::exception& e) {
    r = { { "status", "exception" }, { "message", e.what() } };
  } catch(...) {
    r = { { "status", "exception" }, { "message", "unknown exception" } };
  }
  r["method"] = method;
  if(!write_report(report, r)) {
    std::cerr << "robustness_corpus: error: cannot write " << report << "\n";
    return 1;
  }
  return 0;
}
