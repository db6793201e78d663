// triangle_mesh.h - an indexed triangle mesh, the one mesh type the mesh
// library computes with.
//
// Vertices are in the mesh file's frame, turned Z-up where mdlc turns it
// (mesh_axes.h), in meters once scaled; each triangle
// names three vertices, counter-clockwise seen from outside for a properly
// oriented closed surface.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "passes/mesh/io/mesh_axes.h"

namespace mdlc::mesh {

/// The colour a mesh file gives a run of its triangles: the diffuse (glTF:
/// base) colour of their material, RGBA in [0, 1]. The run goes from
/// `first_triangle` to the next run's first triangle (or the end).
struct TriangleColor {
  uint64_t first_triangle = 0;
  Eigen::Vector4d rgba;
  bool operator==(const TriangleColor&) const = default;
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  /// The up axis the file declares (glTF: Y, by its specification;
  /// COLLADA: its <up_axis>), kNone for formats without one; and whether
  /// the vertices were turned from it to Z-up when read (mesh_axes.h).
  UpAxis declared_up = UpAxis::kNone;
  bool turned_to_z_up = false;
  /// The file's material colours, in triangle order; empty when it names
  /// none (an STL, an OBJ without .mtl), so the model's colour applies. For
  /// drawing only: no computation reads them.
  std::vector<TriangleColor> colors;

  bool empty() const { return triangles.empty(); }
  /// The three corners of triangle `t`.
  const Eigen::Vector3d& corner(size_t t, int k) const { return vertices[triangles[t][k]]; }
};

/// A loaded mesh, or why there is none. Shared: the cache hands the same
/// immutable mesh to every geometry that names the file.
struct MeshOrError {
  std::shared_ptr<const TriangleMesh> mesh;
  std::string error;  // set when `mesh` is null
  bool over_limit = false;  // the error is an input limit (ir/limits.h)
  bool ok() const { return mesh != nullptr; }
};

/// `mesh` with every vertex scaled component-wise by `scale`. A mirroring
/// scale (negative product) reverses the triangles' winding so that a closed
/// mesh stays outward-oriented, as MuJoCo and Drake both do.
TriangleMesh Scaled(const TriangleMesh& mesh, const Eigen::Vector3d& scale);

/// Whether each edge is shared by exactly two triangles (closed) and those
/// two traverse it in opposite directions (consistently oriented).
struct MeshTopology {
  bool closed = false;
  bool consistently_oriented = false;
};
MeshTopology AnalyzeTopology(const TriangleMesh& mesh);

}  // namespace mdlc::mesh
