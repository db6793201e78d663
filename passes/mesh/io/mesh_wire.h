// mesh_wire.h - what mdlc asks the mesh reader (reader/) and what the reader
// answers: one loaded mesh, or why there is none (issue 16). The program
// takes the request on its command line and answers on standard output; the
// import module takes the same request and answers through a callback.
//
// Request: NAME=VALUE for every limit (ir/limits.h), collada-up-axis=MODE
// (mesh_axes.h), "--", the file's path.
//
// The child runs assimp on an untrusted file and may have been corrupted by
// it, so the parent decodes the reply as untrusted bytes too: every count is
// checked against the bytes that are there, every triangle's vertices
// against the vertex count. Both ends are the same build on the same
// machine, so numbers are in the machine's own byte order; the version
// guards against a reader from another build.
//
// Reply: "MDLCMESH", u32 version, u8 kind, then
//   kind 0 (mesh):  u8 declared up axis, u8 turned to Z-up (0 or 1),
//                   u64 vertex count V, u64 triangle count T,
//                   3V float64 coordinates, 3T int32 vertex indices,
//                   u64 colour count C, C times (u64 first triangle,
//                   4 float64 RGBA), first triangles increasing and < T
//   kind 1 (error): u8 over_limit, u64 length, the message's bytes
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

inline constexpr uint32_t kMeshWireVersion = 3;

/// The part of a request that is not the file: every limit and the axes.
/// What changes a read's result besides the file's bytes.
std::vector<std::string> EncodeMeshSettings(const Limits& limits, const MeshAxes& axes = {});

/// The request to read `path` within `limits`, oriented as `axes` says.
std::vector<std::string> EncodeMeshRequest(const std::string& path, const Limits& limits,
                                           const MeshAxes& axes = {});

/// The file, limits and axes `args` (a request) ask for; a message saying
/// what is wrong when they are not a request.
std::optional<std::string> DecodeMeshRequest(const std::vector<std::string_view>& args,
                                             std::string* path, Limits* limits, MeshAxes* axes);

/// `result` as the reader sends it.
std::string EncodeMeshReply(const MeshOrError& result);

/// The result a reply carries; nullopt, with `*problem` set, when the bytes
/// are not a well-formed reply of this version (truncated, extra bytes,
/// counts that do not fit, a triangle naming a vertex that is not there, a
/// mesh without triangles).
std::optional<MeshOrError> DecodeMeshReply(std::string_view bytes, std::string* problem);

}  // namespace mdlc::mesh
