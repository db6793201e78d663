// build_plant.h - turns a resolved ir::Module into a Plant (plant.h).
//
// Preconditions, guaranteed by the passes before the backend: every Ref is
// resolved; every non-world body is the child of exactly one joint; the
// joints form a tree rooted at the world; inertials are physically valid;
// per-coordinate joint vectors are empty or of the joint's size. BuildPlant
// still checks what it relies on and reports a violated precondition as an
// error at the entity's location (unknown-reference, multiple-parents,
// kinematic-loop, self-joint, zero-axis, bad-limits, bad-value), returning
// nullopt; it never crashes on such input.
//
// Mass properties are re-expressed about the COM in the body frame:
// com = X_BI.p and I_B = R_BI * I_I * R_BI^T; a body without an inertial is
// massless. Joint vectors are normalized as PlantJoint describes. Last, the
// MJCF gains that need the finished plant's mass matrix at qpos0 are applied
// (inertia_scaled_gains.h).
#pragma once

#include <optional>

#include "backend/plant.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

std::optional<Plant> BuildPlant(const ir::Module& module, DiagnosticEngine& diags);

}  // namespace mdlc::backend
