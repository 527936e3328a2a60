// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "metrics.h"

#include <iomanip>

namespace dlf_cli {

Metrics compute_metrics(const Indexed_mesh& mesh, const std::vector<Vec2>& uv, const std::vector<double>& face_density)
{
  return CGAL::Surface_mesh_parameterization::discrete_lie_flow_distortion(mesh.xyz, uv, mesh.faces, face_density);
}

nlohmann::ordered_json metrics_to_json(const Metrics& m)
{
  // Field names are fixed by doc/design.md ("Metrics"); later ones are additions.
  return nlohmann::ordered_json{
    { "d_area", m.d_area },
    { "arap", m.arap },
    { "symmetric_dirichlet", m.symmetric_dirichlet },
    { "log_area_ratio", { { "mean_abs", m.log_area_mean_abs }, { "max_abs", m.log_area_max_abs },
                          { "rms", m.log_area_rms } } },
    { "inverted_faces", m.inverted_faces },
    { "degenerate_faces", m.degenerate_faces },
    { "min_angle_degrees", m.min_angle_degrees },
    { "faces_below_1_degree", m.faces_below_1_degree },
    { "wasserstein_table1", m.wasserstein_table1 },
    { "area_total", m.area_total },
    { "beltrami", { { "mean", m.beltrami_mean }, { "weighted_mean", m.beltrami_weighted_mean },
                    { "max", m.beltrami_max } } }
  };
}

void print_metrics(std::ostream& out, const Metrics& m, const std::string& indent)
{
  out << indent << "d_area               " << m.d_area << "  (optimum 2)\n"
      << indent << "arap                 " << m.arap << "\n"
      << indent << "symmetric_dirichlet  " << m.symmetric_dirichlet << "\n"
      << indent << "|log area ratio|     mean " << m.log_area_mean_abs << ", max " << m.log_area_max_abs
      << ", rms " << m.log_area_rms << "\n"
      << indent << "inverted faces       " << m.inverted_faces << "\n"
      << indent << "degenerate faces     " << m.degenerate_faces << "\n"
      << indent << "min angle (degrees)  " << m.min_angle_degrees << "  (" << m.faces_below_1_degree
      << " faces below 1 degree)\n"
      << indent << "wasserstein (Table 1) " << m.wasserstein_table1 << "  (area shares, optimum 0)\n"
      << indent << "area_total           " << m.area_total << "  (optimum 0)\n"
      << indent << "|Beltrami|           mean " << m.beltrami_mean << ", area-weighted " << m.beltrami_weighted_mean
      << ", max " << m.beltrami_max << "  (optimum 0: conformal)\n";
}

void add_levels_json(nlohmann::ordered_json& j, const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R)
{
  j["levels"] = nlohmann::ordered_json::array();
  for(const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_level& l : R.levels)
    j["levels"].push_back({ { "vertices", l.vertices }, { "faces", l.faces }, { "iterations", l.iterations },
                            { "d_area", l.d_area }, { "seconds", l.seconds } });
  j["seconds"]["levels"] = R.seconds_levels;
  j["levels_refused"] = R.levels_refused.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(R.levels_refused);
}

void print_levels(std::ostream& out, const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R)
{
  if(!R.levels.empty()) {
    const std::streamsize precision = out.precision();
    double seconds = R.seconds_levels;
    out << "  coarse to fine:";
    for(std::size_t k = 0; k < R.levels.size(); ++k) {
      seconds += R.levels[k].seconds;
      if(k + 1 < R.levels.size()) out << (k ? ", " : " ") << R.levels[k].faces << " faces " << R.levels[k].iterations << " it";
    }
    out << "; start d_area " << R.levels.back().d_area << " (levels " << std::setprecision(3) << seconds << " s)\n"
        << std::setprecision(int(precision));
  } else if(!R.levels_refused.empty()) {
    out << "  coarse to fine refused (" << R.levels_refused << "): the flow ran from the start\n";
  }
}

} // namespace dlf_cli
