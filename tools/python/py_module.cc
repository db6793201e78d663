// py_module.cc - the extension module mdlc._mdlc: compile(), expand_xacro()
// and Diagnostic.
// The package mdlc (mdlc/__init__.py) wraps it with the Python-facing API:
// argument handling and the CompileError exception.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "py_model.h"

namespace mdlc::python {
namespace py = pybind11;

namespace {

/// A diagnostic with its location spelled out, for Python.
struct PyDiagnostic {
  std::string file;  // empty when the diagnostic has no location
  int line = 0, column = 0;
  std::string severity, group, kind, message;
  std::vector<std::string> notes;
  std::string text;  // as the command line prints it
};

PyDiagnostic MakeDiagnostic(const Diagnostic& d, const SourceManager& sources) {
  const DiagKindInfo& info = InfoFor(d.kind);
  PyDiagnostic out;
  if (d.loc.valid()) out.file = sources.Path(d.loc.file);
  out.line = static_cast<int>(d.loc.line);
  out.column = static_cast<int>(d.loc.column);
  out.severity = std::string(SeverityName(d.severity));
  out.group = std::string(info.group);
  out.kind = std::string(info.name);
  out.message = d.message;
  for (const DiagnosticNote& n : d.notes) out.notes.push_back(n.message);
  out.text = FormatDiagnosticText(d, sources);
  return out;
}

std::optional<Format> ParseFormat(const std::optional<std::string>& name) {
  if (!name) return std::nullopt;
  if (auto format = FormatFromName(*name)) return format;
  if (*name == "dmd.yaml") return Format::Directives;  // accepted since the module's first release
  throw py::value_error("unknown format '" + *name + "'; expected " + std::string(kFormatNames));
}

// Compiles; returns (model or None, [Diagnostic, ...]). The GIL is released
// while mdlc works, so Python threads may compile in parallel.
py::tuple CompileForPython(const std::vector<std::pair<std::string, std::optional<std::string>>>& inputs,
                           const std::optional<std::string>& format, Options options) {
  std::vector<Input> mdlc_inputs;
  const std::optional<Format> fmt = ParseFormat(format);
  for (const auto& [path, text] : inputs) {
    mdlc_inputs.push_back(text ? Input::Text(*text, path, fmt) : Input::File(path, fmt));
  }
  std::shared_ptr<const Result> result;
  {
    py::gil_scoped_release release;
    result = std::make_shared<const Result>(Compile(mdlc_inputs, options));
  }
  py::list diagnostics;
  for (const Diagnostic& d : result->diagnostics()) {
    diagnostics.append(MakeDiagnostic(d, result->sources()));
  }
  if (!result->ok() || !result->has_model()) return py::make_tuple(py::none(), diagnostics);
  return py::make_tuple(MakeModel(result, diagnostics), diagnostics);
}

// Expands a xacro file; returns (xml or None, [Diagnostic, ...]), the XML
// set when the expansion had no error. The GIL is released meanwhile.
py::tuple ExpandXacroForPython(const std::string& path, Options options) {
  std::vector<PyDiagnostic> collected;
  options.on_diagnostic = [&collected](const Diagnostic& d, const SourceManager& sources) {
    collected.push_back(MakeDiagnostic(d, sources));
  };
  XacroExpansion expansion;
  {
    py::gil_scoped_release release;
    expansion = ExpandXacro(path, options);
  }
  py::list diagnostics;
  for (PyDiagnostic& d : collected) diagnostics.append(std::move(d));
  if (!expansion.ok()) return py::make_tuple(py::none(), diagnostics);
  return py::make_tuple(*expansion.xml, diagnostics);
}

// The options compile() and expand_xacro() share: packages, xacro
// arguments, diagnostics and limits.
void SetCommonOptions(Options& options,
                      const std::vector<std::pair<std::string, std::string>>& packages,
                      const std::vector<std::string>& package_paths, bool use_ros_package_path,
                      const std::vector<std::pair<std::string, std::string>>& xacro_args,
                      bool strict, const std::vector<std::string>& limits) {
  for (const std::string& setting : limits) {
    if (auto problem = SetLimit(options.limits, setting)) throw py::value_error(*problem);
  }
  options.packages = packages;
  options.package_paths = package_paths;
  options.use_ros_package_path = use_ros_package_path;
  options.xacro_args = xacro_args;
  options.diagnostics.warnings_as_errors = strict;
}

}  // namespace
}  // namespace mdlc::python

PYBIND11_MODULE(_mdlc, m) {
  namespace py = pybind11;
  using namespace mdlc;
  using namespace mdlc::python;
  m.doc() = "mdlc's compiled core; use the package mdlc (mdlc.compile)";
  m.attr("__version__") = std::string(kVersion);

  py::class_<PyDiagnostic>(m, "Diagnostic")
      .def_readonly("file", &PyDiagnostic::file)
      .def_readonly("line", &PyDiagnostic::line)
      .def_readonly("column", &PyDiagnostic::column)
      .def_readonly("severity", &PyDiagnostic::severity, "'error', 'warning' or 'note'")
      .def_readonly("group", &PyDiagnostic::group, "The -W group, e.g. 'unknown-element'")
      .def_readonly("kind", &PyDiagnostic::kind)
      .def_readonly("message", &PyDiagnostic::message)
      .def_readonly("notes", &PyDiagnostic::notes)
      .def_readonly("text", &PyDiagnostic::text, "As the command line prints it")
      .def("__str__", [](const PyDiagnostic& d) { return d.text; })
      .def("__repr__", [](const PyDiagnostic& d) {
        return "<mdlc.Diagnostic " + d.severity + " " + d.file + ":" + std::to_string(d.line) +
               ":" + std::to_string(d.column) + ": " + d.message + ">";
      });

  BindModel(m);

  m.def(
      "_compile",
      [](const std::vector<std::pair<std::string, std::optional<std::string>>>& inputs,
         const std::optional<std::string>& format,
         const std::vector<std::pair<std::string, std::string>>& packages,
         const std::vector<std::string>& package_paths, bool use_ros_package_path, bool strict,
         const std::vector<std::string>& disabled_warnings,
         const std::vector<std::string>& error_warnings, std::optional<std::string> model_name,
         bool auto_rename, const std::vector<std::pair<std::string, double>>& joint_positions,
         const std::vector<std::string>& limits, const std::string& mesh_reader,
         const std::vector<std::pair<std::string, std::string>>& xacro_args,
         const std::string& collada_up_axis) {
        Options options;
        if (collada_up_axis == "apply") {
          options.collada_up_axis = ColladaUpAxis::Apply;
        } else if (collada_up_axis != "as-written") {
          throw py::value_error("unknown collada_up_axis '" + collada_up_axis +
                                "'; expected 'as-written' or 'apply'");
        }
        if (mesh_reader == "in-process") {
          options.mesh_reader = MeshReader::InProcess;
        } else if (mesh_reader != "process") {
          throw py::value_error("unknown mesh_reader '" + mesh_reader +
                                "'; expected 'process' or 'in-process'");
        }
        SetCommonOptions(options, packages, package_paths, use_ros_package_path, xacro_args,
                         strict, limits);
        options.diagnostics.disabled_groups.insert(disabled_warnings.begin(),
                                                   disabled_warnings.end());
        options.diagnostics.error_groups.insert(error_warnings.begin(), error_warnings.end());
        options.model_name = std::move(model_name);
        options.auto_rename = auto_rename;
        options.joint_positions = joint_positions;
        return CompileForPython(inputs, format, std::move(options));
      },
      py::arg("inputs"), py::arg("format"), py::arg("packages"), py::arg("package_paths"),
      py::arg("use_ros_package_path"), py::arg("strict"), py::arg("disabled_warnings"),
      py::arg("error_warnings"), py::arg("model_name"), py::arg("auto_rename"),
      py::arg("joint_positions"), py::arg("limits"), py::arg("mesh_reader"),
      py::arg("xacro_args"), py::arg("collada_up_axis"));

  m.def(
      "_expand_xacro",
      [](const std::string& path, const std::vector<std::pair<std::string, std::string>>& args,
         const std::vector<std::pair<std::string, std::string>>& packages,
         const std::vector<std::string>& package_paths, bool use_ros_package_path, bool strict,
         const std::vector<std::string>& limits) {
        Options options;
        SetCommonOptions(options, packages, package_paths, use_ros_package_path, args, strict,
                         limits);
        return ExpandXacroForPython(path, std::move(options));
      },
      py::arg("path"), py::arg("args"), py::arg("packages"), py::arg("package_paths"),
      py::arg("use_ros_package_path"), py::arg("strict"), py::arg("limits"));

  m.def(
      "_resolve_uri",
      [](const std::string& uri, const std::vector<std::pair<std::string, std::string>>& packages,
         const std::vector<std::string>& package_paths, bool use_ros_package_path,
         const std::string& relative_to) {
        Options options;
        options.packages = packages;
        options.package_paths = package_paths;
        options.use_ros_package_path = use_ros_package_path;
        UriResolution resolution = ResolveUri(uri, options, relative_to);
        return std::make_pair(std::move(resolution.path), std::move(resolution.messages));
      },
      py::arg("uri"), py::arg("packages"), py::arg("package_paths"),
      py::arg("use_ros_package_path"), py::arg("relative_to"));
}
