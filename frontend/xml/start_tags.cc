#include "frontend/xml/start_tags.h"

#include <algorithm>
#include <array>
#include <bit>
#include <iterator>
#include <utility>

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

// Past the comment, processing instruction, CDATA section or declaration
// whose '<' is at `at`, counting the newlines in it. Records in
// `entity_decl` the first entity declaration met, when asked.
[[gnu::noinline]] const char* SkipMarkup(std::string_view text, const char* at,
                                         std::optional<size_t>* entity_decl, LineCursor& lines) {
  const size_t pos = static_cast<size_t>(at - text.data());
  // comments, CDATA sections and processing instructions end at their
  // terminator, looked for after the opener as libxml2 does: "<!--->" opens
  // a comment, it does not close one
  static constexpr std::pair<std::string_view, std::string_view> kSpans[] = {
      {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
  const std::string_view rest = text.substr(pos);
  size_t next = pos + 1;  // a guard: every "<!" and "<?" is one of the cases below
  const auto* span = std::find_if(std::begin(kSpans), std::end(kSpans),
                                  [&](const auto& s) { return rest.starts_with(s.first); });
  if (span != std::end(kSpans)) {
    const size_t found = text.find(span->second, pos + span->first.size());
    next = found == std::string_view::npos ? text.size() : found + span->second.size();
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
    next = std::min(i + 1, text.size());
  }
  CountLines(at, text.data() + next, lines);
  return text.data() + next;
}

// NextStartTag, counting into `lines` the newlines it passes.
size_t FindStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl,
                    LineCursor& lines) {
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  LineCursor at = lines;  // kept in registers through the loop
  const char* p = begin + pos;
#if defined(__SSE2__)
  // 32 bytes at a time while the text has more: the next '<' is nearly
  // always among them, and after an end tag's '<' the next one's mostly is
  // too, so a window is read once for both
  while (end - p > 32) {  // more than 32: a '<' found has a byte after it
    const WindowMasks window = MatchWindow(p, '<');
    const char* resume = nullptr;
    for (uint32_t lt = window.hits; lt != 0; lt &= lt - 1) {
      const int i = std::countr_zero(lt);
      const char* const tag = p + i;
      if (tag[1] == '/') continue;  // an end tag holds no other '<'
      detail::PassNewlines(window.newlines & ((1u << i) - 1), p, at);
      if (tag[1] != '!' && tag[1] != '?') {
        lines = at;
        return static_cast<size_t>(tag - begin);
      }
      resume = SkipMarkup(text, tag, entity_decl, at);
      break;
    }
    if (resume) {
      p = resume;
    } else {
      detail::PassNewlines(window.newlines, p, at);
      p += 32;
    }
  }
#endif
  while (true) {
    p = ScanTo(p, end, '<', at);
    if (end - p < 2) {
      lines = at;
      return std::string_view::npos;
    }
    // end tags and start tags first: they are nearly every '<' of a model
    if (p[1] == '/') {  // an end tag holds no '<': the next one is past it
      p += 2;
    } else if (p[1] != '!' && p[1] != '?') {
      lines = at;
      return static_cast<size_t>(p - begin);
    } else {
      p = SkipMarkup(text, p, entity_decl, at);
    }
  }
}

}  // namespace

size_t NextStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl) {
  LineCursor unused{1, text.data()};
  return FindStartTag(text, pos, entity_decl, unused);
}

bool StartTagLocator::Place(detail::ElementNode& element) {
  const size_t start = FindStartTag(text_, pos_, nullptr, lines_);
  if (start == std::string_view::npos) return false;
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  element.line = lines_.line;
  element.column = lines_.ColumnOf(begin + start);
  const uint32_t count = element.attribute_count;
  if (count == 0) {
    // nothing to place inside the tag, and it holds no '<' (a value never
    // does): the next scan starts within it and counts its lines
    pos_ = start + 1;
    return true;
  }
  // "<name attr='v' ...>": libxml2 reports the attributes in the order
  // written, so the next unplaced one is almost always the one met next,
  // and its name is compared whole where the tag's next name starts, with
  // no walk of it a byte at a time; the list is searched only when it is
  // not (namespace declarations are written like attributes but are not
  // among them)
  detail::AttributeNode* attributes = element.attributes;
  uint32_t next_unplaced = 0;
  const char* p = begin + start + 1;
  while (p < end && IsNameChar(*p)) ++p;
  while (p < end) {
    for (; p < end && IsXmlSpace(*p); ++p) {
      if (*p == '\n') lines_.PassNewlineAt(p);
    }
    if (p >= end || *p == '>' || *p == '/') break;
    const char* const name_start = p;
    const uint32_t name_line = lines_.line;
    const uint32_t name_column = lines_.ColumnOf(name_start);
    uint32_t found = count;
    if (next_unplaced < count && attributes[next_unplaced].line == 0) {
      const std::string_view expected = attributes[next_unplaced].name;
      if (static_cast<size_t>(end - p) > expected.size() &&
          SameName({p, expected.size()}, expected) && !IsNameChar(p[expected.size()])) {
        found = next_unplaced;
        p += expected.size();
      }
    }
    if (found == count) {
      while (p < end && IsNameChar(*p)) ++p;
    }
    const std::string_view name(name_start, static_cast<size_t>(p - name_start));
    if (p + 1 < end && *p == '=' && (p[1] == '"' || p[1] == '\'')) {
      ++p;  // name="value", as nearly every attribute is written
    } else {
      for (; p < end && *p != '"' && *p != '\''; ++p) {
        if (*p == '\n') lines_.PassNewlineAt(p);
      }
    }
    if (p >= end) break;
    // a value holds no '<' and its own quote only as a reference, so the
    // next such quote closes it
    const char* const close = ScanTo(p + 1, end, *p, lines_);
    p = close < end ? close + 1 : end;
    // any other name (a namespace declaration, or attributes libxml2
    // reported in another order) is searched for among the unplaced
    for (uint32_t k = 0; k < count && found == count; ++k) {
      if (attributes[k].line == 0 && SameName(attributes[k].name, name)) found = k;
    }
    if (found == count) continue;
    attributes[found].line = name_line;
    attributes[found].column = name_column;
    if (found == next_unplaced) ++next_unplaced;
  }
  pos_ = static_cast<size_t>(p - begin);
  return true;
}

}  // namespace mdlc::xml
