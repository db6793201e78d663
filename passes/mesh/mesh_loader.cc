#include "passes/mesh/mesh_loader.h"

#include <fmt/format.h>

#include "passes/mesh/point_cloud.h"
#include "passes/mesh/reader_pool.h"
#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/reader_location.h"

namespace mdlc::mesh {

MeshOrError LoadMesh(const std::string& path, const Limits& limits, const MeshAxes& axes) {
  const MeshReaderLocation reader = FindMeshReader();
  return HullOfPointCloud(reader.path.empty() ? LoadMeshInProcess(path, limits, axes)
                                              : LoadMeshInChild(reader.path, path, limits, axes),
                          fmt::format("mesh file '{}'", path));
}

}  // namespace mdlc::mesh
