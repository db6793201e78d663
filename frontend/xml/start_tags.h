// start_tags.h - where each start tag and attribute name sits in the text.
//
// libxml2 records only a line per node (the line where the start tag ends).
// mdlc finds exact positions itself: one forward scan of the buffer meets
// the start tags in document order, the order in which the tree builder
// creates their elements, and pairs each with its element and each
// attribute name with its attribute, counting lines on the way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "frontend/xml/xml_node.h"
#include "ir/location.h"
#include "ir/source_manager.h"

namespace mdlc::xml {

/// The offset of the next start tag's '<' at or after `pos`, skipping
/// comments, processing instructions, CDATA, declarations and end tags;
/// npos at the end. Records in `entity_decl` the first entity declaration
/// it passes, when asked.
size_t NextStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl);

/// Line and column of offsets met in increasing order, found by counting
/// the newlines passed since the last one: one pass over the text in all.
class LineTracker {
 public:
  LineTracker(std::string_view text, FileId file, const SourceManager& sources)
      : text_(text), file_(file), sources_(sources) {}
  Loc At(size_t offset) {
    if (next_newline_known_ && offset >= scanned_ && offset <= next_newline_) {
      scanned_ = offset;  // on the current line
      return Loc{file_, line_, static_cast<uint32_t>(offset - line_start_ + 1)};
    }
    return AtAfterNewlines(offset);
  }

 private:
  Loc AtAfterNewlines(size_t offset);

  std::string_view text_;
  FileId file_;
  const SourceManager& sources_;
  size_t scanned_ = 0;     // newlines before here are counted
  uint32_t line_ = 1;      // the line `scanned_` is on
  size_t line_start_ = 0;  // that line's first offset
  // the first newline at or after `scanned_` (the text's size when none is
  // left): offsets before it are on the current line, found with no search,
  // as most attributes are (a start tag's attributes share its line)
  size_t next_newline_ = 0;
  bool next_newline_known_ = false;
};

/// Places elements, in document order, at their start tags.
class StartTagLocator {
 public:
  StartTagLocator(std::string_view text, FileId file, const SourceManager& sources)
      : text_(text), lines_(text, file, sources) {}

  /// Sets the line and column of `element` and of its attributes from the
  /// next start tag. Returns false, leaving them unset, when no tag is left
  /// (never for text libxml2 accepted; a guard).
  bool Place(detail::ElementNode& element);

 private:
  std::string_view text_;
  LineTracker lines_;
  size_t pos_ = 0;  // just past the last start tag placed
};

}  // namespace mdlc::xml
