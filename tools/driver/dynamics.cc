// dynamics.cc - the free functions of mdlc/dynamics.h over the plant a
// Result holds; frames are looked up by name here.
#include "mdlc/dynamics.h"

#include <stdexcept>
#include <string>

#include "backend/kinematics.h"
#include "backend/named_frames.h"

namespace mdlc {

namespace {

backend::BodyFixedFrame Frame(const backend::Plant& plant, std::string_view name) {
  const backend::FrameLookup lookup = backend::FindFrameByName(plant, name);
  switch (lookup.status) {
    case backend::FrameLookupStatus::Found:
      return lookup.frame;
    case backend::FrameLookupStatus::Ambiguous:
      throw std::invalid_argument("frame name '" + std::string(name) +
                                  "' is ambiguous; give its scoped name (instance::name)");
    case backend::FrameLookupStatus::NotFound:
      break;
  }
  throw std::invalid_argument("no body or frame is named '" + std::string(name) + "'");
}

std::vector<ModelId> ModelsNamed(const backend::Plant& plant,
                                 const std::vector<std::string>& names) {
  std::vector<ModelId> models;
  for (const std::string& name : names) {
    bool found = false;
    for (size_t m = 0; m < plant.model_instances.size(); ++m) {
      if (plant.model_instances[m] == name) {
        models.push_back(ModelId(m));
        found = true;
      }
    }
    if (!found) throw std::invalid_argument("no model instance is named '" + name + "'");
  }
  return models;
}

}  // namespace

Eigen::VectorXd InverseDynamics(const Result& result, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                                const DynamicsOptions& options) {
  return backend::InverseDynamics(result.plant(), q, v, vdot, options);
}

Eigen::VectorXd BiasTerm(const Result& result, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v) {
  return backend::BiasTerm(result.plant(), q, v);
}

Eigen::VectorXd GravityForces(const Result& result, const Eigen::VectorXd& q) {
  return backend::GravityForces(result.plant(), q);
}

Eigen::VectorXd ForwardDynamics(const Result& result, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                const DynamicsOptions& options) {
  return backend::ForwardDynamics(result.plant(), q, v, tau, options);
}

double KineticEnergy(const Result& result, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const DynamicsOptions& options) {
  return backend::KineticEnergy(result.plant(), q, v, options);
}

double PotentialEnergy(const Result& result, const Eigen::VectorXd& q,
                       const DynamicsOptions& options) {
  return backend::PotentialEnergy(result.plant(), q, options);
}

Eigen::MatrixXd JacobianSpatialVelocity(const Result& result, const Eigen::VectorXd& q,
                                        std::string_view frame_B, const Eigen::Vector3d& p_BoBp_B,
                                        std::string_view frame_A, std::string_view frame_E) {
  const backend::Plant& plant = result.plant();
  return backend::JacobianSpatialVelocity(plant, q, Frame(plant, frame_B), p_BoBp_B,
                                          Frame(plant, frame_A), Frame(plant, frame_E));
}

Eigen::MatrixXd JacobianTranslationalVelocity(const Result& result, const Eigen::VectorXd& q,
                                              std::string_view frame_B,
                                              const Eigen::Vector3d& p_BoBp_B,
                                              std::string_view frame_A,
                                              std::string_view frame_E) {
  return JacobianSpatialVelocity(result, q, frame_B, p_BoBp_B, frame_A, frame_E).bottomRows<3>();
}

Transform FramePose(const Result& result, const Eigen::VectorXd& q, std::string_view frame) {
  const backend::BodyFixedFrame F = Frame(result.plant(), frame);
  return backend::BodyPosesInWorld(result.plant(), q)[F.body.index()] * F.X_BF;
}

backend::Vector6d FrameSpatialVelocity(const Result& result, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& v, std::string_view frame) {
  const backend::Plant& plant = result.plant();
  const backend::BodyFixedFrame F = Frame(plant, frame);
  const backend::Vector6d V_WB = backend::BodySpatialVelocities(plant, q, v)[F.body.index()];
  const Eigen::Vector3d w = V_WB.head<3>();
  const Eigen::Vector3d p_BoFo_W = backend::BodyPosesInWorld(plant, q)[F.body.index()].R * F.X_BF.p;
  backend::Vector6d V_WF;
  V_WF << w, V_WB.tail<3>() + w.cross(p_BoFo_W);
  return V_WF;
}

backend::Vector6d FrameSpatialAcceleration(const Result& result, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                                           std::string_view frame) {
  const backend::Plant& plant = result.plant();
  const backend::BodyFixedFrame F = Frame(plant, frame);
  const size_t b = F.body.index();
  const backend::Vector6d A_WB = backend::BodySpatialAccelerations(plant, q, v, vdot)[b];
  const backend::Vector6d V_WB = backend::BodySpatialVelocities(plant, q, v)[b];
  // a_Fo = a_Bo + alpha x p + w x (w x p), p = p_BoFo_W
  const Eigen::Vector3d w = V_WB.head<3>(), alpha = A_WB.head<3>();
  const Eigen::Vector3d p = backend::BodyPosesInWorld(plant, q)[b].R * F.X_BF.p;
  backend::Vector6d A_WF;
  A_WF << alpha, A_WB.tail<3>() + alpha.cross(p) + w.cross(w.cross(p));
  return A_WF;
}

backend::CenterOfMass CenterOfMass(const Result& result, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& v,
                                   const std::vector<std::string>& model_instances) {
  const backend::Plant& plant = result.plant();
  return backend::CalcCenterOfMass(plant, q, v, ModelsNamed(plant, model_instances));
}

}  // namespace mdlc
