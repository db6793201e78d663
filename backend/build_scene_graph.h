// build_scene_graph.h - the SceneGraph (scene_graph.h) of a resolved module.
//
// Geometries and cameras are registered on the bodies of `plant`, which must
// have been built from the same module. A geometry's property map is its IR
// properties (the last value wins for a repeated key; "renderer/accepting"
// lists are sorted) plus, for an illustration or perception geometry, its
// color as "phong/diffuse" [r, g, b, a] (inline rgba, else its material's)
// and its material's texture as "phong/diffuse_map", unless the IR already
// set those keys. Collision filters come from collision_filters.h.
// Unresolved references are reported as errors and yield nullopt.
#pragma once

#include <optional>

#include "backend/plant.h"
#include "backend/scene_graph.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

std::optional<SceneGraph> BuildSceneGraph(const ir::Module& module, const Plant& plant,
                                          DiagnosticEngine& diags);

}  // namespace mdlc::backend
