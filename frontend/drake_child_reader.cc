// drake_child_reader.cc - see drake_child_reader.h.
#include "frontend/drake_child_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "frontend/xml/trim.h"

namespace mdlc::frontend {
namespace {

/// The value a child writes, trimmed, and where: its @value or its text.
struct WrittenValue {
  std::string text;
  Loc loc;
};
WrittenValue ValueOf(const xml::XmlElement& child, ValueSpelling spelling) {
  if (spelling == ValueSpelling::Attribute) {
    const xml::XmlAttribute a = child.Attribute("value");
    return {std::string(xml::Trim(a.value)), a.present() ? a.loc : child.GetLoc()};
  }
  return {std::string(xml::Trim(child.Text())), child.GetLoc()};
}

/// What is missing when nothing is written: the attribute, or the text.
DiagKind MissingKind(ValueSpelling spelling) {
  return spelling == ValueSpelling::Attribute ? DiagKind::MissingAttribute
                                              : DiagKind::MissingElement;
}

}  // namespace

DrakeChildReader::DrakeChildReader(const xml::XmlElement& parent,
                                   std::initializer_list<std::string_view> known,
                                   ValueSpelling spelling, xml::AttributeReader& attrs,
                                   ir::Module& module,
                                   std::initializer_list<std::string_view> repeatable,
                                   bool check_attributes)
    : parent_(parent),
      parent_name_(parent.Name()),
      spelling_(spelling),
      diags_(attrs.diags()),
      module_(module) {
  if (check_attributes) attrs.WarnUnknownAttributes(parent, {});
  // unknown and repeated children: Drake ignores them (or, for SDFormat,
  // rejects unknown drake: ones); mdlc warns. Known tags are literals, so
  // `seen` may hold views of them.
  std::vector<std::string_view> seen;
  for (auto c = parent.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view tag = c.Name();
    const std::string_view* known_tag = nullptr;
    for (const std::string_view& k : known) {
      if (k == tag) known_tag = &k;
    }
    if (!known_tag) {
      diags_.Report(DiagKind::UnknownElement, c.GetLoc(),
                    fmt::format("unknown element <{}> in <{}> is ignored", tag, parent_name_));
      continue;
    }
    if (std::find(repeatable.begin(), repeatable.end(), *known_tag) != repeatable.end()) {
      continue;
    }
    if (std::find(seen.begin(), seen.end(), *known_tag) != seen.end()) {
      diags_.Report(DiagKind::UnknownElement, c.GetLoc(),
                    fmt::format("<{}> is repeated in <{}>; only the first one is used",
                                *known_tag, parent_name_));
    } else {
      seen.push_back(*known_tag);
    }
  }
}

xml::XmlElement DrakeChildReader::Find(std::string_view tag, xml::Need need) {
  xml::XmlElement child = parent_.Child(tag);
  if (!child && need == xml::Need::Required) {
    Fail(parent_.GetLoc(), fmt::format("<{}> needs a <{}> child", parent_name_, tag),
         DiagKind::MissingElement);
  }
  return child;
}

std::optional<DrakeChildReader::WrittenName> DrakeChildReader::ReadName(
    const xml::XmlElement& child, std::string_view attr, ValueSpelling spelling) {
  if (spelling == ValueSpelling::Attribute) {
    // as written: Drake does not trim attribute names
    const xml::XmlAttribute a = child.Attribute(attr);
    if (!a.present() || a.value.empty()) {
      Fail(a.present() ? a.loc : child.GetLoc(), fmt::format("<{}> needs a name", child.Name()),
           DiagKind::MissingAttribute);
      return std::nullopt;
    }
    return WrittenName{module_.Intern(a.value), a.loc};
  }
  const std::string text(xml::Trim(child.Text()));
  if (text.empty()) {
    Fail(child.GetLoc(), fmt::format("<{}> needs a name", child.Name()),
         DiagKind::MissingElement);
    return std::nullopt;
  }
  return WrittenName{module_.Intern(text), child.GetLoc()};
}

std::optional<Eigen::Vector3d> DrakeChildReader::Vector(std::string_view tag, Sign sign) {
  xml::XmlElement child = Find(tag, xml::Need::Required);
  if (!child) return std::nullopt;
  const WrittenValue v = ValueOf(child, spelling_);
  if (v.text.empty()) {
    Fail(v.loc, fmt::format("<{}> needs a value", tag), MissingKind(spelling_));
    return std::nullopt;
  }
  auto values = xml::ParseDoubleList(v.text);
  if (!values || values->size() != 3) {
    Fail(v.loc, fmt::format("<{}> must hold 3 numbers, got '{}'", tag, v.text));
    return std::nullopt;
  }
  const Eigen::Vector3d out((*values)[0], (*values)[1], (*values)[2]);
  if (!out.allFinite()) {
    Fail(v.loc, fmt::format("<{}> must hold finite numbers, got '{}'", tag, v.text),
         DiagKind::NonFinite);
    return std::nullopt;
  }
  if ((sign == Sign::NonNegative && out.minCoeff() < 0) ||
      (sign == Sign::Positive && !(out.minCoeff() > 0))) {
    Fail(v.loc, fmt::format("<{}> must be {}, got '{}'", tag,
                            sign == Sign::Positive ? "positive" : "non-negative", v.text));
    return std::nullopt;
  }
  return out;
}

std::optional<double> DrakeChildReader::Scalar(std::string_view tag, xml::Need need, Sign sign,
                                               Infinities inf) {
  xml::XmlElement child = Find(tag, need);
  if (!child) return std::nullopt;
  const WrittenValue v = ValueOf(child, spelling_);
  if (v.text.empty()) {
    Fail(v.loc, fmt::format("<{}> needs a value", tag), MissingKind(spelling_));
    return std::nullopt;
  }
  return CheckedScalar(v.text, v.loc, fmt::format("<{}>", tag), sign, inf,
                       /*lenient=*/spelling_ == ValueSpelling::Text);
}

std::optional<double> DrakeChildReader::AttributeScalar(const xml::XmlElement& child,
                                                        std::string_view attr) {
  const std::string child_name(child.Name());
  const xml::XmlAttribute a = child.Attribute(attr);
  if (!a.present()) {
    Fail(child.GetLoc(), fmt::format("<{}> needs its '{}' attribute", child_name, attr),
         DiagKind::MissingAttribute);
    return std::nullopt;
  }
  // an attribute in both formats, so never lenient: libsdformat's leniency
  // about text after a number is for element text
  return CheckedScalar(xml::Trim(a.value), a.loc, fmt::format("'{}' of <{}>", attr, child_name),
                       Sign::Any, {}, /*lenient=*/false);
}

std::optional<double> DrakeChildReader::CheckedScalar(std::string_view text, Loc loc,
                                                      const std::string& what, Sign sign,
                                                      Infinities inf, bool lenient) {
  std::optional<double> v = xml::ParseDouble(text);
  if (!v && lenient && !text.empty()) {
    // libsdformat reads the leading number of element text and drops the
    // rest; real models rely on it, so take the number, and warn
    const std::string copy(text);
    char* end = nullptr;
    const double prefix = std::strtod(copy.c_str(), &end);
    if (end && end != copy.c_str()) {
      diags_.Report(DiagKind::TrailingText, loc,
                    fmt::format("{} holds '{}': the text after the number {} is ignored", what,
                                text, std::string_view(copy.c_str(), end - copy.c_str())));
      v = prefix;
    }
  }
  if (!v) {
    Fail(loc, fmt::format("{} must hold a number, got '{}'", what, text));
    return std::nullopt;
  }
  const bool bad_inf = (std::isinf(*v) && *v > 0 && !inf.positive) ||
                       (std::isinf(*v) && *v < 0 && !inf.negative);
  if (std::isnan(*v) || bad_inf) {
    const char* rule = std::isnan(*v)  ? "a number, not NaN"
                       : inf.positive ? "finite or inf"
                       : inf.negative ? "finite or -inf"
                                      : "finite";
    Fail(loc, fmt::format("{} must be {}, got '{}'", what, rule, text));
    return std::nullopt;
  }
  if (sign == Sign::Positive && !(*v > 0)) {
    Fail(loc, fmt::format("{} must be positive, got '{}'", what, text));
    return std::nullopt;
  }
  if (sign == Sign::NonNegative && !(*v >= 0)) {
    Fail(loc, fmt::format("{} must be non-negative, got '{}'", what, text));
    return std::nullopt;
  }
  return v;
}

Loc DrakeChildReader::ValueLoc(const xml::XmlElement& child) const {
  return ValueOf(child, spelling_).loc;
}

void DrakeChildReader::Fail(Loc loc, std::string message, DiagKind kind) {
  diags_.Report(kind, loc, std::move(message));
  ok_ = false;
}

}  // namespace mdlc::frontend
