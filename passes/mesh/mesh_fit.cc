#include "passes/mesh/mesh_fit.h"

#include <algorithm>

namespace mdlc::mesh {

std::optional<FittedPrimitive> FitPrimitive(const MujocoMeshProperties& mesh,
                                            const ir::Shape& type, bool aabb, double fitscale,
                                            std::string* error) {
  // MuJoCo's half sizes: radius / half length / half extents
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  Eigen::Vector3d center_P = Eigen::Vector3d::Zero();
  const bool sphere = std::holds_alternative<ir::Sphere>(type);
  const bool capsule = std::holds_alternative<ir::Capsule>(type);
  const bool cylinder = std::holds_alternative<ir::Cylinder>(type);
  const bool box_like =
      std::holds_alternative<ir::Box>(type) || std::holds_alternative<ir::Ellipsoid>(type);
  if (!sphere && !capsule && !cylinder && !box_like) {
    if (error) *error = "only a box, sphere, capsule, cylinder or ellipsoid can be fitted to a mesh";
    return std::nullopt;
  }
  if (!aabb) {
    const Eigen::Vector3d& b = mesh.inertia_box;
    if (sphere) {
      half[0] = b.sum() / 3;
    } else if (capsule) {
      half[0] = (b[0] + b[1]) / 2;
      half[1] = std::max(0.0, b[2] - half[0] / 2);
    } else if (cylinder) {
      half[0] = (b[0] + b[1]) / 2;
      half[1] = b[2];
    } else {
      half = b;
    }
  } else {
    center_P = (mesh.aabb_min + mesh.aabb_max) / 2;
    const Eigen::Vector3d h = mesh.aabb_max - center_P;
    if (sphere) {
      half[0] = h.maxCoeff();
    } else if (capsule || cylinder) {
      half[0] = std::max(h[0], h[1]);
      half[1] = h[2] - (capsule ? half[0] : 0);
    } else {
      half = h;
    }
  }
  half *= fitscale;

  FittedPrimitive out;
  bool positive = half[0] > 0;
  if (sphere) {
    out.shape = ir::Sphere{half[0]};
  } else if (capsule) {
    // MuJoCo requires every size positive: a capsule whose caps alone span
    // the mesh (no cylinder part) is refused
    positive = positive && half[1] > 0;
    out.shape = ir::Capsule{half[0], 2 * half[1]};
  } else if (cylinder) {
    positive = positive && half[1] > 0;
    out.shape = ir::Cylinder{half[0], 2 * half[1]};
  } else if (std::holds_alternative<ir::Box>(type)) {
    positive = (half.array() > 0).all();
    out.shape = ir::Box{2 * half};
  } else {
    positive = (half.array() > 0).all();
    out.shape = ir::Ellipsoid{half[0], half[1], half[2]};
  }
  if (!positive) {
    if (error) *error = "the fitted primitive has no positive size";
    return std::nullopt;
  }
  out.X_MG = Transform{mesh.R_MP, mesh.mass.com + mesh.R_MP * center_P};
  return out;
}

}  // namespace mdlc::mesh
