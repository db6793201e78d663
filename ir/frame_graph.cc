// frame_graph.cc - see frame_graph.h.
#include "ir/frame_graph.h"

namespace mdlc::ir {

void FrameGraph::IndexNames() {
  names.clear();
  names.Reserve(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const FrameNode& node = nodes[i];
    if (node.kind == FrameNodeKind::Anchor || node.kind == FrameNodeKind::World) continue;
    names.TryAdd(Namespace(node.scope).value, node.name, FrameNodeId(i));  // first one wins
  }
  names_complete = true;
}

}  // namespace mdlc::ir
