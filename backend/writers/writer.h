// writer.h - the compiled model written out as URDF, SDFormat or MJCF
// (`mdlc convert`).
//
// A writer reads the instantiated plant and scene graph (what every format
// agrees on once compiled), and the IR module it was built from only for
// source locations: plant body i is IR body i, and so on (backend/plant.h).
// What the target format cannot express is reported as a -Wlossy warning at
// its source location, saying what was dropped or approximated; --strict
// makes those errors.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "backend/compiled_model.h"
#include "backend/writers/mesh_transcoder.h"
#include "ir/diagnostics.h"
#include "ir/format.h"
#include "ir/module.h"

namespace mdlc::writers {

struct WriteOptions {
  /// urdf, sdf or mjcf.
  Format to = Format::Urdf;
  /// The file being written: mesh paths are made relative to its folder
  /// (empty: the current directory).
  std::filesystem::path output;
  /// Copy every mesh into this folder (one copy per distinct content) and
  /// name the copies instead of the originals; a mesh the target cannot
  /// read is written as an OBJ of the triangles mdlc read (asset_paths.h).
  std::optional<std::filesystem::path> copy_assets_dir;
  /// Gives those OBJ copies, from the meshes as the compile read them (its
  /// limits and up-axis handling); null: such a mesh is named as it is,
  /// with the warning given without --copy-assets.
  MeshTranscoder* meshes = nullptr;
  /// Keep package:// URIs as written instead of naming the files.
  bool keep_package_uris = false;
  /// MJCF: fuse each body welded to its parent (not the world) into it
  /// (mjcf_layout.h); the other writers keep every body.
  bool fuse_fixed = false;
  /// URDF: plain URDF for urdfdom and ROS (urdf_writer.cc): one root link,
  /// Drake's shapes and joints approximated; the other writers ignore it.
  bool plain = false;
};

/// The model in `options.to`; nullopt after an error was reported (an
/// unsupported target, or a -Wlossy warning promoted by --strict).
std::optional<std::string> Write(const backend::CompiledModel& model, const ir::Module& module,
                                 const WriteOptions& options, DiagnosticEngine& diags);

/// One writer per format (called by Write).
std::optional<std::string> WriteUrdf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags);
std::optional<std::string> WriteMjcf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags);

std::optional<std::string> WriteSdf(const backend::CompiledModel& model,
                                    const ir::Module& module, const WriteOptions& options,
                                    DiagnosticEngine& diags);

}  // namespace mdlc::writers
