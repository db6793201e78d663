// compiled_model.h - what the backend produces: the plant and its scene graph.
//
// A CompiledModel owns all its data (names included) and does not refer back
// to the ir::Module it was instantiated from (backend.h: Instantiate).
#pragma once

#include "backend/plant.h"
#include "backend/scene_graph.h"

namespace mdlc::backend {

struct CompiledModel {
  Plant plant;
  SceneGraph scene;
};

}  // namespace mdlc::backend
