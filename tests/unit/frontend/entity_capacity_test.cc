// ReserveEntities: room in the entity tables before a document is lowered,
// growing geometrically when many small documents each ask for a little
// (issue 16: large scenes stay linear).
#include "frontend/entity_capacity.h"

#include <gtest/gtest.h>

namespace mdlc::frontend {
namespace {

TEST(ReserveEntitiesTest, RoomForAnEighthOfTheElements) {
  ir::Module m;
  const size_t before = m.bodies.size();
  ReserveEntities(m, 800);
  EXPECT_GE(m.bodies.capacity(), before + 100);
  EXPECT_GE(m.joints.capacity(), m.joints.size() + 100);
  EXPECT_GE(m.geometries.capacity(), m.geometries.size() + 100);
  EXPECT_GE(m.frames.capacity(), m.frames.size() + 100);
  EXPECT_GE(m.frame_graph.nodes.capacity(), m.frame_graph.nodes.size() + 100);
}

// A scene of 10,000 small files, each reserving before its entities are
// added: the table must move a logarithmic number of times, not once per file.
TEST(ReserveEntitiesTest, ManySmallDocumentsGrowTheTablesGeometrically) {
  ir::Module m;
  int moves = 0;
  const ir::Body* storage = m.bodies.data();
  for (int file = 0; file < 10000; ++file) {
    ReserveEntities(m, 24);  // a three-element room per file
    for (int i = 0; i < 3; ++i) m.bodies.emplace_back();
    if (m.bodies.data() != storage) {
      ++moves;
      storage = m.bodies.data();
    }
  }
  EXPECT_LE(moves, 20);
}

}  // namespace
}  // namespace mdlc::frontend
