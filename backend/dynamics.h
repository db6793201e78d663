// dynamics.h - velocities, accelerations and rigid-body dynamics of the plant
// (the subset of Drake's MultibodyPlant calculations a controller or planner
// needs), by the recursive Newton-Euler and articulated-body algorithms in
// world Plücker coordinates (tree_sweep.h).
//
// Coordinates are the plant's q and v (kinematics.h says what they are per
// joint type: a quaternion_floating joint has q = [qw qx qy qz px py pz] and
// v = [w_FM_F; v_FM_F], a ball joint roll-pitch-yaw q and v = w_FM_F). All
// generalized-force vectors are in v order. Every function taking q, v, vdot
// or tau checks their sizes (num_positions / num_velocities) and throws
// std::invalid_argument otherwise.
//
// Sign conventions are Drake's:
//   InverseDynamics  tau = M vdot + C(q,v) v - tau_g(q) - tau_applied(q,v)
//                        (+ reflected inertia * vdot), CalcInverseDynamics
//   BiasTerm         C(q,v) v, no gravity (CalcBiasTerm)
//   GravityForces    tau_g(q): positive when gravity does positive work
//                    (CalcGravityGeneralizedForces)
//   ForwardDynamics  vdot with M vdot + C v = tau + tau_g + tau_applied
// where tau_applied is what DynamicsOptions switches on: joint damping
// (-d v, per velocity) and the force elements (joint springs, linear
// spring-dampers, and roll-pitch-yaw bushings, whose generalized forces come
// from their potential 1/2 k x^2 and dissipation 1/2 b xdot^2 over their six
// coordinates, as Drake's LinearBushingRollPitchYaw defines them). Reflected inertia (an actuator's rotor_inertia *
// gear_ratio^2 on its joint's velocity) is part of M here, as in Drake's
// dynamics; CalcMassMatrix (mass_matrix.h) stays the rigid-body matrix.
//
// Not modelled (out of scope for these functions): coupler and other
// constraints, kinematic loops, contact, joint limits and deformable bodies
// (massless here). A spring-damper whose ends meet, or a bushing at pitch
// +-90 degrees, throws std::domain_error (their forces are undefined there).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "backend/plant.h"
#include "backend/spatial.h"
#include "ir/transform.h"

namespace mdlc::backend {

struct DynamicsOptions {
  bool gravity = true;             // the plant's gravity (Plant::gravity)
  bool joint_damping = false;      // tau_applied -= damping .* v
  bool force_elements = false;     // joint springs and linear spring-dampers
  bool reflected_inertia = true;   // actuators' rotor_inertia * gear_ratio^2
};

/// A frame fixed on a body: its body and X_BF. A body's own frame has X_BF
/// the identity.
struct BodyFixedFrame {
  BodyId body;
  Transform X_BF = Transform::Identity();
};

/// V_WB_W of every body (indexed by BodyId): [w_WB; v_WBo], both in W, the
/// translational part being the velocity of the body origin Bo.
std::vector<Vector6d> BodySpatialVelocities(const Plant& plant, const Eigen::VectorXd& q,
                                            const Eigen::VectorXd& v);

/// A_WB_W of every body: [alpha_WB; a_WBo] in W (no gravity in it).
std::vector<Vector6d> BodySpatialAccelerations(const Plant& plant, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v,
                                               const Eigen::VectorXd& vdot);

/// The generalized forces tau that produce vdot at (q, v).
Eigen::VectorXd InverseDynamics(const Plant& plant, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                                const DynamicsOptions& options = {});

/// C(q, v) v: the Coriolis, centripetal and gyroscopic terms.
Eigen::VectorXd BiasTerm(const Plant& plant, const Eigen::VectorXd& q, const Eigen::VectorXd& v);

/// tau_g(q), the generalized forces of the plant's gravity.
Eigen::VectorXd GravityForces(const Plant& plant, const Eigen::VectorXd& q);

/// The generalized forces of what `options` switches on among joint damping
/// and force elements (gravity and inertia excluded).
Eigen::VectorXd AppliedForces(const Plant& plant, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& v, const DynamicsOptions& options);

/// Each velocity's reflected inertia (0 where no actuator drives it).
Eigen::VectorXd ReflectedInertia(const Plant& plant);

/// vdot for (q, v, tau): the solution of (M + reflected) vdot = tau + tau_g
/// + tau_applied - C v, by the articulated-body algorithm (O(n) in the
/// bodies; M is never formed). Throws std::domain_error when M is singular:
/// a joint with no inertia along its own motion (it moves only massless
/// bodies, or point masses on its axis).
Eigen::VectorXd ForwardDynamics(const Plant& plant, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const Eigen::VectorXd& tau,
                                const DynamicsOptions& options = {});

/// 1/2 v^T M v (rigid bodies; reflected inertia too when options say so).
double KineticEnergy(const Plant& plant, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const DynamicsOptions& options = {});

/// Gravity's potential energy -sum m g . p_WBcm (zero at the world origin)
/// when options.gravity, plus the force elements' (1/2 k stretch^2) when
/// options.force_elements.
double PotentialEnergy(const Plant& plant, const Eigen::VectorXd& q,
                       const DynamicsOptions& options = {});

/// Js_V_ABp_E (6 x nv): the spatial velocity of frame B shifted to point Bp
/// (p_BoBp_B, in B), measured in frame A and expressed in frame E, as
/// J * v (Drake's CalcJacobianSpatialVelocity with respect to v).
Eigen::MatrixXd JacobianSpatialVelocity(const Plant& plant, const Eigen::VectorXd& q,
                                        const BodyFixedFrame& B, const Eigen::Vector3d& p_BoBp_B,
                                        const BodyFixedFrame& A, const BodyFixedFrame& E);

/// Js_v_ABp_E (3 x nv): the bottom three rows of the above
/// (CalcJacobianTranslationalVelocity with respect to v).
Eigen::MatrixXd JacobianTranslationalVelocity(const Plant& plant, const Eigen::VectorXd& q,
                                              const BodyFixedFrame& B,
                                              const Eigen::Vector3d& p_BoBp_B,
                                              const BodyFixedFrame& A, const BodyFixedFrame& E);

/// The bodies a center of mass sums over: all (empty `models`) or those of
/// the given model instances. The world body never counts.
struct CenterOfMass {
  double mass = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // p_WScm
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // v_WScm (zero without v)
  Eigen::MatrixXd jacobian;                            // Js_v_WScm_W, 3 x nv
};

/// The combined center of mass of the selected bodies at (q, v). Throws
/// std::domain_error when their total mass is not positive.
CenterOfMass CalcCenterOfMass(const Plant& plant, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& v, const std::vector<ModelId>& models = {});

}  // namespace mdlc::backend
