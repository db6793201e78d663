#include "frontend/xml/attribute_reader.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>

#include "frontend/xml/trim.h"
#include "ir/scoped_name.h"

namespace mdlc::xml {

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

namespace {
// Calls f(value) for each whitespace-separated number; false at the first
// token that is not a number. Each token is read where it stands, in one
// pass (number lists are most of a model's bytes); a token that
// from_chars cannot read whole goes through ParseDouble, which also knows
// a leading '+' and out-of-range values.
template <typename F>
bool ForEachNumber(std::string_view text, F&& f) {
  const char* p = text.data();
  const char* const end = p + text.size();
  while (true) {
    while (p < end && IsXmlSpace(*p)) ++p;
    if (p >= end) return true;
    double value = 0;
    auto [stop, ec] = std::from_chars(p, end, value);
    if (ec == std::errc() && (stop == end || IsXmlSpace(*stop))) {
      f(value);
      p = stop;
      continue;
    }
    const char* token_end = p;
    while (token_end < end && !IsXmlSpace(*token_end)) ++token_end;
    auto v = ParseDouble(std::string_view(p, static_cast<size_t>(token_end - p)));
    if (!v) return false;
    f(*v);
    p = token_end;
  }
}
}  // namespace

std::optional<size_t> ParseDoublesInto(std::string_view text, double* out, size_t capacity) {
  size_t count = 0;
  const bool ok = ForEachNumber(text, [&](double v) {
    if (count < capacity) out[count] = v;
    ++count;
  });
  if (!ok) return std::nullopt;
  return count;
}

std::optional<std::vector<double>> ParseDoubleList(std::string_view text) {
  std::vector<double> out;
  out.reserve(8);  // most lists are vectors, quaternions, poses, inertias: one allocation
  if (!ForEachNumber(text, [&](double v) { out.push_back(v); })) return std::nullopt;
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

bool AttributeReader::Fixed(const XmlElement& e, std::string_view attr, double* out,
                            size_t count, Need need, Finite finite) {
  XmlAttribute a = e.Attribute(attr);
  if (!a.present()) {
    if (need == Need::Required) ReportMissing(e, attr);
    return false;
  }
  auto n = ParseDoublesInto(a.value, out, count);
  if (!n) {
    diags_.Report(DiagKind::BadValue, a.loc,
                  fmt::format("attribute '{}' of <{}> must be numbers, got '{}'", attr, e.Name(),
                              a.value));
    return false;
  }
  if (*n != count) {
    diags_.Report(DiagKind::BadValue, a.loc,
                  fmt::format("attribute '{}' of <{}> must have {} value{}, got {} ('{}')", attr,
                              e.Name(), count, count == 1 ? "" : "s", *n, a.value));
    return false;
  }
  if (finite == Finite::Required) {
    for (size_t i = 0; i < count; ++i) {
      if (!std::isfinite(out[i])) {
        diags_.Report(DiagKind::NonFinite, a.loc,
                      fmt::format("attribute '{}' of <{}> must be finite, got '{}'", attr,
                                  e.Name(), a.value));
        return false;
      }
    }
  }
  return true;
}

std::optional<std::vector<double>> AttributeReader::Doubles(const XmlElement& e,
                                                            std::string_view attr, size_t count,
                                                            Need need, Finite finite) {
  if (count > 0) {
    std::vector<double> values(count);
    if (!Fixed(e, attr, values.data(), count, need, finite)) return std::nullopt;
    return values;
  }
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
  double v;
  if (!Fixed(e, attr, &v, 1, need, finite)) return std::nullopt;
  return v;
}

std::optional<Eigen::Vector3d> AttributeReader::Vector3(const XmlElement& e,
                                                        std::string_view attr, Need need,
                                                        Finite finite) {
  Eigen::Vector3d v;
  if (!Fixed(e, attr, v.data(), 3, need, finite)) return std::nullopt;
  return v;
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
                                            std::initializer_list<std::string_view> known,
                                            std::initializer_list<WhenAbsent> absent) {
  // compare names first; build the located attribute only for an unknown one
  e.ForEachAttributeName([&](std::string_view name) {
    for (std::string_view k : known) {
      if (SameName(k, name)) return;
    }
    if (name.starts_with("xmlns")) return;
    const Loc loc = e.Attribute(name).loc;
    auto diag = diags_.Report(DiagKind::UnknownAttribute, loc,
                              fmt::format("unknown attribute '{}' on <{}> is ignored", name,
                                          e.Name()));
    const std::optional<std::string> best = ir::ClosestName(name, std::vector(known));
    if (!best) return;
    // a misspelled attribute leaves the one meant unset: say what that means
    std::string meaning;
    for (const WhenAbsent& a : absent) {
      if (a.attribute == *best && !e.Attribute(*best).present()) {
        meaning = fmt::format(" (as written, {})", a.meaning);
      }
    }
    diag.Note(loc, fmt::format("did you mean '{}'?{}", *best, meaning));
  });
}

}  // namespace mdlc::xml
