#include "frontend/directives/yaml_schema.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/exceptions.h>

#include <cmath>

#include "frontend/xml/attribute_reader.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend {

std::unique_ptr<yaml::Document> YamlSchemaReader::Parse(std::string_view contents) {
  try {
    return yaml::Document::Load(contents);
  } catch (const YAML::Exception& e) {
    // yaml-cpp's exceptions carry the position of the problem
    Loc loc{file_, 1, 1};
    if (!e.mark.is_null() && e.mark.line >= 0) {
      loc = Loc{file_, static_cast<uint32_t>(e.mark.line + 1),
                static_cast<uint32_t>(e.mark.column + 1)};
    }
    // yaml-cpp's depth guard says only "bad file"
    const bool too_deep = dynamic_cast<const YAML::DeepRecursion*>(&e) != nullptr;
    diags_.Report(DiagKind::YamlSyntax, loc,
                  too_deep ? std::string("malformed YAML: nested too deeply")
                           : fmt::format("malformed YAML: {}", e.msg));
    return nullptr;
  }
}

Loc YamlSchemaReader::LocOf(const yaml::Node& node, Loc fallback) const {
  if (node.line() == 0) return fallback;  // undefined, or without a place
  return Loc{file_, node.line(), node.column()};
}

void YamlSchemaReader::ReportType(const yaml::Node& node, std::string_view what,
                                  std::string_view expected, Loc fallback) {
  std::string_view found = node.IsMap() ? "a map" : node.IsSequence() ? "a list" : "a scalar";
  diags_.Report(DiagKind::BadValue, LocOf(node, fallback),
                fmt::format("{} must be {}, not {}", what, expected, found));
}

// A map and the maps its merge keys ("<<: *defaults", YAML's merge key,
// which Drake's YAML reader honors) bring in, nearest first: a key of an
// earlier map hides the same key of a later one. Breadth-first, with no
// recursion, and bounded, so aliases cannot make it blow up.
std::vector<yaml::Node> YamlSchemaReader::MergedMaps(const yaml::Node& map) const {
  constexpr size_t kMaxMaps = 64;
  std::vector<yaml::Node> maps = {map};
  for (size_t i = 0; i < maps.size() && maps.size() < kMaxMaps; ++i) {
    for (const yaml::Entry entry : maps[i].Entries()) {
      if (!entry.first.IsScalar() || entry.first.Scalar() != "<<") continue;
      const yaml::Node merged = entry.second;
      if (merged.IsMap()) maps.push_back(merged);
      if (merged.IsSequence()) {
        for (const yaml::Node m : merged.Items()) {
          if (m.IsMap() && maps.size() < kMaxMaps) maps.push_back(m);
        }
      }
    }
  }
  return maps;
}

bool YamlSchemaReader::CheckMap(const yaml::Node& node, std::string_view what,
                                std::initializer_list<std::string_view> allowed, Loc fallback) {
  if (!node.IsMap()) {
    if (node.IsNull()) {
      diags_.Report(DiagKind::BadValue, LocOf(node, fallback),
                    fmt::format("{} is empty; it must be a map", what));
    } else {
      ReportType(node, what, "a map", fallback);
    }
    return false;
  }
  // checks one map's keys; says whether it merges others in
  auto check_keys = [&](const yaml::Node& map) {
    bool merges = false;
    std::vector<std::string_view> seen;
    for (const yaml::Entry entry : map.Entries()) {
      const yaml::Node key = entry.first;
      const Loc key_loc = LocOf(key, LocOf(map, fallback));
      if (!key.IsScalar()) {
        diags_.Report(DiagKind::BadValue, key_loc,
                      fmt::format("{} has a key that is not a name", what));
        continue;
      }
      const std::string_view name = key.Scalar();
      if (name == "<<") {
        merges = true;
        const yaml::Node merged = entry.second;
        bool maps_only = merged.IsMap() || merged.IsSequence();
        if (merged.IsSequence()) {
          for (const yaml::Node item : merged.Items()) maps_only = maps_only && item.IsMap();
        }
        if (!maps_only) {
          diags_.Report(DiagKind::BadValue, LocOf(merged, key_loc),
                        "a merge key ('<<') must name a map or a list of maps");
        }
        continue;
      }
      bool known = false;
      for (std::string_view a : allowed) known = known || a == name;
      if (!known) {
        auto diag = diags_.Report(DiagKind::UnknownKey, key_loc,
                                  fmt::format("unknown key '{}' in {}", name, what));
        std::vector<std::string_view> candidates(allowed);
        if (auto best = ir::ClosestName(name, candidates)) {
          diag.Note(key_loc, fmt::format("did you mean '{}'?", *best));
        }
        continue;
      }
      // within one map a key is written once; a merged map's key may be
      // overridden by the map merging it
      for (std::string_view s : seen) {
        if (s == name) {
          diags_.Report(DiagKind::BadValue, key_loc,
                        fmt::format("key '{}' appears twice in {}", name, what));
          break;
        }
      }
      seen.push_back(name);
    }
    return merges;
  };
  if (!check_keys(node)) return true;  // most maps merge nothing
  const std::vector<yaml::Node> maps = MergedMaps(node);
  for (size_t m = 1; m < maps.size(); ++m) check_keys(maps[m]);
  return true;
}

YamlSchemaReader::Field YamlSchemaReader::Get(const yaml::Node& map, std::string_view key) const {
  // the map's own key hides any merged one, and most maps merge nothing:
  // one walk of the map alone settles almost every lookup
  bool merges = false;
  for (const yaml::Entry entry : map.Entries()) {
    if (!entry.first.IsScalar()) continue;
    const std::string_view name = entry.first.Scalar();
    if (name == key) return Field{entry.second, LocOf(entry.first)};
    merges = merges || name == "<<";
  }
  if (!merges) return Field{};
  for (const yaml::Node m : MergedMaps(map)) {
    for (const yaml::Entry entry : m.Entries()) {
      if (entry.first.IsScalar() && entry.first.Scalar() == key) {
        return Field{entry.second, LocOf(entry.first)};
      }
    }
  }
  return Field{};
}

std::optional<LocatedString> YamlSchemaReader::String(const yaml::Node& node, std::string_view what,
                                                      Loc fallback) {
  const Loc loc = LocOf(node, fallback);
  if (node.IsNull()) return LocatedString{"", loc};
  if (!node.IsScalar()) {
    ReportType(node, what, "a string", fallback);
    return std::nullopt;
  }
  return LocatedString{std::string(node.Scalar()), loc};
}

std::optional<double> YamlSchemaReader::Number(const yaml::Node& node, std::string_view what,
                                               Loc fallback) {
  if (!node.IsScalar()) {
    ReportType(node, what, "a number", fallback);
    return std::nullopt;
  }
  const std::string_view text = node.Scalar();
  std::optional<double> value = xml::ParseDouble(text);
  if (!value) {
    // YAML spells the special values .inf, -.inf and .nan
    std::string lower;
    for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == ".inf" || lower == "+.inf" || lower == "-.inf" || lower == ".nan") {
      value = lower == ".nan" ? NAN : INFINITY;
    }
  }
  if (!value) {
    diags_.Report(DiagKind::BadValue, LocOf(node, fallback),
                  fmt::format("{} must be a number, not '{}'", what, text));
    return std::nullopt;
  }
  if (!std::isfinite(*value)) {
    diags_.Report(DiagKind::NonFinite, LocOf(node, fallback),
                  fmt::format("{} must be finite, not '{}'", what, text));
    return std::nullopt;
  }
  return value;
}

std::optional<std::vector<double>> YamlSchemaReader::Numbers(const yaml::Node& node,
                                                             std::string_view what, Loc fallback,
                                                             std::optional<size_t> count) {
  if (!node.IsSequence()) {
    ReportType(node, what, count ? fmt::format("a list of {} numbers", *count) : "a list of numbers",
               fallback);
    return std::nullopt;
  }
  if (count && node.size() != *count) {
    diags_.Report(DiagKind::BadValue, LocOf(node, fallback),
                  fmt::format("{} must have {} numbers, not {}", what, *count, node.size()));
    return std::nullopt;
  }
  std::vector<double> values;
  values.reserve(node.size());
  bool ok = true;
  for (const yaml::Node item : node.Items()) {
    auto v = Number(item, what, LocOf(node, fallback));
    ok = ok && v.has_value();
    if (v) values.push_back(*v);
  }
  if (!ok) return std::nullopt;
  return values;
}

std::optional<Eigen::Vector3d> YamlSchemaReader::Vector3(const yaml::Node& node,
                                                         std::string_view what, Loc fallback) {
  auto v = Numbers(node, what, fallback, 3);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<std::vector<LocatedString>> YamlSchemaReader::Strings(const yaml::Node& node,
                                                                    std::string_view what,
                                                                    Loc fallback) {
  if (node.IsNull()) return std::vector<LocatedString>{};
  if (!node.IsSequence()) {
    ReportType(node, what, "a list of names", fallback);
    return std::nullopt;
  }
  std::vector<LocatedString> out;
  out.reserve(node.size());
  bool ok = true;
  for (const yaml::Node item : node.Items()) {
    if (!item.IsScalar()) {
      ReportType(item, fmt::format("each entry of {}", what), "a name", LocOf(node, fallback));
      ok = false;
      continue;
    }
    out.push_back({std::string(item.Scalar()), LocOf(item, LocOf(node, fallback))});
  }
  if (!ok) return std::nullopt;
  return out;
}

std::string_view YamlSchemaReader::ExplicitTag(const yaml::Node& node) {
  const std::string_view tag = node.Tag();
  // yaml-cpp gives "?" for an untagged plain node and "!" for a quoted one
  if (tag.empty() || tag == "?" || tag == "!") return {};
  return tag;
}

}  // namespace mdlc::frontend
