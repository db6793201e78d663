// count_text.h - a count and its noun, in the noun's right number: "1 body",
// "2 bodies", "0 warnings". Every message that prints a count says it this
// way, so no user reads "1 bodies" or "2 error(s)".
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace mdlc::ir {

/// "1 body" / "3 bodies": the plural given, for the nouns whose plural is
/// not the singular and an 's'.
inline std::string CountOf(size_t n, std::string_view singular, std::string_view plural) {
  return fmt::format("{} {}", n, n == 1 ? singular : plural);
}

/// "1 warning" / "3 warnings".
inline std::string CountOf(size_t n, std::string_view singular) {
  return n == 1 ? fmt::format("1 {}", singular) : fmt::format("{} {}s", n, singular);
}

}  // namespace mdlc::ir
