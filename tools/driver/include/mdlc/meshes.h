// mdlc/meshes.h - the mesh files a compiled model names, as the compile read
// them (its reader, its axes, its cache), for tools that show or count them.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc {

/// How big a mesh file is, as the compile's mesh reader sees it: vertices
/// at the same position count once, polygons count as the triangles they
/// are split into.
struct MeshSize {
  size_t vertices = 0;
  size_t triangles = 0;
  std::string error;  // set when the file could not be read as a mesh
  bool ok() const { return error.empty(); }
};

/// A run of a mesh's triangles in one colour of the file's materials
/// (COLLADA, glTF, OBJ's .mtl): from first_triangle to the next run's first
/// triangle (or the end); RGBA in [0, 1].
struct MeshColor {
  size_t first_triangle = 0;
  Eigen::Vector4d rgba;
};

/// A mesh file's triangles as the compile reads them: unscaled (the
/// geometry's scale is not applied), glTF turned Z-up, COLLADA as
/// Options::meshes.collada_up_axis says.
struct MeshTriangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<MeshColor> colors;  // empty when the file names no colour
  std::string error;  // set when the file could not be read as a mesh
  bool ok() const { return error.empty(); }
};

/// The sizes of mesh files the model names (ir::Mesh::resolved paths), from
/// the meshes the compile read: a file the passes read is not read again,
/// nor one the mesh cache knows; the others are read now, in parallel.
std::vector<MeshSize> MeshSizes(const Result& result,
                                const std::vector<std::string>& resolved_paths);

/// The triangles of those files, read the same way. `axes_note`, when
/// given, gets the note mdlc gives about COLLADA files among them that
/// declare an up axis other than Z (empty when none do).
std::vector<MeshTriangles> ReadMeshes(const Result& result,
                                      const std::vector<std::string>& resolved_paths,
                                      std::string* axes_note = nullptr);

}  // namespace mdlc
