// mdlc/mdlc.h - mdlc as a library: compile robot models (URDF, SDFormat,
// MJCF, Drake Model Directives, with Drake's extensions), from files or from
// text in memory, into a multibody plant, its scene graph and cameras.
//
//   mdlc::Result r = mdlc::Compile(mdlc::Input::File("robot.urdf"));
//   for (const mdlc::Diagnostic& d : r.diagnostics()) std::cerr << r.FormatText(d);
//   if (!r.ok()) return 1;
//   Eigen::VectorXd q = r.DefaultPositions();
//   Eigen::MatrixXd M = r.MassMatrix(q);
//   std::vector<mdlc::Transform> X_WB = r.BodyPoses(q);  // indexed by BodyId
//
// Everything a compile makes stays in its Result: the source buffers (which
// diagnostics point into), the IR module and the compiled model. The plant
// and scene graph are plain data (backend/plant.h, backend/scene_graph.h).
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
#include "backend/plant_json.h"
#include "ir/diagnostics.h"
#include "ir/format.h"
#include "ir/limits.h"
#include "ir/module.h"
#include "ir/source_manager.h"
#include "ir/transform.h"
#include "mdlc/version.h"

namespace mdlc {

class Compilation;
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

/// Where a compile reads mesh files (Options::mesh_reader, `--mesh-reader`).
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
/// (Options::collada_up_axis, `--collada-up-axis`). glTF meshes are always
/// turned from glTF's Y-up to Z-up, as Drake turns them.
enum class ColladaUpAxis {
  /// Vertices as written, whatever the file declares: what RViz (for URDF)
  /// and Gazebo (for SDFormat) show.
  AsWritten,
  /// A file that declares X_UP or Y_UP (or nothing: Y_UP by COLLADA's
  /// default) is turned to Z-up.
  Apply,
};

/// Everything the `mdlc compile` command line can ask for.
struct Options {
  // -- packages, for package:// and model:// URIs, looked up in this order
  /// Explicit NAME -> DIR definitions (`--package NAME=DIR`).
  std::vector<std::pair<std::string, std::string>> packages;
  /// Folders searched for package.xml files (`--package-path DIR`).
  std::vector<std::string> package_paths;
  /// Also use the ROS environment: the folders of ROS_PACKAGE_PATH (ROS 1,
  /// searched like package_paths), then the packages of the ament index of
  /// each AMENT_PREFIX_PATH prefix (ROS 2). The command line does; a library
  /// reads the environment only if asked.
  bool use_ros_package_path = false;
  /// The folders above, walked once before (ScanPackages) and shared by many
  /// compiles, e.g. from several threads: the compile reads the packages
  /// from it instead of walking the folders again. Used only when it was made
  /// for the same folders; otherwise the folders are walked.
  std::shared_ptr<const assets::PackageScan> package_scan;

  // -- diagnostics
  /// Strictness and warning groups: warnings_as_errors (`--strict`,
  /// `-Werror`), disabled_groups (`-Wno-GROUP`), error_groups
  /// (`-Werror=GROUP`), max_errors (`--max-errors`).
  DiagnosticPolicy diagnostics;
  /// Called with each diagnostic as it is reported. Unset: the Result keeps
  /// them (Result::diagnostics()). Either way Result::ok() tells the outcome.
  std::function<void(const Diagnostic&, const SourceManager&)> on_diagnostic;

  // -- xacro
  /// xacro's NAME:=VALUE arguments for an input that is a `.xacro` file
  /// (`mdlc compile robot.urdf.xacro ur_type:=ur5e`).
  std::vector<std::pair<std::string, std::string>> xacro_args;

  // -- naming
  /// Name the (single) model instance this instead of the name in the file.
  std::optional<std::string> model_name;
  /// On an instance-name collision, pick NAME_1, NAME_2, ... instead of failing.
  bool auto_rename = false;

  // -- joint positions
  /// Positions of 1-dof joints by scoped or unambiguous local name (`--q`),
  /// applied by Result::DefaultPositions; an unknown name is an error.
  std::vector<std::pair<std::string, double>> joint_positions;

  // -- the base
  /// Weld each body that no joint holds to the world at its default pose,
  /// instead of giving it a floating joint (Drake's rule, the default): a
  /// fixed-base arm stays fixed (`--fixed-base`).
  bool fixed_base = false;

  // -- the pipeline
  /// Pass names to run instead of the default pipeline (`--passes`).
  std::vector<std::string> passes;
  /// Print the IR after these passes / after every pass, to `print_sink`
  /// (default: standard error).
  std::vector<std::string> print_after;
  bool print_after_all = false;
  std::function<void(std::string_view)> print_sink;
  /// Time each pass (Result::timing_report) / verify the IR after each pass.
  bool time_passes = false;
  bool verify_each = false;
  /// Stop after the passes: the IR module only, no plant (`--emit=ir`).
  bool skip_backend = false;

  // -- input limits
  /// Bounds on file sizes, document size and depth, include depth and mesh
  /// size (ir/limits.h; `--limit NAME=VALUE`). Over one is an error.
  Limits limits;
  /// Where mesh files are read (`--mesh-reader=process|in-process`).
  MeshReader mesh_reader = MeshReader::Process;
  /// COLLADA's declared up axis (`--collada-up-axis=as-written|apply`).
  ColladaUpAxis collada_up_axis = ColladaUpAxis::AsWritten;

  // -- caching
  /// Keep derived mesh data (convex hulls, mass properties) in this folder
  /// between compiles, keyed by the mesh file's content and the options
  /// (empty: no cache). The command line uses $MDLC_CACHE_DIR, else
  /// $XDG_CACHE_HOME/mdlc, else ~/.cache/mdlc (`--cache-dir`, `--no-cache`).
  std::string mesh_cache_dir;
};

/// The folder the command line keeps its mesh cache in by default (see
/// Options::mesh_cache_dir); empty when no environment variable names one.
std::string DefaultMeshCacheDirectory();

/// How big a mesh file is, as the compile's mesh reader sees it
/// (Result::MeshSizes): vertices at the same position count once, polygons
/// count as the triangles they are split into.
struct MeshSize {
  size_t vertices = 0;
  size_t triangles = 0;
  std::string error;  // set when the file could not be read as a mesh
  bool ok() const { return error.empty(); }
};

/// A run of a mesh's triangles in one colour of the file's materials
/// (COLLADA, glTF, OBJ's .mtl): from first_triangle to the next run's first
/// triangle (or the end); RGBA in [0, 1].
struct MeshColor {
  size_t first_triangle = 0;
  Eigen::Vector4d rgba;
};

/// A mesh file's triangles as the compile reads them (Result::ReadMeshes):
/// unscaled (the geometry's scale is not applied), glTF turned Z-up, COLLADA
/// as Options::collada_up_axis says.
struct MeshTriangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<MeshColor> colors;  // empty when the file names no colour
  std::string error;  // set when the file could not be read as a mesh
  bool ok() const { return error.empty(); }
};

/// What `mdlc convert` writes (Result::Convert).
struct ConvertOptions {
  /// The target: urdf, sdf or mjcf.
  Format to = Format::Urdf;
  /// The file the text will be written to: mesh paths are written relative
  /// to its folder (empty: the current directory).
  std::string output;
  /// Copy every mesh into this folder (one copy per distinct content) and
  /// name the copies; a mesh the target cannot read (MJCF: other than STL,
  /// OBJ or MSH) is written as an OBJ of the triangles mdlc read.
  std::optional<std::string> copy_assets_dir;
  /// URDF only: plain URDF that urdfdom and ROS read (`--plain`): one root
  /// link, with a floating joint to each free body, and Drake's shapes and
  /// joints approximated (-Wlossy).
  bool plain = false;
  /// Keep package:// URIs as the source wrote them.
  bool keep_package_uris = false;
  /// MJCF only: fuse each body welded to its parent (not to the world) into
  /// that body, mass properties combined exactly, its geometry, frames and
  /// cameras re-posed there, its own frame kept as a site (`--fuse-fixed`).
  bool fuse_fixed = false;
};

/// What a compile made. Move-only; owns everything it refers to.
class Result {
 public:
  Result(Result&&) noexcept;
  Result& operator=(Result&&) noexcept;
  ~Result();

  /// True when no error was reported (warnings are fine, unless promoted).
  bool ok() const;
  /// Every diagnostic, in report order (empty when Options::on_diagnostic
  /// took them as they came).
  const std::vector<Diagnostic>& diagnostics() const;
  size_t error_count() const;
  size_t warning_count() const;
  /// `file:line:col: severity: message [-Wgroup]` with the source line, and
  /// the one-line JSON form (`--diagnostics-format=json`).
  std::string FormatText(const Diagnostic& diagnostic, bool color = false) const;
  std::string FormatJson(const Diagnostic& diagnostic) const;

  const SourceManager& sources() const;
  /// The IR after the passes (as far as they got when !ok()).
  const ir::Module& module() const;

  /// The plant, scene graph and cameras; only when has_model() (ok() and not
  /// Options::skip_backend). The accessors throw std::logic_error otherwise.
  bool has_model() const;
  const backend::CompiledModel& model() const;
  const backend::Plant& plant() const { return model().plant; }
  const backend::SceneGraph& scene_graph() const { return model().scene; }
  const std::vector<backend::SceneCamera>& cameras() const { return model().scene.cameras; }

  /// Each joint's default position, then Options::joint_positions.
  Eigen::VectorXd DefaultPositions() const;
  /// Sets 1-dof joint `name` (scoped, or local when unambiguous) in q;
  /// false when there is no such joint.
  bool SetJointPosition(Eigen::VectorXd& q, std::string_view name, double value) const;
  /// The nv x nv mass matrix at q (size num_positions; else
  /// std::invalid_argument), rows and columns in velocity order.
  Eigen::MatrixXd MassMatrix(const Eigen::VectorXd& q) const;
  /// X_WB of every body at q, indexed by BodyId (0 is the world).
  std::vector<Transform> BodyPoses(const Eigen::VectorXd& q) const;
  /// The plant-json dump at q (the contract: shared/spec/plant-json.md).
  std::string PlantJson(const Eigen::VectorXd& q,
                        const backend::PlantJsonOptions& options = {}) const;

  /// The --time-passes report (Options::time_passes).
  const std::string& timing_report() const;

  /// The sizes of mesh files the model names (ir::Mesh::resolved paths),
  /// from the meshes this compile read: a file the passes read is not read
  /// again, nor one the mesh cache knows; the others are read now, in
  /// parallel.
  std::vector<MeshSize> MeshSizes(const std::vector<std::string>& resolved_paths) const;
  /// The triangles of those files, read the same way (and as the compile
  /// reads them: its reader, its axes). `axes_note`, when given, gets the
  /// note mdlc gives about COLLADA files among them that declare an up axis
  /// other than Z (empty when none do).
  std::vector<MeshTriangles> ReadMeshes(const std::vector<std::string>& resolved_paths,
                                        std::string* axes_note = nullptr) const;

  /// The compiled model written as options.to (`mdlc convert`). What the
  /// target cannot hold is reported as -Wlossy warnings, added to
  /// diagnostics(); nullopt (and !ok()) after an error, e.g. a lossy
  /// warning made an error by the diagnostic policy.
  std::optional<std::string> Convert(const ConvertOptions& options);

 private:
  friend Result Compile(const std::vector<Input>& inputs, const Options& options);
  Result(std::unique_ptr<Compilation> compilation,
         std::vector<std::pair<std::string, double>> joint_positions);

  std::unique_ptr<Compilation> compilation_;
  std::vector<std::pair<std::string, double>> joint_positions_;
};

/// Walks the package folders of `options` (package_paths, then those of
/// ROS_PACKAGE_PATH when use_ros_package_path) once, for
/// Options::package_scan. The scan never changes: share it among threads.
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
  /// Each diagnostic as `mdlc compile` prints it, when Options::on_diagnostic
  /// is unset.
  std::vector<std::string> messages;
  bool ok() const { return xml.has_value(); }
};

/// Expands a xacro file (`mdlc xacro`) with Options::xacro_args and the
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
