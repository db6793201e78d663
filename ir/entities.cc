#include "ir/entities.h"

namespace mdlc::ir {

JointLimits JointLimits::Unbounded(int nv) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto n = static_cast<size_t>(nv);
  JointLimits l;
  l.lower.assign(n, -kInf);
  l.upper.assign(n, kInf);
  l.velocity_lower.assign(n, -kInf);
  l.velocity_upper.assign(n, kInf);
  l.acceleration_lower.assign(n, -kInf);
  l.acceleration_upper.assign(n, kInf);
  l.effort.assign(n, kInf);
  return l;
}

std::string_view JointTypeName(JointType type) {
  switch (type) {
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
    case JointType::Ball: return "ball";
    case JointType::Universal: return "universal";
    case JointType::Planar: return "planar";
    case JointType::Screw: return "screw";
    case JointType::Curvilinear: return "curvilinear";
    case JointType::Weld: return "weld";
    case JointType::QuaternionFloating: return "quaternion_floating";
    case JointType::RpyFloating: return "rpy_floating";
  }
  return "weld";
}

int JointPositionCount(JointType type) {
  switch (type) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Screw:
    case JointType::Curvilinear: return 1;
    case JointType::Universal: return 2;
    case JointType::Ball: return 3;  // roll-pitch-yaw, as Drake's BallRpyJoint
    case JointType::Planar: return 3;
    case JointType::Weld: return 0;
    case JointType::QuaternionFloating: return 7;
    case JointType::RpyFloating: return 6;
  }
  return 0;
}

int JointVelocityCount(JointType type) {
  switch (type) {
    case JointType::QuaternionFloating: return 6;
    default: return JointPositionCount(type);
  }
}

std::string_view ShapeTypeName(const Shape& shape) {
  struct Visitor {
    std::string_view operator()(const Box&) const { return "box"; }
    std::string_view operator()(const Sphere&) const { return "sphere"; }
    std::string_view operator()(const Cylinder&) const { return "cylinder"; }
    std::string_view operator()(const Capsule&) const { return "capsule"; }
    std::string_view operator()(const Ellipsoid&) const { return "ellipsoid"; }
    std::string_view operator()(const HalfSpace&) const { return "half_space"; }
    std::string_view operator()(const Mesh& m) const { return m.convex ? "convex" : "mesh"; }
  };
  return std::visit(Visitor{}, shape);
}

std::string_view ConstraintTypeName(ConstraintType type) {
  switch (type) {
    case ConstraintType::Coupler: return "coupler";
    case ConstraintType::Ball: return "ball";
    case ConstraintType::Distance: return "distance";
    case ConstraintType::Weld: return "weld";
    case ConstraintType::Tendon: return "tendon";
  }
  return "coupler";
}

NameScopeList NameScopes(const Geometry& geometry) {
  NameScopeList scopes;
  for (uint8_t role : {kProximityRole, kIllustrationRole, kPerceptionRole}) {
    if (geometry.roles & role) {
      scopes.items[scopes.count++] = uint64_t{geometry.body.id.value} << 8 | role;
    }
  }
  return scopes;
}

}  // namespace mdlc::ir
