// mdlc/kinematics.h - the compiled plant's kinematics and mass matrix at a
// configuration, and the plant-json dump: free functions of a Result that
// made a model (Result::has_model(); they throw std::logic_error otherwise).
//
//   Eigen::VectorXd q = mdlc::DefaultPositions(result);
//   mdlc::SetJointPosition(result, q, "arm::elbow", 0.5);
//   Eigen::MatrixXd M = mdlc::MassMatrix(result, q);
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "backend/plant_json.h"
#include "ir/transform.h"
#include "mdlc/mdlc.h"

namespace mdlc {

/// Each joint's default position, then Options::model.joint_positions.
Eigen::VectorXd DefaultPositions(const Result& result);

/// Sets 1-dof joint `name` (scoped, or local when unambiguous) in q; false
/// when there is no such joint.
bool SetJointPosition(const Result& result, Eigen::VectorXd& q, std::string_view name,
                      double value);

/// The nv x nv mass matrix at q (size num_positions; else
/// std::invalid_argument), rows and columns in velocity order.
Eigen::MatrixXd MassMatrix(const Result& result, const Eigen::VectorXd& q);

/// X_WB of every body at q, indexed by BodyId (0 is the world).
std::vector<Transform> BodyPoses(const Result& result, const Eigen::VectorXd& q);

/// The plant-json dump at q (the contract: shared/spec/plant-json.md).
std::string PlantJson(const Result& result, const Eigen::VectorXd& q,
                      const backend::PlantJsonOptions& options = {});

}  // namespace mdlc
