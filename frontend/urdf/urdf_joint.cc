// urdf_joint.cc - <joint> and <drake:joint> (their shared reading), <frame>
// (URDF-010..018, URDF-041, URDF-042, EXT-001).
// ReadAnyJoint is the outline; each step below reads one concern: the name
// and the two ends (with the origin), the type and the element that spells
// it, the axis, the unbounded values every joint starts from, the
// parameters of Drake's custom types, then the other children (<limit>,
// <dynamics>, <mimic>, ROS settings, type-specific drake: children).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "frontend/original_names.h"
#include "frontend/unknown_element.h"
#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Drake rejects an axis shorter than this ("axis is zero")
constexpr double kMinAxisNorm = 1e-8;

// Drake's planar joint moves in the x-y plane of its frame: rotate the frame
// so that its z axis is the URDF axis.
Eigen::Matrix3d FrameWithZAlong(const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
}

}  // namespace

// Which element may declare a joint type (EXT-001): the standard URDF types
// belong in <joint>, Drake's custom ones in <drake:joint>, and planar is
// accepted in both (Drake long supported only the custom spelling).
enum class Spelling { Joint, DrakeJoint, Either };

// declared in urdf_reader_detail.h, so that the reading steps can share it
struct UrdfJointType {
  std::string_view name;
  ir::JointType type;
  Spelling spelling;
  bool continuous = false;  // revolute without position limits
  bool floating = false;    // makes no joint at all
};

namespace {

constexpr UrdfJointType kJointTypes[] = {
    {"revolute", ir::JointType::Revolute, Spelling::Joint},
    {"continuous", ir::JointType::Revolute, Spelling::Joint, true},
    {"prismatic", ir::JointType::Prismatic, Spelling::Joint},
    {"fixed", ir::JointType::Weld, Spelling::Joint},
    {"floating", ir::JointType::QuaternionFloating, Spelling::Joint, false, true},
    {"planar", ir::JointType::Planar, Spelling::Either},
    {"ball", ir::JointType::Ball, Spelling::DrakeJoint},
    {"universal", ir::JointType::Universal, Spelling::DrakeJoint},
    {"screw", ir::JointType::Screw, Spelling::DrakeJoint},
    {"curvilinear", ir::JointType::Curvilinear, Spelling::DrakeJoint},
};

const UrdfJointType* FindJointType(std::string_view name) {
  for (const UrdfJointType& t : kJointTypes) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

// The drake: children of a joint element that belong to one joint type
// (EXT-002, EXT-003); they are read by that type's helper.
struct TypeSpecificChild {
  std::string_view tag;
  ir::JointType type;
};
constexpr TypeSpecificChild kTypeSpecificChildren[] = {
    {"drake:screw_thread_pitch", ir::JointType::Screw},
    {"drake:plane_normal", ir::JointType::Curvilinear},
    {"drake:initial_tangent", ir::JointType::Curvilinear},
    {"drake:is_periodic", ir::JointType::Curvilinear},
    {"drake:curves", ir::JointType::Curvilinear},
};

// Drake reads no <limit> for its custom joint types: their limits stay
// unbounded (curvilinear: the ends of an open path) and their effort
// infinite.
bool IgnoresLimits(ir::JointType type) {
  return type == ir::JointType::Ball || type == ir::JointType::Universal ||
         type == ir::JointType::Screw || type == ir::JointType::Curvilinear;
}

// every joint starts unbounded, with infinite effort and no damping; its
// children narrow that
void SetUnboundedJointValues(ir::Joint& joint) {
  const int nv = ir::JointVelocityCount(joint.type);
  joint.limits.lower.assign(nv, -kInf);
  joint.limits.upper.assign(nv, kInf);
  joint.limits.velocity_lower.assign(nv, -kInf);
  joint.limits.velocity_upper.assign(nv, kInf);
  joint.limits.acceleration_lower.assign(nv, -kInf);
  joint.limits.acceleration_upper.assign(nv, kInf);
  joint.limits.effort.assign(nv, kInf);
  joint.damping.assign(nv, 0.0);
}

}  // namespace

void UrdfReader::ReadJoint(const xml::XmlElement& e) { ReadAnyJoint(e, /*drake_element=*/false); }

void UrdfReader::ReadAnyJoint(const xml::XmlElement& e, bool drake_element) {
  ir::Joint joint;
  const std::optional<std::string_view> type = ReadJointEnds(e, joint);
  if (!type) return;
  const UrdfJointType* kind = ReadJointType(e, *type, drake_element, joint);
  if (!kind) return;  // unknown or floating: no joint
  if (!ReadJointAxis(e, *kind, joint)) return;
  SetUnboundedJointValues(joint);
  ReadCustomTypeParameters(e, joint);
  ReadJointChildren(e, *kind, joint);
  const Symbol joint_name = joint.name;
  const JointId id = module().Add(std::move(joint));
  joint_ids_[joint_name.value] = id;
  ReadOriginalName(e, id, ctx_);
}

std::optional<std::string_view> UrdfReader::ReadJointEnds(const xml::XmlElement& e,
                                                          ir::Joint& joint) {
  const std::string_view element = e.Name();  // "joint" or "drake:joint"
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto type = attrs_.String(e, "type", xml::Need::Required);
  attrs_.WarnUnknownAttributes(e, {"name", "type", "drake_ignore"});
  auto parent = e.Child("parent");
  auto child = e.Child("child");
  if (!parent) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   fmt::format("<{}> is missing its <parent> element", element));
  }
  if (!child) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   fmt::format("<{}> is missing its <child> element", element));
  }
  auto parent_link = parent ? attrs_.String(parent, "link", xml::Need::Required) : std::nullopt;
  auto child_link = child ? attrs_.String(child, "link", xml::Need::Required) : std::nullopt;
  if (!name || !type || !parent_link || !child_link) return std::nullopt;

  joint.name = module().Intern(*name);
  joint.model = model_;
  joint.loc = e.GetLoc();
  CheckUniqueName(joint_names_, joint.name, joint.loc, "joint");
  joint.parent = {module().Intern(*parent_link), parent.Attribute("link").loc, {}};
  joint.child = {module().Intern(*child_link), child.Attribute("link").loc, {}};
  joint.X_PF = ReadOrigin(e);
  return type;
}

const UrdfJointType* UrdfReader::ReadJointType(const xml::XmlElement& e, std::string_view type,
                                               bool drake_element, ir::Joint& joint) {
  const std::string_view name = module().Text(joint.name);
  const Loc type_loc = e.Attribute("type").loc;
  const UrdfJointType* kind = FindJointType(type);
  if (!kind) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' has unrecognized type '{}'; expected {}", name, type,
                               drake_element
                                   ? "ball, universal, screw, planar or curvilinear"
                                   : "revolute, continuous, prismatic, fixed, floating or planar"));
    return nullptr;
  }
  // the element must suit the type (EXT-001). Drake reports the mismatch and
  // still makes the joint; so does mdlc, so that nothing else fails because
  // of it (transmissions and mimics naming the joint, its child's parent).
  if (drake_element && kind->spelling == Spelling::Joint) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' of type '{}' is a standard joint type: declare it with "
                               "<joint>, not <drake:joint>",
                               name, type));
  } else if (!drake_element && kind->spelling == Spelling::DrakeJoint) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' of type '{}' is a custom joint type: declare it with "
                               "<drake:joint>, not <joint>",
                               name, type));
  }
  if (kind->floating) {
    // Drake makes no joint: the child stays a free body (URDF-012)
    diags().Report(DiagKind::FloatingJoint, type_loc,
                   fmt::format("joint '{}' of type 'floating' creates no joint: link '{}' becomes "
                               "a free body",
                               name, module().Text(joint.child.name)));
    return nullptr;
  }
  joint.type = kind->type;
  return kind;
}

bool UrdfReader::ReadJointAxis(const xml::XmlElement& e, const UrdfJointType& kind,
                               ir::Joint& joint) {
  // the axis, in the joint frame (URDF-011). Drake reads and checks it for
  // every type but fixed, floating and ball; universal and curvilinear
  // joints do not use it.
  const bool reads_axis = joint.type != ir::JointType::Weld && joint.type != ir::JointType::Ball;
  const bool uses_axis = joint.type == ir::JointType::Revolute ||
                         joint.type == ir::JointType::Prismatic ||
                         joint.type == ir::JointType::Planar || joint.type == ir::JointType::Screw;
  if (auto axis = e.Child("axis"); axis && reads_axis) {
    attrs_.WarnUnknownAttributes(axis, {"xyz"});
    if (auto xyz = attrs_.Vector3(axis, "xyz", xml::Need::Required)) {
      if (xyz->norm() < kMinAxisNorm) {
        diags().Report(DiagKind::ZeroAxis, axis.Attribute("xyz").loc,
                       fmt::format("joint '{}': axis is zero; it must have a direction",
                                   module().Text(joint.name)));
        return false;
      }
      if (uses_axis) {
        joint.axis = xyz->normalized();
      } else {
        diags().Report(DiagKind::JointWarning, axis.GetLoc(),
                       fmt::format("<axis> of {} joint '{}' is ignored{}", kind.name,
                                   module().Text(joint.name),
                                   joint.type == ir::JointType::Universal
                                       ? ": Drake's universal joint turns about its frame's x "
                                         "axis, then y"
                                       : ": the path gives the motion"));
      }
    }
  }
  if (joint.type == ir::JointType::Planar) {
    joint.X_PF.R = joint.X_PF.R * FrameWithZAlong(joint.axis);
    joint.X_CM.R = FrameWithZAlong(joint.axis);
    joint.axis = Eigen::Vector3d::UnitZ();
  }
  return true;
}

void UrdfReader::ReadCustomTypeParameters(const xml::XmlElement& e, ir::Joint& joint) {
  // the parameters of Drake's custom types (EXT-002, EXT-003). After an
  // error here the joint is still declared, as after a misspelled type.
  if (joint.type == ir::JointType::Screw) {
    ReadScrewThreadPitch(e, joint);
  } else if (joint.type == ir::JointType::Curvilinear) {
    // Drake's curvilinear joint limits an open path to its ends
    if (ReadCurvilinearPath(e, joint) && !joint.curvilinear_path.periodic) {
      joint.limits.lower.set(0, 0);
      joint.limits.upper.set(0, joint.curvilinear_path.TotalLength());
    }
  }
}

void UrdfReader::ReadJointChildren(const xml::XmlElement& e, const UrdfJointType& kind,
                                   ir::Joint& joint) {
  const std::string_view element = e.Name();
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    std::string_view tag = c.Name();
    if (tag == "origin" || tag == "parent" || tag == "child" || tag == "axis") {
      continue;  // read before the other children
    } else if (tag == "limit") {
      ReadJointLimit(c, kind, joint);
    } else if (tag == "dynamics") {
      ReadDynamics(c, joint);
    } else if (tag == "mimic") {
      ReadMimic(c, joint);
    } else if (tag == "calibration" || tag == "safety_controller") {
      ReportRosJointSetting(c, element);
    } else if (!CheckTypeSpecificChild(c, kind, joint)) {
      ReportUnknownElement(diags(), c, element,
                           {"origin", "parent", "child", "axis", "limit", "dynamics", "mimic",
                            "calibration", "safety_controller"});
    }
  }
}

void UrdfReader::ReadJointLimit(const xml::XmlElement& limit, const UrdfJointType& kind,
                                ir::Joint& joint) {
  if (joint.type == ir::JointType::Revolute || joint.type == ir::JointType::Prismatic) {
    ReadLimits(limit, joint, kind.continuous);
  } else if (IgnoresLimits(joint.type)) {
    diags().Report(DiagKind::UnsupportedElement, limit.GetLoc(),
                   fmt::format("<limit> of {} joint '{}' is ignored: Drake reads no limits "
                               "or effort for {} joints",
                               kind.name, module().Text(joint.name), kind.name));
  }
  // fixed and planar joints ignore <limit> silently, as in Drake
}

void UrdfReader::ReportRosJointSetting(const xml::XmlElement& c, std::string_view element) {
  if (c.Name() == "calibration") {
    if (!std::exchange(said_calibration_, true)) {
      diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                     fmt::format("element <calibration> in <{}> is ignored: the plant holds "
                                 "no encoder calibration (said once per file)",
                                 element));
    }
  } else if (!std::exchange(said_safety_controller_, true)) {
    diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                   fmt::format("element <safety_controller> in <{}> is ignored: the plant "
                               "holds no ROS safety controller, only the <limit> (said once "
                               "per file)",
                               element));
  }
}

bool UrdfReader::CheckTypeSpecificChild(const xml::XmlElement& c, const UrdfJointType& kind,
                                        const ir::Joint& joint) {
  const std::string_view tag = c.Name();
  auto it = std::find_if(std::begin(kTypeSpecificChildren), std::end(kTypeSpecificChildren),
                         [&](const TypeSpecificChild& s) { return s.tag == tag; });
  if (it == std::end(kTypeSpecificChildren)) return false;
  // read by ReadCustomTypeParameters when the type is right
  if (it->type != joint.type) {
    diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                   fmt::format("<{}> applies only to {} joints; it is ignored in {} joint '{}'",
                               tag, ir::JointTypeName(it->type), kind.name,
                               module().Text(joint.name)));
  }
  return true;
}

void UrdfReader::ReadFrame(const xml::XmlElement& e) {
  // Drake's <frame name link xyz rpy> extension (URDF-041)
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto link = attrs_.String(e, "link", xml::Need::Required);
  attrs_.WarnUnknownAttributes(e, {"name", "link", "xyz", "rpy"});
  if (!name || !link) return;
  ir::Frame frame;
  frame.name = module().Intern(*name);
  frame.model = model_;
  frame.loc = e.GetLoc();
  CheckUniqueName(frame_names_, frame.name, frame.loc, "frame");
  frame.body = {module().Intern(*link), e.Attribute("link").loc, {}};
  if (auto xyz = attrs_.Vector3(e, "xyz")) frame.X_BF.p = *xyz;
  if (auto rpy = attrs_.Vector3(e, "rpy")) frame.X_BF.R = RotationFromRpy(*rpy);
  const FrameId id = module().Add(std::move(frame));
  ReadOriginalName(e, id, ctx_);
}

}  // namespace mdlc::frontend::urdf
