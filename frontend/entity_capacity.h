// entity_capacity.h - room in the IR's entity tables before a large document
// is lowered. It pays: without it the 10,000-link models' peak memory is 15%
// to 28% higher (tests/bench/NOTES.md). The room is an estimate from element
// counts, made apart from the readers; EntityRoomTest.HoldsWhatEvery* checks
// it against what lowering every test and corpus model really adds, so a
// reader that starts adding more fails a test instead of quietly doubling.
#pragma once

#include <cstddef>
#include <cstdint>

#include "frontend/xml/xml_document.h"
#include "ir/module.h"

namespace mdlc::frontend {

/// How many entities of each kind a document is expected to add.
struct EntityRoom {
  size_t bodies = 0, frames = 0, joints = 0, geometries = 0, frame_nodes = 0, models = 0;
  size_t frame_scopes = 0;  // SDFormat's name scopes: the world's and one per model
};

/// What a URDF document adds, from its element counts: a body per <link>, a
/// joint per <joint> and <drake:joint>, a geometry per <visual> and
/// <collision>, a frame per <frame>; and a joint for the root link to float
/// on, which the kinematic-tree pass adds.
EntityRoom UrdfEntityRoom(const xml::XmlDocument& doc);
/// What an SDFormat document adds itself (each file it includes reserves
/// its own room when it is read): as URDF, with a model instance, a floating
/// joint and a frame (its model frame) per <model>, and a frame-graph node
/// for the world and per model, link, joint, frame, visual, collision and
/// sensor, and a name scope for the world and per model.
EntityRoom SdfEntityRoom(const xml::XmlDocument& doc);

/// Reserves `room` past the entities the module already holds, so that
/// lowering a large model does not grow its tables by doubling, which moves
/// every entity (several hundred bytes each) and, in a fresh process,
/// touches twice their memory.
void ReserveEntities(ir::Module& module, const EntityRoom& room);

}  // namespace mdlc::frontend
