// xml_out.cc - see xml_out.h.
#include "backend/writers/xml_out.h"

#include <fmt/format.h>
#include <libxml/xmlwriter.h>

#include <stdexcept>
#include <vector>

namespace mdlc::writers {

std::string NumberText(double value) { return fmt::format("{}", value); }

std::string VectorText(const Eigen::Ref<const Eigen::VectorXd>& values) {
  std::string out;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (i) out += ' ';
    out += NumberText(values[i]);
  }
  return out;
}

namespace {
const xmlChar* X(const std::string& s) { return reinterpret_cast<const xmlChar*>(s.c_str()); }
}  // namespace

struct XmlOut::State {
  xmlBufferPtr buffer = nullptr;
  xmlTextWriterPtr writer = nullptr;
  /// Per open element, what it holds so far: libxml2 does not indent the
  /// end tag of an element that holds only comments; Close does.
  enum class Content { None, Comments, Other };
  std::vector<Content> content;
  void Holds(Content c) {
    if (content.empty()) return;
    Content& top = content.back();
    if (c == Content::Other || top == Content::None) top = c;
  }
  void Check(int rc) {
    if (rc < 0) throw std::runtime_error("internal: the XML writer failed");
  }
};

XmlOut::XmlOut() : s_(std::make_unique<State>()) {
  s_->buffer = xmlBufferCreate();
  s_->writer = xmlNewTextWriterMemory(s_->buffer, 0);
  if (!s_->buffer || !s_->writer) throw std::runtime_error("internal: no memory for XML output");
  xmlTextWriterSetIndent(s_->writer, 1);
  xmlTextWriterSetIndentString(s_->writer, reinterpret_cast<const xmlChar*>("  "));
  s_->Check(xmlTextWriterStartDocument(s_->writer, "1.0", "UTF-8", nullptr));
}

XmlOut::~XmlOut() {
  if (s_->writer) xmlFreeTextWriter(s_->writer);
  if (s_->buffer) xmlBufferFree(s_->buffer);
}

XmlOut& XmlOut::Open(std::string_view tag) {
  s_->Holds(State::Content::Other);
  s_->Check(xmlTextWriterStartElement(s_->writer, X(std::string(tag))));
  s_->content.push_back(State::Content::None);
  return *this;
}

XmlOut& XmlOut::Attr(std::string_view name, std::string_view value) {
  s_->Check(
      xmlTextWriterWriteAttribute(s_->writer, X(std::string(name)), X(std::string(value))));
  return *this;
}

XmlOut& XmlOut::Text(std::string_view text) {
  s_->Holds(State::Content::Other);
  s_->Check(xmlTextWriterWriteString(s_->writer, X(std::string(text))));
  return *this;
}

XmlOut& XmlOut::Close() {
  if (!s_->content.empty() && s_->content.back() == State::Content::Comments) {
    // the comment ended its line: indent the end tag as its start tag
    const std::string indent(2 * (s_->content.size() - 1), ' ');
    s_->Check(xmlTextWriterWriteRaw(s_->writer, X(indent)));
  }
  if (!s_->content.empty()) s_->content.pop_back();
  s_->Check(xmlTextWriterEndElement(s_->writer));
  return *this;
}

XmlOut& XmlOut::Comment(std::string_view text) {
  // "--" may not appear inside a comment
  std::string safe(text);
  for (size_t at; (at = safe.find("--")) != std::string::npos;) safe.replace(at, 2, "- -");
  s_->Holds(State::Content::Comments);
  s_->Check(xmlTextWriterWriteComment(s_->writer, X(" " + safe + " ")));
  return *this;
}

std::string XmlOut::Finish() {
  s_->Check(xmlTextWriterEndDocument(s_->writer));
  xmlTextWriterFlush(s_->writer);
  return std::string(reinterpret_cast<const char*>(xmlBufferContent(s_->buffer)),
                     static_cast<size_t>(xmlBufferLength(s_->buffer)));
}

}  // namespace mdlc::writers
