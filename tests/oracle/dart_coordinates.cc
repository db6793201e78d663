// dart_coordinates.cc - see dart_coordinates.h.
#include "dart_coordinates.h"

#include <dart/dynamics/PlanarJoint.hpp>
#include <dart/math/Geometry.hpp>

#include <Eigen/Dense>

#include "backend/kinematics.h"

namespace mdlc::oracle {
namespace {

using backend::Plant;
using backend::PlantJoint;
using ir::JointType;

// The DART joint type that moves a body as mdlc's `type` does.
const char* DartTypeFor(JointType type) {
  switch (type) {
    case JointType::Revolute: return "RevoluteJoint";
    case JointType::Prismatic: return "PrismaticJoint";
    case JointType::Ball: return "BallJoint";
    case JointType::Universal: return "UniversalJoint";
    case JointType::Planar: return "PlanarJoint";
    case JointType::Weld: return "WeldJoint";
    case JointType::QuaternionFloating: return "FreeJoint";
    default: return nullptr;  // screw, curvilinear, rpy_floating: not paired
  }
}

Transform FromIsometry(const Eigen::Isometry3d& X) { return {X.linear(), X.translation()}; }

bool IsIdentity(const Transform& X, double tol) {
  return (X.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tol &&
         X.p.cwiseAbs().maxCoeff() <= tol;
}

Eigen::Matrix3d Hat(const Eigen::Vector3d& p) {
  Eigen::Matrix3d S;
  S << 0, -p.z(), p.y(), p.z(), 0, -p.x(), -p.y(), p.x(), 0;
  return S;
}

// A planar joint's [x; y] = A [q0; q1]: DART's axes t1, t2 of the plane,
// written in mdlc's frame F (the same frame: PairWithDart checks it).
Eigen::Matrix2d PlanarAxes(const dart::dynamics::Joint& joint) {
  const auto& planar = static_cast<const dart::dynamics::PlanarJoint&>(joint);
  Eigen::Matrix2d B;  // [q0; q1] = B [x; y]
  B.col(0) = planar.getTranslationalAxis1().head<2>();
  B.col(1) = planar.getTranslationalAxis2().head<2>();
  return B.inverse();
}

}  // namespace

std::string PairWithDart(const Plant& plant,
                         const std::vector<dart::dynamics::SkeletonPtr>& skeletons,
                         DartPairing* pairing) {
  pairing->skeletons = skeletons;
  pairing->skeleton_v_start.clear();
  int nv = 0;
  size_t dart_bodies = 0;
  for (const auto& s : skeletons) {
    pairing->skeleton_v_start.push_back(nv);
    nv += static_cast<int>(s->getNumDofs());
    dart_bodies += s->getNumBodyNodes();
  }
  pairing->nv = nv;
  if (nv != plant.num_velocities) {
    return "DART has " + std::to_string(nv) + " velocities, mdlc " +
           std::to_string(plant.num_velocities);
  }
  pairing->bodies.assign(plant.bodies.size(), nullptr);
  size_t paired = 0;
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const backend::PlantBody& body = plant.bodies[b];
    if (body.is_world) continue;
    const std::string scoped = plant.ScopedName(body);
    const size_t cut = scoped.rfind("::");
    const std::string model = cut == std::string::npos ? "" : scoped.substr(0, cut);
    for (const auto& s : skeletons) {
      if (skeletons.size() > 1 && s->getName() != model) continue;
      if (auto* node = s->getBodyNode(body.name)) pairing->bodies[b] = node;
    }
    if (!pairing->bodies[b]) return "DART has no body for " + scoped;
    ++paired;
  }
  if (paired != dart_bodies) {
    return "DART has " + std::to_string(dart_bodies) + " bodies, mdlc " + std::to_string(paired);
  }
  pairing->joints.clear();
  for (BodyId b : plant.body_order) {
    const backend::PlantBody& body = plant.body(b);
    if (body.is_world) continue;
    const PlantJoint& joint = plant.joint(body.inbound_joint);
    dart::dynamics::Joint* dart = pairing->bodies[b.index()]->getParentJoint();
    const std::string name = plant.ScopedName(joint);
    const auto* dart_parent = dart->getParentBodyNode();
    if (dart_parent != pairing->bodies[joint.parent.index()]) {
      return "joint " + name + ": DART's parent body is " +
             (dart_parent ? dart_parent->getName() : std::string("the world"));
    }
    const char* want = DartTypeFor(joint.type);
    if (!want || dart->getType() != want) {
      return "joint " + name + ": mdlc " + std::string(ir::JointTypeName(joint.type)) +
             ", DART " + dart->getType();
    }
    // DART's joint frames against mdlc's F and M (dart_coordinates.h).
    const Transform X_PJp = FromIsometry(dart->getTransformFromParentBodyNode());
    const Transform X_CJc = FromIsometry(dart->getTransformFromChildBodyNode());
    const Transform K = X_PJp.inverse() * joint.X_PF, L = joint.X_CM.inverse() * X_CJc;
    // A ball joint's motion stays a rotation only if neither frame is offset;
    // a plane in DART's joint frame must be mdlc's.
    if ((joint.type == JointType::Ball && (!K.p.isZero(1e-9) || !L.p.isZero(1e-9))) ||
        (joint.type == JointType::Planar && (!IsIdentity(K, 1e-9) || !IsIdentity(L, 1e-9)))) {
      return "joint " + name + ": DART's joint frames are offset from mdlc's F and M";
    }
    if (joint.type == JointType::Planar) {
      const auto& planar = static_cast<const dart::dynamics::PlanarJoint&>(*dart);
      if (!planar.getRotationalAxis().isApprox(Eigen::Vector3d::UnitZ(), 1e-12)) {
        return "joint " + name + ": DART's plane is not mdlc's x-y plane of F";
      }
    }
    if (joint.nv == 0) continue;
    // DART applies mimic joints as constraints, mdlc's dynamics leave
    // couplers out: both compare as independent joints.
    dart->setActuatorType(dart::dynamics::Joint::FORCE);
    JointPair pair;
    pair.joint = body.inbound_joint;
    pair.dart = dart;
    pair.K = K;
    pair.L = L;
    for (size_t k = 0; k < skeletons.size(); ++k) {
      if (skeletons[k].get() == dart->getSkeleton().get()) {
        pair.dart_v_start =
            pairing->skeleton_v_start[k] + static_cast<int>(dart->getIndexInSkeleton(0));
      }
    }
    pairing->joints.push_back(pair);
  }
  return "";
}

DartState ToDartState(const Plant& plant, const DartPairing& pairing, const Eigen::VectorXd& q,
                      const Eigen::VectorXd& v) {
  const int nv = pairing.nv;
  DartState s;
  s.q = Eigen::VectorXd::Zero(nv);  // DART's positions: as many as velocities
  s.T = Eigen::MatrixXd::Zero(nv, nv);
  s.a = Eigen::VectorXd::Zero(nv);
  for (const JointPair& pair : pairing.joints) {
    const PlantJoint& joint = plant.joint(pair.joint);
    const int i = joint.v_start, d = pair.dart_v_start, n = joint.nv;
    const Eigen::VectorXd q_j = q.segment(joint.q_start, joint.nq);
    switch (joint.type) {
      case JointType::QuaternionFloating: {
        const Transform X_FM = backend::JointPose(joint, q_j);
        const Transform Q = pair.K * X_FM * pair.L;
        s.q.segment<3>(d) = dart::math::logMap(Q.R);
        s.q.segment<3>(d + 3) = Q.p;
        // V_M = Ad_L V_Jc = [R_L w; R_L v + p_L x R_L w], then into F
        const Eigen::Matrix3d& R_L = pair.L.R;
        s.T.block<3, 3>(i, d) = X_FM.R * R_L;
        s.T.block<3, 3>(i + 3, d) = X_FM.R * Hat(pair.L.p) * R_L;
        s.T.block<3, 3>(i + 3, d + 3) = X_FM.R * R_L;
        const Eigen::Vector3d w_FM_F = v.segment<3>(i), v_FM_F = v.segment<3>(i + 3);
        s.a.segment<3>(i + 3) = w_FM_F.cross(v_FM_F);
        break;
      }
      case JointType::Ball: {
        const Transform X_FM = backend::JointPose(joint, q_j);
        s.q.segment<3>(d) = dart::math::logMap(pair.K.R * X_FM.R * pair.L.R);
        s.T.block<3, 3>(i, d) = X_FM.R * pair.L.R;
        break;
      }
      case JointType::Planar: {
        const Eigen::Matrix2d A = PlanarAxes(*pair.dart);
        s.q.segment<2>(d) = A * q_j.head<2>();
        s.q(d + 2) = q_j(2);
        s.T.block<2, 2>(i, d) = A.inverse();
        s.T(i + 2, d + 2) = 1;
        break;
      }
      default:  // revolute, prismatic, universal
        s.q.segment(d, n) = q_j;
        s.T.block(i, d, n, n).setIdentity();
        break;
    }
  }
  s.v = s.T.partialPivLu().solve(v);
  return s;
}

namespace {
template <typename Set>
void SetStacked(const DartPairing& pairing, const Eigen::VectorXd& x, Set set) {
  for (size_t k = 0; k < pairing.skeletons.size(); ++k) {
    const int n = static_cast<int>(pairing.skeletons[k]->getNumDofs());
    set(*pairing.skeletons[k], Eigen::VectorXd(x.segment(pairing.skeleton_v_start[k], n)));
  }
}
}  // namespace

void SetDartPositions(const DartPairing& pairing, const Eigen::VectorXd& q) {
  SetStacked(pairing, q, [](auto& s, const Eigen::VectorXd& x) { s.setPositions(x); });
}
void SetDartVelocities(const DartPairing& pairing, const Eigen::VectorXd& v) {
  SetStacked(pairing, v, [](auto& s, const Eigen::VectorXd& x) { s.setVelocities(x); });
}
void SetDartAccelerations(const DartPairing& pairing, const Eigen::VectorXd& vdot) {
  SetStacked(pairing, vdot, [](auto& s, const Eigen::VectorXd& x) { s.setAccelerations(x); });
}
void SetDartForces(const DartPairing& pairing, const Eigen::VectorXd& tau) {
  SetStacked(pairing, tau, [](auto& s, const Eigen::VectorXd& x) { s.setForces(x); });
}

}  // namespace mdlc::oracle
