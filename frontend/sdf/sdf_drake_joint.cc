// sdf_drake_joint.cc - <drake:joint> of an SDFormat model (EXT-001, EXT-003,
// EXT-004): planar and curvilinear joints, written as element text.
//
// As in Drake, the joint's frame F IS the frame named by drake:parent and M
// the one named by drake:child (no pose of its own; <pose> is an error).
// When both name links, X_PF = X_CM = identity and the joint's parent and
// child are plain link references for resolve-names (scoped names reach
// into nested models). Naming an explicit <frame> or a model frame of the
// model is reported as not implemented: F and M would need separate nodes in
// the frame graph, which JointFrameSpec cannot express yet, and SDFormat
// joint-frame semantics would place F wrongly.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "frontend/drake_child_reader.h"
#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::sdf {
namespace {
// Drake's tolerance for "perpendicular" between a curvilinear path's initial
// tangent and its plane normal (as in urdf_drake_joint.cc)
constexpr double kPerpendicularTolerance = 128 * std::numeric_limits<double>::epsilon();

// PlanarJoint: x, y translation and rotation about z of F; three
// non-negative dampings, required (EXT-004). False after an error.
bool ReadPlanar(SdfReader& reader, const xml::XmlElement& e, DrakeChildReader& r,
                const std::string& name, ir::Joint& joint) {
  joint.axis = Eigen::Vector3d::UnitZ();
  auto damping = r.Vector("drake:damping", Sign::NonNegative);
  for (const char* t : {"drake:initial_tangent", "drake:plane_normal", "drake:is_periodic",
                        "drake:curves"}) {
    if (auto c = e.Child(t)) {
      reader.diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                            fmt::format("<{}> applies only to curvilinear joints; it is ignored "
                                        "in planar joint '{}'",
                                        t, name));
    }
  }
  if (!r.ok()) return false;
  joint.damping = {damping->x(), damping->y(), damping->z()};
  return true;
}

// <drake:plane_normal> or <drake:initial_tangent>: a non-zero direction in
// an <xyz> child. Returns where it is written (invalid when absent or bad).
Loc ReadDirection(SdfReader& reader, const xml::XmlElement& e, DrakeChildReader& r,
                  std::string_view tag, const std::string& name, Eigen::Vector3d& out) {
  xml::XmlElement c = e.Child(tag);
  if (!c) return {};
  reader.CheckChildren(c, {"xyz"});
  xml::XmlElement xyz = c.Child("xyz");
  if (!xyz) {
    r.Fail(c.GetLoc(), fmt::format("<{}> needs an <xyz> child", tag), DiagKind::MissingElement);
    return {};
  }
  auto v = reader.TextVector3(xyz);
  if (!v) {
    r.Invalidate();
    return {};
  }
  if (v->norm() == 0) {
    r.Fail(xyz.GetLoc(),
           fmt::format("curvilinear joint '{}': <{}> is zero; it must have a direction", name,
                       tag),
           DiagKind::ZeroAxis);
    return {};
  }
  out = *v;
  return xyz.GetLoc();
}

// <drake:curves>: the path's segments, in order; at least one.
void ReadCurves(SdfReader& reader, const xml::XmlElement& curves, DrakeChildReader& r,
                const std::string& name, ir::CurvilinearPath& path) {
  bool any_curve = false;
  for (auto c = curves.FirstChild(); c; c = c.NextSibling()) {
    any_curve = true;
    const std::string_view ct = c.Name();
    if (ct == "drake:line_segment") {
      DrakeChildReader piece(c, {"drake:length"}, ValueSpelling::Text, reader.attrs_,
                             reader.module());
      auto length = piece.Scalar("drake:length", xml::Need::Required, Sign::Positive);
      if (!piece.ok()) {
        r.Invalidate();
        continue;
      }
      path.segments.push_back({*length, 0.0});
    } else if (ct == "drake:circular_arc") {
      DrakeChildReader piece(c, {"drake:radius", "drake:angle"}, ValueSpelling::Text,
                             reader.attrs_, reader.module());
      auto radius = piece.Scalar("drake:radius", xml::Need::Required, Sign::Positive);
      auto angle = piece.Scalar("drake:angle", xml::Need::Required, Sign::Any);
      if (angle && *angle == 0) {
        piece.Fail(c.Child("drake:angle").GetLoc(),
                   fmt::format("curvilinear joint '{}': the <drake:angle> of a "
                               "<drake:circular_arc> must not be zero",
                               name));
      }
      if (!piece.ok()) {
        r.Invalidate();
        continue;
      }
      // the sign of the angle is the turn about the plane normal
      const double length = *radius * std::abs(*angle);
      path.segments.push_back({length, *angle / length});
    } else {
      r.Fail(c.GetLoc(), fmt::format("<{}> in <drake:curves> is not a path segment; a path is "
                                     "made of <drake:line_segment> and <drake:circular_arc>",
                                     ct));
    }
  }
  if (!any_curve) {
    r.Fail(curves.GetLoc(),
           fmt::format("curvilinear joint '{}' has an empty <drake:curves> list", name),
           DiagKind::MissingElement);
  }
}

// Curvilinear (EXT-003): optional damping (one value), plane normal and
// initial tangent (<xyz> children), periodicity, and the curves. False
// after an error.
bool ReadCurvilinear(SdfReader& reader, const xml::XmlElement& e, DrakeChildReader& r,
                     const std::string& name, ir::Joint& joint) {
  if (auto d = r.Scalar("drake:damping", xml::Need::Optional, Sign::NonNegative)) {
    joint.damping.assign(1, *d);
  }
  ir::CurvilinearPath path;
  ReadDirection(reader, e, r, "drake:plane_normal", name, path.plane_normal);
  const Loc tangent_loc =
      ReadDirection(reader, e, r, "drake:initial_tangent", name, path.initial_tangent);
  if (r.ok() && std::abs(path.initial_tangent.normalized().dot(path.plane_normal.normalized())) >
                    kPerpendicularTolerance) {
    r.Fail(tangent_loc.valid() ? tangent_loc : e.GetLoc(),
           fmt::format("curvilinear joint '{}': the initial tangent [{} {} {}] is not "
                       "perpendicular to the plane normal [{} {} {}]",
                       name, path.initial_tangent.x(), path.initial_tangent.y(),
                       path.initial_tangent.z(), path.plane_normal.x(), path.plane_normal.y(),
                       path.plane_normal.z()));
  }
  if (xml::XmlElement p = e.Child("drake:is_periodic")) {
    // Drake takes exactly "true" or "false"
    const std::string value(xml::Trim(p.Text()));
    if (value == "true") {
      path.periodic = true;
    } else if (value != "false") {
      r.Fail(p.GetLoc(),
             fmt::format("<drake:is_periodic> must be true or false, got '{}'", value));
    }
  }
  xml::XmlElement curves = e.Child("drake:curves");
  if (!curves) {
    r.Fail(e.GetLoc(),
           fmt::format("curvilinear <drake:joint> '{}' needs a <drake:curves> child, its path",
                       name),
           DiagKind::MissingElement);
    return false;
  }
  ReadCurves(reader, curves, r, name, path);
  if (!r.ok()) return false;
  joint.curvilinear_path = std::move(path);
  // Drake's curvilinear joint limits an open path to its ends
  if (!joint.curvilinear_path.periodic) {
    joint.limits.lower.set(0, 0);
    joint.limits.upper.set(0, joint.curvilinear_path.TotalLength());
  }
  return true;
}
}  // namespace

// F is the drake:parent frame and M the drake:child frame, links or explicit
// frames alike: the joint's node stands for M, and the pass takes F from the
// parent frame itself (JointFrameSpec::frames_given).
void SdfReader::AddDrakeJointFrames(JointId joint, const ModelScope& s,
                                    const ir::Ref<BodyId>& parent,
                                    const ir::Ref<BodyId>& child) {
  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Joint;
  node.name = module()[joint].name;
  node.loc = module()[joint].loc;
  node.relative_to = {child.name, child.loc};
  node.attached_to = {child.name, child.loc};
  node.target = ir::FrameTarget::Joint;
  node.target_index = joint.value;
  ir::JointFrameSpec spec;
  spec.joint = joint;
  spec.node = AddNode(s, std::move(node));
  spec.parent = {parent.name, parent.loc};
  spec.frames_given = true;
  graph().joints.push_back(spec);
}

void SdfReader::ReadDrakeJoint(const xml::XmlElement& e, ModelScope& s) {
  // name and type first, as Drake reads them
  attrs_.WarnUnknownAttributes(e, {"name", "type"});
  const xml::XmlAttribute type_attr = e.Attribute("type");
  const xml::XmlAttribute name_attr = e.Attribute("name");
  if (!type_attr.present()) {
    diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                   "<drake:joint> needs a 'type' attribute (planar or curvilinear)");
    return;
  }
  if (!name_attr.present()) {
    diags().Report(DiagKind::MissingAttribute, e.GetLoc(), "<drake:joint> needs a name");
    return;
  }
  const std::string name(name_attr.value);
  const std::string type(type_attr.value);
  if (!CheckDefinedName(name, name_attr.loc, "joint")) return;
  if (auto pose = e.Child("pose")) {
    diags().Report(DiagKind::NotImplemented, pose.GetLoc(),
                   "<pose> in <drake:joint> is not supported yet: the joint's frames are those "
                   "named by <drake:parent> and <drake:child>");
    return;
  }
  ir::JointType joint_type;
  if (type == "planar") {
    joint_type = ir::JointType::Planar;
  } else if (type == "curvilinear") {
    joint_type = ir::JointType::Curvilinear;
  } else {
    diags().Report(DiagKind::BadValue, type_attr.loc,
                   fmt::format("<drake:joint> '{}' has unknown type '{}'; the types are planar "
                               "and curvilinear",
                               name, type));
    return;
  }
  DrakeChildReader r(e,
                     {"drake:parent", "drake:child", "drake:damping", "drake:initial_tangent",
                      "drake:plane_normal", "drake:is_periodic", "drake:curves", "pose"},
                     ValueSpelling::Text, attrs_, module(), {},
                     /*check_attributes=*/false);  // name and type: checked above
  // drake:parent / drake:child: a link or any frame (scoped names reach into
  // nested models); the resolve-frames pass binds F and M to them
  ir::Ref<BodyId> parent, child;
  if (!r.Name("drake:parent", parent)) return;
  if (!r.Name("drake:child", child)) return;

  ir::Joint joint;
  joint.name = module().Intern(name);
  joint.model = s.model;
  joint.loc = e.GetLoc();
  joint.type = joint_type;
  joint.parent = parent;
  joint.child = child;
  const int nv = ir::JointVelocityCount(joint_type);
  joint.limits = ir::JointLimits::Unbounded(nv);
  joint.damping.assign(nv, 0.0);
  // a drake:joint shares the joint namespace of its model (COMMON-023)
  if (JointNameTaken(s.model, joint.name)) {
    // the first joint of the name, for the note: a scan, on an error only
    const auto& joints = module().joints;
    const auto first = std::find_if(joints.begin(), joints.end(), [&](const ir::Joint& other) {
      return other.model == s.model && other.name == joint.name;
    });
    diags()
        .Report(DiagKind::DuplicateName, name_attr.loc,
                fmt::format("the joint name '{}' is already used by a joint of this model", name))
        .Note(first->loc, "first defined here");
    return;
  }
  const bool ok = joint_type == ir::JointType::Planar
                      ? ReadPlanar(*this, e, r, name, joint)
                      : ReadCurvilinear(*this, e, r, name, joint);
  if (!ok) return;
  AddDrakeJointFrames(module().Add(std::move(joint)), s, parent, child);
}

}  // namespace mdlc::frontend::sdf
