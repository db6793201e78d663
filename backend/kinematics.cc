// kinematics.cc - X_FM(q), H_FM(q) per joint type, and forward kinematics.
#include "backend/kinematics.h"

#include <Eigen/Geometry>
#include <numbers>
#include <stdexcept>

namespace mdlc::backend {

using ir::JointType;

namespace {

Eigen::Matrix3d Rx(double angle) { return RotationAboutAxis(Eigen::Vector3d::UnitX(), angle); }
Eigen::Matrix3d Ry(double angle) { return RotationAboutAxis(Eigen::Vector3d::UnitY(), angle); }
Eigen::Matrix3d Rz(double angle) { return RotationAboutAxis(Eigen::Vector3d::UnitZ(), angle); }

/// Screw joints advance `pitch` meters per revolution.
double ScrewLead(const PlantJoint& joint) {
  return joint.screw_thread_pitch / (2 * std::numbers::pi);
}

Eigen::Matrix3d QuaternionRotation(double w, double x, double y, double z) {
  Eigen::Quaterniond quat(w, x, y, z);
  if (quat.squaredNorm() == 0) return Eigen::Matrix3d::Identity();
  return quat.normalized().toRotationMatrix();
}

void RequireFullQ(const Plant& plant, const Eigen::VectorXd& q) {
  if (q.size() != plant.num_positions) {
    throw std::invalid_argument("q has " + std::to_string(q.size()) +
                                " entries; the plant has " +
                                std::to_string(plant.num_positions) + " positions");
  }
}

}  // namespace

Transform JointPose(const PlantJoint& joint, const Eigen::Ref<const Eigen::VectorXd>& q) {
  switch (joint.type) {
    case JointType::Revolute:
      return Transform::FromRotation(RotationAboutAxis(joint.axis, q[0]));
    case JointType::Prismatic:
      return Transform::FromTranslation(joint.axis * q[0]);
    case JointType::Screw:
      return {RotationAboutAxis(joint.axis, q[0]), joint.axis * (q[0] * ScrewLead(joint))};
    case JointType::Universal:
      return Transform::FromRotation(Rx(q[0]) * Ry(q[1]));
    case JointType::Ball:
      return Transform::FromRotation(RotationFromRpy(q.head<3>()));
    case JointType::Planar:
      return {Rz(q[2]), Eigen::Vector3d(q[0], q[1], 0)};
    case JointType::Curvilinear:
      return joint.curvilinear_path.PoseAt(q[0]);
    case JointType::Weld:
      return Transform::Identity();
    case JointType::QuaternionFloating:
      return {QuaternionRotation(q[0], q[1], q[2], q[3]), q.segment<3>(4)};
    case JointType::RpyFloating:
      return {RotationFromRpy(q.head<3>()), q.segment<3>(3)};
  }
  return Transform::Identity();
}

MotionSubspace JointMotionSubspace(const PlantJoint& joint,
                                   const Eigen::Ref<const Eigen::VectorXd>& q) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d ex = Eigen::Vector3d::UnitX(), ey = Eigen::Vector3d::UnitY(),
                        ez = Eigen::Vector3d::UnitZ();
  MotionSubspace H = MotionSubspace::Zero(6, joint.nv);
  switch (joint.type) {
    case JointType::Revolute:
      H.col(0) << joint.axis, zero;
      break;
    case JointType::Prismatic:
      H.col(0) << zero, joint.axis;
      break;
    case JointType::Screw:
      H.col(0) << joint.axis, joint.axis * ScrewLead(joint);
      break;
    case JointType::Universal:
      // w_FM = qdot0 x_F + qdot1 (Rx(q0) y)
      H.col(0) << ex, zero;
      H.col(1) << Rx(q[0]) * ey, zero;
      break;
    case JointType::Ball:
      H.topRows<3>().setIdentity();
      break;
    case JointType::Planar:
      H.col(0) << zero, ex;
      H.col(1) << zero, ey;
      H.col(2) << ez, zero;
      break;
    case JointType::Curvilinear:
      H.col(0) = joint.curvilinear_path.VelocityAt(q[0]);
      break;
    case JointType::Weld:
      break;
    case JointType::QuaternionFloating:
    case JointType::RpyFloating:
      H.setIdentity();
      break;
  }
  return H;
}

std::vector<Transform> BodyPosesInWorld(const Plant& plant, const Eigen::VectorXd& q) {
  RequireFullQ(plant, q);
  std::vector<Transform> X_WB(plant.bodies.size());
  // parents come before children in joint_order, so one sweep suffices
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    const Transform X_FM = JointPose(joint, q.segment(joint.q_start, joint.nq));
    X_WB[joint.child.index()] =
        X_WB[joint.parent.index()] * joint.X_PF * X_FM * joint.X_CM.inverse();
  }
  return X_WB;
}

Transform JointFrameInWorld(const Plant& plant, const std::vector<Transform>& X_WB,
                            JointId id) {
  const PlantJoint& joint = plant.joint(id);
  return X_WB[joint.parent.index()] * joint.X_PF;
}

}  // namespace mdlc::backend
