// assimp_loader.h - reads a mesh file into one TriangleMesh through assimp
// (BEYOND-001): OBJ (a missing .mtl is fine), STL (ASCII and binary), DAE,
// glTF/GLB, PLY, and whatever else assimp reads.
//
// Every mesh of the file's scene is merged, each placed by its node's
// transform. Vertices at exactly the same position are merged, so that
// formats that store triangle soups (STL) or split vertices by normal still
// give a connected surface whose closedness can be checked. glTF, and
// COLLADA when asked, are turned Z-up (mesh_axes.h). The result is
// unscaled: consumers apply the geometry's scale (Scaled()).
//
// assimp has memory errors and hangs on malformed files that mdlc cannot
// mend, so this runs in the process of the mesh reader program
// (reader/mdlc_mesh_reader.cc), where a crash is contained (issue 16).
// When mdlc reads meshes in its own process (asked to, or without the
// program: mesh_loader.h) it runs in the import module
// (reader/mdlc_mesh_import.cc), which mdlc opens on first use: neither mdlc
// nor the libraries link assimp, whose loading and symbol binding were most
// of the start-up time of every mdlc process.
#pragma once

#include <string>

#include "ir/limits.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// The mesh in `path`, read by assimp in this process and turned Z-up as
/// `axes` and the file's format say (mesh_axes.h); an error when the file
/// cannot be read or parsed, holds no triangles, or is over the file-size or
/// mesh-vertices limit.
MeshOrError ImportMesh(const std::string& path, const Limits& limits = {},
                       const MeshAxes& axes = {});

}  // namespace mdlc::mesh
