// applied_forces.h - the generalized forces and potential energy of joint
// damping and of the plant's force elements (dynamics.h says which):
// joint springs act on their joint's coordinate, linear spring-dampers
// through their end points, and roll-pitch-yaw bushings through their six
// coordinates (rpy and xyz of frame C in frame A), from the potential
// 1/2 k x^2 and the dissipation 1/2 b xdot^2 as Drake's
// LinearBushingRollPitchYaw defines them.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "backend/dynamics.h"
#include "backend/tree_sweep.h"

namespace mdlc::backend {

/// Adds the joint-space forces (damping, joint springs, bushings) into tau
/// and the body forces (spring-dampers; world Plücker, by body, allocated on
/// first use) into f_ext, for what `options` switches on.
void CollectAppliedForces(const Plant& plant, const TreeState& s, const Eigen::VectorXd& q,
                          const Eigen::VectorXd& v, const DynamicsOptions& options,
                          Eigen::VectorXd& tau, std::vector<Vector6d>& f_ext);

/// The same as one generalized-force vector.
Eigen::VectorXd AppliedForcesAt(const Plant& plant, const TreeState& s, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const DynamicsOptions& options);

/// The force elements' potential energy at q.
double ForceElementsPotentialEnergy(const Plant& plant, const TreeState& s,
                                    const Eigen::VectorXd& q);

}  // namespace mdlc::backend
