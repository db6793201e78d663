// The command line's --collada-up-axis (issue 55, BEYOND-001): a COLLADA
// mesh that declares Y_UP is read as written by default and turned to Z-up
// when asked, in what the compile computes from it (a body's mass from its
// mesh); one note per compile says which was done, -Wno-mesh-axes silences
// it, and the derived-mesh cache keeps the two readings apart.
#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace mdlc::cli_test {
namespace {

class MeshAxesCliTest : public CliFixture {
 protected:
  /// A free body whose mass comes from a mesh of `file` (tests/models/meshes).
  fs::path Model(const std::string& file) {
    return Write("axes.xml", fmt::format(R"(<mujoco model="axes">
  <asset><mesh name="m" file="{}/meshes/{}"/></asset>
  <worldbody><body name="b"><freejoint/><geom type="mesh" mesh="m"/></body></worldbody>
</mujoco>
)",
                                          MDLC_TEST_MODELS, file));
  }
  /// The body's center of mass, in its frame, as plant-json gives it.
  std::array<double, 3> Com(const Outcome& r) {
    const nlohmann::json plant = nlohmann::json::parse(r.out);
    for (const auto& body : plant["bodies"]) {
      if (body["name"] == "b") return body["com"].get<std::array<double, 3>>();
    }
    ADD_FAILURE() << "no body b in " << r.out;
    return {};
  }
};

void ExpectCom(const std::array<double, 3>& got, const std::array<double, 3>& want) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "component " << k;
}

TEST_F(MeshAxesCliTest, ColladaUpAxisIsReadAsWrittenUnlessApplied) {  // issue 55, BEYOND-001
  const fs::path model = Model("box_y_up.dae");
  const std::string compile = "compile --emit=plant-json --cache-dir " + (dir_ / "cache").string();
  // the box's center (1.5, 0.25, 1.25), as written in Y_UP axes, is (x, z, -y)
  const std::array<double, 3> as_written{1.5, 1.25, -0.25}, applied{1.5, 0.25, 1.25};
  // twice each way, alternating: a cached mass of one reading never serves the other
  for (int round = 0; round < 2; ++round) {
    const Outcome plain = Mdlc(compile + " " + model.string());
    ASSERT_EQ(plain.status, 0) << plain.err;
    ExpectCom(Com(plain), as_written);
    EXPECT_NE(plain.err.find(fmt::format(
                  "axes.xml:2:25: note: COLLADA mesh '{}/meshes/box_y_up.dae' declares Y_UP; its "
                  "vertices are read as written, as RViz and Gazebo show them "
                  "(--collada-up-axis=apply turns such files to Z-up) [-Wmesh-axes]",
                  MDLC_TEST_MODELS)),
              std::string::npos)
        << plain.err;

    const Outcome turned = Mdlc(compile + " --collada-up-axis=apply " + model.string());
    ASSERT_EQ(turned.status, 0) << turned.err;
    ExpectCom(Com(turned), applied);
    EXPECT_NE(turned.err.find("declares Y_UP; turned to Z-up, as --collada-up-axis=apply asks"),
              std::string::npos)
        << turned.err;
  }
  // a note, not a warning: --strict does not fail it, -Wno-mesh-axes silences it
  const Outcome strict = Mdlc(compile + " --strict " + model.string());
  EXPECT_EQ(strict.status, 0) << strict.err;
  const Outcome quiet = Mdlc(compile + " -Wno-mesh-axes " + model.string());
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST_F(MeshAxesCliTest, ZUpColladaAndGltfGetNoNote) {  // issue 55, BEYOND-001
  for (const char* file : {"box.dae", "box.gltf"}) {
    const Outcome r = Mdlc("compile --emit=plant-json --no-cache " + Model(file).string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << file;
    ExpectCom(Com(r), {1.5, 0.25, 1.25});  // glTF turned Z-up, as Drake turns it
  }
}

TEST_F(MeshAxesCliTest, AnUnknownModeIsBadUsage) {  // issue 55
  const Outcome r = Mdlc("compile --collada-up-axis=Y_UP " + Model("box.dae").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--collada-up-axis"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mdlc::cli_test
