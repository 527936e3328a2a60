// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target of every file the `dlf` tool reads and of every flow on
// small inputs. The mode (the environment's DLF_FUZZ_MODE, fuzz/run.sh sets
// it; seeds in fuzz/seeds/MODE) says what the input bytes are:
//   mesh      a mesh file (OFF when an "OFF" header is near the start, else
//             OBJ) read by the tool's reader; small readable meshes then get
//             a short flow (a disk: the planar flow in the certified and the
//             paper mode; anything else: the spherical flow, which must
//             refuse what is not a closed genus-0 surface);
//   ply, stl, ts
//             the same through CGAL's reader of that format;
//   literal   a mesh file as in `mesh`, flowed in the literal mode
//             (Algorithm 1 as printed: the disk and the sphere);
//   selection a CGAL selection file, as `--seam` and `--roi` read it, on a
//             fixed grid (the seams cut open, the faces selected);
//   density   a `--density` file on the same grid;
//   uv        an OBJ as `--init-uv`, `--init-map`-style per-vertex uv and
//             `dlf score` read it, on the same grid;
//   medit     a Medit `.mesh` file, read as `dlf volume` reads it; small
//             tet meshes then get a short volume flow.
// The invariants that abort:
//   - a reader either throws the tool's error (or returns false with a
//     message) or returns only finite values, in-range indices, triangles of
//     three distinct vertices and no unreferenced vertex;
//   - a parameterizer returns a known status with a message;
//   - on `OK`: finite output, and (certified mode, sphere, volume) every
//     face or tet positively oriented by CGAL's exact predicate on the
//     returned doubles.
// Build and run with fuzz/run.sh.

#include "arguments.h"
#include "cli_error.h"
#include "density_input.h"
#include "mesh_input.h"
#include "obj_io.h"
#include "seam_input.h"
#include "surface_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_medit.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
using namespace dlf_cli;

// Flows are run on small meshes only, so that an execution stays in the
// millisecond range and the fuzzer explores the reader and the checks.
const std::size_t max_flow_faces = 200;
const std::size_t flow_iterations = 20;

[[noreturn]] void violation(const char* what, const std::string& detail = std::string())
{
  std::fprintf(stderr, "dlf_fuzz: invariant violated: %s %s\n", what, detail.c_str());
  std::abort();
}

bool known_status(int code) { return std::strcmp(SMP::discrete_lie_flow_error_name(code), "ERROR_UNKNOWN") != 0; }

void check_read_mesh(const Indexed_mesh& m)
{
  if(m.faces.empty()) violation("reader returned no faces");
  std::vector<bool> used(m.xyz.size(), false);
  for(const Vec3& p : m.xyz)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) violation("non-finite coordinate");
  for(const Triangle& t : m.faces) {
    for(int i : t) {
      if(i < 0 || std::size_t(i) >= m.xyz.size()) violation("face index out of range");
      used[std::size_t(i)] = true;
    }
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) violation("face with a repeated vertex");
  }
  for(bool u : used)
    if(!u) violation("unreferenced vertex");
}

void run_disk(const Indexed_mesh& mesh, SMP::Discrete_lie_flow_mode mode)
{
  typedef SMP::Discrete_lie_flow_parameterizer_3<Surface_mesh> Parameterizer;
  Surface_mesh sm;
  build_surface_mesh(mesh, sm);
  halfedge_descriptor bhd = boost::graph_traits<Surface_mesh>::null_halfedge();
  for(halfedge_descriptor h : halfedges(sm))
    if(is_border(h, sm)) { bhd = h; break; }
  auto uvmap = sm.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  auto vimap = sm.add_property_map<vertex_descriptor, int>("v:index", -1).first;
  auto vpmap = sm.add_property_map<vertex_descriptor, bool>("v:parameterized", false).first;
  for(vertex_descriptor v : vertices(sm)) put(vimap, v, int(v.idx()));

  SMP::Discrete_lie_flow_options options;
  options.mode = mode;
  options.max_iterations = flow_iterations;
  Parameterizer parameterizer(Parameterizer::Initial_parameterizer(), options);
  const SMP::Error_code code = parameterizer.parameterize(sm, bhd, uvmap, vimap, vpmap);
  const SMP::Discrete_lie_flow_report& R = parameterizer.report();
  // CGAL's entry point returns CGAL's nearest code; the report keeps the precise one.
  if(!known_status(code) || !known_status(R.status) ||
     SMP::discrete_lie_flow_cgal_error_code(R.status) != code)
    violation("disk: unknown or inconsistent status");
  if(code != SMP::OK) {
    if(R.message.empty()) violation("disk: error without a message");
    return;
  }
  if(!std::isfinite(R.final_d_area)) violation("disk: non-finite d_area");
  std::vector<D::Vec2> uv(num_vertices(sm));
  for(vertex_descriptor v : vertices(sm)) {
    const Kernel::Point_2 p = get(uvmap, v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y())) violation("disk: non-finite uv");
    uv[v.idx()] = {{ p.x(), p.y() }};
  }
  if(mode != SMP::Discrete_lie_flow_mode::CERTIFIED) {
    // The paper's and the literal mode certify their flowing triangulation,
    // not the caller's.
    if(R.flowing_inverted_faces != 0) violation("disk (paper, literal): folded flowing triangulation");
    return;
  }
  std::vector<D::Face> faces(mesh.faces.begin(), mesh.faces.end());
  const D::Orientation_count oc = D::count_orientations_2(uv, faces);
  // A border parameterizer that runs clockwise gives a mirrored map, which
  // the flow keeps (every face negative: still one-to-one).
  if(oc.degenerate == 0 && oc.inverted == faces.size()) return;
  if(!oc.all_positive())
    violation("disk: ok with non-positive faces", std::to_string(oc.inverted) + " inverted, " +
                                                      std::to_string(oc.degenerate) + " degenerate");
}

void run_sphere(const Indexed_mesh& mesh, SMP::Discrete_lie_flow_mode mode)
{
  SMP::Discrete_lie_flow_options options;
  options.mode = mode;
  options.max_iterations = flow_iterations;
  D::Default_spd_solver solver;
  SMP::Discrete_lie_flow_report report;
  D::Sphere_problem P;
  P.xyz = mesh.xyz;
  P.faces.assign(mesh.faces.begin(), mesh.faces.end());
  std::vector<D::Vec3> points;
  const SMP::Error_code code = D::map_to_sphere(P, points, options, solver, report);
  const SMP::Discrete_lie_flow_report& R = report;
  if(!known_status(code) || R.status != code) violation("sphere: unknown or inconsistent status");
  if(code != SMP::OK) {
    if(R.message.empty()) violation("sphere: error without a message");
    if(!points.empty()) violation("sphere: output written on error");
    return;
  }
  if(points.size() != mesh.xyz.size()) violation("sphere: wrong output size");
  for(const D::Vec3& p : points) {
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) violation("sphere: non-finite point");
    if(std::abs(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1) > 1e-9) violation("sphere: point off the unit sphere");
  }
  if(mode != SMP::Discrete_lie_flow_mode::CERTIFIED) {
    // As on the disk: the paper's and the literal mode certify their
    // flowing triangulation only.
    if(R.flowing_inverted_faces != 0) violation("sphere (paper, literal): folded flowing triangulation");
    return;
  }
  std::vector<D::Face> faces(mesh.faces.begin(), mesh.faces.end());
  if(!D::count_orientations_sphere(points, faces).all_positive()) violation("sphere: ok with non-positive faces");
}

// The fixed mesh of the modes that read a file about a mesh: a 4 × 4 grid
// of the unit square (25 vertices, 32 faces), slightly bent.
Indexed_mesh grid_mesh()
{
  Indexed_mesh m;
  const int n = 4;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      m.xyz.push_back({{ double(i) / n, double(j) / n, 0.1 * i * j / (n * n) }});
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      m.faces.push_back({{ a, a + 1, a + n + 2 }});
      m.faces.push_back({{ a, a + n + 2, a + n + 1 }});
    }
  return m;
}

void check_uv(const std::vector<Vec2>& uv, std::size_t expected, const char* what)
{
  if(uv.size() != expected) violation(what, "wrong number of uv");
  for(const Vec2& p : uv)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) violation(what, "non-finite uv");
}

void fuzz_selection(const std::string& path)
{
  static const Indexed_mesh grid = grid_mesh();
  try {
    const std::vector<int> faces = read_selection(path, grid);
    for(int f : faces)
      if(f < 0 || std::size_t(f) >= grid.faces.size()) violation("selection: face out of range");
  } catch(const Cli_error&) {
  }
  try {
    const Seam_selection seams = read_seam_selection(path, grid);
    for(const Vertex_pair& e : seams.edges)
      if(e[0] < 0 || e[1] < 0 || std::size_t(e[0]) >= grid.xyz.size() || std::size_t(e[1]) >= grid.xyz.size() ||
         e[0] == e[1])
        violation("seam: edge out of range");
    const Seam_cut cut = cut_along_seams(grid, seams);
    check_read_mesh(cut.mesh);
    if(cut.mesh.faces.size() != grid.faces.size() || cut.input_vertex.size() != cut.mesh.xyz.size())
      violation("seam: the cut changed the faces or lost its vertex map");
    for(std::size_t v = 0; v < cut.input_vertex.size(); ++v) {
      const int i = cut.input_vertex[v];
      if(i < 0 || std::size_t(i) >= grid.xyz.size() || cut.mesh.xyz[v] != grid.xyz[std::size_t(i)])
        violation("seam: a cut vertex is not a side of its input vertex");
    }
  } catch(const Cli_error&) {
  }
}

void fuzz_density(const std::string& path)
{
  static const Indexed_mesh grid = grid_mesh();
  Disk_settings settings;
  settings.density_file = path;
  try {
    const Density_setup d = make_density(grid, settings);
    if(d.face_density.size() != grid.faces.size()) violation("density: not one value per face");
    for(double x : d.face_density)
      if(!std::isfinite(x) || !(x > 0)) violation("density: a value that is not finite and positive");
  } catch(const Cli_error&) {
  }
}

void fuzz_uv(const std::string& path)
{
  static const Indexed_mesh grid = grid_mesh();
  try {
    check_uv(read_uv_obj(path, grid.xyz.size()), grid.xyz.size(), "read_uv_obj");
  } catch(const Cli_error&) {
  }
  try {
    const Obj_map map = read_map_obj(path, grid);
    check_read_mesh(map.surface);
    check_uv(map.uv, map.surface.xyz.size(), "read_map_obj");
    if(map.surface.faces.size() != grid.faces.size()) violation("read_map_obj: the faces changed");
  } catch(const Cli_error&) {
  }
}

void fuzz_medit(const std::string& text)
{
  std::istringstream in(text);
  D::Medit_tet_mesh m;
  std::string error;
  if(!D::read_medit(in, m, error)) {
    if(error.empty()) violation("medit: refused without a message");
    return;
  }
  for(const D::Vec3& p : m.points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) violation("medit: non-finite point");
  for(const auto& t : m.tets)
    for(int i : t)
      if(i < 0 || std::size_t(i) >= m.points.size()) violation("medit: tet index out of range");
  if(m.tets.empty() || m.tets.size() > max_flow_faces) return;

  SMP::Discrete_lie_flow_volume_options options;
  options.max_iterations = flow_iterations;
  SMP::Discrete_lie_flow_volume_parameterizer_3<> parameterizer(options);
  std::vector<std::array<int, 4> > tets(m.tets.begin(), m.tets.end());
  std::vector<Kernel::Point_3> points, ball;
  for(const D::Vec3& p : m.points) points.push_back(Kernel::Point_3(p[0], p[1], p[2]));
  const SMP::Error_code code = parameterizer.parameterize(points, tets, ball);
  const SMP::Discrete_lie_flow_volume_report& R = parameterizer.report();
  if(!known_status(code) || R.status != code) violation("volume: unknown or inconsistent status");
  if(code != SMP::OK) {
    if(R.message.empty()) violation("volume: error without a message");
    if(!ball.empty()) violation("volume: output written on error");
    return;
  }
  if(ball.size() != points.size()) violation("volume: wrong output size");
  for(const Kernel::Point_3& p : ball)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()) ||
       p.x() * p.x() + p.y() * p.y() + p.z() * p.z() > 1 + 1e-9)
      violation("volume: a point not finite or outside the unit ball");
  // CGAL's exact predicate on the returned doubles (Kernel above is not exact).
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Exact_point;
  auto exact = [&](int i) {
    const Kernel::Point_3& p = ball[std::size_t(i)];
    return Exact_point(p.x(), p.y(), p.z());
  };
  for(const auto& t : tets)
    if(CGAL::orientation(exact(t[0]), exact(t[1]), exact(t[2]), exact(t[3])) != CGAL::POSITIVE)
      violation("volume: ok with a tet that is not positive");
}

enum class Mode { MESH, PLY, STL, TS, LITERAL, SELECTION, DENSITY, UV, MEDIT };

Mode fuzz_mode = Mode::MESH;

std::string scratch_path(const char* extension)
{
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/dlf_fuzz_" + std::to_string(long(getpid())) + extension;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  const char* m = std::getenv("DLF_FUZZ_MODE");
  const std::string mode = m ? m : "mesh";
  const std::pair<const char*, Mode> modes[] = { { "mesh", Mode::MESH }, { "ply", Mode::PLY }, { "stl", Mode::STL },
    { "ts", Mode::TS }, { "literal", Mode::LITERAL }, { "selection", Mode::SELECTION },
    { "density", Mode::DENSITY }, { "uv", Mode::UV }, { "medit", Mode::MEDIT } };
  for(const auto& k : modes)
    if(mode == k.first) { fuzz_mode = k.second; return 0; }
  std::fprintf(stderr, "dlf_fuzz: unknown DLF_FUZZ_MODE '%s' (mesh, ply, stl, ts, literal, selection, density, uv, medit)\n",
               mode.c_str());
  std::exit(2);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size > (1 << 16)) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if(fuzz_mode == Mode::MEDIT) {
    fuzz_medit(text);
    return 0;
  }
  const char* extension = ".txt";
  switch(fuzz_mode) {
  case Mode::PLY: extension = ".ply"; break;
  case Mode::STL: extension = ".stl"; break;
  case Mode::TS: extension = ".ts"; break;
  case Mode::UV: extension = ".obj"; break;
  case Mode::SELECTION: extension = ".selection.txt"; break;
  case Mode::MESH: case Mode::LITERAL: {
    // CGAL picks the reader by extension; an OFF file names itself on its
    // first line that is neither blank nor a comment.
    std::size_t line = text.find_first_not_of(" \t\r\n");
    while(line != std::string::npos && text[line] == '#') line = text.find_first_not_of(" \t\r\n", text.find('\n', line));
    const bool off = line != std::string::npos && text.substr(line, text.find('\n', line) - line).find("OFF") != std::string::npos;
    extension = off ? ".off" : ".obj";
    break;
  }
  default: break;
  }
  const std::string path = scratch_path(extension);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), std::streamsize(text.size()));
  }
  switch(fuzz_mode) {
  case Mode::SELECTION: fuzz_selection(path); return 0;
  case Mode::DENSITY: fuzz_density(path); return 0;
  case Mode::UV: fuzz_uv(path); return 0;
  default: break;
  }
  Indexed_mesh mesh;
  try {
    mesh = read_triangle_mesh(path);
  } catch(const Cli_error&) {
    return 0;
  }
  check_read_mesh(mesh);
  if(mesh.faces.size() > max_flow_faces) return 0;

  bool disk = true;
  try {
    check_disk_topology(mesh, path);
  } catch(const Cli_error&) {
    disk = false;
  }
  if(fuzz_mode == Mode::LITERAL) {
    if(disk) run_disk(mesh, SMP::Discrete_lie_flow_mode::LITERAL);
    else run_sphere(mesh, SMP::Discrete_lie_flow_mode::LITERAL);
  } else if(disk) {
    run_disk(mesh, SMP::Discrete_lie_flow_mode::CERTIFIED);
    run_disk(mesh, SMP::Discrete_lie_flow_mode::PAPER);
  } else {
    run_sphere(mesh, SMP::Discrete_lie_flow_mode::CERTIFIED);
  }
  return 0;
}
