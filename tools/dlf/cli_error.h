// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one error type of the `dlf` tool: a one-line message and the exit code
// it maps to. Thrown anywhere in the tool, caught once in main().

#ifndef DLF_CLI_CLI_ERROR_H
#define DLF_CLI_CLI_ERROR_H

#include <stdexcept>
#include <string>

namespace dlf_cli {

/// Exit codes of the tool.
enum Exit_code
{
  EXIT_OK = 0,
  EXIT_BAD_INPUT = 1,   ///< usage error, unreadable or unsuitable input, output not writable
  EXIT_FLOW_ERROR = 2,  ///< the parameterizer returned an error (or the command is not available)
  EXIT_NOT_CONVERGED = 3 ///< a valid, fold-free map was written, but the flow stopped short of its targets
};

class Cli_error : public std::runtime_error
{
public:
  explicit Cli_error(const std::string& message, Exit_code code = EXIT_BAD_INPUT)
    : std::runtime_error(message), m_code(code)
  {}
  Exit_code code() const { return m_code; }

private:
  Exit_code m_code;
};

} // namespace dlf_cli

#endif
