// The corpus Model Directives (.dmd.yaml), compiled with the corpus as the
// package path, judged against Drake.
//
// 1. Every `dmd` row of the manifest: the scene compiles, or (a missing
//    include, an unknown package, a fragment meant to be pulled in by
//    add_directives) fails with a located error `FILE:LINE:COL: error: ...`.
//    Fragments are also checked through their parents: the parent compiles
//    and holds what the fragment adds. The table must cover every directives
//    file of the manifest, so a new corpus file cannot slip by.
// 2. The facts Drake's own multibody/parsing/test/process_model_directives_test.cc
//    checks on these files, checked on mdlc's plant-json (instance names,
//    frames in the right instance at the right pose, weld joints named
//    `{parent}_welds_to_{child}` in the child's instance, default positions,
//    collision filter pairs, flattened = unflattened), with the poses
//    recomputed by hand from the model files.
//
// Features: DMD-001..DMD-070, COMMON-022 (namespaced instance names),
// COMMON-032 (`world` inside a namespace), COMMON-033 (scoped frame lookup).
//
// Skipped (reported as skipped) when ../shared is absent.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../oracle/oracle_util.h"
#include "shared_corpus.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

using mdlc::corpus_test::Corpus;
using mdlc::corpus_test::HaveCorpus;

// Drake's process_model_directives_test data, relative to corpus/
const std::string kTestDir = "drake/multibody/parsing/test/process_model_directives_test/";

// ------------------------------------------------------------ the table

struct Expectation {
  const char* path;        // relative to corpus/
  bool accepted;           // does mdlc compile it?
  const char* keyword;     // rejected: the located error must contain this
  const char* located_in;  // rejected: file name the error is located in ("" = `path`)
  int line;                // rejected: the line it is located at
  const char* why;
};

// clang-format off
constexpr Expectation kExpectations[] = {
  {"drake/manipulation/kuka_iiwa/test/iiwa7_wsg_renamed_weld_frames.dmd.yaml", true, "", "", 0,
   "DMD-030, DMD-040: frames on the arm, the gripper welded to one"},
  {"drake/manipulation/util/test/iiwa7_wsg.dmd.yaml", true, "", "", 0,
   "COMMON-033: an unscoped base frame (iiwa_link_7) unique across instances"},
  {"drake/manipulation/util/test/iiwa7_wsg_cameras.dmd.yaml", true, "", "", 0,
   "DMD-060: add_directives without a namespace; welds to SDFormat __model__ frames"},
  {"drake/manipulation/util/test/panda_arm_and_hand.dmd.yaml", true, "", "", 0,
   "DMD-040: a weld with X_PC (Drake's WeldOffset)"},
  {"drake/multibody/parsing/test/process_model_directives_test/acrobot.dmd.yaml", false,
   "cannot read the included file", "acrobot.xml", 9,
   "COMMON-011: the dm_control acrobot.xml it loads includes ./common/*.xml, not in the corpus"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_backreference.dmd.yaml", false,
   "no frame named 'simple_model_origin'", "", 8,
   "a fragment: test_backreferences.dmd.yaml adds the frame it welds to (unknown frame standalone)"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_frame_without_model_namespace.dmd.yaml",
   true, "", "", 0, "DMD-030: unscoped frames land in their base frame's instance"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_mid.dmd.yaml", true, "", "", 0,
   "DMD-020, DMD-060: nested namespaces"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_sub.dmd.yaml", true, "", "", 0,
   "DMD-030, DMD-040, DMD-050 (Drake's BasicSmokeTest)"},
  {"drake/multibody/parsing/test/process_model_directives_test/add_scoped_top.dmd.yaml", true, "", "", 0,
   "DMD-060, DMD-062: one fragment in four namespaces (Drake's AddScopedSmokeTest)"},
  {"drake/multibody/parsing/test/process_model_directives_test/bad_package_uri.dmd.yaml", false,
   "unknown package 'nonexistent'", "", 4,
   "DMD-002, COMMON-011: deliberately broken (Drake's ErrorMessages)"},
  {"drake/multibody/parsing/test/process_model_directives_test/collision_filter_group.dmd.yaml", true,
   "", "", 0, "DMD-050: groups across models and namespaces, groups of groups"},
  // KNOWN DISAGREEMENT (deliberate, not an mdlc bug): Drake's DeepNestedChildFrameWelds
  // expects ProcessModelDirectives to throw "Failure at ... in AddWeld(): condition
  // 'found' failed": after WeldFrames has welded the frames, Drake looks for the
  // child frame's instance (top_level_model::robot1, an SDFormat nested model) among
  // the instances the directives added, for its ModelInstanceInfo report, and does
  // not find it. The plant itself is well defined; mdlc builds it
  // (checked in DmdDrakeFacts.Dmd040_DeepNestedChildWelds).
  {"drake/multibody/parsing/test/process_model_directives_test/deep_child_frame_weld.dmd.yaml", true,
   "", "", 0, "DMD-040: the child is a frame of a nested SDFormat instance (Drake: internal check fails)"},
  // KNOWN DISAGREEMENT (deliberate, as above): Drake's DeepNestedChildWelds.
  {"drake/multibody/parsing/test/process_model_directives_test/deep_child_weld.dmd.yaml", true,
   "", "", 0, "DMD-040: the child is a body of a nested SDFormat instance (Drake: internal check fails)"},
  {"drake/multibody/parsing/test/process_model_directives_test/default_positions.dmd.yaml", true,
   "", "", 0, "DMD-011, DMD-012, DMD-013: default joint positions and free body poses"},
  {"drake/multibody/parsing/test/process_model_directives_test/flattened.dmd.yaml", true, "", "", 0,
   "DMD-050: namespaced filter groups (model_namespace)"},
  {"drake/multibody/parsing/test/process_model_directives_test/inject_frames.dmd.yaml", true, "", "", 0,
   "DMD-030, DMD-040: frames injected into models, welds chained through them"},
  {"drake/multibody/parsing/test/process_model_directives_test/sub_collision.dmd.yaml", true, "", "", 0,
   "DMD-050: also loads on its own"},
  {"drake/multibody/parsing/test/process_model_directives_test/test_backreferences.dmd.yaml", true,
   "", "", 0, "DMD-060: a fragment naming frames its parent added"},
  {"drake/multibody/parsing/test/process_model_directives_test/unflattened_arm.dmd.yaml", true, "",
   "", 0, "DMD-050: also loads on its own"},
  {"drake/multibody/parsing/test/process_model_directives_test/unflattened_top.dmd.yaml", true, "",
   "", 0, "DMD-060: the same arm in two namespaces"},
  {"drake/systems/sensors/test/rgbd_sensor_async_gl_test.dmd.yaml", true, "", "", 0,
   "DMD-012: free bodies posed in the world"},
  {"drake_models/tri_homecart/homecart.dmd.yaml", true, "", "", 0,
   "DMD-060: two fragments, the second using the first's instances"},
  {"drake_models/tri_homecart/homecart_grippers.dmd.yaml", false,
   "frame 'ur3_left::ur_ee_link': no model instance named 'ur3_left'", "", 6,
   "a fragment: homecart.dmd.yaml adds the arms it mounts grippers on (unknown frame standalone)"},
  {"drake_models/tri_homecart/homecart_no_grippers.dmd.yaml", true, "", "", 0,
   "DMD-030, DMD-040: a cart, two arms and a board on frames"},
  {"drake_models/tutorials/models/furnished_living_room.dmd.yaml", true, "", "", 0,
   "DMD-040: furniture welded to the world with X_PC"},
};
// clang-format on

void PrintTo(const Expectation& e, std::ostream* os) { *os << e.path; }

// ------------------------------------------------------------ helpers

mdlc::oracle::RunResult CompileFile(const fs::path& file, const std::string& emit) {
  return mdlc::oracle::RunProcess({MDLC_BINARY, "compile", file.string(), "--package-path",
                                   Corpus().string(), "--emit=" + emit},
                                  60);
}

// The plant of a scene that must compile (`path` relative to corpus/, or
// absolute); compiled once per test program.
const json& Plant(const std::string& path) {
  static std::map<std::string, json> cache;
  if (auto it = cache.find(path); it != cache.end()) return it->second;
  const fs::path file = fs::path(path).is_absolute() ? fs::path(path) : Corpus() / path;
  const auto r = CompileFile(file, "plant-json");
  json plant = json::object();
  EXPECT_EQ(r.exit_code, 0) << path << "\n" << r.err << r.spawn_error;
  if (r.exit_code == 0) plant = json::parse(r.out);
  return cache.emplace(path, std::move(plant)).first->second;
}

// plant[name], or an empty list when the plant lacks it (a scene that did
// not compile)
const json& Table(const json& plant, const char* name) {
  static const json kEmpty = json::array();
  return plant.contains(name) ? plant[name] : kEmpty;
}

const json* Find(const json& plant, const char* table, const std::string& instance,
                 const std::string& name) {
  for (const json& e : Table(plant, table)) {
    if (e["model_instance"] == instance && e["name"] == name) return &e;
  }
  return nullptr;
}

// (instance, local name) of a scoped name "a::b::local"
std::pair<std::string, std::string> Split(const std::string& scoped) {
  const size_t at = scoped.rfind("::");
  if (at == std::string::npos) return {"", scoped};
  return {scoped.substr(0, at), scoped.substr(at + 2)};
}

std::vector<std::string> Instances(const json& plant) {
  if (!plant.contains("model_instances")) return {};
  return plant["model_instances"].get<std::vector<std::string>>();
}

using Pairs = std::vector<std::pair<std::string, std::string>>;
Pairs Filters(const json& plant) {
  if (!plant.contains("collision_filters")) return {};
  return plant["collision_filters"].get<Pairs>();
}

Eigen::Isometry3d Pose(const json& X) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(X["q"][0], X["q"][1], X["q"][2], X["q"][3]).toRotationMatrix();
  T.translation() = Eigen::Vector3d(X["p"][0], X["p"][1], X["p"][2]);
  return T;
}

Eigen::Isometry3d Iso(const Eigen::Vector3d& p,
                      const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = p;
  return T;
}

// Drake's RollPitchYaw (fixed axes x, y, z): R = Rz(yaw) Ry(pitch) Rx(roll)
Eigen::Matrix3d RpyDeg(double r, double p, double y) {
  constexpr double kDeg = std::numbers::pi / 180;
  return (Eigen::AngleAxisd(y * kDeg, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(p * kDeg, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(r * kDeg, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// X_WB of body `instance::name` (the world body: identity)
std::optional<Eigen::Isometry3d> BodyInWorld(const json& plant, const std::string& scoped) {
  if (scoped == "world") return Eigen::Isometry3d::Identity();
  const auto [instance, name] = Split(scoped);
  const json* b = Find(plant, "bodies", instance, name);
  if (!b) return std::nullopt;
  return Pose((*b)["X_WB"]);
}

// X_WF of frame `name` of `instance` as Drake's Frame::CalcPoseInWorld gives
// it: a frame of the plant (its body's X_WB composed with X_BF), or a body
// frame (body frames are frames named like their body in Drake).
std::optional<Eigen::Isometry3d> FrameInWorld(const json& plant, const std::string& instance,
                                              const std::string& name) {
  if (const json* frame = Find(plant, "frames", instance, name)) {
    const auto X_WB = BodyInWorld(plant, (*frame)["body"]);
    if (!X_WB) return std::nullopt;
    return *X_WB * Pose((*frame)["X_BF"]);
  }
  if (Find(plant, "bodies", instance, name)) return BodyInWorld(plant, instance + "::" + name);
  return std::nullopt;
}

// Drake's plant.HasFrameNamed(name, instance): a frame or a body frame
bool HasFrame(const json& plant, const std::string& instance, const std::string& name) {
  return Find(plant, "frames", instance, name) || Find(plant, "bodies", instance, name);
}

// max |X - expected| over the 3x4 matrix (Drake's CompareMatrices on GetAsMatrix34)
::testing::AssertionResult PoseNear(const std::optional<Eigen::Isometry3d>& X,
                                    const Eigen::Isometry3d& expected, double tol = 1e-12) {
  if (!X) return ::testing::AssertionFailure() << "no such frame or body";
  const double err = (X->matrix().topRows<3>() - expected.matrix().topRows<3>()).cwiseAbs().maxCoeff();
  if (err <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "pose off by " << err << " (tolerance " << tol << ")\n"
                                       << "actual:\n"
                                       << X->matrix().topRows<3>() << "\nexpected:\n"
                                       << expected.matrix().topRows<3>();
}

// A weld joint `name` in `instance` (DMD-070: Drake's WeldFrames names it
// `{parent frame}_welds_to_{child frame}` and puts it in the child frame's
// instance) between the bodies `parent` and `child` (scoped names).
::testing::AssertionResult IsWeld(const json& plant, const std::string& instance,
                                  const std::string& name, const std::string& parent,
                                  const std::string& child) {
  const json* j = Find(plant, "joints", instance, name);
  if (!j) return ::testing::AssertionFailure() << "no joint " << name << " in " << instance;
  if ((*j)["type"] != "weld" || (*j)["parent"] != parent || (*j)["child"] != child) {
    return ::testing::AssertionFailure() << "joint " << instance << "::" << name << " is " << *j;
  }
  return ::testing::AssertionSuccess();
}

// --------------------------------------------- 1. every directives file

class DmdCorpusFile : public ::testing::TestWithParam<Expectation> {};

TEST_P(DmdCorpusFile, CompilesOrFailsLocated) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  const Expectation& e = GetParam();
  const auto r = CompileFile(Corpus() / e.path, "none");
  ASSERT_TRUE(r.spawn_error.empty()) << r.spawn_error;
  ASSERT_FALSE(r.timed_out) << e.path;
  if (e.accepted) {
    EXPECT_EQ(r.exit_code, 0) << e.path << " (" << e.why << ")\n" << r.err;
    return;
  }
  EXPECT_EQ(r.exit_code, 1) << e.path << " (" << e.why << ")\n" << r.err;
  // located: "…/FILE:LINE:COL: error: …KEYWORD…"
  const std::string file = *e.located_in ? e.located_in : fs::path(e.path).filename().string();
  const std::regex located("(^|.*/)" + std::regex_replace(file, std::regex(R"([.])"), R"(\.)") +
                           ":" + std::to_string(e.line) + R"(:\d+: error: .*)");
  bool found = false;
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);) {
    found = found || (std::regex_match(line, located) && line.find(e.keyword) != std::string::npos);
  }
  EXPECT_TRUE(found) << "no error '" << e.keyword << "' located at " << file << ":" << e.line
                     << ":\n"
                     << r.err;
}

std::string CaseName(const ::testing::TestParamInfo<Expectation>& info) {
  std::string name = fs::path(info.param.path).stem().stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(DmdManifest, DmdCorpusFile, ::testing::ValuesIn(kExpectations), CaseName);

TEST(DmdCorpusTable, CoversEveryDirectivesFileOfTheManifest) {
  const auto rows = mdlc::oracle::ReadManifest(Corpus() / "manifest.tsv");
  if (!rows) GTEST_SKIP() << "shared corpus not found";
  std::set<std::string> listed;
  for (const auto& e : kExpectations) listed.insert(e.path);
  std::set<std::string> in_manifest;
  for (const auto& cols : *rows) {
    if (cols.size() < 2 || cols[0] != "dmd") continue;
    in_manifest.insert(cols[1]);
    EXPECT_TRUE(listed.count(cols[1])) << "no expectation for " << cols[1];
  }
  for (const auto& path : listed) {
    EXPECT_TRUE(in_manifest.count(path)) << "not a dmd row of the manifest: " << path;
  }
  EXPECT_EQ(in_manifest.size(), std::size(kExpectations));
}

// --------------------------------------------- fragments through parents

class DmdFragments : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  }
};

// add_backreference.dmd.yaml, through test_backreferences.dmd.yaml (Drake's
// TestBackreferences; DMD-060, COMMON-033): the unscoped weld parent
// `simple_model_origin` is the frame the parent added (in the world instance;
// under namespace `nested`, nested::simple_model_origin), the weld joint is in
// the child's instance.
TEST_F(DmdFragments, Dmd060_AddBackreferenceThroughTestBackreferences) {
  const json& plant = Plant(kTestDir + "test_backreferences.dmd.yaml");
  EXPECT_EQ(Instances(plant),
            (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance", "simple_model",
                                      "nested", "nested::simple_model", "nested::extra_model"}));
  // the frames the parent adds (DMD-030: unscoped -> the base frame's
  // instance; base `world` -> the world instance)
  EXPECT_TRUE(Find(plant, "frames", "WorldModelInstance", "simple_model_origin"));
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "WorldModelInstance", "simple_model_origin"),
                       Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "nested", "simple_model_origin"),
                       Iso({1, 2, 3})));
  // what the fragment adds: one weld per inclusion
  EXPECT_TRUE(IsWeld(plant, "simple_model", "simple_model_origin_welds_to_base", "world",
                     "simple_model::base"));
  EXPECT_TRUE(IsWeld(plant, "nested::simple_model", "simple_model_origin_welds_to_base", "world",
                     "nested::simple_model::base"));
  EXPECT_TRUE(PoseNear(BodyInWorld(plant, "simple_model::base"), Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(PoseNear(BodyInWorld(plant, "nested::simple_model::base"), Iso({1, 2, 3})));
  // nested::extra_model::base is welded to nested::simple_model::frame (at 1,2,3)
  EXPECT_TRUE(PoseNear(BodyInWorld(plant, "nested::extra_model::base"), Iso({2, 4, 6})));
  // welded bodies get no floating joint
  for (const json& j : Table(plant, "joints")) {
    EXPECT_NE(j["type"], "quaternion_floating") << j;
  }
}

// homecart_grippers.dmd.yaml, through homecart.dmd.yaml (DMD-030, DMD-040,
// DMD-060): the grippers are mounted on frames injected into the arms the
// first fragment added; the rest of the scene is homecart_no_grippers.
TEST_F(DmdFragments, Dmd060_HomecartGrippersThroughHomecart) {
  const json& cart = Plant("drake_models/tri_homecart/homecart.dmd.yaml");
  const json& bare = Plant("drake_models/tri_homecart/homecart_no_grippers.dmd.yaml");
  std::vector<std::string> instances = Instances(bare);
  instances.push_back("gripper_left");
  instances.push_back("gripper_right");
  EXPECT_EQ(Instances(cart), instances);
  for (const char* side : {"left", "right"}) {
    const std::string arm = std::string("ur3_") + side;
    const std::string gripper = std::string("gripper_") + side;
    // DMD-030: unscoped add_frame -> the base frame's instance (ur3_*)
    const json* origin = Find(cart, "frames", arm, gripper + "_origin");
    ASSERT_TRUE(origin) << gripper;
    EXPECT_EQ((*origin)["body"], arm + "::ur_ee_link");
    EXPECT_TRUE(PoseNear(Pose((*origin)["X_BF"]), Iso({0.06, 0, 0}, RpyDeg(0, 0, -90))));
    // DMD-040, DMD-070: the weld, in the child's instance
    EXPECT_TRUE(IsWeld(cart, gripper, gripper + "_origin_welds_to_body", arm + "::ur_ee_link",
                       gripper + "::body"));
    const auto X_WE = BodyInWorld(cart, arm + "::ur_ee_link");
    ASSERT_TRUE(X_WE) << arm;
    EXPECT_TRUE(PoseNear(BodyInWorld(cart, gripper + "::body"),
                         *X_WE * Iso({0.06, 0, 0}, RpyDeg(0, 0, -90))));
    // scoped add_frame -> that instance; body_frame is the SDFormat frame on `body`
    const json* grasp = Find(cart, "frames", gripper, "grasp_frame");
    ASSERT_TRUE(grasp) << gripper;
    EXPECT_EQ((*grasp)["body"], gripper + "::body");
    EXPECT_TRUE(PoseNear(Pose((*grasp)["X_BF"]), Iso({0, 0.11, 0})));
  }
  // the first fragment's plant is unchanged by the second
  for (const json& b : Table(bare, "bodies")) {
    const std::string scoped = b["model_instance"].get<std::string>() + "::" +
                               b["name"].get<std::string>();
    EXPECT_TRUE(PoseNear(BodyInWorld(cart, scoped), Pose(b["X_WB"]))) << scoped;
  }
  for (const json& f : Table(bare, "frames")) {
    EXPECT_TRUE(Find(cart, "frames", f["model_instance"], f["name"])) << f;
  }
}

// ------------------------------------------------ 2. Drake's expectations

class DmdDrakeFacts : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  }
};

// Drake's BasicSmokeTest / SugarSmokeTest (DMD-010, DMD-030, DMD-040): two
// instances (simple_model, extra_model, in that order), two bodies, the two
// named frames; poses from simple_model.sdf (`frame` at 1,2,3 on `base`).
TEST_F(DmdDrakeFacts, Dmd010_AddScopedSubSmoke) {
  const json& plant = Plant(kTestDir + "add_scoped_sub.dmd.yaml");
  EXPECT_EQ(Instances(plant), (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance",
                                                        "simple_model", "extra_model"}));
  EXPECT_EQ(Table(plant, "bodies").size(), 2u);
  // the unscoped name resolves to the base frame's instance, the scoped one
  // explicitly: both in simple_model, 10,20,30 from `frame`
  for (const char* name : {"sub_added_frame", "sub_added_frame_explicit"}) {
    EXPECT_TRUE(Find(plant, "frames", "simple_model", name)) << name;
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, "simple_model", name), Iso({11, 22, 33}))) << name;
  }
  EXPECT_TRUE(IsWeld(plant, "extra_model", "frame_welds_to_base", "simple_model::base",
                     "extra_model::base"));
  EXPECT_TRUE(PoseNear(BodyInWorld(plant, "extra_model::base"), Iso({1, 2, 3})));
}

// Drake's AddScopedSmokeTest (DMD-060, DMD-062, COMMON-022): the same
// fragment in no namespace, left, right and mid::nested.
TEST_F(DmdDrakeFacts, Dmd060_AddScopedTopFramesLandInTheirInstances) {
  const json& plant = Plant(kTestDir + "add_scoped_top.dmd.yaml");
  // DMD-070 / Drake's Flatten (model names): instances in directive order,
  // namespaced names prefixed (COMMON-022)
  EXPECT_EQ(Instances(plant),
            (std::vector<std::string>{
                "WorldModelInstance", "DefaultModelInstance", "simple_model", "extra_model", "left",
                "left::simple_model", "left::extra_model", "right", "right::simple_model",
                "right::extra_model", "mid", "mid::nested", "mid::nested::simple_model",
                "mid::nested::extra_model"}));
  for (const std::string prefix : {"", "left::", "right::", "mid::nested::"}) {
    const std::string simple = prefix + "simple_model";
    const std::string extra = prefix + "extra_model";
    for (const char* frame : {"base", "frame", "sub_added_frame", "top_added_frame"}) {
      EXPECT_TRUE(HasFrame(plant, simple, frame)) << simple << "::" << frame;
    }
    for (const char* frame : {"base", "frame"}) {
      EXPECT_TRUE(HasFrame(plant, extra, frame)) << extra << "::" << frame;
    }
    // simple_model is free at identity; frame 1,2,3; sub_added_frame +10,20,30;
    // top_added_frame +5,10,15; extra_model welded to simple_model::frame
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, simple, "base"), Eigen::Isometry3d::Identity()));
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, simple, "frame"), Iso({1, 2, 3}))) << simple;
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, simple, "sub_added_frame"), Iso({11, 22, 33})));
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, simple, "top_added_frame"), Iso({16, 32, 48})));
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, extra, "base"), Iso({1, 2, 3}))) << extra;
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, extra, "frame"), Iso({2, 4, 6}))) << extra;
    EXPECT_TRUE(IsWeld(plant, extra, "frame_welds_to_base", simple + "::base", extra + "::base"));
  }
  // scoped add_frame names: the namespace instance
  for (const char* ns : {"left", "right", "mid::nested"}) {
    EXPECT_TRUE(Find(plant, "frames", ns, "simple_model_test_frame")) << ns;
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, ns, "simple_model_test_frame"),
                         Eigen::Isometry3d::Identity()))
        << ns;
  }
  // unscoped at top level: the base frame's instance, not the world's
  EXPECT_TRUE(Find(plant, "frames", "simple_model", "simple_model_test_frame"));
  EXPECT_FALSE(Find(plant, "frames", "WorldModelInstance", "simple_model_test_frame"));
}

// add_scoped_mid on its own (DMD-020, DMD-060): the nested namespace.
TEST_F(DmdDrakeFacts, Dmd060_AddScopedMidNestsTheFragment) {
  const json& plant = Plant(kTestDir + "add_scoped_mid.dmd.yaml");
  EXPECT_EQ(Instances(plant),
            (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance", "nested",
                                      "nested::simple_model", "nested::extra_model"}));
  const json* f = Find(plant, "frames", "nested", "simple_model_test_frame");
  ASSERT_TRUE(f);
  EXPECT_EQ((*f)["body"], "nested::simple_model::base");
  EXPECT_TRUE(IsWeld(plant, "nested::extra_model", "frame_welds_to_base",
                     "nested::simple_model::base", "nested::extra_model::base"));
}

// Drake's AddFrameWithoutScope (DMD-030, COMMON-032, COMMON-033).
TEST_F(DmdDrakeFacts, Dmd030_UnscopedFramesJoinTheirBaseFramesInstance) {
  const json& plant = Plant(kTestDir + "add_frame_without_model_namespace.dmd.yaml");
  const json* on_world = Find(plant, "frames", "WorldModelInstance", "world_as_base_frame");
  ASSERT_TRUE(on_world);
  EXPECT_EQ((*on_world)["body"], "world");
  const json* on_model = Find(plant, "frames", "simple_model", "included_as_base_frame");
  ASSERT_TRUE(on_model);
  EXPECT_EQ((*on_model)["body"], "simple_model::base");
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "simple_model", "included_as_base_frame"),
                       Eigen::Isometry3d::Identity()));
}

// Drake's FlattenWithWorld (COMMON-032): the same file under a namespace;
// `world` stays the world (not nested::world). Processed (not flattened) as
// ProcessModelDirectives does: the unscoped frame on `world` joins the world
// instance, the one on nested::simple_model::__model__ that instance.
TEST_F(DmdDrakeFacts, Common032_WorldIsNotNamespaced) {
  const fs::path dir = fs::temp_directory_path() / ("mdlc_dmd_corpus_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "flatten_with_world.dmd.yaml";
  std::ofstream(file) << R"(directives:
- add_model_instance:
    name: nested
- add_directives:
    file: package://process_model_directives_test/add_frame_without_model_namespace.dmd.yaml
    model_namespace: nested
)";
  const json& plant = Plant(file.string());
  fs::remove_all(dir);
  EXPECT_EQ(Instances(plant), (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance",
                                                        "nested", "nested::simple_model"}));
  const json* on_world = Find(plant, "frames", "WorldModelInstance", "world_as_base_frame");
  ASSERT_TRUE(on_world);
  EXPECT_EQ((*on_world)["body"], "world");
  EXPECT_TRUE(Find(plant, "frames", "nested::simple_model", "included_as_base_frame"));
}

// Drake's TestBackreferences is DmdFragments.Dmd060_AddBackreferenceThroughTestBackreferences.

// Drake's InjectFrames (DMD-030, DMD-040, DMD-070).
TEST_F(DmdDrakeFacts, Dmd040_InjectedFramesPlaceWeldedModels) {
  const json& plant = Plant(kTestDir + "inject_frames.dmd.yaml");
  EXPECT_TRUE(Find(plant, "frames", "top_level_model", "top_injected_frame"));
  EXPECT_TRUE(HasFrame(plant, "mid_level_model", "base"));
  EXPECT_TRUE(Find(plant, "frames", "mid_level_model", "mid_injected_frame"));
  // top_level_model is free at identity; frames 1,2,3 from their bases; the
  // second weld adds X_PC = 4,5,6
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "top_level_model", "top_injected_frame"), Iso({1, 2, 3})));
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "mid_level_model", "base"), Iso({1, 2, 3})));
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "mid_level_model", "mid_injected_frame"), Iso({2, 4, 6})));
  EXPECT_TRUE(PoseNear(FrameInWorld(plant, "bottom_level_model", "base"), Iso({6, 9, 12})));
  EXPECT_TRUE(IsWeld(plant, "mid_level_model", "top_injected_frame_welds_to_base",
                     "top_level_model::base", "mid_level_model::base"));
  EXPECT_TRUE(IsWeld(plant, "bottom_level_model", "mid_injected_frame_welds_to_base",
                     "mid_level_model::base", "bottom_level_model::base"));
}

// Drake's CollisionFilterGroupSmokeTest (DMD-050): exactly these pairs are
// filtered (each simple_model has one collision geometry, on `base`; all
// bodies are free, so the plant adds no adjacency filters).
TEST_F(DmdDrakeFacts, Dmd050_CollisionFilterGroupsAcrossModelsAndNamespaces) {
  const json& plant = Plant(kTestDir + "collision_filter_group.dmd.yaml");
  const Pairs expected = {
      {"model1::base", "model2::base"},                          // across_models
      {"model1::base", "nested::sub_model2::base"},              // nested_members
      {"model3::base", "nested::sub_model1::base"},              // nested_group
      {"model3::base", "nested::sub_model2::base"},              // nested_group
      {"model4::base", "model5::base"},                          // group_4567
      {"model4::base", "model6::base"},                          // group_4567
      {"model4::base", "model7::base"},                          // group_4567
      {"model5::base", "model6::base"},                          // group_4567
      {"model5::base", "model7::base"},                          // group_4567
      {"model6::base", "model7::base"},                          // group_4567
      {"nested::sub_model1::base", "nested::sub_model2::base"},  // across_sub_models
  };
  EXPECT_EQ(Filters(plant), expected);
  // every body carries the proximity geometry the pairs are about
  for (const json& b : Table(plant, "bodies")) {
    bool has_proximity = false;
    for (const json& g : Table(plant, "geometries")) {
      if (g["body"] == b["model_instance"].get<std::string>() + "::" + b["name"].get<std::string>() &&
          g["name"] == "collision") {
        has_proximity = has_proximity || g["roles"] == json({"proximity"});
      }
    }
    EXPECT_TRUE(has_proximity) << b["model_instance"];
  }
}

// sub_collision on its own: only its across_sub_models group.
TEST_F(DmdDrakeFacts, Dmd050_SubCollisionOnItsOwn) {
  const json& plant = Plant(kTestDir + "sub_collision.dmd.yaml");
  EXPECT_EQ(Filters(plant), (Pairs{{"sub_model1::base", "sub_model2::base"}}));
}

// Drake's DefaultPositions (DMD-011, DMD-012, DMD-013): both free bodies at
// RollPitchYaw(5, 6, 7 deg), 1,2,3 (Drake: 1e-14), the acrobot's joints at
// exactly 0.1 and 0.2.
TEST_F(DmdDrakeFacts, Dmd012_DefaultPositionsAndFreeBodyPoses) {
  const json& plant = Plant(kTestDir + "default_positions.dmd.yaml");
  const Eigen::Isometry3d X_WB = Iso({1, 2, 3}, RpyDeg(5, 6, 7));
  const Eigen::Quaterniond q(X_WB.linear());
  for (const char* instance : {"simple_model", "simple_model_again"}) {
    EXPECT_TRUE(PoseNear(BodyInWorld(plant, std::string(instance) + "::base"), X_WB, 1e-14))
        << instance;
    // the free body's floating joint (named like the body) holds the pose
    // as its default positions [qw, qx, qy, qz, x, y, z]
    const json* joint = Find(plant, "joints", instance, "base");
    ASSERT_TRUE(joint) << instance;
    EXPECT_EQ((*joint)["type"], "quaternion_floating");
    EXPECT_EQ((*joint)["parent"], "world");
    const auto d = (*joint)["default_positions"].get<std::vector<double>>();
    ASSERT_EQ(d.size(), 7u) << instance;
    const double sign = d[0] * q.w() < 0 ? -1 : 1;  // q and -q are one rotation
    const double expected[7] = {q.w(), q.x(), q.y(), q.z(), 1, 2, 3};
    for (int i = 0; i < 7; ++i) {
      EXPECT_NEAR(d[i], (i < 4 ? sign : 1) * expected[i], 1e-14) << instance << " [" << i << "]";
    }
  }
  for (const auto& [joint, angle] : {std::pair{"ShoulderJoint", 0.1}, std::pair{"ElbowJoint", 0.2}}) {
    const json* j = Find(plant, "joints", "joint_parsing_test", joint);
    ASSERT_TRUE(j) << joint;
    EXPECT_EQ((*j)["type"], "revolute");
    EXPECT_EQ((*j)["default_positions"], json({angle})) << joint;  // Drake: EXPECT_EQ
  }
}

// Drake's FlattenCollisionGroups (DMD-050, DMD-060): unflattened_top and its
// hand-flattened twin flattened.dmd.yaml both process, with 4 added models,
// and (same directives) give the same plant.
TEST_F(DmdDrakeFacts, Dmd060_FlattenedAndUnflattenedScenesAgree) {
  const json& deep = Plant(kTestDir + "unflattened_top.dmd.yaml");
  const json& flat = Plant(kTestDir + "flattened.dmd.yaml");
  const std::vector<std::string> instances = {
      "WorldModelInstance", "DefaultModelInstance", "right", "right::panda", "right::camera",
      "left",               "left::panda",          "left::camera"};
  EXPECT_EQ(Instances(deep), instances);
  EXPECT_EQ(Instances(flat), instances);
  for (const char* table : {"bodies", "frames", "joints", "geometries"}) {
    ASSERT_TRUE(deep.contains(table) && flat.contains(table)) << table;
    std::map<std::string, json> by_name;
    for (const json& e : Table(deep, table)) {
      const std::string key = e["model_instance"].get<std::string>() + "::" + e["name"].get<std::string>() +
                              (e.contains("body") ? " on " + e["body"].get<std::string>() : "");
      by_name[key] = e;
    }
    EXPECT_EQ(by_name.size(), Table(flat, table).size()) << table;
    for (const json& e : Table(flat, table)) {
      const std::string key = e["model_instance"].get<std::string>() + "::" + e["name"].get<std::string>() +
                              (e.contains("body") ? " on " + e["body"].get<std::string>() : "");
      ASSERT_TRUE(by_name.count(key)) << table << " " << key;
      if (e.contains("X_WB")) {
        EXPECT_TRUE(PoseNear(Pose(by_name[key]["X_WB"]), Pose(e["X_WB"]))) << key;
      }
      EXPECT_EQ(by_name[key], e) << table << " " << key;
    }
  }
  EXPECT_EQ(Filters(deep), Filters(flat));
  // the arm's groups stay within their namespace: no pair across left/right
  for (const auto& [a, b] : Filters(deep)) {
    EXPECT_EQ(a.substr(0, a.find("::")), b.substr(0, b.find("::"))) << a << " / " << b;
  }
}

// Drake's WeldOffset (DMD-040): panda_link0 welded to the world, the hand
// welded to panda_link8 at X_PC = RollPitchYaw(0, 0, -45 deg); Drake checks
// CalcRelativeTransform(link8, hand) == X_PC.
TEST_F(DmdDrakeFacts, Dmd040_WeldOffsetPlacesTheChild) {
  const json& plant = Plant("drake/manipulation/util/test/panda_arm_and_hand.dmd.yaml");
  EXPECT_EQ(Instances(plant), (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance",
                                                        "panda", "panda_hand"}));
  EXPECT_TRUE(IsWeld(plant, "panda", "world_welds_to_panda_link0", "world", "panda::panda_link0"));
  EXPECT_TRUE(IsWeld(plant, "panda_hand", "panda_link8_welds_to_panda_hand", "panda::panda_link8",
                     "panda_hand::panda_hand"));
  const auto X_W8 = BodyInWorld(plant, "panda::panda_link8");
  const auto X_WH = BodyInWorld(plant, "panda_hand::panda_hand");
  ASSERT_TRUE(X_W8 && X_WH);
  EXPECT_TRUE(PoseNear(X_W8->inverse() * *X_WH, Iso({0, 0, 0}, RpyDeg(0, 0, -45))));
}

// Drake's DeepNestedChildWelds / DeepNestedChildFrameWelds (DMD-040).
// KNOWN DISAGREEMENT (deliberate): Drake throws "condition 'found' failed" from
// its ModelInstanceInfo bookkeeping *after* MultibodyPlant::WeldFrames has
// built the weld; mdlc reports no error and builds the plant WeldFrames
// builds. These are the facts of that plant.
TEST_F(DmdDrakeFacts, Dmd040_DeepNestedChildWelds) {
  const std::vector<std::string> instances = {"WorldModelInstance", "DefaultModelInstance",
                                              "top_level_model", "top_level_model::robot1",
                                              "simple_model"};
  {
    const json& plant = Plant(kTestDir + "deep_child_weld.dmd.yaml");
    EXPECT_EQ(Instances(plant), instances);
    EXPECT_TRUE(IsWeld(plant, "top_level_model::robot1", "base_welds_to_robot_base",
                       "simple_model::base", "top_level_model::robot1::robot_base"));
    EXPECT_TRUE(PoseNear(BodyInWorld(plant, "top_level_model::robot1::robot_base"),
                         Eigen::Isometry3d::Identity()));
  }
  {
    const json& plant = Plant(kTestDir + "deep_child_frame_weld.dmd.yaml");
    EXPECT_EQ(Instances(plant), instances);
    // unscoped add_frame on top_level_model::robot1::robot_base: that instance
    const json* f = Find(plant, "frames", "top_level_model::robot1", "top_injected_frame");
    ASSERT_TRUE(f);
    EXPECT_EQ((*f)["body"], "top_level_model::robot1::robot_base");
    EXPECT_TRUE(IsWeld(plant, "top_level_model::robot1", "base_welds_to_top_injected_frame",
                       "simple_model::base", "top_level_model::robot1::robot_base"));
    // the injected frame sits on simple_model::base (identity), so its body is at -1,-2,-3
    EXPECT_TRUE(PoseNear(FrameInWorld(plant, "top_level_model::robot1", "top_injected_frame"),
                         Eigen::Isometry3d::Identity()));
    EXPECT_TRUE(PoseNear(BodyInWorld(plant, "top_level_model::robot1::robot_base"),
                         Iso({-1, -2, -3})));
  }
}

}  // namespace
