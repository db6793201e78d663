#include "passes/mesh/convex_hull.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <cstdio>
#include <unordered_map>

namespace mdlc::mesh {
namespace {

/// Reads everything qhull wrote to `f` (its error report).
std::string Drain(FILE* f) {
  std::string text;
  if (!f) return text;
  std::rewind(f);
  char buf[256];
  while (size_t n = std::fread(buf, 1, sizeof buf, f)) text.append(buf, n);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

}  // namespace

std::optional<TriangleMesh> ConvexHull(const std::vector<Eigen::Vector3d>& points,
                                       std::string* error) {
  auto fail = [&](std::string why) -> std::optional<TriangleMesh> {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  if (points.size() < 4) return fail("a convex hull needs at least 4 points");
  std::vector<coordT> coords;
  coords.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});

  // qhull reports errors on a stream; keep them for the message instead of
  // letting them reach stderr
  FILE* errors = std::tmpfile();
  qhT qh_storage;
  qhT* qh = &qh_storage;
  QHULL_LIB_CHECK
  qh_zero(qh, errors);
  // "Qt": triangulated output, so every facet is a triangle
  char options[] = "qhull Qt";
  const int exitcode = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(),
                                    False, options, nullptr, errors);
  std::optional<TriangleMesh> hull;
  if (exitcode == 0) {
    hull.emplace();
    std::unordered_map<int, int> index;  // point id -> hull vertex
    auto vertex_of = [&](vertexT* v) {
      const int id = qh_pointid(qh, v->point);
      auto [it, inserted] = index.emplace(id, static_cast<int>(hull->vertices.size()));
      if (inserted) hull->vertices.push_back(points[id]);
      return it->second;
    };
    facetT* facet;
    FORALLfacets {
      if (facet->upperdelaunay || qh_setsize(qh, facet->vertices) != 3) continue;
      Eigen::Vector3i t;
      for (int k = 0; k < 3; ++k) t[k] = vertex_of(static_cast<vertexT*>(facet->vertices->e[k].p));
      // qhull's vertex order is not a winding; orient by the facet's outward normal
      const Eigen::Vector3d n(facet->normal[0], facet->normal[1], facet->normal[2]);
      const Eigen::Vector3d& a = hull->vertices[t[0]];
      if ((hull->vertices[t[1]] - a).cross(hull->vertices[t[2]] - a).dot(n) < 0) {
        std::swap(t[1], t[2]);
      }
      hull->triangles.push_back(t);
    }
  }
  int curlong = 0, totlong = 0;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
  if (exitcode != 0) {
    std::string why = Drain(errors);
    if (errors) std::fclose(errors);
    // qhull's first line says what went wrong (e.g. the points are coplanar)
    const size_t eol = why.find('\n');
    return fail(why.empty() ? "qhull failed" : why.substr(0, eol));
  }
  if (errors) std::fclose(errors);
  return hull;
}

}  // namespace mdlc::mesh
