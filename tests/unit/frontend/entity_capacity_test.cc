// ReserveEntities: room in the entity tables before a document is lowered,
// growing geometrically when many small documents each ask for a little
// (issue 16: large scenes stay linear); the element counts a document keeps;
// and each XML frontend's room, which must hold what its lowering adds
// (URDF-001, SDF-002, MJCF-020..024, MJCF-040, BEYOND-004).
#include "frontend/entity_capacity.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "frontend/frontend.h"
#include "frontend/mjcf/mjcf_capacity.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"
#include "tests/unit/files_under.h"
#include "tests/unit/mjcf_test_util.h"
#include "ir/format.h"

namespace mdlc::frontend {
namespace {

TEST(ReserveEntitiesTest, RoomPastTheEntitiesAlreadyThere) {
  ir::Module m;
  m.bodies.resize(5);
  ReserveEntities(m, EntityRoom{100, 200, 300, 400, 500, 600, 700});
  EXPECT_GE(m.bodies.capacity(), 105u);
  EXPECT_GE(m.frames.capacity(), m.frames.size() + 200);
  EXPECT_GE(m.joints.capacity(), m.joints.size() + 300);
  EXPECT_GE(m.geometries.capacity(), m.geometries.size() + 400);
  EXPECT_GE(m.frame_graph.nodes.capacity(), m.frame_graph.nodes.size() + 500);
  EXPECT_GE(m.models.capacity(), m.models.size() + 600);
  EXPECT_GE(m.frame_graph.scopes.capacity(), m.frame_graph.scopes.size() + 700);
}

// A scene of 10,000 small files, each reserving before its entities are
// added: the table must move a logarithmic number of times, not once per file.
TEST(ReserveEntitiesTest, ManySmallDocumentsGrowTheTablesGeometrically) {
  ir::Module m;
  int moves = 0;
  const ir::Body* storage = m.bodies.data();
  for (int file = 0; file < 10000; ++file) {
    ReserveEntities(m, EntityRoom{.bodies = 3});  // a three-body room per file
    for (int i = 0; i < 3; ++i) m.bodies.emplace_back();
    if (m.bodies.data() != storage) {
      ++moves;
      storage = m.bodies.data();
    }
  }
  EXPECT_LE(moves, 20);
}

// A document's element counts, prefixed names and a document with more
// distinct names than the count table first holds included.
TEST(ElementCountsTest, CountsEveryName) {
  std::string xml = "<r xmlns:drake='d'>";
  for (int i = 0; i < 100; ++i) xml += fmt::format("<e{}/><link/><drake:joint/>", i % 70);
  xml += "</r>";
  SourceManager sources;
  DiagnosticEngine diags;
  auto doc = xml::XmlDocument::Parse(sources.AddBuffer("c.xml", xml), sources, diags);
  ASSERT_NE(doc, nullptr);
  EXPECT_EQ(doc->CountOf("r"), 1u);
  EXPECT_EQ(doc->CountOf("link"), 100u);
  EXPECT_EQ(doc->CountOf("drake:joint"), 100u);
  EXPECT_EQ(doc->CountOf("joint"), 0u);
  EXPECT_EQ(doc->CountOf("e0"), 2u);   // i = 0 and 70
  EXPECT_EQ(doc->CountOf("e69"), 1u);
  uint64_t named_e = 0;
  for (int k = 0; k < 70; ++k) named_e += doc->CountOf(fmt::format("e{}", k));
  EXPECT_EQ(named_e, 100u);
}

// How much each table of a module grew from `before`.
EntityRoom Added(const ir::Module& before, const ir::Module& after) {
  return {after.bodies.size() - before.bodies.size(), after.frames.size() - before.frames.size(),
          after.joints.size() - before.joints.size(),
          after.geometries.size() - before.geometries.size(),
          after.frame_graph.nodes.size() - before.frame_graph.nodes.size(),
          after.models.size() - before.models.size(),
          after.frame_graph.scopes.size() - before.frame_graph.scopes.size()};
}

// `floating`: the floating joints the kinematic-tree pass will add, which
// the room holds beyond what the frontend adds; `unreserved_models`: model
// instances the frontend adds without room (a URDF file's one robot).
void ExpectRoomIsWhatTheLoweringAdds(Format format, const std::string& text,
                                     EntityRoom (*room_of)(const xml::XmlDocument&),
                                     size_t floating, size_t unreserved_models) {
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  const ir::Module empty;
  const FileId file = sources.AddBuffer("model.xml", text);
  auto doc = xml::XmlDocument::Parse(file, sources, diags);
  ASSERT_NE(doc, nullptr);
  const EntityRoom room = room_of(*doc);
  frontend::FrontendContext ctx{sources, diags, module, {}};
  ASSERT_TRUE(frontend::ReadModel(file, format, ctx).has_value());
  ASSERT_FALSE(diags.has_errors());
  const EntityRoom added = Added(empty, module);
  EXPECT_EQ(room.bodies, added.bodies);
  EXPECT_EQ(room.frames, added.frames);
  EXPECT_EQ(room.joints, added.joints + floating);
  EXPECT_EQ(room.geometries, added.geometries);
  EXPECT_EQ(room.frame_nodes, added.frame_nodes);
  EXPECT_EQ(room.frame_scopes, added.frame_scopes);
  EXPECT_EQ(room.models + unreserved_models, added.models);
}

TEST(UrdfEntityRoomTest, CountsWhatTheRobotAdds) {
  ExpectRoomIsWhatTheLoweringAdds(Format::Urdf, R"(<robot name="r" xmlns:drake="http://drake.mit.edu">
  <link name="a"><visual><geometry><box size="1 1 1"/></geometry></visual>
    <collision><geometry><sphere radius="1"/></geometry></collision></link>
  <link name="b"><collision><geometry><sphere radius="1"/></geometry></collision></link>
  <link name="c"/>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <drake:joint name="k" type="planar"><parent link="b"/><child link="c"/>
    <axis xyz="0 0 1"/></drake:joint>
  <frame name="f" link="a" xyz="0 0 1" rpy="0 0 0"/>
</robot>)",
                                  UrdfEntityRoom, /*floating=*/1, /*unreserved_models=*/1);
}

TEST(SdfEntityRoomTest, CountsWhatTheWorldAdds) {
  ExpectRoomIsWhatTheLoweringAdds(Format::Sdf, R"(<?xml version="1.0"?>
<sdf version="1.9"><world name="w">
  <model name="m">
    <link name="a"><visual name="v"><geometry><box><size>1 1 1</size></box></geometry></visual>
      <collision name="c"><geometry><sphere><radius>1</radius></sphere></geometry></collision></link>
    <link name="b"><pose>0 0 1 0 0 0</pose></link>
    <joint name="j" type="revolute"><parent>a</parent><child>b</child>
      <axis><xyz>0 0 1</xyz></axis></joint>
    <frame name="f" attached_to="a"/>
    <model name="inner"><link name="c"/></model>
  </model>
  <model name="free"><link name="d"/></model>
</world></sdf>)",
                                  SdfEntityRoom, /*floating=*/3, /*unreserved_models=*/0);
}

// A file holding one model, not a world, still has the world's node.
TEST(SdfEntityRoomTest, CountsWhatAModelFileAdds) {
  ExpectRoomIsWhatTheLoweringAdds(Format::Sdf, R"(<?xml version="1.0"?>
<sdf version="1.9"><model name="m">
  <link name="a"><collision name="c"><geometry><sphere><radius>1</radius></sphere></geometry>
    </collision></link>
  <link name="b"/>
  <joint name="j" type="revolute"><parent>a</parent><child>b</child>
    <axis><xyz>0 0 1</xyz></axis></joint>
</model></sdf>)",
                                  SdfEntityRoom, /*floating=*/1, /*unreserved_models=*/0);
}

// The room counted from an MJCF document's element counts holds what its
// lowering adds, never less (counts that fell short would make a large
// model's tables double and move every entity): a body with two joints (one
// massless body between them), a joint-less body (a weld), a free body,
// geoms that are both visual and collision, geoms and a site inside
// <frame>s, and world geoms. The room is a slot per <body> and per joint in
// both the body and the joint table (a default class's <joint> included).
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
  const EntityRoom room = mjcf::MjcfEntityRoom({std::shared_ptr<const xml::XmlDocument>(std::move(doc))});

  const EntityRoom added = Added(empty, lowered.module);
  // 4 bodies, 3 joints and a freejoint in them, and the <default>'s joint
  EXPECT_EQ(room.bodies, 4u + 3u + 1u + 1u);
  EXPECT_EQ(room.joints, room.bodies);
  EXPECT_LE(added.bodies, room.bodies);
  EXPECT_LE(added.joints, room.joints);
  EXPECT_EQ(room.frames, added.frames);
  // room for each of the seven geoms and the default class's <geom> twice
  // (illustration and proximity), which holds what the lowering added
  EXPECT_EQ(room.geometries, 2 * 8u);
  EXPECT_LE(added.geometries, room.geometries);
}

// The room is an estimate made before lowering, from element counts: a
// change to what a reader adds could leave it short, and nothing else would
// fail (the tables would grow by doubling, as fast but with up to a third
// more peak memory on the 10,000-link models). So every test model, example
// and corpus file that one document describes (no <include>, no xacro, no
// MJCF <replicate> or <attach>, whose room the reader takes from the
// document they expand to) is lowered, and its room must hold what the
// lowering added, per table.
struct RoomCheck {
  int files = 0;
  std::vector<std::string> short_rooms;
};
void CheckRoomHoldsWhatEachFileAdds(const std::filesystem::path& root, RoomCheck& check) {
  testing::ForEachFileUnder({root}, {".urdf", ".sdf", ".xml"},
                            [&](const std::string& path, const std::string& text) {
    SourceManager sources;
    DiagnosticEngine diags;
    const FileId file = sources.AddBuffer(path, text);
    auto doc = xml::XmlDocument::Parse(file, sources, diags);
    if (!doc || diags.has_errors() || doc->CountOf("include") > 0) return;
    if (doc->CountOf("replicate") > 0 || doc->CountOf("attach") > 0) return;
    const std::optional<Format> format = FormatFromRootElement(doc->Root().Name());
    if (!format) return;
    EntityRoom room;
    size_t floating = 0;  // URDF and SDFormat reserve the kinematic-tree pass's floating joints
    if (*format == Format::Urdf) {
      room = UrdfEntityRoom(*doc);
      floating = doc->CountOf("robot");
    } else if (*format == Format::Sdf) {
      room = SdfEntityRoom(*doc);
      floating = doc->CountOf("model");
    } else if (*format == Format::Mjcf) {
      room = mjcf::MjcfEntityRoom({std::shared_ptr<const xml::XmlDocument>(std::move(doc))});
    } else {
      return;
    }
    ir::Module module;
    const ir::Module empty;
    FrontendContext ctx{sources, diags, module, {}};
    if (!ReadModel(file, *format, ctx) || diags.has_errors()) return;
    ++check.files;
    const EntityRoom added = Added(empty, module);
    const std::pair<const char*, std::pair<size_t, size_t>> tables[] = {
        {"bodies", {room.bodies, added.bodies}},
        {"frames", {room.frames, added.frames}},
        {"joints", {room.joints, added.joints + floating}},
        {"geometries", {room.geometries, added.geometries}},
        {"frame graph nodes", {room.frame_nodes, added.frame_nodes}},
        {"frame scopes", {room.frame_scopes, added.frame_scopes}}};
    for (const auto& [table, counts] : tables) {
      if (counts.first < counts.second) {
        check.short_rooms.push_back(fmt::format("{}: room for {} {}, {} added", path,
                                                counts.first, table, counts.second));
      }
    }
  });
}

TEST(EntityRoomTest, HoldsWhatEveryTestModelAdds) {
  const std::filesystem::path tests = std::filesystem::path(MDLC_TEST_MODELS).parent_path();
  RoomCheck check;
  CheckRoomHoldsWhatEachFileAdds(tests / "models", check);
  CheckRoomHoldsWhatEachFileAdds(tests / "golden", check);
  CheckRoomHoldsWhatEachFileAdds(MDLC_EXAMPLES_DIR, check);
  EXPECT_GE(check.files, 60);  // 71 when this was written
  EXPECT_EQ(check.short_rooms, std::vector<std::string>{});
}

TEST(EntityRoomTest, HoldsWhatEveryCorpusModelAdds) {
  const std::filesystem::path corpus = std::filesystem::path(MDLC_SHARED_DIR) / "corpus";
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << "no corpus beside the repository";
  RoomCheck check;
  CheckRoomHoldsWhatEachFileAdds(corpus, check);
  EXPECT_GE(check.files, 50);
  EXPECT_EQ(check.short_rooms, std::vector<std::string>{});
}

}  // namespace
}  // namespace mdlc::frontend
