// entity_capacity.h - room in the IR's entity tables before a large document
// is lowered.
#pragma once

#include <cstdint>

#include "ir/module.h"

namespace mdlc::frontend {

/// Reserves room in the module's entity tables for a document of `elements`
/// elements, so that lowering a large model does not grow them by doubling,
/// which moves every entity (several hundred bytes each) and, in a fresh
/// process, touches twice their memory. Every entity comes from an element
/// written with several others around it (a pose, an inertia, a shape), so
/// an eighth of the count is room enough for a whole table; room left over
/// in a large table is address space that is never touched.
void ReserveEntities(ir::Module& module, uint64_t elements);

}  // namespace mdlc::frontend
