// mesh_model_gen.h - the synthetic mesh-heavy model of bench_meshes.cc: an
// MJCF file of N free bodies, each with a mesh geom of its own binary STL
// file and no <inertial>, so that a compile (mdlc's or MuJoCo's) has to read
// every one of the N files to find the bodies' masses.
//
// Body k's mesh is a closed, outward-oriented ellipsoid, triangulated by
// latitude and longitude, with radii and a triangle count (about 500 to
// 1000) of its own: no two files hold the same bytes, so no cache keyed by
// content can answer one file from another.
#pragma once

#include <filesystem>
#include <string>

namespace mdlc::bench {

/// The name of the MJCF file WriteMeshBodiesModel writes for `bodies`.
std::string MeshBodiesModelName(int bodies);

/// Writes dir/m0.stl ... dir/m{bodies-1}.stl and the MJCF model naming them
/// (dir/MeshBodiesModelName(bodies)), making `dir` if needed. Returns the
/// model's path; throws std::runtime_error when a file cannot be written.
std::filesystem::path WriteMeshBodiesModel(const std::filesystem::path& dir, int bodies);

}  // namespace mdlc::bench
