// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the input bytes are a mesh file (OFF when an "OFF"
// header is near the start, else OBJ), read by the `dlf` tool's reader;
// small readable meshes then get a short flow (a disk: the planar flow in
// both modes; anything else: the spherical flow, which must refuse what is
// not a closed genus-0 surface). The invariants that abort:
//   - the reader returns only finite coordinates, triangles of three distinct
//     in-range indices, and no unreferenced vertex;
//   - a parameterizer returns a known status with a message;
//   - on `OK`: finite output, and (certified mode, sphere) every face
//     positively oriented by CGAL's exact predicate on the returned doubles.
// Build and run with fuzz/run.sh.

#include "cli_error.h"
#include "mesh_input.h"
#include "surface_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
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
  if(mode == SMP::Discrete_lie_flow_mode::PAPER) {
    // The paper's mode certifies its flowing triangulation, not the caller's.
    if(R.flowing_inverted_faces != 0) violation("disk (paper): folded flowing triangulation");
    return;
  }
  std::vector<D::Face> faces(mesh.faces.begin(), mesh.faces.end());
  const D::Orientation_count oc = D::count_orientations_2(uv, faces);
  if(!oc.all_positive())
    violation("disk: ok with non-positive faces", std::to_string(oc.inverted) + " inverted, " +
                                                      std::to_string(oc.degenerate) + " degenerate");
}

void run_sphere(const Indexed_mesh& mesh)
{
  SMP::Discrete_lie_flow_options options;
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
  std::vector<D::Face> faces(mesh.faces.begin(), mesh.faces.end());
  if(!D::count_orientations_sphere(points, faces).all_positive()) violation("sphere: ok with non-positive faces");
}

std::string scratch_path(const char* extension)
{
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/dlf_fuzz_" + std::to_string(long(getpid())) + extension;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size > (1 << 16)) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  // CGAL picks the reader by extension; an OFF file names itself on its
  // first line that is neither blank nor a comment.
  std::size_t line = text.find_first_not_of(" \t\r\n");
  while(line != std::string::npos && text[line] == '#') line = text.find_first_not_of(" \t\r\n", text.find('\n', line));
  const bool off = line != std::string::npos && text.substr(line, text.find('\n', line) - line).find("OFF") != std::string::npos;
  const std::string path = scratch_path(off ? ".off" : ".obj");
  {
    std::ofstream out(path, std::ios::binary);
    out.write(text.data(), std::streamsize(text.size()));
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
  if(disk) {
    run_disk(mesh, SMP::Discrete_lie_flow_mode::CERTIFIED);
    run_disk(mesh, SMP::Discrete_lie_flow_mode::PAPER);
  } else {
    run_sphere(mesh);
  }
  return 0;
}
