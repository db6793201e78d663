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

std::optional<uint32_t> BinaryStlTriangleCount(std::string_view head, uint64_t file_size) {
  // 80 bytes of header, a little-endian count, 50 bytes per triangle; an
  // ASCII file ("solid ...") does not match that size
  if (head.size() < 84) return std::nullopt;
  uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = count << 8 | static_cast<unsigned char>(head[80 + k]);
  if (file_size != 84 + uint64_t{count} * 50) return std::nullopt;
  return count;
}

}  // namespace mdlc::mesh
