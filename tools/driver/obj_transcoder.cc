// obj_transcoder.cc - see obj_transcoder.h.
#include "tools/driver/obj_transcoder.h"

#include "passes/mesh/mesh_export.h"
#include "passes/mesh/point_cloud.h"
#include "passes/mesh/vtk_surface.h"

namespace mdlc {

writers::ObjOrError ObjTranscoder::ObjFor(const std::filesystem::path& file) {
  const mesh::MeshOrError mesh = mesh::IsVtk(file.string()) ? mesh::ReadVtkSurface(file.string())
                                                             : meshes_.Get(file.string());
  if (!mesh.ok()) return {"", mesh.error};
  return {mesh::ObjText(*mesh.mesh), ""};
}

writers::ObjOrError ObjTranscoder::ObjForInline(const ir::InlineMesh& inline_mesh,
                                                const std::string& what) {
  // as load-meshes gives it to the compile (a visual-only inline mesh was
  // never needed there, so it is built here rather than looked up)
  const mesh::MeshOrError mesh = mesh::TrianglesOfInlineMesh(inline_mesh, what);
  if (!mesh.ok()) return {"", mesh.error};
  return {mesh::ObjText(*mesh.mesh), ""};
}

}  // namespace mdlc
