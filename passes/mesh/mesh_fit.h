// mesh_fit.h - a primitive sized and placed to stand in for a mesh, as
// MuJoCo 3.3.8 fits a geom of a primitive type that names a mesh
// (BEYOND-002).
//
// MuJoCo fits in the mesh's principal frame P (origin at the center of mass,
// axes the principal axes with decreasing moments, so P's z axis is the
// axis of least inertia: a capsule or cylinder lies along it):
// * by default, to the equivalent-inertia box (half sizes b): sphere radius
//   = mean(b); capsule radius = (bx + by)/2 and half length = max(0, bz -
//   radius/2); cylinder radius = (bx + by)/2 and half length = bz; box and
//   ellipsoid half sizes = b; centered at P's origin;
// * with compiler@fitaabb, to the bounding box of the vertices in P (half
//   sizes h, center c): sphere radius = max(h); capsule and cylinder radius
//   = max(hx, hy), half length = hz (capsule: minus the radius); box and
//   ellipsoid = h; centered at c;
// * then every size is multiplied by geom@fitscale.
// The measure behind the inertia box follows mesh@inertia (a shell's area).
#pragma once

#include <optional>
#include <string>

#include "ir/entities.h"
#include "ir/transform.h"
#include "passes/mesh/mass_properties.h"

namespace mdlc::mesh {

struct FittedPrimitive {
  ir::Shape shape;  // same alternative as asked for, sized (Drake's full lengths)
  Transform X_MG;   // the primitive's pose in the mesh file's frame
};

/// Fits a primitive of the type held by `type` (Box, Sphere, Capsule,
/// Cylinder or Ellipsoid; sizes ignored) to the mesh. nullopt, with a
/// reason, for other types or a fit with no positive size.
std::optional<FittedPrimitive> FitPrimitive(const MujocoMeshProperties& mesh,
                                            const ir::Shape& type, bool aabb, double fitscale,
                                            std::string* error);

}  // namespace mdlc::mesh
