// asset_paths.h - how a written model names the files it uses (meshes,
// textures): by default a path relative to the output file's folder, so the
// written model loads from wherever it is written; with --copy-assets, copies
// of the files (one per distinct content) in a folder of the user's; with
// --keep-package-uris, package:// URIs as the source wrote them.
//
// A mesh file the target cannot read (MuJoCo reads STL, OBJ and MSH only)
// is, with --copy-assets, written as an OBJ of the triangles mdlc read from
// it (WriteOptions::meshes, mesh_transcoder.h), so the target loads the
// shape the plant has; without --copy-assets it is named as it is, with a -Wlossy warning
// per file saying the target cannot read it. A mesh mdlc cannot read either
// (an empty file) is left to the writer, which drops its geometry.
//
// An MJCF mesh written in the model file (vertex and face lists) has no file
// to name: the MJCF writer writes it back in the file; for the other targets
// --copy-assets writes an OBJ of it (NameInlineMesh), and without it the
// writer leaves its geometry out with a -Wlossy warning.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "backend/writers/writer.h"
#include "ir/diagnostics.h"

namespace mdlc::writers {

/// Which mesh files a target reads.
struct MeshTarget {
  const char* reader;  // "MuJoCo"
  /// Empty when the reader reads `file`, else why not ("MuJoCo reads ...").
  std::string (*why_not)(const std::filesystem::path& file);
};

class AssetPaths {
 public:
  AssetPaths(const WriteOptions& options, DiagnosticEngine& diags);

  /// The text to write for a file that the source named `uri` and that
  /// resolved to `resolved` (empty when it did not resolve). nullopt after
  /// reporting a file that could not be copied.
  std::optional<std::string> Name(const std::string& uri, const std::string& resolved, Loc loc);
  /// As Name(), for a mesh file that `target` may not read: with
  /// --copy-assets, one it cannot read is named by an OBJ copy; without, it
  /// is reported once.
  std::optional<std::string> NameMesh(const std::string& uri, const std::string& resolved,
                                      Loc loc, const MeshTarget& target);
  /// Why NameMesh could not write the mesh `resolved` in a format the
  /// target reads (mdlc cannot read it either); nullopt when it could, or
  /// was not asked to. The writer drops the geometry: the target would
  /// refuse the whole model.
  std::optional<std::string> UnconvertibleMesh(const std::string& resolved) const;
  /// An MJCF inline mesh (`mesh.inline_data`: no file, `resolved` is only
  /// the compile's key for it): with --copy-assets, the OBJ copy of its
  /// triangles (a point cloud's convex hull), named as the other copies
  /// are. nullopt without --copy-assets (`*why` empty), or when the OBJ
  /// cannot be built or written (`*why` says why). Each mesh once.
  std::optional<std::string> NameInlineMesh(const ir::Mesh& mesh, Loc loc, std::string* why);
  /// The -Wlossy warning for geometry `geometry` at `loc`, left out because
  /// its inline mesh has no file `target` ("URDF") can name: NameInlineMesh's
  /// `why`, or, without one, that --copy-assets writes an OBJ of it. Once
  /// per geometry (a visual and a collision of one source geom are one).
  void ReportInlineMeshLeftOut(const std::string& geometry, const ir::Mesh& mesh,
                               std::string_view target, const std::string& why, Loc loc);

 private:
  std::optional<std::filesystem::path> Copy(const std::filesystem::path& file, Loc loc);
  /// The OBJ copy of the mesh `file`; nullopt when mdlc cannot read it
  /// (UnconvertibleMesh says why) or the copy cannot be written (reported).
  std::optional<std::filesystem::path> ObjCopy(const std::filesystem::path& file, Loc loc);
  /// `bytes` in the copy folder as STEM-HASH.EXT (one file per content).
  std::optional<std::filesystem::path> WriteCopy(const std::string& bytes,
                                                 const std::filesystem::path& named_after,
                                                 const std::string& extension, Loc loc);
  std::string Relative(const std::filesystem::path& file) const;

  const WriteOptions& options_;
  DiagnosticEngine& diags_;
  std::filesystem::path output_dir_;
  std::map<std::filesystem::path, std::filesystem::path> copies_;    // original -> copy
  std::map<std::string, std::filesystem::path> copies_by_content_;  // content -> copy
  std::map<std::filesystem::path, std::filesystem::path> obj_copies_;  // original -> OBJ
  std::map<std::filesystem::path, std::string> unconvertible_;        // original -> why
  std::map<std::filesystem::path, std::string> target_verdicts_;      // original -> why_not
  std::set<std::filesystem::path> unreadable_reported_;
  struct InlineCopy {
    std::optional<std::string> name;
    std::string why;
  };
  std::map<std::string, InlineCopy> inline_copies_;  // Mesh::resolved -> its OBJ copy
  std::set<std::tuple<uint32_t, uint32_t, uint32_t, std::string>> inline_left_out_;  // loc, name
};

}  // namespace mdlc::writers
