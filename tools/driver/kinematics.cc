// kinematics.cc - the free functions of mdlc/kinematics.h over the plant a
// Result holds.
#include "mdlc/kinematics.h"

#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "backend/positions.h"
#include "tools/driver/result_access.h"

namespace mdlc {

Eigen::VectorXd DefaultPositions(const Result& result) {
  Eigen::VectorXd q = backend::DefaultPositions(result.plant());
  for (const auto& [name, value] : ResultAccess::joint_positions(result)) {
    backend::SetJointPositionByName(result.plant(), q, name, value);  // checked by Compile
  }
  return q;
}

bool SetJointPosition(const Result& result, Eigen::VectorXd& q, std::string_view name,
                      double value) {
  return backend::SetJointPositionByName(result.plant(), q, name, value);
}

Eigen::MatrixXd MassMatrix(const Result& result, const Eigen::VectorXd& q) {
  return backend::CalcMassMatrix(result.plant(), q);
}

std::vector<Transform> BodyPoses(const Result& result, const Eigen::VectorXd& q) {
  return backend::BodyPosesInWorld(result.plant(), q);
}

std::string PlantJson(const Result& result, const Eigen::VectorXd& q,
                      const backend::PlantJsonOptions& options) {
  return backend::EmitPlantJson(result.model(), q, options);
}

}  // namespace mdlc
