// cached_properties.h - the mesh computations worth keeping between compiles
// (mass properties, convex hulls; issue 16), through the mesh cache's
// DerivedMeshCache when it has one: a hit skips the computation and the
// reading of the mesh (issue 57), a miss reads, computes and stores.
// Results are the same bits either way (doubles are stored exactly).
//
// Each takes a file whose MeshCache::Status() is ok (load-meshes made sure).
#pragma once

#include <optional>
#include <string>

#include "passes/mesh/mesh_cache.h"
#include "passes/mesh/mass_properties.h"

namespace mdlc::mesh {

/// MujocoMeshMassProperties of the mesh at `path` scaled by `scale`.
std::optional<MujocoMeshProperties> CachedMujocoMeshMassProperties(
    MeshCache& meshes, const std::string& path, const Eigen::Vector3d& scale,
    ir::MeshInertia mode, std::string* error);

/// The solid mass properties of a collision mesh (SDFormat's
/// <inertial auto="true">): of the scaled mesh itself when it is closed and
/// outward-oriented and not declared convex, else of its convex hull.
struct CollisionSolid {
  std::optional<MassProperties> mass;  // unset: no volume (`error` says why)
  bool used_hull = false;
  std::string error;
};
CollisionSolid CachedCollisionSolid(MeshCache& meshes, const std::string& path,
                                    const Eigen::Vector3d& scale, bool convex);

}  // namespace mdlc::mesh
