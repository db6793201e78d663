// mdlc/mdlc.h - mdlc as a library: compile robot models (URDF, SDFormat,
// MJCF, Drake Model Directives, with Drake's extensions), from files or from
// text in memory, into a multibody plant, its scene graph and cameras.
//
//   mdlc::Result r = mdlc::Compile(mdlc::Input::File("robot.urdf"));
//   for (const mdlc::Diagnostic& d : r.diagnostics()) std::cerr << r.FormatText(d);
//   if (!r.ok()) return 1;
//   Eigen::VectorXd q = mdlc::DefaultPositions(r);       // mdlc/kinematics.h
//   Eigen::MatrixXd M = mdlc::MassMatrix(r, q);
//   std::vector<mdlc::Transform> X_WB = mdlc::BodyPoses(r, q);  // by BodyId
//
// A Result is the outcome of a compile and what it made: the diagnostics, the
// source buffers they point into, and the plant, scene graph and cameras
// (plain data: backend/plant.h, backend/scene_graph.h). What is computed from
// it are free functions in headers of their own, included when wanted:
//   mdlc/kinematics.h  positions, mass matrix, body poses, the plant-json dump
//   mdlc/convert.h     the model written as URDF, SDFormat or MJCF
//   mdlc/meshes.h      the mesh files the model names, as the compile read them
//   mdlc/ir.h          the IR module after the passes (the compiler's internals)
// This header reaches neither the IR module nor any third-party library but
// Eigen.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backend/compiled_model.h"
#include "ir/diagnostics.h"
#include "ir/format.h"
#include "ir/limits.h"
#include "ir/source_manager.h"
#include "mdlc/version.h"

namespace mdlc {

class Compilation;
class ResultAccess;
namespace assets {
class PackageScan;
}

/// One model to compile: a file, or text held in memory.
struct Input {
  /// The file to read; for text, its name, which diagnostics print and which
  /// relative paths in the model (meshes, includes) are resolved against:
  /// text named "robots/arm.urdf" finds "meshes/a.obj" in "robots/meshes/".
  std::string path;
  /// The model's text; unset: read `path`.
  std::optional<std::string> text;
  /// Unset: taken from the extension of `path` (.urdf, .sdf, .xml, .dmd.yaml).
  std::optional<Format> format;

  static Input File(std::string path, std::optional<Format> format = {});
  static Input Text(std::string text, std::string name, std::optional<Format> format = {});
};

/// Where a compile reads mesh files (Options::meshes.reader, `--mesh-reader`).
enum class MeshReader {
  /// In worker processes running the mdlc-mesh-reader program, one per
  /// thread reading meshes, each reading many files, so that a crash or
  /// hang of the mesh importer on a malformed file is an error about that
  /// file, not a crash of the caller; a fresh worker reads the files after
  /// it. Without the program, files are read in this process and a note
  /// says so.
  Process,
  /// In this process: no worker processes, and no such protection.
  InProcess,
};

/// What a compile does with the up axis a COLLADA (.dae) mesh file declares
/// (Options::meshes.collada_up_axis, `--collada-up-axis`). glTF meshes are always
/// turned from glTF's Y-up to Z-up, as Drake turns them.
enum class ColladaUpAxis {
  /// Vertices as written, whatever the file declares: what RViz (for URDF)
  /// and Gazebo (for SDFormat) show.
  AsWritten,
  /// A file that declares X_UP or Y_UP (or nothing: Y_UP by COLLADA's
  /// default) is turned to Z-up.
  Apply,
};

/// Where package:// and model:// URIs are looked up, in this order
/// (Options::packages).
struct PackageOptions {
  /// Explicit NAME -> DIR definitions (`--package NAME=DIR`).
  std::vector<std::pair<std::string, std::string>> definitions;
  /// Folders searched for package.xml files (`--package-path DIR`).
  std::vector<std::string> paths;
  /// Also use the ROS environment: the folders of ROS_PACKAGE_PATH (ROS 1,
  /// searched like `paths`), then the packages of the ament index of each
  /// AMENT_PREFIX_PATH prefix (ROS 2). The command line does; a library
  /// reads the environment only if asked.
  bool use_ros_package_path = false;
  /// The folders above, walked once before (ScanPackages) and shared by many
  /// compiles, e.g. from several threads: the compile reads the packages
  /// from it instead of walking the folders again. Used only when it was made
  /// for the same folders; otherwise the folders are walked.
  std::shared_ptr<const assets::PackageScan> scan;
};

/// Which diagnostics count and where they go (Options::diagnostics).
struct DiagnosticOptions {
  /// Strictness and warning groups: warnings_as_errors (`--strict`,
  /// `-Werror`), disabled_groups (`-Wno-GROUP`), error_groups
  /// (`-Werror=GROUP`), max_errors (`--max-errors`).
  DiagnosticPolicy policy;
  /// Called with each diagnostic as it is reported. Unset: the Result keeps
  /// them (Result::diagnostics()). Either way Result::ok() tells the outcome.
  std::function<void(const Diagnostic&, const SourceManager&)> on_diagnostic;
};

/// What the model instances are called (Options::naming).
struct NamingOptions {
  /// Name the (single) model instance this instead of the name in the file.
  std::optional<std::string> model_name;
  /// On an instance-name collision, pick NAME_1, NAME_2, ... instead of failing.
  bool auto_rename = false;
};

/// What the model is made from and how it stands (Options::model).
struct ModelOptions {
  /// xacro's NAME:=VALUE arguments for an input that is a `.xacro` file
  /// (`mdlc compile robot.urdf.xacro ur_type:=ur5e`).
  std::vector<std::pair<std::string, std::string>> xacro_args;
  /// Weld each body that no joint holds to the world at its default pose,
  /// instead of giving it a floating joint (Drake's rule, the default): a
  /// fixed-base arm stays fixed (`--fixed-base`).
  bool fixed_base = false;
  /// Positions of 1-dof joints by scoped or unambiguous local name (`--q`),
  /// applied by DefaultPositions (mdlc/kinematics.h); an unknown name is an
  /// error.
  std::vector<std::pair<std::string, double>> joint_positions;
};

/// How mesh files are read and what is kept of them (Options::meshes).
struct MeshOptions {
  /// Where mesh files are read (`--mesh-reader=process|in-process`).
  MeshReader reader = MeshReader::Process;
  /// COLLADA's declared up axis (`--collada-up-axis=as-written|apply`).
  ColladaUpAxis collada_up_axis = ColladaUpAxis::AsWritten;
  /// Keep derived mesh data (convex hulls, mass properties) in this folder
  /// between compiles, keyed by the mesh file's content and the options
  /// (empty: no cache). The command line uses $MDLC_CACHE_DIR, else
  /// $XDG_CACHE_HOME/mdlc, else ~/.cache/mdlc (`--cache-dir`, `--no-cache`).
  std::string cache_dir;
};

/// For working on the compiler rather than with it: which passes run, and
/// what is printed, timed and verified around them (Options::instrumentation).
/// Kept apart from the options a model is compiled with, as MLIR keeps IR
/// printing and timing apart from its pass pipeline's options.
struct Instrumentation {
  /// Pass names to run instead of the default pipeline (`--passes`).
  std::vector<std::string> passes;
  /// Print the IR after these passes / after every pass, to `print_sink`
  /// (default: standard error).
  std::vector<std::string> print_after;
  bool print_after_all = false;
  std::function<void(std::string_view)> print_sink;
  /// Time each pass (TimingReport, mdlc/pass_list.h) / verify the IR after each pass.
  bool time_passes = false;
  bool verify_each = false;
};

/// Everything the `mdlc compile` command line can ask for, in groups.
struct Options {
  PackageOptions packages;
  DiagnosticOptions diagnostics;
  NamingOptions naming;
  ModelOptions model;
  MeshOptions meshes;
  /// Bounds on file sizes, document size and depth, include depth and mesh
  /// size (ir/limits.h; `--limit NAME=VALUE`). Over one is an error.
  Limits limits;
  /// Stop after the passes: the IR module only, no plant (`--emit=ir`).
  bool skip_backend = false;
  Instrumentation instrumentation;
};

/// The folder the command line keeps its mesh cache in by default (see
/// Options::meshes.cache_dir); empty when no environment variable names one.
std::string DefaultMeshCacheDirectory();

/// What a compile made: its outcome and the compiled model. Move-only; owns
/// everything it refers to. Nothing done with it afterwards changes it.
class Result {
 public:
  Result(Result&&) noexcept;
  Result& operator=(Result&&) noexcept;
  ~Result();

  /// True when no error was reported (warnings are fine, unless promoted).
  bool ok() const;
  /// Every diagnostic, in report order (empty when Options::diagnostics.on_diagnostic
  /// took them as they came).
  const std::vector<Diagnostic>& diagnostics() const;
  size_t error_count() const;
  size_t warning_count() const;
  /// `file:line:col: severity: message [-Wgroup]` with the source line, and
  /// the one-line JSON form (`--diagnostics-format=json`).
  std::string FormatText(const Diagnostic& diagnostic, bool color = false) const;
  std::string FormatJson(const Diagnostic& diagnostic) const;

  const SourceManager& sources() const;
  /// The plant, scene graph and cameras; only when has_model() (ok() and not
  /// Options::skip_backend). The accessors throw std::logic_error otherwise.
  bool has_model() const;
  const backend::CompiledModel& model() const;
  const backend::Plant& plant() const { return model().plant; }
  const backend::SceneGraph& scene_graph() const { return model().scene; }
  const std::vector<backend::SceneCamera>& cameras() const { return model().scene.cameras; }

 private:
  friend Result Compile(const std::vector<Input>& inputs, const Options& options);
  // what the free functions of the other public headers (kinematics.h,
  // convert.h, meshes.h, ir.h) read of the compile
  friend class ResultAccess;
  Result(std::unique_ptr<Compilation> compilation,
         std::vector<std::pair<std::string, double>> joint_positions);

  std::unique_ptr<Compilation> compilation_;
  std::vector<std::pair<std::string, double>> joint_positions_;
};

/// Walks the package folders of `options` (packages.paths, then those of
/// ROS_PACKAGE_PATH when use_ros_package_path) once, for
/// Options::packages.scan. The scan never changes: share it among threads.
std::shared_ptr<const assets::PackageScan> ScanPackages(const Options& options);

/// What ResolveUri found: the file, or the diagnostics that say why not.
struct UriResolution {
  std::optional<std::string> path;  // lexically normal; set when the file exists
  /// Each diagnostic as `mdlc compile` prints it (with its notes), e.g. an
  /// unknown package with the folders searched, or a path that does not exist.
  std::vector<std::string> messages;
  bool ok() const { return path.has_value(); }
};

/// Resolves a `package://`, `model://` or `file://` URI, or a path (relative
/// to `base_dir`), to an existing file or folder with the packages `options`
/// defines, exactly as a model's mesh reference is resolved: for files that
/// no model names, such as a texture or a controller's configuration
/// (Drake's PackageMap::ResolveUrl). Only the package options are used.
UriResolution ResolveUri(std::string_view uri, const Options& options = {},
                         const std::string& base_dir = ".");

/// What ExpandXacro made: the expanded XML, or the diagnostics that say why not.
struct XacroExpansion {
  /// The expanded document, as the `xacro` command writes it; set when it
  /// expanded without error.
  std::optional<std::string> xml;
  /// Every file the expansion read besides the top one (includes, YAML), as
  /// `xacro --deps` lists them.
  std::vector<std::string> dependencies;
  /// Each diagnostic as `mdlc compile` prints it, when Options::diagnostics.on_diagnostic
  /// is unset.
  std::vector<std::string> messages;
  bool ok() const { return xml.has_value(); }
};

/// Expands a xacro file (`mdlc xacro`) with Options::model.xacro_args and the
/// packages `options` defines (for `$(find PKG)`), with no compile after.
/// `shown_name` is the name the banner comment gives the input (empty: `path`).
XacroExpansion ExpandXacro(const std::string& path, const Options& options = {},
                           const std::string& shown_name = "");

/// Compiles the inputs into one plant, as `mdlc compile` does. Never throws
/// for a bad model: problems are diagnostics, and ok() is false.
Result Compile(const std::vector<Input>& inputs, const Options& options = {});
inline Result Compile(const Input& input, const Options& options = {}) {
  return Compile(std::vector<Input>{input}, options);
}

}  // namespace mdlc
