// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output files that appear all at once or not at all: each is written to a
// hidden temporary in its own directory (so the final rename is atomic) and
// renamed only when the whole command has succeeded.

#ifndef DLF_CLI_OUTPUT_FILES_H
#define DLF_CLI_OUTPUT_FILES_H

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  /// Removes the temporaries of files not committed.
  ~Output_files();

  /// Registers an output path before any work is done, so that a typo in a
  /// directory fails at once rather than after the flow. Throws `Cli_error`
  /// if the directory does not exist or is not writable, or if the path was
  /// already declared (two outputs into one file).
  void declare(const std::string& path, const std::string& option);

  /// Writes the declared `path` (to its temporary) with `body`; throws
  /// `Cli_error` if the stream fails.
  void write(const std::string& path, const std::function<void(std::ostream&)>& body);

  /// Renames every written temporary to its final name.
  void commit();

  /// The final paths written by `commit()`.
  const std::vector<std::string>& committed() const { return m_committed; }

private:
  struct File
  {
    std::string path, temporary, option;
    bool written = false;
  };
  std::vector<File> m_files;
  std::vector<std::string> m_committed;
};

} // namespace dlf_cli

#endif
