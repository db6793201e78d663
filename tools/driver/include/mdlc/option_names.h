// mdlc/option_names.h - the one place that checks the names and values a
// caller gives mdlc's options: warning groups (-W), pass names (--passes,
// --print-after), limits (--limit), the mesh reader and COLLADA's up axis,
// and the keywords of the Python module's compile(). The command line and
// the Python module both use it, so a misspelling is refused the same way
// everywhere, with the nearest known name as a suggestion:
//
//   unknown warning group 'jiont' in -Wno-jiont; did you mean 'joint'?
//
// Each function returns nothing when the text is good (and applies it), or
// the message, without a prefix: the command line prints it after
// "mdlc: error: ", Python raises it as a ValueError.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc {

/// Every warning group of mdlc's diagnostics (what -Wno-GROUP names),
/// sorted.
const std::vector<std::string_view>& WarningGroupNames();

/// Every built-in pass, in the default pipeline's order.
const std::vector<std::string_view>& PassNames();

/// Applies the text of one -W flag to `policy`: "error" (every warning is
/// an error), "error=GROUP", "no-GROUP", or "GROUP" (enabled, as by
/// default). `where` names the flag in the message ("-Wno-jiont", or a
/// Python keyword).
std::optional<std::string> ApplyWarningFlag(DiagnosticPolicy& policy, std::string_view flag,
                                            std::string_view where);

/// Checks that `name` is a pass (`where`: "--passes", "--print-after").
std::optional<std::string> CheckPassName(std::string_view name, std::string_view where);

/// Sets the limit a NAME=VALUE setting names (ir/limits.h SetLimit), with
/// a suggestion for a misspelt NAME.
std::optional<std::string> ApplyLimitSetting(Limits& limits, std::string_view setting,
                                             std::string_view where);

/// "process" or "in-process" (`--mesh-reader`).
std::optional<std::string> ParseMeshReader(std::string_view text, std::string_view where,
                                           MeshReader& reader);

/// "as-written" or "apply" (`--collada-up-axis`).
std::optional<std::string> ParseColladaUpAxis(std::string_view text, std::string_view where,
                                              ColladaUpAxis& axis);

/// An option of a compile as the Python module takes it by keyword, and
/// the command-line flag that sets the same (empty when none does).
struct OptionName {
  std::string_view keyword;
  std::string_view flag;
};

/// The keywords of the Python module's compile(), sorted.
const std::vector<OptionName>& CompileOptionNames();

/// Checks that `keyword` is one of CompileOptionNames() (`function` names
/// the caller in the message: "mdlc.compile").
std::optional<std::string> CheckOptionKeyword(std::string_view keyword, std::string_view function);

}  // namespace mdlc
