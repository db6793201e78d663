// stats.h - `mdlc stats`: mass properties and counts (issue 15), as
// `gz sdf --inertial-stats` gives for SDFormat models, for every format and
// for worlds too.
#pragma once

#include <string>

#include "mdlc/mdlc.h"
#include "mdlc/meshes.h"

namespace mdlc::tools {

/// Per body: mass, center of mass and inertia about it in the body frame, at
/// full precision, and whether they could be physical; per model instance
/// and in total: mass, center of mass in the world at the default
/// configuration, and counts of bodies, joints by type, geometries by role
/// and shape, actuators, constraints and cameras; per mesh geometry, its
/// file's vertex and triangle counts, and per instance and in total their
/// sums (mdlc::MeshSizes: the meshes the compile read, the rest read now).
/// `model` is result.model(), or the part of it a failed compile made
/// (partial_model.h).
std::string FormatStats(const backend::CompiledModel& model, const Result& result);
std::string FormatStatsJson(const backend::CompiledModel& model, const Result& result);

}  // namespace mdlc::tools
