// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "progress.h"

#include <unistd.h>

namespace dlf_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

Progress::Progress(Verbosity verbosity, bool show_flips, std::FILE* out)
  : m_verbosity(verbosity), m_show_flips(show_flips),
    m_in_place(verbosity == Verbosity::NORMAL && ::isatty(::fileno(out)) == 1), m_out(out)
{}

std::function<bool(const SMP::Discrete_lie_flow_iteration&)> Progress::callback()
{
  if(m_verbosity == Verbosity::QUIET) return {};
  return [this](const SMP::Discrete_lie_flow_iteration& it) { return print(it); };
}

bool Progress::print(const SMP::Discrete_lie_flow_iteration& it)
{
  // "\r" and clear-to-end-of-line: the new line may be shorter than the last.
  if(m_in_place) std::fputs("\r\033[K", m_out);
  std::fprintf(m_out, "  iteration %4zu  step %-9.3g  residual %-9.3e  d_area %.8f  elapsed %.2f s", it.iteration,
               it.step, it.residual, it.d_area, it.seconds);
  if(m_verbosity == Verbosity::VERBOSE) {
    std::fprintf(m_out, "  critical %.3g (face %d)  backtracks %zu", it.critical_step, it.limiting_face, it.backtracks);
    if(m_show_flips) std::fprintf(m_out, "  flips %zu", it.flips);
  }
  if(m_in_place) m_line_open = true;
  else std::fputc('\n', m_out);
  std::fflush(m_out);
  return true;
}

void Progress::finish()
{
  if(m_line_open) std::fputc('\n', m_out);
  m_line_open = false;
  std::fflush(m_out);
}

} // namespace dlf_cli
