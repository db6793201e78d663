// mesh_export.cc - see mesh_export.h.
#include "passes/mesh/mesh_export.h"

#include <fmt/format.h>

#include <iterator>

namespace mdlc::mesh {

std::string ObjText(const TriangleMesh& mesh) {
  std::string out = "# written by mdlc: the triangles mdlc read from the source mesh\n";
  out.reserve(out.size() + mesh.vertices.size() * 40 + mesh.triangles.size() * 24);
  for (const Eigen::Vector3d& v : mesh.vertices) {
    // {} is the shortest text that reads back as the same double
    fmt::format_to(std::back_inserter(out), "v {} {} {}\n", v.x(), v.y(), v.z());
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    fmt::format_to(std::back_inserter(out), "f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  }
  return out;
}

}  // namespace mdlc::mesh
