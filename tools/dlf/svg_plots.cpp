// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_plots.h"
#include "svg_common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

const double plot_width = 640, panel_height = 220, left = 80, top = 44, gap = 64;

struct Panel
{
  double x, y, w, h;     // frame in SVG coordinates
  double x0, x1, y0, y1; // data range; y in log10 when `log_y`
  bool log_y;
  double px(double v) const { return x + (x1 > x0 ? (v - x0) / (x1 - x0) : 0.5) * w; }
  double py(double v) const
  {
    const double t = log_y ? std::log10(v) : v;
    return y + h - (y1 > y0 ? (t - y0) / (y1 - y0) : 0.5) * h;
  }
};

std::string plot_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", x);
  return buffer;
}

// Integer ticks at about `n` round steps (1, 2, 5 × 10^k) over [a, b].
std::vector<double> ticks(double a, double b, int n)
{
  std::vector<double> t;
  if(!(b > a)) { t.push_back(a); return t; }
  const double raw = (b - a) / n, p = std::pow(10., std::floor(std::log10(raw)));
  const double step = raw / p < 2 ? p : raw / p < 5 ? 2 * p : 5 * p;
  // Multiples of the step, so that 0 is exactly 0 and not a rounding residue.
  for(long k = long(std::ceil(a / step)); k * step <= b + 1e-9 * step; ++k) t.push_back(double(k) * step);
  return t;
}

void frame(std::ostream& out, const Panel& p, const std::string& title, const std::string& x_label)
{
  out << "<rect x=\"" << p.x << "\" y=\"" << p.y << "\" width=\"" << p.w << "\" height=\"" << p.h
      << "\" fill=\"none\" stroke=\"#444\"/>\n"
      << "<text x=\"" << p.x << "\" y=\"" << p.y - 8 << "\" font-weight=\"bold\">" << xml_escape(title) << "</text>\n"
      << "<text x=\"" << p.x + p.w / 2 << "\" y=\"" << p.y + p.h + 34 << "\" text-anchor=\"middle\">" << x_label
      << "</text>\n";
}

void x_ticks(std::ostream& out, const Panel& p, const std::vector<double>& values, bool integer)
{
  for(double v : values) {
    const double x = p.px(v);
    out << "<line x1=\"" << x << "\" y1=\"" << p.y + p.h << "\" x2=\"" << x << "\" y2=\"" << p.y + p.h + 5
        << "\" stroke=\"#444\"/><text x=\"" << x << "\" y=\"" << p.y + p.h + 18 << "\" text-anchor=\"middle\">"
        << (integer ? plot_number(std::round(v)) : plot_number(v)) << "</text>\n";
  }
}

// A log-scale panel of one quantity per iteration.
void log_panel(std::ostream& out, const Panel& p, const std::vector<double>& xs, const std::vector<double>& ys,
               const std::string& colour, double target)
{
  for(int e = int(p.y0); e <= int(p.y1); ++e) {
    const double y = p.py(std::pow(10., e));
    out << "<line x1=\"" << p.x << "\" y1=\"" << y << "\" x2=\"" << p.x + p.w << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/><text x=\"" << p.x - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << e
        << "</text>\n";
  }
  if(target > 0 && std::log10(target) >= p.y0 && std::log10(target) <= p.y1) {
    const double y = p.py(target);
    out << "<line x1=\"" << p.x << "\" y1=\"" << y << "\" x2=\"" << p.x + p.w << "\" y2=\"" << y
        << "\" stroke=\"#444\" stroke-dasharray=\"5,4\"/><text x=\"" << p.x + 6 << "\" y=\"" << y - 5
        << "\">tolerance " << plot_number(target) << "</text>\n";
  }
  if(xs.empty()) {
    out << "<text x=\"" << p.x + p.w / 2 << "\" y=\"" << p.y + p.h / 2 << "\" text-anchor=\"middle\">no iteration</text>\n";
    return;
  }
  std::ostringstream points;
  points.precision(6);
  for(std::size_t k = 0; k < xs.size(); ++k) points << (k ? " " : "") << p.px(xs[k]) << ',' << p.py(ys[k]);
  out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"" << points.str() << "\"/>\n";
  if(xs.size() <= 80)
    for(std::size_t k = 0; k < xs.size(); ++k)
      out << "<circle cx=\"" << p.px(xs[k]) << "\" cy=\"" << p.py(ys[k]) << "\" r=\"2.5\" fill=\"" << colour << "\"/>\n";
}

// Log10 range of the positive values (and of `extra` when > 0), whole decades.
void log_range(const std::vector<double>& ys, double extra, double& lo, double& hi)
{
  lo = 1e300; hi = -1e300;
  for(double y : ys) { lo = std::min(lo, y); hi = std::max(hi, y); }
  if(extra > 0) { lo = std::min(lo, extra); hi = std::max(hi, extra); }
  if(!(lo <= hi)) { lo = 1e-3; hi = 1; }
  lo = std::floor(std::log10(lo));
  hi = std::ceil(std::log10(hi));
  if(hi <= lo) hi = lo + 1;
}

} // namespace

void write_convergence_plot(std::ostream& out, const std::vector<SMP::Discrete_lie_flow_iteration>& history,
                            double initial_d_area, double tolerance, const std::string& caption)
{
  // d_area ≥ 2; below 1e-16 its excess is rounding, drawn at the floor.
  const double floor_value = 1e-16;
  std::vector<double> xd, yd, xr, yr;
  if(std::isfinite(initial_d_area)) { xd.push_back(0); yd.push_back(std::max(initial_d_area - 2, floor_value)); }
  for(const SMP::Discrete_lie_flow_iteration& it : history) {
    xd.push_back(double(it.iteration));
    yd.push_back(std::max(it.d_area - 2, floor_value));
    xr.push_back(double(it.iteration));
    yr.push_back(std::max(it.residual, floor_value));
  }
  const double last = history.empty() ? 1. : double(history.back().iteration);
  Panel a{ left, top, plot_width, panel_height, 0, std::max(1., last), 0, 0, true };
  log_range(yd, tolerance, a.y0, a.y1);
  Panel b = a;
  b.y = top + panel_height + gap;
  log_range(yr, 0, b.y0, b.y1);

  const double width = left + plot_width + 30, height = b.y + panel_height + 50;
  write_svg_header(out, width, height, caption);
  const std::vector<double> iteration_ticks = ticks(0, a.x1, 10);
  frame(out, a, "area distortion: d_area − 2 (log scale; optimum 0)", "iteration");
  x_ticks(out, a, iteration_ticks, true);
  log_panel(out, a, xd, yd, "#b2182b", tolerance);
  frame(out, b, "area residual: Σ (A_Ω − A_M)² / (Σ A_Ω)² (log scale)", "iteration");
  x_ticks(out, b, iteration_ticks, true);
  log_panel(out, b, xr, yr, "#2166ac", 0);
  out << "</svg>\n";
}

void write_log_ratio_histogram(std::ostream& out, const std::vector<double>& before, const std::vector<double>& after,
                               bool weighted, const std::string& caption)
{
  const int bins = 60;
  const double width = left + plot_width + 30;
  const int panels = before.empty() ? 1 : 2;
  const double height = top + panels * (panel_height + gap) + 10;
  write_svg_header(out, width, height, caption);
  const std::string quantity = weighted ? "log(domain area / (ρ · surface area))" : "log(domain area / surface area)";

  const std::vector<double>* data[2] = { &before, &after };
  const char* names[2] = { "before the flow (initial map)", "after the flow" };
  double y = top;
  for(int k = 2 - panels; k < 2; ++k) {
    const std::vector<double>& v = *data[k];
    std::vector<double> magnitude;
    double sum_abs = 0;
    for(double x : v)
      if(std::isfinite(x)) { magnitude.push_back(std::abs(x)); sum_abs += std::abs(x); }
    const std::size_t finite = magnitude.size();
    // The range holds 99.5% of the faces (the rest go to the end bins, so a
    // few outliers do not squash the shape), and at least ±log 1.1.
    double range = std::log(1.1), largest = 0;
    if(finite > 0) {
      const std::size_t q = std::min(finite - 1, std::size_t(0.995 * double(finite)));
      std::nth_element(magnitude.begin(), magnitude.begin() + std::ptrdiff_t(q), magnitude.end());
      range = std::max(range, magnitude[q] * 1.0001);
      largest = *std::max_element(magnitude.begin(), magnitude.end());
    }
    std::vector<std::size_t> count(bins, 0);
    for(double x : v)
      if(std::isfinite(x)) ++count[std::size_t(std::max(0, std::min(bins - 1, int(std::floor((x + range) / (2 * range) * bins)))))];
    const std::size_t highest = std::max<std::size_t>(1, *std::max_element(count.begin(), count.end()));

    std::ostringstream title;
    title.precision(3);
    title << names[k] << ": " << finite << " faces, mean |log ratio| " << (finite ? sum_abs / double(finite) : 0.)
          << ", max " << largest;
    if(largest > range) title << " (end bins hold the 0.5% beyond)";
    if(finite < v.size()) title << ", " << v.size() - finite << " inverted or flat left out";
    Panel p{ left, y, plot_width, panel_height, -range, range, 0, 1.05 * double(highest), false };
    frame(out, p, title.str(), quantity);
    out << "<text transform=\"translate(" << p.x - 50 << ',' << p.y + p.h / 2
        << ") rotate(-90)\" text-anchor=\"middle\">faces</text>\n";
    x_ticks(out, p, ticks(-range, range, 8), false);
    for(double t : ticks(0, double(highest), 4)) {
      const double ty = p.py(t);
      out << "<line x1=\"" << p.x - 5 << "\" y1=\"" << ty << "\" x2=\"" << p.x << "\" y2=\"" << ty
          << "\" stroke=\"#444\"/><text x=\"" << p.x - 8 << "\" y=\"" << ty + 4 << "\" text-anchor=\"end\">"
          << plot_number(std::round(t)) << "</text>\n";
    }
    // Bars in the colours of the layout picture: the same scale of ratios.
    for(int i = 0; i < bins; ++i) {
      if(count[std::size_t(i)] == 0) continue;
      const double lo = -range + 2 * range * i / bins, hi = lo + 2 * range / bins;
      const double top_y = p.py(double(count[std::size_t(i)]));
      char buffer[200];
      std::snprintf(buffer, sizeof(buffer),
                    "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\" stroke=\"#444\" "
                    "stroke-width=\"0.5\"/>\n",
                    p.px(lo), top_y, p.px(hi) - p.px(lo), p.y + p.h - top_y, colour_of_log_ratio(0.5 * (lo + hi)).c_str());
      out << buffer;
    }
    const double zero = p.px(0);
    out << "<line x1=\"" << zero << "\" y1=\"" << p.y << "\" x2=\"" << zero << "\" y2=\"" << p.y + p.h
        << "\" stroke=\"#444\" stroke-dasharray=\"3,3\"/>\n";
    y += panel_height + gap;
  }
  out << "</svg>\n";
}

} // namespace dlf_cli
