// model_gen_mjcf.h - the benchmark robot of mechanism.h in MuJoCo XML.
//
// Mirrors write_mjcf() of bench/gen_models.py in the shared directory: radian
// angles, bodies nested as the kinematic tree (a chain of N is N levels
// deep; indentation capped at 16 levels), hinge joints with limits, damping
// and frictionloss, a full inertia at the COM, a visual-only geom
// (contype=conaffinity=0, group 1) and a collision geom (group 3) per body.
#pragma once

#include <string>

#include "mechanism.h"

namespace mdlc::bench {

/// The MJCF text of the `shape` robot with `num_links` links, model name
/// "{shape}_n{num_links}".
std::string GenerateMjcf(Shape shape, int num_links);

}  // namespace mdlc::bench
