// model_naming.h - choosing a model instance's name (COMMON-021, COMMON-022).
#pragma once

#include <optional>
#include <string_view>

#include "frontend/frontend.h"

namespace mdlc::frontend {

/// The model instance whose full name is exactly `name`, if any.
std::optional<ModelId> FindModelInstance(const ir::Module& module, std::string_view name);

/// Adds a model instance named `requested` (or the caller's override), after
/// checking it is free. On a collision: NAME_1, NAME_2, ... with auto-rename,
/// otherwise an error at `loc` (and nullopt).
std::optional<ModelId> AddModelInstance(std::string_view requested, Loc loc,
                                        ir::SourceFormat format, FrontendContext& ctx);

}  // namespace mdlc::frontend
