// filter_declarations.h - a scene's collision filters in the form the URDF
// and SDFormat writers write them: one filter group per declaration (a
// joint's pair, a welded composite, a group that ignores itself) and two
// per pair of sets (a group that ignores another), never one per filtered
// pair. A composite of N welded links is one group of N members, where a
// list of its pairs would be N(N-1)/2 groups (issue 16).
#pragma once

#include <functional>
#include <vector>

#include "backend/scene_graph.h"

namespace mdlc::writers {

/// Bodies whose collisions a filter group written for it removes: every two
/// of `members` when `ignored` is empty (a group that ignores itself), else
/// every body of `members` with every body of `ignored` (a body never with
/// itself).
struct FilterDeclaration {
  std::vector<BodyId> members;
  std::vector<BodyId> ignored;

  bool ignores_itself() const { return ignored.empty(); }
};

/// The scene's filter declarations without the world, which no filter group
/// can name: `on_world(body)` is called once for each body whose filter
/// with the world is left out, in declaration order. Left out as well: a
/// set declared twice, a pair within a set (a weld inside its composite)
/// and declarations left filtering no pair. Together the declarations
/// filter exactly the pairs of `filters.Pairs` that do not name the world.
std::vector<FilterDeclaration> DeclarationsWithoutWorld(
    const backend::CollisionFilters& filters, const std::function<void(BodyId)>& on_world);

}  // namespace mdlc::writers
