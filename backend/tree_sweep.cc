// tree_sweep.cc - the sweeps of tree_sweep.h.
#include "backend/tree_sweep.h"

#include <stdexcept>
#include <string>

#include "backend/kinematics.h"

namespace mdlc::backend {

using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

void RequireSize(const char* what, const VectorXd& x, int size, const char* unit) {
  if (x.size() != size) {
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(x.size()) +
                                " entries; the plant has " + std::to_string(size) + " " + unit);
  }
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

/// Moves [w; v] about point Fo in F to world Plücker about O.
Vector6d FrameToWorld(const Transform& X_WF, const Vector6d& x_F) {
  const Vector3d w = X_WF.R * Angular(x_F);
  return Spatial(w, X_WF.R * Linear(x_F) + X_WF.p.cross(w));
}

}  // namespace

void RequireState(const Plant& plant, const VectorXd& q, const VectorXd* v,
                  const VectorXd* v_like, const char* v_like_name) {
  RequireSize("q", q, plant.num_positions, "positions");
  if (v) RequireSize("v", *v, plant.num_velocities, "velocities");
  if (v_like) RequireSize(v_like_name, *v_like, plant.num_velocities, "velocities");
}

TreeState SweepDown(const Plant& plant, const VectorXd& q, const VectorXd* v) {
  TreeState s;
  const size_t num_bodies = plant.bodies.size();
  s.X_WB.resize(num_bodies);
  s.V.assign(num_bodies, Vector6d::Zero());
  s.joint.resize(plant.joints.size());
  s.I.resize(num_bodies);
  // parents come before children in joint_order, so one sweep poses them all
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    JointState& js = s.joint[id.index()];
    const int p = joint.parent.index(), c = joint.child.index();
    const auto q_j = q.segment(joint.q_start, joint.nq);
    const Transform X_FM = JointPose(joint, q_j);
    const Transform X_WF = s.X_WB[p] * joint.X_PF;
    const Transform X_WM = X_WF * X_FM;
    s.X_WB[c] = X_WM * joint.X_CM.inverse();
    const PlantBody& body = plant.bodies[c];
    const Eigen::Matrix3d& R_WB = s.X_WB[c].R;
    if (body.mass != 0 || !body.I_BBcm_B.isZero(0)) {
      s.I[c] = CompactInertia::About(body.mass, s.X_WB[c] * body.p_BoBcm_B,
                                     R_WB * body.I_BBcm_B * R_WB.transpose());
    }
    const MotionSubspace H = JointMotionSubspace(joint, q_j);
    js.S = ToWorldPlucker(H, X_WF.R, X_WM.p);
    if (!v || joint.nv == 0) {
      s.V[c] = s.V[p];
      continue;
    }
    const auto v_j = v->segment(joint.v_start, joint.nv);
    const Vector6d V_FM = H * v_j;  // about Mo, in F
    s.V[c] = s.V[p] + js.S * v_j;
    // d/dt of S' v at fixed v, S' = H moved to F's origin: the rate of H
    // itself, and the shift p_FMo x w changing as Mo moves and w turns
    const Vector6d H_rate = JointSubspaceRate(joint, q_j, v_j);
    const Vector6d S_rate_F =
        Spatial(Angular(H_rate), Linear(H_rate) + Linear(V_FM).cross(Angular(V_FM)) +
                                     X_FM.p.cross(Angular(H_rate)));
    js.velocity_product = CrossMotion(s.V[p], s.V[c] - s.V[p]) + FrameToWorld(X_WF, S_rate_F);
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
    const MotionSubspace& S = s.joint[it->index()].S;
    if (joint.nv == 1) {
      tau[joint.v_start] = S.col(0).dot(f[joint.child.index()]);
    } else if (joint.nv > 1) {
      tau.segment(joint.v_start, joint.nv) = S.transpose() * f[joint.child.index()];
    }
    f[joint.parent.index()] += f[joint.child.index()];
  }
  return tau;
}

std::vector<Vector6d> Accelerations(const Plant& plant, const TreeState& s,
                                    const VectorXd* vdot, const Vector6d& A_world) {
  std::vector<Vector6d> A(plant.bodies.size());
  A[0] = A_world;
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    const JointState& js = s.joint[id.index()];
    const int c = joint.child.index();
    A[c] = A[joint.parent.index()] + js.velocity_product;
    if (vdot && joint.nv == 1) {
      A[c] += js.S.col(0) * (*vdot)[joint.v_start];
    } else if (vdot && joint.nv > 1) {
      A[c] += js.S * vdot->segment(joint.v_start, joint.nv);
    }
  }
  return A;
}

VectorXd Rnea(const Plant& plant, const TreeState& s, const VectorXd* vdot,
              const Vector6d& A_world, const std::vector<Vector6d>& f_ext) {
  const std::vector<Vector6d> A = Accelerations(plant, s, vdot, A_world);
  std::vector<Vector6d> f(plant.bodies.size(), Vector6d::Zero());
  for (size_t b = 1; b < plant.bodies.size(); ++b) {
    if (!s.I[b].is_zero) f[b] = s.I[b] * A[b] + CrossForce(s.V[b], s.I[b] * s.V[b]);
    if (!f_ext.empty()) f[b] -= f_ext[b];
  }
  return GeneralizedFromBodyForces(plant, s, std::move(f));
}

Vector6d GravityBaseAcceleration(const Plant& plant, bool gravity) {
  return gravity ? Spatial(Vector3d::Zero(), -plant.gravity) : Vector6d::Zero();
}

Vector3d CenterOfMassInWorld(const Plant& plant, const TreeState& s, size_t b) {
  return s.X_WB[b] * plant.bodies[b].p_BoBcm_B;
}

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

}  // namespace mdlc::backend
