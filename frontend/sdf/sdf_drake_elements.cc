// sdf_drake_elements.cc - drake: elements of an SDFormat model and joint
// (EXT-001, EXT-003, EXT-004, EXT-010, EXT-012..014, EXT-040, EXT-050..054,
// EXT-070, SDF-021).
//
// SDFormat spells Drake's extensions with element text
// (<drake:bushing_torque_stiffness>1 2 3</drake:bushing_torque_stiffness>)
// where URDF uses attributes; the IR they lower to is the URDF frontend's
// (urdf_drake_elements.cc, urdf_drake_joint.cc, urdf_transmission.cc), and
// so are the rules and the keywords of the messages. References stay names
// (with the location of the element that wrote them) for resolve-names,
// which looks them up in the element's model instance, `a::b` in nested ones;
// rules that need resolved entities are the check-model-elements and
// check-joints passes'.
//
// drake:joint (EXT-001): as in Drake, the joint's frame F IS the frame named
// by drake:parent and M the one named by drake:child (no pose of its own;
// <pose> is an error). When both name links, X_PF = X_CM = identity and the
// joint's parent and child are plain link references for resolve-names
// (scoped names reach into nested models). Naming an explicit <frame> or a
// model frame of the model is reported as not implemented: F and M would
// need separate nodes in the frame graph, which JointFrameSpec cannot
// express yet, and SDFormat joint-frame semantics would place F wrongly.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Drake's tolerance for "perpendicular" between a curvilinear path's initial
// tangent and its plane normal (as in urdf_drake_joint.cc)
constexpr double kPerpendicularTolerance = 128 * std::numeric_limits<double>::epsilon();

std::string Trimmed(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return std::string(s);
}

bool EndsWithVtk(std::string_view uri) {
  if (uri.size() < 4) return false;
  std::string ext(uri.substr(uri.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".vtk";
}

enum class Sign { Any, Positive, NonNegative };

/// Reads the children of one model-level drake: element, written as element
/// text. As in Drake, each child is found by tag (the first of that tag wins)
/// and a missing required child is an error at the parent ("Unable to find
/// the <tag> child tag"). Every problem is reported and makes ok() false;
/// the caller then adds nothing.
class TextChildReader {
 public:
  TextChildReader(SdfReader& reader, const xml::XmlElement& parent,
                  std::initializer_list<std::string_view> known,
                  std::initializer_list<std::string_view> repeatable = {},
                  bool check_attributes = true)
      : r_(reader), parent_(parent), parent_name_(parent.Name()) {
    if (check_attributes) r_.attrs_.WarnUnknownAttributes(parent, {});
    // unknown children: Drake rejects unknown drake: ones; mdlc warns (SDF-001)
    std::vector<std::string_view> seen;
    for (auto c = parent.FirstChild(); c; c = c.NextSibling()) {
      const std::string_view tag = c.Name();
      const std::string_view* known_tag = nullptr;
      for (const std::string_view& k : known) {
        if (k == tag) known_tag = &k;
      }
      if (!known_tag) {
        r_.diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                          fmt::format("unsupported element <{}> in <{}> is ignored", tag,
                                      parent_name_));
        continue;
      }
      if (std::find(repeatable.begin(), repeatable.end(), *known_tag) != repeatable.end()) {
        continue;
      }
      if (std::find(seen.begin(), seen.end(), *known_tag) != seen.end()) {
        r_.diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                          fmt::format("<{}> is repeated in <{}>; only the first one is used",
                                      *known_tag, parent_name_));
      } else {
        seen.push_back(*known_tag);
      }
    }
  }

  bool ok() const { return ok_; }

  xml::XmlElement Find(std::string_view tag, xml::Need need) {
    xml::XmlElement child = parent_.Child(tag);
    if (!child && need == xml::Need::Required) {
      Fail(parent_.GetLoc(),
           fmt::format("<{}>: Unable to find the <{}> child tag.", parent_name_, tag));
    }
    return child;
  }

  /// A name (link, frame or joint) as the child's text; located at the child.
  template <typename RefT>
  bool Name(std::string_view tag, RefT& ref) {
    xml::XmlElement child = Find(tag, xml::Need::Required);
    return child && NameOf(child, ref);
  }
  template <typename RefT>
  bool NameOf(const xml::XmlElement& child, RefT& ref) {
    std::string text = Trimmed(child.Text());
    if (text.empty()) {
      Fail(child.GetLoc(),
           fmt::format("The tag <{}> is missing a required string value.", child.Name()));
      return false;
    }
    ref.name = r_.module().Intern(text);
    ref.loc = child.GetLoc();
    return true;
  }

  /// Three finite numbers in the child's text.
  std::optional<Eigen::Vector3d> Vector(std::string_view tag, Sign sign = Sign::Any) {
    xml::XmlElement child = Find(tag, xml::Need::Required);
    if (!child) return std::nullopt;
    auto v = r_.TextVector3(child);
    if (!v) return Failed();
    if (sign == Sign::NonNegative && v->minCoeff() < 0) {
      Fail(child.GetLoc(), fmt::format("<{}>: The <{}> child tag must be non-negative, got '{}'",
                                       parent_name_, tag, Trimmed(child.Text())));
      return std::nullopt;
    }
    return v;
  }

  /// One number in the child's text. NaN is always an error; infinities
  /// only where allowed.
  std::optional<double> Scalar(std::string_view tag, xml::Need need, Sign sign,
                               bool allow_pos_inf = false, bool allow_neg_inf = false) {
    xml::XmlElement child = Find(tag, need);
    if (!child) return std::nullopt;
    auto v = r_.TextDouble(child, xml::Finite::NotRequired);
    if (!v) return Failed();
    const bool bad_inf = (*v == kInf && !allow_pos_inf) || (*v == -kInf && !allow_neg_inf);
    if (std::isnan(*v) || bad_inf) {
      const char* what = std::isnan(*v)   ? "a number (not NaN)"
                         : allow_pos_inf ? "finite or inf"
                         : allow_neg_inf ? "finite or -inf"
                                         : "finite";
      Fail(child.GetLoc(), fmt::format("<{}> must be {}, got '{}'", tag, what,
                                       Trimmed(child.Text())));
      return std::nullopt;
    }
    if (sign == Sign::Positive && !(*v > 0)) {
      Fail(child.GetLoc(), fmt::format("<{}>: The <{}> child tag must be strictly positive, "
                                       "got '{}'",
                                       parent_name_, tag, Trimmed(child.Text())));
      return std::nullopt;
    }
    if (sign == Sign::NonNegative && !(*v >= 0)) {
      Fail(child.GetLoc(), fmt::format("<{}>: The <{}> child tag must be non-negative, got '{}'",
                                       parent_name_, tag, Trimmed(child.Text())));
      return std::nullopt;
    }
    return v;
  }

  /// A problem already reported elsewhere (by the value readers).
  void Invalidate() { ok_ = false; }

  void Fail(Loc loc, std::string message, DiagKind kind = DiagKind::BadValue) {
    r_.diags().Report(kind, loc, std::move(message));
    ok_ = false;
  }

 private:
  std::nullopt_t Failed() {
    ok_ = false;
    return std::nullopt;
  }

  SdfReader& r_;
  const xml::XmlElement& parent_;
  const std::string parent_name_;
  bool ok_ = true;
};

/// The scope whose namespace `id` publishes its names into (merged models).
}  // namespace

// --- drake:joint (EXT-001, EXT-003, EXT-004) ---

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

namespace {
struct DrakeJointEnd {
  ir::Ref<BodyId> body;
  bool ok = false;
};
}  // namespace

void SdfReader::ReadDrakeModelElement(const xml::XmlElement& e, ModelScope& s) {
  const std::string_view tag = e.Name();

  // -- helpers shared by the element kinds
  // drake:parent / drake:child: a link name (scoped names reach into nested
  // models), resolved by resolve-names; F and M are the links' own frames
  auto frame_end = [&](TextChildReader& r, std::string_view which,
                       std::string_view joint_name) -> DrakeJointEnd {
    DrakeJointEnd end;
    xml::XmlElement child = r.Find(which, xml::Need::Required);
    if (!child || !r.NameOf(child, end.body)) return end;
    // a link or any frame: the resolve-frames pass binds F and M to them
    end.ok = true;
    return end;
  };

  if (tag == "drake:joint") {
    // -- name and type first, as Drake reads them
    attrs_.WarnUnknownAttributes(e, {"name", "type"});
    const xml::XmlAttribute type_attr = e.Attribute("type");
    const xml::XmlAttribute name_attr = e.Attribute("name");
    if (!type_attr.present()) {
      diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                     "<drake:joint>: Unable to find the 'type' attribute.");
      return;
    }
    if (!name_attr.present()) {
      diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                     "<drake:joint>: Unable to find the 'name' attribute.");
      return;
    }
    const std::string name(name_attr.value);
    const std::string type(type_attr.value);
    if (!CheckDefinedName(name, name_attr.loc, "joint")) return;
    if (auto pose = e.Child("pose")) {
      diags().Report(DiagKind::NotImplemented, pose.GetLoc(),
                     "<drake:joint> does not yet support the <pose> child tag: its frames are "
                     "those named by <drake:parent> and <drake:child>");
      return;
    }
    ir::JointType joint_type;
    if (type == "planar") {
      joint_type = ir::JointType::Planar;
    } else if (type == "curvilinear") {
      joint_type = ir::JointType::Curvilinear;
    } else {
      diags().Report(DiagKind::BadValue, type_attr.loc,
                     fmt::format("<drake:joint> '{}' has unrecognized value for 'type' "
                                 "attribute: {} (expected planar or curvilinear)",
                                 name, type));
      return;
    }
    TextChildReader r(*this, e,
                      {"drake:parent", "drake:child", "drake:damping", "drake:initial_tangent",
                       "drake:plane_normal", "drake:is_periodic", "drake:curves", "pose"},
                      {}, /*check_attributes=*/false);  // name and type: checked above
    DrakeJointEnd parent = frame_end(r, "drake:parent", name);
    if (!parent.ok) return;
    DrakeJointEnd child = frame_end(r, "drake:child", name);
    if (!child.ok) return;

    ir::Joint joint;
    joint.name = module().Intern(name);
    joint.model = s.model;
    joint.loc = e.GetLoc();
    joint.type = joint_type;
    joint.parent = parent.body;
    joint.child = child.body;
    const int nv = ir::JointVelocityCount(joint_type);
    joint.limits = ir::JointLimits::Unbounded(nv);
    joint.damping.assign(nv, 0.0);
    // a drake:joint shares the joint namespace of its model (COMMON-023)
    for (const ir::Joint& other : module().joints) {
      if (other.model == s.model && other.name == joint.name) {
        diags()
            .Report(DiagKind::DuplicateName, name_attr.loc,
                    fmt::format("the joint name '{}' is already used by a joint of this model",
                                name))
            .Note(other.loc, "first defined here");
        return;
      }
    }

    if (joint_type == ir::JointType::Planar) {
      // PlanarJoint: x, y translation and rotation about z of F; three
      // non-negative dampings, required (EXT-004)
      joint.axis = Eigen::Vector3d::UnitZ();
      auto damping = r.Vector("drake:damping", Sign::NonNegative);
      for (const char* t : {"drake:initial_tangent", "drake:plane_normal", "drake:is_periodic",
                            "drake:curves"}) {
        if (auto c = e.Child(t)) {
          diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                         fmt::format("<{}> applies only to curvilinear joints; it is ignored in "
                                     "planar joint '{}'",
                                     t, name));
        }
      }
      if (!r.ok()) return;
      joint.damping = {damping->x(), damping->y(), damping->z()};
      AddDrakeJointFrames(module().Add(std::move(joint)), s, parent.body, child.body);
      return;
    }

    // curvilinear (EXT-003): optional damping (one value), plane normal and
    // initial tangent (<xyz> children), periodicity, and the curves
    if (auto d = r.Scalar("drake:damping", xml::Need::Optional, Sign::Any)) {
      if (*d < 0) {
        r.Fail(e.Child("drake:damping").GetLoc(),
               fmt::format("<drake:joint> '{}' has negative value for 'damping': {}", name, *d));
      } else {
        joint.damping.assign(1, *d);
      }
    }
    ir::CurvilinearPath path;
    Loc tangent_loc;
    auto direction = [&](std::string_view t, Eigen::Vector3d& out) -> Loc {
      xml::XmlElement c = e.Child(t);
      if (!c) return {};
      CheckChildren(c, {"xyz"});
      xml::XmlElement xyz = c.Child("xyz");
      if (!xyz) {
        r.Fail(c.GetLoc(), fmt::format("<{}>: Unable to find the <xyz> child tag.", t),
               DiagKind::MissingElement);
        return {};
      }
      auto v = TextVector3(xyz);
      if (!v) {
        r.Invalidate();
        return {};
      }
      if (v->norm() == 0) {
        r.Fail(xyz.GetLoc(),
               fmt::format("curvilinear joint '{}': <{}> is zero; it must have a direction",
                           name, t),
               DiagKind::ZeroAxis);
        return {};
      }
      out = *v;
      return xyz.GetLoc();
    };
    direction("drake:plane_normal", path.plane_normal);
    tangent_loc = direction("drake:initial_tangent", path.initial_tangent);
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
      const std::string value = Trimmed(p.Text());
      if (value == "true") {
        path.periodic = true;
      } else if (value != "false") {
        r.Fail(p.GetLoc(), fmt::format("<drake:is_periodic>: boolean node contains non-boolean "
                                       "value '{}' (write true or false)",
                                       value));
      }
    }
    xml::XmlElement curves = e.Child("drake:curves");
    if (!curves) {
      r.Fail(e.GetLoc(), fmt::format("<drake:joint>: Unable to find the <drake:curves> child "
                                     "node (curvilinear joint '{}' needs its path)",
                                     name),
             DiagKind::MissingElement);
      return;
    }
    bool any_curve = false;
    for (auto c = curves.FirstChild(); c; c = c.NextSibling()) {
      any_curve = true;
      const std::string_view ct = c.Name();
      if (ct == "drake:line_segment") {
        TextChildReader piece(*this, c, {"drake:length"});
        auto length = piece.Scalar("drake:length", xml::Need::Required, Sign::Any);
        if (!piece.ok()) {
          r.Invalidate();
        } else if (*length <= 0) {
          r.Fail(c.Child("drake:length").GetLoc(),
                 fmt::format("curvilinear joint '{}': a drake:line_segment node has a 0 or "
                             "negative drake:length ({})",
                             name, *length));
        } else {
          path.segments.push_back({*length, 0.0});
        }
      } else if (ct == "drake:circular_arc") {
        TextChildReader piece(*this, c, {"drake:radius", "drake:angle"});
        auto radius = piece.Scalar("drake:radius", xml::Need::Required, Sign::Any);
        auto angle = piece.Scalar("drake:angle", xml::Need::Required, Sign::Any);
        bool arc_ok = piece.ok();
        if (radius && *radius <= 0) {
          r.Fail(c.Child("drake:radius").GetLoc(),
                 fmt::format("curvilinear joint '{}': a drake:circular_arc node has a 0 or "
                             "negative drake:radius ({})",
                             name, *radius));
          arc_ok = false;
        }
        if (angle && *angle == 0) {
          r.Fail(c.Child("drake:angle").GetLoc(),
                 fmt::format("curvilinear joint '{}': a drake:circular_arc angle must not be "
                             "zero",
                             name));
          arc_ok = false;
        }
        if (!arc_ok) {
          r.Invalidate();
          continue;
        }
        // the sign of the angle is the turn about the plane normal
        const double length = *radius * std::abs(*angle);
        path.segments.push_back({length, *angle / length});
      } else {
        r.Fail(c.GetLoc(), fmt::format("<drake:joint>: drake:curves node contains an invalid "
                                       "child node <{}> (only drake:line_segment and "
                                       "drake:circular_arc)",
                                       ct));
      }
    }
    if (!any_curve) {
      r.Fail(curves.GetLoc(),
             fmt::format("curvilinear joint '{}' has an empty <drake:curves> list", name),
             DiagKind::MissingElement);
    }
    if (!r.ok()) return;
    joint.curvilinear_path = std::move(path);
    // Drake's curvilinear joint limits an open path to its ends
    if (!joint.curvilinear_path.periodic) {
      joint.limits.lower[0] = 0;
      joint.limits.upper[0] = joint.curvilinear_path.TotalLength();
    }
    AddDrakeJointFrames(module().Add(std::move(joint)), s, parent.body, child.body);
    return;
  }

  // --- collision filter groups (EXT-040, COMMON-050..055) ---
  if (tag == "drake:collision_filter_group") {
    attrs_.WarnUnknownAttributes(e, {"name", "ignore"});
    if (auto ignore = e.Attribute("ignore"); ignore.present()) {
      // an SDFormat boolean: true/1 skip the group
      const std::string v = Trimmed(ignore.value);
      if (v == "true" || v == "1") return;
      if (v != "false" && v != "0") {
        diags().Report(DiagKind::UnsupportedValue, ignore.loc,
                       fmt::format("attribute 'ignore' of <drake:collision_filter_group> is "
                                   "'{}', not a boolean; the group is read",
                                   ignore.value));
      }
    }
    const xml::XmlAttribute name = e.Attribute("name");
    bool ok = true;
    if (!name.present()) {
      diags().Report(DiagKind::MissingAttribute, e.GetLoc(),
                     "The tag <drake:collision_filter_group> is missing the required attribute "
                     "\"name\"");
      ok = false;
    } else if (name.value.empty()) {
      diags().Report(DiagKind::MissingAttribute, name.loc,
                     "<drake:collision_filter_group> has an empty 'name'");
      ok = false;
    }
    ir::CollisionFilterGroup group;
    group.model = s.model;
    group.loc = e.GetLoc();
    auto reference = [&](const xml::XmlElement& c, auto& refs) {
      attrs_.WarnUnknownAttributes(c, {});
      std::string text = Trimmed(c.Text());
      if (text.empty()) {
        diags().Report(DiagKind::MissingElement, c.GetLoc(),
                       fmt::format("The tag <{}> is missing a required string value.", c.Name()));
        ok = false;
        return;
      }
      refs.push_back({module().Intern(text), c.GetLoc(), {}});
    };
    for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
      const std::string_view ct = c.Name();
      if (ct == "drake:member") {
        reference(c, group.members);
      } else if (ct == "drake:member_group") {
        reference(c, group.member_groups);
      } else if (ct == "drake:ignored_collision_filter_group") {
        reference(c, group.ignored_groups);
      } else {
        diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                       fmt::format("unsupported element <{}> in <drake:collision_filter_group> "
                                   "is ignored",
                                   ct));
      }
    }
    if (!ok) return;
    group.name = module().Intern(name.value);
    module().Add(std::move(group));
    return;
  }

  // --- force elements (EXT-050, EXT-051) ---
  if (tag == "drake:linear_bushing_rpy") {
    TextChildReader r(*this, e,
                      {"drake:bushing_frameA", "drake:bushing_frameC",
                       "drake:bushing_torque_stiffness", "drake:bushing_torque_damping",
                       "drake:bushing_force_stiffness", "drake:bushing_force_damping"});
    ir::LinearBushingRpy f;
    r.Name("drake:bushing_frameA", f.frame_A);
    r.Name("drake:bushing_frameC", f.frame_C);
    // LinearBushingRollPitchYaw requires every gain to be >= 0
    auto torque_stiffness = r.Vector("drake:bushing_torque_stiffness", Sign::NonNegative);
    auto torque_damping = r.Vector("drake:bushing_torque_damping", Sign::NonNegative);
    auto force_stiffness = r.Vector("drake:bushing_force_stiffness", Sign::NonNegative);
    auto force_damping = r.Vector("drake:bushing_force_damping", Sign::NonNegative);
    if (!r.ok()) return;
    f.torque_stiffness = *torque_stiffness;
    f.torque_damping = *torque_damping;
    f.force_stiffness = *force_stiffness;
    f.force_damping = *force_damping;
    module().Add(ir::ForceElement{s.model, e.GetLoc(), std::move(f)});
    return;
  }
  if (tag == "drake:linear_spring_damper") {
    TextChildReader r(*this, e,
                      {"drake:linear_spring_damper_body_A", "drake:linear_spring_damper_p_AP",
                       "drake:linear_spring_damper_body_B", "drake:linear_spring_damper_p_BQ",
                       "drake:linear_spring_damper_free_length",
                       "drake:linear_spring_damper_stiffness",
                       "drake:linear_spring_damper_damping"});
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
    module().Add(ir::ForceElement{s.model, e.GetLoc(), std::move(f)});
    return;
  }

  // --- constraints (EXT-052..054) ---
  if (tag == "drake:ball_constraint") {
    TextChildReader r(*this, e,
                      {"drake:ball_constraint_body_A", "drake:ball_constraint_body_B",
                       "drake:ball_constraint_p_AP", "drake:ball_constraint_p_BQ"});
    ir::BallConstraint c;
    r.Name("drake:ball_constraint_body_A", c.body_A);
    r.Name("drake:ball_constraint_body_B", c.body_B);
    auto p_AP = r.Vector("drake:ball_constraint_p_AP");
    auto p_BQ = r.Vector("drake:ball_constraint_p_BQ");
    if (!r.ok()) return;
    c.p_AP = *p_AP;
    c.p_BQ = *p_BQ;
    module().Add(ir::Constraint{s.model, e.GetLoc(), std::move(c)});
    return;
  }
  if (tag == "drake:distance_constraint") {
    TextChildReader r(*this, e,
                      {"drake:distance_constraint_body_A", "drake:distance_constraint_p_AP",
                       "drake:distance_constraint_body_B", "drake:distance_constraint_p_BQ",
                       "drake:distance_constraint_distance", "drake:distance_constraint_stiffness",
                       "drake:distance_constraint_damping"});
    ir::DistanceConstraint c;
    r.Name("drake:distance_constraint_body_A", c.body_A);
    r.Name("drake:distance_constraint_body_B", c.body_B);
    auto p_AP = r.Vector("drake:distance_constraint_p_AP");
    auto p_BQ = r.Vector("drake:distance_constraint_p_BQ");
    auto distance =
        r.Scalar("drake:distance_constraint_distance", xml::Need::Required, Sign::Positive);
    // +inf stiffness: a rigid constraint (AddDistanceConstraint's default)
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
    module().Add(ir::Constraint{s.model, e.GetLoc(), std::move(c)});
    return;
  }
  if (tag == "drake:tendon_constraint") {
    TextChildReader r(*this, e,
                      {"drake:tendon_constraint_joint", "drake:tendon_constraint_offset",
                       "drake:tendon_constraint_lower_limit",
                       "drake:tendon_constraint_upper_limit", "drake:tendon_constraint_stiffness",
                       "drake:tendon_constraint_damping"},
                      {"drake:tendon_constraint_joint"});
    ir::TendonConstraint c;
    // <drake:tendon_constraint_joint name="j" a="1"/>: attributes, as in Drake
    for (auto j = e.FirstChild(); j; j = j.NextSibling()) {
      if (j.Name() != "drake:tendon_constraint_joint") continue;
      attrs_.WarnUnknownAttributes(j, {"name", "a"});
      const xml::XmlAttribute jn = j.Attribute("name");
      const xml::XmlAttribute ja = j.Attribute("a");
      bool joint_ok = true;
      if (!jn.present() || jn.value.empty()) {
        r.Fail(jn.present() ? jn.loc : j.GetLoc(),
               "The tag <drake:tendon_constraint_joint> is missing the required attribute "
               "\"name\"",
               DiagKind::MissingAttribute);
        joint_ok = false;
      }
      std::optional<double> a;
      if (!ja.present()) {
        r.Fail(j.GetLoc(),
               "The tag <drake:tendon_constraint_joint> is missing the required attribute \"a\"",
               DiagKind::MissingAttribute);
        joint_ok = false;
      } else {
        a = attrs_.Double(j, "a", xml::Need::Required);
        if (!a) {
          r.Fail(ja.loc, "attribute 'a' of <drake:tendon_constraint_joint> must be a finite "
                         "number");
          joint_ok = false;
        }
      }
      if (!joint_ok) continue;
      c.joints.push_back({module().Intern(jn.value), jn.loc, {}});
      c.a.push_back(*a);
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
      r.Fail(e.Child("drake:tendon_constraint_lower_limit").GetLoc(),
             fmt::format("<drake:tendon_constraint>: lower limit {} is greater than upper "
                         "limit {}",
                         c.lower, c.upper));
      return;
    }
    module().Add(ir::Constraint{s.model, e.GetLoc(), std::move(c)});
    return;
  }

  // Any other drake: element is unknown (SDF-001: a warning). The model
  // reader's CheckChildren reports it, since it does not list it among the
  // model's children; nothing more to say here.
}

// --- drake: children of a <joint> (EXT-010, EXT-012..014, SDF-021) ---

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
                         fmt::format("Joint '{}' drake:mimic element is missing the required "
                                     "'{}' attribute",
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
                       fmt::format("Joint '{}' drake:mimic element has an empty 'joint' "
                                   "attribute",
                                   joint_name));
        continue;
      }
      if (other.value == joint_name) {
        diags().Report(DiagKind::BadValue, other.loc,
                       fmt::format("Joint '{}' drake:mimic element specifies joint '{}'. Joints "
                                   "cannot mimic themselves.",
                                   joint_name, other.value));
        continue;
      }
      if (!multiplier || !offset) continue;
      // Drake ignores mimic unless both joints are single-dof (a warning);
      // this joint's dofs are known now, the other's after resolve-names
      if (const int nv = ir::JointVelocityCount(joint.type);
          nv != 1 || joint.type == ir::JointType::Weld) {
        diags().Report(DiagKind::JointWarning, child.GetLoc(),
                       fmt::format("Drake only supports the drake:mimic element for single-dof "
                                   "joints; joint '{}' ({}) has {} dofs, so its drake:mimic is "
                                   "ignored",
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
                         fmt::format("<drake:controller_gains>: Unable to find the '{}' "
                                     "attribute.",
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
}

// --- drake:deformable_properties (EXT-070) ---

void SdfReader::ReadDeformableProperties(const xml::XmlElement& link, ModelScope&, BodyId body) {
  const xml::XmlElement props = link.Child("drake:deformable_properties");
  const std::string link_name(link.Attribute("name").value);
  ir::DeformableProperties d;
  d.loc = props.GetLoc();
  bool ok = true;
  auto fail = [&](DiagKind kind, Loc loc, std::string message) {
    diags().Report(kind, loc, std::move(message));
    ok = false;
  };

  // the FEM parameters (Drake's LoadDeformableConfig), each optional
  CheckChildren(props, {"drake:youngs_modulus", "drake:poissons_ratio", "drake:mass_damping",
                        "drake:stiffness_damping", "drake:mass_density",
                        "drake:material_model"});
  struct Param {
    const char* tag;
    double* out;
    bool (*valid)(double);
    const char* rule;
  };
  const Param params[] = {
      {"drake:youngs_modulus", &d.youngs_modulus, [](double v) { return v > 0; },
       "Young's modulus must be positive"},
      {"drake:poissons_ratio", &d.poissons_ratio, [](double v) { return v > -1 && v < 0.5; },
       "Poisson's ratio must be in the range (-1, 0.5)"},
      {"drake:mass_damping", &d.mass_damping, [](double v) { return v >= 0; },
       "Mass damping must be non-negative"},
      {"drake:stiffness_damping", &d.stiffness_damping, [](double v) { return v >= 0; },
       "Stiffness damping must be non-negative"},
      {"drake:mass_density", &d.mass_density, [](double v) { return v > 0; },
       "Mass density must be positive"},
  };
  for (const Param& p : params) {
    xml::XmlElement c = props.Child(p.tag);
    if (!c) continue;
    auto v = TextDouble(c);
    if (!v) {
      ok = false;
      continue;
    }
    if (!p.valid(*v)) {
      fail(DiagKind::BadValue, c.GetLoc(), fmt::format("{}, got {}", p.rule, *v));
      continue;
    }
    *p.out = *v;
  }
  if (xml::XmlElement c = props.Child("drake:material_model")) {
    const std::string mm = Trimmed(c.Text());
    if (mm == "linear_corotated" || mm == "corotated" || mm == "neohookean" || mm == "linear") {
      d.material_model = mm;
    } else {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("Invalid <drake:material_model> value '{}'. Must be 'linear', "
                       "'linear_corotated', 'neohookean', or 'corotated'.",
                       mm));
    }
  }

  // wall boundary conditions: children of the link, in world coordinates
  for (auto c = link.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() != "drake:wall_boundary_condition") continue;
    CheckChildren(c, {"drake:point_on_plane", "drake:outward_normal"});
    auto point = ChildVector3(c, "drake:point_on_plane");
    auto normal = ChildVector3(c, "drake:outward_normal");
    for (const char* t : {"drake:point_on_plane", "drake:outward_normal"}) {
      if (!c.Child(t)) {
        fail(DiagKind::MissingElement, c.GetLoc(),
             fmt::format("<drake:wall_boundary_condition>: Unable to find the <{}> child tag.",
                         t));
      }
    }
    if (!point || !normal) {
      ok = false;
      continue;
    }
    if (!(normal->norm() > 1e-10)) {
      fail(DiagKind::ZeroAxis, c.Child("drake:outward_normal").GetLoc(),
           "Outward normal vector cannot be zero in <drake:outward_normal>");
      continue;
    }
    d.wall_boundary_conditions.push_back({*point, normal->normalized()});
  }

  // what a deformable link may hold: one collision, at most one visual, and
  // no mass properties or frames of its own (Drake: AddDeformableLinkFromSpecification)
  std::vector<xml::XmlElement> collisions, visuals;
  for (auto c = link.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view t = c.Name();
    if (t == "collision") {
      collisions.push_back(c);
    } else if (t == "visual") {
      visuals.push_back(c);
    } else if (t == "inertial") {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("deformable link '{}' must not have an <inertial>: its mass comes from "
                       "drake:mass_density and its mesh",
                       link_name));
    } else if (t == "frame") {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("deformable link '{}' must not have frames attached to it", link_name));
    } else if (t != "pose" && t != "drake:deformable_properties" &&
               t != "drake:wall_boundary_condition") {
      diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                     fmt::format("tag '{}' found as a child of deformable link '{}' is "
                                 "unsupported and will be ignored",
                                 t, link_name));
    }
  }
  if (collisions.size() != 1) {
    fail(DiagKind::BadValue, link.GetLoc(),
         fmt::format("Each deformable <link> must have exactly one <collision> element; link "
                     "'{}' has {}",
                     link_name, collisions.size()));
  } else {
    const xml::XmlElement collision = collisions.front();
    const xml::XmlElement geometry = collision.Child("geometry");
    const xml::XmlElement sphere = geometry ? geometry.Child("sphere") : xml::XmlElement();
    const xml::XmlElement mesh = geometry ? geometry.Child("mesh") : xml::XmlElement();
    std::optional<double> hint;
    if (auto proximity = collision.Child("drake:proximity_properties")) {
      if (auto h = proximity.Child("drake:mesh_resolution_hint")) hint = TextDouble(h);
    }
    if (sphere) {
      if (!hint) {
        fail(DiagKind::MissingElement, geometry.GetLoc(),
             "The <geometry> of a deformable <link>'s <collision> is a primitive shape, so it "
             "must specify a positive <drake:mesh_resolution_hint> in its "
             "<drake:proximity_properties> to control the resolution of the tetrahedral mesh "
             "generated for it.");
      } else if (!(*hint > 0)) {
        fail(DiagKind::BadValue, geometry.GetLoc(),
             "drake:mesh_resolution_hint must be positive.");
      } else {
        d.resolution_hint = *hint;
      }
    } else if (mesh) {
      const std::string uri = Trimmed(mesh.Child("uri") ? mesh.Child("uri").Text() : "");
      if (!EndsWithVtk(uri)) {
        fail(DiagKind::BadValue, mesh.GetLoc(),
             fmt::format("The <mesh> of a deformable <link>'s <collision> must name a .vtk file "
                         "holding a tetrahedral mesh, found '{}'",
                         uri));
      }
      if (hint) {
        diags().Report(DiagKind::UnsupportedElement, geometry.GetLoc(),
                       "A deformable <link>'s <collision> specified a "
                       "<drake:mesh_resolution_hint>, but its <geometry> is a <mesh>; the hint "
                       "is ignored because the mesh is used as given.");
      }
    } else {
      std::string found;
      if (geometry) {
        for (auto g = geometry.FirstChild(); g; g = g.NextSibling()) {
          found += fmt::format("{}<{}>", found.empty() ? "" : ", ", g.Name());
        }
      }
      fail(DiagKind::BadGeometry, geometry ? geometry.GetLoc() : collision.GetLoc(),
           fmt::format("The <geometry> of a deformable <link>'s <collision> must be either a "
                       "<mesh> (whose uri names a .vtk file containing a tetrahedral mesh) or a "
                       "<sphere>; found {}.",
                       found.empty() ? "nothing" : found));
    }
  }
  if (visuals.size() > 1) {
    fail(DiagKind::BadValue, visuals[1].GetLoc(),
         fmt::format("A deformable <link> may have at most one <visual> element; link '{}' has "
                     "{}",
                     link_name, visuals.size()));
  }

  // nothing may be jointed or attached to it: it is not a rigid body
  const xml::XmlElement model = link.Parent();
  for (auto c = model.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view t = c.Name();
    if (t == "joint" || t == "drake:joint") {
      const bool drake_joint = t == "drake:joint";
      for (const char* end : {"parent", "child"}) {
        const xml::XmlElement ref = c.Child(drake_joint ? fmt::format("drake:{}", end) : end);
        if (ref && Trimmed(ref.Text()) == link_name) {
          fail(DiagKind::BadValue, ref.GetLoc(),
               fmt::format("deformable link '{}' cannot be the {} of joint '{}': a deformable "
                           "body has no joints",
                           link_name, end, c.Attribute("name").value));
        }
      }
    } else if (t == "frame") {
      if (auto a = c.Attribute("attached_to"); a.present() && Trimmed(a.value) == link_name) {
        fail(DiagKind::BadValue, a.loc,
             fmt::format("frame '{}' cannot be attached to deformable link '{}'",
                         c.Attribute("name").value, link_name));
      }
    }
  }

  if (!ok) return;
  ir::Body& b = module()[body];
  // no mass in the rigid plant: the FEM model has it (mass_density)
  b.inertial.reset();
  b.deformable = std::move(d);
}

}  // namespace mdlc::frontend::sdf
