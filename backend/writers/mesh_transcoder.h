// mesh_transcoder.h - where a writer gets a mesh file as OBJ text, for a
// target that cannot read the file as it is, or a mesh the model file holds
// itself (MJCF vertex and face lists) for a target that names mesh files
// only (`mdlc convert --copy-assets`, asset_paths.h).
//
// Writers read no mesh file themselves: reading meshes belongs to the passes
// (passes/mesh), with the compile's limits, up-axis handling and cache. The
// driver hands the writer an implementation backed by the compile's own
// mesh reading (tools/driver/obj_transcoder.h), so the OBJ holds the very
// triangles the plant was built from.
#pragma once

#include <filesystem>
#include <string>

#include "ir/entities.h"

namespace mdlc::writers {

/// OBJ text, or why there is none.
struct ObjOrError {
  std::string obj;
  std::string error;  // empty on success
  bool ok() const { return error.empty(); }
};

class MeshTranscoder {
 public:
  virtual ~MeshTranscoder() = default;
  /// `file` as Wavefront OBJ text of the triangles mdlc reads from it, or
  /// why mdlc cannot read it.
  virtual ObjOrError ObjFor(const std::filesystem::path& file) = 0;
  /// An MJCF inline mesh (ir::Mesh::inline_data) as OBJ text of the
  /// triangles the compile takes from it: its faces, or the convex hull of
  /// its points when it has none. `what` names it in the error.
  virtual ObjOrError ObjForInline(const ir::InlineMesh& mesh, const std::string& what) = 0;
};

}  // namespace mdlc::writers
