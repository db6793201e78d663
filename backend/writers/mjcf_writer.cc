// mjcf_writer.cc - the compiled model as MJCF, as MuJoCo 3.3 reads it.
//
// MJCF nests bodies by the kinematic tree and puts a body's inbound joint
// inside it, at `pos` and along `axis` in the body's own frame; the body's
// pose in its parent is its pose when every joint is at its `ref`. Each plant
// body B is written with a frame L on it (X_BL): B's own frame, except under
// a ball joint (L has the orientation of the joint's frame M, because MJCF's
// ball rotates about the body's axes) and under a floating joint (L is M, as
// MJCF's free joint moves the body frame itself). For a 1-dof joint with
// default position q0, the body's pose in its parent's frame L_P is
//   X_LpL = X_LpP * X_PF * X_FM(q0) * X_CM^-1 * X_BL,
// the joint's pos is p_LM, its axis R_LM * axis_F and its ref q0: mdlc and
// MuJoCo then move the body as the plant does, at every q. Everything on B
// (inertia, geoms, sites, cameras, constraint points) is re-expressed in L.
//
// Mapping (what cannot be written is a -Wlossy warning at its source):
//   weld -> no joint; revolute -> hinge; prismatic -> slide; ball -> ball;
//   quaternion floating on a root body -> <freejoint/> (its default pose is
//   the body's pose); other joint types -> no joint (fixed at their default
//   positions). Inertia -> <inertial> with diaginertia or fullinertia
//   (every body; a massless one has mass 0, which MuJoCo refuses when the
//   body moves). Geometry -> <geom>: visual and collision by default,
//   visual only with contype=conaffinity=0, collision only with group 3
//   (mdlc and Drake register a group-3 geom for proximity only). Frames ->
//   <site>; cameras -> <camera>; actuators -> <motor>, <position> (kp, kv)
//   or <velocity> (kv), their rotor inertia as the joint's armature (times
//   the gear squared); joint springs -> stiffness and springref; couplers ->
//   <equality><joint polycoef>; ball and weld constraints -> <connect> and
//   <weld> between two sites; tendon constraints -> fixed tendons; collision
//   filters -> <contact><exclude>.
// Several model instances become one model whose names carry their instance
// ("arm/link1"), as the URDF writer does; an element whose written name does
// not give back its scoped name holds a comment naming its instance and name,
// which mdlc's reader restores (ir/syntax/original_name_comment.h).
//
// Which plant bodies become <body> elements is mjcf_layout.h's: a chain of
// massless bodies between hinges and slides (an MJCF body's stacked joints,
// as mdlc reads them) is one <body> with several <joint>s, and with
// --fuse-fixed a welded body is fused into its parent. For a body B with
// joints j1..jn, each 1-dof, at default positions q0_k, the body's pose is
//   X_PB0 = prod_k X_F_k * X_FM_k(q0_k) * X_CM_k^-1
// (F_1 on the parent, F_k on the massless body before joint k), and joint k
// is written at frame M_k's pose in B at the default positions,
//   X_BM_k = (X_CM_k^-1 * prod_{i>k} X_F_i * X_FM_i(q0_i) * X_CM_i^-1)^-1,
// with ref q0_k: MuJoCo turns B about each joint's axis through its pos, in
// B's frame, in order, which is the chain's motion at every q (see
// frontend/mjcf/mjcf_joint.cc, which reads it back into the chain).
//
// This file writes the document and the body tree; mjcf_writer_detail.h
// lists the files that write the rest.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>

#include "backend/kinematics.h"
#include "backend/writers/mjcf_writer_detail.h"

namespace mdlc::writers::mjcf {

std::string QuatText(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q = CanonicalQuaternion(R);
  return VectorText(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()));
}

std::string MjcfWriter::Write() {
  names_.ReportFlattening(m_, "MJCF model", diags_);
  ReportLayout();
  NoteFreeUrdfRoots();
  ChooseLinkFrames();
  PrepareConstraintSites();
  out_.Open("mujoco").Attr("model", names_.model_name());
  out_.Open("compiler")
      .Attr("angle", "radian")
      .Attr("autolimits", "true")
      .Attr("inertiafromgeom", "false")
      .Close();
  out_.Open("option").Attr("gravity", plant_.gravity);
  if (plant_.time_step > 0) out_.Attr("timestep", plant_.time_step);
  out_.Close();
  WriteMeshAssets();
  // the written children of each written body, in body order (parents first)
  for (BodyId b : plant_.body_order) {
    if (b.index() == 0 || !layout_.written(b) || !layout_.parent[b.index()].valid()) continue;
    children_[Owner(layout_.parent[b.index()]).index()].push_back(b);
  }
  out_.Open("worldbody");
  WriteBodyTree(ir::kWorldBody);
  out_.Close();
  WriteContacts();
  WriteEqualities();
  WriteTendons();
  WriteActuators();
  WriteForceElements();
  out_.Close();
  return out_.Finish();
}

MjcfWriter::Kind MjcfWriter::KindOf(const PlantJoint& j) const {
  switch (j.type) {
    case ir::JointType::Revolute: return Kind::Hinge;
    case ir::JointType::Prismatic: return Kind::Slide;
    case ir::JointType::Ball: return Kind::Ball;
    case ir::JointType::QuaternionFloating:
      return j.parent.index() == 0 ? Kind::Free : Kind::None;
    default: return Kind::None;
  }
}

void MjcfWriter::ChooseLinkFrames() {
  X_BL_.assign(plant_.bodies.size(), Transform());
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    const PlantBody& body = plant_.bodies[b];
    if (!body.inbound_joint.valid()) continue;
    const PlantJoint& j = plant_.joint(body.inbound_joint);
    const Kind kind = KindOf(j);
    if (kind == Kind::Free) X_BL_[b] = j.X_CM;
    if (kind == Kind::Ball) X_BL_[b] = Transform::FromRotation(j.X_CM.R);
  }
}

void MjcfWriter::NoteFreeUrdfRoots() {
  // the floating joints the compiler gave to URDF links that no joint holds
  std::vector<JointId> free;
  for (size_t j = 0; j < plant_.joints.size(); ++j) {
    const PlantJoint& joint = plant_.joints[j];
    if (joint.unnamed && KindOf(joint) == Kind::Free &&
        m_.models[joint.model.index()].format == ir::SourceFormat::Urdf) {
      free.push_back(JointId(j));
    }
  }
  if (free.empty()) return;
  const PlantJoint& first = plant_.joint(free[0]);
  diags_.Report(DiagKind::FreeBase, BodyLoc(first.child),
                fmt::format("root link '{}' of URDF model '{}' has no joint to the world, so "
                            "the plant floats it (Drake's rule) and the MJCF gives it a free "
                            "joint{}: it falls in MuJoCo, whose own URDF import would fix it; "
                            "--fixed-base welds {} to the world",
                            plant_.body(first.child).name,
                            m_.ModelName(first.model),
                            free.size() > 1
                                ? fmt::format(" (as {} more such links)", free.size() - 1)
                                : "",
                            free.size() > 1 ? "them" : "it"));
}

void MjcfWriter::ReportLayout() {
  for (size_t b = 1; b < plant_.bodies.size(); ++b) {
    const PlantBody& body = plant_.bodies[b];
    const BodyId owner = layout_.owner[b];
    switch (layout_.role[b]) {
      case MjcfBodyLayout::Role::Written:
        break;
      case MjcfBodyLayout::Role::Merged:
        if (body.unnamed) break;
        diags_.Report(DiagKind::Lossy, BodyLoc(BodyId(b)),
                      fmt::format("body '{}' is massless and moves on joint '{}', which MuJoCo "
                                  "refuses; it is not written, and its joints move body '{}' "
                                  "instead, with the same motion",
                                  body.name, plant_.joint(body.inbound_joint).name,
                                  BodyName(owner)));
        break;
      case MjcfBodyLayout::Role::Fused:
        fused_site_names_[b] = site_names_.TakeUnique(BodyName(BodyId(b)));
        diags_
            .Report(DiagKind::FusedBody, BodyLoc(BodyId(b)),
                    fmt::format("body '{}' is fused into body '{}' (--fuse-fixed): its fixed "
                                "joint '{}' is gone, its mass properties are added to '{}', its "
                                "geometry, frames and cameras are re-posed there, and its own "
                                "frame is kept as site '{}'",
                                body.name, BodyName(owner),
                                plant_.joint(body.inbound_joint).name, BodyName(owner),
                                fused_site_names_[b]));
        ReportBodyLosses(BodyId(b));
        break;
    }
  }
}

void MjcfWriter::WriteBodyTree(BodyId root) {
  WriteOwnContents(root);
  std::vector<std::pair<BodyId, size_t>> open{{root, 0}};  // a body, its next child
  while (!open.empty()) {
    const BodyId body = open.back().first;
    const std::vector<BodyId>& children = children_[body.index()];
    if (open.back().second == children.size()) {
      if (open.size() > 1) out_.Close();  // the root's element is its caller's
      open.pop_back();
      continue;
    }
    const BodyId child = children[open.back().second++];
    OpenBody(child);
    open.emplace_back(child, 0);
  }
}

Eigen::VectorXd MjcfWriter::WrittenDefault(const PlantJoint& j, Kind kind, Loc loc) {
  Eigen::VectorXd q0 = Eigen::Map<const Eigen::VectorXd>(
      j.default_positions.data(), static_cast<Eigen::Index>(j.default_positions.size()));
  if (q0.size() != j.nq) q0 = Eigen::VectorXd::Zero(j.nq);
  if (kind == Kind::None && j.type != ir::JointType::Weld) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("{} joint '{}' has no MJCF form{}; body '{}' is written fixed "
                              "to its parent at the joint's default position",
                              ir::JointTypeName(j.type), j.name,
                              j.type == ir::JointType::QuaternionFloating
                                  ? " (its parent is not the world)"
                                  : "",
                              BodyName(j.child)));
  }
  if (kind == Kind::Ball && !q0.isZero(0)) {  // the plant's ball: roll-pitch-yaw
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the default orientation of ball joint '{}' is not written "
                              "(an MJCF ball joint starts at the body's pose)",
                              j.name));
    q0.setZero();
  }
  return q0;
}

void MjcfWriter::OpenBody(BodyId body) {
  const std::vector<JointId>& chain = layout_.joints[body.index()];
  const size_t n = chain.size();
  std::vector<Kind> kinds(n);
  std::vector<Eigen::VectorXd> q0(n);
  // X_{k-1,k}: the pose of the child of joint k in its parent at the
  // default positions; the first parent is layout_.parent
  std::vector<Transform> step(n);
  for (size_t k = 0; k < n; ++k) {
    const PlantJoint& j = plant_.joint(chain[k]);
    kinds[k] = KindOf(j);
    q0[k] = WrittenDefault(j, kinds[k], JointLoc(chain[k]));
    step[k] = j.X_PF * backend::JointPose(j, q0[k]) * j.X_CM.inverse();
  }
  // X_PB0, then in the written parent's frame L_P
  Transform X_PB0 = step[0];
  for (size_t k = 1; k < n; ++k) X_PB0 = X_PB0 * step[k];
  const BodyId parent = layout_.parent[body.index()];
  const Transform X_LpL = X_BL_[Owner(parent).index()].inverse() * InOwner(parent, X_PB0) *
                          X_BL_[body.index()];
  out_.Open("body").Attr("name", BodyName(body));
  Pose(X_LpL);
  OriginalName(plant_.body(body).model, plant_.body(body).name, BodyName(body));
  ReportBodyLosses(body);
  WriteInertial(body);
  // each joint at its frame M_k in B: X_BM_k = (X_CM_k^-1 * X_{C_k,B})^-1
  Transform X_CkB;  // identity for the last joint
  std::vector<Transform> X_BM(n);
  for (size_t k = n; k-- > 0;) {
    const PlantJoint& j = plant_.joint(chain[k]);
    X_BM[k] = k + 1 == n ? j.X_CM : X_CkB.inverse() * j.X_CM;
    X_CkB = step[k] * X_CkB;
  }
  for (size_t k = 0; k < n; ++k) WriteJoint(chain[k], kinds[k], q0[k], body, X_BM[k]);
  WriteOwnContents(body);
}

void MjcfWriter::ReportBodyLosses(BodyId body) {
  const PlantBody& b = plant_.body(body);
  if (b.deformable) {
    diags_.Report(DiagKind::Lossy, BodyLoc(body),
                  fmt::format("body '{}' is deformable; it is written as a massless rigid "
                              "body",
                              b.name));
  }
  if (b.surface_velocity_axis) {
    diags_.Report(DiagKind::Lossy, BodyLoc(body),
                  fmt::format("the surface velocity axis of body '{}' is dropped: MJCF has "
                              "none",
                              b.name));
  }
}

void MjcfWriter::WriteInertial(BodyId body) {
  // every body has one: with inertiafromgeom=false, a moving body without
  // one is an error (MuJoCo also rejects a moving body of mass 0)
  // the body's own, with those of the bodies fused into it
  const size_t i = body.index();
  const Transform X_LB = X_BL_[i].inverse();
  const Eigen::Vector3d p = X_LB * layout_.p_BoBcm_B[i];
  const Eigen::Matrix3d I = X_LB.R * layout_.I_BBcm_B[i] * X_LB.R.transpose();
  out_.Open("inertial").Attr("pos", p).Attr("mass", layout_.mass[i]);
  if (I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0) {
    out_.Attr("diaginertia", Eigen::Vector3d(I.diagonal()));
  } else {
    // the principal axes, found here in double precision: MuJoCo
    // diagonalises a fullinertia itself with an iteration that stops early
    // (mjuu_eig3), leaving entries off by up to 1e-5 of their size
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(I);
    Eigen::Matrix3d R = principal.eigenvectors();
    if (R.determinant() < 0) R.col(2) = -R.col(2);  // a rotation, not a reflection
    out_.Attr("quat", QuatText(R)).Attr("diaginertia", Eigen::Vector3d(principal.eigenvalues()));
  }
  out_.Close();
}

std::vector<uint32_t> MjcfWriter::Owned(const EntityIndex& index, BodyId body) const {
  std::vector<uint32_t> out;
  for (uint32_t b : bodies_by_owner_[body.index()]) {
    const auto on_b = index[b];
    out.insert(out.end(), on_b.begin(), on_b.end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace mdlc::writers::mjcf

namespace mdlc::writers {

std::optional<std::string> WriteMjcf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags) {
  return mjcf::MjcfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
