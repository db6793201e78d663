// summary.h - the human-readable summary `mdlc compile` prints by default.
#pragma once

#include <string>

#include "backend/compiled_model.h"

namespace mdlc::tools {

std::string FormatSummary(const backend::CompiledModel& model);

}  // namespace mdlc::tools
