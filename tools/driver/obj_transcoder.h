// obj_transcoder.h - the writers' MeshTranscoder backed by a compile's own
// mesh reading: `mdlc convert --copy-assets` writes a mesh the target cannot
// read as an OBJ of exactly the triangles the plant was built from (the
// compile's limits, up-axis handling and cache), and a tetrahedral VTK
// volume, which the mesh readers do not take, as its boundary surface.
#pragma once

#include "backend/writers/mesh_transcoder.h"
#include "passes/mesh/mesh_cache.h"

namespace mdlc {

class ObjTranscoder final : public writers::MeshTranscoder {
 public:
  explicit ObjTranscoder(mesh::MeshCache& meshes) : meshes_(meshes) {}
  writers::ObjOrError ObjFor(const std::filesystem::path& file) override;
  writers::ObjOrError ObjForInline(const ir::InlineMesh& mesh, const std::string& what) override;

 private:
  mesh::MeshCache& meshes_;
};

}  // namespace mdlc
