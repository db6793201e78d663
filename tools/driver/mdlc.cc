// mdlc.cc - the public API (mdlc/mdlc.h) over a Compilation.
#include "mdlc/mdlc.h"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>

#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "backend/positions.h"
#include "backend/writers/writer.h"
#include "ir/assets/package_scan.h"
#include "frontend/xacro/xacro.h"
#include "tools/driver/compiler.h"
#include "tools/driver/obj_transcoder.h"

namespace mdlc {

Input Input::File(std::string path, std::optional<Format> format) {
  return Input{std::move(path), std::nullopt, format};
}

Input Input::Text(std::string text, std::string name, std::optional<Format> format) {
  return Input{std::move(name), std::move(text), format};
}

namespace {

/// The folders a compile with `options` walks for packages, in order.
std::vector<std::string> PackageFolders(const Options& options) {
  std::vector<std::string> folders = options.package_paths;
  if (options.use_ros_package_path) {
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
void DefinePackages(const Options& options, Compilation& c) {
  for (const auto& [name, dir] : options.packages) c.packages.Add(name, dir, c.diags);
  const std::vector<std::string> folders = PackageFolders(options);
  if (options.package_scan && options.package_scan->roots() == folders) {
    for (const assets::FolderScan& folder : options.package_scan->folders()) {
      c.packages.PopulateFromScan(folder, c.sources, c.diags);
    }
  } else {
    for (const std::string& dir : folders) c.packages.PopulateFromFolder(dir, c.sources, c.diags);
  }
  if (options.use_ros_package_path) {
    if (const char* prefixes = std::getenv("AMENT_PREFIX_PATH")) {
      c.packages.PopulateFromAmentPrefixes(prefixes);
    }
  }
}

void CheckJointPositions(const Options& options, Compilation& c) {
  if (!c.model) return;
  Eigen::VectorXd q = backend::DefaultPositions(c.model->plant);
  for (const auto& [name, value] : options.joint_positions) {
    if (!backend::SetJointPositionByName(c.model->plant, q, name, value)) {
      c.diags.Report(DiagKind::UnknownReference, {},
                     fmt::format("no single-dof joint named '{}' to set the position of (use "
                                 "the scoped name 'instance::joint' when a name is ambiguous)",
                                 name));
    }
  }
}

}  // namespace

std::string DefaultMeshCacheDirectory() { return mesh::DerivedMeshCache::DefaultDirectory(); }

std::shared_ptr<const assets::PackageScan> ScanPackages(const Options& options) {
  return std::make_shared<const assets::PackageScan>(PackageFolders(options));
}

UriResolution ResolveUri(std::string_view uri, const Options& options,
                         const std::string& base_dir) {
  Compilation c(options.diagnostics);
  c.sources.set_limits(options.limits);  // package.xml files are read within them
  DefinePackages(options, c);
  UriResolution resolution;
  resolution.path = assets::ResolveUri(uri, base_dir, c.packages, {}, c.diags);
  for (const Diagnostic& d : c.diags.diagnostics()) {
    resolution.messages.push_back(FormatDiagnosticText(d, c.sources, /*color=*/false));
  }
  return resolution;
}

XacroExpansion ExpandXacro(const std::string& path, const Options& options,
                           const std::string& shown_name) {
  Compilation c(options.diagnostics);
  if (options.on_diagnostic) {
    c.diags.SetConsumer([&sources = c.sources, consumer = options.on_diagnostic](
                            const Diagnostic& d) { consumer(d, sources); });
  }
  c.sources.set_limits(options.limits);
  DefinePackages(options, c);
  xacro::XacroOptions xacro_options;
  xacro_options.args = options.xacro_args;
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
  auto c = std::make_unique<Compilation>(options.diagnostics);
  if (options.on_diagnostic) {
    c->diags.SetConsumer(
        [&sources = c->sources, consumer = options.on_diagnostic](const Diagnostic& d) {
          consumer(d, sources);
        });
  }
  c->options.inputs = inputs;
  c->options.frontend.model_name = options.model_name;
  c->options.frontend.auto_rename = options.auto_rename;
  c->options.frontend.xacro_args = options.xacro_args;
  c->options.pipeline = options.passes;
  c->options.instrumentation.print_after.insert(options.print_after.begin(),
                                                 options.print_after.end());
  c->options.instrumentation.print_after_all = options.print_after_all;
  c->options.instrumentation.print_sink = options.print_sink;
  c->options.instrumentation.time_passes = options.time_passes;
  c->options.instrumentation.verify_each = options.verify_each;
  c->options.skip_backend = options.skip_backend;
  c->options.fixed_base = options.fixed_base;
  c->sources.set_limits(options.limits);
  c->options.mesh_reading = options.mesh_reader == MeshReader::InProcess
                                ? mesh::MeshReading::kInProcess
                                : mesh::MeshReading::kChildProcess;
  c->options.mesh_axes.collada = options.collada_up_axis == ColladaUpAxis::Apply
                                     ? mesh::ColladaUpAxis::kApply
                                     : mesh::ColladaUpAxis::kAsWritten;
  if (!options.mesh_cache_dir.empty()) {
    c->derived_meshes = std::make_shared<mesh::DerivedMeshCache>(options.mesh_cache_dir);
  }
  DefinePackages(options, *c);
  if (c->Run()) CheckJointPositions(options, *c);
  return Result(std::move(c), options.joint_positions);
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
const ir::Module& Result::module() const { return compilation_->module; }

bool Result::has_model() const { return compilation_->model.has_value() && ok(); }
const backend::CompiledModel& Result::model() const {
  if (!has_model()) {
    throw std::logic_error(ok() ? "mdlc: the compile stopped before the backend (skip_backend)"
                                : "mdlc: the compile failed; see diagnostics()");
  }
  return *compilation_->model;
}

Eigen::VectorXd Result::DefaultPositions() const {
  Eigen::VectorXd q = backend::DefaultPositions(plant());
  for (const auto& [name, value] : joint_positions_) {
    backend::SetJointPositionByName(plant(), q, name, value);  // checked by Compile
  }
  return q;
}

bool Result::SetJointPosition(Eigen::VectorXd& q, std::string_view name, double value) const {
  return backend::SetJointPositionByName(plant(), q, name, value);
}

Eigen::MatrixXd Result::MassMatrix(const Eigen::VectorXd& q) const {
  return backend::CalcMassMatrix(plant(), q);
}

std::vector<Transform> Result::BodyPoses(const Eigen::VectorXd& q) const {
  return backend::BodyPosesInWorld(plant(), q);
}

std::string Result::PlantJson(const Eigen::VectorXd& q,
                              const backend::PlantJsonOptions& options) const {
  return backend::EmitPlantJson(model(), q, options);
}

const std::string& Result::timing_report() const { return compilation_->timing_report(); }

namespace {

/// Reads `paths` through the compile's mesh cache (in parallel, each file
/// once) and makes an `Out` of each: its error, or what `take` takes from
/// the mesh.
template <typename Out, typename Take>
std::vector<Out> ReadEach(mesh::MeshCache& meshes, const std::vector<std::string>& paths,
                          Take take) {
  meshes.Prefetch(paths);
  std::vector<Out> out;
  out.reserve(paths.size());
  for (const std::string& path : paths) {
    const mesh::MeshOrError m = meshes.Get(path);
    Out& o = out.emplace_back();
    if (m.ok()) {
      take(path, *m.mesh, o);
    } else {
      o.error = m.error;
    }
  }
  return out;
}

}  // namespace

std::vector<MeshSize> Result::MeshSizes(const std::vector<std::string>& resolved_paths) const {
  // the counts are among a mesh's facts: a warm cache answers without
  // reading the file
  mesh::MeshCache& meshes = *compilation_->meshes;
  meshes.Survey(resolved_paths);
  std::vector<MeshSize> out;
  out.reserve(resolved_paths.size());
  for (const std::string& path : resolved_paths) {
    const mesh::MeshStatus m = meshes.Status(path);
    MeshSize& size = out.emplace_back();
    if (m.ok()) {
      size.vertices = m.facts->vertices;
      size.triangles = m.facts->triangles;
    } else {
      size.error = m.error;
    }
  }
  return out;
}

std::vector<MeshTriangles> Result::ReadMeshes(const std::vector<std::string>& resolved_paths,
                                              std::string* axes_note) const {
  mesh::OffAxisColladaFiles off_axis;
  std::vector<MeshTriangles> meshes = ReadEach<MeshTriangles>(
      *compilation_->meshes, resolved_paths,
      [&](const std::string& path, const mesh::TriangleMesh& m, MeshTriangles& out) {
        out.vertices = m.vertices;
        out.triangles = m.triangles;
        for (const mesh::TriangleColor& c : m.colors) {
          out.colors.push_back({static_cast<size_t>(c.first_triangle), c.rgba});
        }
        off_axis.Add(path, m.declared_up, m.turned_to_z_up);
      });
  if (axes_note) *axes_note = off_axis.Note();
  return meshes;
}

std::optional<std::string> Result::Convert(const ConvertOptions& options) {
  if (!has_model()) {
    throw std::logic_error("mdlc: nothing to convert; the compile did not make a model");
  }
  writers::WriteOptions write;
  write.to = options.to;
  write.output = options.output;
  if (options.copy_assets_dir) write.copy_assets_dir = *options.copy_assets_dir;
  write.keep_package_uris = options.keep_package_uris;
  write.fuse_fixed = options.fuse_fixed;
  write.plain = options.plain;
  ObjTranscoder meshes(*compilation_->meshes);
  write.meshes = &meshes;
  return writers::Write(*compilation_->model, compilation_->module, write, compilation_->diags);
}

}  // namespace mdlc
