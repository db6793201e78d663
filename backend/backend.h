// backend.h - the backend's public API: instantiate a resolved ir::Module as a
// multibody plant plus its scene graph, then query or dump it.
//
//   DiagnosticEngine diags;
//   std::optional<backend::CompiledModel> model = backend::Instantiate(module, diags);
//   if (!model) return 1;  // errors are in `diags`
//   Eigen::VectorXd q = backend::DefaultPositions(model->plant);
//   backend::SetJointPositionByName(model->plant, q, "robot::elbow", 0.5);
//   std::string json = backend::EmitPlantJson(*model, q, {});
//
// See build_plant.h for the preconditions on the Module and the errors
// reported when they do not hold.
#pragma once

#include <optional>

#include "backend/compiled_model.h"
#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "backend/plant.h"
#include "backend/plant_json.h"
#include "backend/positions.h"
#include "backend/scene_graph.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

/// Builds the plant and the scene graph; nullopt after reporting errors.
std::optional<CompiledModel> Instantiate(const ir::Module& module, DiagnosticEngine& diags);

}  // namespace mdlc::backend
