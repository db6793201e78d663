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
}  // namespace

EntityRoom UrdfEntityRoom(const xml::XmlDocument& doc) {
  EntityRoom room;
  room.bodies = doc.CountOf("link");
  room.joints = doc.CountOf("joint") + doc.CountOf("drake:joint");
  room.geometries = doc.CountOf("visual") + doc.CountOf("collision");
  room.frames = doc.CountOf("frame");
  return room;
}

EntityRoom SdfEntityRoom(const xml::XmlDocument& doc) {
  EntityRoom room = UrdfEntityRoom(doc);
  const size_t models = doc.CountOf("model");
  const size_t explicit_frames = room.frames;
  room.frames += models;  // each model's own frame
  room.frame_nodes = doc.CountOf("world") + models + room.bodies + room.joints + explicit_frames +
                     room.geometries + doc.CountOf("sensor");
  return room;
}

void ReserveEntities(ir::Module& module, const EntityRoom& room) {
  ReserveMore(module.bodies, room.bodies);
  ReserveMore(module.frames, room.frames);
  ReserveMore(module.joints, room.joints);
  ReserveMore(module.geometries, room.geometries);
  ReserveMore(module.frame_graph.nodes, room.frame_nodes);
}

}  // namespace mdlc::frontend
