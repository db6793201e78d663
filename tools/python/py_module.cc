// py_module.cc - the extension module mdlc._mdlc: compile() (its options by
// keyword, checked as the command line checks its flags), expand_xacro() and
// Diagnostic.
// The package mdlc (mdlc/__init__.py) wraps it with the Python-facing API:
// argument handling and the CompileError exception.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mdlc/option_names.h"
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

// -- the keyword options of mdlc.compile(), checked by the same code as the
// command line's flags (mdlc/option_names.h)

std::string TypeName(py::handle value) {
  return py::str(value.get_type().attr("__name__")).cast<std::string>();
}

[[noreturn]] void WrongType(const std::string& function, const std::string& keyword,
                            const std::string& expected, py::handle value) {
  throw py::type_error(function + ": " + keyword + " expects " + expected + ", got " +
                       TypeName(value));
}

void Check(const std::optional<std::string>& problem) {
  if (problem) throw py::value_error(*problem);
}

// a str, or os.PathLike for a path
std::string Text(const std::string& function, const std::string& keyword, py::handle value,
                 bool path = false) {
  if (path && !py::isinstance<py::str>(value) && py::hasattr(value, "__fspath__")) {
    return Text(function, keyword, py::module_::import("os").attr("fspath")(value));
  }
  if (!py::isinstance<py::str>(value)) WrongType(function, keyword, path ? "a path" : "a str", value);
  return value.cast<std::string>();
}

// a list (or tuple, or other iterable) of str; a single str is one item,
// not its letters
std::vector<std::string> TextList(const std::string& function, const std::string& keyword,
                                  py::handle value, bool paths = false) {
  if (py::isinstance<py::str>(value) || (paths && py::hasattr(value, "__fspath__"))) {
    return {Text(function, keyword, value, paths)};
  }
  if (!py::isinstance<py::iterable>(value)) WrongType(function, keyword, "a list", value);
  std::vector<std::string> out;
  for (py::handle item : value) out.push_back(Text(function, keyword, item, paths));
  return out;
}

py::dict Dict(const std::string& function, const std::string& keyword, py::handle value) {
  if (!py::isinstance<py::dict>(value)) WrongType(function, keyword, "a dict", value);
  return py::reinterpret_borrow<py::dict>(value);
}

template <typename T>
T Value(const std::string& function, const std::string& keyword, py::handle value,
        const std::string& expected) {
  if constexpr (std::is_same_v<T, bool>) {
    if (!py::isinstance<py::bool_>(value)) WrongType(function, keyword, expected, value);
  }
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    WrongType(function, keyword, expected, value);
  }
}

// Sets the option `keyword` names; ValueError for an unknown keyword or
// value (with the nearest known name), TypeError for a value of the wrong
// type. None leaves an option at its default.
void ApplyKeyword(Options& options, const std::string& function, const std::string& keyword,
                  py::handle value) {
  Check(CheckOptionKeyword(keyword, function));
  if (value.is_none()) return;
  const auto& f = function;
  const auto& k = keyword;
  if (k == "packages") {
    for (auto [name, dir] : Dict(f, k, value)) {
      options.packages.definitions.emplace_back(Text(f, k, name), Text(f, k, dir, true));
    }
    std::sort(options.packages.definitions.begin(), options.packages.definitions.end());
  } else if (k == "package_paths") {
    options.packages.paths = TextList(f, k, value, true);
  } else if (k == "use_ros_package_path") {
    options.packages.use_ros_package_path = Value<bool>(f, k, value, "a bool");
  } else if (k == "strict") {
    // strict=False does not undo warnings=["error"]
    if (Value<bool>(f, k, value, "a bool")) options.diagnostics.policy.warnings_as_errors = true;
  } else if (k == "warnings") {  // the text of -W flags: "error", "no-joint", ...
    for (const std::string& flag : TextList(f, k, value)) {
      Check(ApplyWarningFlag(options.diagnostics.policy, flag, "warnings (-W" + flag + ")"));
    }
  } else if (k == "disabled_warnings") {
    for (const std::string& group : TextList(f, k, value)) {
      Check(ApplyWarningFlag(options.diagnostics.policy, "no-" + group, k));
    }
  } else if (k == "error_warnings") {
    for (const std::string& group : TextList(f, k, value)) {
      Check(ApplyWarningFlag(options.diagnostics.policy, "error=" + group, k));
    }
  } else if (k == "max_errors") {
    options.diagnostics.policy.max_errors = Value<size_t>(f, k, value, "a count");
  } else if (k == "model_name") {
    options.naming.model_name = Text(f, k, value);
  } else if (k == "auto_rename") {
    options.naming.auto_rename = Value<bool>(f, k, value, "a bool");
  } else if (k == "fixed_base") {
    options.model.fixed_base = Value<bool>(f, k, value, "a bool");
  } else if (k == "joint_positions") {
    for (auto [name, position] : Dict(f, k, value)) {
      options.model.joint_positions.emplace_back(Text(f, k, name),
                                                 Value<double>(f, k, position, "numbers"));
    }
  } else if (k == "limits") {  // {"file_size": "64M"}: --limit file-size=64M
    for (auto [name, limit] : Dict(f, k, value)) {
      std::string setting = Text(f, k, name);
      std::replace(setting.begin(), setting.end(), '_', '-');
      Check(ApplyLimitSetting(options.limits, setting + "=" + py::str(limit).cast<std::string>(),
                              k));
    }
  } else if (k == "mesh_reader") {
    Check(ParseMeshReader(Text(f, k, value), k, options.meshes.reader));
  } else if (k == "collada_up_axis") {
    Check(ParseColladaUpAxis(Text(f, k, value), k, options.meshes.collada_up_axis));
  } else if (k == "xacro_args") {
    for (auto [name, text] : Dict(f, k, value)) {
      if (!py::isinstance<py::str>(name) || !py::isinstance<py::str>(text)) {
        throw py::type_error(f + ": xacro arguments map str to str, got " + TypeName(name) +
                             " -> " + TypeName(text) + " for " +
                             py::repr(name).cast<std::string>());
      }
      options.model.xacro_args.emplace_back(name.cast<std::string>(), text.cast<std::string>());
    }
  } else if (k == "cache_dir") {
    options.meshes.cache_dir = Text(f, k, value, true);
  } else {
    // CompileOptionNames() has a keyword this function does not set
    throw py::value_error(f + ": the option '" + k + "' is not available from Python");
  }
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
  options.diagnostics.on_diagnostic = [&collected](const Diagnostic& d,
                                                    const SourceManager& sources) {
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

// The options of expand_xacro(): packages, xacro arguments, strictness and
// limits (compile() takes its options by keyword: ApplyKeyword).
void SetCommonOptions(Options& options,
                      const std::vector<std::pair<std::string, std::string>>& packages,
                      const std::vector<std::string>& package_paths, bool use_ros_package_path,
                      const std::vector<std::pair<std::string, std::string>>& xacro_args,
                      bool strict, const std::vector<std::string>& limits) {
  for (const std::string& setting : limits) {
    Check(ApplyLimitSetting(options.limits, setting, "limits"));
  }
  options.packages.definitions = packages;
  options.packages.paths = package_paths;
  options.packages.use_ros_package_path = use_ros_package_path;
  options.model.xacro_args = xacro_args;
  options.diagnostics.policy.warnings_as_errors = strict;
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
  BindDynamics(m);

  // (inputs: [(path, text or None)], format or None, {keyword: value},
  // function): the options by the keywords of mdlc.compile, each checked
  // by name and value (ApplyKeyword); `function` names the caller in errors
  m.def(
      "_compile",
      [](const std::vector<std::pair<std::string, std::optional<std::string>>>& inputs,
         const std::optional<std::string>& format, const py::dict& keywords,
         const std::string& function) {
        Options options;
        for (auto [keyword, value] : keywords) {
          ApplyKeyword(options, function, py::str(keyword).cast<std::string>(), value);
        }
        return CompileForPython(inputs, format, std::move(options));
      },
      py::arg("inputs"), py::arg("format"), py::arg("options"), py::arg("function"));

  m.def("_option_names", [] {
    std::vector<std::string> names;
    for (const OptionName& o : CompileOptionNames()) names.emplace_back(o.keyword);
    return names;
  }, "The keywords mdlc.compile takes");

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
        options.packages.definitions = packages;
        options.packages.paths = package_paths;
        options.packages.use_ros_package_path = use_ros_package_path;
        UriResolution resolution = ResolveUri(uri, options, relative_to);
        return std::make_pair(std::move(resolution.path), std::move(resolution.messages));
      },
      py::arg("uri"), py::arg("packages"), py::arg("package_paths"),
      py::arg("use_ros_package_path"), py::arg("relative_to"));
}
