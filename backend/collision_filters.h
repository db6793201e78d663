// collision_filters.h - which body pairs never collide.
//
// A pair is listed when both bodies carry proximity geometry and any of:
// - COMMON-054, adjacency (Drake's default filter, which MuJoCo's
//   "filterparent" matches): the bodies are the parent and child of a joint,
//   except joints whose parent is the world and quaternion_floating joints;
// - COMMON-054, welded composites: the bodies are connected through weld
//   joints (the world's composite included);
// - COMMON-051/052, collision filter groups: one body is in group G and the
//   other in group H (possibly G itself) where G ignores H; a group's members
//   include, transitively, those of its member groups (cycles merge).
// The result keeps the declarations (CollisionFilters in scene_graph.h):
// linear in bodies, joints and group members, however many pairs they
// filter; CollisionFilters::Pairs lists the pairs for output.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "backend/plant.h"
#include "backend/scene_graph.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

/// Each body's welded composite (COMMON-054), named by its smallest body
/// index: bodies connected through weld joints share it.
std::vector<uint32_t> WeldedComposites(const Plant& plant);

/// Reports unresolved group references as errors and returns nullopt then.
std::optional<CollisionFilters> ComputeCollisionFilters(
    const ir::Module& module, const Plant& plant, const std::vector<SceneGeometry>& geometries,
    DiagnosticEngine& diags);

}  // namespace mdlc::backend
