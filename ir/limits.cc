#include "ir/limits.h"

#include <fmt/format.h>

#include <charconv>
#include <limits>

namespace mdlc {

const std::vector<LimitInfo>& AllLimits() {
  static const std::vector<LimitInfo> kLimits = {
      {"file-size", "bytes of any one file read (model, include, mesh)", &Limits::file_size,
       uint64_t{std::numeric_limits<int>::max()}},
      {"total-size", "bytes of all model files of one compile", &Limits::total_size,
       std::numeric_limits<uint64_t>::max()},
      {"elements", "elements in one XML document", &Limits::elements,
       std::numeric_limits<uint64_t>::max()},
      {"depth", "element nesting depth of one XML document", &Limits::depth,
       std::numeric_limits<uint64_t>::max()},
      {"include-depth", "files included inside included files", &Limits::include_depth,
       std::numeric_limits<uint64_t>::max()},
      {"model-depth", "nesting depth of model instances", &Limits::model_depth,
       std::numeric_limits<uint64_t>::max()},
      {"mesh-vertices", "vertices of one mesh file", &Limits::mesh_vertices,
       std::numeric_limits<uint64_t>::max()},
      // a day at most: the reader's deadline is kept in milliseconds
      {"mesh-seconds", "seconds to read one mesh file", &Limits::mesh_seconds, 24 * 3600},
      {"macro-depth", "xacro macro calls inside macro calls", &Limits::macro_depth,
       std::numeric_limits<uint64_t>::max()},
      {"expansion-nodes", "nodes one xacro expansion makes", &Limits::expansion_nodes,
       std::numeric_limits<uint64_t>::max()},
  };
  return kLimits;
}

namespace {

std::optional<uint64_t> ParseCount(std::string_view text) {
  uint64_t scale = 1;
  if (!text.empty()) {
    switch (text.back()) {
      case 'K': case 'k': scale = uint64_t{1} << 10; break;
      case 'M': case 'm': scale = uint64_t{1} << 20; break;
      case 'G': case 'g': scale = uint64_t{1} << 30; break;
      default: break;
    }
    if (scale != 1) text.remove_suffix(1);
  }
  uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (value > std::numeric_limits<uint64_t>::max() / scale) return std::nullopt;
  return value * scale;
}

std::string LimitNames() {
  std::string names;
  for (const LimitInfo& l : AllLimits()) names += (names.empty() ? "" : ", ") + std::string(l.name);
  return names;
}

}  // namespace

std::optional<std::string> SetLimit(Limits& limits, std::string_view setting) {
  const size_t eq = setting.find('=');
  if (eq == std::string_view::npos) {
    return fmt::format("limit '{}' has no value; write NAME=VALUE, NAME one of {}", setting,
                       LimitNames());
  }
  const std::string_view name = setting.substr(0, eq);
  for (const LimitInfo& l : AllLimits()) {
    if (l.name != name) continue;
    const std::optional<uint64_t> value = ParseCount(setting.substr(eq + 1));
    if (!value || *value == 0) {
      return fmt::format("limit {} needs a positive whole number (K, M, G suffixes allowed), "
                         "not '{}'",
                         name, setting.substr(eq + 1));
    }
    if (*value > l.max_value) {
      return fmt::format("limit {} can be at most {}", name, l.max_value);
    }
    limits.*l.field = *value;
    return std::nullopt;
  }
  return fmt::format("unknown limit '{}'; the limits are {}", name, LimitNames());
}

std::string FormatBytes(uint64_t bytes) {
  constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB"};
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  double value = static_cast<double>(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 3) {
    value /= 1024;
    ++unit;
  }
  return value == static_cast<double>(static_cast<uint64_t>(value))
             ? fmt::format("{} {}", static_cast<uint64_t>(value), kUnits[unit])
             : fmt::format("{:.1f} {}", value, kUnits[unit]);
}

}  // namespace mdlc
