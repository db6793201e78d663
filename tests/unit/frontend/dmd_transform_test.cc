// Drake's YAML transform schema as Model Directives write it (DMD-013) and
// the strict YAML reading under it (DMD-001): rotations are checked against
// Eigen's own angle-axis products, not against mdlc's rotation helpers.
#include "frontend/directives/dmd_transform.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

namespace mdlc::frontend {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

class DmdTransformTest : public ::testing::Test {
 protected:
  // Reads the transform under the key `X` of a one-entry map.
  std::optional<DirectiveTransform> Read(const std::string& yaml) {
    file_ = sources_.AddBuffer("t.dmd.yaml", yaml);
    YamlSchemaReader reader(file_, diags_);
    auto doc = reader.Parse(sources_.Contents(file_));
    if (!doc) return std::nullopt;
    auto x = reader.Get(doc->root(), "X");
    return ReadDirectiveTransform(reader, x.value, "X", x.key_loc);
  }
  // The first diagnostic's "line:col: message".
  std::string FirstError() const {
    if (diags_.diagnostics().empty()) return "";
    const Diagnostic& d = diags_.diagnostics().front();
    return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message;
  }

  SourceManager sources_;
  DiagnosticEngine diags_;
  FileId file_;
};

TEST_F(DmdTransformTest, RpyIsFixedAxisRollPitchYawInDegrees) {
  auto t = Read("X: {translation: [1, -2, 3.5], rotation: !Rpy {deg: [10, 20, 30]}}");
  ASSERT_TRUE(t) << FirstError();
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(30 * kDeg, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(20 * kDeg, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_TRUE(t->X.R.isApprox(expected, 1e-15));
  EXPECT_EQ(t->X.p, Eigen::Vector3d(1, -2, 3.5));
  EXPECT_FALSE(t->base_frame);
}

TEST_F(DmdTransformTest, AngleAxisNormalizesItsAxis) {
  auto t = Read("X: {base_frame: arm::tool, rotation: !AngleAxis {angle_deg: 120, axis: [0, 3, 4]}}");
  ASSERT_TRUE(t) << FirstError();
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(120 * kDeg, Eigen::Vector3d(0, 0.6, 0.8)).toRotationMatrix();
  EXPECT_TRUE(t->X.R.isApprox(expected, 1e-15));
  ASSERT_TRUE(t->base_frame);
  EXPECT_EQ(t->base_frame->text, "arm::tool");
  EXPECT_EQ(t->base_frame->loc.line, 1u);
  EXPECT_EQ(t->base_frame->loc.column, 17u);
}

TEST_F(DmdTransformTest, OmittedPartsAreIdentity) {
  for (const char* yaml : {"X: {}", "X:", "X: {rotation: !Identity {}}", "X: {rotation: !Rpy {}}",
                           "X: {translation: !DeterministicVector {value: [0, 0, 0]}}"}) {
    auto t = Read(yaml);
    ASSERT_TRUE(t) << yaml << ": " << FirstError();
    EXPECT_TRUE(t->X.IsIdentity()) << yaml;
  }
}

TEST_F(DmdTransformTest, RandomDistributionsAreErrors) {
  EXPECT_FALSE(Read("X: {rotation: !Uniform {}}"));
  EXPECT_EQ(FirstError(), "1:15: rotation is a random distribution (!Uniform); model directives "
                          "must be deterministic");
  EXPECT_FALSE(Read("X:\n  translation: !GaussianVector {mean: [0, 0, 0], stddev: [1, 1, 1]}"));
  EXPECT_FALSE(Read("X: {rotation: !AngleAxis {angle_deg: !Uniform {min: 0, max: 1}}}"));
  EXPECT_EQ(diags_.error_count(), 3u);
}

TEST_F(DmdTransformTest, SchemaErrorsAreLocated) {
  EXPECT_FALSE(Read("X:\n  translation: [0, 0]\n"));
  EXPECT_EQ(FirstError(), "2:16: X 'translation' must have 3 numbers, not 2");
}

TEST_F(DmdTransformTest, UnknownKeysSuggestTheKnownOne) {
  EXPECT_FALSE(Read("X:\n  base_frame: world\n  translaton: [0, 0, 1]\n"));
  ASSERT_EQ(diags_.diagnostics().size(), 1u);
  const Diagnostic& d = diags_.diagnostics().front();
  EXPECT_EQ(d.kind, DiagKind::UnknownKey);
  EXPECT_EQ(d.loc.line, 3u);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].message, "did you mean 'translation'?");
}

TEST_F(DmdTransformTest, RepeatedKeysAndUntaggedRotationsAreErrors) {
  EXPECT_FALSE(Read("X: {rotation: {deg: [0, 0, 90]}}"));
  EXPECT_NE(FirstError().find("rotation needs a tag"), std::string::npos) << FirstError();
  Read("X: {translation: [0, 0, 1], translation: [0, 0, 2]}");
  bool repeated = false;
  for (const Diagnostic& d : diags_.diagnostics()) {
    repeated = repeated || d.message == "key 'translation' appears twice in X";
  }
  EXPECT_TRUE(repeated);
}

// YAML merge keys, as Drake's YAML reader takes them: the merging map's own
// keys win over the merged ones, and merged keys are checked too.
TEST_F(DmdTransformTest, MergeKeysBringInDefaults) {
  auto t = Read("base: &base {translation: [1, 2, 3], rotation: !Rpy {deg: [0, 0, 90]}}\n"
                "X: {<<: *base, translation: [4, 5, 6]}\n");
  ASSERT_TRUE(t) << FirstError();
  EXPECT_EQ(t->X.p, Eigen::Vector3d(4, 5, 6));
  EXPECT_TRUE(t->X.R.isApprox(
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-15));
  EXPECT_FALSE(Read("bad: &bad {translaton: [1, 2, 3]}\nX: {<<: *bad}\n"));
  EXPECT_EQ(FirstError(), "1:12: unknown key 'translaton' in X");
  EXPECT_FALSE(Read("X: {<<: [0, 1]}\n"));
}

TEST_F(DmdTransformTest, NonFiniteNumbersAreErrors) {
  for (const char* yaml : {"X: {translation: [0, .inf, 0]}", "X: {translation: [0, 0, -.Inf]}",
                           "X: {translation: [1e999, 0, 0]}", "X: {translation: [.NaN, 0, 0]}"}) {
    const size_t before = diags_.diagnostics().size();
    EXPECT_FALSE(Read(yaml)) << yaml;
    ASSERT_EQ(diags_.diagnostics().size(), before + 1) << yaml;
    EXPECT_EQ(diags_.diagnostics().back().kind, DiagKind::NonFinite) << yaml;
  }
}

}  // namespace
}  // namespace mdlc::frontend
