// sdf_drake_elements.cc - drake: elements of an SDFormat model and of its
// joints (EXT-001, EXT-010, EXT-012..014, EXT-040, EXT-050..054, SDF-021).
//
// SDFormat spells Drake's extensions with element text
// (<drake:bushing_torque_stiffness>1 2 3</drake:bushing_torque_stiffness>)
// where URDF uses attributes. The model-level elements other than
// drake:joint are read by the reader both formats share (drake_elements.h);
// drake:joint is sdf_drake_joint.cc's. References stay names (with the
// location of the element that wrote them) for resolve-names, which looks
// them up in the element's model instance, `a::b` in nested ones; rules that
// need resolved entities are the check-model-elements and check-joints
// passes'.
#include <fmt/format.h>

#include <string>

#include "frontend/drake_elements.h"
#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {

// --- model-level drake: elements, read after every link, joint and nested
// model of the model ---

void SdfReader::ReadDrakeModelElement(const xml::XmlElement& e, ModelScope& s) {
  if (e.Name() == "drake:joint") {
    ReadDrakeJoint(e, s);
    return;
  }
  // Any other drake: element is unknown (SDF-001: a warning). The model
  // reader's CheckChildren reports it, since it does not list it among the
  // model's children; nothing more to say here.
  ReadDrakeModelLevelElement(e, {module(), attrs_, s.model, ValueSpelling::Text});
}

// --- drake: children of a <joint> (EXT-010, EXT-012..014, SDF-021) ---

// SDFormat 1.11's <axis><mimic joint axis><multiplier><offset><reference>:
// follower = multiplier (leader - reference) + offset, the linear relation
// <drake:mimic> states with offset' = offset - multiplier reference. Drake
// reads only <drake:mimic>; mdlc reads both (the README lists it), the Drake
// element first when a joint has both.
void SdfReader::ReadAxisMimic(const xml::XmlElement& joint_element, ModelScope& s,
                              JointId joint_id) {
  const ir::Joint& joint = module()[joint_id];
  const std::string joint_name(module().Text(joint.name));
  for (const char* axis_tag : {"axis", "axis2"}) {
    const xml::XmlElement axis = joint_element.Child(axis_tag);
    const xml::XmlElement mimic = axis ? axis.Child("mimic") : xml::XmlElement();
    if (!mimic) continue;
    attrs_.WarnUnknownAttributes(mimic, {"joint", "axis"});
    CheckChildren(mimic, {"multiplier", "offset", "reference"});
    const int nv = ir::JointVelocityCount(joint.type);
    auto ignored = [&](std::string why) {
      diags().Report(DiagKind::JointWarning, mimic.GetLoc(),
                     fmt::format("<mimic> of joint '{}' is ignored: {}", joint_name, why));
    };
    if (std::string_view(axis_tag) == "axis2" || nv != 1 || joint.type == ir::JointType::Weld) {
      ignored(fmt::format("a coupler joins single-dof joints, and this is the <{}> of a {} joint",
                          axis_tag, ir::JointTypeName(joint.type)));
      continue;
    }
    if (const xml::XmlElement drake = joint_element.Child("drake:mimic")) {
      ignored("the joint's <drake:mimic> is read instead");
      continue;
    }
    auto leader = attrs_.String(mimic, "joint", xml::Need::Required);
    if (!leader) continue;
    if (leader->empty() || *leader == joint_name) {
      diags().Report(DiagKind::BadValue, mimic.Attribute("joint").loc,
                     leader->empty() ? fmt::format("<mimic> of joint '{}' names no joint",
                                                   joint_name)
                                     : fmt::format("<mimic> of joint '{}' names joint '{}' "
                                                   "itself; a joint cannot follow itself",
                                                   joint_name, *leader));
      continue;
    }
    if (const xml::XmlAttribute leader_axis = mimic.Attribute("axis");
        leader_axis.present() && leader_axis.value != "axis") {
      ignored(fmt::format("it follows the '{}' of joint '{}', and a coupler follows a "
                          "single-dof joint's only axis",
                          leader_axis.value, *leader));
      continue;
    }
    // SDFormat's defaults where the element is left out
    const double multiplier = ChildDouble(mimic, "multiplier").value_or(1.0);
    const double offset = ChildDouble(mimic, "offset").value_or(0.0);
    const double reference = ChildDouble(mimic, "reference").value_or(0.0);
    ir::CouplerConstraint c;
    c.joint0 = {joint.name, joint.loc, {}};  // the follower, as in Drake
    c.joint1 = {module().Intern(*leader), mimic.Attribute("joint").loc, {}};
    c.gear_ratio = multiplier;
    c.offset = offset - multiplier * reference;
    module().Add(ir::Constraint{s.model, mimic.GetLoc(), std::move(c)});
  }
}

void SdfReader::ReadJointDrakeChildren(const xml::XmlElement& joint_element, ModelScope& s,
                                       JointId joint_id, std::optional<ActuatorId> actuator) {
  const ir::Joint& joint = module()[joint_id];
  const std::string joint_name(module().Text(joint.name));
  for (auto child = joint_element.FirstChild(); child; child = child.NextSibling()) {
    const std::string_view tag = child.Name();
    if (tag != "drake:mimic" && tag != "drake:rotor_inertia" && tag != "drake:gear_ratio" &&
        tag != "drake:controller_gains") {
      continue;  // other children are the joint reader's (it warns on unknown drake: ones)
    }
    // as in Drake, the first element of each name counts
    if (auto first = joint_element.Child(tag); first.raw() != child.raw()) {
      diags()
          .Report(DiagKind::UnsupportedElement, child.GetLoc(),
                  fmt::format("<{}> is given more than once in joint '{}'; only the first one "
                              "is used, this one is ignored",
                              tag, joint_name))
          .Note(first.GetLoc(), fmt::format("the first <{}> is here", tag));
      continue;
    }

    if (tag == "drake:mimic") {
      // q_joint = multiplier * q_other + offset: a coupler constraint whose
      // joint1 is this joint (EXT-010). Attributes, all required.
      attrs_.WarnUnknownAttributes(child, {"joint", "multiplier", "offset"});
      bool ok = true;
      for (const char* attr : {"joint", "multiplier", "offset"}) {
        if (!child.Attribute(attr).present()) {
          diags().Report(DiagKind::MissingAttribute, child.GetLoc(),
                         fmt::format("<drake:mimic> of joint '{}' needs attribute '{}'",
                                     joint_name, attr));
          ok = false;
        }
      }
      if (!ok) continue;
      const xml::XmlAttribute other = child.Attribute("joint");
      auto multiplier = attrs_.Double(child, "multiplier", xml::Need::Required);
      auto offset = attrs_.Double(child, "offset", xml::Need::Required);
      if (other.value.empty()) {
        diags().Report(DiagKind::MissingAttribute, other.loc,
                       fmt::format("<drake:mimic> of joint '{}' has an empty 'joint'",
                                   joint_name));
        continue;
      }
      if (other.value == joint_name) {
        diags().Report(DiagKind::BadValue, other.loc,
                       fmt::format("<drake:mimic> of joint '{}' names joint '{}' itself; a "
                                   "joint cannot follow itself",
                                   joint_name, other.value));
        continue;
      }
      if (!multiplier || !offset) continue;
      // Drake ignores mimic unless both joints are single-dof (a warning);
      // this joint's dofs are known now, the other's after resolve-names
      if (const int nv = ir::JointVelocityCount(joint.type);
          nv != 1 || joint.type == ir::JointType::Weld) {
        diags().Report(DiagKind::JointWarning, child.GetLoc(),
                       fmt::format("<drake:mimic> of joint '{}' ({}, {} dofs) is ignored: a "
                                   "coupler joins single-dof joints",
                                   joint_name, ir::JointTypeName(joint.type),
                                   joint.type == ir::JointType::Weld ? 0 : nv));
        continue;
      }
      ir::CouplerConstraint c;
      c.joint0 = {joint.name, joint.loc, {}};  // the follower, as in Drake
      c.joint1 = {module().Intern(other.value), other.loc, {}};
      c.gear_ratio = *multiplier;
      c.offset = *offset;
      module().Add(ir::Constraint{s.model, child.GetLoc(), std::move(c)});
      continue;
    }

    // actuator parameters (SDF-021): Drake reads them only for a joint that
    // got an actuator, and ignores them otherwise; mdlc says so
    if (!actuator) {
      diags().Report(DiagKind::ActuatorWarning, child.GetLoc(),
                     fmt::format("<{}> is ignored: joint '{}' has no actuator (an actuator is "
                                 "made for a revolute, continuous, prismatic or screw joint "
                                 "whose effort limit is not 0)",
                                 tag, joint_name));
      continue;
    }
    ir::Actuator& a = module().actuators[actuator->index()];
    auto text_value = [&](bool zero_allowed, std::string_view what) -> std::optional<double> {
      auto v = TextDouble(child);
      if (!v) return std::nullopt;
      if (zero_allowed ? *v >= 0 : *v > 0) return v;
      diags().Report(DiagKind::BadValue, child.GetLoc(),
                     fmt::format("the {} given by <{}> must be {}, got {}", what, tag,
                                 zero_allowed ? "non-negative" : "positive", *v));
      return std::nullopt;
    };
    if (tag == "drake:rotor_inertia") {
      // EXT-012: kg·m² (revolute) or kg (prismatic)
      attrs_.WarnUnknownAttributes(child, {});
      if (auto v = text_value(true, "rotor inertia")) a.rotor_inertia = *v;
    } else if (tag == "drake:gear_ratio") {
      // EXT-013: reflected inertia = gear_ratio² · rotor_inertia
      attrs_.WarnUnknownAttributes(child, {});
      if (auto v = text_value(true, "gear ratio")) a.gear_ratio = *v;
    } else {
      // EXT-014: <drake:controller_gains p="..." d="..."/>, both required
      attrs_.WarnUnknownAttributes(child, {"p", "d"});
      auto gain = [&](std::string_view attr, bool zero_allowed,
                      std::string_view what) -> std::optional<double> {
        if (!child.Attribute(attr).present()) {
          diags().Report(DiagKind::MissingAttribute, child.GetLoc(),
                         fmt::format("<drake:controller_gains> needs attribute '{}'",
                                     attr));
          return std::nullopt;
        }
        auto v = attrs_.Double(child, attr, xml::Need::Required);
        if (!v) return std::nullopt;
        if (zero_allowed ? *v >= 0 : *v > 0) return v;
        diags().Report(DiagKind::BadValue, child.Attribute(attr).loc,
                       fmt::format("the {} given by <drake:controller_gains> must be {}, got {}",
                                   what, zero_allowed ? "non-negative" : "positive", *v));
        return std::nullopt;
      };
      auto p = gain("p", false, "proportional gain 'p'");
      auto d = gain("d", true, "derivative gain 'd'");
      if (p && d) {
        a.kp = *p;
        a.kd = *d;
      }
    }
  }
  ReadAxisMimic(joint_element, s, joint_id);
}

}  // namespace mdlc::frontend::sdf
