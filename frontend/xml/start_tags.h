// start_tags.h - where each start tag and attribute name sits in the text.
//
// libxml2 records only a line per node (the line where the start tag ends).
// mdlc finds exact positions itself: one forward scan of the buffer meets
// the start tags in document order, the order in which the tree builder
// creates their elements, and pairs each with its element and each
// attribute name with its attribute, counting lines on the way (the scans
// in byte_scan.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "frontend/xml/byte_scan.h"
#include "frontend/xml/xml_node.h"

namespace mdlc::xml {

/// The offset of the next start tag's '<' at or after `pos`, skipping
/// comments, processing instructions, CDATA, declarations and end tags;
/// npos at the end. Records in `entity_decl` the first entity declaration
/// it passes, when asked.
size_t NextStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl);

/// Places elements, in document order, at their start tags.
class StartTagLocator {
 public:
  explicit StartTagLocator(std::string_view text) : text_(text) { lines_.line_start = text.data(); }

  /// Sets the line and column of `element` and of its attributes from the
  /// next start tag. Returns false, leaving them unset, when no tag is left
  /// (never for text libxml2 accepted; a guard).
  bool Place(detail::ElementNode& element);

 private:
  std::string_view text_;
  size_t pos_ = 0;    // just past the last start tag placed
  LineCursor lines_;  // the line `pos_` is on
};

}  // namespace mdlc::xml
