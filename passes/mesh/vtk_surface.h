// vtk_surface.h - the boundary surface of a tetrahedral VTK volume mesh
// (Drake's compliant-hydroelastic and deformable geometry), as a
// TriangleMesh: what `mdlc convert --copy-assets` writes as OBJ for MuJoCo,
// which reads no VTK file (asset_paths.h).
//
// Reads VTK's legacy ASCII format, DATASET UNSTRUCTURED_GRID, as Drake
// does: POINTS, then CELLS (version 2 and 3's counted lists, or version
// 5's OFFSETS and CONNECTIVITY), every cell a tetrahedron (type 10). A
// face of exactly one tetrahedron is on the boundary; each is wound to face
// away from its tetrahedron, so a closed volume gives an outward surface.
#pragma once

#include <string>

#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// Whether `path` names a VTK file (.vtk, in any case).
bool IsVtk(const std::string& path);

/// The boundary of the tetrahedral mesh in `path`, with only the vertices
/// it uses; an error when the file is not such a mesh.
MeshOrError ReadVtkSurface(const std::string& path);

}  // namespace mdlc::mesh
