// point_cloud.cc - see point_cloud.h.
#include "passes/mesh/point_cloud.h"

#include <fmt/format.h>

#include "passes/mesh/convex_hull.h"

namespace mdlc::mesh {
namespace {

/// qhull's first line: the rest of its report is a manual for the option
/// that would have let it go on.
std::string FirstLine(const std::string& text) {
  const size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

}  // namespace

MeshOrError HullOfPointCloud(MeshOrError m, std::string_view what) {
  // no points at all: nothing to take the hull of (a reader reports an
  // empty file itself)
  if (!m.ok() || !m.mesh->triangles.empty() || m.mesh->vertices.empty()) return m;
  const TriangleMesh& points = *m.mesh;
  if (points.vertices.size() < 4) {
    return {nullptr,
            fmt::format("{} holds {} point{} and no triangles; the convex hull MuJoCo takes of a "
                        "mesh without faces needs at least 4",
                        what, points.vertices.size(), points.vertices.size() == 1 ? "" : "s")};
  }
  std::string why;
  std::optional<TriangleMesh> hull = ConvexHull(points.vertices, &why);
  if (!hull) {
    return {nullptr, fmt::format("{} holds points and no triangles, and its {} points have no "
                                 "convex hull (they span no volume): {}",
                                 what, points.vertices.size(), FirstLine(why))};
  }
  hull->declared_up = points.declared_up;
  hull->turned_to_z_up = points.turned_to_z_up;
  return {std::make_shared<const TriangleMesh>(std::move(*hull)), {}};
}

MeshOrError TrianglesOfInlineMesh(const ir::InlineMesh& m, std::string_view what) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = m.vertices;
  mesh->triangles = m.faces;
  return HullOfPointCloud({std::move(mesh), {}}, what);
}

}  // namespace mdlc::mesh
