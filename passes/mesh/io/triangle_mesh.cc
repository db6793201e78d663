#include "passes/mesh/io/triangle_mesh.h"

#include <algorithm>
#include <map>
#include <utility>

namespace mdlc::mesh {

TriangleMesh Scaled(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  TriangleMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) out.vertices.push_back(v.cwiseProduct(scale));
  out.triangles = mesh.triangles;
  if (scale.prod() < 0) {
    for (Eigen::Vector3i& t : out.triangles) std::swap(t[1], t[2]);
  }
  return out;
}

MeshTopology AnalyzeTopology(const TriangleMesh& mesh) {
  // count each directed edge; a closed, consistently oriented surface has
  // every directed edge once and its reverse once
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  MeshTopology topo;
  topo.closed = !mesh.triangles.empty();
  topo.consistently_oriented = true;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    const int reverse_count = reverse == directed.end() ? 0 : reverse->second;
    if (count > 1) topo.consistently_oriented = false;
    // undirected edge use: exactly two triangles
    if (count + reverse_count != 2) topo.closed = false;
  }
  return topo;
}

}  // namespace mdlc::mesh
