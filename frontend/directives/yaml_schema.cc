#include "frontend/directives/yaml_schema.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>

#include <cmath>

#include "frontend/xml/attribute_reader.h"
#include "ir/scoped_name.h"

namespace mdlc::frontend {

std::optional<YAML::Node> YamlSchemaReader::Parse(std::string_view contents) {
  try {
    return YAML::Load(std::string(contents));
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
    return std::nullopt;
  }
}

Loc YamlSchemaReader::LocOf(const YAML::Node& node, Loc fallback) const {
  if (!node.IsDefined()) return fallback;
  const YAML::Mark mark = node.Mark();
  if (mark.is_null() || mark.line < 0) return fallback;
  return Loc{file_, static_cast<uint32_t>(mark.line + 1), static_cast<uint32_t>(mark.column + 1)};
}

void YamlSchemaReader::ReportType(const YAML::Node& node, std::string_view what,
                                  std::string_view expected, Loc fallback) {
  std::string_view found = node.IsMap() ? "a map" : node.IsSequence() ? "a list" : "a scalar";
  diags_.Report(DiagKind::BadValue, LocOf(node, fallback),
                fmt::format("{} must be {}, not {}", what, expected, found));
}

// A map and the maps its merge keys ("<<: *defaults", YAML's merge key,
// which Drake's YAML reader honors) bring in, nearest first: a key of an
// earlier map hides the same key of a later one. Breadth-first, with no
// recursion, and bounded, so aliases cannot make it blow up.
std::vector<YAML::Node> YamlSchemaReader::MergedMaps(const YAML::Node& map) const {
  constexpr size_t kMaxMaps = 64;
  std::vector<YAML::Node> maps = {map};
  for (size_t i = 0; i < maps.size() && maps.size() < kMaxMaps; ++i) {
    for (auto it = maps[i].begin(); it != maps[i].end(); ++it) {
      if (!it->first.IsScalar() || it->first.Scalar() != "<<") continue;
      const YAML::Node merged = it->second;
      if (merged.IsMap()) maps.push_back(merged);
      if (merged.IsSequence()) {
        for (const YAML::Node& m : merged) {
          if (m.IsMap() && maps.size() < kMaxMaps) maps.push_back(m);
        }
      }
    }
  }
  return maps;
}

bool YamlSchemaReader::CheckMap(const YAML::Node& node, std::string_view what,
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
  const std::vector<YAML::Node> maps = MergedMaps(node);
  for (size_t m = 0; m < maps.size(); ++m) {
    std::vector<std::string_view> seen;
    for (auto it = maps[m].begin(); it != maps[m].end(); ++it) {
      const YAML::Node key = it->first;  // a copy: it-> yields a temporary
      const Loc key_loc = LocOf(key, LocOf(maps[m], fallback));
      if (!key.IsScalar()) {
        diags_.Report(DiagKind::BadValue, key_loc,
                      fmt::format("{} has a key that is not a name", what));
        continue;
      }
      const std::string& name = key.Scalar();
      if (name == "<<") {
        const YAML::Node merged = it->second;
        bool maps_only = merged.IsMap() || merged.IsSequence();
        if (merged.IsSequence()) {
          for (const YAML::Node& item : merged) maps_only = maps_only && item.IsMap();
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
      seen.push_back(key.Scalar());
    }
  }
  return true;
}

YamlSchemaReader::Field YamlSchemaReader::Get(const YAML::Node& map, std::string_view key) const {
  for (const YAML::Node& m : MergedMaps(map)) {
    for (auto it = m.begin(); it != m.end(); ++it) {
      if (it->first.IsScalar() && it->first.Scalar() == key) {
        return Field{it->second, LocOf(it->first)};
      }
    }
  }
  return Field{YAML::Node(YAML::NodeType::Undefined), {}};
}

std::optional<LocatedString> YamlSchemaReader::String(const YAML::Node& node, std::string_view what,
                                                      Loc fallback) {
  const Loc loc = LocOf(node, fallback);
  if (node.IsNull()) return LocatedString{"", loc};
  if (!node.IsScalar()) {
    ReportType(node, what, "a string", fallback);
    return std::nullopt;
  }
  return LocatedString{node.Scalar(), loc};
}

std::optional<double> YamlSchemaReader::Number(const YAML::Node& node, std::string_view what,
                                               Loc fallback) {
  if (!node.IsScalar()) {
    ReportType(node, what, "a number", fallback);
    return std::nullopt;
  }
  const std::string& text = node.Scalar();
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

std::optional<std::vector<double>> YamlSchemaReader::Numbers(const YAML::Node& node,
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
  for (const YAML::Node& item : node) {
    auto v = Number(item, what, LocOf(node, fallback));
    ok = ok && v.has_value();
    if (v) values.push_back(*v);
  }
  if (!ok) return std::nullopt;
  return values;
}

std::optional<Eigen::Vector3d> YamlSchemaReader::Vector3(const YAML::Node& node,
                                                         std::string_view what, Loc fallback) {
  auto v = Numbers(node, what, fallback, 3);
  if (!v) return std::nullopt;
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<std::vector<LocatedString>> YamlSchemaReader::Strings(const YAML::Node& node,
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
  for (const YAML::Node& item : node) {
    if (!item.IsScalar()) {
      ReportType(item, fmt::format("each entry of {}", what), "a name", LocOf(node, fallback));
      ok = false;
      continue;
    }
    out.push_back({item.Scalar(), LocOf(item, LocOf(node, fallback))});
  }
  if (!ok) return std::nullopt;
  return out;
}

std::string_view YamlSchemaReader::ExplicitTag(const YAML::Node& node) {
  const std::string& tag = node.Tag();
  // yaml-cpp gives "?" for an untagged plain node and "!" for a quoted one
  if (tag.empty() || tag == "?" || tag == "!") return {};
  return tag;
}

}  // namespace mdlc::frontend
