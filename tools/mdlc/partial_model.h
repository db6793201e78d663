// partial_model.h - the plant of a compile that failed, as far as it got, for
// the inspection commands (tree, stats, graph): check_urdf prints a robot's
// tree whose meshes it cannot find, and so does `mdlc tree`, with the errors
// reported and exit status 1.
#pragma once

#include <functional>
#include <optional>

#include "cli_compile.h"
#include "mdlc/mdlc.h"

namespace mdlc::cli {

/// The compiled model when `result` has one; otherwise the plant built from
/// the IR the passes left, when that IR is whole enough for one (every
/// reference resolved, a tree, unique names: the passes failed at the
/// assets, e.g. a mesh in an unknown package), kept until the next call;
/// null when it is not. Meshes that were not found are kept without a file;
/// mass properties the failed passes would have computed are missing.
const backend::CompiledModel* ModelAsFarAsCompiled(const Result& result);

/// What tree, stats and graph share: compiles the flags' files, hands
/// `print` the model as far as it compiled (with a note on standard error
/// naming `what` when the compile failed), and returns the exit status:
/// print's when the compile succeeded, else 1 after "N errors generated."
int PrintAsFarAsCompiled(const CompileFlags& flags, const char* what,
                         const std::function<int(const backend::CompiledModel&, const Result&)>& print);

}  // namespace mdlc::cli
