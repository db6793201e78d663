// obj_transcoder.cc - see obj_transcoder.h.
#include "tools/driver/obj_transcoder.h"

#include "passes/mesh/mesh_export.h"
#include "passes/mesh/vtk_surface.h"

namespace mdlc {

writers::ObjOrError ObjTranscoder::ObjFor(const std::filesystem::path& file) {
  const mesh::MeshOrError mesh = mesh::IsVtk(file.string()) ? mesh::ReadVtkSurface(file.string())
                                                             : meshes_.Get(file.string());
  if (!mesh.ok()) return {"", mesh.error};
  return {mesh::ObjText(*mesh.mesh), ""};
}

}  // namespace mdlc
