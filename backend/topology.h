// topology.h - orders a plant's joints into a tree rooted at the world.
//
// Input: a Plant whose bodies and joints are filled in (ids in range), but
// whose topology fields are not. Output: each body's inbound joint, parent
// and level; `body_order`, `joint_order`; and each joint's q/v slices.
// Tree order is breadth-first by level (Drake's mobilizer order), joints in
// IR order within a level. O(bodies + joints), no recursion.
//
// Earlier passes guarantee that every non-world body is the child of exactly
// one joint and that the joints form a tree; when that does not hold, this
// reports errors (multiple-parents, kinematic-loop, self-joint) at the joints'
// locations and returns false.
#pragma once

#include "backend/plant.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

bool AssignTreeOrder(const ir::Module& module, Plant& plant, DiagnosticEngine& diags);

}  // namespace mdlc::backend
