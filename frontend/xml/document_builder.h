// document_builder.h - an XmlDocument made by a program rather than parsed.
//
// A macro stage (frontend/xacro/) expands its sources into a tree of its
// own and hands the readers the result as the same XmlDocument they read
// from files, with every element placed where its text is written: in the
// top-level file, in an included file, or in a macro expansion's file id
// (SourceManager::AddExpansion). Nothing is printed and parsed again.
//
//   XmlDocumentBuilder b(file, sources);
//   b.StartElement("robot", loc, {{"name", "r", loc}});
//   b.AddText("...");
//   b.EndElement();
//   std::unique_ptr<XmlDocument> doc = b.Finish();
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "frontend/xml/xml_document.h"

namespace mdlc::xml {

struct AttributeSpec {
  std::string_view name;
  std::string_view value;
  Loc loc;  // line and column in the element's file
};

class XmlDocumentBuilder {
 public:
  /// `file` is the document's own file: what XmlDocument::file() answers.
  XmlDocumentBuilder(FileId file, const SourceManager& sources);
  ~XmlDocumentBuilder();

  /// Opens an element inside the open one (the first is the root).
  void StartElement(std::string_view name, Loc loc, std::span<const AttributeSpec> attributes);
  void AddContent(detail::ContentKind kind, std::string_view text);
  void EndElement();
  /// The document, once every element is closed; null if none was made.
  std::unique_ptr<XmlDocument> Finish();

 private:
  struct Open {
    detail::ElementNode* element;
    detail::ElementNode* last_child = nullptr;
    detail::ContentNode* last_content = nullptr;
    detail::ContentNode* unplaced_content = nullptr;
  };
  std::string_view Intern(std::string_view name);
  std::string_view Copy(std::string_view text);
  template <typename T>
  T* Make();

  std::unique_ptr<XmlDocument> document_;
  std::unordered_map<std::string, std::string_view> names_;
  std::vector<Open> open_;
};

}  // namespace mdlc::xml
