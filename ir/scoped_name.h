// scoped_name.h - the syntax of scoped names (COMMON-030, COMMON-031) and
// "did you mean" suggestions, shared by frontends and passes.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::ir {

/// Splits "a::b::c" into scope "a::b" and element "c" (scope empty when
/// unscoped). Returns nullopt for malformed names ("::x", "x::", "a::::b").
struct SplitName {
  std::string_view scope;
  std::string_view element;
};
std::optional<SplitName> SplitScopedName(std::string_view name);

/// "scope::name", or just the non-empty one of the two.
std::string JoinScopedName(std::string_view scope, std::string_view name);

/// The closest of `candidates` to `wanted` by edit distance, when close
/// enough to be a plausible typo ("did you mean ...").
std::optional<std::string> ClosestName(std::string_view wanted,
                                       const std::vector<std::string_view>& candidates);

}  // namespace mdlc::ir
