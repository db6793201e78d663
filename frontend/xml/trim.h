// trim.h - the one definition of "surrounding white space" for every XML
// format: XML's own white space (space, tab, newline, carriage return).
#pragma once

#include <string_view>

namespace mdlc::xml {

/// One character of XML white space.
inline bool IsXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// `s` without leading and trailing XML white space. A view into `s`: keep
/// what it views alive (XmlElement::Text() returns a temporary).
inline std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsXmlSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsXmlSpace(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace mdlc::xml
