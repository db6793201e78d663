#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {
template <auto Factory>
PassInfo Info() {
  auto pass = Factory();
  return PassInfo{pass->name(), pass->description(), Factory};
}
}  // namespace

const std::vector<PassInfo>& RegisteredPasses() {
  static const std::vector<PassInfo> passes = {
      Info<CreateResolveFramesPass>(),
      Info<CreateResolveNamesPass>(),
      // scene directives need every model's frames, and add joints the
      // checks below must see
      Info<CreateApplyDirectivesPass>(),
      // the names `mdlc convert` wrote under others, before the checks
      // report any of them
      Info<CreateRestoreNamesPass>(),
      Info<CreateCheckJointsPass>(),
      Info<CreateCheckModelElementsPass>(),
      Info<CreateBuildKinematicTreePass>(),
      // after the last pass that adds entities
      Info<CreateUniqueNamesPass>(),
      // meshes: resolved, read (once each), then used for fitted primitives
      // and mass properties, all before check-inertia validates the result
      Info<CreateResolveAssetsPass>(),
      Info<CreateLoadMeshesPass>(),
      Info<CreateFitToMeshPass>(),
      Info<CreateMassFromGeometryPass>(),
      Info<CreateInertiaFromCollisionsPass>(),
      Info<CreateCheckInertiaPass>(),
  };
  return passes;
}

std::unique_ptr<Pass> CreatePass(std::string_view name) {
  for (const auto& info : RegisteredPasses()) {
    if (info.name == name) return info.create();
  }
  return nullptr;
}

}  // namespace mdlc::passes
