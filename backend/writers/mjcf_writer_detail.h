// mjcf_writer_detail.h - the MJCF writer's class, shared by the files that
// write its parts (see mjcf_writer.cc for the mapping from plant to MJCF):
//   mjcf_writer.cc       the <mujoco> document, body frames and the body tree,
//                        inertials
//   mjcf_joints.cc       joints: ranges, armature, springs; actuators and the
//                        force elements MJCF cannot hold
//   mjcf_geometry.cc     mesh assets, geoms, sites and cameras
//   mjcf_constraints.cc  contact excludes, equalities and fixed tendons
#pragma once

#include <fmt/format.h>

#include <Eigen/Core>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "backend/writers/mjcf_layout.h"
#include "backend/writers/unique_names.h"
#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"

namespace mdlc::writers::mjcf {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// MJCF's quat attribute for rotation R: "w x y z".
std::string QuatText(const Eigen::Matrix3d& R);

class MjcfWriter : FlatWriterBase {
 public:
  MjcfWriter(const backend::CompiledModel& model, const ir::Module& module,
             const WriteOptions& options, DiagnosticEngine& diags)
      : FlatWriterBase(model, module, options, diags),
        layout_(PlanMjcfBodies(plant_, scene_, options.fuse_fixed)),
        bodies_by_owner_(plant_.bodies.size(), plant_.bodies.size(),
                         [&](size_t b) { return layout_.owner[b].index(); }) {}

  std::string Write();

 private:
  // -- names (FlatWriterBase has the entities' own)

  // -- body frames: X_BL per body

  /// How the joint is written: hinge, slide, ball, free, or nothing.
  enum class Kind { None, Hinge, Slide, Ball, Free };
  Kind KindOf(const PlantJoint& j) const;

  void ChooseLinkFrames();
  Transform InLink(BodyId body, const Transform& X_BA) const {
    return X_BL_[body.index()].inverse() * X_BA;
  }

  // -- the written bodies (mjcf_layout.h)

  /// The written body that holds body b's content.
  BodyId Owner(BodyId b) const { return layout_.owner[b.index()]; }
  /// X_BA given in body b, as a pose in b's owner.
  Transform InOwner(BodyId b, const Transform& X_BA) const {
    if (layout_.role[b.index()] != MjcfBodyLayout::Role::Fused) return X_BA;
    return layout_.X_OB[b.index()] * X_BA;
  }
  /// X_BA given in body b, in the frame L of the <body> that holds it.
  Transform InWrittenLink(BodyId b, const Transform& X_BA) const {
    return InLink(Owner(b), InOwner(b, X_BA));
  }

  /// What the layout merged away (named bodies only: a massless body mdlc
  /// made between an MJCF body's stacked joints comes back as it was) and
  /// fused (--fuse-fixed, a note per body).
  void ReportLayout();
  /// A note when a URDF's root link floats: the plant floats a link no joint
  /// holds (Drake's rule), so the MJCF gives it a free joint, where MuJoCo's
  /// own URDF import would have fixed it (--fixed-base welds it instead).
  void NoteFreeUrdfRoots();
  Eigen::Vector3d PointInLink(BodyId body, const Eigen::Vector3d& p_BP) const {
    return InLink(body, Transform::FromTranslation(p_BP)).p;
  }

  void Pose(const Transform& X) {
    if (!X.p.isZero(0)) out_.Attr("pos", X.p);
    if (!X.R.isIdentity(0)) out_.Attr("quat", QuatText(X.R));
  }

  // -- bodies

  /// `root`'s contents and its written descendants, depth first. A loop,
  /// not recursion: a chain of 10,000 links nests 10,000 bodies deep, past
  /// what the stack holds of recursive calls.
  void WriteBodyTree(BodyId root);

  void WriteOwnContents(BodyId body) {
    WriteGeometries(body);
    WriteSites(body);
    WriteCameras(body);
  }

  /// The default positions of a joint as written (a ball's are dropped).
  Eigen::VectorXd WrittenDefault(const PlantJoint& j, Kind kind, Loc loc);

  /// Opens `body`'s <body> and writes what it holds but its child bodies.
  void OpenBody(BodyId body);

  /// What MJCF cannot hold of a body itself.
  void ReportBodyLosses(BodyId body);

  void WriteInertial(BodyId body);

  /// Joint `id` in written body `body`, its frame M at X_BM in the body
  /// (the joint's X_CM when `body` is its child).
  void WriteJoint(JointId id, Kind kind, const Eigen::VectorXd& q0, BodyId body,
                  const Transform& X_BM);

  /// MJCF's range has two finite bounds, and MuJoCo's limit constraints
  /// overflow on bounds near the largest double (Gazebo's "unbounded"
  /// 1.79769e308): a bound beyond kFar is unbounded, and a range with one
  /// unbounded side is written with that side at -+kFar.
  void Range(const PlantJoint& j, Loc loc);

  // velocity, acceleration and (without an actuator) effort limits: MJCF
  // joints hold none that mdlc reads
  void DropUnwritableLimits(JointId id, Loc loc);

  // an actuator's reflected rotor inertia is the joint's armature; mdlc
  // reads it back as armature / gear^2 for each actuator on the joint
  void Armature(JointId id, Loc loc);

  void Spring(JointId id);

  // -- geometry

  // one <mesh> asset per file and scale, shared by the geoms that use them
  // (a link's visual and collision often name the same file)
  void WriteMeshAssets();
  /// Geometry `index`'s MJCF inline mesh as a <mesh> with vertex (and
  /// face) lists, once per (mesh, scale) in `assets`.
  void WriteInlineMesh(size_t index, const ir::Mesh& mesh,
                       std::map<std::pair<std::string, std::string>, std::string>& assets,
                       bool* open);

  // the geometry of written body `body` and of the bodies fused into it
  void WriteGeometries(BodyId body);

  /// The entities of `index` on written body `body` or on a body whose
  /// content it holds, in entity order.
  std::vector<uint32_t> Owned(const EntityIndex& index, BodyId body) const;

  void WriteGeometry(size_t index, const backend::SceneGeometry& g, Loc loc);

  /// A collision mesh declared convex (drake:declare_convex): MuJoCo
  /// collides with every mesh's convex hull, so MuJoCo's contact is what
  /// the declaration asks for; but MJCF has no flag to carry it, and mdlc
  /// and Drake read an MJCF mesh back as a mesh, not a convex shape.
  void ConvexLoss(const backend::SceneGeometry& g, Loc loc);

  /// MJCF needs positive sizes; Drake reads a zero-radius sphere as a point
  /// contact, written here as the smallest positive (normal) double.
  double PositiveSize(const backend::SceneGeometry& g, double size, Loc loc);

  void Appearance(const backend::SceneGeometry& g, Loc loc);

  void Friction(const backend::SceneGeometry& g, Loc loc);

  // -- sites (frames) and cameras

  // the frames of written body `body` and of the bodies fused into it, the
  // fused bodies' own frames, and the constraints' points
  void WriteSites(BodyId body);

  void WriteCameras(BodyId body);

  // -- contact excludes: MJCF names no groups, so each filtered pair is an
  // <exclude>, but for two bodies of one welded composite. The composite is
  // written as bodies without joints, one nested in another, which MuJoCo
  // never collides with each other (one weld) and mdlc's reader welds again;
  // a composite of N bodies would otherwise take N(N-1)/2 excludes. The
  // adjacent pairs MuJoCo and mdlc filter anyway are harmless to repeat.
  void WriteContacts();

  // -- equality constraints

  /// The written default position (ref) of a 1-dof joint; nullopt when the
  /// joint is not written as a hinge or slide.
  std::optional<double> WrittenRef(JointId id) const {
    const PlantJoint& j = plant_.joint(id);
    const Kind kind = KindOf(j);
    if (kind != Kind::Hinge && kind != Kind::Slide) return std::nullopt;
    return j.default_positions.empty() ? 0.0 : j.default_positions[0];
  }

  /// Sites for a constraint's two points: MJCF's site forms of connect and
  /// weld name both points exactly (the body forms complete one at qpos0).
  std::pair<std::string, std::string> ConstraintSites(size_t i, BodyId A, const Transform& X_AP,
                                                      BodyId B, const Transform& X_BQ);

  // sites must exist before the worldbody is written: equalities are
  // prepared up front (see Write), then written here
  void WriteEqualities();

  /// Sites the constraints need; called before the bodies are written.
  void PrepareConstraintSites();

  // -- tendons: lower <= a.q + offset <= upper as a fixed tendon's range
  // (rigid) or its spring's dead band (springlength, stiffness, damping)

  void WriteTendons();

  // -- actuators

  void WriteActuators();

  // -- force elements: joint springs are written on their joints

  void WriteForceElements();

  MjcfBodyLayout layout_;
  EntityIndex bodies_by_owner_;  // each written body's plant bodies: itself, fused, merged
  std::map<size_t, std::string> fused_site_names_;
  std::vector<Transform> X_BL_;
  std::map<size_t, std::vector<BodyId>> children_;
  std::map<size_t, std::string> mesh_names_;
  // geometries whose mesh MuJoCo cannot read and mdlc could not convert:
  // not written (MuJoCo refuses a model naming such a file), with why
  std::map<size_t, std::string> unconvertible_meshes_;
  // MJCF gives each kind of element one namespace for the whole model
  UniqueNames geom_names_, site_names_, camera_names_;
  std::map<size_t, std::vector<std::pair<std::string, Transform>>> extra_sites_;
  std::vector<std::pair<std::string, std::string>> constraint_sites_;
  std::set<size_t> written_springs_;};

}  // namespace mdlc::writers::mjcf
