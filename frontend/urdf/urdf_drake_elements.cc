// urdf_drake_elements.cc - model-level drake: elements: collision filter
// groups (EXT-040), force elements (EXT-050 linear_bushing_rpy, EXT-051
// linear_spring_damper) and constraints (EXT-052 ball, EXT-053 distance,
// EXT-054 tendon).
//
// Read after every link, joint and frame, so they may name any of them. This
// file lowers syntax only: every name becomes a Ref (name + the location of
// the attribute that wrote it) that the resolve-names pass resolves within the
// model instance; rules that need the resolved entities (group definitions,
// COMMON-050; distinct bodies; single-dof tendon joints) are checked by the
// check-model-elements pass. Values are checked here, as Drake's parser and
// MultibodyPlant do.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Sign { Any, Positive, NonNegative };

/// Reads the children of one drake: element. Like Drake, each child is found
/// by tag (the first of that tag wins) and a missing required child is an
/// error at the parent ("Unable to find the <tag> tag"). Every problem is
/// reported and makes ok() false; the caller then adds nothing.
class ChildReader {
 public:
  ChildReader(const xml::XmlElement& parent, std::initializer_list<std::string_view> known,
              xml::AttributeReader& attrs, ir::Module& module)
      : parent_(parent),
        parent_name_(parent.Name()),
        attrs_(attrs),
        diags_(attrs.diags()),
        module_(module) {
    attrs_.WarnUnknownAttributes(parent, {});
    // unknown and repeated children: Drake ignores them silently; mdlc warns.
    // Known tags are literals, so `seen` may hold views of them; a name
    // from XmlElement::Name() is only valid until the next call.
    std::vector<std::string_view> seen;
    for (auto c = parent.FirstChild(); c; c = c.NextSibling()) {
      std::string_view tag = c.Name();
      const std::string_view* known_tag = nullptr;
      for (const std::string_view& k : known) {
        if (k == tag) known_tag = &k;
      }
      if (!known_tag) {
        diags_.Report(DiagKind::UnknownElement, c.GetLoc(),
                      fmt::format("unknown element <{}> in <{}> is ignored", tag, parent_name_));
        continue;
      }
      if (*known_tag == "drake:tendon_constraint_joint") continue;  // repeatable
      bool repeated = false;
      for (std::string_view s : seen) repeated = repeated || s == *known_tag;
      if (repeated) {
        diags_.Report(DiagKind::UnknownElement, c.GetLoc(),
                      fmt::format("<{}> is repeated in <{}>; only the first one is used",
                                  *known_tag, parent_name_));
      } else {
        seen.push_back(*known_tag);
      }
    }
  }

  bool ok() const { return ok_; }
  DiagnosticEngine& diags() { return diags_; }

  /// The child `tag`; reports its absence when required.
  xml::XmlElement Find(std::string_view tag, xml::Need need) {
    xml::XmlElement child = parent_.Child(tag);
    if (!child && need == xml::Need::Required) {
      Fail(parent_.GetLoc(), fmt::format("<{}>: Unable to find the <{}> tag (it is required)",
                                         parent_name_, tag));
    }
    return child;
  }

  /// A name reference: the child's `name` attribute (a link, joint or frame
  /// name), with the attribute's location for later diagnostics.
  template <typename RefT>
  bool Name(std::string_view tag, RefT& ref) {
    xml::XmlElement child = Find(tag, xml::Need::Required);
    return child && NameOf(child, "name", ref);
  }
  template <typename RefT>
  bool NameOf(const xml::XmlElement& child, std::string_view attr, RefT& ref) {
    xml::XmlAttribute a = child.Attribute(attr);
    if (!a.present()) {
      Fail(child.GetLoc(), fmt::format("Unable to read the '{}' attribute for the <{}> tag: "
                                       "the attribute is missing",
                                       attr, child.Name()));
      return false;
    }
    if (a.value.empty()) {
      Fail(a.loc, fmt::format("the '{}' attribute of <{}> is empty", attr, child.Name()));
      return false;
    }
    ref.name = module_.Intern(a.value);
    ref.loc = a.loc;
    return true;
  }

  /// Three numbers in the child's `value` attribute, finite.
  std::optional<Eigen::Vector3d> Vector(std::string_view tag, Sign sign = Sign::Any) {
    xml::XmlElement child = Find(tag, xml::Need::Required);
    if (!child || !HasValue(child)) return std::nullopt;
    auto v = attrs_.Vector3(child, "value", xml::Need::Required);
    if (!v) return Failed();
    if (sign == Sign::NonNegative && v->minCoeff() < 0) {
      Fail(child.Attribute("value").loc,
           fmt::format("The 'value' attribute for the <{}> tag must be non-negative, got '{}'",
                       tag, child.Attribute("value").value));
      return std::nullopt;
    }
    return v;
  }

  /// One number in the child's `value` attribute. NaN is always an error;
  /// infinities only where `allow_inf` says (+inf, -inf, or both).
  std::optional<double> Scalar(std::string_view tag, xml::Need need, Sign sign,
                               bool allow_pos_inf = false, bool allow_neg_inf = false) {
    xml::XmlElement child = Find(tag, need);
    if (!child || !HasValue(child)) return std::nullopt;
    return ScalarOf(child, "value", sign, allow_pos_inf, allow_neg_inf);
  }
  std::optional<double> ScalarOf(const xml::XmlElement& child, std::string_view attr, Sign sign,
                                 bool allow_pos_inf = false, bool allow_neg_inf = false) {
    const xml::XmlAttribute a = child.Attribute(attr);
    auto v = attrs_.Double(child, attr, xml::Need::Required, xml::Finite::NotRequired);
    if (!v) return Failed();
    const bool bad_inf = (*v == kInf && !allow_pos_inf) || (*v == -kInf && !allow_neg_inf);
    if (std::isnan(*v) || bad_inf) {
      const char* what = std::isnan(*v)   ? "a number (not NaN)"
                         : allow_pos_inf ? "finite or inf"
                         : allow_neg_inf ? "finite or -inf"
                                         : "finite";
      Fail(a.loc, fmt::format("attribute '{}' of <{}> must be {}, got '{}'", attr, child.Name(),
                              what, a.value));
      return std::nullopt;
    }
    if (sign == Sign::Positive && !(*v > 0)) {
      Fail(a.loc, fmt::format("The '{}' attribute for the <{}> tag must be strictly positive, "
                              "got '{}'",
                              attr, child.Name(), a.value));
      return std::nullopt;
    }
    if (sign == Sign::NonNegative && !(*v >= 0)) {
      Fail(a.loc, fmt::format("The '{}' attribute for the <{}> tag must be non-negative, "
                              "got '{}'",
                              attr, child.Name(), a.value));
      return std::nullopt;
    }
    return v;
  }

  void Fail(Loc loc, std::string message) {
    diags_.Report(DiagKind::BadValue, loc, std::move(message));
    ok_ = false;
  }

 private:
  bool HasValue(const xml::XmlElement& child) {
    if (child.Attribute("value").present()) return true;
    diags_.Report(DiagKind::MissingAttribute, child.GetLoc(),
                  fmt::format("Unable to read the 'value' attribute for the <{}> tag: the "
                              "attribute is missing",
                              child.Name()));
    ok_ = false;
    return false;
  }
  std::nullopt_t Failed() {
    ok_ = false;
    return std::nullopt;
  }

  const xml::XmlElement& parent_;
  const std::string parent_name_;
  xml::AttributeReader& attrs_;
  DiagnosticEngine& diags_;
  ir::Module& module_;
  bool ok_ = true;
};
}  // namespace

// <drake:collision_filter_group name [ignore]> with <drake:member link>,
// <drake:member_group name> and <drake:ignored_collision_filter_group name>
// (EXT-040). The group's own rules (COMMON-050) and its references
// (COMMON-053) are checked once every model is read (COMMON-055).
void UrdfReader::ReadCollisionFilterGroup(const xml::XmlElement& e) {
  if (auto ignore = e.Attribute("ignore"); ignore.present()) {
    // Drake skips the group exactly when the value is "true"
    if (ignore.value == "true") return;
    if (ignore.value != "false") {
      diags().Report(DiagKind::UnsupportedValue, ignore.loc,
                     fmt::format("attribute 'ignore' of <drake:collision_filter_group> is '{}'; "
                                 "only 'true' skips the group, so it is read",
                                 ignore.value));
    }
  }
  attrs_.WarnUnknownAttributes(e, {"name", "ignore"});
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (name && name->empty()) {
    diags().Report(DiagKind::MissingAttribute, e.Attribute("name").loc,
                   "<drake:collision_filter_group> has an empty 'name'");
    name.reset();
  }

  ir::CollisionFilterGroup group;
  group.model = model_;
  group.loc = e.GetLoc();
  bool ok = name.has_value();
  // a child's name attribute, as a reference located at the attribute
  auto reference = [&](const xml::XmlElement& c, std::string_view attr, auto& refs) {
    const xml::XmlAttribute a = c.Attribute(attr);
    if (!a.present() || a.value.empty()) {
      diags().Report(DiagKind::MissingAttribute, a.present() ? a.loc : c.GetLoc(),
                     fmt::format("The tag <{}> does not specify the required attribute '{}'{}",
                                 c.Name(), attr, a.present() ? " (it is empty)" : ""));
      ok = false;
      return;
    }
    attrs_.WarnUnknownAttributes(c, {attr});
    refs.push_back({module().Intern(a.value), a.loc, {}});
  };
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    std::string_view tag = c.Name();
    if (tag == "drake:member") {
      reference(c, "link", group.members);
    } else if (tag == "drake:member_group") {
      reference(c, "name", group.member_groups);
    } else if (tag == "drake:ignored_collision_filter_group") {
      reference(c, "name", group.ignored_groups);
    } else {
      diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                     fmt::format("unknown element <{}> in <drake:collision_filter_group> is "
                                 "ignored",
                                 tag));
    }
  }
  if (!ok) return;
  group.name = module().Intern(*name);
  module().Add(std::move(group));
}

// <drake:linear_bushing_rpy> (EXT-050): frames A and C (a <frame> or a
// link's own frame) and four non-negative gain vectors, every child required.
void UrdfReader::ReadLinearBushing(const xml::XmlElement& e) {
  ChildReader r(e,
                {"drake:bushing_frameA", "drake:bushing_frameC", "drake:bushing_torque_stiffness",
                 "drake:bushing_torque_damping", "drake:bushing_force_stiffness",
                 "drake:bushing_force_damping"},
                attrs_, module());
  ir::LinearBushingRpy f;
  r.Name("drake:bushing_frameA", f.frame_A);
  r.Name("drake:bushing_frameC", f.frame_C);
  // Drake's LinearBushingRollPitchYaw requires every gain to be >= 0
  auto torque_stiffness = r.Vector("drake:bushing_torque_stiffness", Sign::NonNegative);
  auto torque_damping = r.Vector("drake:bushing_torque_damping", Sign::NonNegative);
  auto force_stiffness = r.Vector("drake:bushing_force_stiffness", Sign::NonNegative);
  auto force_damping = r.Vector("drake:bushing_force_damping", Sign::NonNegative);
  if (!r.ok()) return;
  f.torque_stiffness = *torque_stiffness;
  f.torque_damping = *torque_damping;
  f.force_stiffness = *force_stiffness;
  f.force_damping = *force_damping;
  module().Add(ir::ForceElement{model_, e.GetLoc(), std::move(f)});
}

// <drake:linear_spring_damper> (EXT-051): every child required; free length
// > 0, stiffness and damping >= 0 (Drake's parser and LinearSpringDamper).
void UrdfReader::ReadLinearSpringDamper(const xml::XmlElement& e) {
  ChildReader r(e,
                {"drake:linear_spring_damper_body_A", "drake:linear_spring_damper_p_AP",
                 "drake:linear_spring_damper_body_B", "drake:linear_spring_damper_p_BQ",
                 "drake:linear_spring_damper_free_length", "drake:linear_spring_damper_stiffness",
                 "drake:linear_spring_damper_damping"},
                attrs_, module());
  ir::LinearSpringDamper f;
  r.Name("drake:linear_spring_damper_body_A", f.body_A);
  r.Name("drake:linear_spring_damper_body_B", f.body_B);
  auto p_AP = r.Vector("drake:linear_spring_damper_p_AP");
  auto p_BQ = r.Vector("drake:linear_spring_damper_p_BQ");
  auto free_length =
      r.Scalar("drake:linear_spring_damper_free_length", xml::Need::Required, Sign::Positive);
  auto stiffness =
      r.Scalar("drake:linear_spring_damper_stiffness", xml::Need::Required, Sign::NonNegative);
  auto damping =
      r.Scalar("drake:linear_spring_damper_damping", xml::Need::Required, Sign::NonNegative);
  if (!r.ok()) return;
  f.p_AP = *p_AP;
  f.p_BQ = *p_BQ;
  f.free_length = *free_length;
  f.stiffness = *stiffness;
  f.damping = *damping;
  module().Add(ir::ForceElement{model_, e.GetLoc(), std::move(f)});
}

// <drake:ball_constraint> (EXT-052): bodies A and B, points P (in A) and Q
// (in B), all required. Distinct bodies are checked after resolution.
void UrdfReader::ReadBallConstraint(const xml::XmlElement& e) {
  ChildReader r(e,
                {"drake:ball_constraint_body_A", "drake:ball_constraint_body_B",
                 "drake:ball_constraint_p_AP", "drake:ball_constraint_p_BQ"},
                attrs_, module());
  ir::BallConstraint c;
  r.Name("drake:ball_constraint_body_A", c.body_A);
  r.Name("drake:ball_constraint_body_B", c.body_B);
  auto p_AP = r.Vector("drake:ball_constraint_p_AP");
  auto p_BQ = r.Vector("drake:ball_constraint_p_BQ");
  if (!r.ok()) return;
  c.p_AP = *p_AP;
  c.p_BQ = *p_BQ;
  module().Add(ir::Constraint{model_, e.GetLoc(), std::move(c)});
}

// <drake:distance_constraint> (EXT-053): every child required; distance > 0,
// stiffness > 0 (+inf: a rigid constraint, AddDistanceConstraint's default),
// damping >= 0.
void UrdfReader::ReadDistanceConstraint(const xml::XmlElement& e) {
  ChildReader r(e,
                {"drake:distance_constraint_body_A", "drake:distance_constraint_p_AP",
                 "drake:distance_constraint_body_B", "drake:distance_constraint_p_BQ",
                 "drake:distance_constraint_distance", "drake:distance_constraint_stiffness",
                 "drake:distance_constraint_damping"},
                attrs_, module());
  ir::DistanceConstraint c;
  r.Name("drake:distance_constraint_body_A", c.body_A);
  r.Name("drake:distance_constraint_body_B", c.body_B);
  auto p_AP = r.Vector("drake:distance_constraint_p_AP");
  auto p_BQ = r.Vector("drake:distance_constraint_p_BQ");
  auto distance =
      r.Scalar("drake:distance_constraint_distance", xml::Need::Required, Sign::Positive);
  auto stiffness = r.Scalar("drake:distance_constraint_stiffness", xml::Need::Required,
                            Sign::Positive, /*allow_pos_inf=*/true);
  auto damping =
      r.Scalar("drake:distance_constraint_damping", xml::Need::Required, Sign::NonNegative);
  if (!r.ok()) return;
  c.p_AP = *p_AP;
  c.p_BQ = *p_BQ;
  c.distance = *distance;
  c.stiffness = *stiffness;
  c.damping = *damping;
  module().Add(ir::Constraint{model_, e.GetLoc(), std::move(c)});
}

// <drake:tendon_constraint> (EXT-054): one or more
// <drake:tendon_constraint_joint name a>, then optional offset, limits,
// stiffness and damping with AddTendonConstraint's defaults (offset 0, limits
// -inf/+inf, stiffness +inf, damping 0) and its preconditions: a finite
// bound on at least one side, lower <= upper, stiffness > 0, damping >= 0.
// Single-dof and distinct joints are checked after resolution.
void UrdfReader::ReadTendonConstraint(const xml::XmlElement& e) {
  ChildReader r(e,
                {"drake:tendon_constraint_joint", "drake:tendon_constraint_offset",
                 "drake:tendon_constraint_lower_limit", "drake:tendon_constraint_upper_limit",
                 "drake:tendon_constraint_stiffness", "drake:tendon_constraint_damping"},
                attrs_, module());
  ir::TendonConstraint c;
  for (auto j = e.FirstChild(); j; j = j.NextSibling()) {
    if (j.Name() != "drake:tendon_constraint_joint") continue;
    attrs_.WarnUnknownAttributes(j, {"name", "a"});
    ir::Ref<JointId> joint;
    const bool named = r.NameOf(j, "name", joint);
    std::optional<double> a;
    if (!j.Attribute("a").present()) {
      r.Fail(j.GetLoc(), "Unable to read the 'a' attribute for the "
                         "<drake:tendon_constraint_joint> tag: the attribute is missing");
    } else {
      a = r.ScalarOf(j, "a", Sign::Any);
    }
    if (named && a) {
      c.joints.push_back(joint);
      c.a.push_back(*a);
    }
  }
  if (c.joints.empty() && r.ok()) {
    r.Fail(e.GetLoc(), "<drake:tendon_constraint> needs at least one "
                       "<drake:tendon_constraint_joint>");
  }
  auto offset = r.Scalar("drake:tendon_constraint_offset", xml::Need::Optional, Sign::Any);
  auto lower = r.Scalar("drake:tendon_constraint_lower_limit", xml::Need::Optional, Sign::Any,
                        /*allow_pos_inf=*/false, /*allow_neg_inf=*/true);
  auto upper = r.Scalar("drake:tendon_constraint_upper_limit", xml::Need::Optional, Sign::Any,
                        /*allow_pos_inf=*/true, /*allow_neg_inf=*/false);
  auto stiffness = r.Scalar("drake:tendon_constraint_stiffness", xml::Need::Optional,
                            Sign::Positive, /*allow_pos_inf=*/true);
  auto damping = r.Scalar("drake:tendon_constraint_damping", xml::Need::Optional,
                          Sign::NonNegative, /*allow_pos_inf=*/true);
  if (!r.ok()) return;
  c.offset = offset.value_or(0.0);
  c.lower = lower.value_or(-kInf);
  c.upper = upper.value_or(kInf);
  c.stiffness = stiffness.value_or(kInf);
  c.damping = damping.value_or(0.0);
  if (c.lower == -kInf && c.upper == kInf) {
    r.Fail(e.GetLoc(), "<drake:tendon_constraint> needs a finite bound: give "
                       "<drake:tendon_constraint_lower_limit> or "
                       "<drake:tendon_constraint_upper_limit> (or both)");
    return;
  }
  if (c.lower > c.upper) {
    r.Fail(e.Child("drake:tendon_constraint_lower_limit").Attribute("value").loc,
           fmt::format("<drake:tendon_constraint>: lower limit {} is greater than upper limit {}",
                       c.lower, c.upper));
    return;
  }
  module().Add(ir::Constraint{model_, e.GetLoc(), std::move(c)});
}

}  // namespace mdlc::frontend::urdf
