// cli_input.h - what a file argument of the command line is: a model file,
// a Gazebo model folder (the frontend reads its model.config), or '-', the
// model text on standard input; and the format a user may name for it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "mdlc/mdlc.h"

namespace mdlc::cli {

/// The names `--format` and `-x` take for an input: those of
/// FormatFromName, and xacro (a file to expand first, whatever its name).
inline constexpr std::string_view kInputFormatNames = "urdf, sdf, mjcf, dmd or xacro";
bool IsInputFormatName(std::string_view name);

/// The Input for `file` read as `format_name` (empty: by its name, or for
/// standard input by its root element). nullopt, with `problem` set, when it
/// cannot be read (standard input) or its format cannot be told.
std::optional<Input> InputFor(const std::string& file, const std::string& format_name,
                              std::string* problem);

}  // namespace mdlc::cli
