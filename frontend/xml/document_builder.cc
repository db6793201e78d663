#include "frontend/xml/document_builder.h"

#include <cstring>

namespace mdlc::xml {

XmlDocumentBuilder::XmlDocumentBuilder(FileId file, const SourceManager& sources)
    : document_(new XmlDocument()) {
  document_->file_ = file;
  document_->sources_ = &sources;
}

XmlDocumentBuilder::~XmlDocumentBuilder() = default;

template <typename T>
T* XmlDocumentBuilder::Make() {
  return new (document_->arena_.allocate(sizeof(T), alignof(T))) T;
}

std::string_view XmlDocumentBuilder::Copy(std::string_view text) {
  auto* out = static_cast<char*>(document_->arena_.allocate(text.size() + 1, 1));
  std::memcpy(out, text.data(), text.size());
  out[text.size()] = '\0';
  return {out, text.size()};
}

// ElementCounts keys names by address: each distinct name gets one copy
std::string_view XmlDocumentBuilder::Intern(std::string_view name) {
  auto [it, inserted] = names_.try_emplace(std::string(name));
  if (inserted) it->second = Copy(name);
  return it->second;
}

void XmlDocumentBuilder::StartElement(std::string_view name, Loc loc,
                                      std::span<const AttributeSpec> attributes) {
  auto* element = Make<detail::ElementNode>();
  element->name = Intern(name);
  element->line = loc.line;
  element->column = loc.column;
  if (loc.file.valid() && loc.file != document_->file_) element->file = loc.file.value;
  document_->element_counts_.Add(element->name);
  if (!attributes.empty()) {
    auto* nodes = static_cast<detail::AttributeNode*>(document_->arena_.allocate(
        sizeof(detail::AttributeNode) * attributes.size(), alignof(detail::AttributeNode)));
    for (size_t i = 0; i < attributes.size(); ++i) {
      auto* node = new (nodes + i) detail::AttributeNode;
      node->name = Intern(attributes[i].name);
      node->value = Copy(attributes[i].value);
      node->line = attributes[i].loc.line;
      node->column = attributes[i].loc.column;
      element->attribute_name_bits |= XmlElement::NameBit(node->name);
    }
    element->attributes = nodes;
    element->attribute_count = static_cast<uint32_t>(attributes.size());
  }
  if (open_.empty()) {
    document_->root_ = element;
  } else {
    Open& parent = open_.back();
    detail::LinkElementChild(parent.element, parent.last_child, parent.unplaced_content, element,
                             XmlElement::NameBit(element->name));
  }
  open_.push_back(Open{element});
}

void XmlDocumentBuilder::AddContent(detail::ContentKind kind, std::string_view text) {
  if (open_.empty()) return;
  Open& open = open_.back();
  auto* node = Make<detail::ContentNode>();
  node->kind = kind;
  node->text = Copy(text);
  if (open.last_content) {
    open.last_content->next = node;
  } else {
    open.element->content = node;
  }
  open.last_content = node;
  if (!open.unplaced_content) open.unplaced_content = node;
}

void XmlDocumentBuilder::EndElement() {
  if (!open_.empty()) open_.pop_back();
}

std::unique_ptr<XmlDocument> XmlDocumentBuilder::Finish() {
  if (!document_->root_) return nullptr;
  return std::move(document_);
}

}  // namespace mdlc::xml
