// plant-json (schema mdlc-plant/1, ../shared/spec/plant-json.md): keys and
// their order, values at q, nulls, the mass-matrix cut-off, determinism,
// and speed on a 10,000-body chain (backend/plant_json.h).
#include "backend/plant_json.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/unit/backend/backend_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using nlohmann::ordered_json;
using test_util::ModelBuilder;

using testing::kInf;

std::vector<std::string> Keys(const ordered_json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  return keys;
}

/// A small arm: a base welded to the world, a shoulder (revolute, limited),
/// a screw, a free body, actuators, geometry, a frame, a camera, a coupler.
ir::Module SmallArm() {
  ModelBuilder b("arm");
  ir::Module& m = b.module();
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  const BodyId base = b.AddBody("base", 5, Eigen::Vector3d(0, 0, 0.05), I);
  const BodyId upper = b.AddBody("upper", 1, Eigen::Vector3d(0, 0, 0.2), I);
  const BodyId nut = b.AddBody("nut", 0.5, Eigen::Vector3d::Zero(), I);
  const BodyId ball = b.AddBody("ball", 0.2, Eigen::Vector3d::Zero(), I * 0.01);
  b.AddJoint("base_weld", JointType::Weld, ir::kWorldBody, base,
             Transform::FromTranslation(Eigen::Vector3d(0, 0, 1)));
  const JointId shoulder =
      b.AddJoint("shoulder", JointType::Revolute, base, upper,
                 Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.1)), Eigen::Vector3d::UnitY());
  m[shoulder].limits.lower = {-1.5};
  m[shoulder].limits.upper = {kInf};
  m[shoulder].limits.velocity_upper = {10};
  m[shoulder].limits.effort = {50};
  m[shoulder].limits.acceleration_upper = {kInf};
  m[shoulder].damping = {0.1};
  const JointId screw = b.AddJoint("screw", JointType::Screw, upper, nut,
                                   Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.4)),
                                   Eigen::Vector3d::UnitZ());
  m[screw].screw_thread_pitch = 0.01;
  m[screw].limits.acceleration_upper = {3};
  const JointId free = b.AddJoint("ball", JointType::QuaternionFloating, ir::kWorldBody, ball);
  m[free].unnamed = true;

  ir::Actuator motor;
  motor.name = m.Intern("shoulder_motor");
  motor.model = b.model();
  motor.joint = b.Ref(shoulder, "shoulder");
  motor.effort_limit = 50;
  motor.gear_ratio = 100;
  motor.rotor_inertia = 2e-5;
  motor.kp = 10;
  m.Add(motor);

  b.AddGeometry("upper_collision", upper, ir::Box{Eigen::Vector3d(0.1, 0.2, 0.3)},
                ir::kProximityRole | ir::kIllustrationRole,
                Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.2)));
  m.geometries.back().rgba = Eigen::Vector4d(1, 0, 0, 1);
  m.geometries.back().properties = {{"material/coulomb_friction", std::vector<double>{0.8, 0.6}}};
  b.AddGeometry("base_collision", base, ir::Cylinder{0.1, 0.05}, ir::kProximityRole);
  b.AddGeometry("ground", ir::kWorldBody, ir::HalfSpace{}, ir::kProximityRole);
  ir::Mesh mesh;
  mesh.uri = "package://arm/nut.obj";
  mesh.scale = Eigen::Vector3d(2, 2, 2);
  b.AddGeometry("nut_visual", nut, mesh, ir::kIllustrationRole | ir::kPerceptionRole);

  ir::Frame tool;
  tool.name = m.Intern("tool");
  tool.model = b.model();
  tool.body = b.BodyRef(upper);
  tool.X_BF = Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.5));
  m.Add(tool);

  ir::Camera camera;
  camera.name = m.Intern("arm/camera0");
  camera.model = b.model();
  camera.body = b.BodyRef(upper);
  m.Add(camera);

  ir::CouplerConstraint coupler;
  coupler.joint0 = b.Ref(shoulder, "shoulder");
  coupler.joint1 = b.Ref(screw, "screw");
  coupler.gear_ratio = -2;
  m.Add(ir::Constraint{b.model(), {}, coupler});
  return std::move(m);
}

struct Emitted {
  CompiledModel model;
  Eigen::VectorXd q;
  std::string text;
  ordered_json json;
};

Emitted Emit(const ir::Module& module, const PlantJsonOptions& options = {},
             double shoulder = 0.3) {
  std::optional<CompiledModel> model = test_util::InstantiateOk(module);
  if (!model) throw std::runtime_error("instantiate failed");
  Eigen::VectorXd q = DefaultPositions(model->plant);
  SetJointPositionByName(model->plant, q, "shoulder", shoulder);
  std::string text = EmitPlantJson(*model, q, options);
  ordered_json json = ordered_json::parse(text);
  return {std::move(*model), std::move(q), std::move(text), std::move(json)};
}

TEST(PlantJson, TopLevelKeysInSpecOrder) {
  const Emitted e = Emit(SmallArm());
  EXPECT_EQ(Keys(e.json),
            (std::vector<std::string>{"schema", "model_instances", "bodies", "joints", "frames",
                                      "geometries", "actuators", "collision_filters",
                                      "constraints", "cameras", "dofs", "mass_matrix",
                                      "reflected_inertia", "force_elements", "gravity",
                                      "time_step"}));
  EXPECT_EQ(e.json["schema"], "mdlc-plant/1");
  EXPECT_EQ(e.json["gravity"], ordered_json::parse("[0, 0, -9.81]"));
  EXPECT_EQ(e.json["time_step"], 0);
  EXPECT_EQ(e.json["force_elements"], ordered_json::array());
}

// COMMON-020 instances; COMMON-042 inertia about the COM in B.
TEST(PlantJson, Common020Common042InstancesAndBodies) {
  const Emitted e = Emit(SmallArm());
  EXPECT_EQ(e.json["model_instances"],
            ordered_json::parse(R"(["WorldModelInstance", "DefaultModelInstance", "arm"])"));
  const ordered_json& bodies = e.json["bodies"];
  ASSERT_EQ(bodies.size(), 4u);  // the world is not listed
  const ordered_json& upper = bodies[1];
  EXPECT_EQ(Keys(upper), (std::vector<std::string>{"name", "model_instance", "mass", "com",
                                                   "inertia", "X_WB"}));
  EXPECT_EQ(upper["name"], "upper");
  EXPECT_EQ(upper["model_instance"], "arm");
  EXPECT_EQ(upper["mass"], 1);
  EXPECT_EQ(upper["com"], ordered_json::parse("[0, 0, 0.2]"));
  EXPECT_EQ(upper["inertia"], ordered_json::parse("[0.1, 0.2, 0.3, 0, 0, 0]"));
  // base at z = 1, shoulder 0.1 above, rotated by 0.3 about y
  const ordered_json& X = upper["X_WB"];
  EXPECT_NEAR(X["p"][2].get<double>(), 1.1, 1e-15);
  EXPECT_NEAR(X["q"][0].get<double>(), std::cos(0.15), 1e-15);
  EXPECT_NEAR(X["q"][2].get<double>(), std::sin(0.15), 1e-15);
}

TEST(PlantJson, JointsCarryLimitsAxesAndFlags) {
  const Emitted e = Emit(SmallArm());
  const ordered_json& joints = e.json["joints"];
  ASSERT_EQ(joints.size(), 4u);
  const ordered_json& weld = joints[0];
  EXPECT_EQ(weld["type"], "weld");
  EXPECT_EQ(weld["parent"], "world");
  EXPECT_EQ(weld["child"], "arm::base");
  EXPECT_FALSE(weld.contains("axis_W"));
  EXPECT_EQ(weld["lower"], ordered_json::array());

  const ordered_json& shoulder = joints[1];
  EXPECT_EQ(Keys(shoulder),
            (std::vector<std::string>{"name", "model_instance", "type", "parent", "child",
                                      "axis_W", "lower", "upper", "velocity_limit",
                                      "effort_limit", "damping", "default_positions"}));
  EXPECT_EQ(shoulder["axis_W"], ordered_json::parse("[0, 1, 0]"));
  EXPECT_EQ(shoulder["lower"], ordered_json::parse("[-1.5]"));
  EXPECT_EQ(shoulder["upper"], ordered_json::parse("[null]"));  // +inf
  EXPECT_EQ(shoulder["velocity_limit"], ordered_json::parse("[10]"));
  EXPECT_EQ(shoulder["effort_limit"], ordered_json::parse("[50]"));
  EXPECT_EQ(shoulder["damping"], ordered_json::parse("[0.1]"));
  EXPECT_EQ(shoulder["default_positions"], ordered_json::parse("[0]"));

  // the screw's axis turns with the shoulder; its pitch and its finite
  // acceleration limit are listed
  const ordered_json& screw = joints[2];
  EXPECT_NEAR(screw["axis_W"][0].get<double>(), std::sin(0.3), 1e-15);
  EXPECT_NEAR(screw["axis_W"][2].get<double>(), std::cos(0.3), 1e-15);
  EXPECT_EQ(screw["screw_thread_pitch"], 0.01);
  EXPECT_EQ(screw["acceleration_limit"], ordered_json::parse("[3]"));
  EXPECT_EQ(screw["lower"], ordered_json::parse("[null]"));

  const ordered_json& free = joints[3];
  EXPECT_EQ(free["type"], "quaternion_floating");
  EXPECT_EQ(free["unnamed"], true);
  EXPECT_EQ(free["lower"].size(), 6u);
  EXPECT_EQ(free["default_positions"], ordered_json::parse("[1, 0, 0, 0, 0, 0, 0]"));
  EXPECT_FALSE(shoulder.contains("unnamed"));
}

TEST(PlantJson, FramesGeometriesActuatorsCamerasConstraints) {
  const Emitted e = Emit(SmallArm());
  EXPECT_EQ(e.json["frames"][0],
            ordered_json::parse(R"({"name": "tool", "model_instance": "arm", "body": "arm::upper",
                                    "X_BF": {"p": [0, 0, 0.5], "q": [1, 0, 0, 0]}})"));

  const ordered_json& geometries = e.json["geometries"];
  ASSERT_EQ(geometries.size(), 4u);
  const ordered_json& box = geometries[0];
  EXPECT_EQ(Keys(box), (std::vector<std::string>{"name", "model_instance", "body", "roles",
                                                 "shape", "X_WG", "properties"}));
  EXPECT_EQ(box["roles"], ordered_json::parse(R"(["proximity", "illustration"])"));
  EXPECT_EQ(box["shape"], ordered_json::parse(R"({"type": "box", "size": [0.1, 0.2, 0.3]})"));
  EXPECT_EQ(box["properties"],
            ordered_json::parse(R"({"material/coulomb_friction": [0.8, 0.6],
                                    "phong/diffuse": [1, 0, 0, 1]})"));
  // X_WG = X_WB * X_BG: 0.2 along the upper link's rotated z
  EXPECT_NEAR(box["X_WG"]["p"][0].get<double>(), 0.2 * std::sin(0.3), 1e-15);
  EXPECT_EQ(geometries[1]["shape"],
            ordered_json::parse(R"({"type": "cylinder", "radius": 0.1, "length": 0.05})"));
  EXPECT_EQ(geometries[2]["body"], "world");
  EXPECT_EQ(geometries[2]["shape"], ordered_json::parse(R"({"type": "half_space"})"));
  EXPECT_EQ(geometries[3]["roles"], ordered_json::parse(R"(["illustration", "perception"])"));
  EXPECT_EQ(geometries[3]["shape"],
            ordered_json::parse(R"({"type": "mesh", "uri": "package://arm/nut.obj",
                                    "scale": [2, 2, 2]})"));

  EXPECT_EQ(e.json["actuators"][0],
            ordered_json::parse(R"({"name": "shoulder_motor", "model_instance": "arm",
                                    "joint": "arm::shoulder", "effort_limit": 50,
                                    "gear_ratio": 100, "rotor_inertia": 2e-05,
                                    "kp": 10, "kd": null})"));
  EXPECT_EQ(e.json["cameras"][0]["name"], "arm/camera0");
  EXPECT_EQ(e.json["cameras"][0]["body"], "arm::upper");
  EXPECT_EQ(e.json["cameras"][0]["width"], 640);
  EXPECT_EQ(e.json["constraints"][0],
            ordered_json::parse(R"({"type": "coupler", "model_instance": "arm",
                                    "joint0": "arm::shoulder", "joint1": "arm::screw",
                                    "gear_ratio": -2, "offset": 0})"));
}

// COMMON-054: the shoulder's parent and child both collide, so they are
// filtered; base and world are welded (one composite).
TEST(PlantJson, Common054CollisionFilters) {
  const Emitted e = Emit(SmallArm());
  EXPECT_EQ(e.json["collision_filters"],
            ordered_json::parse(R"([["arm::base", "arm::upper"], ["arm::base", "world"]])"));
}

TEST(PlantJson, DofsMassMatrixAndReflectedInertia) {
  const Emitted e = Emit(SmallArm());
  EXPECT_EQ(e.json["dofs"], ordered_json::parse(R"(["arm::shoulder", "arm::screw"])"));
  const std::vector<JointId> dofs = {JointId(size_t{1}), JointId(size_t{2})};
  const Eigen::MatrixXd M = CalcMassMatrix(e.model.plant, e.q, dofs);
  const ordered_json& mm = e.json["mass_matrix"];
  ASSERT_EQ(mm.size(), 2u);
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) EXPECT_EQ(mm[r][c].get<double>(), M(r, c));  // round-trips
  }
  EXPECT_GT(M(0, 0), 0);
  const ordered_json& reflected = e.json["reflected_inertia"];
  ASSERT_EQ(reflected.size(), 2u);
  EXPECT_DOUBLE_EQ(reflected[0].get<double>(), 100 * 100 * 2e-5);
  EXPECT_EQ(reflected[1], 0);
}

TEST(PlantJson, MassMatrixLeftOutAboveTheDofLimitUnlessForced) {
  PlantJsonOptions options;
  options.mass_matrix_max_dofs = 1;
  const Emitted skipped = Emit(SmallArm(), options);
  EXPECT_TRUE(skipped.json.contains("dofs"));
  EXPECT_FALSE(skipped.json.contains("mass_matrix"));
  EXPECT_FALSE(skipped.json.contains("reflected_inertia"));
  options.force_mass_matrix = true;
  EXPECT_TRUE(Emit(SmallArm(), options).json.contains("mass_matrix"));
}

TEST(PlantJson, OutputIsByteDeterministic) {
  const ir::Module module = SmallArm();
  const Emitted first = Emit(module);
  const Emitted second = Emit(module);
  EXPECT_EQ(first.text, second.text);
  EXPECT_EQ(first.text, EmitPlantJson(first.model, first.q));
  EXPECT_NE(first.text, Emit(module, {}, 0.4).text);  // q matters
}

TEST(PlantJson, NamesAreEscaped) {
  ModelBuilder b("quote\"d");
  b.AddJoint("tab\tjoint", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("back\\slash"));
  const Emitted e = Emit(b.module());
  EXPECT_EQ(e.json["joints"][0]["name"], "tab\tjoint");
  EXPECT_EQ(e.json["joints"][0]["child"], "quote\"d::back\\slash");
}

// A 10,000-body chain (the shape of ../shared/bench's chain_n10000) must
// build, run FK and dump in well under a second; the mass matrix is left out.
TEST(PlantJson, TenThousandBodyChainInstantiates) {
  const auto start = std::chrono::steady_clock::now();
  ModelBuilder b;
  std::mt19937 rng(1);
  BodyId parent = b.AddBody("link_0", 1, Eigen::Vector3d(0, 0, 0.05), Eigen::Matrix3d::Identity());
  b.AddJoint("weld", JointType::Weld, ir::kWorldBody, parent);
  b.AddGeometry("collision", parent, ir::Sphere{0.05}, ir::kProximityRole);
  for (int i = 1; i < 10000; ++i) {
    const BodyId link = b.AddBody("link_" + std::to_string(i), 1, Eigen::Vector3d(0, 0, 0.05),
                                  test_util::RandomInertia(rng, 1), test_util::RandomRotation(rng));
    b.AddJoint("joint_" + std::to_string(i), JointType::Revolute, parent, link,
               {test_util::RandomRotation(rng), Eigen::Vector3d(0, 0, 0.1)},
               Eigen::Vector3d::UnitZ());
    b.AddGeometry("collision", link, ir::Box{Eigen::Vector3d::Constant(0.05)}, ir::kProximityRole);
    parent = link;
  }
  const auto built_ir = std::chrono::steady_clock::now();
  DiagnosticEngine diags;
  std::optional<CompiledModel> model = Instantiate(b.module(), diags);
  ASSERT_TRUE(model);
  const std::string json = EmitPlantJson(*model, DefaultPositions(model->plant));
  const auto done = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(done - built_ir).count();
  RecordProperty("seconds", std::to_string(seconds));
  std::cout << "10k chain: IR " << std::chrono::duration<double>(built_ir - start).count()
            << " s, instantiate + FK + JSON " << seconds << " s, " << json.size() << " bytes\n";
  // speed is measured by the benchmarks (tests/bench), never asserted here:
  // a loaded machine must not fail a correctness test
  EXPECT_EQ(json.find("\"mass_matrix\""), std::string::npos);
  EXPECT_EQ(model->scene.collision_filters.Pairs(model->plant).size(), 9999u);
}

}  // namespace
}  // namespace mdlc::backend
