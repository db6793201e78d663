// mass_properties.h - volume, center of mass and inertia of triangle meshes.
//
// All results are per unit density (kg/m^3 for solids, kg/m^2 for shells):
// multiply `inertia` by the density, or by mass / measure.
//
// Two families:
// - SolidMassProperties / ShellMassProperties: exact, for a closed,
//   outward-oriented mesh (solid) or any mesh (shell). What SDFormat's
//   inertia-from-collisions uses (BEYOND-001).
// - MujocoMeshMassProperties: what MuJoCo 3.3.8 computes for
//   <mesh inertia="convex|exact|legacy|shell">, with its checks and errors,
//   its principal frame, its equivalent-inertia box and the bounding box in
//   that frame (MJCF-031, BEYOND-002). MuJoCo facts this follows:
//   * the default mesh@inertia is "legacy" (mjs_defaultMesh);
//   * convex: the solid convex hull of all vertices (qhull);
//   * exact: the solid the surface encloses, by the divergence theorem;
//     faces whose orientation disagrees (a directed edge used twice) are an
//     error; an open surface is NOT detected and gives whatever the signed
//     sum gives;
//   * legacy: like exact, but each face's pyramid volume is taken positive:
//     pyramids from the faces' area-weighted centroid for the volume and
//     center of mass, then from the center of mass for the inertia (and the
//     volume MuJoCo finally keeps). Right for convex meshes, too large for
//     non-convex ones; never fails on orientation;
//   * shell: mass on the surface (area-weighted);
//   * a surface area or volume below 1e-15 is an error (a negative volume:
//     misoriented faces); principal moments must be positive and satisfy the
//     triangle inequality (relative tolerance 1e-6, absolute 1e-9);
//   * MuJoCo reads vertices in single precision; mdlc keeps doubles, so
//     meshes whose coordinates are not floats differ in the last digits.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "ir/entities.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

struct MassProperties {
  double measure = 0;  // volume (solid) or surface area (shell)
  Eigen::Vector3d com = Eigen::Vector3d::Zero();          // in the mesh frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();      // about com, mesh axes, per unit density
};

/// The solid the mesh encloses (divergence theorem). The volume is signed:
/// negative for an inward-oriented mesh; meaningless for an open one.
MassProperties SolidMassProperties(const TriangleMesh& mesh);
/// A thin shell of unit area density on the mesh's surface.
MassProperties ShellMassProperties(const TriangleMesh& mesh);

/// MuJoCo's view of a mesh asset.
struct MujocoMeshProperties {
  MassProperties mass;  // measure: volume, or surface area for Shell
  /// Principal frame P (origin at the center of mass): columns are the
  /// principal axes in the mesh frame, moments in decreasing order, det +1.
  Eigen::Matrix3d R_MP = Eigen::Matrix3d::Identity();
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  // per unit density, decreasing
  /// Half sizes of the box with the same measure and principal moments.
  Eigen::Vector3d inertia_box = Eigen::Vector3d::Zero();
  /// Bounding box of all vertices in P.
  Eigen::Vector3d aabb_min = Eigen::Vector3d::Zero(), aabb_max = Eigen::Vector3d::Zero();
};

/// `mesh` (already scaled) as MuJoCo 3.3.8 processes it with mesh@inertia =
/// `mode`; nullopt with MuJoCo's reason in `error` where MuJoCo refuses.
std::optional<MujocoMeshProperties> MujocoMeshMassProperties(const TriangleMesh& mesh,
                                                             ir::MeshInertia mode,
                                                             std::string* error);

/// Principal moments (decreasing) and axes (columns, right-handed) of a
/// symmetric inertia matrix.
void PrincipalAxes(const Eigen::Matrix3d& inertia, Eigen::Vector3d* moments,
                   Eigen::Matrix3d* axes);

/// True when the 3x3 symmetric `A` is positive definite by a margin that
/// round-off cannot fake: its leading principal minors exceed 1e-10 times the
/// matching power of `scale` (Sylvester's criterion), far above the error of
/// computing them (a few machine epsilons times scale^k). Then every
/// eigenvalue an eigen-decomposition of A finds is positive too, so callers
/// that only act on a non-positive one can skip the decomposition.
bool ClearlyPositiveDefinite(const Eigen::Matrix3d& A, double scale);

}  // namespace mdlc::mesh
