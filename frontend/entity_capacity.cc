// entity_capacity.cc - see entity_capacity.h.
#include "frontend/entity_capacity.h"

namespace mdlc::frontend {
namespace {
template <typename Table>
void ReserveMore(Table& table, size_t more) {
  table.reserve(table.size() + more);
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
