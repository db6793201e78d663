// positions.h - building a configuration vector q: defaults and joints by name.
//
// Joint names are either scoped ("instance::joint", "a::b::joint") or local
// ("joint"); a local name is accepted when exactly one joint carries it.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "backend/plant.h"

namespace mdlc::backend {

/// The default configuration: each joint's default_positions (which the plant
/// already filled with zeros, or the identity quaternion, where the model gave
/// none), laid out in q order.
Eigen::VectorXd DefaultPositions(const Plant& plant);

enum class JointLookupStatus { Found, NotFound, Ambiguous };
struct JointLookup {
  JointLookupStatus status = JointLookupStatus::NotFound;
  JointId joint;  // valid when Found
};

/// Finds a joint by scoped name, or by local name when that is unambiguous.
JointLookup FindJointByName(const Plant& plant, std::string_view name);

/// Sets the position of the 1-dof joint `name` in q (q.size() ==
/// plant.num_positions). Returns false, leaving q unchanged, when the name is
/// unknown or ambiguous or the joint does not have exactly one position.
bool SetJointPositionByName(const Plant& plant, Eigen::VectorXd& q, std::string_view name,
                            double value);

}  // namespace mdlc::backend
