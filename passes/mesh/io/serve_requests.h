// serve_requests.h - the loop a mesh reader worker runs: read a request
// frame, read the mesh it names, write the reply frame, until mdlc closes
// the worker's input (issue 57; worker_frames.h says what travels).
//
// The reader program runs it with assimp's importer; tests run it with
// readers that misbehave on purpose.
#pragma once

#include <functional>
#include <string>

#include "ir/limits.h"
#include "passes/mesh/io/mesh_axes.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

using ReadMeshFunction =
    std::function<MeshOrError(const std::string& path, const Limits& limits, const MeshAxes& axes)>;

/// Answers the request frames read from `in` with reply frames written to
/// `out`, each mesh read by `read`. Returns the exit status the worker
/// should end with: 0 at the end of its input, 2 after a malformed request
/// (said on standard error), 3 when a reply cannot be written.
int ServeMeshRequests(int in, int out, const ReadMeshFunction& read);

}  // namespace mdlc::mesh
