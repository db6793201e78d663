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

#include <string>

#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// `mesh` as Wavefront OBJ text: one `v` line per vertex (shortest text that
/// reads back as the same double) and one `f` line per triangle (1-based).
std::string ObjText(const TriangleMesh& mesh);

}  // namespace mdlc::mesh
