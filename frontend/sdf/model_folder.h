// model_folder.h - a Gazebo model folder: a folder whose model.config names
// the file that holds the model (<sdf version="1.9">model.sdf</sdf>), read
// for an <include> URI that names a folder and for a folder given as an
// input (`mdlc tree ~/models/table`).
#pragma once

#include <optional>
#include <string>

#include "frontend/frontend.h"

namespace mdlc::frontend::sdf {

/// The model file of folder `dir`: of the files its model.config names, the
/// one of the newest SDFormat version mdlc reads. nullopt after reporting
/// an error at `loc` (no model.config, or one that names no file).
std::optional<std::string> ModelFileInFolder(const std::string& dir, Loc loc,
                                             FrontendContext& ctx);

}  // namespace mdlc::frontend::sdf
