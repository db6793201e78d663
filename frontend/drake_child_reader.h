// drake_child_reader.h - reads the children of one drake: element, in either
// spelling of Drake's XML extensions: URDF writes a child's value or name in
// an attribute (<drake:bushing_frameA name="a"/>, <drake:x value="1 2 3"/>),
// SDFormat in the child's text (<drake:bushing_frameA>a</drake:bushing_frameA>).
// Everything else - which children exist, which are required, the rules a
// value must meet and every message - is the same for both formats, so it is
// written once here (as drake_proximity.h does for proximity properties).
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"
#include "ir/module.h"
#include "ir/syntax/drake_proximity_tags.h"

namespace mdlc::frontend {

/// Where a drake: child writes its value or name (shared with the writers).
using syntax::ValueSpelling;

/// The sign a number must have.
enum class Sign { Any, Positive, NonNegative };

/// Which infinities a number may be; NaN never is.
struct Infinities {
  bool positive = false;
  bool negative = false;
};

/// Reads the children of one drake: element. As in Drake, each child is
/// found by tag (the first of a tag wins; mdlc warns about repeats and about
/// unknown children) and a missing required child is reported at the parent.
/// Every problem is reported and makes ok() false; the caller then adds
/// nothing to the module.
class DrakeChildReader {
 public:
  /// `known`: the children `parent` may have; `repeatable`: those of them
  /// that may be given more than once. `check_attributes`: warn about any
  /// attribute of `parent` (false when the caller checks them itself).
  DrakeChildReader(const xml::XmlElement& parent, std::initializer_list<std::string_view> known,
                   ValueSpelling spelling, xml::AttributeReader& attrs, ir::Module& module,
                   std::initializer_list<std::string_view> repeatable = {},
                   bool check_attributes = true);

  bool ok() const { return ok_; }
  ValueSpelling spelling() const { return spelling_; }
  DiagnosticEngine& diags() { return diags_; }

  /// The child `tag`; reports its absence when required.
  xml::XmlElement Find(std::string_view tag, xml::Need need);

  /// A reference by name to a link, frame or joint: the required child
  /// `tag`'s name, located where it is written for later diagnostics.
  template <typename RefT>
  bool Name(std::string_view tag, RefT& ref) {
    xml::XmlElement child = Find(tag, xml::Need::Required);
    return child && NameOf(child, ref);
  }
  /// The name `child` writes: its text, or its attribute `attr` in the
  /// attribute spelling.
  template <typename RefT>
  bool NameOf(const xml::XmlElement& child, RefT& ref, std::string_view attr = "name") {
    return Assign(ReadName(child, attr, spelling_), ref);
  }
  /// The name in `child`'s attribute `attr`, in either spelling (Drake reads
  /// <drake:tendon_constraint_joint name="j" a="1"/> from both formats).
  template <typename RefT>
  bool AttributeNameOf(const xml::XmlElement& child, RefT& ref, std::string_view attr) {
    return Assign(ReadName(child, attr, ValueSpelling::Attribute), ref);
  }

  /// Three finite numbers, the value of the required child `tag`.
  std::optional<Eigen::Vector3d> Vector(std::string_view tag, Sign sign = Sign::Any);
  /// One number, the value of the child `tag`; nullopt when it is absent.
  std::optional<double> Scalar(std::string_view tag, xml::Need need, Sign sign,
                               Infinities inf = {});
  /// One finite number in `child`'s attribute `attr`, in either spelling.
  std::optional<double> AttributeScalar(const xml::XmlElement& child, std::string_view attr);

  /// Where `child` writes its value (its @value, or the child itself).
  Loc ValueLoc(const xml::XmlElement& child) const;

  /// Reports a problem the caller found; ok() becomes false.
  void Fail(Loc loc, std::string message, DiagKind kind = DiagKind::BadValue);
  /// A problem already reported (by another reader); ok() becomes false.
  void Invalidate() { ok_ = false; }

 private:
  /// A name and where it is written; nullopt after reporting.
  struct WrittenName {
    Symbol name;
    Loc loc;
  };
  std::optional<WrittenName> ReadName(const xml::XmlElement& child, std::string_view attr,
                                      ValueSpelling spelling);
  template <typename RefT>
  static bool Assign(const std::optional<WrittenName>& written, RefT& ref) {
    if (!written) return false;
    ref.name = written->name;
    ref.loc = written->loc;
    return true;
  }
  /// The number `text` holds, checked against `sign` and `inf`; `what` names
  /// the value in messages ("<drake:x>" or "'a' of <drake:x>"). `lenient`:
  /// take the leading number of text followed by more, with a warning
  /// (libsdformat does so for element text).
  std::optional<double> CheckedScalar(std::string_view text, Loc loc, const std::string& what,
                                      Sign sign, Infinities inf, bool lenient);

  const xml::XmlElement& parent_;
  const std::string parent_name_;  // XmlElement::Name() is only valid until the next call
  const ValueSpelling spelling_;
  DiagnosticEngine& diags_;
  ir::Module& module_;
  bool ok_ = true;
};

}  // namespace mdlc::frontend
