// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "output_files.h"
#include "cli_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace dlf_cli {

namespace fs = std::filesystem;

Output_files::~Output_files()
{
  for(const File& f : m_files) {
    if(!f.written) continue;
    std::error_code ignored;
    fs::remove(f.temporary, ignored);
  }
}

void Output_files::declare(const std::string& path, const std::string& option)
{
  if(path.empty()) throw Cli_error(option + " needs a file name");
  const fs::path p(path);
  std::error_code ec;
  // weakly_canonical: "x.obj" and "./x.obj" are one file, and neither exists yet.
  for(const File& f : m_files)
    if(fs::weakly_canonical(fs::absolute(f.path), ec) == fs::weakly_canonical(fs::absolute(p), ec))
      throw Cli_error(option + " and " + f.option + " name the same file '" + path + "'");
  if(fs::is_directory(p, ec)) throw Cli_error(option + " '" + path + "' is a directory");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if(!fs::is_directory(dir, ec))
    throw Cli_error(option + " '" + path + "': directory '" + dir.string() + "' does not exist");
  if(::access(dir.c_str(), W_OK) != 0)
    throw Cli_error(option + " '" + path + "': directory '" + dir.string() + "' is not writable");
  File f;
  f.path = path;
  f.option = option;
  // Hidden, next to the target (rename() is atomic only within a file
  // system), and unique to this process.
  f.temporary = (dir / ("." + p.filename().string() + ".dlf-" + std::to_string(::getpid()) + ".tmp")).string();
  m_files.push_back(f);
}

void Output_files::write(const std::string& path, const std::function<void(std::ostream&)>& body)
{
  for(File& f : m_files) {
    if(f.path != path) continue;
    f.written = true; // from here on, the destructor removes the temporary
    std::ofstream out(f.temporary, std::ios::binary | std::ios::trunc);
    if(!out) throw Cli_error("cannot create '" + f.temporary + "': " + std::strerror(errno));
    body(out);
    out.flush();
    if(!out) throw Cli_error("cannot write '" + path + "' (disk full?)");
    out.close();
    if(out.fail()) throw Cli_error("cannot write '" + path + "' (disk full?)");
    return;
  }
  throw Cli_error("internal error: output '" + path + "' was not declared");
}

void Output_files::commit()
{
  for(File& f : m_files) {
    if(!f.written) continue;
    if(std::rename(f.temporary.c_str(), f.path.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      // All or nothing: take back what this commit already renamed.
      for(const std::string& done : m_committed) std::remove(done.c_str());
      m_committed.clear();
      throw Cli_error("cannot rename '" + f.temporary + "' to '" + f.path + "': " + reason);
    }
    f.written = false;
    m_committed.push_back(f.path);
  }
}

nlohmann::ordered_json seconds_json(const Command_seconds& c, double initial, double flow, double total)
{
  return { { "read", c.read }, { "check", c.check }, { "initial", initial }, { "flow", flow },
           { "write", c.write }, { "pictures", c.pictures }, { "total", total } };
}

namespace {

// Lists of their own, one entry per iteration or per chart: a table each,
// not columns of a one-row table.
bool is_long_list(const std::string& key) { return key == "history" || key == "chart_list"; }

void flatten(const nlohmann::ordered_json& j, const std::string& name,
             std::vector<std::pair<std::string, const nlohmann::ordered_json*> >& cells)
{
  if(j.is_object() && !j.empty()) {
    for(auto it = j.begin(); it != j.end(); ++it) {
      if(name.empty() && is_long_list(it.key())) continue;
      flatten(it.value(), name.empty() ? it.key() : name + "." + it.key(), cells);
    }
  } else if(j.is_array() && !j.empty()) {
    for(std::size_t k = 0; k < j.size(); ++k) flatten(j[k], name + "." + std::to_string(k), cells);
  } else {
    cells.emplace_back(name, &j);
  }
}

std::string csv_field(const std::string& text)
{
  if(text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for(char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_value(const nlohmann::ordered_json& j)
{
  if(j.is_null() || (j.is_structured() && j.empty())) return "";
  if(j.is_string()) return csv_field(j.get<std::string>());
  return j.dump();
}

} // namespace

void write_csv_report(std::ostream& out, const nlohmann::ordered_json& report)
{
  std::vector<std::pair<std::string, const nlohmann::ordered_json*> > cells;
  flatten(report, "", cells);
  for(std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << csv_field(cells[k].first);
  out << "\n";
  for(std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << csv_value(*cells[k].second);
  out << "\n";
}

void write_report_files(Output_files& outputs, const std::string& json_path, const std::string& csv_path,
                        const nlohmann::ordered_json& report)
{
  if(!json_path.empty()) outputs.write(json_path, [&](std::ostream& o) { o << report.dump(2) << '\n'; });
  if(!csv_path.empty()) outputs.write(csv_path, [&](std::ostream& o) { write_csv_report(o, report); });
}

} // namespace dlf_cli
