// ReserveEntities: room in the entity tables before a document is lowered,
// growing geometrically when many small documents each ask for a little
// (issue 16: large scenes stay linear); and the MJCF frontend's count of the
// entities its body tree adds (MJCF-020..024, MJCF-040, BEYOND-004).
#include "frontend/entity_capacity.h"

#include <gtest/gtest.h>

#include "frontend/mjcf/mjcf_capacity.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"
#include "tests/unit/mjcf_test_util.h"

namespace mdlc::frontend {
namespace {

TEST(ReserveEntitiesTest, RoomForAnEighthOfTheElements) {
  ir::Module m;
  const size_t before = m.bodies.size();
  ReserveEntities(m, EntityRoom::ForElements(800));
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
    ReserveEntities(m, EntityRoom::ForElements(24));  // a three-element room per file
    for (int i = 0; i < 3; ++i) m.bodies.emplace_back();
    if (m.bodies.data() != storage) {
      ++moves;
      storage = m.bodies.data();
    }
  }
  EXPECT_LE(moves, 20);
}

// The room counted from an MJCF document is exactly what its lowering adds:
// a body with two joints (one massless body between them), a joint-less body
// (a weld), a free body, geoms that are both visual and collision, geoms and
// a site inside <frame>s, and world geoms. Counts that fell short would make
// a large model's tables double and move every entity.
TEST(MjcfEntityRoomTest, CountsWhatTheBodyTreeAdds) {
  const std::string xml = R"(<mujoco model="m">
  <default><geom size="0.1"/><joint axis="0 0 1"/></default>
  <worldbody>
    <geom type="plane" size="1 1 1"/>
    <body name="a">
      <joint name="a1"/><joint name="a2" type="slide"/>
      <geom/><geom contype="0" conaffinity="0" group="1"/>
      <frame pos="0 0 1">
        <site name="s"/><geom/>
        <body name="b"><geom/>
          <frame><joint name="b1"/></frame>
          <body name="c"><geom/></body>
        </body>
      </frame>
    </body>
    <body name="free"><freejoint/><geom/></body>
  </worldbody>
</mujoco>
)";
  testing::LoweredMjcf lowered(xml);
  ASSERT_TRUE(lowered.ok()) << lowered.Messages();
  ir::Module empty;

  SourceManager sources;
  DiagnosticEngine diags;
  const FileId file = sources.AddBuffer("model.xml", xml);
  auto doc = xml::XmlDocument::Parse(file, sources, diags);
  ASSERT_NE(doc, nullptr);
  const EntityRoom room = mjcf::MjcfEntityRoom(doc->Root());

  EXPECT_EQ(room.bodies, lowered.module.bodies.size() - empty.bodies.size());
  EXPECT_EQ(room.joints, lowered.module.joints.size() - empty.joints.size());
  EXPECT_EQ(room.frames, lowered.module.frames.size() - empty.frames.size());
  // room for each of the seven geoms twice (illustration and proximity),
  // which holds what the lowering added
  EXPECT_EQ(room.geometries, 2 * 7u);
  EXPECT_LE(lowered.module.geometries.size() - empty.geometries.size(), room.geometries);
}

}  // namespace
}  // namespace mdlc::frontend
