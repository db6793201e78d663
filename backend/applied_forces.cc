// applied_forces.cc - damping, springs, spring-dampers and bushings as
// generalized forces (applied_forces.h).
#include "backend/applied_forces.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "backend/named_frames.h"

namespace mdlc::backend {

using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

/// A bushing's coordinates: roll-pitch-yaw and xyz of frame C in frame A
/// (R_AC, p_AoCo_A), their rates, and J_AC: the spatial velocity of C
/// measured in A and expressed in A, [w_AC_A; v_ACo_A] = J_AC v.
struct BushingState {
  Vector3d rpy, xyz, rpy_rate, xyz_rate;
  Eigen::Matrix3d rpy_rate_from_w;  // rpy_rate = this * w_AC_A
  Eigen::MatrixXd J_AC;
};

BushingState BushingAt(const Plant& plant, const TreeState& s, const VectorXd& v,
                       const LinearBushingRpy& e) {
  const auto frame = [&](const std::string& name) {
    const FrameLookup lookup = FindFrameByName(plant, name);
    if (lookup.status != FrameLookupStatus::Found) {
      throw std::logic_error("a linear_bushing_rpy names frame '" + name + "', which the plant lacks");
    }
    return lookup.frame;
  };
  const BodyFixedFrame A = frame(e.frame_A), C = frame(e.frame_C);
  const Transform X_WA = s.X_WB[A.body.index()] * A.X_BF;
  const Transform X_WC = s.X_WB[C.body.index()] * C.X_BF;
  const Transform X_AC = X_WA.inverse() * X_WC;
  BushingState st;
  st.rpy = RpyFromRotation(X_AC.R);
  st.xyz = X_AC.p;
  st.J_AC = Eigen::MatrixXd::Zero(6, plant.num_velocities);
  AddPointJacobian(plant, s, C.body, X_WC.p, +1, st.J_AC);
  AddPointJacobian(plant, s, A.body, X_WC.p, -1, st.J_AC);
  const Eigen::Matrix3d R_AW = X_WA.R.transpose();
  st.J_AC.topRows<3>() = R_AW * st.J_AC.topRows<3>();
  st.J_AC.bottomRows<3>() = R_AW * st.J_AC.bottomRows<3>();
  // w_AC_A = E rpy_rate for R = Rz(yaw) Ry(pitch) Rx(roll)
  const double cp = std::cos(st.rpy.y()), sp = std::sin(st.rpy.y());
  const double cy = std::cos(st.rpy.z()), sy = std::sin(st.rpy.z());
  if (std::abs(cp) < 1e-10) {
    throw std::domain_error("a linear_bushing_rpy is at pitch +-90 degrees, where its roll and yaw "
                            "rates are undefined");
  }
  Eigen::Matrix3d E;
  E << cy * cp, -sy, 0,
       sy * cp, cy, 0,
       -sp, 0, 1;
  st.rpy_rate_from_w = E.inverse();
  const Vector6d V_AC = st.J_AC * v;
  st.rpy_rate = st.rpy_rate_from_w * V_AC.head<3>();
  st.xyz_rate = V_AC.tail<3>();
  return st;
}

/// Spring-damper geometry: P on body A, Q on body B, in W.
struct SpringDamperState {
  Vector3d p_WP, p_WQ, u_PQ;
  double length = 0, length_rate = 0;
};

SpringDamperState SpringDamperAt(const TreeState& s, const LinearSpringDamper& e) {
  SpringDamperState st;
  st.p_WP = s.X_WB[e.body_A.index()] * e.p_AP;
  st.p_WQ = s.X_WB[e.body_B.index()] * e.p_BQ;
  const Vector3d d = st.p_WQ - st.p_WP;
  st.length = d.norm();
  if (!(st.length > 1e-12)) {
    throw std::domain_error(
        "a linear_spring_damper's end points coincide; its force direction is undefined");
  }
  st.u_PQ = d / st.length;
  st.length_rate = st.u_PQ.dot(PointVelocity(s.V[e.body_B.index()], st.p_WQ) -
                               PointVelocity(s.V[e.body_A.index()], st.p_WP));
  return st;
}

}  // namespace

/// The joint-space part of the applied forces (damping, joint springs) into
/// tau, and the body-space part (spring-dampers) into f_ext.
void CollectAppliedForces(const Plant& plant, const TreeState& s, const VectorXd& q,
                          const VectorXd& v, const DynamicsOptions& options, VectorXd& tau,
                          std::vector<Vector6d>& f_ext) {
  if (options.joint_damping) {
    for (const PlantJoint& joint : plant.joints) {
      for (int k = 0; k < joint.nv && k < static_cast<int>(joint.damping.size()); ++k) {
        tau[joint.v_start + k] -= joint.damping[k] * v[joint.v_start + k];
      }
    }
  }
  if (!options.force_elements) return;
  for (const ForceElement& element : plant.force_elements) {
    if (const auto* spring = std::get_if<JointSpring>(&element)) {
      const PlantJoint& joint = plant.joint(spring->joint);
      tau[joint.v_start] -= spring->stiffness * (q[joint.q_start] - spring->nominal);
    } else if (const auto* e = std::get_if<LinearSpringDamper>(&element)) {
      const SpringDamperState st = SpringDamperAt(s, *e);
      const double tension = e->stiffness * (st.length - e->free_length) + e->damping * st.length_rate;
      // pulls Q towards P and P towards Q when stretched
      const Vector3d F_Q = -tension * st.u_PQ;
      if (f_ext.empty()) f_ext.assign(plant.bodies.size(), Vector6d::Zero());
      f_ext[e->body_B.index()] += Spatial(st.p_WQ.cross(F_Q), F_Q);
      f_ext[e->body_A.index()] += Spatial(st.p_WP.cross(-F_Q), -F_Q);
    } else if (const auto* bushing = std::get_if<LinearBushingRpy>(&element)) {
      // the generalized forces of the bushing's potential 1/2 k.x^2 and
      // dissipation 1/2 b.xdot^2 over its six coordinates
      const BushingState st = BushingAt(plant, s, v, *bushing);
      const Vector3d torque = bushing->torque_stiffness.cwiseProduct(st.rpy) +
                              bushing->torque_damping.cwiseProduct(st.rpy_rate);
      const Vector3d force = bushing->force_stiffness.cwiseProduct(st.xyz) +
                             bushing->force_damping.cwiseProduct(st.xyz_rate);
      tau -= st.J_AC.topRows<3>().transpose() * (st.rpy_rate_from_w.transpose() * torque) +
             st.J_AC.bottomRows<3>().transpose() * force;
    }
  }
}

VectorXd AppliedForcesAt(const Plant& plant, const TreeState& s, const VectorXd& q,
                         const VectorXd& v, const DynamicsOptions& options) {
  VectorXd tau = VectorXd::Zero(plant.num_velocities);
  std::vector<Vector6d> f_ext;
  CollectAppliedForces(plant, s, q, v, options, tau, f_ext);
  return tau + GeneralizedFromBodyForces(plant, s, std::move(f_ext));
}

double ForceElementsPotentialEnergy(const Plant& plant, const TreeState& s, const VectorXd& q) {
  double energy = 0;
  for (const ForceElement& element : plant.force_elements) {
    if (const auto* spring = std::get_if<JointSpring>(&element)) {
      const double stretch = q[plant.joint(spring->joint).q_start] - spring->nominal;
      energy += spring->stiffness * stretch * stretch / 2;
    } else if (const auto* e = std::get_if<LinearSpringDamper>(&element)) {
      const double stretch = SpringDamperAt(s, *e).length - e->free_length;
      energy += e->stiffness * stretch * stretch / 2;
    } else if (const auto* bushing = std::get_if<LinearBushingRpy>(&element)) {
      const BushingState st = BushingAt(plant, s, VectorXd::Zero(plant.num_velocities), *bushing);
      energy += (bushing->torque_stiffness.cwiseProduct(st.rpy).dot(st.rpy) +
                 bushing->force_stiffness.cwiseProduct(st.xyz).dot(st.xyz)) / 2;
    }
  }
  return energy;
}

}  // namespace mdlc::backend
