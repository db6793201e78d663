// entity_capacity.h - room in the IR's entity tables before a large document
// is lowered.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ir/module.h"

namespace mdlc::frontend {

/// How many entities of each kind a document is expected to add.
struct EntityRoom {
  size_t bodies = 0, frames = 0, joints = 0, geometries = 0, frame_nodes = 0;

  /// For a format in which every entity comes from an element written with
  /// several others around it (a URDF link has its inertial, origin, mass,
  /// inertia, visual and collision; an SDFormat link its pose and more): an
  /// eighth of the document's element count for every table. Room left over
  /// in a large table is address space that is never touched.
  static EntityRoom ForElements(uint64_t elements);
};

/// Reserves `room` past the entities the module already holds, so that
/// lowering a large model does not grow its tables by doubling, which moves
/// every entity (several hundred bytes each) and, in a fresh process,
/// touches twice their memory.
void ReserveEntities(ir::Module& module, const EntityRoom& room);

}  // namespace mdlc::frontend
