// dynamics.cc - recursive Newton-Euler in Plücker coordinates about the
// world origin (spatial.h).
//
// In those coordinates a joint's motion subspace S_j is H_FM(q)
// (kinematics.h: columns [w; velocity of M's origin] in F) moved to F's
// origin and re-expressed in W, and the sweep is Featherstone's:
//   V_c = V_p + S_j v_j
//   A_c = A_p + S_j vdot_j + V_p x (S_j v_j) + X_WF (dS'_F/dt v_j)
//   f_c = I_c A_c + V_c x* (I_c V_c) - f_ext,c
//   tau_j = S_j^T (f_c + the f of c's descendants)
// with A_world = -gravity so the weights come out of the same sweep. The
// term dS'_F/dt v_j is the rate of the subspace as F sees it: only universal
// and curvilinear joints have an H that turns with q, and every joint whose
// M origin moves off F's origin (planar, floating, curvilinear, screw)
// shifts its angular columns as it goes.
#include "backend/dynamics.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "backend/named_frames.h"

namespace mdlc::backend {

namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;

Vector3d Angular(const Vector6d& x) { return x.head<3>(); }
Vector3d Linear(const Vector6d& x) { return x.tail<3>(); }
Vector6d Spatial(const Vector3d& angular, const Vector3d& linear) {
  Vector6d x;
  x << angular, linear;
  return x;
}

/// a x m: the rate of motion vector m carried by a frame moving with a.
Vector6d CrossMotion(const Vector6d& a, const Vector6d& m) {
  return Spatial(Angular(a).cross(Angular(m)),
                 Linear(a).cross(Angular(m)) + Angular(a).cross(Linear(m)));
}

/// a x* f: the same for a force vector f = [moment about O; force].
Vector6d CrossForce(const Vector6d& a, const Vector6d& f) {
  return Spatial(Angular(a).cross(Angular(f)) + Linear(a).cross(Linear(f)),
                 Angular(a).cross(Linear(f)));
}

/// The velocity of the body-fixed point at p_W, from a Plücker velocity.
Vector3d PointVelocity(const Vector6d& V, const Vector3d& p_W) {
  return Linear(V) + Angular(V).cross(p_W);
}

void RequireSize(const char* what, const VectorXd& x, int size) {
  if (x.size() != size) {
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(x.size()) +
                                " entries; the plant has " + std::to_string(size));
  }
}

void RequireState(const Plant& plant, const VectorXd& q, const VectorXd* v,
                  const VectorXd* v_like = nullptr, const char* v_like_name = "") {
  RequireSize("q", q, plant.num_positions);
  if (v) RequireSize("v", *v, plant.num_velocities);
  if (v_like) RequireSize(v_like_name, *v_like, plant.num_velocities);
}

/// (dH_FM/dt) v_j in F, about M's origin, for the joints whose H turns with q.
Vector6d JointSubspaceRate(const PlantJoint& joint, const Eigen::Ref<const VectorXd>& q_j,
                           const Eigen::Ref<const VectorXd>& v_j) {
  switch (joint.type) {
    case ir::JointType::Universal: {
      // column 1 is Rx(q0) y, turning about x at v0
      const Vector3d y_F = RotationAboutAxis(Vector3d::UnitX(), q_j[0]) * Vector3d::UnitY();
      return Spatial(v_j[0] * v_j[1] * Vector3d::UnitX().cross(y_F), Vector3d::Zero());
    }
    case ir::JointType::Curvilinear: {
      // the tangent turns about the plane normal at curvature * sdot
      const ir::CurvilinearPath& path = joint.curvilinear_path;
      const Vector3d tangent = Linear(path.VelocityAt(q_j[0]));
      const double kappa = path.CurvatureAt(q_j[0]);
      return Spatial(Vector3d::Zero(),
                     kappa * v_j[0] * v_j[0] * path.plane_normal.cross(tangent));
    }
    default:
      return Vector6d::Zero();
  }
}

/// What one sweep down the tree knows about a joint at (q, v).
struct JointState {
  MotionSubspace S;             // world Plücker columns
  Vector6d subspace_rate_term;  // X_WF (dS'_F/dt) v_j, world Plücker
};

/// Poses, velocities and joint subspaces of the whole tree at (q, v).
struct TreeState {
  std::vector<Transform> X_WB;
  std::vector<Vector6d> V;        // by body, world Plücker
  std::vector<JointState> joint;  // by JointId
  std::vector<Matrix6d> I;        // by body, about the world origin in W
};

/// Moves [w; v] about point Fo in F to world Plücker about O.
Vector6d FrameToWorld(const Transform& X_WF, const Vector6d& x_F) {
  const Vector3d w = X_WF.R * Angular(x_F);
  return Spatial(w, X_WF.R * Linear(x_F) + X_WF.p.cross(w));
}

TreeState SweepDown(const Plant& plant, const VectorXd& q, const VectorXd* v) {
  TreeState s;
  s.X_WB = BodyPosesInWorld(plant, q);
  s.V.assign(plant.bodies.size(), Vector6d::Zero());
  s.joint.resize(plant.joints.size());
  s.I.resize(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const PlantBody& body = plant.bodies[b];
    const Eigen::Matrix3d& R_WB = s.X_WB[b].R;
    s.I[b] = SpatialInertiaAboutOrigin(body.mass, s.X_WB[b] * body.p_BoBcm_B,
                                       R_WB * body.I_BBcm_B * R_WB.transpose());
  }
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    JointState& js = s.joint[id.index()];
    const auto q_j = q.segment(joint.q_start, joint.nq);
    const Transform X_WF = JointFrameInWorld(plant, s.X_WB, id);
    const Vector3d p_WMo = s.X_WB[joint.child.index()] * joint.X_CM.p;
    const MotionSubspace H = JointMotionSubspace(joint, q_j);
    js.S = ToWorldPlucker(H, X_WF.R, p_WMo);
    js.subspace_rate_term.setZero();
    if (!v) continue;
    const auto v_j = v->segment(joint.v_start, joint.nv);
    const Vector6d V_FM = H * v_j;  // about Mo, in F
    s.V[joint.child.index()] = s.V[joint.parent.index()] + js.S * v_j;
    // d/dt of S' v at fixed v, S' = H moved to F's origin: the rate of H
    // itself, and the shift p_FMo x w changing as Mo moves and w turns
    const Vector3d p_FMo = JointPose(joint, q_j).p;
    const Vector6d H_rate = JointSubspaceRate(joint, q_j, v_j);
    const Vector6d S_rate_F =
        Spatial(Angular(H_rate), Linear(H_rate) + Linear(V_FM).cross(Angular(V_FM)) +
                                     p_FMo.cross(Angular(H_rate)));
    js.subspace_rate_term = FrameToWorld(X_WF, S_rate_F);
  }
  return s;
}

/// Generalized forces of body forces f (world Plücker, by body; empty:
/// none): tau_j = S_j^T (the sum of f over j's subtree).
VectorXd GeneralizedFromBodyForces(const Plant& plant, const TreeState& s,
                                   std::vector<Vector6d> f) {
  VectorXd tau = VectorXd::Zero(plant.num_velocities);
  if (f.empty()) return tau;
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    if (joint.nv > 0) {
      tau.segment(joint.v_start, joint.nv) = s.joint[it->index()].S.transpose() * f[joint.child.index()];
    }
    f[joint.parent.index()] += f[joint.child.index()];
  }
  return tau;
}

/// The RNEA with body forces f_ext (world Plücker, by body; may be empty)
/// acting on the bodies: tau for vdot (may be null: zero) and base
/// acceleration A_0.
VectorXd Rnea(const Plant& plant, const TreeState& s, const VectorXd* v, const VectorXd* vdot,
              const Vector6d& A_world, const std::vector<Vector6d>& f_ext) {
  std::vector<Vector6d> A(plant.bodies.size(), Vector6d::Zero());
  std::vector<Vector6d> f(plant.bodies.size(), Vector6d::Zero());
  A[0] = A_world;
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    const JointState& js = s.joint[id.index()];
    const int p = joint.parent.index(), c = joint.child.index();
    A[c] = A[p];
    if (vdot) A[c] += js.S * vdot->segment(joint.v_start, joint.nv);
    if (v) {
      A[c] += CrossMotion(s.V[p], js.S * v->segment(joint.v_start, joint.nv)) +
              js.subspace_rate_term;
    }
    f[c] = s.I[c] * A[c] + CrossForce(s.V[c], s.I[c] * s.V[c]);
    if (!f_ext.empty()) f[c] -= f_ext[c];
  }
  return GeneralizedFromBodyForces(plant, s, std::move(f));
}

Vector6d GravityBaseAcceleration(const Plant& plant, bool gravity) {
  return gravity ? Spatial(Vector3d::Zero(), -plant.gravity) : Vector6d::Zero();
}

Vector3d CenterOfMassInWorld(const Plant& plant, const TreeState& s, size_t b) {
  return s.X_WB[b] * plant.bodies[b].p_BoBcm_B;
}

/// Translational Jacobian columns of the point p_W fixed on `body`, added
/// (sign +1) or subtracted (-1) into the 6-row J, for every joint between
/// the body and the world.
void AddPointJacobian(const Plant& plant, const TreeState& s, BodyId body, const Vector3d& p_W,
                      double sign, Eigen::MatrixXd& J) {
  for (BodyId b = body; !plant.body(b).is_world; b = plant.body(b).parent) {
    const JointId id = plant.body(b).inbound_joint;
    const PlantJoint& joint = plant.joint(id);
    const MotionSubspace& S = s.joint[id.index()].S;
    for (int k = 0; k < joint.nv; ++k) {
      const Vector6d col = S.col(k);
      J.col(joint.v_start + k).head<3>() += sign * Angular(col);
      J.col(joint.v_start + k).tail<3>() += sign * PointVelocity(col, p_W);
    }
  }
}

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

}  // namespace

std::vector<Vector6d> BodySpatialVelocities(const Plant& plant, const VectorXd& q,
                                            const VectorXd& v) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  std::vector<Vector6d> V_WB(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    V_WB[b] = Spatial(Angular(s.V[b]), PointVelocity(s.V[b], s.X_WB[b].p));
  }
  return V_WB;
}

std::vector<Vector6d> BodySpatialAccelerations(const Plant& plant, const VectorXd& q,
                                               const VectorXd& v, const VectorXd& vdot) {
  RequireState(plant, q, &v, &vdot, "vdot");
  const TreeState s = SweepDown(plant, q, &v);
  // the Plücker accelerations, by the forward half of the RNEA
  std::vector<Vector6d> A(plant.bodies.size(), Vector6d::Zero());
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    const JointState& js = s.joint[id.index()];
    const int p = joint.parent.index(), c = joint.child.index();
    A[c] = A[p] + js.S * vdot.segment(joint.v_start, joint.nv) +
           CrossMotion(s.V[p], js.S * v.segment(joint.v_start, joint.nv)) + js.subspace_rate_term;
  }
  // a_Bo = d/dt (v_O + w x p_WBo) = adot_O + alpha x p + w x v_Bo
  std::vector<Vector6d> A_WB(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const Vector3d& p = s.X_WB[b].p;
    const Vector3d v_Bo = PointVelocity(s.V[b], p);
    A_WB[b] = Spatial(Angular(A[b]), PointVelocity(A[b], p) + Angular(s.V[b]).cross(v_Bo));
  }
  return A_WB;
}

VectorXd ReflectedInertia(const Plant& plant) {
  VectorXd r = VectorXd::Zero(plant.num_velocities);
  for (const PlantActuator& actuator : plant.actuators) {
    const PlantJoint& joint = plant.joint(actuator.joint);
    if (joint.nv != 1) continue;  // actuators drive 1-dof joints
    r[joint.v_start] += actuator.rotor_inertia * actuator.gear_ratio * actuator.gear_ratio;
  }
  return r;
}

VectorXd InverseDynamics(const Plant& plant, const VectorXd& q, const VectorXd& v,
                         const VectorXd& vdot, const DynamicsOptions& options) {
  RequireState(plant, q, &v, &vdot, "vdot");
  const TreeState s = SweepDown(plant, q, &v);
  VectorXd tau_joint = VectorXd::Zero(plant.num_velocities);
  std::vector<Vector6d> f_ext;
  CollectAppliedForces(plant, s, q, v, options, tau_joint, f_ext);
  VectorXd tau = Rnea(plant, s, &v, &vdot, GravityBaseAcceleration(plant, options.gravity), f_ext);
  tau -= tau_joint;
  if (options.reflected_inertia) tau += ReflectedInertia(plant).cwiseProduct(vdot);
  return tau;
}

VectorXd BiasTerm(const Plant& plant, const VectorXd& q, const VectorXd& v) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  return Rnea(plant, s, &v, nullptr, Vector6d::Zero(), {});
}

VectorXd GravityForces(const Plant& plant, const VectorXd& q) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  return -Rnea(plant, s, nullptr, nullptr, GravityBaseAcceleration(plant, true), {});
}

VectorXd AppliedForces(const Plant& plant, const VectorXd& q, const VectorXd& v,
                       const DynamicsOptions& options) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  return AppliedForcesAt(plant, s, q, v, options);
}

VectorXd ForwardDynamics(const Plant& plant, const VectorXd& q, const VectorXd& v,
                         const VectorXd& tau, const DynamicsOptions& options) {
  RequireState(plant, q, &v, &tau, "tau");
  const TreeState s = SweepDown(plant, q, &v);
  // C v - tau_g - tau_applied, by the RNEA at vdot = 0
  VectorXd tau_joint = VectorXd::Zero(plant.num_velocities);
  std::vector<Vector6d> f_ext;
  CollectAppliedForces(plant, s, q, v, options, tau_joint, f_ext);
  const VectorXd rhs = tau + tau_joint -
                       Rnea(plant, s, &v, nullptr, GravityBaseAcceleration(plant, options.gravity), f_ext);
  Eigen::MatrixXd M = CalcMassMatrix(plant, q);
  if (options.reflected_inertia) M.diagonal() += ReflectedInertia(plant);
  if (M.rows() == 0) return VectorXd::Zero(0);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
  const VectorXd D = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success || !(D.minCoeff() > 1e-12 * std::max(1.0, D.maxCoeff()))) {
    throw std::domain_error(
        "the mass matrix is singular at this configuration (a joint moves only massless "
        "bodies), so the accelerations are undefined");
  }
  return ldlt.solve(rhs);
}

double KineticEnergy(const Plant& plant, const VectorXd& q, const VectorXd& v,
                     const DynamicsOptions& options) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  double energy = 0;
  for (size_t b = 0; b < plant.bodies.size(); ++b) energy += s.V[b].dot(s.I[b] * s.V[b]);
  if (options.reflected_inertia) energy += ReflectedInertia(plant).dot(v.cwiseProduct(v));
  return energy / 2;
}

double PotentialEnergy(const Plant& plant, const VectorXd& q, const DynamicsOptions& options) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  double energy = 0;
  if (options.gravity) {
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      energy -= plant.bodies[b].mass * plant.gravity.dot(CenterOfMassInWorld(plant, s, b));
    }
  }
  if (options.force_elements) {
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
  }
  return energy;
}

Eigen::MatrixXd JacobianSpatialVelocity(const Plant& plant, const VectorXd& q,
                                        const BodyFixedFrame& B, const Vector3d& p_BoBp_B,
                                        const BodyFixedFrame& A, const BodyFixedFrame& E) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  const Vector3d p_WBp = s.X_WB[B.body.index()] * (B.X_BF * p_BoBp_B);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, plant.num_velocities);
  AddPointJacobian(plant, s, B.body, p_WBp, +1, J);
  // measured in A: minus the motion of A's point that coincides with Bp
  AddPointJacobian(plant, s, A.body, p_WBp, -1, J);
  const Eigen::Matrix3d R_EW = (s.X_WB[E.body.index()].R * E.X_BF.R).transpose();
  J.topRows<3>() = R_EW * J.topRows<3>();
  J.bottomRows<3>() = R_EW * J.bottomRows<3>();
  return J;
}

Eigen::MatrixXd JacobianTranslationalVelocity(const Plant& plant, const VectorXd& q,
                                              const BodyFixedFrame& B, const Vector3d& p_BoBp_B,
                                              const BodyFixedFrame& A, const BodyFixedFrame& E) {
  return JacobianSpatialVelocity(plant, q, B, p_BoBp_B, A, E).bottomRows<3>();
}

CenterOfMass CalcCenterOfMass(const Plant& plant, const VectorXd& q, const VectorXd& v,
                              const std::vector<ModelId>& models) {
  const bool with_v = v.size() > 0;
  RequireState(plant, q, with_v ? &v : nullptr);
  const TreeState s = SweepDown(plant, q, with_v ? &v : nullptr);
  auto selected = [&](size_t b) {
    if (plant.bodies[b].is_world) return false;
    if (models.empty()) return true;
    for (ModelId m : models) {
      if (plant.bodies[b].model == m) return true;
    }
    return false;
  };
  // per body: its selected mass and first moment, then summed over subtrees
  std::vector<double> mass(plant.bodies.size(), 0);
  std::vector<Vector3d> moment(plant.bodies.size(), Vector3d::Zero());
  CenterOfMass com;
  Vector3d momentum = Vector3d::Zero();
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    if (!selected(b)) continue;
    const Vector3d c = CenterOfMassInWorld(plant, s, b);
    mass[b] = plant.bodies[b].mass;
    moment[b] = mass[b] * c;
    com.mass += mass[b];
    com.position += moment[b];
    if (with_v) momentum += mass[b] * PointVelocity(s.V[b], c);
  }
  if (!(com.mass > 0)) {
    throw std::domain_error("the selected bodies have no mass, so they have no center of mass");
  }
  com.position /= com.mass;
  com.velocity = momentum / com.mass;
  // column of joint j: sum over its subtree of m (S_lin + S_ang x c)
  com.jacobian = Eigen::MatrixXd::Zero(3, plant.num_velocities);
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    const int c = joint.child.index();
    const MotionSubspace& S = s.joint[it->index()].S;
    for (int k = 0; k < joint.nv; ++k) {
      com.jacobian.col(joint.v_start + k) =
          (mass[c] * Linear(S.col(k)) + Angular(S.col(k)).cross(moment[c])) / com.mass;
    }
    mass[joint.parent.index()] += mass[c];
    moment[joint.parent.index()] += moment[c];
  }
  return com;
}

}  // namespace mdlc::backend
