// attribute_reader.h - typed reading of XML attributes, with diagnostics.
//
// Every read reports its own problem at the attribute's location (or at the
// element's, for a missing attribute) and returns nullopt, so callers simply
// skip what they could not read and go on reporting other problems.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"

namespace mdlc::xml {

/// Number syntax shared by all XML formats: C doubles, with "nan", "inf" and
/// "-inf" accepted lexically (callers decide whether they are allowed).
std::optional<double> ParseDouble(std::string_view text);
/// Whitespace-separated doubles; nullopt if any token is not a number.
std::optional<std::vector<double>> ParseDoubleList(std::string_view text);
/// Up to `capacity` whitespace-separated doubles into `out`, without
/// allocating. Returns how many the text holds (which may exceed capacity;
/// only the first `capacity` are stored), or nullopt if one is not a number.
std::optional<size_t> ParseDoublesInto(std::string_view text, double* out, size_t capacity);

enum class Need { Optional, Required };
enum class Finite { Required, NotRequired };

class AttributeReader {
 public:
  explicit AttributeReader(DiagnosticEngine& diags) : diags_(diags) {}

  std::optional<std::string_view> String(const XmlElement& e, std::string_view attr,
                                         Need need = Need::Optional);
  std::optional<double> Double(const XmlElement& e, std::string_view attr,
                               Need need = Need::Optional, Finite finite = Finite::Required);
  /// Exactly `count` doubles.
  std::optional<std::vector<double>> Doubles(const XmlElement& e, std::string_view attr,
                                             size_t count, Need need = Need::Optional,
                                             Finite finite = Finite::Required);
  std::optional<Eigen::Vector3d> Vector3(const XmlElement& e, std::string_view attr,
                                         Need need = Need::Optional,
                                         Finite finite = Finite::Required);
  std::optional<bool> Bool(const XmlElement& e, std::string_view attr, Need need = Need::Optional);

  /// What an absent attribute means ("the upper limit is +inf"), said when
  /// an unknown attribute looks like a misspelling of it.
  struct WhenAbsent {
    std::string_view attribute;
    std::string_view meaning;
  };
  /// Warns about attributes not in `known` (a misspelling, most likely); a
  /// note suggests the closest known one, and says what its absence means
  /// when `absent` has it and the element does not write it.
  void WarnUnknownAttributes(const XmlElement& e, std::initializer_list<std::string_view> known,
                             std::initializer_list<WhenAbsent> absent = {});

  void ReportMissing(const XmlElement& e, std::string_view attr);
  /// Reads exactly `count` doubles into `out` (the common fixed-size case,
  /// with no allocation). Returns false after reporting a problem, or when
  /// the attribute is absent (reporting only if required).
  bool Fixed(const XmlElement& e, std::string_view attr, double* out, size_t count, Need need,
             Finite finite);
  DiagnosticEngine& diags() { return diags_; }

 private:
  DiagnosticEngine& diags_;
};

}  // namespace mdlc::xml
