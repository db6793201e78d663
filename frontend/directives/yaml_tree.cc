#include "frontend/directives/yaml_tree.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <cstring>
#include <istream>
#include <streambuf>
#include <utility>
#include <vector>

namespace mdlc::frontend::yaml {

// Builds a Document's tree from yaml-cpp's events, with no recursion: the
// open collections are a stack, and the children of all of them wait in
// one list until their collection ends.
class TreeBuilder final : public YAML::EventHandler {
 public:
  explicit TreeBuilder(Document& doc) : doc_(doc) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    Add(Make(detail::NodeKind::kNull, mark, {}, anchor));
  }
  void OnAlias(const YAML::Mark&, YAML::anchor_t anchor) override {
    // yaml-cpp's parser has already rejected an alias to an unknown anchor
    Add(anchor < anchors_.size() ? anchors_[anchor] : Make(detail::NodeKind::kNull, {}, {}, 0));
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    detail::NodeData* node = Make(detail::NodeKind::kScalar, mark, tag, anchor);
    node->scalar = Copy(value);
    Add(node);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    Open(Make(detail::NodeKind::kSequence, mark, tag, anchor));
  }
  void OnSequenceEnd() override { Close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    Open(Make(detail::NodeKind::kMap, mark, tag, anchor));
  }
  void OnMapEnd() override { Close(); }

 private:
  std::string_view Copy(std::string_view text) {
    if (text.empty()) return {};
    // nearly every node is untagged: yaml-cpp's "?" (plain) or "!" (quoted)
    if (text == "?") return "?";
    if (text == "!") return "!";
    char* out = static_cast<char*>(doc_.arena_.allocate(text.size(), 1));
    std::memcpy(out, text.data(), text.size());
    return {out, text.size()};
  }

  detail::NodeData* Make(detail::NodeKind kind, const YAML::Mark& mark, std::string_view tag,
                         YAML::anchor_t anchor) {
    auto* node = new (doc_.arena_.allocate(sizeof(detail::NodeData), alignof(detail::NodeData)))
        detail::NodeData();
    node->kind = kind;
    if (!mark.is_null() && mark.line >= 0 && mark.column >= 0) {
      node->line = static_cast<uint32_t>(mark.line + 1);
      node->column = static_cast<uint32_t>(mark.column + 1);
    }
    node->tag = Copy(tag);
    // registered before a collection's children, so they may alias it
    if (anchor != YAML::NullAnchor) {
      if (anchors_.size() <= anchor) anchors_.resize(anchor + 1, nullptr);
      anchors_[anchor] = node;
    }
    return node;
  }

  // a finished node (or a collection just opened) joins its parent
  void Add(const detail::NodeData* node) {
    if (open_.empty()) {
      if (!doc_.root_) doc_.root_ = node;
      return;
    }
    pending_.push_back(node);
  }

  void Open(detail::NodeData* collection) {
    Add(collection);
    open_.push_back({collection, pending_.size()});
  }

  void Close() {
    const auto [collection, first] = open_.back();
    open_.pop_back();
    const size_t count = pending_.size() - first;
    if (count > 0) {
      auto* children = static_cast<const detail::NodeData**>(
          doc_.arena_.allocate(count * sizeof(const detail::NodeData*), alignof(void*)));
      std::memcpy(children, pending_.data() + first, count * sizeof(const detail::NodeData*));
      collection->children = children;
      collection->child_count = static_cast<uint32_t>(count);
    }
    pending_.resize(first);
  }

  Document& doc_;
  std::vector<const detail::NodeData*> anchors_;  // by yaml-cpp's anchor number
  std::vector<std::pair<detail::NodeData*, size_t>> open_;  // with its first child in pending_
  std::vector<const detail::NodeData*> pending_;
};

namespace {

// yaml-cpp reads from a stream: this one reads the text in place
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only read
    setg(begin, begin, begin + text.size());
  }
};

}  // namespace

std::unique_ptr<Document> Document::Load(std::string_view text) {
  std::unique_ptr<Document> doc(new Document());
  TextBuffer buffer(text);
  std::istream in(&buffer);
  YAML::Parser parser(in);
  TreeBuilder builder(*doc);
  parser.HandleNextDocument(builder);
  if (!doc->root_) {
    auto* null_root = new (doc->arena_.allocate(sizeof(detail::NodeData), alignof(detail::NodeData)))
        detail::NodeData();
    doc->root_ = null_root;
  }
  return doc;
}

}  // namespace mdlc::frontend::yaml
