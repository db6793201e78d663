// mesh_axes.h - which way is up in a mesh file, and when mdlc turns it to
// its own Z-up (BEYOND-001).
//
// glTF is Y-up by its specification, and Drake turns glTF meshes to Z-up
// when it reads them (a rotation of +90 degrees about x): mdlc always does
// the same, so a glTF mesh and its OBJ twin land in the same place.
//
// COLLADA files declare their up axis (<asset><up_axis>, Y_UP when absent).
// The viewers whose view of a model mdlc follows both read the vertices as
// written, whatever the file declares: RViz for URDF (its mesh loader tells
// assimp to ignore the declaration) and Gazebo for SDFormat (its COLLADA
// loader never reads it, and with assimp it drops the rotation assimp would
// put on the scene's root). So by default mdlc reads them as written too;
// `--collada-up-axis=apply` turns a file that declares X_UP or Y_UP to Z-up
// instead, for meshes made for tools that honour the declaration.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::mesh {

/// The up axis a mesh file declares; kNone for formats that declare none
/// (OBJ, STL, PLY).
enum class UpAxis : uint8_t { kNone = 0, kX = 1, kY = 2, kZ = 3 };

/// What mdlc does with a COLLADA file's declared up axis.
enum class ColladaUpAxis : uint8_t {
  kAsWritten,  // vertices as written, as RViz and Gazebo read them (default)
  kApply,      // turned from the declared up axis to Z-up
};

/// How mesh files are oriented when read; part of every mesh request.
struct MeshAxes {
  ColladaUpAxis collada = ColladaUpAxis::kAsWritten;
  bool operator==(const MeshAxes&) const = default;
};

/// Whether `path` names a COLLADA file (.dae, in any case).
bool IsCollada(std::string_view path);

/// "X_UP", "Y_UP", "Z_UP" (COLLADA's spelling), or "none".
std::string_view UpAxisName(UpAxis up);
/// The axes `name` names ("as-written", "apply"), for the command line.
std::optional<ColladaUpAxis> ColladaUpAxisFromName(std::string_view name);
std::string_view ColladaUpAxisName(ColladaUpAxis mode);

/// The rotation that takes coordinates whose up axis is `up` to Z-up,
/// keeping the frame right-handed (COLLADA's axis conventions): Y_UP
/// (x, y, z) -> (x, -z, y); X_UP (x, y, z) -> (-y, -z, x). The identity for
/// kZ and kNone.
Eigen::Matrix3d RotationToZUp(UpAxis up);

/// The COLLADA files read that declare an up axis other than Z, for the one
/// note a compile (or a page of `mdlc view`) gives about them: what was done
/// with the first file's axes, and how many more there are.
class OffAxisColladaFiles {
 public:
  /// Counts the file at `path`, read with `declared` axis (turned or not),
  /// if it declares X or Y up; false when it does not count (or was counted).
  bool Add(const std::string& path, UpAxis declared, bool turned);
  bool empty() const { return paths_.empty(); }
  /// The note's text; empty when no file counted.
  std::string Note() const;

 private:
  std::vector<std::string> paths_;
  UpAxis first_declared_ = UpAxis::kNone;
  bool first_turned_ = false;
};

/// The up axis a COLLADA document declares in its <asset>, given the start
/// of its text (the document's own <asset> is its first element); Y, the
/// COLLADA default, when it declares none.
UpAxis ColladaDeclaredUpAxis(std::string_view head);

}  // namespace mdlc::mesh
