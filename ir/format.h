// format.h - the input formats mdlc reads, and how a file's name selects one.
#pragma once

#include <optional>
#include <string_view>

namespace mdlc {

enum class Format { Urdf, Sdf, Mjcf, Directives };

/// "URDF", "SDFormat", "MJCF", "Model Directives".
std::string_view FormatName(Format format);

/// The format a path names by its extension (case-insensitive): .urdf, .sdf
/// or .world (Gazebo's worlds), .xml (MJCF), .dmd.yaml. nullopt for anything
/// else.
std::optional<Format> FormatFromPath(std::string_view path);

/// The format a user names (`mdlc -x NAME`, Python's format=): urdf; sdf or
/// sdformat; mjcf or mujoco; dmd or directives. nullopt for anything else.
std::optional<Format> FormatFromName(std::string_view name);

/// The format an XML document's root element names: robot (URDF), sdf
/// (SDFormat), mujoco (MJCF). nullopt for any other element.
std::optional<Format> FormatFromRootElement(std::string_view element);

/// The names FormatFromName takes, for messages: "urdf, sdf, mjcf or dmd".
inline constexpr std::string_view kFormatNames = "urdf, sdf, mjcf or dmd";

}  // namespace mdlc
