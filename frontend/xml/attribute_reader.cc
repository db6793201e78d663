#include "frontend/xml/attribute_reader.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>

namespace mdlc::xml {
namespace {
bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsSpace(s.back())) s.remove_suffix(1);
  return s;
}
}  // namespace

std::optional<double> ParseDouble(std::string_view text) {
  text = Trim(text);
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // overflow: keep strtod's answer (+-inf or a denormal)
    std::string copy(text);
    return std::strtod(copy.c_str(), nullptr);
  }
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::vector<double>> ParseDoubleList(std::string_view text) {
  std::vector<double> out;
  size_t i = 0;
  while (true) {
    while (i < text.size() && IsSpace(text[i])) ++i;
    if (i >= text.size()) break;
    size_t j = i;
    while (j < text.size() && !IsSpace(text[j])) ++j;
    auto v = ParseDouble(text.substr(i, j - i));
    if (!v) return std::nullopt;
    out.push_back(*v);
    i = j;
  }
  return out;
}

void AttributeReader::ReportMissing(const XmlElement& e, std::string_view attr) {
  diags_.Report(DiagKind::MissingAttribute, e.GetLoc(),
                fmt::format("<{}> is missing required attribute '{}'", e.Name(), attr));
}

std::optional<std::string_view> AttributeReader::String(const XmlElement& e, std::string_view attr,
                                                         Need need) {
  XmlAttribute a = e.Attribute(attr);
  if (!a.present()) {
    if (need == Need::Required) ReportMissing(e, attr);
    return std::nullopt;
  }
  return a.value;
}

std::optional<std::vector<double>> AttributeReader::Doubles(const XmlElement& e,
                                                            std::string_view attr, size_t count,
                                                            Need need, Finite finite) {
  XmlAttribute a = e.Attribute(attr);
  if (!a.present()) {
    if (need == Need::Required) ReportMissing(e, attr);
    return std::nullopt;
  }
  auto values = ParseDoubleList(a.value);
  if (!values) {
    diags_.Report(DiagKind::BadValue, a.loc,
                  fmt::format("attribute '{}' of <{}> must be numbers, got '{}'", attr, e.Name(),
                              a.value));
    return std::nullopt;
  }
  if (count && values->size() != count) {
    diags_.Report(DiagKind::BadValue, a.loc,
                  fmt::format("attribute '{}' of <{}> must have {} value{}, got {} ('{}')", attr,
                              e.Name(), count, count == 1 ? "" : "s", values->size(), a.value));
    return std::nullopt;
  }
  if (finite == Finite::Required) {
    for (double v : *values) {
      if (!std::isfinite(v)) {
        diags_.Report(DiagKind::NonFinite, a.loc,
                      fmt::format("attribute '{}' of <{}> must be finite, got '{}'", attr,
                                  e.Name(), a.value));
        return std::nullopt;
      }
    }
  }
  return values;
}

std::optional<double> AttributeReader::Double(const XmlElement& e, std::string_view attr,
                                              Need need, Finite finite) {
  auto v = Doubles(e, attr, 1, need, finite);
  if (!v) return std::nullopt;
  return (*v)[0];
}

std::optional<Eigen::Vector3d> AttributeReader::Vector3(const XmlElement& e,
                                                        std::string_view attr, Need need,
                                                        Finite finite) {
  auto v = Doubles(e, attr, 3, need, finite);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<bool> AttributeReader::Bool(const XmlElement& e, std::string_view attr, Need need) {
  XmlAttribute a = e.Attribute(attr);
  if (!a.present()) {
    if (need == Need::Required) ReportMissing(e, attr);
    return std::nullopt;
  }
  std::string_view v = Trim(a.value);
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  diags_.Report(DiagKind::BadValue, a.loc,
                fmt::format("attribute '{}' of <{}> must be true or false, got '{}'", attr,
                            e.Name(), a.value));
  return std::nullopt;
}

void AttributeReader::WarnUnknownAttributes(const XmlElement& e,
                                            std::initializer_list<std::string_view> known) {
  e.ForEachAttribute([&](const XmlAttribute& a) {
    for (std::string_view k : known) {
      if (k == a.name) return;
    }
    if (a.name.starts_with("xmlns")) return;
    diags_.Report(DiagKind::UnknownAttribute, a.loc,
                  fmt::format("unknown attribute '{}' on <{}> is ignored", a.name, e.Name()));
  });
}

}  // namespace mdlc::xml
