// Collision filter groups from the URDF frontend to plant-json: reference
// resolution (resolve-names), the definition rules (check-model-elements)
// and the excluded body pairs the backend derives (COMMON-050..055,
// EXT-040), compiled end to end.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tools/driver/compiler.h"
#include "passes/pass_registry.h"
#include "tests/unit/urdf_test_util.h"

namespace mdlc {
namespace {

using testing::Lowered;
using Pairs = std::set<std::pair<std::string, std::string>>;

// links with proximity geometry, unless the name starts with "bare"
std::string Links(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* name : names) {
    if (std::string_view(name).starts_with("bare")) {
      out += fmt::format("<link name='{}'/>\n", name);
    } else {
      out += fmt::format(
          "<link name='{}'><collision><geometry><sphere radius='0.1'/></geometry></collision>"
          "</link>\n",
          name);
    }
  }
  return out;
}

std::string Group(std::string_view name, std::initializer_list<const char*> members,
                  std::initializer_list<const char*> member_groups = {},
                  std::initializer_list<const char*> ignored = {}) {
  std::string out = fmt::format("<drake:collision_filter_group name='{}'>", name);
  for (const char* m : members) out += fmt::format("<drake:member link='{}'/>", m);
  for (const char* g : member_groups) out += fmt::format("<drake:member_group name='{}'/>", g);
  for (const char* g : ignored) {
    out += fmt::format("<drake:ignored_collision_filter_group name='{}'/>", g);
  }
  return out + "</drake:collision_filter_group>\n";
}

/// Compiles URDF texts (one model each) through frontends, passes and
/// backend, as `mdlc compile` does.
struct Compiled {
  Compilation c;
  bool ok = false;
  nlohmann::json json;

  explicit Compiled(std::initializer_list<std::string> texts) {
    frontend::FrontendContext ctx{c.sources, c.diags, c.module, c.options.frontend};
    int i = 0;
    for (const std::string& text : texts) {
      frontend::ReadUrdf(c.sources.AddBuffer(fmt::format("m{}.urdf", i++), text), ctx);
    }
    ok = !c.diags.has_errors() && c.RunPasses() && c.RunBackend();
    if (ok) {
      json = nlohmann::json::parse(
          backend::EmitPlantJson(*c.model, backend::DefaultPositions(c.model->plant)));
    }
  }
  Pairs Filters() const {
    Pairs out;
    for (const auto& pair : json["collision_filters"]) {
      out.emplace(pair[0].get<std::string>(), pair[1].get<std::string>());
    }
    return out;
  }
  std::string Messages() const {
    std::string out;
    for (const auto& d : c.diags.diagnostics()) out += d.message + "\n";
    return out;
  }
  bool Has(DiagKind kind, std::string_view text) const {
    for (const auto& d : c.diags.diagnostics()) {
      if (d.kind == kind && d.message.find(text) != std::string::npos) return true;
    }
    return false;
  }
};

std::string Robot(std::string_view name, std::string_view body) {
  return fmt::format("<robot name='{}'>\n{}</robot>", name, body);
}

// ----------------------------------------------------------- end to end

TEST(CollisionFilterGroupsTest, DrakesParsingTestModelGivesItsPairs) {  // COMMON-051, COMMON-052
  // the layout of Drake's collision_filter_group_parsing_test.urdf: free
  // bodies, so only the groups filter
  Compiled m({Robot("t", Links({"l1", "l2", "l3", "l4", "l5", "l6", "l7", "l8", "l9", "l10"}) +
                             Group("g14", {"l1", "l4"}, {}, {"g14"}) +
                             Group("g2", {"l2"}, {}, {"g3"}) +
                             "<drake:collision_filter_group ignore='true' name='g24'>"
                             "<drake:member link='l2'/><drake:member link='l4'/>"
                             "<drake:ignored_collision_filter_group name='g24'/>"
                             "</drake:collision_filter_group>\n" +
                             Group("g3", {"l3"}, {}, {"g14"}) +
                             Group("g56", {"l5", "l6"}, {}, {"g56", "g3", "g2"}) +
                             Group("g78", {"l7", "l8"}) + Group("g910", {"l9", "l10"}) +
                             Group("gg", {}, {"g78", "g910"}, {"gg"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  const Pairs expected = {
      {"t::l1", "t::l4"},                                            // g14 x g14
      {"t::l2", "t::l3"},                                            // g2 x g3
      {"t::l1", "t::l3"}, {"t::l3", "t::l4"},                        // g3 x g14
      {"t::l5", "t::l6"},                                            // g56 x g56
      {"t::l3", "t::l5"}, {"t::l3", "t::l6"},                        // g56 x g3
      {"t::l2", "t::l5"}, {"t::l2", "t::l6"},                        // g56 x g2
      {"t::l10", "t::l7"}, {"t::l10", "t::l8"}, {"t::l10", "t::l9"}, // gg x gg
      {"t::l7", "t::l8"}, {"t::l7", "t::l9"}, {"t::l8", "t::l9"},
  };
  EXPECT_EQ(m.Filters(), expected);
  // the list itself is sorted, each pair ordered (plant-json)
  std::vector<std::pair<std::string, std::string>> list;
  for (const auto& p : m.json["collision_filters"]) list.emplace_back(p[0], p[1]);
  EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
  EXPECT_EQ(list.size(), expected.size());
}

TEST(CollisionFilterGroupsTest, IgnoringAnotherGroupDoesNotFilterWithinEither) {  // COMMON-051
  Compiled m({Robot("r", Links({"a", "b", "c", "d"}) + Group("g", {"a", "b"}, {}, {"h"}) +
                             Group("h", {"c", "d"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::c"}, {"r::a", "r::d"}, {"r::b", "r::c"},
                                {"r::b", "r::d"}}));
}

TEST(CollisionFilterGroupsTest, MemberGroupsAreTransitive) {  // COMMON-052
  // outer <- middle <- inner: outer holds a, b and c
  Compiled m({Robot("r", Links({"a", "b", "c", "d"}) + Group("outer", {"a"}, {"middle"}, {"outer"}) +
                             Group("middle", {"b"}, {"inner"}) + Group("inner", {"c"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::b"}, {"r::a", "r::c"}, {"r::b", "r::c"}}));
}

TEST(CollisionFilterGroupsTest, CyclesOfMemberGroupsMerge) {  // COMMON-052
  // x and y name each other: both hold a and b; z (outside the cycle) holds c
  // and x's members, so z ignoring y filters c against a and b
  Compiled m({Robot("r", Links({"a", "b", "c", "d"}) + Group("x", {"a"}, {"y"}) +
                             Group("y", {"b"}, {"x"}, {"y"}) + Group("z", {"c"}, {"x"}, {"y"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::b"}, {"r::a", "r::c"}, {"r::b", "r::c"}}));
}

TEST(CollisionFilterGroupsTest, GroupsMayNameGroupsDefinedLater) {  // COMMON-055
  Compiled m({Robot("r", Group("first", {"a"}, {"second"}, {"third"}) +
                             Group("second", {"b"}) + Group("third", {"c"}) +
                             Links({"a", "b", "c"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::c"}, {"r::b", "r::c"}}));
}

TEST(CollisionFilterGroupsTest, BodiesWithoutProximityGeometryAreNotListed) {  // plant-json
  Compiled m({Robot("r", Links({"a", "bare", "c"}) + Group("g", {"a", "bare", "c"}, {}, {"g"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::c"}}));
}

TEST(CollisionFilterGroupsTest, GroupPairsJoinTheAdjacencyFilter) {  // COMMON-051, COMMON-054
  Compiled m({Robot("r", Links({"a", "b", "c"}) +
                             "<joint name='j1' type='revolute'><parent link='a'/>"
                             "<child link='b'/></joint>\n"
                             "<joint name='j2' type='revolute'><parent link='b'/>"
                             "<child link='c'/></joint>\n" +
                             Group("ends", {"a", "c", "b"}, {}, {"ends"}))});
  ASSERT_TRUE(m.ok) << m.Messages();
  // a-b and b-c are adjacent anyway; the group adds a-c; no duplicates
  EXPECT_EQ(m.Filters(), (Pairs{{"r::a", "r::b"}, {"r::a", "r::c"}, {"r::b", "r::c"}}));
  EXPECT_EQ(m.json["collision_filters"].size(), 3u);
}

TEST(CollisionFilterGroupsTest, GroupsAreScopedByModelInstance) {  // COMMON-050, COMMON-053
  // two models may both define group g; each names its own links
  const std::string model = Links({"a", "b"}) + Group("g", {"a", "b"}, {}, {"g"});
  Compiled m({Robot("one", model), Robot("two", model)});
  ASSERT_TRUE(m.ok) << m.Messages();
  EXPECT_EQ(m.Filters(), (Pairs{{"one::a", "one::b"}, {"two::a", "two::b"}}));
}

// ----------------------------------------------------------- errors

TEST(CollisionFilterGroupsTest, UnknownMemberIsNotFound) {  // COMMON-053
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("r", Links({"arm", "hand"}) + Group("g", {"arm", "hnad"}))));
  EXPECT_FALSE(l.RunPasses());
  ASSERT_EQ(l.diags.error_count(), 1u) << l.Messages();
  const Diagnostic& d = l.diags.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::UnknownReference);
  EXPECT_NE(d.message.find("body with name 'r::hnad' not found"), std::string::npos) << d.message;
  l.ExpectDiagnostic(DiagKind::UnknownReference, "body with name 'r::hnad' not found");
  EXPECT_EQ(d.loc.line, 4u);  // the group's line, at the member's link attribute
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'hand'?");
}

TEST(CollisionFilterGroupsTest, UnknownGroupIsNotFound) {  // COMMON-053
  for (const std::string& group : {Group("g", {"a"}, {"nope"}), Group("g", {"a"}, {}, {"nope"})}) {
    Lowered l;
    ASSERT_TRUE(l.Read(Robot("r", Links({"a"}) + group)));
    EXPECT_FALSE(l.RunPasses());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference,
                                "collision filter group with name 'r::nope' not found"))
        << l.Messages();
  }
}

TEST(CollisionFilterGroupsTest, MembersAreLookedUpInTheGroupsOwnModelOnly) {  // COMMON-053
  // a URDF group cannot name another model's link, nor the world body
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("one", Links({"a"}))));
  ASSERT_TRUE(l.Read(Robot("two", Links({"b"}) + Group("g", {"b", "a", "one::a", "world"}))));
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "'two::a' not found")) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "'two::one::a' not found"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "'two::world' not found"));
  EXPECT_EQ(l.diags.error_count(), 3u) << l.Messages();
}

TEST(CollisionFilterGroupsTest, ScopedNamesReachNestedInstances) {  // COMMON-030, COMMON-053
  // group of "r" naming "sub::x" finds body x of instance "r::sub"
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("r", Links({"a"}) + Group("g", {"a", "sub::x"}, {"sub::h"}))));
  ir::Module& m = l.module;
  const ModelId sub = m.Add(ir::ModelInstance{m.Intern("r::sub"), {}, ir::SourceFormat::Internal, {}, {}});
  ir::Body x;
  x.name = m.Intern("x");
  x.model = sub;
  const BodyId x_id = m.Add(x);
  ir::Joint free;  // keep the tree valid
  free.name = m.Intern("x_free");
  free.model = sub;
  free.type = ir::JointType::QuaternionFloating;
  free.parent = {m.Intern("world"), {}, ir::kWorldBody};
  free.child = {m.Intern("x"), {}, x_id};
  free.limits.lower.assign(6, -std::numeric_limits<double>::infinity());
  free.limits.upper.assign(6, std::numeric_limits<double>::infinity());
  free.damping.assign(6, 0.0);
  m.Add(free);
  ir::CollisionFilterGroup h;
  h.name = m.Intern("h");
  h.model = sub;
  h.members.push_back({m.Intern("x"), {}, {}});
  const FilterGroupId h_id = m.Add(h);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  const ir::CollisionFilterGroup& g = m.filter_groups[0];
  EXPECT_EQ(g.members[1].id, x_id);
  EXPECT_EQ(g.member_groups[0].id, h_id);
}

TEST(CollisionFilterGroupsTest, GlobalGroupsNameTopLevelInstances) {  // COMMON-053 (directives)
  // a group of the default instance (model directives' global scope) names
  // "model::link"
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("arm", Links({"a", "b"}))));
  ir::Module& m = l.module;
  ir::CollisionFilterGroup g;
  g.name = m.Intern("g");
  g.model = ir::kDefaultModel;
  g.members.push_back({m.Intern("arm::a"), {}, {}});
  g.members.push_back({m.Intern("arm::b"), {}, {}});
  g.ignored_groups.push_back({m.Intern("g"), {}, {}});
  m.Add(g);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_EQ(m.Text(m[m.filter_groups[0].members[1].id].name), "b");
  EXPECT_EQ(m.filter_groups[0].ignored_groups[0].id, FilterGroupId(uint32_t{0}));
}

TEST(CollisionFilterGroupsTest, ScopedGroupNameIsAnError) {  // COMMON-050
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("r", Links({"a"}) + Group("x::g", {"a"}))));
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::InvalidName, "'r::x::g' cannot be a scoped name"))
      << l.Messages();
}

TEST(CollisionFilterGroupsTest, DuplicateGroupIsAnError) {  // COMMON-050
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("r", Links({"a", "b"}) + Group("g", {"a"}) + Group("g", {"b"}))));
  EXPECT_FALSE(l.RunPasses());
  ASSERT_EQ(l.diags.error_count(), 1u) << l.Messages();
  const Diagnostic& d = l.diags.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::DuplicateName);
  EXPECT_NE(d.message.find("group 'r::g' has already been defined"), std::string::npos);
  l.ExpectDiagnostic(DiagKind::DuplicateName, "group 'r::g' has already been defined");
  EXPECT_EQ(d.loc.line, 5u);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 4u);
}

TEST(CollisionFilterGroupsTest, GroupWithoutMembersIsAnError) {  // COMMON-050
  Lowered l;
  // ignored groups are not members
  ASSERT_TRUE(l.Read(Robot("r", Links({"a"}) + Group("h", {"a"}) + Group("g", {}, {}, {"h"}))));
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "group 'r::g' has no members")) << l.Messages();
  // a group whose only members are groups is fine
  Lowered ok;
  ASSERT_TRUE(ok.Read(Robot("r", Links({"a"}) + Group("h", {"a"}) + Group("g", {}, {"h"}))));
  EXPECT_TRUE(ok.RunPasses()) << ok.Messages();
}

TEST(CollisionFilterGroupsTest, CheckPassIsRegisteredAfterResolveNames) {
  bool resolve_seen = false;
  for (const auto& info : passes::RegisteredPasses()) {
    if (info.name == "resolve-names") resolve_seen = true;
    if (info.name == "check-model-elements") {
      EXPECT_TRUE(resolve_seen);
      return;
    }
  }
  ADD_FAILURE() << "check-model-elements is not registered";
}

// ----------------------------------------------------------- constraints and forces

TEST(DrakeElementsScopeTest, ReferencesStayInTheElementsModel) {  // EXT-050..054
  // resolve-names finds "one::a" as a top-level instance's link, but a URDF
  // element may only name its own model's entities (Drake looks them up in
  // the element's instance); the world body is allowed (COMMON-032)
  Lowered l;
  ASSERT_TRUE(l.Read(Robot("one", Links({"a"}) +
                                      "<joint name='j' type='revolute'><parent link='a'/>"
                                      "<child link='bare'/></joint><link name='bare'/>"
                                      "<frame name='f' link='a'/>")));
  ASSERT_TRUE(l.Read(Robot("two", Links({"b"}) + R"(
<drake:ball_constraint>
  <drake:ball_constraint_body_A name='b'/><drake:ball_constraint_body_B name='one::a'/>
  <drake:ball_constraint_p_AP value='0 0 0'/><drake:ball_constraint_p_BQ value='0 0 0'/>
</drake:ball_constraint>
<drake:distance_constraint>
  <drake:distance_constraint_body_A name='b'/><drake:distance_constraint_p_AP value='0 0 0'/>
  <drake:distance_constraint_body_B name='world'/><drake:distance_constraint_p_BQ value='0 0 1'/>
  <drake:distance_constraint_distance value='1'/><drake:distance_constraint_stiffness value='1'/>
  <drake:distance_constraint_damping value='1'/>
</drake:distance_constraint>
<drake:tendon_constraint><drake:tendon_constraint_joint name='one::j' a='1'/>
  <drake:tendon_constraint_upper_limit value='1'/></drake:tendon_constraint>
<drake:linear_bushing_rpy>
  <drake:bushing_frameA name='b'/><drake:bushing_frameC name='one::f'/>
  <drake:bushing_torque_stiffness value='1 1 1'/><drake:bushing_torque_damping value='1 1 1'/>
  <drake:bushing_force_stiffness value='1 1 1'/><drake:bushing_force_damping value='1 1 1'/>
</drake:linear_bushing_rpy>
<drake:linear_spring_damper>
  <drake:linear_spring_damper_body_A name='one::a'/><drake:linear_spring_damper_p_AP value='0 0 0'/>
  <drake:linear_spring_damper_body_B name='b'/><drake:linear_spring_damper_p_BQ value='0 0 0'/>
  <drake:linear_spring_damper_free_length value='1'/>
  <drake:linear_spring_damper_stiffness value='1'/><drake:linear_spring_damper_damping value='1'/>
</drake:linear_spring_damper>
)")));
  EXPECT_FALSE(l.RunPasses());
  EXPECT_EQ(l.diags.error_count(), 4u) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference,
                              "body 'one::a' belongs to model instance 'one': it must be in the "
                              "element's own model instance 'two'"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "joint 'one::j' belongs to model"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "frame 'one::f' belongs to model"));
  EXPECT_FALSE(l.HasDiagnostic(DiagKind::UnknownReference, "'world'"));
}

// ----------------------------------------------------------- constraints and forces in plant-json

TEST(DrakeElementsPlantJsonTest, ConstraintsAndForceElementsAreDumped) {  // EXT-050..054
  Compiled m({Robot("r", Links({"a", "b", "c"}) + R"(
<joint name='j1' type='revolute'><parent link='a'/><child link='b'/></joint>
<joint name='j2' type='prismatic'><parent link='b'/><child link='c'/></joint>
<frame name='fa' link='a' xyz='0 0 1'/>
<drake:linear_bushing_rpy>
  <drake:bushing_frameA name='fa'/><drake:bushing_frameC name='c'/>
  <drake:bushing_torque_stiffness value='1 2 3'/><drake:bushing_torque_damping value='4 5 6'/>
  <drake:bushing_force_stiffness value='7 8 9'/><drake:bushing_force_damping value='10 11 12'/>
</drake:linear_bushing_rpy>
<drake:linear_spring_damper>
  <drake:linear_spring_damper_body_A name='a'/><drake:linear_spring_damper_p_AP value='1 2 3'/>
  <drake:linear_spring_damper_body_B name='c'/><drake:linear_spring_damper_p_BQ value='4 5 6'/>
  <drake:linear_spring_damper_free_length value='7'/>
  <drake:linear_spring_damper_stiffness value='8'/><drake:linear_spring_damper_damping value='9'/>
</drake:linear_spring_damper>
<drake:ball_constraint>
  <drake:ball_constraint_body_A name='a'/><drake:ball_constraint_body_B name='c'/>
  <drake:ball_constraint_p_AP value='0 0 1'/><drake:ball_constraint_p_BQ value='0 0 -1'/>
</drake:ball_constraint>
<drake:distance_constraint>
  <drake:distance_constraint_body_A name='a'/><drake:distance_constraint_p_AP value='1 0 0'/>
  <drake:distance_constraint_body_B name='b'/><drake:distance_constraint_p_BQ value='0 1 0'/>
  <drake:distance_constraint_distance value='0.5'/>
  <drake:distance_constraint_stiffness value='inf'/>
  <drake:distance_constraint_damping value='2'/>
</drake:distance_constraint>
<drake:tendon_constraint>
  <drake:tendon_constraint_joint name='j1' a='1'/><drake:tendon_constraint_joint name='j2' a='-2'/>
  <drake:tendon_constraint_lower_limit value='-0.5'/>
</drake:tendon_constraint>
)")});
  ASSERT_TRUE(m.ok) << m.Messages();
  using nlohmann::json;
  const json& constraints = m.json["constraints"];
  ASSERT_EQ(constraints.size(), 3u) << constraints.dump();
  EXPECT_EQ(constraints[0], json::parse(R"({"type": "ball", "model_instance": "r",
      "body_A": "r::a", "body_B": "r::c", "p_AP": [0, 0, 1], "p_BQ": [0, 0, -1]})"));
  EXPECT_EQ(constraints[1], json::parse(R"({"type": "distance", "model_instance": "r",
      "body_A": "r::a", "body_B": "r::b", "p_AP": [1, 0, 0], "p_BQ": [0, 1, 0],
      "distance": 0.5, "stiffness": null, "damping": 2})"));
  EXPECT_EQ(constraints[2], json::parse(R"({"type": "tendon", "model_instance": "r",
      "joints": ["r::j1", "r::j2"], "a": [1, -2], "offset": 0, "lower": -0.5, "upper": null,
      "stiffness": null, "damping": 0})"));
  const json& forces = m.json["force_elements"];
  ASSERT_EQ(forces.size(), 2u) << forces.dump();
  EXPECT_EQ(forces[0], json::parse(R"({"type": "linear_bushing_rpy", "frameA": "r::fa",
      "frameC": "r::c", "torque_stiffness": [1, 2, 3], "torque_damping": [4, 5, 6],
      "force_stiffness": [7, 8, 9], "force_damping": [10, 11, 12]})"));
  EXPECT_EQ(forces[1], json::parse(R"({"type": "linear_spring_damper", "body_A": "r::a",
      "p_AP": [1, 2, 3], "body_B": "r::c", "p_BQ": [4, 5, 6], "free_length": 7,
      "stiffness": 8, "damping": 9})"));
}

}  // namespace
}  // namespace mdlc
