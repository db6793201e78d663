// original_names.h - the round-trip metadata `mdlc convert` writes inside
// an element whose name it changed (ir/syntax/original_name_comment.h), read by the URDF
// and MJCF frontends into ir::Module::original_names for the restore-names
// pass.
#pragma once

#include <optional>

#include "frontend/frontend.h"
#include "frontend/xml/xml_document.h"
#include "ir/original_name.h"
#include "ir/syntax/original_name_comment.h"

namespace mdlc::frontend {

using OriginalEntity = decltype(ir::OriginalName::entity);

/// Records the `<!-- mdlc:name ... -->` comment directly inside `e`, if
/// any, as the original name of `entity`, and returns it. Names are
/// restored only in a file compiled on its own: not under a name the
/// caller gave (--model-name), a directive's add_model or an SDFormat
/// include, which name the model themselves.
std::optional<syntax::ParsedOriginalName> ReadOriginalName(const xml::XmlElement& e,
                                                           OriginalEntity entity,
                                                           FrontendContext& ctx);

}  // namespace mdlc::frontend
