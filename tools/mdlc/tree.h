// tree.h - `mdlc tree`: each model instance's kinematic tree (issue 15).
#pragma once

#include <string>

#include "backend/compiled_model.h"

namespace mdlc::tools {

/// Per model instance: its body and dof counts, then each root body (with
/// what it hangs on) and the tree below it, one body per line with its
/// joint's name, type, axis, limits and couplers; then the instance's frames.
std::string FormatTree(const backend::CompiledModel& model);
/// The same as JSON: every body with its parent, joint, joint type and dofs.
std::string FormatTreeJson(const backend::CompiledModel& model);

}  // namespace mdlc::tools
