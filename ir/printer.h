// printer.h - the canonical, deterministic text dump of a Module.
//
// The same Module always prints the same bytes: tables in insertion order,
// numbers in shortest round-trip form, locations as file-name:line:col (the
// file's base name, so dumps do not depend on where the input lives).
#pragma once

#include <string>

#include "ir/module.h"
#include "ir/source_manager.h"

namespace mdlc::ir {

struct PrintOptions {
  bool locations = true;
};

std::string PrintModule(const Module& module, const SourceManager& sources,
                        const PrintOptions& options = {});

}  // namespace mdlc::ir
