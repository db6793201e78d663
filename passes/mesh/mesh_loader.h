// mesh_loader.h - how mdlc reads a mesh file: in a worker process running
// the mesh reader program, so that a crash, hang or leak inside assimp
// becomes an error about that file instead of taking down the compiler or
// the program embedding it (issues 16 and 57).
//
// The worker runs ImportMesh (assimp_loader.h) and sends the result
// back (mesh_wire.h, worker_frames.h); reader_pool.h starts and watches
// workers; reader_location.h finds the program. Without the program the file is read
// in this process (in_process_reader.h), which gives the same mesh, without
// the protection.
#pragma once

#include <string>

#include "ir/limits.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// Where mesh files are read (`mdlc --mesh-reader=process|in-process`).
enum class MeshReading { kChildProcess, kInProcess };

/// The mesh in `path` (see ImportMesh for what is an error), read by
/// the mesh reader program when one is found, else in this process.
MeshOrError LoadMesh(const std::string& path, const Limits& limits = {},
                     const MeshAxes& axes = {});

}  // namespace mdlc::mesh
