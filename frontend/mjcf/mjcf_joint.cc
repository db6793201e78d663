// mjcf_joint.cc - a body's joints (MJCF-021..024, MJCF-004, BEYOND-007).
//
// MuJoCo moves a body about each of its joints in turn, every joint's pos
// and axis in the body's own frame: at q, X_PB(q) = X_PB0 * prod_k
// T(p_k) R(a_k, q_k - ref_k) T(-p_k) (slides translate by a_k (q_k - ref_k)).
// Drake's layout is a chain of massless bodies {body}0, {body}1, ... joined
// by the joints in order, the last joint ending on the real body. Placing
// joint k with X_PF = T(p_k) (the first: X_PB0 T(p_1)) and X_CM = T(p_k)
// R(a_k, ref_k) reproduces MuJoCo's motion exactly, with the XML pose at
// q = ref (MJCF-023; Drake itself puts non-final joints in the parent frame).
//
// springdamper (BEYOND-007) is recorded as a request with every joint's
// qpos0 and armature (ir::InertiaScaledGains): MuJoCo derives the joint's
// stiffness and damping from the joint-space inertia at qpos0, which the
// backend has once the plant exists.
//
// LowerJoints is the outline: a weld for a body without joints, a free joint
// alone, or a chain of hinges, slides and balls, each lowered by LowerJoint
// in steps (type; pos and axis; the child; placement and ref; range;
// damping; the name; armature and gains).
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "frontend/mjcf/mjcf_lowering.h"

namespace mdlc::frontend::mjcf {
namespace {

ir::Ref<BodyId> RefTo(const ir::Module& m, BodyId id) { return {m[id].name, m[id].loc, id}; }

/// Attributes the plant cannot hold (MJCF-024), warned once each; the
/// solver's own (solref..., margin) are silent.
void WarnJointAttributes(MjcfReader& r, const Element& j) {
  for (std::string_view a : {"group", "actuatorfrcrange", "actuatorfrclimited",
                             "actuatorgravcomp", "frictionloss", "user"}) {
    const Attribute attr = j.Get(a);
    if (attr.present()) r.WarnOnce(attr.loc, DiagKind::UnsupportedAttribute, "joint", a);
  }
}

/// springdamper="timeconst dampratio" (BEYOND-007): both values when it is
/// in force; "0 0" (MuJoCo's default) asks for nothing, and otherwise both
/// must be positive (MuJoCo's compiler error). nullopt after an error too.
std::optional<std::array<double, 2>> SpringDamper(MjcfReader& r, const Element& j) {
  const Attribute attr = j.Get("springdamper");
  if (!attr.present()) return std::nullopt;
  const std::optional<std::vector<double>> v = r.Numbers(j, "springdamper", 2);
  if (!v || ((*v)[0] == 0 && (*v)[1] == 0)) return std::nullopt;
  if (!((*v)[0] > 0 && (*v)[1] > 0)) {
    r.diags().Report(DiagKind::BadValue, attr.loc,
                     fmt::format("springdamper values (time constant, damping ratio) must both "
                                 "be positive when defined, not '{}'",
                                 attr.value));
    return std::nullopt;
  }
  return std::array<double, 2>{(*v)[0], (*v)[1]};
}

/// MuJoCo's test for a joint axis along one of the body's axes (mjEPS).
bool AlongBodyAxis(const Eigen::Vector3d& axis) {
  return (std::abs(axis.x()) > 1e-14) + (std::abs(axis.y()) > 1e-14) +
             (std::abs(axis.z()) > 1e-14) ==
         1;
}

/// MJCF-004: limited = true | false | auto (limited iff a range is given,
/// when autolimits; an error without autolimits). MuJoCo reads "a range is
/// given" as a range other than 0 0.
std::optional<bool> Limited(MjcfReader& r, const Element& j, const std::array<double, 2>& range) {
  const Attribute limited = j.Get("limited");
  const bool has_range = !(range[0] == 0 && range[1] == 0);
  std::string_view value = limited.present() ? limited.value : "auto";
  if (value == "true") return true;
  if (value == "false") return false;
  if (value != "auto") {
    r.diags().Report(DiagKind::BadValue, limited.loc,
                     fmt::format("joint limited must be true, false or auto, not '{}'", value));
    return std::nullopt;
  }
  if (r.compiler.autolimits) return has_range;
  if (has_range) {
    r.diags().Report(DiagKind::BadValue, j.Get("range").loc,
                     "the joint 'range' is given but 'limited' is not, and compiler autolimits "
                     "is disabled");
    return std::nullopt;
  }
  return false;
}

// MJCF-021: a body without joints is welded to its parent at its pose
// (named as Drake's WeldFrames names it)
void AddWeld(MjcfReader& r, const BodyContext& b) {
  ir::Module& m = r.module();
  ir::Joint weld;
  weld.name = m.Intern(fmt::format("{}_welds_to_{}", m.Text(m[b.parent].name), b.name));
  weld.model = r.model;
  weld.loc = b.e.GetLoc();
  weld.type = ir::JointType::Weld;
  weld.parent = RefTo(m, b.parent);
  weld.child = RefTo(m, b.body);
  weld.X_PF = b.X_PB0;
  weld.limits = ir::JointLimits::Unbounded(0);
  weld.unnamed = true;
  m.Add(std::move(weld));
}

// Each joint element with its classes resolved (a <freejoint> takes no
// defaults, as in MuJoCo), and which of them is free, if one is.
std::vector<Element> ResolveJointElements(MjcfReader& r, std::span<const BodyItem> items,
                                          std::optional<size_t>& free_index) {
  std::vector<Element> joints;
  for (size_t k = 0; k < items.size(); ++k) {
    const BodyItem& item = items[k];
    if (item.e.Name() == "freejoint") {
      r.CheckAttributes(item.e, "freejoint");
      joints.emplace_back(item.e, "freejoint");
      free_index = k;
      continue;
    }
    r.CheckAttributes(item.e, "joint");
    joints.push_back(r.Resolve(item.e, "joint", item.childclass));
    if (joints.back().Get("type").value == "free") free_index = k;
  }
  return joints;
}

// MJCF-021: a free joint makes a floating body that starts at its world
// pose, named after the body once every joint exists (MjcfReader::free_joints)
void LowerFreeJoint(MjcfReader& r, const BodyContext& b, const Element& j, size_t joint_count) {
  ir::Module& m = r.module();
  if (joint_count > 1) {
    r.diags().Report(DiagKind::BadValue, j.loc(),
                     fmt::format("no other joints can be defined in body '{}' with a free joint",
                                 b.name));
    return;
  }
  if (j.xml().Name() == "joint") {
    WarnJointAttributes(r, j);
    if (SpringDamper(r, j)) {
      r.WarnOnce(j.Get("springdamper").loc, DiagKind::UnsupportedAttribute,
                 "joint type=\"free\"", "springdamper",
                 "is not supported for free bodies and is ignored");
    }
    if (auto d = r.Number(j, "damping", 0); d && *d != 0) {
      r.diags().Report(DiagKind::UnsupportedAttribute, j.Get("damping").loc,
                       fmt::format("damping on the free joint of '{}' is not supported for "
                                   "free bodies",
                                   b.name));
    }
  }
  m[b.body].default_pose = b.X_WB0;
  ir::Joint free;
  free.name = m[b.body].name;
  free.model = r.model;
  free.loc = j.loc();
  free.type = ir::JointType::QuaternionFloating;
  free.parent = RefTo(m, ir::kWorldBody);
  free.child = RefTo(m, b.body);
  free.limits = ir::JointLimits::Unbounded(6);
  free.damping.assign(6, 0.0);
  const Eigen::Quaterniond q = CanonicalQuaternion(b.X_WB0.R);
  free.default_positions = {q.w(), q.x(), q.y(), q.z(), b.X_WB0.p.x(), b.X_WB0.p.y(),
                            b.X_WB0.p.z()};
  free.unnamed = true;
  const JointId id = m.Add(std::move(free));
  ReadOriginalName(j.xml(), id, r.ctx);
  r.free_joints.push_back(id);
  r.joint_order.push_back(id);
  r.scaled_gains.joints.push_back(
      {id, 0, j.xml().Name() == "joint" ? r.Number(j, "armature", 0).value_or(0) : 0.0});
  if (auto name = j.xml().Attribute("name"); name.present()) {
    r.joints.Insert(m.Intern(name.value), id);
  }
}

// A joint's pos and axis in the body frame, through any <frame> the joint is in.
void ReadPosAndAxis(MjcfReader& r, const Element& j, const BodyItem& item, Eigen::Vector3d& pos,
                    Eigen::Vector3d& axis) {
  pos = Eigen::Vector3d::Zero();
  axis = Eigen::Vector3d::UnitZ();
  if (Eigen::Vector3d v; r.FixedNumbers(j, "pos", v.data(), 3)) pos = v;
  if (Eigen::Vector3d v; r.FixedNumbers(j, "axis", v.data(), 3)) axis = v;
  pos = item.X_BF * pos;
  axis = item.X_BF.R * axis;
}

// MuJoCo's "simple" body: besides its place in the tree, only slides, at
// the body origin, along the body's axes (its inertia frame is checked by
// the backend)
bool IsSimpleBody(MjcfReader& r, const BodyContext& b, std::span<const Element> joints,
                  std::span<const BodyItem> items) {
  bool simple_body = b.simple_position;
  for (size_t k = 0; k < joints.size() && simple_body; ++k) {
    const Attribute type = joints[k].Get("type");
    Eigen::Vector3d pos, axis;
    ReadPosAndAxis(r, joints[k], items[k], pos, axis);
    simple_body = type.present() && type.value == "slide" && (pos.array().abs() < 1e-6).all() &&
                  axis.norm() >= 1e-14 && AlongBodyAxis(axis.normalized());
  }
  return simple_body;
}

// hinge, slide or ball (free joints are lowered apart); nullopt after an error
std::optional<ir::JointType> JointTypeOf(MjcfReader& r, const Element& j) {
  const Attribute type_attr = j.Get("type");
  const std::string_view type = type_attr.present() ? type_attr.value : "hinge";
  if (type == "hinge") return ir::JointType::Revolute;
  if (type == "slide") return ir::JointType::Prismatic;
  if (type == "ball") return ir::JointType::Ball;
  r.diags().Report(DiagKind::BadValue, type_attr.loc,
                   fmt::format("unknown joint type '{}': expected hinge, slide, ball or free",
                               type));
  return std::nullopt;
}

// The child of joint k: an intermediate massless body, or, for the last
// joint, the body itself (MJCF-023)
BodyId JointChild(MjcfReader& r, const BodyContext& b, const Element& j, size_t k, bool last) {
  if (last) return b.body;
  ir::Module& m = r.module();
  ir::Body dummy;
  dummy.name = m.Intern(fmt::format("{}{}", b.name, k));
  dummy.unnamed = true;
  dummy.model = r.model;
  dummy.loc = j.loc();
  const BodyId child = m.Add(std::move(dummy));
  if (b.original) {  // named after the body's original name, as it was
    m.original_names.push_back(
        {child, b.original->model, fmt::format("{}{}", b.original->name, k), j.loc()});
  }
  return child;
}

// The joint's frames (see the top of this file) and its default position:
// ref, the position at which the XML pose holds. Returns ref.
double PlaceJoint(MjcfReader& r, const BodyContext& b, const Element& j, size_t k,
                  const Eigen::Vector3d& pos, ir::Joint& joint) {
  const bool hinge = joint.type == ir::JointType::Revolute;
  double ref = r.Number(j, "ref", 0).value_or(0);
  if (hinge) ref = r.compiler.Angle(ref);
  if (joint.type == ir::JointType::Ball && j.Get("ref").present()) {
    r.WarnOnce(j.Get("ref").loc, DiagKind::UnsupportedAttribute, "joint", "ref",
               "has no effect on ball joints and is ignored");
    ref = 0;
  }
  const Transform T_pos = Transform::FromTranslation(pos);
  joint.X_PF = (k == 0 ? b.X_PB0 : Transform()) * T_pos;
  if (hinge) {
    joint.X_CM = T_pos * Transform::FromRotation(RotationAboutAxis(joint.axis, ref));
  } else if (joint.type == ir::JointType::Prismatic) {
    joint.X_CM = Transform::FromTranslation(pos + ref * joint.axis);
  } else {
    joint.X_CM = T_pos;
  }
  if (joint.type != ir::JointType::Ball) joint.default_positions = {ref};
  return ref;
}

// range and limited (MJCF-004, MJCF-022)
void ReadRange(MjcfReader& r, const Element& j, ir::Joint& joint) {
  const bool hinge = joint.type == ir::JointType::Revolute;
  std::array<double, 2> range{0, 0};  // kept when the attribute is absent or wrong
  if (std::array<double, 2> v; r.FixedNumbers(j, "range", v.data(), 2)) range = v;
  if (auto limited = Limited(r, j, range); limited && *limited) {
    if (joint.type == ir::JointType::Ball) {
      r.WarnOnce(j.Get("range").loc, DiagKind::UnsupportedAttribute, "joint", "range",
                 "on a ball joint is not supported and is ignored");
    } else if (range[0] >= range[1]) {
      r.diags().Report(DiagKind::BadLimits, j.Get("range").loc,
                       "joint range[0] must be smaller than range[1]");
    } else {
      joint.limits.lower = {hinge ? r.compiler.Angle(range[0]) : range[0]};
      joint.limits.upper = {hinge ? r.compiler.Angle(range[1]) : range[1]};
    }
  }
}

// Adds the joint to the module, its name to the reader's table (a repeated
// name is an error) and to the joint order.
JointId AddNamedJoint(MjcfReader& r, const Element& j, ir::Joint joint) {
  ir::Module& m = r.module();
  const xml::XmlAttribute name = j.xml().Attribute("name");
  const JointId id = m.Add(std::move(joint));
  ReadOriginalName(j.xml(), id, r.ctx);
  r.joint_order.push_back(id);
  if (name.present()) {
    auto [first, inserted] = r.joints.Insert(m[id].name, id);
    if (!inserted) {
      r.diags()
          .Report(DiagKind::DuplicateName, name.loc,
                  fmt::format("repeated joint name '{}'", name.value))
          .Note(m[first].loc, "the first joint of that name is here");
    }
  }
  return id;
}

// stiffness and springdamper (BEYOND-007): springdamper sets stiffness and
// damping from the inertia at qpos0 (the backend computes them), replacing
// the joint's own; otherwise a stiffness about springref is a joint spring
void AddJointGains(MjcfReader& r, const BodyContext& b, const Element& j, JointId id,
                   bool simple_body, const std::optional<std::array<double, 2>>& spring_damper,
                   double springref, double stiffness) {
  ir::Module& m = r.module();
  const ir::JointType jt = m[id].type;
  if (spring_damper) {
    const Attribute attr = j.Get("springdamper");
    ir::InertiaScaledGains::SpringDamper request;
    request.joint = id;
    request.loc = attr.loc;
    request.timeconst = (*spring_damper)[0];
    request.dampratio = (*spring_damper)[1];
    request.springref = springref;
    if (simple_body) request.simple_body = b.body;
    r.scaled_gains.spring_dampers.push_back(request);
    for (const char* own : {"stiffness", "damping"}) {
      if (j.HasOwn(own)) {
        r.diags().Report(DiagKind::JointWarning, j.Get(own).loc,
                         fmt::format("joint '{}' {} is ignored: 'springdamper' sets it from "
                                     "the joint-space inertia at qpos0, as in MuJoCo",
                                     m.Text(m[id].name), own));
      }
    }
    if (jt == ir::JointType::Ball) {
      r.WarnOnce(attr.loc, DiagKind::UnsupportedAttribute, "joint type=\"ball\"", "springdamper",
                 "sets the joint's damping only: stiffness is not supported on ball joints "
                 "and is ignored");
    }
  } else if (stiffness != 0) {
    if (jt == ir::JointType::Ball) {
      r.WarnOnce(j.Get("stiffness").loc, DiagKind::UnsupportedAttribute, "joint", "stiffness",
                 "on a ball joint is not supported and is ignored");
    } else {
      ir::JointSpring spring;
      spring.joint = {m[id].name, j.loc(), id};
      spring.stiffness = stiffness;
      spring.nominal = springref;
      m.Add(ir::ForceElement{r.model, j.Get("stiffness").loc, spring});
    }
  }
}

// Joint k of a body's hinges, slides and balls, from `parent` to the child
// it makes; nullopt after an error that stops the body's joints.
std::optional<BodyId> LowerJoint(MjcfReader& r, const BodyContext& b, const Element& j,
                                 const BodyItem& item, size_t k, bool last, bool simple_body,
                                 BodyId parent) {
  ir::Module& m = r.module();
  const std::optional<ir::JointType> jt = JointTypeOf(r, j);
  if (!jt) return std::nullopt;
  const bool hinge = *jt == ir::JointType::Revolute;
  const int nv = ir::JointVelocityCount(*jt);

  Eigen::Vector3d pos, axis;
  ReadPosAndAxis(r, j, item, pos, axis);
  if (*jt != ir::JointType::Ball && axis.norm() < 1e-14) {
    r.diags().Report(DiagKind::ZeroAxis, j.Get("axis").loc, "joint axis too small");
    return std::nullopt;
  }
  if (*jt == ir::JointType::Ball) axis = Eigen::Vector3d::UnitZ();
  axis.normalize();

  const BodyId child = JointChild(r, b, j, k, last);
  ir::Joint joint;
  const xml::XmlAttribute name = j.xml().Attribute("name");
  joint.name = name.present()
                   ? m.Intern(name.value)
                   : m.Intern(fmt::format("{}-{}", m.Text(m[parent].name), m.Text(m[child].name)));
  joint.unnamed = !name.present();
  joint.model = r.model;
  joint.loc = j.loc();
  joint.type = *jt;
  joint.parent = RefTo(m, parent);
  joint.child = RefTo(m, child);
  joint.axis = axis;
  joint.limits = ir::JointLimits::Unbounded(nv);
  const double ref = PlaceJoint(r, b, j, k, pos, joint);
  ReadRange(r, j, joint);
  joint.damping.assign(static_cast<size_t>(nv), r.Number(j, "damping", 0).value_or(0));
  WarnJointAttributes(r, j);
  const std::optional<std::array<double, 2>> spring_damper = SpringDamper(r, j);
  const JointId id = AddNamedJoint(r, j, std::move(joint));

  // MJCF-024: armature waits for an actuator to become rotor inertia
  const double armature = r.Number(j, "armature", 0).value_or(0);
  if (const auto a = j.Get("armature"); a.present()) r.joint_armature[id.value] = {armature, a.loc};
  r.scaled_gains.joints.push_back({id, *jt == ir::JointType::Ball ? 0.0 : ref, armature});
  const double springref_value = r.Number(j, "springref", 0).value_or(0);
  const double springref = hinge ? r.compiler.Angle(springref_value) : springref_value;
  const double stiffness = r.Number(j, "stiffness", 0).value_or(0);
  AddJointGains(r, b, j, id, simple_body, spring_damper, springref, stiffness);
  return child;
}

}  // namespace

void LowerJoints(MjcfReader& r, const BodyContext& b, std::span<const BodyItem> items,
                 bool mocap) {
  if (items.empty()) {
    AddWeld(r, b);
    return;
  }
  (void)mocap;  // a mocap body with joints was reported by the caller
  std::optional<size_t> free_index;
  const std::vector<Element> joints = ResolveJointElements(r, items, free_index);
  if (free_index) {
    LowerFreeJoint(r, b, joints[*free_index], items.size());
    return;
  }
  const bool simple_body = IsSimpleBody(r, b, joints, items);
  BodyId parent = b.parent;
  for (size_t k = 0; k < joints.size(); ++k) {
    const std::optional<BodyId> child =
        LowerJoint(r, b, joints[k], items[k], k, k + 1 == joints.size(), simple_body, parent);
    if (!child) return;
    parent = *child;
  }
}

}  // namespace mdlc::frontend::mjcf
