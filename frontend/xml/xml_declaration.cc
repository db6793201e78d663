#include "frontend/xml/xml_declaration.h"

#include <cctype>

namespace mdlc::xml {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// "1." followed by one or more digits: what XML 1.0 (fifth edition) and
/// libxml2 accept.
bool IsXml1Version(std::string_view v) {
  if (v.size() < 3 || v[0] != '1' || v[1] != '.') return false;
  for (char c : v.substr(2)) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

}  // namespace

std::optional<DeclaredVersion> UnsupportedXmlVersion(std::string_view text) {
  // a byte-order mark may come first; the declaration, if any, is next
  const size_t start = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  if (text.substr(start, 5) != "<?xml" || text.size() < start + 6 || !IsSpace(text[start + 5])) {
    return std::nullopt;
  }
  const size_t end = text.find("?>", start);
  if (end == std::string_view::npos) return std::nullopt;  // libxml2 reports it
  size_t at = start + 5;
  while (at < end && IsSpace(text[at])) ++at;
  if (text.substr(at, 7) != "version") return std::nullopt;
  at += 7;
  while (at < end && IsSpace(text[at])) ++at;
  if (at >= end || text[at] != '=') return std::nullopt;
  ++at;
  while (at < end && IsSpace(text[at])) ++at;
  if (at >= end || (text[at] != '"' && text[at] != '\'')) return std::nullopt;
  const char quote = text[at++];
  const size_t close = text.find(quote, at);
  if (close == std::string_view::npos || close > end) return std::nullopt;
  const std::string_view value = text.substr(at, close - at);
  if (IsXml1Version(value)) return std::nullopt;
  return DeclaredVersion{at, value};
}

}  // namespace mdlc::xml
