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
// Each pair is ordered by the bodies' scoped names and the list is sorted
// and free of duplicates. Cost: linear in bodies and joints plus the number
// of pairs produced.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "backend/plant.h"
#include "backend/scene_graph.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

/// Reports unresolved group references as errors and returns nullopt then.
std::optional<std::vector<std::pair<BodyId, BodyId>>> ComputeCollisionFilters(
    const ir::Module& module, const Plant& plant, const std::vector<SceneGeometry>& geometries,
    DiagnosticEngine& diags);

}  // namespace mdlc::backend
