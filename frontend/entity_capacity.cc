// entity_capacity.cc - see entity_capacity.h.
#include "frontend/entity_capacity.h"

#include <algorithm>

namespace mdlc::frontend {
namespace {
// Room for `more` entries past the current ones. The capacity at least
// doubles when it must grow: a scene of many small files (Model Directives,
// SDFormat includes) reserves once per file, and growing by exactly the
// request each time would move every entity once per file.
template <typename Table>
void ReserveMore(Table& table, size_t more) {
  const size_t wanted = table.size() + more;
  if (wanted > table.capacity()) table.reserve(std::max(wanted, 2 * table.capacity()));
}

// what URDF and SDFormat both make of an element: links, joints, visuals,
// collisions and frames
EntityRoom CountedFromElements(const xml::XmlDocument& doc) {
  EntityRoom room;
  room.bodies = doc.CountOf("link");
  room.joints = doc.CountOf("joint") + doc.CountOf("drake:joint");
  room.geometries = doc.CountOf("visual") + doc.CountOf("collision");
  room.frames = doc.CountOf("frame");
  return room;
}

// The kinematic-tree pass gives every root body a floating joint; room for
// one per robot or model keeps that from moving a table sized to the file
EntityRoom WithFloatingJoints(EntityRoom room, size_t roots) {
  room.joints += roots;
  return room;
}
}  // namespace

EntityRoom UrdfEntityRoom(const xml::XmlDocument& doc) {
  return WithFloatingJoints(CountedFromElements(doc), doc.CountOf("robot"));
}

EntityRoom SdfEntityRoom(const xml::XmlDocument& doc) {
  const size_t models = doc.CountOf("model");
  EntityRoom room = CountedFromElements(doc);
  // the world's node comes first, whether the file has a <world> or a model
  room.frame_nodes = 1 + models + room.bodies + room.joints + room.frames + room.geometries +
                     doc.CountOf("sensor");
  room.frames += models;  // each model's own frame
  room.models = models;
  room.frame_scopes = 1 + models;
  return WithFloatingJoints(room, models);
}

void ReserveEntities(ir::Module& module, const EntityRoom& room) {
  ReserveMore(module.bodies, room.bodies);
  ReserveMore(module.frames, room.frames);
  ReserveMore(module.joints, room.joints);
  ReserveMore(module.geometries, room.geometries);
  ReserveMore(module.frame_graph.nodes, room.frame_nodes);
  ReserveMore(module.frame_graph.scopes, room.frame_scopes);
  module.ReserveModels(room.models);
}

}  // namespace mdlc::frontend
