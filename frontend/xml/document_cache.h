// document_cache.h - an XML file a compile loads many times, parsed at most twice.
//
// A file may be loaded many times in one compile: a directives scene adds
// the same robot once per instance, a world includes one model per copy.
// Each load is its own buffer (its own FileId, with its own "included from"
// place), but the text is the same, and so is the tree. The cache keeps the
// tree of a path's second load and gives every later load of the same text
// a document over that tree, placed in the later buffer.
//
// Only a parse that reported nothing is shared: a document with warnings or
// errors is parsed again at each load, so that each load reports its own.
// A tree is kept from a path's second load on: a scene that adds many
// different files, once each, keeps none of them past its own reading.
#pragma once

#include <absl/container/flat_hash_map.h>

#include <memory>
#include <string>

#include "frontend/xml/xml_document.h"

namespace mdlc::xml {

class DocumentCache {
 public:
  /// XmlDocument::Parse, or the tree of an earlier load of the same path
  /// with the same text.
  std::shared_ptr<const XmlDocument> Parse(FileId file, const SourceManager& sources,
                                           DiagnosticEngine& diags);

  /// How many loads were served without a parse.
  uint64_t reused() const { return reused_; }

 private:
  // by path: the tree to share, or null for a path loaded once so far
  absl::flat_hash_map<std::string, std::shared_ptr<const XmlDocument>> by_path_;
  uint64_t reused_ = 0;
};

}  // namespace mdlc::xml
