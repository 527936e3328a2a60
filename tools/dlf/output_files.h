// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output files that appear all at once or not at all: each is written to a
// hidden temporary in its own directory (so the final rename is atomic) and
// renamed only when the whole command has succeeded.

#ifndef DLF_CLI_OUTPUT_FILES_H
#define DLF_CLI_OUTPUT_FILES_H

#include <nlohmann/json.hpp>

#include <chrono>
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

/// The command's own time around the library's run, in seconds: reading
/// the input, checking it, writing the maps, drawing the pictures. Zero
/// where the command (or the Python module, which reads and writes no file)
/// has no such step.
struct Command_seconds
{
  double read = 0, check = 0, write = 0, pictures = 0;
};

/// The `seconds` object that `dlf disk`, `dlf sphere` and `dlf volume`
/// share: read, check, initial, flow, write, pictures, total, always all
/// seven in this order (0 for a step the command does not have). `total`
/// is the parameterizer's whole call (its initial map, its flow and its
/// own bookkeeping); the command's wall time is about read + check + total
/// + write + pictures. A command appends its own split after these.
nlohmann::ordered_json seconds_json(const Command_seconds& command, double initial, double flow, double total);

/// Seconds of wall time since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Writes `report` as CSV: a header line and one row. Nested objects are
/// flattened into dotted column names (`final.d_area`, `seconds.flow`),
/// lists by index (`regions.0.achieved_fraction`), except the per-iteration
/// `history` and the atlas's per-chart `chart_list`, which stay in the JSON
/// report. A null is an empty cell; strings are quoted when they hold a
/// comma, a quote or a line break (RFC 4180); numbers are written as the
/// JSON writes them (shortest round trip).
void write_csv_report(std::ostream& out, const nlohmann::ordered_json& report);

/// Writes `report` to the declared outputs `json_path` (indented by 2) and
/// `csv_path` (`write_csv_report()`); an empty path is not written.
void write_report_files(Output_files& outputs, const std::string& json_path, const std::string& csv_path,
                        const nlohmann::ordered_json& report);

} // namespace dlf_cli

#endif
