// pass_registry.h - every built-in pass by name, and the default pipeline.
//
// Registration is an explicit table (pass_registry.cc) rather than static
// constructors, which a static library's linker would be free to drop.
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "passes/pass.h"

namespace mdlc::passes {

struct PassInfo {
  std::string_view name;
  std::string_view description;
  std::function<std::unique_ptr<Pass>()> create;
};

/// All registered passes, in default pipeline order.
const std::vector<PassInfo>& RegisteredPasses();
/// The pass named `name`, or null.
std::unique_ptr<Pass> CreatePass(std::string_view name);

// factories, one per pass file
std::unique_ptr<Pass> CreateResolveFramesPass();
std::unique_ptr<Pass> CreateResolveNamesPass();
std::unique_ptr<Pass> CreateApplyDirectivesPass();
std::unique_ptr<Pass> CreateRestoreNamesPass();
std::unique_ptr<Pass> CreateBuildKinematicTreePass();
std::unique_ptr<Pass> CreateUniqueNamesPass();
std::unique_ptr<Pass> CreateInertiaFromCollisionsPass();
std::unique_ptr<Pass> CreateCheckInertiaPass();
std::unique_ptr<Pass> CreateCheckJointsPass();
std::unique_ptr<Pass> CreateCheckModelElementsPass();
std::unique_ptr<Pass> CreateResolveAssetsPass();
std::unique_ptr<Pass> CreateLoadMeshesPass();
std::unique_ptr<Pass> CreateFitToMeshPass();
std::unique_ptr<Pass> CreateMassFromGeometryPass();

}  // namespace mdlc::passes
