// cached_properties.h - the mesh computations worth keeping between compiles
// (mass properties, convex hulls; issue 16), through a DerivedMeshCache when
// one is given: a hit skips the computation, a miss computes and stores.
// Results are the same bits either way (doubles are stored exactly).
#pragma once

#include <optional>
#include <string>

#include "passes/mesh/derived_cache.h"
#include "passes/mesh/mass_properties.h"

namespace mdlc::mesh {

/// MujocoMeshMassProperties of `mesh` (read from `path`) scaled by `scale`.
std::optional<MujocoMeshProperties> CachedMujocoMeshMassProperties(
    DerivedMeshCache* cache, const std::string& path, const TriangleMesh& mesh,
    const Eigen::Vector3d& scale, ir::MeshInertia mode, std::string* error);

/// The solid mass properties of a collision mesh (SDFormat's
/// <inertial auto="true">): of the scaled mesh itself when it is closed and
/// outward-oriented and not declared convex, else of its convex hull.
struct CollisionSolid {
  std::optional<MassProperties> mass;  // unset: no volume (`error` says why)
  bool used_hull = false;
  std::string error;
};
CollisionSolid CachedCollisionSolid(DerivedMeshCache* cache, const std::string& path,
                                    const TriangleMesh& mesh, const Eigen::Vector3d& scale,
                                    bool convex);

}  // namespace mdlc::mesh
