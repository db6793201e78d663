// child_reader.h - reads one mesh file by running the mesh reader program in
// a child process and decoding what it sends back (issue 16).
//
// The child gets the path and the limits on its command line and answers on
// standard output (mesh_wire.h). Whatever happens to it becomes an error
// about the file: a crash (a signal), a failure (a non-zero exit status), a
// malformed reply, or not finishing within the mesh-seconds limit, after
// which it is killed. Safe to call from several threads at once.
#pragma once

#include <string>

#include "ir/limits.h"
#include "passes/mesh/triangle_mesh.h"

namespace mdlc::mesh {

/// The mesh in `path`, read by the program `reader` within `limits` and
/// oriented as `axes` says.
MeshOrError LoadMeshInChild(const std::string& reader, const std::string& path,
                            const Limits& limits, const MeshAxes& axes = {});

}  // namespace mdlc::mesh
