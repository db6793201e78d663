// original_name_comment.h - the text of the comment `mdlc convert` writes
// beside an element whose name the URDF or MJCF writer changed, and which
// mdlc's URDF and MJCF readers read back into an ir::OriginalName
// (ir/original_name.h):
//
//   <link name="arm/link1">
//     <!-- mdlc:name model="arm" name="link1" -->
//
// (readers other than mdlc's ignore comments). One codec for both
// directions, so the writers and the readers cannot disagree on it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mdlc::syntax {

/// The comment's text: `mdlc:name model="M" name="N"`, each value
/// percent-encoded where XML comments or the quotes need it ('%', '"', and a
/// '-' after a '-').
std::string FormatOriginalNameComment(std::string_view model, std::string_view name);

/// The model and name a comment's text holds; nullopt for another comment.
struct ParsedOriginalName {
  std::string model, name;
};
std::optional<ParsedOriginalName> ParseOriginalNameComment(std::string_view text);

}  // namespace mdlc::syntax
