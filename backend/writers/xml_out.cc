// xml_out.cc - see xml_out.h.
#include "backend/writers/xml_out.h"

#include <fmt/format.h>
#include <libxml/xmlwriter.h>

#include <algorithm>
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
/// Elements deeper than this are indented as this deep.
constexpr size_t kMaxIndentDepth = 32;
}  // namespace

struct XmlOut::State {
  xmlBufferPtr buffer = nullptr;
  xmlTextWriterPtr writer = nullptr;
  /// Per open element, whether it holds elements or comments so far (its
  /// end tag then goes on a line of its own) or text (inline).
  enum class Content { None, Lines, Text };
  std::vector<Content> content;
  void Check(int rc) {
    if (rc < 0) throw std::runtime_error("internal: the XML writer failed");
  }
  /// A line break and the indentation of an element `depth` levels down,
  /// capped: a chain of 10,000 bodies nested in MJCF would otherwise be
  /// indented 10,000 deep, and the file grow as the square of the chain.
  void NewLine(size_t depth) {
    line.assign(1, '\n');
    line.append(2 * std::min(depth, kMaxIndentDepth), ' ');
    Check(xmlTextWriterWriteRaw(writer, X(line)));
  }
  /// Starts the line of an element or comment: the element it is in then
  /// ends on a line of its own.
  void StartLine() {
    if (!content.empty()) content.back() = Content::Lines;
    NewLine(content.size());
  }
  std::string line;
};

XmlOut::XmlOut() : s_(std::make_unique<State>()) {
  s_->buffer = xmlBufferCreate();
  if (!s_->buffer) throw std::runtime_error("internal: no memory for XML output");
  // libxml2's buffer grows by exactly what each write needs, a realloc that
  // copies the whole text each time where realloc cannot grow in place (under
  // AddressSanitizer, always): a file of 30,000 nested models took 11 minutes
  // to write there. Doubling keeps writing linear.
  xmlBufferSetAllocationScheme(s_->buffer, XML_BUFFER_ALLOC_DOUBLEIT);
  s_->writer = xmlNewTextWriterMemory(s_->buffer, 0);
  if (!s_->writer) throw std::runtime_error("internal: no memory for XML output");
  s_->Check(xmlTextWriterStartDocument(s_->writer, "1.0", "UTF-8", nullptr));
}

XmlOut::~XmlOut() {
  if (s_->writer) xmlFreeTextWriter(s_->writer);
  if (s_->buffer) xmlBufferFree(s_->buffer);
}

XmlOut& XmlOut::Open(std::string_view tag) {
  // the declaration ends its own line
  if (!s_->content.empty()) s_->StartLine();
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
  if (!s_->content.empty() && s_->content.back() == State::Content::None) {
    s_->content.back() = State::Content::Text;
  }
  s_->Check(xmlTextWriterWriteString(s_->writer, X(std::string(text))));
  return *this;
}

XmlOut& XmlOut::Close() {
  if (!s_->content.empty()) {
    if (s_->content.back() == State::Content::Lines) s_->NewLine(s_->content.size() - 1);
    s_->content.pop_back();
  }
  s_->Check(xmlTextWriterEndElement(s_->writer));
  return *this;
}

XmlOut& XmlOut::Comment(std::string_view text) {
  // "--" may not appear inside a comment
  std::string safe(text);
  for (size_t at; (at = safe.find("--")) != std::string::npos;) safe.replace(at, 2, "- -");
  s_->StartLine();
  s_->Check(xmlTextWriterWriteComment(s_->writer, X(" " + safe + " ")));
  return *this;
}

std::string XmlOut::Finish() {
  while (!s_->content.empty()) Close();
  s_->Check(xmlTextWriterEndDocument(s_->writer));
  xmlTextWriterFlush(s_->writer);
  return std::string(reinterpret_cast<const char*>(xmlBufferContent(s_->buffer)),
                     static_cast<size_t>(xmlBufferLength(s_->buffer)));
}

}  // namespace mdlc::writers
