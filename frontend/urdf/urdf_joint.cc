// urdf_joint.cc - <joint> and <drake:joint> (their shared reading), <frame>
// (URDF-010..018, URDF-041, URDF-042, EXT-001).
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

// Which element may declare a joint type (EXT-001): the standard URDF types
// belong in <joint>, Drake's custom ones in <drake:joint>, and planar is
// accepted in both (Drake long supported only the custom spelling).
enum class Spelling { Joint, DrakeJoint, Either };

struct UrdfJointType {
  std::string_view name;
  ir::JointType type;
  Spelling spelling;
  bool continuous = false;  // revolute without position limits
  bool floating = false;    // makes no joint at all
};

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
}  // namespace

void UrdfReader::ReadJoint(const xml::XmlElement& e) { ReadAnyJoint(e, /*drake_element=*/false); }

void UrdfReader::ReadAnyJoint(const xml::XmlElement& e, bool drake_element) {
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
  if (!name || !type || !parent_link || !child_link) return;

  ir::Joint joint;
  joint.name = module().Intern(*name);
  joint.model = model_;
  joint.loc = e.GetLoc();
  CheckUniqueName(joint_names_, joint.name, joint.loc, "joint");
  joint.parent = {module().Intern(*parent_link), parent.Attribute("link").loc, {}};
  joint.child = {module().Intern(*child_link), child.Attribute("link").loc, {}};
  joint.X_PF = ReadOrigin(e);

  const Loc type_loc = e.Attribute("type").loc;
  const UrdfJointType* kind = FindJointType(*type);
  if (!kind) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' has unrecognized type '{}'; expected {}", *name, *type,
                               drake_element
                                   ? "ball, universal, screw, planar or curvilinear"
                                   : "revolute, continuous, prismatic, fixed, floating or planar"));
    return;
  }
  // the element must suit the type (EXT-001). Drake reports the mismatch and
  // still makes the joint; so does mdlc, so that nothing else fails because
  // of it (transmissions and mimics naming the joint, its child's parent).
  if (drake_element && kind->spelling == Spelling::Joint) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' of type '{}' is a standard joint type: declare it with "
                               "<joint>, not <drake:joint>",
                               *name, *type));
  } else if (!drake_element && kind->spelling == Spelling::DrakeJoint) {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' of type '{}' is a custom joint type: declare it with "
                               "<drake:joint>, not <joint>",
                               *name, *type));
  }
  if (kind->floating) {
    // Drake makes no joint: the child stays a free body (URDF-012)
    diags().Report(DiagKind::FloatingJoint, type_loc,
                   fmt::format("joint '{}' of type 'floating' creates no joint: link '{}' becomes "
                               "a free body",
                               *name, *child_link));
    return;
  }
  joint.type = kind->type;

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
                       fmt::format("joint '{}': axis is zero; it must have a direction", *name));
        return;
      }
      if (uses_axis) {
        joint.axis = xyz->normalized();
      } else {
        diags().Report(DiagKind::JointWarning, axis.GetLoc(),
                       fmt::format("<axis> of {} joint '{}' is ignored{}", *type, *name,
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

  const int nv = ir::JointVelocityCount(joint.type);
  joint.limits.lower.assign(nv, -kInf);
  joint.limits.upper.assign(nv, kInf);
  joint.limits.velocity_lower.assign(nv, -kInf);
  joint.limits.velocity_upper.assign(nv, kInf);
  joint.limits.acceleration_lower.assign(nv, -kInf);
  joint.limits.acceleration_upper.assign(nv, kInf);
  joint.limits.effort.assign(nv, kInf);
  joint.damping.assign(nv, 0.0);

  // the parameters of Drake's custom types (EXT-002, EXT-003). After an
  // error here the joint is still declared, for the same reason as above.
  if (joint.type == ir::JointType::Screw) {
    ReadScrewThreadPitch(e, joint);
  } else if (joint.type == ir::JointType::Curvilinear) {
    // Drake's curvilinear joint limits an open path to its ends
    if (ReadCurvilinearPath(e, joint) && !joint.curvilinear_path.periodic) {
      joint.limits.lower.set(0, 0);
      joint.limits.upper.set(0, joint.curvilinear_path.TotalLength());
    }
  }

  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    std::string_view tag = c.Name();
    if (tag == "origin" || tag == "parent" || tag == "child" || tag == "axis") {
      continue;
    } else if (tag == "limit") {
      if (joint.type == ir::JointType::Revolute || joint.type == ir::JointType::Prismatic) {
        ReadLimits(c, joint, kind->continuous);
      } else if (IgnoresLimits(joint.type)) {
        diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                       fmt::format("<limit> of {} joint '{}' is ignored: Drake reads no limits "
                                   "or effort for {} joints",
                                   *type, *name, *type));
      }
      // fixed and planar joints ignore <limit> silently, as in Drake
    } else if (tag == "dynamics") {
      attrs_.WarnUnknownAttributes(c, {"damping", "friction", "coulomb_window", "spring_reference",
                                       "spring_stiffness"});
      if (joint.type == ir::JointType::Planar) {
        // three values: x, y and the rotation about z (URDF-014)
        if (auto d = c.Attribute("damping"); d.present()) {
          if (auto values = attrs_.Doubles(c, "damping", 3)) {
            if (std::any_of(values->begin(), values->end(), [](double v) { return v < 0; })) {
              diags().Report(DiagKind::BadValue, d.loc,
                             fmt::format("joint '{}': damping must not be negative", *name));
            } else {
              joint.damping = *values;
            }
          }
        }
      } else if (nv > 0) {
        // one value; ball and universal joints apply it to every dof, as
        // Drake's BallRpyJoint and UniversalJoint do
        if (auto d = attrs_.Double(c, "damping")) {
          if (*d < 0) {
            diags().Report(DiagKind::BadValue, c.Attribute("damping").loc,
                           fmt::format("joint '{}': damping must not be negative", *name));
          } else {
            joint.damping.assign(nv, *d);
          }
        }
      }
      if (auto f = attrs_.Double(c, "friction"); f && *f != 0 && !said_friction_) {
        said_friction_ = true;
        diags().Report(DiagKind::UnsupportedAttribute, c.Attribute("friction").loc,
                       "joint friction is ignored: the plant holds no Coulomb friction in joints, "
                       "only <dynamics damping> (said once per file)");
      }
      if (auto w = c.Attribute("coulomb_window"); w.present()) {
        diags().Report(DiagKind::UnsupportedAttribute, w.loc,
                       "attribute 'coulomb_window' is not supported and is ignored");
      }
    } else if (tag == "mimic") {
      ReadMimic(c, joint);
    } else if (tag == "calibration") {
      if (!std::exchange(said_calibration_, true)) {
        diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                       fmt::format("element <calibration> in <{}> is ignored: the plant holds "
                                   "no encoder calibration (said once per file)",
                                   element));
      }
    } else if (tag == "safety_controller") {
      if (!std::exchange(said_safety_controller_, true)) {
        diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                       fmt::format("element <safety_controller> in <{}> is ignored: the plant "
                                   "holds no ROS safety controller, only the <limit> (said once "
                                   "per file)",
                                   element));
      }
    } else if (auto it = std::find_if(std::begin(kTypeSpecificChildren),
                                      std::end(kTypeSpecificChildren),
                                      [&](const TypeSpecificChild& s) { return s.tag == tag; });
               it != std::end(kTypeSpecificChildren)) {
      // read above when the type is right
      if (it->type != joint.type) {
        diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                       fmt::format("<{}> applies only to {} joints; it is ignored in {} joint '{}'",
                                   tag, ir::JointTypeName(it->type), *type, *name));
      }
    } else {
      ReportUnknownElement(diags(), c, element,
                           {"origin", "parent", "child", "axis", "limit", "dynamics", "mimic",
                            "calibration", "safety_controller"});
    }
  }
  const Symbol joint_name = joint.name;
  const JointId id = module().Add(std::move(joint));
  joint_ids_[joint_name.value] = id;
  ReadOriginalName(e, id, ctx_);
}

void UrdfReader::ReadLimits(const xml::XmlElement& e, ir::Joint& joint, bool continuous) {
  // a misspelled bound (uper=) leaves that side unbounded: the note says so
  static constexpr std::string_view kUnbounded[] = {"the lower limit is -inf: unbounded",
                                                    "the upper limit is +inf: unbounded"};
  attrs_.WarnUnknownAttributes(
      e, {"lower", "upper", "velocity", "effort", "drake:acceleration"},
      continuous ? std::initializer_list<xml::AttributeReader::WhenAbsent>{}
                 : std::initializer_list<xml::AttributeReader::WhenAbsent>{
                       {"lower", kUnbounded[0]}, {"upper", kUnbounded[1]}});
  // joint limits may be infinite: that means "unbounded"
  auto lower = attrs_.Double(e, "lower", xml::Need::Optional, xml::Finite::NotRequired);
  auto upper = attrs_.Double(e, "upper", xml::Need::Optional, xml::Finite::NotRequired);
  auto velocity = attrs_.Double(e, "velocity", xml::Need::Optional, xml::Finite::NotRequired);
  auto effort = attrs_.Double(e, "effort", xml::Need::Optional, xml::Finite::NotRequired);
  auto accel =
      attrs_.Double(e, "drake:acceleration", xml::Need::Optional, xml::Finite::NotRequired);
  for (auto [value, attr] : {std::pair{&lower, "lower"}, {&upper, "upper"},
                             {&velocity, "velocity"}, {&effort, "effort"},
                             {&accel, "drake:acceleration"}}) {
    if (*value && std::isnan(**value)) {
      diags().Report(DiagKind::NonFinite, e.Attribute(attr).loc,
                     fmt::format("attribute '{}' of <limit> is NaN", attr));
      value->reset();
    }
  }
  if (!continuous) {
    // an absent bound leaves that side unbounded, as in Drake
    const double lo = lower.value_or(-kInf), hi = upper.value_or(kInf);
    if (lo > hi) {
      diags().Report(DiagKind::BadLimits, e.GetLoc(),
                     fmt::format("joint '{}': lower limit {} is greater than upper limit {}",
                                 module().Text(joint.name), lo, hi));
      return;
    }
    joint.limits.lower.set(0, lo);
    joint.limits.upper.set(0, hi);
  }
  for (auto [value, what] : {std::pair{&velocity, "velocity"}, {&effort, "effort"},
                             {&accel, "drake:acceleration"}}) {
    if (*value && **value < 0) {
      diags().Report(DiagKind::BadLimits, e.Attribute(what).loc,
                     fmt::format("joint '{}': {} limit must not be negative",
                                 module().Text(joint.name), what));
      value->reset();
    }
  }
  if (velocity) {
    joint.limits.velocity_lower.set(0, -*velocity);
    joint.limits.velocity_upper.set(0, *velocity);
  }
  if (effort) joint.limits.effort.set(0, *effort);
  if (accel) {
    joint.limits.acceleration_lower.set(0, -*accel);
    joint.limits.acceleration_upper.set(0, *accel);
  }
}

void UrdfReader::ReadMimic(const xml::XmlElement& e, const ir::Joint& joint) {
  // q_joint = multiplier * q_other + offset, as a coupler constraint (URDF-018).
  // Drake's convention: joint0 is the joint that follows (the one holding
  // <mimic>), joint1 the joint it follows.
  auto other = attrs_.String(e, "joint", xml::Need::Required);
  if (!other) return;
  attrs_.WarnUnknownAttributes(e, {"joint", "multiplier", "offset"});
  if (module().Intern(*other) == joint.name) {
    diags().Report(DiagKind::BadValue, e.Attribute("joint").loc,
                   fmt::format("joint '{}' cannot mimic itself", module().Text(joint.name)));
    return;
  }
  ir::CouplerConstraint c;
  c.joint0 = {joint.name, joint.loc, {}};
  c.joint1 = {module().Intern(*other), e.Attribute("joint").loc, {}};
  c.gear_ratio = attrs_.Double(e, "multiplier").value_or(1.0);
  c.offset = attrs_.Double(e, "offset").value_or(0.0);
  module().Add(ir::Constraint{model_, e.GetLoc(), std::move(c)});
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
