// urdf_transmission.cc - <transmission>: actuators, as Drake makes them
// (URDF-020..024). Read after every joint, so a transmission may name a joint
// defined later in the file.
#include <fmt/format.h>

#include <cmath>

#include "frontend/original_names.h"
#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
bool IsSilentlyIgnored(std::string_view tag) { return tag == "hardwareInterface"; }
}  // namespace

void UrdfReader::ReadTransmission(const xml::XmlElement& e) {
  auto warn_unsupported = [&](const xml::XmlElement& el, std::string_view parent) {
    diags().Report(DiagKind::UnsupportedElement, el.GetLoc(),
                   fmt::format("element <{}> in <{}> is not supported and is ignored",
                               el.Name(), parent));
  };
  auto check_reduction = [&](const xml::XmlElement& el) {
    // a reduction of exactly 1 changes nothing; any other is not applied (URDF-022)
    auto value = xml::ParseDouble(el.Text());
    if (!value || *value != 1.0) {
      diags().Report(DiagKind::UnsupportedValue, el.GetLoc(),
                     fmt::format("mechanicalReduction '{}' is not applied: the actuator's gear "
                                 "ratio stays 1",
                                 el.Text()));
    }
  };
  if (auto name = e.Attribute("name"); name.present() && !said_transmission_name_) {
    said_transmission_name_ = true;
    diags().Report(DiagKind::UnsupportedAttribute, name.loc,
                   "attribute 'name' of <transmission> is ignored: the plant names the actuator "
                   "by its <actuator name> (said once per file)");
  }
  // the type: a <type> child or the legacy attribute
  std::string type;
  if (auto type_element = e.Child("type")) {
    type = type_element.Text();
  } else if (auto attr = e.Attribute("type"); attr.present()) {
    type = std::string(attr.value);
  } else {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   "<transmission> has no type (a <type> element or a 'type' attribute)");
    return;
  }
  if (type.find("SimpleTransmission") == std::string::npos) {
    diags().Report(DiagKind::UnsupportedValue, e.GetLoc(),
                   fmt::format("transmission type '{}' is not supported (only "
                               "SimpleTransmission); no actuator is created",
                               type));
    return;
  }
  xml::XmlElement actuator, joint;
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    std::string_view tag = c.Name();
    if (tag == "type") continue;
    if (tag == "actuator" && !actuator) {
      actuator = c;
    } else if (tag == "joint" && !joint) {
      joint = c;
    } else if (tag == "mechanicalReduction") {
      check_reduction(c);
    } else if (IsSilentlyIgnored(tag)) {
    } else {
      warn_unsupported(c, "transmission");
    }
  }
  if (!actuator) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(), "<transmission> has no <actuator>");
    return;
  }
  if (!joint) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(), "<transmission> has no <joint>");
    return;
  }
  ir::Actuator a;
  for (const auto& part : {actuator, joint}) {
    for (auto c = part.FirstChild(); c; c = c.NextSibling()) {
      if (c.Name() == "mechanicalReduction") {
        check_reduction(c);
      } else if (part.raw() == actuator.raw() && ReadActuatorExtension(c, a)) {
        // drake:rotor_inertia, drake:gear_ratio, drake:controller_gains
      } else if (!IsSilentlyIgnored(c.Name())) {
        warn_unsupported(c, part.Name());
      }
    }
  }
  auto actuator_name = attrs_.String(actuator, "name", xml::Need::Required);
  auto joint_name = attrs_.String(joint, "name", xml::Need::Required);
  if (!actuator_name || !joint_name) return;

  auto it = joint_ids_.find(module().Intern(*joint_name).value);
  if (it == joint_ids_.end()) {
    diags().Report(DiagKind::UnknownReference, joint.Attribute("name").loc,
                   fmt::format("transmission names unknown joint '{}'", *joint_name));
    return;
  }
  const ir::Joint& target = module()[it->second];
  if (target.type == ir::JointType::Weld) {
    diags().Report(DiagKind::ActuatorWarning, joint.GetLoc(),
                   fmt::format("transmission on fixed joint '{}' is ignored: a fixed joint "
                               "cannot be actuated",
                               *joint_name));
    return;
  }
  const double effort = target.limits.effort.empty() ? std::numeric_limits<double>::infinity()
                                                     : target.limits.effort[0];
  if (effort < 0) {
    diags().Report(DiagKind::BadValue, joint.GetLoc(),
                   fmt::format("joint '{}' has a negative effort limit", *joint_name));
    return;
  }
  if (effort == 0) {
    diags().Report(DiagKind::ActuatorWarning, joint.GetLoc(),
                   fmt::format("joint '{}' has an effort limit of zero: no actuator is created",
                               *joint_name));
    return;
  }
  a.name = module().Intern(*actuator_name);
  a.model = model_;
  a.loc = actuator.GetLoc();
  a.joint = {target.name, joint.Attribute("name").loc, {}};
  a.effort_limit = effort;
  const ActuatorId id = module().Add(std::move(a));
  ReadOriginalName(actuator, id, ctx_);
}

bool UrdfReader::ReadActuatorExtension(const xml::XmlElement& child, ir::Actuator& actuator) {
  std::string_view tag = child.Name();
  if (tag != "drake:rotor_inertia" && tag != "drake:gear_ratio" && tag != "drake:controller_gains") {
    return false;
  }
  // as in Drake, the first element of each name counts
  if (auto first = child.Parent().Child(tag); first.raw() != child.raw()) {
    diags()
        .Report(DiagKind::UnsupportedElement, child.GetLoc(),
                fmt::format("<{}> is given more than once in <actuator>; only the first one is "
                            "used, this one is ignored",
                            tag))
        .Note(first.GetLoc(), fmt::format("the first <{}> is here", tag));
    return true;
  }
  // a number that must not be negative (p: must be positive)
  auto read = [&](std::string_view attr, bool zero_allowed,
                  std::string_view what) -> std::optional<double> {
    auto v = attrs_.Double(child, attr, xml::Need::Required);
    if (!v) return std::nullopt;
    if (zero_allowed ? *v >= 0 : *v > 0) return v;
    diags().Report(DiagKind::BadValue, child.Attribute(attr).loc,
                   fmt::format("the {} given by <{}> must be {}, got {}", what, tag,
                               zero_allowed ? "non-negative" : "positive", *v));
    return std::nullopt;
  };
  if (tag == "drake:rotor_inertia") {
    // EXT-012: kg·m² (revolute) or kg (prismatic)
    attrs_.WarnUnknownAttributes(child, {"value"});
    if (auto v = read("value", true, "rotor inertia")) actuator.rotor_inertia = *v;
  } else if (tag == "drake:gear_ratio") {
    // EXT-013: reflected inertia = gear_ratio² · rotor_inertia
    attrs_.WarnUnknownAttributes(child, {"value"});
    if (auto v = read("value", true, "gear ratio")) actuator.gear_ratio = *v;
  } else {
    // EXT-014: both gains are required
    attrs_.WarnUnknownAttributes(child, {"p", "d"});
    auto p = read("p", false, "proportional gain 'p'");
    auto d = read("d", true, "derivative gain 'd'");
    if (p && d) {
      actuator.kp = *p;
      actuator.kd = *d;
    }
  }
  return true;
}

}  // namespace mdlc::frontend::urdf
