// urdf_drake_joint.cc - <drake:joint> (EXT-001..003): Drake's custom joint
// types ball, universal, screw, planar and curvilinear.
//
// A <drake:joint> has the children of a <joint>, read by the same code
// (UrdfReader::ReadAnyJoint in urdf_joint.cc), which calls back here for the
// parameters only Drake's types have: a screw's thread pitch and a
// curvilinear joint's path.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
// Drake's tolerance for "perpendicular" between a curvilinear path's initial
// tangent and its plane normal (RotationMatrix's orthonormality tolerance)
constexpr double kPerpendicularTolerance = 128 * std::numeric_limits<double>::epsilon();
}  // namespace

void UrdfReader::ReadDrakeJoint(const xml::XmlElement& e) {
  ReadAnyJoint(e, /*drake_element=*/true);
}

void UrdfReader::ReadScrewThreadPitch(const xml::XmlElement& e, ir::Joint& joint) {
  // EXT-002: required, in meters per revolution; the sign gives the hand
  const std::string_view name = module().Text(joint.name);
  auto pitch = e.Child("drake:screw_thread_pitch");
  if (!pitch) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   fmt::format("screw joint '{}' is missing its <drake:screw_thread_pitch> "
                               "element (the advance per revolution, in meters)",
                               name));
    return;
  }
  attrs_.WarnUnknownAttributes(pitch, {"value"});
  auto value = attrs_.Double(pitch, "value", xml::Need::Required);
  if (!value) return;
  if (*value == 0) {
    diags().Report(DiagKind::BadValue, pitch.Attribute("value").loc,
                   fmt::format("screw joint '{}': the thread pitch must not be zero", name));
    return;
  }
  joint.screw_thread_pitch = *value;
}

bool UrdfReader::ReadCurvilinearPath(const xml::XmlElement& e, ir::Joint& joint) {
  // EXT-003: a planar path of lines and arcs, in the joint frame F, starting
  // at F's origin
  const std::string_view name = module().Text(joint.name);
  ir::CurvilinearPath path;
  bool ok = true;

  // drake:plane_normal (default +z) and drake:initial_tangent (default +x)
  auto read_direction = [&](std::string_view tag, Eigen::Vector3d& out) -> Loc {
    auto c = e.Child(tag);
    if (!c) return {};
    attrs_.WarnUnknownAttributes(c, {"xyz"});
    auto xyz = attrs_.Vector3(c, "xyz", xml::Need::Required);
    if (!xyz) {
      ok = false;
      return {};
    }
    if (xyz->norm() == 0) {
      diags().Report(DiagKind::ZeroAxis, c.Attribute("xyz").loc,
                     fmt::format("curvilinear joint '{}': <{}> is zero; it must have a direction",
                                 name, tag));
      ok = false;
      return {};
    }
    out = *xyz;
    return c.Attribute("xyz").loc;
  };
  read_direction("drake:plane_normal", path.plane_normal);
  const Loc tangent_loc = read_direction("drake:initial_tangent", path.initial_tangent);
  if (ok && std::abs(path.initial_tangent.normalized().dot(path.plane_normal.normalized())) >
                kPerpendicularTolerance) {
    diags().Report(DiagKind::BadValue, tangent_loc.valid() ? tangent_loc : e.GetLoc(),
                   fmt::format("curvilinear joint '{}': the initial tangent [{} {} {}] is not "
                               "perpendicular to the plane normal [{} {} {}]",
                               name, path.initial_tangent.x(), path.initial_tangent.y(),
                               path.initial_tangent.z(), path.plane_normal.x(),
                               path.plane_normal.y(), path.plane_normal.z()));
    ok = false;
  }

  // drake:is_periodic: Drake takes exactly "true" as true, anything else as false
  if (auto p = e.Child("drake:is_periodic")) {
    attrs_.WarnUnknownAttributes(p, {"value"});
    auto value = p.Attribute("value");
    if (!value.present()) {
      diags().Report(DiagKind::JointWarning, p.GetLoc(),
                     fmt::format("<drake:is_periodic> of curvilinear joint '{}' has no 'value'; "
                                 "the path is not periodic",
                                 name));
    } else if (value.value == "true") {
      path.periodic = true;
    } else if (value.value != "false") {
      diags().Report(DiagKind::JointWarning, value.loc,
                     fmt::format("<drake:is_periodic> value '{}' is not 'true' or 'false'; as in "
                                 "Drake, the path of joint '{}' is not periodic",
                                 value.value, name));
    }
  }

  // drake:curves: the pieces, in order
  auto curves = e.Child("drake:curves");
  if (!curves) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   fmt::format("curvilinear joint '{}' is missing its <drake:curves> list", name));
    return false;
  }
  attrs_.WarnUnknownAttributes(curves, {});
  bool any_curve = false;
  for (auto c = curves.FirstChild(); c; c = c.NextSibling()) {
    any_curve = true;
    const std::string_view tag = c.Name();
    if (tag == "drake:line_segment") {
      attrs_.WarnUnknownAttributes(c, {"length"});
      auto length = attrs_.Double(c, "length", xml::Need::Required);
      if (!length) {
        ok = false;
      } else if (*length <= 0) {
        diags().Report(DiagKind::BadValue, c.Attribute("length").loc,
                       fmt::format("curvilinear joint '{}': a <drake:line_segment> length must "
                                   "be positive, got {}",
                                   name, *length));
        ok = false;
      } else {
        path.segments.push_back({*length, 0.0});
      }
    } else if (tag == "drake:circular_arc") {
      attrs_.WarnUnknownAttributes(c, {"radius", "angle"});
      const auto radius = attrs_.Double(c, "radius", xml::Need::Required);
      const auto angle = attrs_.Double(c, "angle", xml::Need::Required);
      bool arc_ok = radius.has_value() && angle.has_value();
      if (radius && *radius <= 0) {
        diags().Report(DiagKind::BadValue, c.Attribute("radius").loc,
                       fmt::format("curvilinear joint '{}': a <drake:circular_arc> radius must "
                                   "be positive, got {}",
                                   name, *radius));
        arc_ok = false;
      }
      if (angle && *angle == 0) {
        diags().Report(DiagKind::BadValue, c.Attribute("angle").loc,
                       fmt::format("curvilinear joint '{}': a <drake:circular_arc> angle must "
                                   "not be zero",
                                   name));
        arc_ok = false;
      }
      if (!arc_ok) {
        ok = false;
        continue;
      }
      // the sign of the angle is the direction of the turn about the plane
      // normal: curvature = angle / length = sign(angle) / radius
      const double r = radius.value(), a = angle.value();
      const double length = r * std::abs(a);
      if (!(length > 0 && std::isfinite(length))) {
        diags().Report(DiagKind::BadValue, c.GetLoc(),
                       fmt::format("curvilinear joint '{}': the <drake:circular_arc> length "
                                   "(radius times |angle|) is {}; it must be positive and finite",
                                   name, length));
        ok = false;
        continue;
      }
      path.segments.push_back({length, a / length});
    } else {
      diags().Report(DiagKind::BadValue, c.GetLoc(),
                     fmt::format("curvilinear joint '{}': <drake:curves> may hold only "
                                 "<drake:line_segment> and <drake:circular_arc>, not <{}>",
                                 name, tag));
      ok = false;
    }
  }
  if (!any_curve) {
    diags().Report(DiagKind::MissingElement, curves.GetLoc(),
                   fmt::format("curvilinear joint '{}' has an empty <drake:curves> list", name));
    return false;
  }
  if (!ok) return false;
  joint.curvilinear_path = std::move(path);
  return true;
}

}  // namespace mdlc::frontend::urdf
