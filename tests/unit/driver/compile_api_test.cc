// The public API, mdlc::Compile (mdlc/mdlc.h): files and text in memory,
// every option the command line has, and the Result's evaluations.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"
#include "mdlc/convert.h"
#include "mdlc/ir.h"
#include "mdlc/kinematics.h"
#include "mdlc/pass_list.h"

namespace mdlc {
namespace {

namespace fs = std::filesystem;
const fs::path kExamples = MDLC_EXAMPLES_DIR;

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

constexpr const char* kPendulum = R"(<?xml version="1.0"?>
<robot name="pendulum">
  <link name="world"/>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
      <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="world"/><child link="arm"/><axis xyz="0 1 0"/>
  </joint>
</robot>
)";

// The text of a model file, compiled from memory under the file's own name,
// gives the same plant-json, byte for byte, as the file (every format).
class TextEqualsFile : public ::testing::TestWithParam<const char*> {};

TEST_P(TextEqualsFile, PlantJsonIsByteIdentical) {
  const fs::path path = kExamples / GetParam();
  Options options;
  options.packages.paths = {kExamples.string()};  // the directives scene's package
  const Result from_file = Compile(Input::File(path.string()), options);
  const Result from_text = Compile(Input::Text(ReadFile(path), path.string()), options);
  ASSERT_TRUE(from_file.ok());
  ASSERT_TRUE(from_text.ok());
  const std::string file_json = mdlc::PlantJson(from_file, mdlc::DefaultPositions(from_file));
  EXPECT_EQ(mdlc::PlantJson(from_text, mdlc::DefaultPositions(from_text)), file_json);
  EXPECT_GT(file_json.size(), 100u);
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, TextEqualsFile,
                         ::testing::Values("urdf/double_pendulum.urdf", "sdf/workcell.sdf",
                                           "mjcf/arm_with_gripper.xml",
                                           "directives/handover_cell.dmd.yaml"));

TEST(CompileApi, TextTakesItsFormatFromTheArgumentOrTheName) {
  EXPECT_TRUE(Compile(Input::Text(kPendulum, "generated", Format::Urdf)).ok());
  EXPECT_TRUE(Compile(Input::Text(kPendulum, "generated.urdf")).ok());
  const Result unknown = Compile(Input::Text(kPendulum, "generated"));
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.diagnostics()[0].kind, DiagKind::UnknownFormat);
  EXPECT_NE(unknown.diagnostics()[0].message.find("generated"), std::string::npos);
}

TEST(CompileApi, AFileReadAsAnotherFormatThanItsExtension) {
  const fs::path dir = fs::temp_directory_path() / "mdlc_compile_api_format";
  fs::create_directories(dir);
  const fs::path path = dir / "pendulum.txt";
  std::ofstream(path) << kPendulum;
  EXPECT_FALSE(Compile(Input::File(path.string())).ok());  // .txt: unknown
  EXPECT_TRUE(Compile(Input::File(path.string(), Format::Urdf)).ok());
  fs::remove_all(dir);
}

TEST(CompileApi, DiagnosticsAreLocatedInTheNamedText) {
  std::string broken = kPendulum;
  broken.replace(broken.find("<child link=\"arm\"/>"), 19, "<child link=\"hand\"/>");
  const Result r = Compile(Input::Text(broken, "gen/broken.urdf"));
  ASSERT_FALSE(r.ok());
  ASSERT_GE(r.error_count(), 1u);
  const Diagnostic& d = r.diagnostics()[0];
  EXPECT_EQ(r.sources().Path(d.loc.file), "gen/broken.urdf");
  EXPECT_EQ(d.loc.line, 9u);  // the <child> naming it
  EXPECT_NE(r.FormatText(d).find("gen/broken.urdf:9:"), std::string::npos);
  EXPECT_NE(r.FormatJson(d).find("\"line\""), std::string::npos);
  EXPECT_FALSE(r.has_model());
  EXPECT_THROW(r.plant(), std::logic_error);
}

std::string WithUnknownElement() {
  std::string text = kPendulum;
  text.replace(text.find("<link name=\"arm\">"), 17, "<link name=\"arm\"><bogus/>");
  return text;
}

TEST(CompileApi, StrictnessAndWarningGroups) {
  const Input noisy = Input::Text(WithUnknownElement(), "noisy.urdf");
  const Result lenient = Compile(noisy);
  EXPECT_TRUE(lenient.ok());
  EXPECT_EQ(lenient.warning_count(), 1u);

  Options strict;
  strict.diagnostics.policy.warnings_as_errors = true;
  EXPECT_FALSE(Compile(noisy, strict).ok());

  Options silenced;
  silenced.diagnostics.policy.disabled_groups = {"unknown"};
  const Result quiet = Compile(noisy, silenced);
  EXPECT_TRUE(quiet.ok());
  EXPECT_TRUE(quiet.diagnostics().empty());

  Options promoted;
  promoted.diagnostics.policy.error_groups = {"unknown"};
  EXPECT_FALSE(Compile(noisy, promoted).ok());
}

TEST(CompileApi, DiagnosticsStreamToACallbackWhenOneIsGiven) {
  std::vector<std::string> seen;
  Options options;
  options.diagnostics.on_diagnostic = [&](const Diagnostic& d, const SourceManager& sources) {
    seen.push_back(FormatDiagnosticText(d, sources));
  };
  const Result r = Compile(Input::Text(WithUnknownElement(), "noisy.urdf"), options);
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_NE(seen[0].find("noisy.urdf:4:"), std::string::npos);
  EXPECT_TRUE(r.diagnostics().empty());  // the callback took it
}

TEST(CompileApi, JointPositionsSetTheDefaultConfiguration) {
  Options options;
  options.model.joint_positions = {{"shoulder", 0.5}};
  const Result r = Compile(Input::Text(kPendulum, "p.urdf"), options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(mdlc::DefaultPositions(r), Eigen::VectorXd::Constant(1, 0.5));
  Eigen::VectorXd q = mdlc::DefaultPositions(r);
  EXPECT_TRUE(mdlc::SetJointPosition(r, q, "pendulum::shoulder", -1));
  EXPECT_FALSE(mdlc::SetJointPosition(r, q, "elbow", 1));
  EXPECT_EQ(q[0], -1);

  options.model.joint_positions = {{"elbow", 1}};
  const Result unknown = Compile(Input::Text(kPendulum, "p.urdf"), options);
  EXPECT_FALSE(unknown.ok());
  EXPECT_NE(unknown.diagnostics().back().message.find("'elbow'"), std::string::npos);
}

TEST(CompileApi, MassMatrixAndBodyPosesAreFreeFunctions) {
  const Result r = Compile(Input::Text(kPendulum, "p.urdf"));
  ASSERT_TRUE(r.ok());
  // iyy about the center of mass plus m d^2
  EXPECT_NEAR(mdlc::MassMatrix(r, mdlc::DefaultPositions(r))(0, 0), 0.1 + 2 * 0.25, 1e-15);
  const std::vector<Transform> X_WB = mdlc::BodyPoses(r, Eigen::VectorXd::Constant(1, M_PI / 2));
  ASSERT_EQ(X_WB.size(), r.plant().bodies.size());
  EXPECT_THROW(mdlc::MassMatrix(r, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

// Convert reports what the target cannot hold in its own output, under the
// compile's diagnostic policy; the Result stays as the compile left it, so a
// second conversion says the same.
TEST(CompileApi, ConvertLeavesTheResultAsItWas) {
  constexpr const char* kCapsule = R"(<?xml version="1.0"?>
<robot name="pill" xmlns:drake="http://drake.mit.edu">
  <link name="pill">
    <collision><geometry><drake:capsule radius="0.1" length="0.4"/></geometry></collision>
  </link>
</robot>
)";
  ConvertOptions plain;
  plain.to = Format::Urdf;
  plain.plain = true;
  const Result r = Compile(Input::Text(kCapsule, "pill.urdf"));
  ASSERT_TRUE(r.ok());
  const size_t diagnostics = r.diagnostics().size(), warnings = r.warning_count();
  const ConvertOutput first = mdlc::Convert(r, plain);
  ASSERT_TRUE(first.ok());
  ASSERT_EQ(first.warning_count, 1u);  // the capsule, written as a cylinder (-Wlossy)
  ASSERT_EQ(first.diagnostics.size(), 1u);
  EXPECT_EQ(first.diagnostics[0].kind, DiagKind::Lossy);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.diagnostics().size(), diagnostics);
  EXPECT_EQ(r.warning_count(), warnings);
  const ConvertOutput second = mdlc::Convert(r, plain);
  EXPECT_EQ(second.text, first.text);
  EXPECT_EQ(second.diagnostics.size(), 1u);

  // -Werror=lossy, given to the compile, makes the conversion fail
  Options strict;
  strict.diagnostics.policy.error_groups.insert("lossy");
  const Result s = Compile(Input::Text(kCapsule, "pill.urdf"), strict);
  ASSERT_TRUE(s.ok());
  const ConvertOutput refused = mdlc::Convert(s, plain);
  EXPECT_FALSE(refused.ok());
  EXPECT_EQ(refused.error_count, 1u);
  EXPECT_TRUE(s.ok());
}

TEST(CompileApi, NamingAndPipelineOptions) {
  Options options;
  options.naming.model_name.emplace("renamed");  // assigning it draws a false GCC 12 warning
  const Result r = Compile(Input::Text(kPendulum, "p.urdf"), options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.plant().model_instances.back(), "renamed");

  Options twice;
  twice.naming.auto_rename = true;
  const Result both = Compile({Input::Text(kPendulum, "a.urdf"), Input::Text(kPendulum, "b.urdf")},
                              twice);
  ASSERT_TRUE(both.ok());
  EXPECT_EQ(both.plant().model_instances.back(), "pendulum_1");

  Options ir_only;
  ir_only.skip_backend = true;
  ir_only.instrumentation.time_passes = true;
  const Result ir = Compile(Input::Text(kPendulum, "p.urdf"), ir_only);
  EXPECT_TRUE(ir.ok());
  EXPECT_FALSE(ir.has_model());
  EXPECT_EQ(mdlc::IrModule(ir).bodies.size(), 2u);  // world, arm
  EXPECT_FALSE(TimingReport(ir).empty());

  Options unknown_pass;
  unknown_pass.instrumentation.passes = {"no-such-pass"};
  EXPECT_FALSE(Compile(Input::Text(kPendulum, "p.urdf"), unknown_pass).ok());
}

// COMMON-022: auto-rename gives each copy the first free NAME_n. The
// compile remembers the last n of each name, so many copies stay linear;
// a suffix another model took is still skipped, and the names are those a
// search from NAME_1 gives.
TEST(CompileApi, AutoRenameTakesTheFirstFreeSuffixOfEachName) {
  const std::string taken = std::string(kPendulum).replace(
      std::string(kPendulum).find("\"pendulum\""), 10, "\"pendulum_2\"");
  std::vector<Input> inputs = {Input::Text(taken, "taken.urdf")};
  for (int i = 0; i < 4; ++i) inputs.push_back(Input::Text(kPendulum, "p.urdf"));
  Options options;
  options.naming.auto_rename = true;
  const Result r = Compile(inputs, options);
  ASSERT_TRUE(r.ok());
  std::vector<std::string> names;
  for (const std::string& name : r.plant().model_instances) names.push_back(name);
  const std::vector<std::string> expected = {"pendulum_2", "pendulum", "pendulum_1",
                                             "pendulum_3", "pendulum_4"};
  ASSERT_GE(names.size(), expected.size());
  EXPECT_EQ(std::vector<std::string>(names.end() - expected.size(), names.end()), expected);
}

TEST(CompileApi, ResultsMoveAndOutliveTheirInputs) {
  Result r = [] {
    const std::string text = kPendulum;  // gone when the lambda returns
    return Compile(Input::Text(text, "p.urdf"));
  }();
  Result moved = std::move(r);
  ASSERT_TRUE(moved.ok());
  EXPECT_EQ(moved.plant().bodies.size(), 2u);  // world, arm
  EXPECT_EQ(kVersion, MDLC_VERSION_STRING);
}

}  // namespace
}  // namespace mdlc
