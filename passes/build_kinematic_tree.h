// build_kinematic_tree.h - the build-kinematic-tree pass with --fixed-base
// (Options::model.fixed_base): the driver puts it in the pipeline in place of the
// registered one (pass_registry.h), under the same name.
#pragma once

#include <memory>

#include "passes/pass.h"

namespace mdlc::passes {

/// build-kinematic-tree, welding each body without an inboard joint to the
/// world at its default pose instead of giving it a floating joint.
std::unique_ptr<Pass> CreateFixedBaseKinematicTreePass();

}  // namespace mdlc::passes
