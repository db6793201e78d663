// shape_mass.h - mass properties of primitive shapes per unit density,
// shared by inertia-from-collisions (SDFormat) and mass-from-geometry
// (MJCF).
#pragma once

#include <Eigen/Core>
#include <optional>

#include "ir/entities.h"
#include "ir/transform.h"

namespace mdlc::passes {

/// Volume (or surface area) and inertia about the shape's center in its own
/// frame, per unit density.
struct UnitMass {
  double measure = 0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// The solid shape, closed forms (they are also MuJoCo's). nullopt for
/// half spaces and meshes.
std::optional<UnitMass> SolidOf(const ir::Shape& shape);

/// The hollow shape with its mass on the surface, as MuJoCo 3.3.8 computes
/// geom@shellinertia: exact for boxes, spheres, cylinders and capsules; for
/// ellipsoids, Thomsen's approximation of the area and the inertia of a
/// 1e-6 thick layer. nullopt for half spaces and meshes.
std::optional<UnitMass> MujocoShellOf(const ir::Shape& shape);

/// Sums the mass properties of parts of a body, each given by its mass, its
/// frame G in the body frame B, its center of mass in G and its inertia
/// about that center in G's axes.
class MassSum {
 public:
  void Add(double mass, const Transform& X_BG, const Eigen::Vector3d& p_GGcm,
           const Eigen::Matrix3d& I_Gcm_G);
  int parts() const { return parts_; }
  double mass() const { return mass_; }
  /// Center of mass in B (mass > 0).
  Eigen::Vector3d com() const { return first_moment_ / mass_; }
  /// Inertia about the center of mass, in B's axes (mass > 0).
  Eigen::Matrix3d inertia_about_com() const;
  /// As an Inertial: X_BI translated to the center of mass, not rotated.
  ir::Inertial ToInertial(Loc loc) const;

 private:
  int parts_ = 0;
  double mass_ = 0;
  Eigen::Vector3d first_moment_ = Eigen::Vector3d::Zero();  // sum of m * p_BGcm
  Eigen::Matrix3d inertia_Bo_ = Eigen::Matrix3d::Zero();     // about Bo, in B
};

/// The inertia matrix (about the center of mass, in I's axes) an Inertial holds.
Eigen::Matrix3d InertiaMatrix(const ir::Inertial& inertial);
/// Sets an Inertial's six inertia entries from a symmetric matrix.
void SetInertiaMatrix(ir::Inertial& inertial, const Eigen::Matrix3d& I);

}  // namespace mdlc::passes
