#include "frontend/xacro/macro_params.h"

#include <vector>

namespace mdlc::xacro {
namespace {

// Python's \s, for the ASCII text an attribute value holds
bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool EndsWord(std::string_view s, size_t at) { return at == s.size() || IsSpace(s[at]); }

// The end of a `${...}` or `$(...)` default starting at `at`: the first
// closing bracket with a blank or the end after it; npos if none.
size_t BracketedEnd(std::string_view s, size_t at, char close) {
  for (size_t end = s.find(close, at + 2); end != std::string_view::npos;
       end = s.find(close, end + 1)) {
    if (EndsWord(s, end + 1)) return end + 1;
  }
  return std::string_view::npos;
}

// The end of a default made of pieces from `at`: quoted ('...' or "...")
// or runs of anything but blanks and quotes, ending at a blank or the end;
// npos when no way of cutting it ends so. xacro's expression tries the
// shortest quote first and, when what follows does not end the default,
// a longer one (to a later quote of the same kind): from each position the
// outcome is the same whatever came before, so it is found for every
// position from the right, in one pass, never by trying again.
size_t PiecesEnd(std::string_view s, size_t at) {
  constexpr size_t kNone = std::string_view::npos;
  const size_t n = s.size();
  // end[i]: where the default ends when pieces go on from i
  std::vector<size_t> end(n + 2, kNone);
  // good_single[i]: the first ' at or after i after which the pieces end
  // (its end[+1] is known); likewise for "
  std::vector<size_t> good_single(n + 2, kNone), good_double(n + 2, kNone);
  size_t run_end = n;  // the first blank or quote after a run of plain characters
  for (size_t i = n + 1; i-- > 0;) {
    if (i == n || IsSpace(s[i])) {
      end[i] = i;
      run_end = i;
    } else if (s[i] == '\'' || s[i] == '"') {
      run_end = i;
      const size_t close = s[i] == '\'' ? good_single[i + 1] : good_double[i + 1];
      if (close != kNone) end[i] = end[close + 1];
    } else {
      end[i] = end[run_end];
    }
    if (i < n) {
      const bool ends_after = end[i + 1] != kNone;
      good_single[i] = s[i] == '\'' && ends_after ? i : good_single[i + 1];
      good_double[i] = s[i] == '"' && ends_after ? i : good_double[i + 1];
    }
  }
  return end[at];
}

}  // namespace

// xacro reads `params` with one regular expression; this is the same
// grammar read by hand, in linear time: the expression backtracks without
// bound on unbalanced quotes, and a matcher that recurses overflows its
// stack on a long default.
MacroParam NextMacroParam(std::string_view& rest) {
  MacroParam param;
  const std::string_view s = rest;
  size_t i = 0;
  while (i < s.size() && IsSpace(s[i])) ++i;
  const size_t name_start = i;
  while (i < s.size() && !IsSpace(s[i]) && s[i] != ':' && s[i] != '=') ++i;
  const size_t name_end = i;
  size_t j = i;
  while (j < s.size() && IsSpace(s[j])) ++j;
  if (j < s.size() && s[j] == ':') ++j;
  bool with_default = name_end > name_start && j < s.size() && s[j] == '=';
  if (with_default) {
    ++j;
    while (j < s.size() && IsSpace(s[j])) ++j;
    bool forward = false;
    if (j < s.size() && s[j] == '^') {
      forward = true;
      ++j;
      if (j < s.size() && s[j] == '|') ++j;
    }
    // the default: ${...}, $(...), pieces, or nothing, then a blank or the end
    size_t end = std::string_view::npos;
    if (s.substr(j, 2) == "${") end = BracketedEnd(s, j, '}');
    if (end == std::string_view::npos && s.substr(j, 2) == "$(") end = BracketedEnd(s, j, ')');
    if (end == std::string_view::npos && j < s.size() && !IsSpace(s[j])) end = PiecesEnd(s, j);
    if (end == std::string_view::npos && EndsWord(s, j)) end = j;
    if (end != std::string_view::npos) {
      param.name = std::string(s.substr(name_start, name_end - name_start));
      param.has_default = true;
      if (forward) param.forward = param.name;
      if (end > j) param.default_text = std::string(s.substr(j, end - j));
      size_t next = end;
      while (next < s.size() && IsSpace(s[next])) ++next;
      rest = s.substr(next);
      return param;
    }
  }
  // no default: the name is the first word
  if (name_start == s.size()) {
    rest = {};
    return param;
  }
  size_t word_end = name_start;
  while (word_end < s.size() && !IsSpace(s[word_end])) ++word_end;
  param.name = std::string(s.substr(name_start, word_end - name_start));
  while (word_end < s.size() && IsSpace(s[word_end])) ++word_end;
  rest = s.substr(word_end);
  return param;
}

}  // namespace mdlc::xacro
