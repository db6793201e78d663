// number_text.h - how the inspection commands (tree, graph) print a number:
// six significant digits, fixed or exponent notation, whichever is shorter.
#pragma once

#include <fmt/format.h>

#include <string>

namespace mdlc::tools {

inline std::string Number(double v) { return fmt::format("{:.6g}", v); }

}  // namespace mdlc::tools
