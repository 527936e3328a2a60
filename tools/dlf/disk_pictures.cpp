// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "disk_pictures.h"
#include "svg_common.h"
#include "svg_layout.h"
#include "svg_plots.h"
#include "texture_output.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>

namespace dlf_cli {

namespace {

// The outline the layout picture draws: the regions of interest, else the
// pieces of a piecewise-constant density file.
std::vector<std::array<int, 2> > layout_outline(const Indexed_mesh& mesh, const Density_setup& density)
{
  if(density.regions.empty()) return density_outline(mesh, density.face_density);
  return region_outline(mesh, region_faces(density));
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

} // namespace

std::vector<int> region_faces(const Density_setup& density)
{
  std::vector<int> roi;
  for(const Density_region& r : density.regions) roi.insert(roi.end(), r.faces.begin(), r.faces.end());
  std::sort(roi.begin(), roi.end());
  roi.erase(std::unique(roi.begin(), roi.end()), roi.end());
  return roi;
}

std::vector<std::array<int, 2> > density_outline(const Indexed_mesh& mesh, const std::vector<double>& face_density,
                                                 std::size_t max_levels)
{
  std::vector<std::array<int, 2> > out;
  if(face_density.empty()) return out;
  std::set<double> levels;
  for(double rho : face_density) {
    levels.insert(rho);
    if(levels.size() > max_levels) return out;
  }
  if(levels.size() < 2) return out;
  // Each interior edge once, as (min, max, face); equal keys are its two sides.
  std::vector<std::array<int, 3> > sides;
  sides.reserve(3 * mesh.faces.size());
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      sides.push_back({{ std::min(a, b), std::max(a, b), int(f) }});
    }
  std::sort(sides.begin(), sides.end());
  for(std::size_t k = 0; k + 1 < sides.size(); ++k)
    if(sides[k][0] == sides[k + 1][0] && sides[k][1] == sides[k + 1][1] &&
       face_density[std::size_t(sides[k][2])] != face_density[std::size_t(sides[k + 1][2])])
      out.push_back({{ sides[k][0], sides[k][1] }});
  return out;
}

void declare_pictures(Output_files& outputs, const Disk_settings& s)
{
  if(!s.svg.empty()) outputs.declare(s.svg, "--svg");
  if(!s.convergence_svg.empty()) outputs.declare(s.convergence_svg, "--plot-convergence");
  if(!s.histogram_svg.empty()) outputs.declare(s.histogram_svg, "--plot-histogram");
  if(!s.texture_obj.empty()) {
    const Texture_paths t = texture_paths(s.texture_obj);
    outputs.declare(t.obj, "--texture");
    outputs.declare(t.mtl, "--texture (its .mtl)");
    outputs.declare(t.png, "--texture (its .png)");
  }
}

std::vector<std::pair<std::string, double> > write_pictures(Output_files& outputs, const Disk_settings& s,
                                                           const Indexed_mesh& mesh, const Disk_run& run,
                                                           const Density_setup& density, const std::string& caption,
                                                           const Indexed_mesh* input)
{
  std::vector<std::pair<std::string, double> > timings;
  auto timed = [&](const std::string& path, const std::function<void(std::ostream&)>& body) {
    const auto t0 = std::chrono::steady_clock::now();
    outputs.write(path, body);
    timings.emplace_back(path, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  };
  if(!s.svg.empty())
    timed(s.svg, [&](std::ostream& o) {
      write_svg_layout(o, mesh, run.final_uv, caption, s.svg_options, density.face_density, layout_outline(mesh, density),
                       density.regions.empty() ? "density pieces" : "region of interest", region_faces(density));
    });
  if(!s.convergence_svg.empty())
    timed(s.convergence_svg, [&](std::ostream& o) {
      const double initial = run.report.initial_d_area >= 2 ? run.report.initial_d_area
                                                            : std::numeric_limits<double>::quiet_NaN();
      write_convergence_plot(o, run.report.history, initial, s.options.tolerance, caption);
    });
  if(!s.histogram_svg.empty())
    timed(s.histogram_svg, [&](std::ostream& o) {
      const std::vector<double> before = run.initial_uv.empty() ? std::vector<double>()
                                       : face_log_area_ratios(mesh, run.initial_uv, density.face_density);
      write_log_ratio_histogram(o, before, face_log_area_ratios(mesh, run.final_uv, density.face_density),
                                !density.face_density.empty(), caption);
    });
  if(!s.texture_obj.empty()) {
    const Texture_paths t = texture_paths(s.texture_obj);
    timed(t.obj, [&](std::ostream& o) {
      const Indexed_mesh& surface = input ? *input : mesh;
      write_textured_obj(o, surface.xyz, unit_square_uv(run.final_uv), surface.faces, file_name(t.mtl),
                         caption + " (uv scaled into [0,1]^2)", mesh.faces);
    });
    timed(t.mtl, [&](std::ostream& o) { write_checker_mtl(o, file_name(t.png)); });
    timed(t.png, [&](std::ostream& o) { write_checker_png(o, s.texture_size, 16); });
  }
  return timings;
}

} // namespace dlf_cli
