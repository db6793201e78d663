#include "frontend/xml/start_tags.h"

#include <array>
#include <cstring>

#include "frontend/xml/trim.h"

namespace mdlc::xml {
namespace {

// XML name characters (ASCII letters, digits, _ : - . and any non-ASCII byte),
// as a table: this runs for every byte of every start tag
constexpr auto kNameChar = [] {
  std::array<bool, 256> table{};
  for (int c = 0; c < 256; ++c) {
    table[c] = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == ':' || c == '-' || c == '.' || c >= 0x80;
  }
  return table;
}();
bool IsNameChar(char c) { return kNameChar[static_cast<unsigned char>(c)]; }

void SetPosition(uint32_t& line, uint32_t& column, Loc loc) {
  line = loc.line;
  column = loc.column;
}

}  // namespace

size_t NextStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl) {
  while (true) {
    pos = text.find('<', pos);
    if (pos == std::string_view::npos || pos + 1 >= text.size()) return std::string_view::npos;
    auto skip_past = [&](std::string_view terminator) {
      size_t end = text.find(terminator, pos);
      return end == std::string_view::npos ? text.size() : end + terminator.size();
    };
    // end tags and start tags first: they are nearly every '<' of a model
    const char kind = text[pos + 1];
    if (kind == '/') {  // an end tag holds no '<': the next one is past it
      pos += 2;
      continue;
    }
    if (kind != '!' && kind != '?') return pos;
    std::string_view rest = text.substr(pos);
    if (rest.starts_with("<!--")) {
      pos = skip_past("-->");
    } else if (rest.starts_with("<![CDATA[")) {
      pos = skip_past("]]>");
    } else if (rest.starts_with("<?")) {
      pos = skip_past("?>");
    } else if (rest.starts_with("<!")) {
      // DOCTYPE (with an optional [internal subset]) or another declaration;
      // a quoted ']' or '>' can end the DOCTYPE early here, so a declaration
      // met on its own is checked too
      if (rest.starts_with("<!ENTITY") && entity_decl && !*entity_decl) *entity_decl = pos;
      size_t i = pos + 2;
      int depth = 0;
      for (; i < text.size(); ++i) {
        char c = text[i];
        if (c == '[') ++depth;
        else if (c == ']') --depth;
        else if (c == '>' && depth <= 0) break;
        else if (c == '<' && text.substr(i).starts_with("<!ENTITY") && entity_decl && !*entity_decl)
          *entity_decl = i;
      }
      pos = i + 1;
    }
  }
}

Loc LineTracker::AtAfterNewlines(size_t offset) {
  if (offset < scanned_) return sources_.LocForOffset(file_, offset);  // a guard: callers go forward
  const char* data = text_.data();
  size_t from = scanned_;
  if (next_newline_known_ && next_newline_ < offset) {  // the newline already found
    ++line_;
    line_start_ = from = next_newline_ + 1;
  }
  for (const char* p = data + from;
       (p = static_cast<const char*>(std::memchr(p, '\n', offset - (p - data))));) {
    ++p;
    ++line_;
    line_start_ = static_cast<size_t>(p - data);
  }
  const void* next =
      offset < text_.size() ? std::memchr(data + offset, '\n', text_.size() - offset) : nullptr;
  next_newline_ = next ? static_cast<size_t>(static_cast<const char*>(next) - data) : text_.size();
  next_newline_known_ = true;
  scanned_ = offset;
  return Loc{file_, line_, static_cast<uint32_t>(offset - line_start_ + 1)};
}

bool StartTagLocator::Place(detail::ElementNode& element) {
  const size_t start = NextStartTag(text_, pos_, nullptr);
  if (start == std::string_view::npos) return false;
  SetPosition(element.line, element.column, lines_.At(start));
  // "<name attr='v' ...>": libxml2 reports the attributes in the order
  // written, so the next unplaced one is almost always the one met next;
  // the list is searched only when it is not (namespace declarations are
  // written like attributes but are not among them)
  detail::AttributeNode* attributes = element.attributes;
  const uint32_t count = element.attribute_count;
  uint32_t next_unplaced = 0;
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  const char* p = begin + start + 1;
  while (p < end && IsNameChar(*p)) ++p;
  while (p < end) {
    while (p < end && IsXmlSpace(*p)) ++p;
    if (p >= end || *p == '>' || *p == '/') break;
    const char* const name_start = p;
    while (p < end && IsNameChar(*p)) ++p;
    const std::string_view name(name_start, static_cast<size_t>(p - name_start));
    while (p < end && *p != '"' && *p != '\'') ++p;
    if (p >= end) break;
    // a value holds no '<' and its own quote only as a reference, so the
    // next such quote closes it
    const void* close = std::memchr(p + 1, *p, static_cast<size_t>(end - p - 1));
    p = close ? static_cast<const char*>(close) + 1 : end;
    if (count == 0) continue;
    auto unplaced_named = [&](uint32_t k) {
      return attributes[k].line == 0 && SameName(attributes[k].name, name);
    };
    uint32_t found = count;
    if (next_unplaced < count && unplaced_named(next_unplaced)) {
      found = next_unplaced;
    } else {
      for (uint32_t k = 0; k < count && found == count; ++k) {
        if (unplaced_named(k)) found = k;
      }
    }
    if (found == count) continue;
    SetPosition(attributes[found].line, attributes[found].column,
                lines_.At(static_cast<size_t>(name_start - begin)));
    if (found == next_unplaced) ++next_unplaced;
  }
  pos_ = static_cast<size_t>(p - begin);
  return true;
}

}  // namespace mdlc::xml
