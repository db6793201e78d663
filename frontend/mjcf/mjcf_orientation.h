// mjcf_orientation.h - MuJoCo's orientation forms as rotation matrices
// (MJCF-010, MJCF-003). Pure functions, no diagnostics: each returns the
// rotation or the reason MuJoCo rejects the value, and callers report it.
//
// Every form follows MuJoCo's compiler (engine_util_misc / user_objects):
// angles are in radians here (callers convert from the compiler's unit).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <variant>

namespace mdlc::frontend::mjcf {

/// A rotation, or why the value does not define one.
using RotationOrError = std::variant<Eigen::Matrix3d, std::string>;

/// quat="w x y z", normalised. A zero quaternion is an error.
RotationOrError RotationFromQuat(double w, double x, double y, double z);
/// axisangle: rotation by `angle` (radians) about `axis` (normalised; a
/// near-zero axis is an error).
RotationOrError RotationFromAxisAngle(const Eigen::Vector3d& axis, double angle);
/// euler with compiler@eulerseq: three rotations about the axes the
/// sequence names; lowercase = axes that move with the frame (intrinsic,
/// post-multiplied), uppercase = fixed axes (extrinsic, pre-multiplied).
RotationOrError RotationFromEuler(const Eigen::Vector3d& angles, std::string_view sequence);
/// xyaxes: x normalised, y made orthogonal to x (Gram-Schmidt), z = x cross y.
RotationOrError RotationFromXYAxes(const Eigen::Vector3d& x, const Eigen::Vector3d& y);
/// zaxis: the minimal rotation taking +z to `z` (a half turn about +x when
/// `z` points along -z, as MuJoCo picks it).
RotationOrError RotationFromZAxis(const Eigen::Vector3d& z);

/// True if `sequence` is exactly three of x, y, z, X, Y, Z.
bool IsValidEulerSequence(std::string_view sequence);

}  // namespace mdlc::frontend::mjcf
