// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `discrete_lie_flow._core`: NumPy arrays in, arrays and
// report dicts out. The checks, the runs and the reports are the `dlf`
// tool's own code (disk_outcome.h, sphere_outcome.h, mesh_info.h), called on
// arrays instead of files, so that a Python run and a command-line run of
// the same mesh give the same map, bit for bit, and the same report fields.
// Keyword arguments become the tool's options (tolerance= is --tolerance)
// and are checked by the tool's parser; its messages are reworded to name
// the keyword (tolerance, not --tolerance). Wrong types raise TypeError,
// wrong shapes and values ValueError.

#include "commands.h"
#include "cli_error.h"
#include "disk_outcome.h"
#include "mesh_info.h"
#include "metrics.h"
#include "seam_input.h"
#include "sphere_outcome.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_version.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
namespace SMP = CGAL::Surface_mesh_parameterization;
using dlf_cli::Cli_error;
using dlf_cli::Indexed_mesh;
using dlf_cli::Vec2;
using dlf_cli::Vec3;

namespace {

// FlowError, created at import (a subclass of RuntimeError).
PyObject* flow_error_type = nullptr;

[[noreturn]] void value_error(const std::string& message) { throw py::value_error(message); }
[[noreturn]] void type_error(const std::string& message) { throw py::type_error(message); }

char dtype_kind(const py::array& a) { return a.dtype().kind(); }
bool is_real_kind(char k) { return k == 'f' || k == 'i' || k == 'u'; }
bool is_integer_kind(char k) { return k == 'i' || k == 'u'; }
std::string type_name(const py::handle& h) { return py::str(py::type::of(h).attr("__name__")); }
std::string dtype_name(const py::array& a) { return py::str(a.dtype()); }

// The tool's message in the words of the Python call: the keyword instead
// of the option (--max-iterations is max_iterations), no pointer to the
// tool's --help.
std::string keyword_message(std::string m)
{
  for(std::size_t see; (see = m.find(" (see 'dlf ")) != std::string::npos; ) {
    const std::size_t end = m.find(')', see);
    m.erase(see, end == std::string::npos ? std::string::npos : end - see + 1);
  }
  const std::pair<const char*, const char*> special[] = {
    { "--roi/--roi-ball", "regions" }, { "(--roi, --roi-ball)", "(regions)" }, { "--no-flips", "delaunay_flips=False" },
    { "--literal-targets", "literal_targets=True" }, { "--roi-ball", "regions" }, { "--roi", "regions" } };
  std::string out;
  for(std::size_t i = 0; i < m.size(); ) {
    bool replaced = false;
    for(const auto& p : special) {
      const std::size_t n = std::char_traits<char>::length(p.first);
      if(m.compare(i, n, p.first) == 0 && (i + n == m.size() || !(std::isalnum((unsigned char)(m[i + n])) || m[i + n] == '-'))) {
        out += p.second;
        i += n;
        replaced = true;
        break;
      }
    }
    if(replaced) continue;
    if(m.compare(i, 2, "--") == 0 && i + 2 < m.size() && std::islower((unsigned char)(m[i + 2])) &&
       (i == 0 || !std::isalnum((unsigned char)(m[i - 1])))) {
      i += 2;
      while(i < m.size() && (std::isalnum((unsigned char)(m[i])) || m[i] == '-')) out += m[i] == '-' ? '_' : m[i], ++i;
      continue;
    }
    out += m[i++];
  }
  return out;
}

std::string shape_text(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// An array of `h`, or a TypeError for what is no array of numbers (None,
// a string, a dict); a ragged list stays a ValueError (a shape).
py::array as_array(const py::handle& h, const char* name)
{
  if(h.is_none()) type_error(std::string(name) + " must be an array, not None");
  if(PyUnicode_Check(h.ptr()) || PyBytes_Check(h.ptr()))
    type_error(std::string(name) + " must be an array, not " + type_name(h));
  py::array a = py::array::ensure(h);
  if(!a) value_error(std::string(name) + " must be an array (a list of rows of equal length, or a NumPy array)");
  return a;
}

// A (rows, cols) array of real numbers as row-major doubles; any stride
// and any integer or floating dtype; the caller's array is only read.
std::vector<double> real_matrix(const py::handle& h, const char* name, py::ssize_t cols, py::ssize_t rows = -1)
{
  const py::array a = as_array(h, name);
  if(!is_real_kind(dtype_kind(a))) type_error(std::string(name) + " must hold real numbers, got dtype " + dtype_name(a));
  if(a.ndim() != 2 || a.shape(1) != cols || (rows >= 0 && a.shape(0) != rows))
    value_error(std::string(name) + " must have shape (" + (rows >= 0 ? std::to_string(rows) : std::string("n")) + ", " +
                std::to_string(cols) + "), got " + shape_text(a));
  // A C-contiguous float64 copy when needed (forcecast from the checked kinds only).
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if(!d) throw py::error_already_set();
  return std::vector<double>(d.data(), d.data() + d.size());
}

std::vector<std::vector<std::size_t> > index_triangles(const py::handle& h, std::size_t vertices)
{
  const py::array a = as_array(h, "F");
  if(!is_integer_kind(dtype_kind(a))) type_error("F must hold integers, got dtype " + dtype_name(a));
  if(a.ndim() != 2 || a.shape(1) != 3) value_error("F must have shape (m, 3), got " + shape_text(a));
  const auto d = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  if(!d) throw py::error_already_set();
  std::vector<std::vector<std::size_t> > faces(std::size_t(a.shape(0)));
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t c = 0; c < 3; ++c) {
      const long long i = d.data()[3 * f + c];
      if(i < 0 || (unsigned long long)(i) >= vertices)
        value_error("F: face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + " of " +
                    std::to_string(vertices));
      faces[f].push_back(std::size_t(i));
    }
  return faces;
}

std::vector<Vec3> points_of(const std::vector<double>& v)
{
  std::vector<Vec3> xyz(v.size() / 3);
  for(std::size_t i = 0; i < xyz.size(); ++i) xyz[i] = {{ v[3 * i], v[3 * i + 1], v[3 * i + 2] }};
  return xyz;
}

Indexed_mesh mesh_of(const py::handle& V, const py::handle& F)
{
  std::vector<Vec3> xyz = points_of(real_matrix(V, "V", 3));
  std::vector<std::vector<std::size_t> > faces = index_triangles(F, xyz.size());
  return dlf_cli::checked_triangle_mesh(std::move(xyz), std::move(faces), "mesh");
}

std::vector<double> density_of(const py::object& density)
{
  if(density.is_none()) return {};
  const py::array a = as_array(density, "density");
  if(!is_real_kind(dtype_kind(a))) type_error("density must hold real numbers, got dtype " + dtype_name(a));
  if(a.ndim() != 1)
    value_error("density must be a 1-d array (one value per face or per vertex), got shape " + shape_text(a));
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<double>(d.data(), d.data() + d.size());
}

py::object to_python(const nlohmann::ordered_json& j)
{
  // Doubles are written shortest-round-trip: the dict holds the very values.
  return py::module_::import("json").attr("loads")(j.dump());
}

std::string number(double x)
{
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// A word option (mode, init, border, name), which must not read as an option of the tool.
const std::string& word_arg(const std::string& value, const char* name)
{
  if(value.find('\0') != std::string::npos) value_error(std::string(name) + " must not contain a NUL character");
  if(value.empty() || value[0] == '-') value_error(std::string("invalid value '") + value + "' for " + name);
  return value;
}

// Face indices of the mesh (a region's), increasing and each once.
std::vector<int> face_indices(const py::handle& h, const std::string& name, std::size_t faces)
{
  const py::array a = as_array(h, name.c_str());
  if(!is_integer_kind(dtype_kind(a))) type_error(name + " must hold face indices (integers), got dtype " + dtype_name(a));
  if(a.ndim() != 1) value_error(name + " must be a 1-d array of face indices, got shape " + shape_text(a));
  const auto d = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<int> out;
  for(py::ssize_t k = 0; k < d.size(); ++k) {
    const long long f = d.data()[k];
    if(f < 0 || (unsigned long long)(f) >= faces)
      value_error(name + ": face " + std::to_string(f) + " does not exist (the mesh has " + std::to_string(faces) + " faces)");
    out.push_back(int(f));
  }
  if(out.empty()) value_error(name + " selects no face");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// `regions=[{"faces": [...] or "ball": (x, y, z, r), "factor": k, "name": ...}, ...]`
// as the tool's --roi / --roi-ball with --factor.
std::vector<dlf_cli::Region_option> regions_of(const py::object& regions, std::size_t faces)
{
  std::vector<dlf_cli::Region_option> out;
  if(regions.is_none()) return out;
  if(PyUnicode_Check(regions.ptr()) || PyDict_Check(regions.ptr()) || !PySequence_Check(regions.ptr()))
    type_error("regions must be a list of dicts, got " + type_name(regions));
  std::size_t k = 0;
  for(const py::handle& item : regions) {
    const std::string at = "regions[" + std::to_string(k++) + "]";
    if(!PyDict_Check(item.ptr())) type_error(at + " must be a dict with 'faces' or 'ball', and 'factor', got " + type_name(item));
    const py::dict d = py::reinterpret_borrow<py::dict>(item);
    for(const auto& kv : d) {
      const std::string key = py::str(kv.first);
      if(key != "faces" && key != "ball" && key != "factor" && key != "name")
        value_error(at + ": unknown key '" + key + "' (faces or ball, factor, name)");
    }
    dlf_cli::Region_option r;
    if(d.contains("faces") == d.contains("ball")) value_error(at + " needs one of 'faces' and 'ball'");
    if(d.contains("faces")) r.faces = face_indices(d["faces"], at + "['faces']", faces);
    else {
      const std::vector<double> ball = [&] {
        const py::array a = as_array(d["ball"], (at + "['ball']").c_str());
        if(!is_real_kind(dtype_kind(a))) type_error(at + "['ball'] must hold numbers (x, y, z, radius), got dtype " + dtype_name(a));
        if(a.ndim() != 1 || a.shape(0) != 4) value_error(at + "['ball'] must be (x, y, z, radius), got shape " + shape_text(a));
        const auto f = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
        return std::vector<double>(f.data(), f.data() + 4);
      }();
      for(int c = 0; c < 4; ++c) r.ball[std::size_t(c)] = ball[std::size_t(c)];
      if(!std::isfinite(ball[0] + ball[1] + ball[2]) || !(ball[3] > 0) || !std::isfinite(ball[3]))
        value_error(at + "['ball']: the centre must be finite and the radius a positive number");
    }
    if(!d.contains("factor")) value_error(at + " needs a 'factor' (its density, > 0)");
    const py::object factor = d["factor"];
    if(PyBool_Check(factor.ptr()) || !PyNumber_Check(factor.ptr()))
      type_error(at + "['factor'] must be a number, got " + type_name(factor));
    r.factor = py::float_(factor).cast<double>();
    if(!(r.factor > 0) || !std::isfinite(r.factor)) value_error(at + "['factor'] must be a positive number");
    r.label = d.contains("name") ? std::string(py::str(d["name"])) : at;
    out.push_back(r);
  }
  if(out.empty()) value_error("regions is empty: give at least one region, or None");
  return out;
}

// A number option; a TypeError (as Python's own) for anything else.
double number_arg(const py::object& x, const char* name)
{
  if(PyBool_Check(x.ptr()) || !PyNumber_Check(x.ptr()) || PyUnicode_Check(x.ptr()))
    throw py::type_error(std::string(name) + " must be a number, got " + std::string(py::str(py::type::of(x).attr("__name__"))));
  return py::float_(x).cast<double>();
}

// A word option given as an object (None allowed by the caller).
std::string string_arg(const py::object& x, const char* name)
{
  if(!PyUnicode_Check(x.ptr())) type_error(std::string(name) + " must be a string, got " + type_name(x));
  return x.cast<std::string>();
}

long long integer_arg(const py::object& x, const char* name)
{
  if(PyBool_Check(x.ptr()) || !PyIndex_Check(x.ptr()))
    throw py::type_error(std::string(name) + " must be an integer, got " + std::string(py::str(py::type::of(x).attr("__name__"))));
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(py::int_(x).ptr(), &overflow);
  if(overflow != 0) value_error(std::string(name) + " is out of range: " + std::string(py::str(x)));
  return n;
}

// The options common to both flows, as the tool's arguments.
void add_flow_arguments(std::vector<std::string>& args, const std::string& mode, const py::object& tolerance,
                        const py::object& max_iterations, const py::object& mu, const py::object& share_tolerance,
                        const py::object& fixed_step, const py::object& threshold, bool literal_targets,
                        bool delaunay_flips, bool history)
{
  args.insert(args.end(), { "--mode", word_arg(mode, "mode"), "--quiet" });
  if(!tolerance.is_none()) args.insert(args.end(), { "--tolerance", number(number_arg(tolerance, "tolerance")) });
  if(!max_iterations.is_none()) {
    const long long n = integer_arg(max_iterations, "max_iterations");
    if(n < 0) value_error("max_iterations must be >= 0");
    args.insert(args.end(), { "--max-iterations", std::to_string(n) });
  }
  if(!mu.is_none()) args.insert(args.end(), { "--mu", number(number_arg(mu, "mu")) });
  if(!share_tolerance.is_none()) args.insert(args.end(), { "--share-tolerance", number(number_arg(share_tolerance, "share_tolerance")) });
  if(!fixed_step.is_none()) args.insert(args.end(), { "--fixed-step", number(number_arg(fixed_step, "fixed_step")) });
  if(!threshold.is_none()) args.insert(args.end(), { "--threshold", number(number_arg(threshold, "threshold")) });
  if(literal_targets) args.push_back("--literal-targets");
  if(!delaunay_flips) args.push_back("--no-flips");
  if(history) args.push_back("--history");
}

// The per-iteration callback, called without the GIL held by the flow: it
// takes the GIL, calls Python, and stops the flow on False or on an
// exception, which is kept to be raised once the flow has returned.
class Python_callback
{
public:
  explicit Python_callback(py::object f) : m_f(std::move(f))
  {
    if(!m_f.is_none() && !PyCallable_Check(m_f.ptr()))
      type_error("callback must be callable (or None), got " + type_name(m_f));
  }
  ~Python_callback()
  {
    if(m_type) {
      py::gil_scoped_acquire gil;
      Py_XDECREF(m_type);
      Py_XDECREF(m_value);
      Py_XDECREF(m_trace);
    }
  }

  void install(SMP::Discrete_lie_flow_options& options)
  {
    if(m_f.is_none()) return;
    options.callback = [this](const SMP::Discrete_lie_flow_iteration& it) { return call(it); };
  }

  /// Raises the callback's exception, if any (GIL held).
  void rethrow()
  {
    if(!m_type) return;
    PyErr_Restore(m_type, m_value, m_trace);
    m_type = m_value = m_trace = nullptr;
    throw py::error_already_set();
  }

private:
  bool call(const SMP::Discrete_lie_flow_iteration& it)
  {
    py::gil_scoped_acquire gil;
    try {
      py::dict d;
      d["iteration"] = it.iteration;
      d["step"] = it.step;
      d["critical_step"] = it.critical_step;
      d["limiting_face"] = it.limiting_face;
      d["d_area"] = it.d_area;
      d["residual"] = it.residual;
      d["backtracks"] = it.backtracks;
      d["flips"] = it.flips;
      d["seconds"] = it.seconds;
      const py::object r = m_f(d);
      if(r.is_none()) return true;
      const int go_on = PyObject_IsTrue(r.ptr());
      if(go_on < 0) throw py::error_already_set();
      return go_on == 1;
    } catch(py::error_already_set& e) {
      e.restore();
      PyErr_Fetch(&m_type, &m_value, &m_trace);
      return false;
    }
  }

  py::object m_f;
  PyObject *m_type = nullptr, *m_value = nullptr, *m_trace = nullptr;
};

// Cli_error as ValueError (bad input) or FlowError (with the report, when there is one).
[[noreturn]] void raise(const Cli_error& e, const py::object& report = py::none())
{
  if(e.code() != dlf_cli::EXIT_FLOW_ERROR) throw py::value_error(keyword_message(e.what()));
  py::object error = py::reinterpret_borrow<py::object>(flow_error_type)(keyword_message(e.what()));
  error.attr("report") = report;
  PyErr_SetObject(flow_error_type, error.ptr());
  throw py::error_already_set();
}

py::array_t<double> rows_of(const std::vector<double>& flat, py::ssize_t cols)
{
  py::array_t<double> out({ py::ssize_t(flat.size()) / cols, cols });
  std::copy(flat.begin(), flat.end(), out.mutable_data());
  return out;
}

// Per-corner uv, (faces, 3, 2): corner c of face f is uv[faces[f][c]].
py::array_t<double> corners_of(const std::vector<Vec2>& uv, const std::vector<dlf_cli::Triangle>& faces)
{
  py::array_t<double> out({ py::ssize_t(faces.size()), py::ssize_t(3), py::ssize_t(2) });
  double* d = out.mutable_data();
  for(const dlf_cli::Triangle& t : faces)
    for(int v : t) {
      *d++ = uv[std::size_t(v)][0];
      *d++ = uv[std::size_t(v)][1];
    }
  return out;
}

// The seam edges of `seam=`: an (k, 2) array of vertex indices, flattened.
std::vector<long> seam_pairs(const py::object& seam)
{
  const py::array a = as_array(seam, "seam");
  if(!is_integer_kind(dtype_kind(a))) type_error("seam must hold vertex indices (integers), got dtype " + dtype_name(a));
  if(a.ndim() != 2 || a.shape(1) != 2) value_error("seam must have shape (k, 2), one edge a row, got " + shape_text(a));
  const auto d = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<long>(d.data(), d.data() + d.size());
}

// band=: a number >= 0, with regions only.
double band_arg(const py::object& band, bool has_regions)
{
  if(band.is_none()) return 0;
  const double b = number_arg(band, "band");
  if(!has_regions) value_error("band applies to regions only");
  if(!(b >= 0) || !std::isfinite(b)) value_error("band must be a number >= 0");
  return b;
}

// The flows' mesh: V and F with the checks of the tool's reader.
Indexed_mesh flow_mesh(const py::object& V, const py::object& F)
{
  try {
    return mesh_of(V, F);
  } catch(const Cli_error& e) {
    raise(e);
  }
}

// density=, regions= and band= of a flow, checked.
struct Measure_control
{
  std::vector<double> density_values;
  std::vector<dlf_cli::Region_option> regions;
  double band = 0;
};

Measure_control measure_control(const py::object& density, const py::object& regions, const py::object& band,
                                std::size_t faces)
{
  Measure_control m;
  m.density_values = density_of(density);
  m.regions = regions_of(regions, faces);
  if(!m.density_values.empty() && !m.regions.empty()) value_error("density and regions exclude each other");
  m.band = band_arg(band, !m.regions.empty());
  return m;
}

// Parses the tool's `args` into `settings` (`parse`), lets `configure`
// finish them, and runs `compute` without the GIL, the callback's
// exception raised once it has returned.
template <class Settings, class Parse, class Configure, class Compute>
auto run_flow(const std::vector<std::string>& args, Settings& settings, Python_callback& progress, Parse parse,
              Configure configure, Compute compute) -> decltype(compute())
{
  decltype(compute()) outcome;
  try {
    if(!parse(args, settings)) value_error("invalid options");
    configure();
    progress.install(settings.options);
    py::gil_scoped_release release;
    outcome = compute();
  } catch(const Cli_error& e) {
    progress.rethrow();
    raise(e);
  }
  progress.rethrow();
  return outcome;
}

py::tuple disk(const py::object& V, const py::object& F, const std::string& mode, const py::object& border,
               const std::string& init, const py::object& density, const py::object& regions, const py::object& band,
               const py::object& seam, const py::object& tolerance,
               const py::object& init_uv, const py::object& max_iterations, const py::object& mu,
               const py::object& share_tolerance, const py::object& fixed_step, const py::object& threshold,
               int outer_loop, bool literal_targets, bool delaunay_flips, bool history, const py::object& callback,
               const std::string& name)
{
  word_arg(name, "name"); // first: the messages below quote it
  const Indexed_mesh input = flow_mesh(V, F);
  const Measure_control measure = measure_control(density, regions, band, input.faces.size());
  const std::vector<long> seam_edges = seam.is_none() ? std::vector<long>() : seam_pairs(seam);
  // The caller's own start (as --init-uv): one row per vertex, its border kept.
  std::vector<std::array<double, 2> > start_uv;
  if(!init_uv.is_none()) {
    if(!seam.is_none()) value_error("init_uv applies to meshes without seam");
    if(init != "tutte") value_error("init_uv and init exclude each other");
    if(!border.is_none() && string_arg(border, "border") != "free")
      value_error("init_uv keeps the map's own border: border=\"free\" only");
    const std::vector<double> flat = real_matrix(init_uv, "init_uv", 2, py::ssize_t(input.xyz.size()));
    for(std::size_t i = 0; i < flat.size() / 2; ++i) {
      if(!std::isfinite(flat[2 * i]) || !std::isfinite(flat[2 * i + 1]))
        value_error("init_uv: row " + std::to_string(i) + " is not finite");
      start_uv.push_back({{ flat[2 * i], flat[2 * i + 1] }});
    }
  }
  std::vector<std::string> args{ word_arg(name, "name"), "--init", word_arg(init, "init"), "--outer-loop",
                                 std::to_string(outer_loop) };
  if(!start_uv.empty()) args.insert(args.end(), { "--border", "free" });
  else if(!border.is_none()) args.insert(args.end(), { "--border", word_arg(string_arg(border, "border"), "border") });
  add_flow_arguments(args, mode, tolerance, max_iterations, mu, share_tolerance, fixed_step, threshold, literal_targets,
                     delaunay_flips, history);
  dlf_cli::Disk_settings s;
  Python_callback progress(callback);
  const dlf_cli::Disk_outcome outcome = run_flow(args, s, progress, dlf_cli::parse_disk_arguments, [&] {
    if(!start_uv.empty()) { s.init = "uv"; s.init_uv = start_uv; }
    if(!seam.is_none()) { s.seam = "seam"; s.seam_pairs = seam_edges; }
    s.regions = measure.regions;
    s.band = measure.band;
    // As with a density file: a density asks for a tighter default tolerance.
    if((!measure.density_values.empty() || !measure.regions.empty()) && tolerance.is_none())
      s.options.tolerance = dlf_cli::density_tolerance;
  }, [&] { return dlf_cli::compute_disk(input, s, measure.density_values); });
  const py::object report = to_python(dlf_cli::disk_report(s, input, outcome));
  if(!outcome.ok) raise(dlf_cli::disk_failure(s, input, outcome), report);
  // With seams, a vertex on a seam has one uv per side: per-corner uv.
  if(!seam.is_none()) return py::make_tuple(corners_of(outcome.run.final_uv, outcome.cut.mesh.faces), report);
  std::vector<double> uv;
  for(const Vec2& p : outcome.run.final_uv) uv.insert(uv.end(), { p[0], p[1] });
  return py::make_tuple(rows_of(uv, 2), report);
}

py::tuple sphere(const py::object& V, const py::object& F, const std::string& mode, const py::object& density,
                 const py::object& regions, const py::object& band,
                 const py::object& tolerance, const py::object& log_area_tolerance, const py::object& max_iterations,
                 const py::object& mu, const py::object& share_tolerance, const py::object& fixed_step,
                 const py::object& threshold, bool literal_targets, bool delaunay_flips, bool history,
                 const std::string& start, const py::object& init_map, const py::object& callback,
                 const std::string& name)
{
  word_arg(name, "name"); // first: the messages below quote it
  const Indexed_mesh input = flow_mesh(V, F);
  // The caller's start: read as a mesh with the input's faces, so that its
  // rows get the same checks as V's.
  const std::vector<Vec3> start_points = [&] {
    if(init_map.is_none()) return std::vector<Vec3>();
    try {
      return mesh_of(init_map, F).xyz;
    } catch(const Cli_error& e) {
      raise(Cli_error(std::string("init_map: ") + e.what()));
    }
  }();
  const Measure_control measure = measure_control(density, regions, band, input.faces.size());
  std::vector<std::string> args{ word_arg(name, "name") };
  add_flow_arguments(args, mode, tolerance, max_iterations, mu, share_tolerance, fixed_step, threshold, literal_targets,
                     delaunay_flips, history);
  if(!log_area_tolerance.is_none())
    args.insert(args.end(), { "--log-area-tolerance", number(number_arg(log_area_tolerance, "log_area_tolerance")) });
  if(start != "tutte") {
    if(!start_points.empty()) value_error("init_map and start exclude each other");
    args.insert(args.end(), { "--start", word_arg(start, "start") });
  }
  dlf_cli::Sphere_settings s;
  Python_callback progress(callback);
  const dlf_cli::Sphere_outcome outcome = run_flow(args, s, progress, dlf_cli::parse_sphere_arguments, [&] {
    s.density.regions = measure.regions; // as --roi-ball: the sphere keeps its default tolerance
    s.density.band = measure.band;
    if(!measure.density_values.empty() && tolerance.is_none()) s.options.tolerance = dlf_cli::density_tolerance;
    if(!start_points.empty()) { s.start = "given"; s.init_map = start_points; }
  }, [&] { return dlf_cli::compute_sphere(input, s, measure.density_values); });
  if(!outcome.ok()) {
    const Cli_error e = dlf_cli::sphere_failure(s, outcome);
    raise(e, outcome.input_error() ? py::none() : to_python(dlf_cli::sphere_report(s, input, outcome)));
  }
  const py::object report = to_python(dlf_cli::sphere_report(s, input, outcome));
  std::vector<double> points;
  for(const Vec3& p : outcome.points) points.insert(points.end(), { p[0], p[1], p[2] });
  return py::make_tuple(rows_of(points, 3), report);
}

py::object score(const py::object& V, const py::object& F, const py::object& uv_in, const py::object& density)
{
  try {
    const Indexed_mesh mesh = mesh_of(V, F);
    const std::vector<double> flat = real_matrix(uv_in, "uv", 2, py::ssize_t(mesh.xyz.size()));
    std::vector<Vec2> uv(mesh.xyz.size());
    for(std::size_t i = 0; i < uv.size(); ++i) {
      uv[i] = {{ flat[2 * i], flat[2 * i + 1] }};
      if(!std::isfinite(uv[i][0]) || !std::isfinite(uv[i][1]))
        value_error("uv: vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    const std::vector<double> values = density_of(density);
    std::vector<double> face_density;
    if(!values.empty())
      face_density = dlf_cli::density_of_values(mesh, values, [&](std::size_t k) {
                       return k < values.size() ? "density[" + std::to_string(k) + "]" : std::string("density");
                     }).face_density;
    dlf_cli::Metrics m;
    {
      py::gil_scoped_release release;
      m = dlf_cli::compute_metrics(mesh, uv, face_density);
    }
    return to_python(dlf_cli::metrics_to_json(m));
  } catch(const Cli_error& e) {
    raise(e);
  }
}

py::object info(const py::object& V, const py::object& F, const std::string& name)
{
  // Unlike the flows, info() describes what it is given: non-finite
  // coordinates, unreferenced vertices, non-manifold faces are counted.
  word_arg(name, "name");
  const std::vector<Vec3> xyz = points_of(real_matrix(V, "V", 3));
  const std::vector<std::vector<std::size_t> > faces = index_triangles(F, xyz.size());
  if(faces.empty()) value_error("F: the mesh has no faces");
  return to_python(dlf_cli::mesh_info(name, xyz, faces));
}

py::tuple read_mesh(const std::string& path)
{
  dlf_cli::Indexed_mesh mesh;
  try {
    py::gil_scoped_release release;
    mesh = dlf_cli::read_triangle_mesh(path);
  } catch(const Cli_error& e) {
    raise(e);
  }
  std::vector<double> xyz;
  for(const Vec3& p : mesh.xyz) xyz.insert(xyz.end(), { p[0], p[1], p[2] });
  py::array_t<long long> faces({ py::ssize_t(mesh.faces.size()), py::ssize_t(3) });
  long long* d = faces.mutable_data();
  for(const dlf_cli::Triangle& t : mesh.faces)
    for(int v : t) *d++ = v;
  return py::make_tuple(rows_of(xyz, 3), faces);
}

typedef CGAL::Simple_cartesian<double> Atlas_kernel;
typedef CGAL::Surface_mesh<Atlas_kernel::Point_3> Atlas_mesh;

// The report of discrete_lie_flow_atlas() with the keys of `dlf atlas --report`.
nlohmann::ordered_json atlas_report(const SMP::Discrete_lie_flow_atlas_report& r, std::size_t faces,
                                    const std::string& name)
{
  nlohmann::ordered_json j = { { "input", name }, { "faces", faces } };
  const nlohmann::ordered_json atlas = dlf_cli::atlas_report_json(r);
  for(const auto& item : atlas.items()) j[item.key()] = item.value();
  return j;
}

py::tuple atlas(const py::object& V, const py::object& F, const std::string& border, const py::object& tips,
                const py::object& gutter, bool stretch, const py::object& density, const std::string& name)
{
  // Any triangle mesh the halfedge structure holds: several components,
  // any genus, isolated vertices (ignored); not repaired (the tool repairs files).
  word_arg(name, "name");
  const std::vector<Vec3> xyz = points_of(real_matrix(V, "V", 3));
  const std::vector<std::vector<std::size_t> > faces = index_triangles(F, xyz.size());
  if(faces.empty()) value_error("F: the mesh has no faces");
  for(std::size_t i = 0; i < xyz.size(); ++i)
    if(!std::isfinite(xyz[i][0]) || !std::isfinite(xyz[i][1]) || !std::isfinite(xyz[i][2]))
      value_error("V: vertex " + std::to_string(i) + " has a non-finite coordinate");
  SMP::Discrete_lie_flow_atlas_options options;
  if(border != "square" && border != "circle") value_error("invalid value '" + border + "' for border (expected square or circle)");
  options.border = border == "square" ? SMP::Discrete_lie_flow_border::SQUARE : SMP::Discrete_lie_flow_border::CIRCLE;
  if(!tips.is_none()) {
    const long long k = integer_arg(tips, "tips");
    if(k < 2 || k > 1000) value_error("tips must be a whole number from 2 to 1000");
    options.tips = std::size_t(k);
  }
  if(!gutter.is_none()) {
    options.gutter = number_arg(gutter, "gutter");
    if(!(options.gutter >= 0 && options.gutter < 0.5)) value_error("gutter must be in [0, 0.5)");
  }
  options.stretch_to_fill = stretch;
  const std::vector<double> values = density_of(density);
  if(!values.empty() && values.size() != faces.size())
    value_error("density: " + std::to_string(values.size()) + " values; expected " + std::to_string(faces.size()) +
                " (one per face)");
  for(std::size_t f = 0; f < values.size(); ++f)
    if(!(values[f] > 0) || !std::isfinite(values[f]))
      value_error("density[" + std::to_string(f) + "]: the density of face " + std::to_string(f) + " is " +
                  number(values[f]) + " (a density is a finite number > 0)");
  options.flow.face_density = values;

  Atlas_mesh mesh;
  for(const Vec3& p : xyz) mesh.add_vertex(Atlas_kernel::Point_3(p[0], p[1], p[2]));
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const auto& t = faces[f];
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      value_error("F: face " + std::to_string(f) + " uses a vertex twice");
    if(mesh.add_face(Atlas_mesh::Vertex_index(Atlas_mesh::size_type(t[0])), Atlas_mesh::Vertex_index(Atlas_mesh::size_type(t[1])),
                     Atlas_mesh::Vertex_index(Atlas_mesh::size_type(t[2]))) == Atlas_mesh::null_face())
      value_error("F: face " + std::to_string(f) + " makes the mesh non-manifold or inconsistently oriented "
                  "(`dlf atlas` repairs such files: it orients faces and splits non-manifold vertices)");
  }
  auto uv = mesh.add_property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2>("h:uv").first;
  SMP::Discrete_lie_flow_atlas_report r;
  {
    py::gil_scoped_release release;
    r = SMP::discrete_lie_flow_atlas(mesh, uv, options);
  }
  const py::object report = to_python(atlas_report(r, faces.size(), name));
  if(r.code != SMP::OK) {
    const bool input_error = r.code == SMP::ERROR_EMPTY_MESH || int(r.code) == int(SMP::ERROR_DEGENERATE_INPUT) ||
                             r.code == SMP::ERROR_NON_TRIANGULAR_MESH || int(r.code) == int(SMP::ERROR_INVALID_DENSITY);
    raise(Cli_error(name + ": " + SMP::discrete_lie_flow_error_name(r.code) + ": " + r.message,
                    input_error ? dlf_cli::EXIT_BAD_INPUT : dlf_cli::EXIT_FLOW_ERROR), report);
  }
  if(!r.valid()) raise(Cli_error(name + ": the atlas failed its exact checks", dlf_cli::EXIT_FLOW_ERROR), report);
  // Corner c of face f: the halfedge of face f that points to F[f][c].
  py::array_t<double> out({ py::ssize_t(faces.size()), py::ssize_t(3), py::ssize_t(2) });
  double* d = out.mutable_data();
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Atlas_mesh::Face_index face{ Atlas_mesh::size_type(f) };
    for(std::size_t c = 0; c < 3; ++c)
      for(auto h : CGAL::halfedges_around_face(mesh.halfedge(face), mesh))
        if(std::size_t(mesh.target(h)) == faces[f][c]) {
          d[6 * f + 2 * c] = uv[h].x();
          d[6 * f + 2 * c + 1] = uv[h].y();
        }
  }
  return py::make_tuple(out, report);
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "Discrete Lie Flow: area-preserving and measure-controlled maps of triangle meshes "
            "(the compiled part of discrete_lie_flow; import discrete_lie_flow instead).";
  m.attr("__version__") = DISCRETE_LIE_FLOW_VERSION_STR;
  flow_error_type = PyErr_NewExceptionWithDoc(
    "discrete_lie_flow.FlowError",
    "The flow failed on a valid input (the library's error code and message); `report` holds the "
    "run's report dict, as `dlf --report` writes it, or None.",
    PyExc_RuntimeError, nullptr);
  m.attr("FlowError") = py::handle(flow_error_type);

  using namespace pybind11::literals;
  m.def("disk", &disk, "V"_a, "F"_a, py::kw_only(), "mode"_a = "certified", "border"_a = py::none(),
        "init"_a = "tutte", "density"_a = py::none(), "regions"_a = py::none(), "band"_a = py::none(),
        "seam"_a = py::none(), "tolerance"_a = py::none(), "init_uv"_a = py::none(),
        "max_iterations"_a = py::none(), "mu"_a = py::none(), "share_tolerance"_a = py::none(),
        "fixed_step"_a = py::none(), "threshold"_a = py::none(), "outer_loop"_a = 0, "literal_targets"_a = false,
        "delaunay_flips"_a = true, "history"_a = false, "callback"_a = py::none(), "name"_a = "mesh",
        "Maps a disk-topology mesh (or a disk with holes) onto the plane; see discrete_lie_flow.disk.");
  m.def("sphere", &sphere, "V"_a, "F"_a, py::kw_only(), "mode"_a = "certified", "density"_a = py::none(),
        "regions"_a = py::none(), "band"_a = py::none(),
        "tolerance"_a = py::none(), "log_area_tolerance"_a = py::none(), "max_iterations"_a = py::none(),
        "mu"_a = py::none(), "share_tolerance"_a = py::none(), "fixed_step"_a = py::none(),
        "threshold"_a = py::none(), "literal_targets"_a = false,
        "delaunay_flips"_a = true, "history"_a = false, "start"_a = "tutte", "init_map"_a = py::none(),
        "callback"_a = py::none(), "name"_a = "mesh",
        "Maps a closed genus-0 mesh onto the unit sphere; see discrete_lie_flow.sphere.");
  m.def("score", &score, "V"_a, "F"_a, "uv"_a, py::kw_only(), "density"_a = py::none(),
        "The distortion metrics of a map; see discrete_lie_flow.score.");
  m.def("atlas", &atlas, "V"_a, "F"_a, py::kw_only(), "border"_a = "square", "tips"_a = py::none(),
        "gutter"_a = py::none(), "stretch"_a = true, "density"_a = py::none(), "name"_a = "mesh",
        "Any triangle mesh to an area-preserving atlas in the unit square; see discrete_lie_flow.atlas.");
  m.def("read_mesh", &read_mesh, "path"_a, "A triangle mesh file as (V, F); see discrete_lie_flow.read_mesh.");
  m.def("info", &info, "V"_a, "F"_a, py::kw_only(), "name"_a = "mesh",
        "What `dlf info` reports of a mesh; see discrete_lie_flow.info.");
}
