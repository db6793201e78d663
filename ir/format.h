// format.h - the input formats mdlc reads, and how a file's name selects one.
#pragma once

#include <optional>
#include <string_view>

namespace mdlc {

enum class Format { Urdf, Sdf, Mjcf, Directives };

/// "URDF", "SDFormat", "MJCF", "Model Directives".
std::string_view FormatName(Format format);

/// The format a path names by its extension (case-insensitive): .urdf, .sdf,
/// .xml (MJCF), .dmd.yaml. nullopt for anything else.
std::optional<Format> FormatFromPath(std::string_view path);

}  // namespace mdlc
