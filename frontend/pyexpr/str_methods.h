// str_methods.h - methods of str, list, tuple and dict values, str.format
// and printf-style `%` formatting.
#pragma once

#include <string>
#include <string_view>

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

// format(value, spec): Python's format-spec mini-language for str, int
// (and bool) and float values: fill, align (< > ^ =), sign, z, #, 0, width,
// grouping (, _), .precision and the types s d n b o x X c e E f F g G %.
Result<std::string> FormatWithSpec(const Value& v, std::string_view spec);

}  // namespace mdlc::pyexpr
