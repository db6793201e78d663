// tree_builder.h - mdlc's XML tree (xml_node.h), built from libxml2's SAX
// events as libxml2 parses.
//
// Every element is placed at its start tag as it is made (start_tags.h) and
// counted against the elements and depth limits, so a document over a
// limit stops the parse there, before its tree is built.
//
// Text follows libxml2's XML_PARSE_NOBLANKS rules, which mdlc's DOM used
// before: a run of whitespace only is kept when it is an element's whole
// content, when text is the element's first or last child so far, or once
// the element is marked as one whose blanks matter, and dropped otherwise
// (indentation between elements). libxml2 marks an element when it keeps a
// piece of its text that starts with a blank (its fast path) or holds a
// character outside ASCII (its slow path); the pieces are the ones its
// characters callback hands over.
#pragma once

#include <cstdint>
#include <memory_resource>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "frontend/xml/element_counts.h"
#include "frontend/xml/start_tags.h"
#include "frontend/xml/xml_node.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

struct _xmlSAXHandler;

namespace mdlc::xml {

/// Carves small pieces (nodes, names, values) out of blocks taken from an
/// arena. A monotonic_buffer_resource's allocate is a virtual call into
/// libstdc++ for each of the three or so pieces an element makes (2% of a
/// compile's instructions); here the common case is an inline pointer bump.
/// Everything still lives in, and is released with, the arena.
class BlockCarver {
 public:
  explicit BlockCarver(std::pmr::memory_resource& arena) : arena_(arena) {}

  void* Allocate(size_t bytes, size_t alignment) {
    const uintptr_t start = (reinterpret_cast<uintptr_t>(cursor_) + alignment - 1) &
                            ~(static_cast<uintptr_t>(alignment) - 1);
    if (bytes == 0 || start + bytes > reinterpret_cast<uintptr_t>(end_)) {
      return Refill(bytes, alignment);
    }
    cursor_ = reinterpret_cast<char*>(start + bytes);
    return reinterpret_cast<void*>(start);
  }

 private:
  static constexpr size_t kBlockSize = 64 * 1024;
  void* Refill(size_t bytes, size_t alignment);

  std::pmr::memory_resource& arena_;
  char* cursor_ = nullptr;
  char* end_ = nullptr;
};

class TreeBuilder {
 public:
  /// Builds into `arena` the tree of `file`, whose text libxml2 is given.
  TreeBuilder(FileId file, const SourceManager& sources, std::pmr::memory_resource& arena,
              DiagnosticEngine& diags);

  /// Keep every whitespace-only text node (ParseOptions::keep_blank_text).
  void set_keep_blank_text(bool keep) { keep_blank_text_ = keep; }
  /// Keep namespace declarations as attributes
  /// (ParseOptions::keep_namespace_declarations).
  void set_keep_namespace_declarations(bool keep) { keep_namespace_declarations_ = keep; }

  /// Points the handler's callbacks at TreeBuilder; the parser context's
  /// `_private` must then point at this builder.
  static void Install(_xmlSAXHandler& sax);

  detail::ElementNode* root() const { return root_; }
  /// How many elements of each name, handed over once the tree is built.
  ElementCounts TakeElementCounts() { return std::move(element_counts_); }
  /// Comments outside the root element, when namespace declarations and
  /// blanks are kept (a writer of the document wants them): (text, whether
  /// after the root).
  std::vector<std::pair<std::string_view, bool>> TakeOutsideComments() {
    return std::move(outside_comments_);
  }
  /// The document declared an entity (the parse stopped there).
  bool declared_entity() const { return declared_entity_; }
  /// An element went over a limit, reported (the parse stopped there).
  bool over_limit() const { return over_limit_; }

 private:
  struct Open {
    detail::ElementNode* element;
    detail::ElementNode* last_child = nullptr;
    detail::ContentNode* last_content = nullptr;
    // the first content node since the last element child: the next
    // element child is the one they come before
    detail::ContentNode* unplaced_content = nullptr;
    bool has_children = false;  // any node: element, text, CDATA, comment, PI
    bool first_is_text = false;
    bool last_is_text = false;
    bool blanks_matter = false;  // marked as libxml2 marks it: every later blank is kept
  };
  // the SAX callbacks, which find the builder through the parser context
  static void OnStartElement(void* ctx, const unsigned char* local, const unsigned char* prefix,
                             const unsigned char* uri, int namespace_count,
                             const unsigned char** namespaces, int attribute_count,
                             int defaulted_count, const unsigned char** attributes);
  static void OnEndElement(void* ctx, const unsigned char*, const unsigned char*,
                           const unsigned char*);
  static void OnCharacters(void* ctx, const unsigned char* text, int length);
  static void OnCdata(void* ctx, const unsigned char* text, int length);
  static void OnComment(void* ctx, const unsigned char* text);
  static void OnProcessingInstruction(void* ctx, const unsigned char*, const unsigned char*);
  static void OnEntityDeclaration(void* ctx, const unsigned char*, int, const unsigned char*,
                                  const unsigned char*, unsigned char*);

  void StartElement(void* parser, const unsigned char* local, const unsigned char* prefix,
                    int namespace_count, const unsigned char** namespaces, int attribute_count,
                    const unsigned char** attributes);
  void EndElement();
  /// Makes the pending text a child, or drops it; `at_end_tag` when the
  /// element's end tag follows it.
  void FlushText(bool at_end_tag);
  void AddContent(detail::ContentKind kind, std::string_view text);
  /// Notes a child that is not text in the innermost open element.
  void NoteOtherChild();
  /// "prefix:local" or "local", stored for the document's lifetime.
  std::string_view QualifiedName(const unsigned char* prefix, const unsigned char* local);
  /// `text` copied into the arena with a terminating NUL.
  std::string_view Copy(std::string_view text);
  /// An attribute value copied, with "&#38;" decoded: libxml2 leaves that
  /// one reference undecoded (for '&' written as "&amp;" or "&#38;").
  std::string_view CopyValue(std::string_view value);

  FileId file_;
  BlockCarver arena_;
  DiagnosticEngine& diags_;
  const Limits& limits_;
  StartTagLocator locator_;
  detail::ElementNode* root_ = nullptr;
  std::vector<Open> open_;
  std::string pending_text_;  // characters since the last node, not yet placed
  bool pending_blank_ = true;  // pending_text_ holds blanks only
  bool pending_marks_ = false;  // kept, pending_text_ marks its element (see above)
  // joined names by libxml2's interned (prefix, local) pointers
  absl::flat_hash_map<std::pair<const void*, const void*>, std::string_view> joined_names_;
  uint64_t elements_ = 0;
  ElementCounts element_counts_;
  bool keep_blank_text_ = false;
  bool keep_namespace_declarations_ = false;
  std::vector<std::pair<std::string_view, bool>> outside_comments_;
  bool declared_entity_ = false;
  bool over_limit_ = false;
};

}  // namespace mdlc::xml
