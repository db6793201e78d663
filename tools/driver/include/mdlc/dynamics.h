// mdlc/dynamics.h - velocities, Jacobians, center of mass, inverse and
// forward dynamics and energy of a compiled model: free functions of a Result
// that made a model (Result::has_model(); they throw std::logic_error
// otherwise). Conventions and what is left out (constraints, loops, contact,
// limits) are backend/dynamics.h's; q and v are as mdlc/kinematics.h lays
// them out.
//
//   Eigen::VectorXd q = mdlc::DefaultPositions(result);
//   Eigen::VectorXd v = Eigen::VectorXd::Zero(result.plant().num_velocities);
//   Eigen::VectorXd tau = mdlc::InverseDynamics(result, q, v, vdot);
//   Eigen::MatrixXd J = mdlc::JacobianSpatialVelocity(result, q, "arm::tool0");
//
// Frames are named as in plant-json: a body ("model::link", or "world"), or a
// frame ("model::frame"); a local name is accepted when exactly one body or
// frame carries it. An unknown or ambiguous name throws std::invalid_argument.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "backend/dynamics.h"
#include "mdlc/mdlc.h"

namespace mdlc {

using backend::DynamicsOptions;

/// tau = M vdot + C v - tau_g - tau_applied (CalcInverseDynamics).
Eigen::VectorXd InverseDynamics(const Result& result, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                                const DynamicsOptions& options = {});

/// C(q, v) v, without gravity (CalcBiasTerm).
Eigen::VectorXd BiasTerm(const Result& result, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v);

/// tau_g(q) (CalcGravityGeneralizedForces).
Eigen::VectorXd GravityForces(const Result& result, const Eigen::VectorXd& q);

/// vdot for (q, v, tau), with what `options` switches on.
Eigen::VectorXd ForwardDynamics(const Result& result, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                const DynamicsOptions& options = {});

double KineticEnergy(const Result& result, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const DynamicsOptions& options = {});
double PotentialEnergy(const Result& result, const Eigen::VectorXd& q,
                       const DynamicsOptions& options = {});

/// Js_V_ABp_E (6 x nv) for frame `frame_B` shifted to p_BoBp_B, measured in
/// `frame_A` and expressed in `frame_E` (both default to the world).
Eigen::MatrixXd JacobianSpatialVelocity(const Result& result, const Eigen::VectorXd& q,
                                        std::string_view frame_B,
                                        const Eigen::Vector3d& p_BoBp_B = Eigen::Vector3d::Zero(),
                                        std::string_view frame_A = "world",
                                        std::string_view frame_E = "world");

/// Js_v_ABp_E (3 x nv), the translational rows of the above.
Eigen::MatrixXd JacobianTranslationalVelocity(
    const Result& result, const Eigen::VectorXd& q, std::string_view frame_B,
    const Eigen::Vector3d& p_BoBp_B = Eigen::Vector3d::Zero(),
    std::string_view frame_A = "world", std::string_view frame_E = "world");

/// X_WF of a named body or frame at q.
Transform FramePose(const Result& result, const Eigen::VectorXd& q, std::string_view frame);

/// V_WF_W = [w; v of F's origin] of a named body or frame at (q, v).
backend::Vector6d FrameSpatialVelocity(const Result& result, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& v, std::string_view frame);

/// A_WF_W = [alpha; a of F's origin] of a named body or frame at (q, v, vdot),
/// gravity not included (the derivative of FrameSpatialVelocity).
backend::Vector6d FrameSpatialAcceleration(const Result& result, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                                           std::string_view frame);

/// The center of mass of every body (empty `model_instances`) or of the
/// bodies of the named model instances; v may be empty (velocity then zero).
backend::CenterOfMass CenterOfMass(const Result& result, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& v = {},
                                   const std::vector<std::string>& model_instances = {});

}  // namespace mdlc
