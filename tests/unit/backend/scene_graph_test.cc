// The scene graph: geometry properties and collision filters
// (backend/build_scene_graph.h, backend/collision_filters.h).
#include "backend/build_scene_graph.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>

#include "tests/unit/backend/backend_test_util.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using test_util::ModelBuilder;
using Pairs = std::vector<std::pair<std::string, std::string>>;

// The filtered pairs by scoped name, after checking that the filters'
// query answers for every two bodies what the list says.
Pairs FilterNames(const CompiledModel& model) {
  const backend::Plant& plant = model.plant;
  const std::vector<std::pair<BodyId, BodyId>> pairs = model.scene.collision_filters.Pairs(plant);
  std::set<std::pair<BodyId, BodyId>> listed;
  for (const auto& [a, b] : pairs) listed.insert({std::min(a, b), std::max(a, b)});
  for (size_t a = 0; a < plant.bodies.size(); ++a) {
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      const bool filtered = model.scene.collision_filters.Filtered(BodyId(a), BodyId(b));
      EXPECT_EQ(filtered, listed.count({BodyId(std::min(a, b)), BodyId(std::max(a, b))}) > 0)
          << plant.ScopedName(plant.bodies[a]) << " and " << plant.ScopedName(plant.bodies[b]);
    }
  }
  Pairs out;
  for (const auto& [a, b] : pairs) {
    out.emplace_back(plant.ScopedName(plant.body(a)), plant.ScopedName(plant.body(b)));
  }
  return out;
}

void AddCollision(ModelBuilder& b, BodyId body) {
  b.AddGeometry("collision", body, ir::Sphere{0.1}, ir::kProximityRole);
}

// COMMON-054: bodies connected by a joint never collide, when both carry
// proximity geometry; Drake (and MuJoCo) exempt joints to the world and
// Drake exempts floating joints.
TEST(BackendCollisionFilters, Common054AdjacentBodies) {
  ModelBuilder b;
  const BodyId base = b.AddMasslessBody("base");
  const BodyId upper = b.AddMasslessBody("upper");
  const BodyId lower = b.AddMasslessBody("lower");
  const BodyId visual_only = b.AddMasslessBody("visual_only");
  const BodyId floater = b.AddMasslessBody("floater");
  b.AddJoint("base", JointType::Revolute, ir::kWorldBody, base);
  b.AddJoint("shoulder", JointType::Revolute, base, upper);
  b.AddJoint("elbow", JointType::Revolute, upper, lower);
  b.AddJoint("wrist", JointType::Revolute, lower, visual_only);
  b.AddJoint("floater", JointType::QuaternionFloating, lower, floater);
  b.AddGeometry("ground", ir::kWorldBody, ir::HalfSpace{}, ir::kProximityRole);
  for (BodyId body : {base, upper, lower, floater}) AddCollision(b, body);
  b.AddGeometry("visual", visual_only, ir::Sphere{0.1}, ir::kIllustrationRole);
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  EXPECT_EQ(FilterNames(*model), (Pairs{{"robot::base", "robot::upper"},
                                        {"robot::lower", "robot::upper"}}));
}

// COMMON-054: free bodies (a scene of many small models) filter nothing,
// whatever geometry they carry; the pairs come only from joints and welds.
TEST(BackendCollisionFilters, Common054FreeBodiesFilterNothing) {
  ModelBuilder b;
  b.AddGeometry("ground", ir::kWorldBody, ir::HalfSpace{}, ir::kProximityRole);
  for (const char* name : {"c", "a", "b"}) {
    const BodyId body = b.AddMasslessBody(name);
    b.AddJoint(name, JointType::QuaternionFloating, ir::kWorldBody, body);
    AddCollision(b, body);
  }
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  EXPECT_EQ(model->plant.bodies.size(), 4u);
  EXPECT_TRUE(FilterNames(*model).empty());
}

// COMMON-054: bodies welded together into one composite filter each other,
// the world's composite included.
TEST(BackendCollisionFilters, Common054WeldedComposites) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId c = b.AddMasslessBody("c");
  const BodyId d = b.AddMasslessBody("d");
  const BodyId e = b.AddMasslessBody("e");
  const BodyId f = b.AddMasslessBody("f");
  b.AddJoint("a", JointType::Revolute, ir::kWorldBody, a);
  b.AddJoint("c", JointType::Weld, a, c);
  b.AddJoint("d", JointType::Weld, c, d);   // a, c, d: one composite
  b.AddJoint("e", JointType::Weld, ir::kWorldBody, e);  // world, e
  b.AddJoint("f", JointType::Weld, e, f);   // world, e, f
  b.AddGeometry("ground", ir::kWorldBody, ir::Box{Eigen::Vector3d::Ones()}, ir::kProximityRole);
  for (BodyId body : {a, d, e, f}) AddCollision(b, body);  // not c
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  EXPECT_EQ(FilterNames(*model), (Pairs{{"robot::a", "robot::d"},
                                        {"robot::e", "robot::f"},
                                        {"robot::e", "world"},
                                        {"robot::f", "world"}}));
}

ir::Ref<FilterGroupId> GroupRef(ModelBuilder& b, FilterGroupId id) { return b.Ref(id, "group"); }

FilterGroupId AddGroup(ModelBuilder& b, std::string_view name, const std::vector<BodyId>& members) {
  ir::CollisionFilterGroup g;
  g.name = b.module().Intern(name);
  g.model = b.model();
  for (BodyId id : members) g.members.push_back(b.BodyRef(id));
  return b.module().Add(g);
}

// COMMON-051: (G, G) excludes pairs within G, (G, H) pairs across;
// COMMON-052: member groups count transitively, and a cycle merges groups.
TEST(BackendCollisionFilters, Common051FilterGroups) {
  ModelBuilder b;
  std::vector<BodyId> bodies;
  for (const char* name : {"b0", "b1", "b2", "b3", "b4"}) {
    bodies.push_back(b.AddMasslessBody(name));
    b.AddJoint(name, JointType::QuaternionFloating, ir::kWorldBody, bodies.back());
    AddCollision(b, bodies.back());
  }
  ir::Module& m = b.module();
  const FilterGroupId self = AddGroup(b, "self", {bodies[0], bodies[1]});
  const FilterGroupId left = AddGroup(b, "left", {bodies[2]});
  const FilterGroupId right = AddGroup(b, "right", {bodies[3]});
  const FilterGroupId loop = AddGroup(b, "loop", {bodies[4]});
  m.filter_groups[self.index()].ignored_groups.push_back(GroupRef(b, self));
  // right contains loop, loop contains right: both are {b3, b4}
  m.filter_groups[right.index()].member_groups.push_back(GroupRef(b, loop));
  m.filter_groups[loop.index()].member_groups.push_back(GroupRef(b, right));
  m.filter_groups[left.index()].ignored_groups.push_back(GroupRef(b, loop));
  auto model = test_util::InstantiateOk(m);
  ASSERT_TRUE(model);
  EXPECT_EQ(FilterNames(*model), (Pairs{{"robot::b0", "robot::b1"},
                                        {"robot::b2", "robot::b3"},
                                        {"robot::b2", "robot::b4"}}));
}

// COMMON-051: a group that ignores a group sharing a member filters that
// member against the others, and never against itself.
TEST(BackendCollisionFilters, Common051OverlappingGroups) {
  ModelBuilder b;
  std::vector<BodyId> bodies;
  for (const char* name : {"b0", "b1", "b2", "b3"}) {
    bodies.push_back(b.AddMasslessBody(name));
    b.AddJoint(name, JointType::QuaternionFloating, ir::kWorldBody, bodies.back());
    if (bodies.size() < 4) AddCollision(b, bodies.back());  // b3: no proximity geometry
  }
  ir::Module& m = b.module();
  const FilterGroupId g = AddGroup(b, "g", {bodies[0], bodies[1], bodies[3]});
  const FilterGroupId h = AddGroup(b, "h", {bodies[1], bodies[2], bodies[3]});
  m.filter_groups[g.index()].ignored_groups.push_back(GroupRef(b, h));
  auto model = test_util::InstantiateOk(m);
  ASSERT_TRUE(model);
  EXPECT_EQ(FilterNames(*model), (Pairs{{"robot::b0", "robot::b1"},
                                        {"robot::b0", "robot::b2"},
                                        {"robot::b1", "robot::b2"}}));
}

// COMMON-054, COMMON-051: 20,000 bodies welded into one composite, all in a
// group that ignores itself, filter 200 million pairs, held as two
// declarations of 20,000 bodies each (a list of the pairs would take
// gigabytes); every pair answers filtered, a free body's pairs do not.
TEST(BackendCollisionFilters, AWeldedCompositeIsHeldAsOneSet) {
  ModelBuilder b;
  constexpr int kBodies = 20000;
  std::vector<BodyId> bodies;
  ir::CollisionFilterGroup all;
  all.name = b.module().Intern("all");
  all.model = b.model();
  for (int i = 0; i < kBodies; ++i) {
    bodies.push_back(b.AddMasslessBody(fmt::format("b{}", i)));
    b.AddJoint(fmt::format("j{}", i), i == 0 ? JointType::Revolute : JointType::Weld,
               i == 0 ? ir::kWorldBody : bodies[i - 1], bodies.back());
    AddCollision(b, bodies.back());
    all.members.push_back(b.BodyRef(bodies.back()));
  }
  const BodyId free_body = b.AddMasslessBody("free");
  b.AddJoint("free", JointType::QuaternionFloating, ir::kWorldBody, free_body);
  AddCollision(b, free_body);
  const FilterGroupId group = b.module().Add(all);
  b.module().filter_groups[group.index()].ignored_groups.push_back(GroupRef(b, group));
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const CollisionFilters& filters = model->scene.collision_filters;
  EXPECT_TRUE(filters.Filtered(bodies.front(), bodies.back()));
  EXPECT_TRUE(filters.Filtered(bodies[kBodies / 2], bodies[7]));
  EXPECT_FALSE(filters.Filtered(bodies[3], bodies[3]));
  EXPECT_FALSE(filters.Filtered(bodies.back(), free_body));
  EXPECT_FALSE(filters.Filtered(ir::kWorldBody, bodies.front()));
}

TEST(BackendCollisionFilters, UnresolvedGroupReferenceIsAnError) {
  ModelBuilder b;
  ir::CollisionFilterGroup g;
  g.name = b.module().Intern("g");
  g.model = b.model();
  g.ignored_groups.push_back(b.Ref(FilterGroupId(), "missing"));
  b.module().Add(g);
  DiagnosticEngine diags;
  EXPECT_FALSE(Instantiate(b.module(), diags));
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].kind, DiagKind::VerifierFailure);
}

// Many properties on one geometry (more than the short in-place sort
// handles): still sorted by key, one per key, the last one given winning.
TEST(BackendSceneGraph, ManyPropertiesSortedOnePerKeyLastWins) {
  ModelBuilder b;
  const BodyId link = b.AddMasslessBody("link");
  b.AddJoint("j", JointType::Revolute, ir::kWorldBody, link);
  ir::Module& m = b.module();
  const GeometryId id = b.AddGeometry("g", link, ir::Sphere{1}, ir::kProximityRole);
  for (int round = 0; round < 2; ++round) {
    for (int k = 29; k >= 0; --k) {
      m[id].properties.push_back({fmt::format("group/p{:02}", k), double(100 * round + k)});
    }
  }
  auto model = test_util::InstantiateOk(m);
  ASSERT_TRUE(model);
  const auto& properties = model->scene.geometries.at(0).properties;
  ASSERT_EQ(properties.size(), 30u);
  for (int k = 0; k < 30; ++k) {
    EXPECT_EQ(properties[k].key, fmt::format("group/p{:02}", k));
    EXPECT_EQ(std::get<double>(properties[k].value), 100 + k);  // the second round's
  }
}

TEST(BackendSceneGraph, ColorBecomesPhongDiffuseForVisibleGeometry) {
  ModelBuilder b;
  const BodyId link = b.AddMasslessBody("link");
  b.AddJoint("j", JointType::Revolute, ir::kWorldBody, link);
  ir::Module& m = b.module();
  ir::Material red;
  red.name = m.Intern("red");
  red.model = b.model();
  red.rgba = Eigen::Vector4d(1, 0, 0, 1);
  red.texture = "red.png";
  const MaterialId red_id = m.Add(red);

  const GeometryId inline_color =
      b.AddGeometry("inline", link, ir::Sphere{1}, ir::kIllustrationRole);
  m[inline_color].rgba = Eigen::Vector4d(0.5, 0.25, 0, 1);
  m[inline_color].material = b.Ref(red_id, "red");
  m[inline_color].properties = {{"z/last", 1.0}, {"a/first", true}, {"a/first", false}};
  const GeometryId from_material =
      b.AddGeometry("material", link, ir::Sphere{1}, ir::kPerceptionRole);
  m[from_material].material = b.Ref(red_id, "red");
  m[from_material].properties = {{"renderer/accepting", std::vector<std::string>{"vtk", "gl"}}};
  const GeometryId collision = b.AddGeometry("collision", link, ir::Sphere{1}, ir::kProximityRole);
  m[collision].rgba = Eigen::Vector4d(0, 1, 0, 1);

  auto model = test_util::InstantiateOk(m);
  ASSERT_TRUE(model);
  const auto& g = model->scene.geometries;
  ASSERT_EQ(g.size(), 3u);
  ASSERT_EQ(g[0].properties.size(), 4u);  // sorted, one per key, last wins
  EXPECT_EQ(g[0].properties[0].key, "a/first");
  EXPECT_EQ(std::get<bool>(g[0].properties[0].value), false);
  EXPECT_EQ(g[0].properties[1].key, "phong/diffuse");
  EXPECT_EQ(std::get<std::vector<double>>(g[0].properties[1].value),
            (std::vector<double>{0.5, 0.25, 0, 1}));
  EXPECT_EQ(g[0].properties[2].key, "phong/diffuse_map");
  EXPECT_EQ(g[0].properties[3].key, "z/last");

  ASSERT_EQ(g[1].properties.size(), 3u);
  EXPECT_EQ(std::get<std::vector<double>>(g[1].properties[0].value),
            (std::vector<double>{1, 0, 0, 1}));
  EXPECT_EQ(g[1].properties[2].key, "renderer/accepting");
  EXPECT_EQ(std::get<std::vector<std::string>>(g[1].properties[2].value),
            (std::vector<std::string>{"gl", "vtk"}));

  EXPECT_TRUE(g[2].properties.empty());  // proximity only: no color
}

}  // namespace
}  // namespace mdlc::backend
