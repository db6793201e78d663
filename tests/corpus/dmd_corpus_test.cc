// The corpus Model Directives, compiled with the corpus as the package path:
// every scene whose files are all present compiles; the broken ones (a
// missing file, an unknown package) and the fragments meant to be pulled in
// by add_directives fail with a located error, and the fragments' parents
// compile with what the fragments add. Then the facts Drake's own
// process_model_directives_test.cc checks on the same files, checked on
// mdlc's plant-json. The table must cover every directives file of the
// manifest, so a new corpus file cannot slip by.
//
// Skipped (reported as skipped) when ../shared is absent.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <set>
#include <string>

#include "../oracle/oracle_util.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path Corpus() { return fs::path(MDLC_SHARED_DIR) / "corpus"; }
constexpr const char* kTestDir = "drake/multibody/parsing/test/process_model_directives_test/";

struct Expectation {
  const char* path;        // relative to corpus/
  bool accepted;           // does mdlc compile it?
  const char* keyword;     // rejected: a word the error must contain
  const char* located_in;  // rejected: the file the error is located in ("" = `path`)
  const char* why;
};

// clang-format off
constexpr Expectation kExpectations[] = {
  {"drake/manipulation/kuka_iiwa/test/iiwa7_wsg_renamed_weld_frames.dmd.yaml", true, "", "",
   "DMD-030, DMD-040: frames on the arm, the gripper welded to one"},
  {"drake/manipulation/util/test/iiwa7_wsg.dmd.yaml", true, "", "",
   "COMMON-033: an unscoped base frame (iiwa_link_7) unique across instances"},
  {"drake/manipulation/util/test/iiwa7_wsg_cameras.dmd.yaml", true, "", "",
   "DMD-060: add_directives without a namespace; welds to SDFormat __model__ frames"},
  {"drake/manipulation/util/test/panda_arm_and_hand.dmd.yaml", true, "", "",
   "DMD-040: a weld with X_PC"},
  {"drake/multibody/parsing/test/process_model_directives_test/acrobot.dmd.yaml", false,
   "cannot read the included file", ".xml",
   "COMMON-011: the dm_control acrobot it loads includes ./common/*.xml, not in the corpus"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_backreference.dmd.yaml", false,
   "no frame named 'simple_model_origin'", "",
   "a fragment: test_backreferences.dmd.yaml adds the frame it welds to"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_frame_without_model_namespace.dmd.yaml",
   true, "", "", "DMD-030: unscoped frames land in their base frame's instance"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_mid.dmd.yaml", true, "", "",
   "DMD-060: nested namespaces"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_sub.dmd.yaml", true, "", "",
   "DMD-030, DMD-050: also loads on its own"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_top.dmd.yaml", true, "", "",
   "DMD-060, DMD-062: one fragment in four namespaces"},
  {"drake/multibody/parsing/test/process_model_directives_test/bad_package_uri.dmd.yaml", false,
   "unknown package 'nonexistent'", "", "DMD-002, COMMON-011: deliberately broken"},
  {"drake/multibody/parsing/test/process_model_directives_test/collision_filter_group.dmd.yaml", true,
   "", "", "DMD-050: groups across models and namespaces, groups of groups"},
  {"drake/multibody/parsing/test/process_model_directives_test/deep_child_frame_weld.dmd.yaml", true,
   "", "",
   "DMD-040: the child is a frame of a nested SDFormat instance. Drake trips an internal check "
   "of its ModelInstanceInfo bookkeeping (\"condition 'found' failed\") here; the plant itself "
   "is well defined, and mdlc builds it"},
  {"drake/multibody/parsing/test/process_model_directives_test/deep_child_weld.dmd.yaml", true,
   "", "", "DMD-040: the child is a body of a nested SDFormat instance (as above)"},
  {"drake/multibody/parsing/test/process_model_directives_test/default_positions.dmd.yaml", true,
   "", "", "DMD-011, DMD-012: default joint positions and free body poses"},
  {"drake/multibody/parsing/test/process_model_directives_test/flattened.dmd.yaml", true, "", "",
   "DMD-050: namespaced filter groups (model_namespace)"},
  {"drake/multibody/parsing/test/process_model_directives_test/inject_frames.dmd.yaml", true, "", "",
   "DMD-030, DMD-040: frames injected into models, welds chained through them"},
  {"drake/multibody/parsing/test/process_model_directives_test/sub_collision.dmd.yaml", true, "", "",
   "DMD-050: also loads on its own"},
  {"drake/multibody/parsing/test/process_model_directives_test/test_backreferences.dmd.yaml", true,
   "", "", "DMD-060: a fragment naming frames its parent added"},
  {"drake/multibody/parsing/test/process_model_directives_test/unflattened_arm.dmd.yaml", true, "",
   "", "DMD-050: also loads on its own"},
  {"drake/multibody/parsing/test/process_model_directives_test/unflattened_top.dmd.yaml", true, "",
   "", "DMD-060: the same arm in two namespaces"},
  {"drake/systems/sensors/test/rgbd_sensor_async_gl_test.dmd.yaml", true, "", "",
   "DMD-012: free bodies posed in the world"},
  {"drake_models/tri_homecart/homecart.dmd.yaml", true, "", "",
   "DMD-060: two fragments, the second using the first's instances"},
  {"drake_models/tri_homecart/homecart_grippers.dmd.yaml", false,
   "no model instance named 'ur3_left'", "",
   "a fragment: homecart.dmd.yaml adds the arms it mounts grippers on"},
  {"drake_models/tri_homecart/homecart_no_grippers.dmd.yaml", true, "", "",
   "DMD-030, DMD-040: a cart, two arms and a board on frames"},
  {"drake_models/tutorials/models/furnished_living_room.dmd.yaml", true, "", "",
   "DMD-040: furniture welded to the world with X_PC"},
};
// clang-format on

void PrintTo(const Expectation& e, std::ostream* os) { *os << e.path; }

mdlc::oracle::RunResult Compile(const std::string& path, const std::string& emit) {
  return mdlc::oracle::RunProcess({MDLC_BINARY, "compile", (Corpus() / path).string(),
                                   "--package-path", Corpus().string(), "--emit=" + emit},
                                  60);
}

// The plant of a corpus scene that must compile.
json Plant(const std::string& path) {
  auto r = Compile(path, "plant-json");
  EXPECT_EQ(r.exit_code, 0) << path << "\n" << r.err;
  if (r.exit_code != 0) return json::object();
  return json::parse(r.out);
}

const json* Find(const json& plant, const char* table, const std::string& instance,
                 const std::string& name) {
  if (!plant.contains(table)) return nullptr;
  for (const json& e : plant[table]) {
    if (e["model_instance"] == instance && e["name"] == name) return &e;
  }
  return nullptr;
}

Eigen::Isometry3d Pose(const json& X) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(X["q"][0], X["q"][1], X["q"][2], X["q"][3]).toRotationMatrix();
  T.translation() = Eigen::Vector3d(X["p"][0], X["p"][1], X["p"][2]);
  return T;
}

// X_WF of frame `name` of `instance`: its body's pose composed with X_BF
std::optional<Eigen::Isometry3d> FrameInWorld(const json& plant, const std::string& instance,
                                              const std::string& name) {
  const json* frame = Find(plant, "frames", instance, name);
  if (!frame) return std::nullopt;
  const std::string body = (*frame)["body"];
  if (body == "world") return Pose((*frame)["X_BF"]);
  const size_t split = body.rfind("::");
  const json* b = Find(plant, "bodies", body.substr(0, split), body.substr(split + 2));
  if (!b) return std::nullopt;
  return Pose((*b)["X_WB"]) * Pose((*frame)["X_BF"]);
}

class DmdCorpus : public ::testing::TestWithParam<Expectation> {};

TEST_P(DmdCorpus, MdlcFollowsDrake) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  const Expectation& e = GetParam();
  const auto r = Compile(e.path, "none");
  if (e.accepted) {
    EXPECT_EQ(r.exit_code, 0) << e.path << " (" << e.why << ")\n" << r.err;
    return;
  }
  EXPECT_EQ(r.exit_code, 1) << e.path << " (" << e.why << ")\n" << r.err;
  EXPECT_NE(r.err.find(e.keyword), std::string::npos) << e.path << "\n" << r.err;
  // located: "FILE:LINE:COL: error: ...KEYWORD"
  const std::string file = *e.located_in ? e.located_in : fs::path(e.path).filename().string();
  const std::regex located(".*" + std::regex_replace(file, std::regex(R"([.])"), R"(\.)") +
                           R"(:\d+:\d+: error: .*)");
  bool found = false;
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);) {
    found = found || (std::regex_match(line, located) && line.find(e.keyword) != std::string::npos);
  }
  EXPECT_TRUE(found) << "no located error with '" << e.keyword << "' in " << file << ":\n" << r.err;
}

std::string CaseName(const ::testing::TestParamInfo<Expectation>& info) {
  std::string name = fs::path(info.param.path).stem().stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Corpus, DmdCorpus, ::testing::ValuesIn(kExpectations), CaseName);

TEST(DmdCorpusTable, CoversEveryDirectivesFile) {
  auto rows = mdlc::oracle::ReadManifest(Corpus() / "manifest.tsv");
  if (!rows) GTEST_SKIP() << "shared corpus not found";
  std::set<std::string> listed;
  for (const auto& e : kExpectations) listed.insert(e.path);
  size_t seen = 0;
  for (const auto& cols : *rows) {
    if (cols.size() < 2 || cols[0] != "dmd") continue;
    ++seen;
    EXPECT_TRUE(listed.count(cols[1])) << "no expectation for " << cols[1];
  }
  EXPECT_EQ(seen, std::size(kExpectations));
}

// ----------------------------------------------------- Drake's expectations

class DmdDrakeFacts : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  }
};

// The fragments compile through their parents (DMD-060): what
// add_backreference adds, Drake's TestBackreferences checks.
TEST_F(DmdDrakeFacts, FragmentsCompileThroughTheirParents) {
  const json refs = Plant(std::string(kTestDir) + "test_backreferences.dmd.yaml");
  for (const char* instance : {"simple_model", "nested::simple_model"}) {
    const json* weld = Find(refs, "joints", instance, "simple_model_origin_welds_to_base");
    ASSERT_TRUE(weld) << instance;
    EXPECT_EQ((*weld)["type"], "weld");
  }
  const json cart = Plant("drake_models/tri_homecart/homecart.dmd.yaml");
  for (const char* side : {"left", "right"}) {
    const std::string gripper = std::string("gripper_") + side;
    const json* weld = Find(cart, "joints", gripper, gripper + "_origin_welds_to_body");
    ASSERT_TRUE(weld) << gripper;
    EXPECT_EQ((*weld)["parent"], std::string("ur3_") + side + "::ur_ee_link");
    // DMD-030: an unscoped add_frame lands in its base frame's instance
    EXPECT_TRUE(Find(cart, "frames", std::string("ur3_") + side, gripper + "_origin"));
    EXPECT_TRUE(Find(cart, "frames", gripper, "grasp_frame"));
  }
}

// Drake's AddScopedSmokeTest (DMD-060, DMD-062).
TEST_F(DmdDrakeFacts, ScopedFramesLandInTheirInstances) {
  const json plant = Plant(std::string(kTestDir) + "add_scoped_top.dmd.yaml");
  auto has_frame_or_body = [&](const std::string& instance, const std::string& name) {
    return Find(plant, "frames", instance, name) || Find(plant, "bodies", instance, name);
  };
  for (std::string prefix : {"", "left::", "right::", "mid::nested::"}) {
    for (const char* frame : {"base", "frame", "sub_added_frame", "top_added_frame"}) {
      EXPECT_TRUE(has_frame_or_body(prefix + "simple_model", frame)) << prefix << frame;
    }
    for (const char* frame : {"base", "frame"}) {
      EXPECT_TRUE(has_frame_or_body(prefix + "extra_model", frame)) << prefix << frame;
    }
  }
  for (const char* ns : {"left", "right", "mid::nested"}) {
    EXPECT_TRUE(Find(plant, "frames", ns, "simple_model_test_frame")) << ns;
  }
  EXPECT_TRUE(Find(plant, "frames", "simple_model", "simple_model_test_frame"));
}

// Drake's AddFrameWithoutScope (DMD-030, COMMON-032).
TEST_F(DmdDrakeFacts, UnscopedFramesJoinTheirBaseFramesInstance) {
  const json plant = Plant(std::string(kTestDir) + "add_frame_without_model_namespace.dmd.yaml");
  EXPECT_TRUE(Find(plant, "frames", "WorldModelInstance", "world_as_base_frame"));
  EXPECT_TRUE(Find(plant, "frames", "simple_model", "included_as_base_frame"));
}

// Drake's InjectFrames (DMD-030, DMD-040, DMD-070).
TEST_F(DmdDrakeFacts, InjectedFramesPlaceWeldedModels) {
  const json plant = Plant(std::string(kTestDir) + "inject_frames.dmd.yaml");
  const auto top_frame = FrameInWorld(plant, "top_level_model", "top_injected_frame");
  const auto mid_frame = FrameInWorld(plant, "mid_level_model", "mid_injected_frame");
  ASSERT_TRUE(top_frame && mid_frame);
  EXPECT_TRUE(top_frame->translation().isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  EXPECT_TRUE(mid_frame->translation().isApprox(Eigen::Vector3d(2, 4, 6), 1e-12));
  const json* mid = Find(plant, "bodies", "mid_level_model", "base");
  const json* bottom = Find(plant, "bodies", "bottom_level_model", "base");
  ASSERT_TRUE(mid && bottom);
  EXPECT_TRUE(Pose((*mid)["X_WB"]).translation().isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  EXPECT_TRUE(Pose((*bottom)["X_WB"]).translation().isApprox(Eigen::Vector3d(6, 9, 12), 1e-12));
  EXPECT_TRUE(Find(plant, "joints", "bottom_level_model", "mid_injected_frame_welds_to_base"));
}

// Drake's DefaultPositions (DMD-011, DMD-012, DMD-013).
TEST_F(DmdDrakeFacts, DefaultPositionsAndFreeBodyPoses) {
  const json plant = Plant(std::string(kTestDir) + "default_positions.dmd.yaml");
  constexpr double kDeg = std::numbers::pi / 180;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(7 * kDeg, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(6 * kDeg, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(5 * kDeg, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  for (const char* instance : {"simple_model", "simple_model_again"}) {
    const json* base = Find(plant, "bodies", instance, "base");
    ASSERT_TRUE(base) << instance;
    const Eigen::Isometry3d X_WB = Pose((*base)["X_WB"]);
    EXPECT_TRUE(X_WB.linear().isApprox(R, 1e-14)) << instance;
    EXPECT_TRUE(X_WB.translation().isApprox(Eigen::Vector3d(1, 2, 3), 1e-14)) << instance;
  }
  const json* shoulder = Find(plant, "joints", "joint_parsing_test", "ShoulderJoint");
  const json* elbow = Find(plant, "joints", "joint_parsing_test", "ElbowJoint");
  ASSERT_TRUE(shoulder && elbow);
  EXPECT_EQ((*shoulder)["default_positions"], json({0.1}));
  EXPECT_EQ((*elbow)["default_positions"], json({0.2}));
}

// Drake's CollisionFilterGroupSmokeTest (DMD-050): exactly these body pairs
// (each body has one collision geometry; the free bodies add no others).
TEST_F(DmdDrakeFacts, CollisionFilterGroupsAcrossModelsAndNamespaces) {
  const json plant = Plant(std::string(kTestDir) + "collision_filter_group.dmd.yaml");
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"model1::base", "model2::base"},
      {"model1::base", "nested::sub_model2::base"},
      {"model3::base", "nested::sub_model1::base"},
      {"model3::base", "nested::sub_model2::base"},
      {"model4::base", "model5::base"},
      {"model4::base", "model6::base"},
      {"model4::base", "model7::base"},
      {"model5::base", "model6::base"},
      {"model5::base", "model7::base"},
      {"model6::base", "model7::base"},
      {"nested::sub_model1::base", "nested::sub_model2::base"},
  };
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(plant["collision_filters"].get<Pairs>(), expected);
}

// Drake's Flatten and FlattenCollisionGroups: the unflattened scene and its
// hand-flattened twin give the same plant.
TEST_F(DmdDrakeFacts, FlattenedAndUnflattenedScenesAgree) {
  const json deep = Plant(std::string(kTestDir) + "unflattened_top.dmd.yaml");
  const json flat = Plant(std::string(kTestDir) + "flattened.dmd.yaml");
  std::set<std::string> deep_instances(deep["model_instances"].begin(), deep["model_instances"].end());
  std::set<std::string> flat_instances(flat["model_instances"].begin(), flat["model_instances"].end());
  EXPECT_EQ(deep_instances, flat_instances);
  for (const char* table : {"bodies", "frames", "joints"}) {
    std::map<std::string, json> by_name;
    for (const json& e : deep[table]) {
      by_name[e["model_instance"].get<std::string>() + "::" + e["name"].get<std::string>()] = e;
    }
    ASSERT_EQ(by_name.size(), flat[table].size()) << table;
    for (const json& e : flat[table]) {
      const std::string key = e["model_instance"].get<std::string>() + "::" + e["name"].get<std::string>();
      ASSERT_TRUE(by_name.count(key)) << table << " " << key;
      EXPECT_EQ(by_name[key], e) << table << " " << key;
    }
  }
  EXPECT_EQ(deep["collision_filters"], flat["collision_filters"]);
}

// Drake's WeldOffset (DMD-040): the hand is welded at X_PC = Rz(-45 deg).
TEST_F(DmdDrakeFacts, WeldOffsetPlacesTheChild) {
  const json plant = Plant("drake/manipulation/util/test/panda_arm_and_hand.dmd.yaml");
  const json* hand = Find(plant, "bodies", "panda_hand", "panda_hand");
  const json* link8_body = Find(plant, "bodies", "panda", "panda_link8");
  ASSERT_TRUE(hand && link8_body);
  const Eigen::Isometry3d expected =
      Pose((*link8_body)["X_WB"]) *
      Eigen::Isometry3d(Eigen::AngleAxisd(-std::numbers::pi / 4, Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(Pose((*hand)["X_WB"]).isApprox(expected, 1e-12));
  const json* weld = Find(plant, "joints", "panda_hand", "panda_link8_welds_to_panda_hand");
  ASSERT_TRUE(weld);
  EXPECT_EQ((*weld)["parent"], "panda::panda_link8");
}

}  // namespace
