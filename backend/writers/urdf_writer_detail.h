// urdf_writer_detail.h - the URDF writer's class, shared by the files that
// write its parts (see urdf_writer.cc for the mapping from plant to URDF):
//   urdf_writer.cc          the <robot>, its links and their geometry
//   urdf_joints.cc          joints: limits, dynamics, mimics; transmissions
//   urdf_drake_elements.cc  frames, constraints, force elements, collision
//                           filter groups, and the cameras URDF cannot hold
#pragma once

#include <fmt/format.h>

#include <Eigen/Core>
#include <limits>
#include <set>
#include <string>
#include <string_view>

#include "backend/writers/unique_names.h"
#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"

namespace mdlc::writers::urdf {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// URDF readers other than Drake's (urdfdom) need finite numbers in a
/// <limit>: an unbounded side is written as the largest double.
double FiniteLimit(double value);

class UrdfWriter : FlatWriterBase {
 public:
  UrdfWriter(const backend::CompiledModel& model, const ir::Module& module,
             const WriteOptions& options, DiagnosticEngine& diags)
      : FlatWriterBase(model, module, options, diags), plain_(options.plain) {}

  std::string Write();

 private:
  // -- frames: X_BL, the pose of body B's link frame L in B

  Transform LinkInBody(BodyId body) const {
    const PlantBody& b = plant_.body(body);
    if (!b.inbound_joint.valid()) return {};
    return plant_.joint(b.inbound_joint).X_CM;
  }
  /// X_LA for a pose X_BA given in body B.
  Transform InLink(BodyId body, const Transform& X_BA) const {
    return LinkInBody(body).inverse() * X_BA;
  }

  void Origin(const Transform& X) {
    if (X.IsIdentity()) return;
    out_.Open("origin").Attr("xyz", X.p).Attr("rpy", RpyFromRotation(X.R)).Close();
  }

  // -- links

  bool NeedsWorldLink() const;
  /// Plain URDF (--plain) holds one tree: when the free bodies and the
  /// world would be several roots, the world link is written with a
  /// floating joint to each free body.
  bool FloatsFreeRoots() const;
  static bool IsFreeRoot(const PlantJoint& j) { return IsFloating(j) && j.parent.index() == 0; }

  void WriteLink(BodyId body);

  // -- geometry

  void WriteGeometry(const backend::SceneGeometry& g, Loc loc);

  void Shape(const backend::SceneGeometry& g, Loc loc, bool collision);
  /// Plain URDF: a capsule or ellipsoid as the primitive that bounds it.
  void PlainShape(const backend::SceneGeometry& g, Loc loc);

  void Material(const backend::SceneGeometry& g, Loc loc);

  // -- joints

  void WriteJoint(JointId id);

  static bool IsIdentityPose(const PlantJoint& j);

  void Dynamics(const PlantJoint& j, Loc loc);

  /// The effort limit URDF writes: an actuated joint's limit is its
  /// actuator's (Drake reads an actuator's effort from its joint's <limit>).
  double EffortOf(JointId id, const PlantJoint& j, Loc loc);

  void Limits(JointId id, const PlantJoint& j, Loc loc);

  // a coupler whose follower is this joint becomes its <mimic> (EXT-010)
  void Mimic(JointId id);

  // -- frames, actuators, constraints, force elements, filters, cameras

  void WriteFrames();

  void WriteTransmissions();

  /// p_LP for a point given in body B.
  Eigen::Vector3d PointInLink(BodyId body, const Eigen::Vector3d& p_BP) const {
    return InLink(body, Transform::FromTranslation(p_BP)).p;
  }

  void BodiesAndPoints(std::string_view prefix, BodyId A, BodyId B, const Eigen::Vector3d& p_AP,
                       const Eigen::Vector3d& p_BQ);

  void WriteConstraints();

  std::string FrameOrLink(const std::string& scoped) const;
  /// A frame's name, unique among the robot's links and frames: a frame of
  /// another instance (or of the world) that repeats a name takes its
  /// instance's prefix, then a number (reported).
  std::string FrameName(const backend::PlantFrame& frame, Loc loc);

  void WriteForceElements();

  // one group per declaration (two for a group that ignores another):
  // exactly the plant's filters, in proportion to the declarations
  void WriteCollisionFilters();

  void WriteCameras();

  const bool plain_;  // WriteOptions::plain
  bool floats_free_roots_ = false;
  std::set<size_t> mimicked_, mimic_written_;
  UniqueNames frame_names_;  // links' and frames' names
};

}  // namespace mdlc::writers::urdf
