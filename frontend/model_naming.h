// model_naming.h - choosing a model instance's name (COMMON-021, COMMON-022).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <absl/container/flat_hash_map.h>

#include "frontend/frontend.h"

namespace mdlc::frontend {

/// The suffix auto-rename last gave each name. NAME_1, NAME_2, ... stay
/// taken once taken (frontends never free a name), so the next rename of
/// NAME starts past it and gets the first free suffix all the same; searched
/// from NAME_1 every time, n copies of one model took n^2/2 lookups.
struct RenameSuffixes {
  absl::flat_hash_map<std::string, int> last;
};

/// The model instance whose full name is exactly `name`, if any.
std::optional<ModelId> FindModelInstance(const ir::Module& module, std::string_view name);

/// Adds a model instance named `requested` (or the caller's override), after
/// checking it is free. On a collision: NAME_1, NAME_2, ... with auto-rename,
/// otherwise an error at `loc` (and nullopt).
std::optional<ModelId> AddModelInstance(std::string_view requested, Loc loc,
                                        ir::SourceFormat format, FrontendContext& ctx);

}  // namespace mdlc::frontend
