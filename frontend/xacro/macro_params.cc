#include "frontend/xacro/macro_params.h"

#include <regex>

namespace mdlc::xacro {

MacroParam NextMacroParam(std::string_view& rest) {
  // the grammar xacro reads `params` with, as one regular expression: a
  // name, `:=` or `=`, an optional `^` or `^|`, and a default that is
  // `${...}`, `$(...)`, or quoted and unquoted pieces up to a blank
  static const std::regex kParamWithDefault(
      R"(^\s*([^\s:=]+?)\s*:?=\s*(\^\|?)?(\$\{.*?\}|\$\(.*?\)|(?:'.*?'|".*?"|[^\s'"]+)+|)(?:\s+|$)([^]*))");
  MacroParam param;
  std::match_results<std::string_view::const_iterator> m;
  if (std::regex_search(rest.begin(), rest.end(), m, kParamWithDefault)) {
    param.name = m[1].str();
    param.has_default = true;
    if (m[2].matched) param.forward = param.name;
    if (m[3].length() > 0) param.default_text = m[3].str();
    rest = rest.substr(static_cast<size_t>(m[4].first - rest.begin()));
    return param;
  }
  // no default: the name is the first word
  const size_t start = rest.find_first_not_of(" \t\n\r\f\v");
  if (start == std::string_view::npos) {
    rest = {};
    return param;
  }
  const size_t end = rest.find_first_of(" \t\n\r\f\v", start);
  param.name = std::string(rest.substr(start, end == std::string_view::npos ? end : end - start));
  rest = end == std::string_view::npos ? std::string_view() : rest.substr(end);
  // split(None, 1) drops the blanks after the first word too
  const size_t next = rest.find_first_not_of(" \t\n\r\f\v");
  rest = next == std::string_view::npos ? std::string_view() : rest.substr(next);
  return param;
}

}  // namespace mdlc::xacro
