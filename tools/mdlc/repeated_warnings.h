// repeated_warnings.h - the command line shows a warning that repeats once.
//
// A Gazebo model with forty links says "element <velocity_decay> in <link> is
// not supported and is ignored" forty times; the one line that matters drowns
// in them. So the text output shows the first of each warning (same group,
// same message; only the location differs) and counts the rest, and at the
// end of the run one note per repeated warning says how many were not shown
// (-fno-collapse shows them all). Errors are never collapsed: each one stops
// the compile and must be fixed where it is. Machine output (JSON) is never
// collapsed either: its reader wants every diagnostic.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace mdlc::cli {

class RepeatedWarnings {
 public:
  /// True when this warning is the first of its kind (show it), false when
  /// it repeats one already shown (it is counted instead). `where` is the
  /// location the note at the end names ("file:line:col").
  bool FirstOfItsKind(std::string_view group, std::string_view message, std::string_view where);

  /// One note per warning that repeated, in the order the warnings first
  /// came: "where: note: N more warnings 'message' were not shown
  /// [-fno-collapse shows them]". Empty when nothing repeated.
  std::string Notes() const;

  /// How many warnings were counted and not shown.
  size_t hidden() const { return hidden_; }

 private:
  struct Kind {
    std::string where, group, message;
    size_t repeats = 0;
  };
  std::unordered_map<std::string, size_t> index_;  // group, '\0', message -> kinds_
  std::vector<Kind> kinds_;
  size_t hidden_ = 0;
};

}  // namespace mdlc::cli
