// mdlc.cc - the public API (mdlc/mdlc.h) over a Compilation.
#include "mdlc/mdlc.h"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>

#include "backend/positions.h"
#include "ir/assets/package_scan.h"
#include "frontend/xacro/xacro.h"
#include "tools/driver/compiler.h"

namespace mdlc {

Input Input::File(std::string path, std::optional<Format> format) {
  return Input{std::move(path), std::nullopt, format};
}

Input Input::Text(std::string text, std::string name, std::optional<Format> format) {
  return Input{std::move(name), std::move(text), format};
}

namespace {

/// The folders a compile with `packages` walks for package.xml files, in order.
std::vector<std::string> PackageFolders(const PackageOptions& packages) {
  std::vector<std::string> folders = packages.paths;
  if (packages.use_ros_package_path) {
    if (const char* ros = std::getenv("ROS_PACKAGE_PATH")) {
      for (std::string& dir : assets::SplitPathList(ros)) folders.push_back(std::move(dir));
    }
  }
  return folders;
}

// Packages come from the explicit list, then the package paths and ROS 1's
// ROS_PACKAGE_PATH (walked for package.xml files), then a ROS 2 install's
// ament index. Reading an index lists one folder per prefix, so it is done
// per compile rather than kept in the shared scan.
void DefinePackages(const PackageOptions& packages, Compilation& c) {
  for (const auto& [name, dir] : packages.definitions) c.packages.Add(name, dir, c.diags);
  const std::vector<std::string> folders = PackageFolders(packages);
  if (packages.scan && packages.scan->roots() == folders) {
    for (const assets::FolderScan& folder : packages.scan->folders()) {
      c.packages.PopulateFromScan(folder, c.sources, c.diags);
    }
  } else {
    for (const std::string& dir : folders) c.packages.PopulateFromFolder(dir, c.sources, c.diags);
  }
  if (packages.use_ros_package_path) {
    if (const char* prefixes = std::getenv("AMENT_PREFIX_PATH")) {
      c.packages.PopulateFromAmentPrefixes(prefixes);
    }
  }
}

void CheckJointPositions(const ModelOptions& model, Compilation& c) {
  if (!c.model) return;
  Eigen::VectorXd q = backend::DefaultPositions(c.model->plant);
  for (const auto& [name, value] : model.joint_positions) {
    if (!backend::SetJointPositionByName(c.model->plant, q, name, value)) {
      c.diags.Report(DiagKind::UnknownReference, {},
                     fmt::format("no single-dof joint named '{}' to set the position of (use "
                                 "the scoped name 'instance::joint' when a name is ambiguous)",
                                 name));
    }
  }
}

// A compilation whose diagnostics follow `diagnostics`: counted by its
// policy, and handed to on_diagnostic as they come when it is set.
std::unique_ptr<Compilation> MakeCompilation(const DiagnosticOptions& diagnostics) {
  auto c = std::make_unique<Compilation>(diagnostics.policy);
  c->options.diagnostics = diagnostics.policy;
  if (diagnostics.on_diagnostic) {
    c->diags.SetConsumer(
        [&sources = c->sources, consumer = diagnostics.on_diagnostic](const Diagnostic& d) {
          consumer(d, sources);
        });
  }
  return c;
}

// The public instrumentation is the pass manager's, with the pipeline apart
// (CompileOptions::pipeline) and print_after as a set.
passes::PassInstrumentation PassInstrumentationOf(const Instrumentation& in) {
  passes::PassInstrumentation out;
  out.print_after.insert(in.print_after.begin(), in.print_after.end());
  out.print_after_all = in.print_after_all;
  out.print_sink = in.print_sink;
  out.time_passes = in.time_passes;
  out.verify_each = in.verify_each;
  return out;
}

void SetMeshOptions(const MeshOptions& meshes, Compilation& c) {
  c.options.mesh_reading = meshes.reader == MeshReader::InProcess
                               ? mesh::MeshReading::kInProcess
                               : mesh::MeshReading::kChildProcess;
  c.options.mesh_axes.collada = meshes.collada_up_axis == ColladaUpAxis::Apply
                                    ? mesh::ColladaUpAxis::kApply
                                    : mesh::ColladaUpAxis::kAsWritten;
  if (!meshes.cache_dir.empty()) {
    c.derived_meshes = std::make_shared<mesh::DerivedMeshCache>(meshes.cache_dir);
  }
}

}  // namespace

std::string DefaultMeshCacheDirectory() { return mesh::DerivedMeshCache::DefaultDirectory(); }

std::shared_ptr<const assets::PackageScan> ScanPackages(const Options& options) {
  return std::make_shared<const assets::PackageScan>(PackageFolders(options.packages));
}

UriResolution ResolveUri(std::string_view uri, const Options& options,
                         const std::string& base_dir) {
  Compilation c(options.diagnostics.policy);
  c.sources.set_limits(options.limits);  // package.xml files are read within them
  DefinePackages(options.packages, c);
  UriResolution resolution;
  resolution.path = assets::ResolveUri(uri, base_dir, c.packages, {}, c.diags);
  for (const Diagnostic& d : c.diags.diagnostics()) {
    resolution.messages.push_back(FormatDiagnosticText(d, c.sources, /*color=*/false));
  }
  return resolution;
}

XacroExpansion ExpandXacro(const std::string& path, const Options& options,
                           const std::string& shown_name) {
  std::unique_ptr<Compilation> compilation = MakeCompilation(options.diagnostics);
  Compilation& c = *compilation;
  c.sources.set_limits(options.limits);
  DefinePackages(options.packages, c);
  xacro::XacroOptions xacro_options;
  xacro_options.args = options.model.xacro_args;
  xacro_options.packages = &c.packages;
  XacroExpansion out;
  std::unique_ptr<xacro::Expansion> expansion =
      xacro::ExpandFile(path, xacro_options, c.sources, c.diags);
  if (expansion) {
    out.dependencies = expansion->dependencies;
    if (!c.diags.has_errors()) {
      out.xml = xacro::WriteXml(*expansion, shown_name.empty() ? path : shown_name);
    }
  }
  for (const Diagnostic& d : c.diags.diagnostics()) {
    out.messages.push_back(FormatDiagnosticText(d, c.sources, /*color=*/false));
  }
  return out;
}

Result Compile(const std::vector<Input>& inputs, const Options& options) {
  std::unique_ptr<Compilation> c = MakeCompilation(options.diagnostics);
  c->options.inputs = inputs;
  c->options.frontend.model_name = options.naming.model_name;
  c->options.frontend.auto_rename = options.naming.auto_rename;
  c->options.frontend.xacro_args = options.model.xacro_args;
  c->options.fixed_base = options.model.fixed_base;
  c->options.pipeline = options.instrumentation.passes;
  c->options.instrumentation = PassInstrumentationOf(options.instrumentation);
  c->options.skip_backend = options.skip_backend;
  c->sources.set_limits(options.limits);
  SetMeshOptions(options.meshes, *c);
  DefinePackages(options.packages, *c);
  if (c->Run()) CheckJointPositions(options.model, *c);
  return Result(std::move(c), options.model.joint_positions);
}

Result::Result(std::unique_ptr<Compilation> compilation,
               std::vector<std::pair<std::string, double>> joint_positions)
    : compilation_(std::move(compilation)), joint_positions_(std::move(joint_positions)) {}
Result::Result(Result&&) noexcept = default;
Result& Result::operator=(Result&&) noexcept = default;
Result::~Result() = default;

bool Result::ok() const { return !compilation_->diags.has_errors(); }
const std::vector<Diagnostic>& Result::diagnostics() const {
  return compilation_->diags.diagnostics();
}
size_t Result::error_count() const { return compilation_->diags.error_count(); }
size_t Result::warning_count() const { return compilation_->diags.warning_count(); }

std::string Result::FormatText(const Diagnostic& diagnostic, bool color) const {
  return FormatDiagnosticText(diagnostic, compilation_->sources, color);
}
std::string Result::FormatJson(const Diagnostic& diagnostic) const {
  return FormatDiagnosticJson(diagnostic, compilation_->sources);
}

const SourceManager& Result::sources() const { return compilation_->sources; }

bool Result::has_model() const { return compilation_->model.has_value() && ok(); }
const backend::CompiledModel& Result::model() const {
  if (!has_model()) {
    throw std::logic_error(ok() ? "mdlc: the compile stopped before the backend (skip_backend)"
                                : "mdlc: the compile failed; see diagnostics()");
  }
  return *compilation_->model;
}

}  // namespace mdlc
