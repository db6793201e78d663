// ref_check.h - the backend's defensive check of IR references (header-only).
//
// The passes resolve every Ref before the backend runs; the backend still
// refuses a Ref whose id is invalid or out of its table's range, reporting
// an unknown-reference error instead of indexing out of bounds.
#pragma once

#include <fmt/format.h>

#include <string_view>

#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::backend {

/// True when `id` indexes a table of `size` entries; else reports an error
/// about `what` (e.g. "body") named `name`, at `loc`.
template <typename IdT>
bool CheckId(IdT id, size_t size, std::string_view what, std::string_view name, Loc loc,
             DiagnosticEngine& diags) {
  if (id.valid() && id.index() < size) return true;
  diags.Report(DiagKind::VerifierFailure, loc,
               fmt::format("internal: unresolved reference to {} '{}'", what, name));
  return false;
}

/// CheckId for a Ref: reports at the Ref's own location when it has one.
template <typename IdT>
bool CheckRef(const ir::Module& module, const ir::Ref<IdT>& ref, size_t size,
              std::string_view what, Loc entity_loc, DiagnosticEngine& diags) {
  return CheckId(ref.id, size, what, module.Text(ref.name),
                 ref.loc.valid() ? ref.loc : entity_loc, diags);
}

/// True when an entity's model instance id is in range; else reports.
inline bool CheckModel(const ir::Module& module, ModelId model, Loc loc,
                       DiagnosticEngine& diags) {
  if (model.valid() && model.index() < module.models.size()) return true;
  diags.Report(DiagKind::VerifierFailure, loc,
               fmt::format("internal: entity belongs to no known model instance (id {})",
                           model.value));
  return false;
}

}  // namespace mdlc::backend
