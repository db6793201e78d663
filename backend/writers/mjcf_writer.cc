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
// which mdlc's reader restores (ir/original_names.h).
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
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <variant>

#include "backend/collision_filters.h"
#include "backend/kinematics.h"
#include "backend/writers/mjcf_layout.h"
#include "backend/writers/names.h"
#include "backend/writers/unique_names.h"
#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"
#include "ir/overloaded.h"

namespace mdlc::writers {
namespace {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string QuatText(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q = CanonicalQuaternion(R);
  return VectorText(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()));
}

class MjcfWriter : FlatWriterBase {
 public:
  MjcfWriter(const backend::CompiledModel& model, const ir::Module& module,
             const WriteOptions& options, DiagnosticEngine& diags)
      : FlatWriterBase(model, module, options, diags),
        layout_(PlanMjcfBodies(plant_, scene_, options.fuse_fixed)),
        bodies_by_owner_(plant_.bodies.size(), plant_.bodies.size(),
                         [&](size_t b) { return layout_.owner[b].index(); }) {}

  std::string Write() {
    names_.ReportFlattening(m_, "MJCF model", diags_);
    ReportLayout();
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

 private:
  // -- names (FlatWriterBase has the entities' own)

  // -- body frames: X_BL per body

  /// How the joint is written: hinge, slide, ball, free, or nothing.
  enum class Kind { None, Hinge, Slide, Ball, Free };
  Kind KindOf(const PlantJoint& j) const {
    switch (j.type) {
      case ir::JointType::Revolute: return Kind::Hinge;
      case ir::JointType::Prismatic: return Kind::Slide;
      case ir::JointType::Ball: return Kind::Ball;
      case ir::JointType::QuaternionFloating:
        return j.parent.index() == 0 ? Kind::Free : Kind::None;
      default: return Kind::None;
    }
  }

  void ChooseLinkFrames() {
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
  void ReportLayout() {
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
  void WriteBodyTree(BodyId root) {
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

  void WriteOwnContents(BodyId body) {
    WriteGeometries(body);
    WriteSites(body);
    WriteCameras(body);
  }

  /// The default positions of a joint as written (a ball's are dropped).
  Eigen::VectorXd WrittenDefault(const PlantJoint& j, Kind kind, Loc loc) {
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

  /// Opens `body`'s <body> and writes what it holds but its child bodies.
  void OpenBody(BodyId body) {
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

  /// What MJCF cannot hold of a body itself.
  void ReportBodyLosses(BodyId body) {
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

  void WriteInertial(BodyId body) {
    // every body has one: with inertiafromgeom=false, a moving body without
    // one is an error (MuJoCo also rejects a moving body of mass 0)
    // the body's own, with those of the bodies fused into it
    const size_t i = body.index();
    const Transform X_LB = X_BL_[i].inverse();
    const Eigen::Vector3d p = X_LB * layout_.p_BoBcm_B[i];
    const Eigen::Matrix3d I = X_LB.R * layout_.I_BBcm_B[i] * X_LB.R.transpose();
    out_.Open("inertial").Attr("pos", p).Attr("mass", layout_.mass[i]);
    // both read exactly; MuJoCo rejects a fullinertia without positive
    // eigenvalues (a massless body's zero), not the same diaginertia
    if (I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0) {
      out_.Attr("diaginertia", Eigen::Vector3d(I.diagonal()));
    } else {
      out_.Attr("fullinertia", VectorText((Eigen::VectorXd(6) << I(0, 0), I(1, 1), I(2, 2),
                                           I(0, 1), I(0, 2), I(1, 2))
                                              .finished()));
    }
    out_.Close();
  }

  /// Joint `id` in written body `body`, its frame M at X_BM in the body
  /// (the joint's X_CM when `body` is its child).
  void WriteJoint(JointId id, Kind kind, const Eigen::VectorXd& q0, BodyId body,
                  const Transform& X_BM) {
    const PlantJoint& j = plant_.joint(id);
    const Loc loc = JointLoc(id);
    if (kind == Kind::None) return;
    const Transform X_LM = X_BL_[body.index()].inverse() * X_BM;
    if (kind == Kind::Free) {
      if (!j.X_PF.IsIdentity()) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("floating joint '{}' has a frame F other than the world "
                                  "frame; MJCF's free joint moves the body in the world frame, "
                                  "so its coordinates differ",
                                  j.name));
      }
      out_.Open("freejoint");
      if (!j.unnamed) {
        out_.Attr("name", JointName(id));
        // the reader names a free joint after its body
        OriginalName(j.model, j.name, BodyName(j.child));
      }
      out_.Close();
      return;
    }
    out_.Open("joint").Attr("name", JointName(id));
    out_.Attr("type", kind == Kind::Hinge ? "hinge" : kind == Kind::Slide ? "slide" : "ball");
    if (!X_LM.p.isZero(0)) out_.Attr("pos", X_LM.p);
    if (kind != Kind::Ball) {
      out_.Attr("axis", Eigen::Vector3d(X_LM.R * j.axis));
      if (q0[0] != 0) out_.Attr("ref", q0[0]);
      Range(j, loc);
    } else if (std::any_of(j.lower.begin(), j.lower.end(), [](double v) { return v != -kInf; }) ||
               std::any_of(j.upper.begin(), j.upper.end(), [](double v) { return v != kInf; })) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the limits of ball joint '{}' are dropped: mdlc reads no "
                                "MJCF ball joint range",
                                j.name));
    }
    if (!j.damping.empty() && j.damping[0] != 0) out_.Attr("damping", j.damping[0]);
    if (!std::all_of(j.damping.begin(), j.damping.end(),
                     [&](double d) { return d == j.damping[0]; })) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has a different damping per coordinate; MJCF "
                                "holds one, so the first is written",
                                j.name));
    }
    Armature(id, loc);
    Spring(id);
    OriginalName(j.model, j.name, JointName(id));
    out_.Close();
    DropUnwritableLimits(id, loc);
  }

  /// MJCF's range has two finite bounds, and MuJoCo's limit constraints
  /// overflow on bounds near the largest double (Gazebo's "unbounded"
  /// 1.79769e308): a bound beyond kFar is unbounded, and a range with one
  /// unbounded side is written with that side at -+kFar.
  void Range(const PlantJoint& j, Loc loc) {
    constexpr double kFar = 1e10;
    const bool low = j.lower[0] > -kFar, high = j.upper[0] < kFar;
    if (!low && !high) {
      if (j.lower[0] != -kInf || j.upper[0] != kInf) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("joint '{}' has limits [{}, {}], beyond what MuJoCo computes "
                                  "with; it is written unbounded",
                                  j.name, j.lower[0], j.upper[0]));
      }
      return;
    }
    if (low && high && j.lower[0] >= j.upper[0]) {
      // MJCF reads range="0 0" as no range, and rejects an empty one
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has limits [{}, {}]; MJCF's range must be a "
                                "non-empty interval, so it is written unbounded",
                                j.name, j.lower[0], j.upper[0]));
      return;
    }
    if (!low || !high) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' is bounded on one side only ([{}, {}]); MJCF's "
                                "range has two finite bounds, so the other one is written as "
                                "{}",
                                j.name, j.lower[0], j.upper[0], low ? kFar : -kFar));
    }
    out_.Attr("range", VectorText(Eigen::Vector2d(low ? j.lower[0] : -kFar,
                                                  high ? j.upper[0] : kFar)));
  }

  // velocity, acceleration and (without an actuator) effort limits: MJCF
  // joints hold none that mdlc reads
  void DropUnwritableLimits(JointId id, Loc loc) {
    const PlantJoint& j = plant_.joint(id);
    auto bounded = [](const ir::DofValues& lo, const ir::DofValues& hi) {
      for (size_t k = 0; k < lo.size() && k < hi.size(); ++k) {
        if (lo[k] != -kInf || hi[k] != kInf) return true;
      }
      return false;
    };
    if (bounded(j.velocity_lower, j.velocity_upper)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the velocity limits of joint '{}' are dropped: MJCF has none",
                                j.name));
    }
    if (bounded(j.acceleration_lower, j.acceleration_upper)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the acceleration limits of joint '{}' are dropped: MJCF has "
                                "none",
                                j.name));
    }
    const bool actuated = !actuators_by_joint_[id.index()].empty();
    const bool effort =
        std::any_of(j.effort.begin(), j.effort.end(), [](double e) { return e != kInf; });
    if (effort && !actuated) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the effort limit of joint '{}' is dropped: it has no "
                                "actuator to hold it as a forcerange",
                                j.name));
    }
  }

  // an actuator's reflected rotor inertia is the joint's armature; mdlc
  // reads it back as armature / gear^2 for each actuator on the joint
  void Armature(JointId id, Loc loc) {
    std::optional<double> armature;
    for (uint32_t i : actuators_by_joint_[id.index()]) {
      const backend::PlantActuator& a = plant_.actuators[i];
      if (a.rotor_inertia == 0) continue;
      const double reflected = a.rotor_inertia * a.gear_ratio * a.gear_ratio;
      if (armature && *armature != reflected) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("joint '{}' has actuators of different reflected inertia; "
                                  "MJCF's armature holds one, so the first is written",
                                  plant_.joint(id).name));
        continue;
      }
      armature = reflected;
    }
    if (armature) out_.Attr("armature", *armature);
  }

  void Spring(JointId id) {
    for (uint32_t i : springs_by_joint_[id.index()]) {
      const auto& s = std::get<backend::JointSpring>(plant_.force_elements[i]);
      out_.Attr("stiffness", s.stiffness);
      if (s.nominal != 0) out_.Attr("springref", s.nominal);
      written_springs_.insert(id.index());
      return;
    }
  }

  // -- geometry

  // one <mesh> asset per file and scale, shared by the geoms that use them
  // (a link's visual and collision often name the same file)
  void WriteMeshAssets() {
    bool open = false;
    std::map<std::pair<std::string, std::string>, std::string> assets;  // (file, scale) -> name
    for (size_t i = 0; i < scene_.geometries.size(); ++i) {
      const backend::SceneGeometry& g = scene_.geometries[i];
      const Loc loc = GeometryLoc(i);
      const auto* mesh = std::get_if<ir::Mesh>(&g.shape);
      if (!mesh) continue;
      const std::optional<std::string> file =
          assets_.Name(mesh->uri, mesh->resolved, mesh->uri_loc.valid() ? mesh->uri_loc : loc);
      const std::string scale =
          mesh->scale != Eigen::Vector3d::Ones() ? VectorText(mesh->scale) : std::string();
      auto [it, added] =
          assets.emplace(std::pair(file.value_or(""), scale), fmt::format("mesh{}", i));
      mesh_names_[i] = it->second;
      if (!added) continue;
      if (!open) out_.Open("asset");
      open = true;
      out_.Open("mesh").Attr("name", it->second);
      if (file) out_.Attr("file", *file);
      if (!scale.empty()) out_.Attr("scale", scale);
      out_.Close();
    }
    if (open) out_.Close();
  }

  // the geometry of written body `body` and of the bodies fused into it
  void WriteGeometries(BodyId body) {
    for (uint32_t i : Owned(geometries_by_body_, body)) {
      WriteGeometry(i, scene_.geometries[i], GeometryLoc(i));
    }
  }

  /// The entities of `index` on written body `body` or on a body whose
  /// content it holds, in entity order.
  std::vector<uint32_t> Owned(const EntityIndex& index, BodyId body) const {
    std::vector<uint32_t> out;
    for (uint32_t b : bodies_by_owner_[body.index()]) {
      const auto on_b = index[b];
      out.insert(out.end(), on_b.begin(), on_b.end());
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  void WriteGeometry(size_t index, const backend::SceneGeometry& g, Loc loc) {
    const bool visual = g.roles & (ir::kIllustrationRole | ir::kPerceptionRole);
    const bool collision = g.roles & ir::kProximityRole;
    if (!visual && !collision) return;
    if (visual && (g.roles & (ir::kIllustrationRole | ir::kPerceptionRole)) !=
                      (ir::kIllustrationRole | ir::kPerceptionRole)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("geometry '{}' has only the {} role; an MJCF visual geom has "
                                "both illustration and perception",
                                g.name,
                                (g.roles & ir::kIllustrationRole) ? "illustration"
                                                                  : "perception"));
    }
    out_.Open("geom");
    std::string name;
    if (!g.unnamed) out_.Attr("name", name = geom_names_.TakeUnique(Named(g.model, g.name)));
    std::visit(ir::Overloaded{
                   [&](const ir::Box& s) {
                     out_.Attr("type", "box").Attr("size", Eigen::Vector3d(s.size / 2));
                   },
                   [&](const ir::Sphere& s) {
                     out_.Attr("type", "sphere").Attr("size", PositiveSize(g, s.radius, loc));
                   },
                   [&](const ir::Cylinder& s) {
                     out_.Attr("type", "cylinder")
                         .Attr("size", VectorText(Eigen::Vector2d(s.radius, s.length / 2)));
                   },
                   [&](const ir::Capsule& s) {
                     out_.Attr("type", "capsule")
                         .Attr("size", VectorText(Eigen::Vector2d(s.radius, s.length / 2)));
                   },
                   [&](const ir::Ellipsoid& s) {
                     out_.Attr("type", "ellipsoid")
                         .Attr("size", Eigen::Vector3d(s.a, s.b, s.c));
                   },
                   // MuJoCo's plane is infinite; its size only draws it
                   [&](const ir::HalfSpace&) {
                     out_.Attr("type", "plane").Attr("size", "0 0 1");
                   },
                   [&](const ir::Mesh& s) {
                     out_.Attr("type", "mesh").Attr("mesh", mesh_names_[index]);
                     if (s.convex && collision) ConvexLoss(g, loc);
                   },
               },
               g.shape);
    Pose(InWrittenLink(g.body, g.X_BG));
    if (!collision) out_.Attr("contype", "0").Attr("conaffinity", "0");
    if (!visual) out_.Attr("group", "3");  // mdlc and Drake: no visual for group > 2
    if (visual) Appearance(g, loc);
    if (collision) Friction(g, loc);
    if (!g.unnamed) OriginalName(g.model, g.name, name);
    out_.Close();
  }

  /// A collision mesh declared convex (drake:declare_convex): MuJoCo
  /// collides with every mesh's convex hull, so MuJoCo's contact is what
  /// the declaration asks for; but MJCF has no flag to carry it, and mdlc
  /// and Drake read an MJCF mesh back as a mesh, not a convex shape.
  void ConvexLoss(const backend::SceneGeometry& g, Loc loc) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the convex declaration of mesh geometry '{}' is dropped: MuJoCo "
                              "collides with every mesh's convex hull, as declared, but MJCF "
                              "has no flag for it, so the written geom reads back as a plain "
                              "mesh",
                              g.name));
  }

  /// MJCF needs positive sizes; Drake reads a zero-radius sphere as a point
  /// contact, written here as the smallest positive (normal) double.
  double PositiveSize(const backend::SceneGeometry& g, double size, Loc loc) {
    if (size > 0) return size;
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("geometry '{}' has size {}; MJCF needs a positive size, so {} "
                              "is written",
                              g.name, size, std::numeric_limits<double>::min()));
    return std::numeric_limits<double>::min();
  }

  void Appearance(const backend::SceneGeometry& g, Loc loc) {
    if (const ir::Property* diffuse = FindProperty(g, "phong/diffuse")) {
      if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
          rgba && rgba->size() == 4) {
        out_.Attr("rgba", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
      }
    }
    for (const ir::Property& p : g.properties) {
      if (p.key == "phong/diffuse" || !IsAppearanceProperty(p)) continue;
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("illustration property '{}' of geometry '{}' is not written "
                                "(the MJCF writer writes a geom's rgba only)",
                                p.key, g.name));
    }
  }

  void Friction(const backend::SceneGeometry& g, Loc loc) {
    for (const ir::Property& p : g.properties) {
      if (IsAppearanceProperty(p)) continue;
      const auto* v = std::get_if<std::vector<double>>(&p.value);
      if (p.key == "material/coulomb_friction" && v && v->size() == 2) {
        out_.Attr("friction", (*v)[0]);
        if ((*v)[1] != (*v)[0]) {
          diags_.Report(DiagKind::Lossy, loc,
                        fmt::format("geometry '{}' has static friction {} and dynamic {}; "
                                    "MJCF's sliding friction is one, so the static one is "
                                    "written",
                                    g.name, (*v)[0], (*v)[1]));
        }
        continue;
      }
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("proximity property '{}' of geometry '{}' has no MJCF "
                                "spelling; it is dropped",
                                p.key, g.name));
    }
  }

  // -- sites (frames) and cameras

  // the frames of written body `body` and of the bodies fused into it, the
  // fused bodies' own frames, and the constraints' points
  void WriteSites(BodyId body) {
    for (uint32_t f : Owned(frames_by_body_, body)) {
      const backend::PlantFrame& frame = plant_.frames[f];
      if (frame.unnamed) continue;
      const std::string name = site_names_.TakeUnique(Named(frame.model, frame.name));
      out_.Open("site").Attr("name", name);
      Pose(InWrittenLink(frame.body, frame.X_BF));
      OriginalName(frame.model, frame.name, name);
      out_.Close();
    }
    for (BodyId fused : layout_.fused[body.index()]) {
      out_.Open("site").Attr("name", fused_site_names_.at(fused.index()));
      Pose(InWrittenLink(fused, Transform()));
      out_.Close();
    }
    for (const auto& [name, p_LP] : extra_sites_[body.index()]) {
      out_.Open("site").Attr("name", name);
      Pose(p_LP);
      out_.Close();
    }
  }

  void WriteCameras(BodyId body) {
    for (uint32_t i : Owned(cameras_by_body_, body)) {
      const backend::SceneCamera& c = scene_.cameras[i];
      // Drake's camera looks along +z with +y down; MuJoCo's along -z with
      // +y up: a half turn about x between the two
      const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
      out_.Open("camera");
      std::string name;
      if (!c.unnamed) out_.Attr("name", name = camera_names_.TakeUnique(Named(c.model, c.name)));
      Pose(InWrittenLink(c.body, c.X_BC * Transform::FromRotation(flip)));
      out_.Attr("fovy", c.fov_y * 180.0 / M_PI);
      out_.Attr("resolution", fmt::format("{} {}", c.width, c.height));
      // the reader names a camera "model/camera"
      if (!c.unnamed) OriginalName(c.model, c.name, names_.model_name() + "/" + name);
      out_.Close();
    }
  }

  // -- contact excludes: MJCF names no groups, so each filtered pair is an
  // <exclude>, but for two bodies of one welded composite. The composite is
  // written as bodies without joints, one nested in another, which MuJoCo
  // never collides with each other (one weld) and mdlc's reader welds again;
  // a composite of N bodies would otherwise take N(N-1)/2 excludes. The
  // adjacent pairs MuJoCo and mdlc filter anyway are harmless to repeat.
  void WriteContacts() {
    const std::vector<uint32_t> composite = backend::WeldedComposites(plant_);
    auto one_composite = [&](BodyId a, BodyId b) {
      return composite[a.index()] == composite[b.index()];
    };
    std::set<std::pair<size_t, size_t>> excluded;  // written bodies, by index
    auto exclude = [&](BodyId a, BodyId b) {
      if (one_composite(a, b)) return;
      const BodyId x = Owner(a), y = Owner(b);
      if (x != y) excluded.insert({std::min(x.index(), y.index()), std::max(x.index(), y.index())});
    };
    const backend::CollisionFilters& filters = scene_.collision_filters;
    for (const auto& [a, b] : filters.pairs()) exclude(a, b);
    for (const std::vector<BodyId>& set : filters.sets()) {
      if (std::all_of(set.begin(), set.end(), [&](BodyId b) { return one_composite(set[0], b); })) {
        continue;  // a welded composite, or a group within one
      }
      for (size_t i = 0; i < set.size(); ++i) {
        for (size_t k = i + 1; k < set.size(); ++k) exclude(set[i], set[k]);
      }
    }
    for (const auto& [side_a, side_b] : filters.set_pairs()) {
      for (BodyId a : side_a) {
        for (BodyId b : side_b) exclude(a, b);
      }
    }
    if (excluded.empty()) return;
    out_.Open("contact");
    for (const auto& [x, y] : excluded) {
      out_.Open("exclude")
          .Attr("body1", BodyName(BodyId(x)))
          .Attr("body2", BodyName(BodyId(y)))
          .Close();
    }
    out_.Close();
  }

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
                                                      BodyId B, const Transform& X_BQ) {
    const std::string a = site_names_.TakeUnique(fmt::format("constraint{}_P", i));
    const std::string b = site_names_.TakeUnique(fmt::format("constraint{}_Q", i));
    extra_sites_[Owner(A).index()].emplace_back(a, InWrittenLink(A, X_AP));
    extra_sites_[Owner(B).index()].emplace_back(b, InWrittenLink(B, X_BQ));
    return {a, b};
  }

  // sites must exist before the worldbody is written: equalities are
  // prepared up front (see Write), then written here
  void WriteEqualities() {
    bool open = false;
    auto open_once = [&] {
      if (!open) out_.Open("equality");
      open = true;
    };
    for (size_t i = 0; i < plant_.constraints.size(); ++i) {
      const backend::PlantConstraint& c = plant_.constraints[i];
      const Loc loc = ConstraintLoc(i);
      std::visit(
          ir::Overloaded{
              [&](const backend::CouplerConstraint& k) {
                const auto ref0 = WrittenRef(k.joint0), ref1 = WrittenRef(k.joint1);
                if (!ref0 || !ref1) {
                  diags_.Report(DiagKind::Lossy, loc,
                                fmt::format("the coupler of joint '{}' to joint '{}' is "
                                            "dropped: a joint it couples has no MJCF hinge or "
                                            "slide",
                                            plant_.joint(k.joint0).name,
                                            plant_.joint(k.joint1).name));
                  return;
                }
                // MuJoCo: q0 - ref0 = c0 + c1 (q1 - ref1)
                const double c0 = k.offset - *ref0 + k.gear_ratio * *ref1;
                open_once();
                out_.Open("joint")
                    .Attr("joint1", JointName(k.joint0))
                    .Attr("joint2", JointName(k.joint1))
                    .Attr("polycoef", VectorText((Eigen::VectorXd(5) << c0, k.gear_ratio, 0,
                                                  0, 0)
                                                     .finished()))
                    .Close();
              },
              [&](const backend::BallConstraint&) {
                open_once();
                out_.Open("connect")
                    .Attr("site1", constraint_sites_[i].first)
                    .Attr("site2", constraint_sites_[i].second)
                    .Close();
              },
              [&](const backend::DistanceConstraint& k) {
                diags_.Report(DiagKind::Lossy, loc,
                              fmt::format("the distance constraint between bodies '{}' and "
                                          "'{}' is dropped: MuJoCo 3 has no distance equality",
                                          BodyName(k.body_A), BodyName(k.body_B)));
              },
              [&](const backend::WeldConstraint&) {
                open_once();
                out_.Open("weld")
                    .Attr("site1", constraint_sites_[i].first)
                    .Attr("site2", constraint_sites_[i].second)
                    .Close();
              },
              [&](const backend::TendonConstraint&) {},  // WriteTendons
          },
          c.payload);
    }
    if (open) out_.Close();
  }

 public:
  /// Sites the constraints need; called before the bodies are written.
  void PrepareConstraintSites() {
    constraint_sites_.resize(plant_.constraints.size());
    for (size_t i = 0; i < plant_.constraints.size(); ++i) {
      const backend::PlantConstraint& c = plant_.constraints[i];
      if (const auto* k = std::get_if<backend::BallConstraint>(&c.payload)) {
        constraint_sites_[i] =
            ConstraintSites(i, k->body_A, Transform::FromTranslation(k->p_AP), k->body_B,
                            Transform::FromTranslation(k->p_BQ));
      } else if (const auto* w = std::get_if<backend::WeldConstraint>(&c.payload)) {
        constraint_sites_[i] = ConstraintSites(i, w->body_A, w->X_AP, w->body_B, w->X_BQ);
      }
    }
  }

 private:
  // -- tendons: lower <= a.q + offset <= upper as a fixed tendon's range
  // (rigid) or its spring's dead band (springlength, stiffness, damping)

  void WriteTendons() {
    bool open = false;
    for (size_t i = 0; i < plant_.constraints.size(); ++i) {
      const auto* k = std::get_if<backend::TendonConstraint>(&plant_.constraints[i].payload);
      if (!k) continue;
      const Loc loc = ConstraintLoc(i);
      const double lo = k->lower - k->offset, hi = k->upper - k->offset;
      const bool rigid = k->stiffness == kInf;
      std::string why;
      if (rigid && (lo == -kInf || hi == kInf)) why = "a rigid tendon needs two finite bounds";
      if (rigid && lo >= hi) why = "MuJoCo's tendon range must not be empty";
      if (!rigid && k->stiffness <= 0) why = "a tendon spring needs a positive stiffness";
      if (!rigid && (lo == -kInf || hi == kInf)) why = "a tendon spring needs finite lengths";
      for (JointId j : k->joints) {
        const Kind kind = KindOf(plant_.joint(j));
        if (kind != Kind::Hinge && kind != Kind::Slide) why = "a joint of it is not 1-dof";
      }
      if (!why.empty()) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("the tendon constraint is dropped: {}", why));
        continue;
      }
      if (!open) out_.Open("tendon");
      open = true;
      out_.Open("fixed").Attr("name", fmt::format("tendon{}", i));
      if (rigid) {
        out_.Attr("range", VectorText(Eigen::Vector2d(lo, hi)));
        if (k->damping != 0) {
          diags_.Report(DiagKind::Lossy, loc,
                        "the damping of a rigid tendon constraint is dropped");
        }
      } else {
        out_.Attr("stiffness", k->stiffness)
            .Attr("damping", k->damping)
            .Attr("springlength", VectorText(Eigen::Vector2d(lo, hi)));
      }
      for (size_t n = 0; n < k->joints.size(); ++n) {
        out_.Open("joint").Attr("joint", JointName(k->joints[n])).Attr("coef", k->a[n]).Close();
      }
      out_.Close();
    }
    if (open) out_.Close();
  }

  // -- actuators

  void WriteActuators() {
    if (plant_.actuators.empty()) return;
    out_.Open("actuator");
    for (size_t i = 0; i < plant_.actuators.size(); ++i) {
      const backend::PlantActuator& a = plant_.actuators[i];
      const Loc loc = ActuatorLoc(i);
      const PlantJoint& j = plant_.joint(a.joint);
      const Kind kind = KindOf(j);
      if (kind != Kind::Hinge && kind != Kind::Slide) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("actuator '{}' is dropped: its {} joint '{}' is not written "
                                  "as an MJCF hinge or slide",
                                  a.name, ir::JointTypeName(j.type), j.name));
        continue;
      }
      const bool kp = a.kp && *a.kp != 0, kd = a.kd && *a.kd != 0;
      const char* tag = kp ? "position" : kd ? "velocity" : "motor";
      out_.Open(tag).Attr("name", Named(a.model, a.name)).Attr("joint", JointName(a.joint));
      if (a.gear_ratio != 1) out_.Attr("gear", a.gear_ratio);
      if (kp) out_.Attr("kp", *a.kp);
      if (kd) out_.Attr("kv", *a.kd);
      // the joint's effort limit is its actuator's (as the URDF writer does)
      double effort = a.effort_limit;
      if (effort == kInf && !j.effort.empty()) effort = j.effort[0];
      if (effort != kInf) out_.Attr("forcerange", VectorText(Eigen::Vector2d(-effort, effort)));
      OriginalName(a.model, a.name, Named(a.model, a.name));
      out_.Close();
    }
    out_.Close();
  }

  // -- force elements: joint springs are written on their joints

  void WriteForceElements() {
    for (size_t i = 0; i < plant_.force_elements.size(); ++i) {
      const Loc loc = ForceElementLoc(i);
      std::visit(ir::Overloaded{
                     [&](const backend::LinearBushingRpy& k) {
                       diags_.Report(DiagKind::Lossy, loc,
                                     fmt::format("the bushing between frames '{}' and '{}' is "
                                                 "dropped: MJCF has no bushings",
                                                 k.frameA, k.frameC));
                     },
                     [&](const backend::LinearSpringDamper& k) {
                       diags_.Report(DiagKind::Lossy, loc,
                                     fmt::format("the spring-damper between bodies '{}' and "
                                                 "'{}' is dropped: the MJCF writer writes no "
                                                 "spatial tendons",
                                                 BodyName(k.body_A), BodyName(k.body_B)));
                     },
                     [&](const backend::JointSpring& k) {
                       if (written_springs_.count(k.joint.index())) return;
                       diags_.Report(DiagKind::Lossy, JointLoc(k.joint),
                                     fmt::format("the spring of joint '{}' is dropped: the "
                                                 "joint is not written as an MJCF hinge or "
                                                 "slide, or has another spring",
                                                 plant_.joint(k.joint).name));
                     },
                 },
                 plant_.force_elements[i]);
    }
  }

  MjcfBodyLayout layout_;
  EntityIndex bodies_by_owner_;  // each written body's plant bodies: itself, fused, merged
  std::map<size_t, std::string> fused_site_names_;
  std::vector<Transform> X_BL_;
  std::map<size_t, std::vector<BodyId>> children_;
  std::map<size_t, std::string> mesh_names_;
  // MJCF gives each kind of element one namespace for the whole model
  UniqueNames geom_names_, site_names_, camera_names_;
  std::map<size_t, std::vector<std::pair<std::string, Transform>>> extra_sites_;
  std::vector<std::pair<std::string, std::string>> constraint_sites_;
  std::set<size_t> written_springs_;
};

}  // namespace

std::optional<std::string> WriteMjcf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags) {
  return MjcfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
