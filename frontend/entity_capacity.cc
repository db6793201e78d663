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

EntityRoom EntityRoom::ForElements(uint64_t elements) {
  const auto eighth = static_cast<size_t>(elements / 8);
  return {eighth, eighth, eighth, eighth, eighth};
}

void ReserveEntities(ir::Module& module, const EntityRoom& room) {
  ReserveMore(module.bodies, room.bodies);
  ReserveMore(module.frames, room.frames);
  ReserveMore(module.joints, room.joints);
  ReserveMore(module.geometries, room.geometries);
  ReserveMore(module.frame_graph.nodes, room.frame_nodes);
}

}  // namespace mdlc::frontend
