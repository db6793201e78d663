// in_process_reader.h - reads a mesh file in mdlc's own process (issue 16),
// as `--mesh-reader=in-process` asks and as a compile does that finds no
// reader program (mesh_loader.h).
//
// assimp is not linked into mdlc: the reading is done by the import module
// (reader/mdlc_mesh_import.cc), opened with dlopen the first time a mesh is
// read this way and kept open until the process ends. The module takes the
// request and gives the reply that the reader program takes and gives
// (mesh_wire.h), so both ways give the same mesh or the same error; only a
// crash inside assimp is not contained here.
#pragma once

#include <string>

#include "ir/limits.h"
#include "passes/mesh/reader_location.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// The mesh in `path`, read in this process; an error when the file cannot
/// be read or parsed, holds no triangles, or is over the file-size or
/// mesh-vertices limit, and when the import module cannot be opened (it is
/// looked for once per process: reader_location.h). Thread-safe.
MeshOrError LoadMeshInProcess(const std::string& path, const Limits& limits = {},
                              const MeshAxes& axes = {});

/// The import module this process reads meshes with: the one opened, once
/// a mesh was read here, else the one the search finds now (the path empty,
/// and the reason, when none); for `--time-passes`. Opens nothing.
MeshReaderLocation ImportModuleLocation();

}  // namespace mdlc::mesh
