// mjcf_elements.h - what the model-element lowerers share (not a public API).
//
// LowerModelElements (mjcf_elements.cc) lowers the MJCF elements that refer
// to the kinematic tree after <worldbody> is done, one file per job:
//   mjcf_elements_equality.cc  connect, weld, joint, distance
//   mjcf_elements_tendon.cc    fixed tendons
//   mjcf_elements_actuator.cc  motor, position, velocity, general
//   mjcf_elements_contact.cc   exclude, pair
//   mjcf_elements_keyframe.cc  key (checked; "home" else the first sets default positions)
//   mjcf_elements_qpos0.cc     body poses at qpos0 (for connect and weld)
// The helpers here read attribute values as an element sees them after
// default classes, look entities up by their MJCF names, and warn once per
// unsupported thing.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "frontend/mjcf/mjcf_reader_detail.h"

namespace mdlc::frontend::mjcf {

/// MuJoCo's tri-state `limited` attributes (ctrllimited, forcelimited, ...).
enum class Limited { False, True, Auto };

/// State of one LowerModelElements run.
class ElementsLowering {
 public:
  explicit ElementsLowering(MjcfReader& reader) : r(reader) {}

  MjcfReader& r;

  ir::Module& module() { return r.module(); }
  DiagnosticEngine& diags() { return r.diags(); }

  // --- attribute values (as written, or from the default class) ----------
  // Each reports a malformed value at the attribute and returns nullopt; an
  // absent attribute is nullopt without a report.
  std::optional<double> Double(const Attribute& a);
  /// Exactly `n` numbers (or at most `n` when `at_most`).
  std::optional<std::vector<double>> Doubles(const Attribute& a, size_t n, bool at_most = false);
  /// Any count of numbers (keyframe vectors).
  std::optional<std::vector<double>> AnyDoubles(const Attribute& a);
  std::optional<bool> Bool(const Attribute& a);
  /// true, false or auto; absent is Auto.
  std::optional<Limited> LimitedValue(const Attribute& a);
  /// MuJoCo's rule (MJCF-004): whether a range is in force, given its
  /// `limited` attribute and whether a range is written. With autolimits
  /// off, a range under limited="auto" is an error (reported at the range).
  bool IsLimited(const Attribute& limited, const Attribute& range);

  // --- lookups by MJCF name -------------------------------------------------
  // Each reports an unknown name as an error at the attribute.
  std::optional<BodyId> FindBody(const Attribute& a, std::string_view element);
  std::optional<JointId> FindJoint(const Attribute& a, std::string_view element);
  std::optional<FrameId> FindSite(const Attribute& a, std::string_view element);
  std::optional<GeometryId> FindGeom(const Attribute& a, std::string_view element);
  /// The body a (possibly unresolved) IR reference names.
  std::optional<BodyId> BodyOf(const ir::Ref<BodyId>& ref) const;

  /// A reference that is already resolved (the frontend knows the entity).
  ir::Ref<BodyId> BodyRef(BodyId id, Loc loc);
  ir::Ref<JointId> JointRef(JointId id, Loc loc);

  // --- warnings -------------------------------------------------------------
  /// Warns once per (element kind, attribute) that the plant cannot hold,
  /// when the element has the attribute (written or from its class).
  void WarnAttribute(const Element& e, std::string_view kind, std::string_view attr,
                     std::string_view why = {});
  /// Warns once per key (an element kind the plant cannot hold, ...).
  void WarnOnce(std::string_view key, DiagKind kind, Loc loc, std::string message);
  /// Warns once per key at `loc` for a value the plant cannot hold.
  void WarnValueOnce(std::string_view key, Loc loc, std::string message) {
    WarnOnce(key, DiagKind::UnsupportedValue, loc, std::move(message));
  }

  // --- the model at MuJoCo's reference configuration qpos0 -----------------
  /// X_WB at qpos0 (every joint at its default position, the MJCF joint
  /// `ref`), computed once, before any keyframe changes default positions.
  const Transform& PoseAtQpos0(BodyId body);
  /// The 1-dof joint's qpos0 (its `ref`).
  double JointQpos0(JointId joint) const;

  /// How many actuator elements the file declares, whatever their kind
  /// (MuJoCo's nu): a keyframe's `ctrl` has this many values.
  size_t actuator_elements = 0;

 private:
  void ComputeQpos0Poses();

  std::unordered_set<std::string> warned_;
  std::vector<Transform> X_WB0_;
  bool have_qpos0_ = false;
};

// One lowering function per top-level element kind (each in its own file).
void LowerEquality(ElementsLowering& L, const xml::XmlElement& section);
void LowerTendons(ElementsLowering& L, const xml::XmlElement& section);
void LowerActuators(ElementsLowering& L, const xml::XmlElement& section);
void LowerContact(ElementsLowering& L, const xml::XmlElement& section);
/// All <keyframe> sections at once: which key applies depends on all of them.
void LowerKeyframes(ElementsLowering& L, const std::vector<xml::XmlElement>& sections);

}  // namespace mdlc::frontend::mjcf
