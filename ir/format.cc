#include "ir/format.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace mdlc {

std::string_view FormatName(Format format) {
  switch (format) {
    case Format::Urdf: return "URDF";
    case Format::Sdf: return "SDFormat";
    case Format::Mjcf: return "MJCF";
    case Format::Directives: return "Model Directives";
  }
  return "?";
}

std::optional<Format> FormatFromPath(std::string_view path) {
  std::string lower(path);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  auto ends_with = [&](std::string_view suffix) { return std::string_view(lower).ends_with(suffix); };
  if (ends_with(".urdf")) return Format::Urdf;
  if (ends_with(".sdf") || ends_with(".world")) return Format::Sdf;  // .world: Gazebo's worlds
  if (ends_with(".xml")) return Format::Mjcf;
  if (ends_with(".dmd.yaml")) return Format::Directives;
  return std::nullopt;
}

std::optional<Format> FormatFromName(std::string_view name) {
  if (name == "urdf") return Format::Urdf;
  if (name == "sdf" || name == "sdformat") return Format::Sdf;
  if (name == "mjcf" || name == "mujoco") return Format::Mjcf;
  if (name == "dmd" || name == "directives") return Format::Directives;
  return std::nullopt;
}

std::optional<Format> FormatFromRootElement(std::string_view element) {
  if (element == "robot") return Format::Urdf;
  if (element == "sdf") return Format::Sdf;
  if (element == "mujoco") return Format::Mjcf;
  return std::nullopt;
}

}  // namespace mdlc
