// mesh_export.h - a mesh written back out as a file another reader takes
// (`mdlc convert --copy-assets`): MuJoCo reads STL, OBJ and MSH meshes only,
// so a COLLADA, glTF or PLY mesh goes to an MJCF model as an OBJ of the
// triangles mdlc read from it.
//
// The OBJ holds exactly the TriangleMesh: the vertices as mdlc placed them
// (every mesh of the file's scene merged by its node transforms, turned Z-up
// where mdlc turns it, unscaled) and its triangles, so the target reads the
// shape mdlc's plant has. Materials and normals are not written (MuJoCo's
// geom has one rgba, and it computes its own normals).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "passes/mesh/triangle_mesh.h"

namespace mdlc::mesh {

/// `mesh` as Wavefront OBJ text: one `v` line per vertex (shortest text that
/// reads back as the same double) and one `f` line per triangle (1-based).
std::string ObjText(const TriangleMesh& mesh);

/// The number of triangles a binary STL file declares in its header; nullopt
/// when `head` (the file's first 84 bytes or more) is not one (ASCII STL).
std::optional<uint32_t> BinaryStlTriangleCount(std::string_view head, uint64_t file_size);

}  // namespace mdlc::mesh
