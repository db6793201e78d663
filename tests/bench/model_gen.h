// model_gen.h - synthetic URDF models for the load-time benchmarks.
//
// A C++ port of the URDF flavour of bench/gen_models.py in the shared
// directory (../shared from the repository root), so the benchmark needs no
// Python: N links, link_0 welded to the world, link_i (i >= 1) attached to
// its parent by a revolute joint joint_i. Chain: parent(i) = i - 1 (kinematic
// depth N). Tree: parent(i) = (i - 1) / 3. Every link has an offset, rotated
// inertial with a full inertia tensor, one visual (with a material) and one
// collision (box / sphere / cylinder mix); every joint has a rotated origin,
// an axis, limits and dynamics.
//
// The element layout, attribute order, number ranges and "%.6g" formatting
// are the script's, so file sizes and parse costs are comparable (within 1%);
// the random values differ (Python's seeding is not reproduced), so the bytes
// do not. Output is deterministic: same arguments, same bytes.
#pragma once

#include <string>
#include <string_view>

#include "mechanism.h"

namespace mdlc::bench {

/// The URDF text of the `shape` model with `num_links` links (>= 1), named
/// "{shape}_n{num_links}" like the script's files.
std::string GenerateUrdf(Shape shape, int num_links);

}  // namespace mdlc::bench
