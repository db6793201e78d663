// convex_hull.h - the convex hull of a point set, computed by qhull.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// The convex hull of `points` as a closed triangle mesh with outward
/// normals, holding only the hull's vertices. Fails (with qhull's reason in
/// `error`) for fewer than four points or points that span no volume.
std::optional<TriangleMesh> ConvexHull(const std::vector<Eigen::Vector3d>& points,
                                       std::string* error = nullptr);

}  // namespace mdlc::mesh
