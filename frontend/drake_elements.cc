// drake_elements.cc - see drake_elements.h. Each element is read into its
// kind's IR payload (ir::LinearBushingRpy, ir::BallConstraint, ...), which
// becomes an entity of the element's model instance.
#include "frontend/drake_elements.h"

#include <fmt/format.h>

#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "frontend/xml/trim.h"

namespace mdlc::frontend {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// --- the IR entity: each element is read into its kind's payload ---

void Add(const DrakeElementContext& ctx, Loc loc, ir::ForceElementPayload payload) {
  ctx.module.Add(ir::ForceElement{ctx.model, loc, std::move(payload)});
}
void Add(const DrakeElementContext& ctx, Loc loc, ir::ConstraintPayload payload) {
  ctx.module.Add(ir::Constraint{ctx.model, loc, std::move(payload)});
}

/// Whether <drake:collision_filter_group ignore> skips the group. The formats
/// read it differently: Drake's URDF parser skips exactly on "true", the
/// SDFormat one reads an SDFormat boolean (true/1, false/0). A value that is
/// neither is reported and the group read.
bool IgnoresGroup(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  const xml::XmlAttribute ignore = e.Attribute("ignore");
  if (!ignore.present()) return false;
  const bool urdf = ctx.spelling == ValueSpelling::Attribute;
  const std::string_view v = urdf ? ignore.value : xml::Trim(ignore.value);
  if (v == "true" || (!urdf && v == "1")) return true;
  if (v != "false" && !(!urdf && v == "0")) {
    ctx.attrs.diags().Report(
        DiagKind::UnsupportedValue, ignore.loc,
        fmt::format("attribute 'ignore' of <drake:collision_filter_group> is '{}'; only {} "
                    "skips the group, so it is read",
                    ignore.value, urdf ? "'true'" : "'true' or '1'"));
  }
  return false;
}
}  // namespace

// The group's own rules (COMMON-050) and its references (COMMON-053) are
// checked once every model is read (COMMON-055).
void ReadDrakeCollisionFilterGroup(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  // a skipped group is skipped silently, even a broken one, as in Drake
  if (IgnoresGroup(e, ctx)) return;
  ctx.attrs.WarnUnknownAttributes(e, {"name", "ignore"});
  constexpr std::string_view kMember = "drake:member";
  constexpr std::string_view kMemberGroup = "drake:member_group";
  constexpr std::string_view kIgnoredGroup = "drake:ignored_collision_filter_group";
  DrakeChildReader r(e, {kMember, kMemberGroup, kIgnoredGroup}, ctx.spelling, ctx.attrs,
                     ctx.module, /*repeatable=*/{kMember, kMemberGroup, kIgnoredGroup},
                     /*check_attributes=*/false);
  // the group's name is an attribute in both formats
  const xml::XmlAttribute name = e.Attribute("name");
  if (!name.present() || name.value.empty()) {
    r.Fail(name.present() ? name.loc : e.GetLoc(), "<drake:collision_filter_group> needs a name",
           DiagKind::MissingAttribute);
  }

  ir::CollisionFilterGroup group;
  group.model = ctx.model;
  group.loc = e.GetLoc();
  // a member is a link, in @link for URDF; groups are named in @name
  auto reference = [&](const xml::XmlElement& c, std::string_view attr, auto& refs) {
    const bool attribute = ctx.spelling == ValueSpelling::Attribute;
    if (!attribute) ctx.attrs.WarnUnknownAttributes(c, {});
    typename std::remove_reference_t<decltype(refs)>::value_type ref;
    if (!r.NameOf(c, ref, attr)) return;
    if (attribute) ctx.attrs.WarnUnknownAttributes(c, {attr});
    refs.push_back(std::move(ref));
  };
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view tag = c.Name();
    if (tag == kMember) {
      reference(c, "link", group.members);
    } else if (tag == kMemberGroup) {
      reference(c, "name", group.member_groups);
    } else if (tag == kIgnoredGroup) {
      reference(c, "name", group.ignored_groups);
    }
  }
  if (!r.ok()) return;
  group.name = ctx.module.Intern(name.value);
  ctx.module.Add(std::move(group));
}

// Frames A and C (a <frame> or a link's own frame) and four gain vectors,
// every child required; Drake's LinearBushingRollPitchYaw requires every
// gain to be >= 0.
void ReadDrakeLinearBushing(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  DrakeChildReader r(e,
                     {"drake:bushing_frameA", "drake:bushing_frameC",
                      "drake:bushing_torque_stiffness", "drake:bushing_torque_damping",
                      "drake:bushing_force_stiffness", "drake:bushing_force_damping"},
                     ctx.spelling, ctx.attrs, ctx.module);
  ir::LinearBushingRpy v;
  r.Name("drake:bushing_frameA", v.frame_A);
  r.Name("drake:bushing_frameC", v.frame_C);
  auto torque_stiffness = r.Vector("drake:bushing_torque_stiffness", Sign::NonNegative);
  auto torque_damping = r.Vector("drake:bushing_torque_damping", Sign::NonNegative);
  auto force_stiffness = r.Vector("drake:bushing_force_stiffness", Sign::NonNegative);
  auto force_damping = r.Vector("drake:bushing_force_damping", Sign::NonNegative);
  if (!r.ok()) return;
  v.torque_stiffness = *torque_stiffness;
  v.torque_damping = *torque_damping;
  v.force_stiffness = *force_stiffness;
  v.force_damping = *force_damping;
  Add(ctx, e.GetLoc(), std::move(v));
}

// Every child required; free length > 0, stiffness and damping >= 0 (Drake's
// parsers and LinearSpringDamper).
void ReadDrakeLinearSpringDamper(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  DrakeChildReader r(e,
                     {"drake:linear_spring_damper_body_A", "drake:linear_spring_damper_p_AP",
                      "drake:linear_spring_damper_body_B", "drake:linear_spring_damper_p_BQ",
                      "drake:linear_spring_damper_free_length",
                      "drake:linear_spring_damper_stiffness",
                      "drake:linear_spring_damper_damping"},
                     ctx.spelling, ctx.attrs, ctx.module);
  ir::LinearSpringDamper v;
  r.Name("drake:linear_spring_damper_body_A", v.body_A);
  r.Name("drake:linear_spring_damper_body_B", v.body_B);
  auto p_AP = r.Vector("drake:linear_spring_damper_p_AP");
  auto p_BQ = r.Vector("drake:linear_spring_damper_p_BQ");
  auto free_length =
      r.Scalar("drake:linear_spring_damper_free_length", xml::Need::Required, Sign::Positive);
  auto stiffness =
      r.Scalar("drake:linear_spring_damper_stiffness", xml::Need::Required, Sign::NonNegative);
  auto damping =
      r.Scalar("drake:linear_spring_damper_damping", xml::Need::Required, Sign::NonNegative);
  if (!r.ok()) return;
  v.p_AP = *p_AP;
  v.p_BQ = *p_BQ;
  v.free_length = *free_length;
  v.stiffness = *stiffness;
  v.damping = *damping;
  Add(ctx, e.GetLoc(), std::move(v));
}

// Bodies A and B, points P (in A) and Q (in B), all required. Distinct
// bodies are checked after resolution.
void ReadDrakeBallConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  DrakeChildReader r(e,
                     {"drake:ball_constraint_body_A", "drake:ball_constraint_body_B",
                      "drake:ball_constraint_p_AP", "drake:ball_constraint_p_BQ"},
                     ctx.spelling, ctx.attrs, ctx.module);
  ir::BallConstraint v;
  r.Name("drake:ball_constraint_body_A", v.body_A);
  r.Name("drake:ball_constraint_body_B", v.body_B);
  auto p_AP = r.Vector("drake:ball_constraint_p_AP");
  auto p_BQ = r.Vector("drake:ball_constraint_p_BQ");
  if (!r.ok()) return;
  v.p_AP = *p_AP;
  v.p_BQ = *p_BQ;
  Add(ctx, e.GetLoc(), std::move(v));
}

// Every child required; distance > 0, stiffness > 0 (+inf: a rigid
// constraint, AddDistanceConstraint's default), damping >= 0.
void ReadDrakeDistanceConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  DrakeChildReader r(e,
                     {"drake:distance_constraint_body_A", "drake:distance_constraint_p_AP",
                      "drake:distance_constraint_body_B", "drake:distance_constraint_p_BQ",
                      "drake:distance_constraint_distance", "drake:distance_constraint_stiffness",
                      "drake:distance_constraint_damping"},
                     ctx.spelling, ctx.attrs, ctx.module);
  ir::DistanceConstraint v;
  r.Name("drake:distance_constraint_body_A", v.body_A);
  r.Name("drake:distance_constraint_body_B", v.body_B);
  auto p_AP = r.Vector("drake:distance_constraint_p_AP");
  auto p_BQ = r.Vector("drake:distance_constraint_p_BQ");
  auto distance =
      r.Scalar("drake:distance_constraint_distance", xml::Need::Required, Sign::Positive);
  auto stiffness = r.Scalar("drake:distance_constraint_stiffness", xml::Need::Required,
                            Sign::Positive, {.positive = true});
  auto damping =
      r.Scalar("drake:distance_constraint_damping", xml::Need::Required, Sign::NonNegative);
  if (!r.ok()) return;
  v.p_AP = *p_AP;
  v.p_BQ = *p_BQ;
  v.distance = *distance;
  v.stiffness = *stiffness;
  v.damping = *damping;
  Add(ctx, e.GetLoc(), std::move(v));
}

// One or more <drake:tendon_constraint_joint name a> (attributes in both
// formats, as Drake reads them), then optional offset, limits, stiffness and
// damping with AddTendonConstraint's defaults (offset 0, limits -inf/+inf,
// stiffness +inf, damping 0) and its preconditions: a finite bound on at
// least one side, lower <= upper, stiffness > 0, damping >= 0. Single-dof and
// distinct joints are checked after resolution.
void ReadDrakeTendonConstraint(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  constexpr std::string_view kJoint = "drake:tendon_constraint_joint";
  DrakeChildReader r(e,
                     {kJoint, "drake:tendon_constraint_offset",
                      "drake:tendon_constraint_lower_limit", "drake:tendon_constraint_upper_limit",
                      "drake:tendon_constraint_stiffness", "drake:tendon_constraint_damping"},
                     ctx.spelling, ctx.attrs, ctx.module, /*repeatable=*/{kJoint});
  ir::TendonConstraint v;
  for (auto j = e.FirstChild(); j; j = j.NextSibling()) {
    if (j.Name() != kJoint) continue;
    ctx.attrs.WarnUnknownAttributes(j, {"name", "a"});
    ir::Ref<JointId> joint;
    const bool named = r.AttributeNameOf(j, joint, "name");
    const std::optional<double> a = r.AttributeScalar(j, "a");
    if (named && a) {
      v.joints.push_back(joint);
      v.a.push_back(*a);
    }
  }
  if (v.joints.empty() && r.ok()) {
    r.Fail(e.GetLoc(), fmt::format("<drake:tendon_constraint> needs at least one <{}>", kJoint),
           DiagKind::MissingElement);
  }
  auto offset = r.Scalar("drake:tendon_constraint_offset", xml::Need::Optional, Sign::Any);
  auto lower = r.Scalar("drake:tendon_constraint_lower_limit", xml::Need::Optional, Sign::Any,
                        {.negative = true});
  auto upper = r.Scalar("drake:tendon_constraint_upper_limit", xml::Need::Optional, Sign::Any,
                        {.positive = true});
  auto stiffness = r.Scalar("drake:tendon_constraint_stiffness", xml::Need::Optional,
                            Sign::Positive, {.positive = true});
  auto damping = r.Scalar("drake:tendon_constraint_damping", xml::Need::Optional,
                          Sign::NonNegative, {.positive = true});
  if (!r.ok()) return;
  v.offset = offset.value_or(0.0);
  v.lower = lower.value_or(-kInf);
  v.upper = upper.value_or(kInf);
  v.stiffness = stiffness.value_or(kInf);
  v.damping = damping.value_or(0.0);
  if (v.lower == -kInf && v.upper == kInf) {
    r.Fail(e.GetLoc(), "<drake:tendon_constraint> needs a finite bound: give "
                       "<drake:tendon_constraint_lower_limit> or "
                       "<drake:tendon_constraint_upper_limit> (or both)");
    return;
  }
  if (v.lower > v.upper) {
    r.Fail(r.ValueLoc(e.Child("drake:tendon_constraint_lower_limit")),
           fmt::format("<drake:tendon_constraint>: lower limit {} is greater than upper limit {}",
                       v.lower, v.upper));
    return;
  }
  Add(ctx, e.GetLoc(), std::move(v));
}

bool ReadDrakeModelLevelElement(const xml::XmlElement& e, const DrakeElementContext& ctx) {
  using Reader = void (*)(const xml::XmlElement&, const DrakeElementContext&);
  struct Entry {
    std::string_view tag;
    Reader read;
  };
  static constexpr std::array<Entry, 6> kReaders = {{
      {"drake:collision_filter_group", &ReadDrakeCollisionFilterGroup},
      {"drake:linear_bushing_rpy", &ReadDrakeLinearBushing},
      {"drake:linear_spring_damper", &ReadDrakeLinearSpringDamper},
      {"drake:ball_constraint", &ReadDrakeBallConstraint},
      {"drake:distance_constraint", &ReadDrakeDistanceConstraint},
      {"drake:tendon_constraint", &ReadDrakeTendonConstraint},
  }};
  const std::string_view tag = e.Name();
  for (const Entry& entry : kReaders) {
    if (entry.tag == tag) {
      entry.read(e, ctx);
      return true;
    }
  }
  return false;
}

}  // namespace mdlc::frontend
