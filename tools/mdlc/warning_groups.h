// warning_groups.h - the diagnostic groups that -W selects, each with a
// line saying what it covers, for `mdlc --list-warnings`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mdlc::cli {

struct WarningGroup {
  std::string_view name;         // what follows -W, -Wno- and -Werror=
  std::string_view description;  // one line, what its diagnostics are about
  bool errors_only;              // no warning or note: -Wno- changes nothing
};

/// Every group of ir/diagnostic_kinds.def, by name; a group without a
/// description here has an empty one (a test keeps that from happening).
std::vector<WarningGroup> WarningGroups();

/// What --list-warnings prints: how the flags use a group, then one line
/// per group.
std::string ListWarningGroups();

}  // namespace mdlc::cli
