// mesh_transcoder.h - where a writer gets a mesh file as OBJ text, for a
// target that cannot read the file as it is (`mdlc convert --copy-assets`,
// asset_paths.h).
//
// Writers read no mesh file themselves: reading meshes belongs to the passes
// (passes/mesh), with the compile's limits, up-axis handling and cache. The
// driver hands the writer an implementation backed by the compile's own
// mesh reading (tools/driver/obj_transcoder.h), so the OBJ holds the very
// triangles the plant was built from.
#pragma once

#include <filesystem>
#include <string>

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
};

}  // namespace mdlc::writers
