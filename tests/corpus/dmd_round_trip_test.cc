// Round trip of Model Directives: a scene compiled from a .dmd.yaml gives
// every body the pose one gets by compiling each model alone and composing
// them by hand, from the directive's own numbers (DMD-010, DMD-012,
// DMD-013, DMD-030, DMD-040, DMD-070):
//
//   X_W_b = X_W_P * X_PC * inverse(X_W_C_alone) * X_W_b_alone
//
// where P is the weld's (or pose's) parent frame in the scene, C the child
// frame and b any body of the child's model, "alone" meaning that model's
// own compile at the same joint positions. Corpus scenes are skipped when
// ../shared is absent; the scene from tests/models always runs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "../oracle/oracle_util.h"
#include "shared_corpus.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using Isometry = Eigen::Isometry3d;

constexpr double kDeg = std::numbers::pi / 180;

Isometry FromJson(const json& X) {
  Isometry T = Isometry::Identity();
  T.linear() = Eigen::Quaterniond(X["q"][0], X["q"][1], X["q"][2], X["q"][3]).toRotationMatrix();
  T.translation() = Eigen::Vector3d(X["p"][0], X["p"][1], X["p"][2]);
  return T;
}

// Drake's schema: translation, then fixed-axis roll-pitch-yaw in degrees
Isometry Xyz(double x, double y, double z, double r = 0, double p = 0, double yaw = 0) {
  Isometry T = Isometry::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw * kDeg, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(p * kDeg, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(r * kDeg, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

json Compile(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {MDLC_BINARY, "compile"};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.push_back("--emit=plant-json");
  auto r = mdlc::oracle::RunProcess(argv, 60);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? json::parse(r.out) : json::object();
}

// One compiled plant: X_W of every body and frame, by "instance::name".
struct Poses {
  std::map<std::string, Isometry> bodies, frames;

  explicit Poses(const json& plant) {
    for (const json& b : plant.value("bodies", json::array())) {
      bodies[b["model_instance"].get<std::string>() + "::" + b["name"].get<std::string>()] =
          FromJson(b["X_WB"]);
    }
    for (const json& f : plant.value("frames", json::array())) {
      const std::string body = f["body"];
      const Isometry X_WB = body == "world" ? Isometry::Identity() : bodies.at(body);
      frames[f["model_instance"].get<std::string>() + "::" + f["name"].get<std::string>()] =
          X_WB * FromJson(f["X_BF"]);
    }
  }
  // a body frame or an explicit frame
  Isometry Frame(const std::string& scoped) const {
    if (auto it = bodies.find(scoped); it != bodies.end()) return it->second;
    return frames.at(scoped);
  }
};

// One model of a scene, placed by hand: its child frame C sits at
// `X_W_P() * X_PC` in the world.
struct Placement {
  std::string instance;  // the instance the scene gives the model
  std::string file;      // the model file, compiled alone
  std::string child;     // C, a body or frame of the model (unscoped)
  std::function<Isometry(const Poses& scene_so_far)> X_W_P;
  Isometry X_PC = Isometry::Identity();
};

struct Mismatch {
  std::string body;
  double error;
};

// Composes every placement by hand and returns the largest error against
// the scene (0 when all agree exactly), with the body it is on.
// A joint position: the joint of one instance of the scene.
struct JointValue {
  std::string instance, joint;
  double value;
};

Mismatch Compare(const Poses& scene, const std::vector<Placement>& placements,
                 const std::vector<std::string>& extra_args, const std::vector<JointValue>& q) {
  Mismatch worst{"", 0};
  size_t compared = 0;
  for (const Placement& p : placements) {
    std::vector<std::string> args = extra_args;
    args.insert(args.begin(), p.file);
    for (const JointValue& v : q) {
      if (v.instance == p.instance) args.push_back(fmt::format("--q={}={}", v.joint, v.value));
    }
    const json alone_plant = Compile(args);
    const Poses alone(alone_plant);
    const std::string alone_instance = alone_plant["model_instances"].back();
    const Isometry X_W_C = p.X_W_P(scene) * p.X_PC;
    const Isometry X_C_W_alone = alone.Frame(alone_instance + "::" + p.child).inverse();
    for (const auto& [name, X_W_b_alone] : alone.bodies) {
      const std::string local = name.substr(alone_instance.size() + 2);
      const std::string in_scene = p.instance + "::" + local;
      EXPECT_TRUE(scene.bodies.count(in_scene)) << in_scene;
      if (!scene.bodies.count(in_scene)) continue;
      const Isometry expected = X_W_C * X_C_W_alone * X_W_b_alone;
      const Isometry& actual = scene.bodies.at(in_scene);
      const double error = std::max((expected.translation() - actual.translation()).norm(),
                                    (expected.linear() - actual.linear()).norm());
      ++compared;
      if (error > worst.error) worst = {in_scene, error};
    }
  }
  EXPECT_GT(compared, 0u);
  return worst;
}

using mdlc::corpus_test::Corpus;

std::function<Isometry(const Poses&)> World() {
  return [](const Poses&) { return Isometry::Identity(); };
}
std::function<Isometry(const Poses&)> FrameOf(std::string scoped,
                                              Isometry offset = Isometry::Identity()) {
  return [scoped, offset](const Poses& s) { return s.Frame(scoped) * offset; };
}

class DmdRoundTrip : public ::testing::Test {
 protected:
  void RequireCorpus() {
    if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  }
  void Check(const std::string& scene_file, const std::vector<Placement>& placements,
             const std::vector<std::string>& package_args, const std::vector<JointValue>& q = {}) {
    std::vector<std::string> args = package_args;
    args.insert(args.begin(), scene_file);
    for (const JointValue& v : q) {
      args.push_back(fmt::format("--q={}::{}={}", v.instance, v.joint, v.value));
    }
    const Poses scene(Compile(args));
    const Mismatch worst = Compare(scene, placements, package_args, q);
    EXPECT_LT(worst.error, 1e-12) << worst.body;
    fmt::print("[ round trip ] {}: {} bodies placed, largest error {:.3g} ({})\n",
               fs::path(scene_file).filename().string(), scene.bodies.size(), worst.error,
               worst.body);
    // and the comparison is sharp: a 1e-6 change to one directive's numbers
    // is caught
    std::vector<Placement> perturbed = placements;
    perturbed.back().X_PC.translation().x() += 1e-6;
    EXPECT_GT(Compare(scene, perturbed, package_args, q).error, 5e-7);
  }
};

TEST_F(DmdRoundTrip, ArmGripperAndBoxFromTestModels) {
  const fs::path models = fs::path(MDLC_TEST_MODELS) / "dmd";
  const std::vector<std::string> packages = {"--package-path", models.string()};
  // tests/golden/dmd/weld_and_frames.dmd.yaml, by hand
  const Isometry wrist =
      Xyz(0, 0, 0.3) * Isometry(Eigen::AngleAxisd(
                           45 * kDeg, Eigen::Vector3d::UnitZ()));  // axis [0, 0, 2] normalized
  const std::vector<Placement> placements = {
      {"arm", (models / "arm.urdf").string(), "base", World(), Xyz(0.5, 0, 0.75, 0, 0, 90)},
      {"gripper", (models / "gripper.sdf").string(), "__model__", FrameOf("arm::fore", wrist)},
      {"box", (models / "box.sdf").string(), "top", [](const Poses&) { return Xyz(0, 0, 0.75); },
       Xyz(0, 0, 0, 180, 0, 0)},
  };
  const std::string scene =
      (fs::path(MDLC_TEST_MODELS).parent_path() / "golden/dmd/weld_and_frames.dmd.yaml").string();
  Check(scene, placements, packages);
  // at another configuration of the arm, too
  Check(scene, placements, packages, {{"arm", "shoulder", 0.7}, {"arm", "elbow", -0.4}, {"gripper", "slide", 0.01}});
}

TEST_F(DmdRoundTrip, IiwaWithWsgGripper) {
  RequireCorpus();
  const fs::path dm = Corpus() / "drake_models";
  const std::vector<Placement> placements = {
      {"iiwa7", (dm / "iiwa_description/sdf/iiwa7_no_collision.sdf").string(), "iiwa_link_0",
       World()},
      {"schunk_wsg", (dm / "wsg_50_description/sdf/schunk_wsg_50_with_tip.sdf").string(), "body",
       FrameOf("iiwa7::iiwa_link_7", Xyz(0, 0, 0.114, 90, 0, 90))},
  };
  Check((Corpus() / "drake/manipulation/util/test/iiwa7_wsg.dmd.yaml").string(), placements,
        {"--package-path", Corpus().string()}, {{"iiwa7", "iiwa_joint_2", 0.5}, {"iiwa7", "iiwa_joint_6", -1}});
}

TEST_F(DmdRoundTrip, PandaArmAndHand) {
  RequireCorpus();
  const fs::path urdf = Corpus() / "drake_models/franka_description/urdf";
  const std::vector<Placement> placements = {
      {"panda", (urdf / "panda_arm.urdf").string(), "panda_link0", World()},
      {"panda_hand", (urdf / "panda_hand.urdf").string(), "panda_hand",
       FrameOf("panda::panda_link8"), Xyz(0, 0, 0, 0, 0, -45)},
  };
  Check((Corpus() / "drake/manipulation/util/test/panda_arm_and_hand.dmd.yaml").string(),
        placements, {"--package-path", Corpus().string()});
}

TEST_F(DmdRoundTrip, FurnishedLivingRoom) {
  RequireCorpus();
  const fs::path m = Corpus() / "drake_models/tutorials/models";
  auto at = [&](const char* name, const char* file, Isometry X_PC) {
    return Placement{name, (m / file).string(), name, World(), X_PC};
  };
  const std::vector<Placement> placements = {
      at("living_room", "living_room.sdf", Isometry::Identity()),
      at("cabinet", "cabinet.sdf", Xyz(-1.7753, 2.5818, 0)),
      at("bookshelves", "bookshelves.sdf", Xyz(2.716, -1.0716, 0, 0, 0, -90)),
      at("tall_cabinet", "tall_cabinet.sdf", Xyz(0.0235, 2.6566, 0)),
      at("sofa", "sofa.sdf", Xyz(0, -2.4117, 0, 0, 0, 180)),
      at("stool", "stool.sdf", Xyz(1.7744, 1.6287, 0, 0, 0, 30)),
      {"curtains", (m / "curtain_open.sdf").string(), "curtains", World()},
  };
  Check((m / "furnished_living_room.dmd.yaml").string(), placements,
        {"--package-path", Corpus().string()});
}

TEST_F(DmdRoundTrip, BinAndFreeBallsPosedInTheWorld) {
  RequireCorpus();
  const fs::path station = Corpus() / "drake_models/manipulation_station";
  std::vector<Placement> placements = {
      {"bin", (station / "bin.sdf").string(), "bin_base", World(), Xyz(0, 0, 0.2)}};
  for (int i = 1; i <= 9; ++i) {
    // default_free_body_pose: {base_link: {translation: [...]}} in the world
    placements.push_back({"ball_" + std::to_string(i), (station / "sphere.sdf").string(),
                          "base_link", World(),
                          Xyz(0.09 - 0.01 * i, 0.01 * i, 0.3 * i)});
  }
  Check((Corpus() / "drake/systems/sensors/test/rgbd_sensor_async_gl_test.dmd.yaml").string(),
        placements, {"--package-path", Corpus().string()});
}

}  // namespace
