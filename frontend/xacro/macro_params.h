// macro_params.h - one parameter of a macro's `params` list.
//
// `params="a b:=1 c:=^ d:=^|2 *origin **content"`: a name, then an
// optional default after `:=` (or `=`), where `^` forwards the caller's
// property of the same name and `^|x` forwards it or else uses x. A default
// runs to the next blank, except inside quotes, `${...}` or `$(...)`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mdlc::xacro {

struct MacroParam {
  std::string name;
  bool has_default = false;
  std::optional<std::string> forward;       // the name forwarded (`^`)
  std::optional<std::string> default_text;  // null: none written
};

/// Takes the first parameter off the front of `rest`.
MacroParam NextMacroParam(std::string_view& rest);

}  // namespace mdlc::xacro
