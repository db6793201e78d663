// plant_json.h - the plant-json dump (schema "mdlc-plant/1").
//
// The contract is ../shared/spec/plant-json.md. Keys are printed in the
// spec's order (schema, model_instances, bodies, joints, frames, geometries,
// actuators, collision_filters, constraints, cameras, dofs, mass_matrix,
// reflected_inertia, then force_elements, gravity, time_step); entities in
// IR order (bodies without the world), dofs in velocity order. Poses,
// axes and the mass matrix are evaluated at `q`. The output is
// byte-deterministic: the same model and q give the same bytes.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "backend/compiled_model.h"

namespace mdlc::backend {

struct PlantJsonOptions {
  /// Above this many dofs, mass_matrix and reflected_inertia are left out...
  size_t mass_matrix_max_dofs = 1000;
  /// ...unless this is set (`--mass-matrix`).
  bool force_mass_matrix = false;
};

/// Requires q.size() == model.plant.num_positions (else std::invalid_argument).
std::string EmitPlantJson(const CompiledModel& model, const Eigen::VectorXd& q,
                          const PlantJsonOptions& options = {});

}  // namespace mdlc::backend
