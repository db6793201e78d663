// view.h - `mdlc view` (issue 15): one self-contained HTML page that shows a
// compiled model in 3D, with a slider per joint dof, the kinematic tree, and
// each body's mass properties and source location.
//
// The page carries everything it needs (three.js, the viewer script, the model
// as JSON, meshes as base64 arrays), so it opens offline from a file. Its
// forward kinematics mirror backend/kinematics.cc joint type by joint type,
// so the poses it shows are the plant's (the browser test holds it to that).
#pragma once

#include <string>

#include "mdlc/mdlc.h"

namespace mdlc::tools {

/// Whether this mdlc was built with the viewer (three.js is embedded at build
/// time and needs npm then).
bool ViewerAvailable();

/// The model as the JSON the page embeds: bodies, joints, frames,
/// geometries and meshes (see view.cc). Mesh files that cannot be read are
/// left out, each with a note in "notes". File paths are written relative
/// to the folder of `model_file`, the first file on the command line.
std::string ViewModelJson(const Result& result, const std::string& title,
                          const std::string& model_file);

/// The whole page: `title`, the model JSON, three.js and the viewer script.
/// Precondition: ViewerAvailable() and result.has_model().
std::string ViewPage(const Result& result, const std::string& title,
                     const std::string& model_file);

}  // namespace mdlc::tools
