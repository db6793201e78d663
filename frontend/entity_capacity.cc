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

void ReserveEntities(ir::Module& module, uint64_t elements) {
  const auto room = static_cast<size_t>(elements / 8);
  ReserveMore(module.bodies, room);
  ReserveMore(module.frames, room);
  ReserveMore(module.joints, room);
  ReserveMore(module.geometries, room);
  ReserveMore(module.frame_graph.nodes, room);
}

}  // namespace mdlc::frontend
