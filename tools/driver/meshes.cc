// meshes.cc - mdlc/meshes.h: mesh files read through the compile's mesh cache.
#include "mdlc/meshes.h"

#include "tools/driver/result_access.h"

namespace mdlc {

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

std::vector<MeshSize> MeshSizes(const Result& result,
                                const std::vector<std::string>& resolved_paths) {
  // the counts are among a mesh's facts: a warm cache answers without
  // reading the file
  mesh::MeshCache& meshes = *ResultAccess::compilation(result).meshes;
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

std::vector<MeshTriangles> ReadMeshes(const Result& result,
                                      const std::vector<std::string>& resolved_paths,
                                      std::string* axes_note) {
  mesh::OffAxisColladaFiles off_axis;
  std::vector<MeshTriangles> meshes = ReadEach<MeshTriangles>(
      *ResultAccess::compilation(result).meshes, resolved_paths,
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

}  // namespace mdlc
