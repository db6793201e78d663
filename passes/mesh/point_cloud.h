// point_cloud.h - meshes given as points without triangles: an OBJ of `v`
// lines only, any mesh file whose reader yields points and no faces, and
// MJCF's inline meshes (<mesh vertex="..." face="...">, with or without
// faces). MuJoCo 3.3.8 makes a mesh without faces the convex hull of its
// points (qhull); so does mdlc, once, where the mesh enters the mesh cache,
// so every pass after it sees triangles.
#pragma once

#include <string>
#include <string_view>

#include "ir/entities.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

/// `m` unchanged when it is an error, has triangles or has no points; else
/// the convex hull of its points, or an error naming `what` ("mesh file 'a.obj'") when they
/// are fewer than four or span no volume (MuJoCo refuses those too).
MeshOrError HullOfPointCloud(MeshOrError m, std::string_view what);

/// An inline mesh as a triangle mesh: its faces, or the hull of its points
/// when it has none. The frontend has checked the face indices.
MeshOrError TrianglesOfInlineMesh(const ir::InlineMesh& m, std::string_view what);

}  // namespace mdlc::mesh
