// backend.cc - Instantiate: plant, then the scene graph on its bodies.
#include "backend/backend.h"

#include "backend/build_plant.h"
#include "backend/build_scene_graph.h"

namespace mdlc::backend {

std::optional<CompiledModel> Instantiate(const ir::Module& module, DiagnosticEngine& diags) {
  std::optional<Plant> plant = BuildPlant(module, diags);
  if (!plant) return std::nullopt;
  std::optional<SceneGraph> scene = BuildSceneGraph(module, *plant, diags);
  if (!scene) return std::nullopt;
  return CompiledModel{std::move(*plant), std::move(*scene)};
}

}  // namespace mdlc::backend
