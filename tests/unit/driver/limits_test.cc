// Input limits (issue 16, ir/limits.h): each bound stops a compile with a
// located limit-exceeded error naming the limit, and the same input compiles
// once the limit is raised through Options::limits (`--limit NAME=VALUE`).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "ir/limits.h"
#include "mdlc/mdlc.h"

namespace mdlc {
namespace {

namespace fs = std::filesystem;

/// A fresh folder per test, removed at the end.
class LimitsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("mdlc_limits_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  /// The one limit-exceeded error of `r`, which must hold `text`.
  static const Diagnostic& LimitError(const Result& r, std::string_view text) {
    const Diagnostic* found = nullptr;
    for (const Diagnostic& d : r.diagnostics()) {
      if (d.kind == DiagKind::LimitExceeded) {
        EXPECT_EQ(found, nullptr) << "a second limit error: " << d.message;
        found = &d;
      }
    }
    EXPECT_NE(found, nullptr);
    static const Diagnostic kNone{};
    if (!found) return kNone;
    EXPECT_NE(found->message.find(text), std::string::npos) << found->message;
    EXPECT_EQ(found->severity, Severity::Error);
    return *found;
  }

  fs::path dir_;
};

constexpr const char* kOneLink = R"(<robot name="r">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
)";

TEST(LimitSettingTest, ParsesNamesAndSizes) {
  Limits limits;
  EXPECT_EQ(SetLimit(limits, "file-size=2M"), std::nullopt);
  EXPECT_EQ(limits.file_size, uint64_t{2} << 20);
  EXPECT_EQ(SetLimit(limits, "depth=12"), std::nullopt);
  EXPECT_EQ(limits.depth, 12u);
  EXPECT_EQ(SetLimit(limits, "total-size=1g"), std::nullopt);
  EXPECT_EQ(limits.total_size, uint64_t{1} << 30);
  EXPECT_NE(SetLimit(limits, "depth"), std::nullopt);
  EXPECT_NE(SetLimit(limits, "depth=0"), std::nullopt);
  EXPECT_NE(SetLimit(limits, "depth=-3"), std::nullopt);
  EXPECT_NE(SetLimit(limits, "depth=1x"), std::nullopt);
  EXPECT_NE(SetLimit(limits, "depht=3"), std::nullopt);
  // libxml2 parses buffers of at most INT_MAX bytes
  EXPECT_NE(SetLimit(limits, "file-size=3G"), std::nullopt);
  EXPECT_EQ(limits.depth, 12u);  // a refused setting changes nothing
}

TEST(LimitSettingTest, FormatsBytes) {
  EXPECT_EQ(FormatBytes(12), "12 bytes");
  EXPECT_EQ(FormatBytes(2048), "2 KiB");
  EXPECT_EQ(FormatBytes(uint64_t{512} << 20), "512 MiB");
  EXPECT_EQ(FormatBytes(uint64_t{3} << 29), "1.5 GiB");
}

TEST_F(LimitsTest, FileSize) {
  const std::string path = Write("r.urdf", kOneLink);
  Options options;
  options.limits.file_size = 100;
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "over the file-size limit of 100 bytes");
  EXPECT_NE(d.message.find("--limit file-size"), std::string::npos);
  options.limits.file_size = fs::file_size(path);
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
}

TEST_F(LimitsTest, TotalSizeIsReportedAtTheDirectiveThatAddsTheFile) {
  const std::string model = Write("r.urdf", kOneLink);
  const std::string scene = Write("scene.dmd.yaml", fmt::format(R"(directives:
- add_model:
    name: a
    file: file://{0}
- add_model:
    name: b
    file: file://{0}
)",
                                                                model));
  Options options;
  options.limits.total_size = fs::file_size(scene) + fs::file_size(model);
  const Result r = Compile(Input::File(scene), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "over the total-size limit");
  EXPECT_EQ(d.loc.line, 7u);  // the second `file:`
  options.limits.total_size += fs::file_size(model);
  EXPECT_TRUE(Compile(Input::File(scene), options).ok());
}

/// The 1-based column of `needle` on line 3 of kOneLink.
uint32_t ColumnOnLine3(std::string_view needle) {
  std::string_view text = kOneLink;
  for (int i = 0; i < 2; ++i) text.remove_prefix(text.find('\n') + 1);
  return static_cast<uint32_t>(text.find(needle) + 1);
}

TEST_F(LimitsTest, ElementsAreCountedPerDocument) {
  const std::string path = Write("r.urdf", kOneLink);
  Options options;
  options.limits.elements = 4;  // robot, link, inertial, mass, inertia
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "more than 4 elements");
  EXPECT_EQ(d.loc.line, 3u);
  EXPECT_EQ(d.loc.column, ColumnOnLine3("<inertia "));  // the fifth element
  options.limits.elements = 5;
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
}

TEST_F(LimitsTest, Depth) {
  const std::string path = Write("r.urdf", kOneLink);
  Options options;
  options.limits.depth = 3;  // robot > link > inertial > mass is 4 deep
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "element nested 4 deep, over the depth limit of 3");
  EXPECT_EQ(d.loc.line, 3u);
  EXPECT_EQ(d.loc.column, ColumnOnLine3("<mass"));
  options.limits.depth = 4;
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
}

TEST_F(LimitsTest, DepthStopsADeepDocumentAtItsFirstTooDeepElement) {
  const int levels = 50'000;
  std::string text = "<robot name=\"r\">";
  for (int i = 0; i < levels; ++i) text += "\n<a>";
  for (int i = 0; i < levels; ++i) text += "</a>";
  text += "</robot>\n";
  const std::string path = Write("deep.urdf", text);
  Options options;
  options.limits.depth = 1000;
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(LimitError(r, "nested 1001 deep").loc.line, 1001u);
}

// Models nest in models: m1 in m0, m2 in m1, ... Every output that prints an
// instance's full name grows with the square of the depth, so the depth is
// bounded; the first model past the bound is the error, and nothing below it
// is read.
TEST_F(LimitsTest, ModelDepthIsReportedAtTheFirstModelTooDeep) {
  const int levels = 12;
  std::string text = "<sdf version=\"1.9\">\n";
  for (int i = 0; i < levels; ++i) {
    text += fmt::format("<model name=\"m{}\"><link name=\"l\"/>\n", i);
  }
  for (int i = 0; i < levels; ++i) text += "</model>";
  const std::string path = Write("nested.sdf", text + "\n</sdf>\n");
  Options options;
  options.limits.model_depth = 10;  // m0 is 1 deep, m10 would be 11
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d =
      LimitError(r, "model 'm10' would be nested 11 deep, over the model-depth limit of 10");
  EXPECT_EQ(d.loc.line, 12u);
  EXPECT_EQ(r.diagnostics().size(), 1u);
  options.limits.model_depth = levels;
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
  EXPECT_EQ(Limits{}.model_depth, 1000u);  // the default, far above real models
}

// SDFormat includes nest: a chain of models each including the next
std::string ChainModel(int i, int last) {
  const std::string include =
      i < last ? fmt::format("<include><uri>m{}.sdf</uri></include>", i + 1) : "";
  return fmt::format(R"(<sdf version="1.9"><model name="m{}"><link name="l"/>{}</model></sdf>
)",
                     i, include);
}

TEST_F(LimitsTest, IncludeDepthIsReportedAtTheIncludeTooDeep) {
  const int last = 5;
  for (int i = 0; i <= last; ++i) Write(fmt::format("m{}.sdf", i), ChainModel(i, last));
  const std::string top = (dir_ / "m0.sdf").string();
  Options options;
  options.limits.include_depth = 3;  // m1 is 1 deep, ..., m4 would be 4
  const Result r = Compile(Input::File(top), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "4 files deep, over the include-depth limit of 3");
  EXPECT_EQ(r.sources().Path(d.loc.file), (dir_ / "m3.sdf").string());
  EXPECT_EQ(d.loc.line, 1u);
  options.limits.include_depth = last;
  EXPECT_TRUE(Compile(Input::File(top), options).ok());
}

TEST_F(LimitsTest, MjcfIncludeDepth) {
  Write("inner.xml", "<mujoco><worldbody><body name=\"b\"><geom size=\"0.1\"/></body>"
                     "</worldbody></mujoco>\n");
  Write("middle.xml", "<mujoco><include file=\"inner.xml\"/></mujoco>\n");
  const std::string top = Write("top.xml", "<mujoco>\n  <include file=\"middle.xml\"/>\n</mujoco>\n");
  Options options;
  options.limits.include_depth = 1;
  const Result r = Compile(Input::File(top), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "2 files deep");
  EXPECT_EQ(r.sources().Path(d.loc.file), (dir_ / "middle.xml").string());
  options.limits.include_depth = 2;
  EXPECT_TRUE(Compile(Input::File(top), options).ok());
}

// a tetrahedron: 4 vertices, 4 triangles; `padding` comment bytes make the
// file as large as wanted
std::string Tetrahedron(size_t padding = 0) {
  return "# " + std::string(padding, 'x') + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n" +
         "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
}

// a free body whose mass comes from the mesh, so the mesh is read
constexpr const char* kMeshBody = R"(<mujoco>
  <asset><mesh file="tetra.obj"/></asset>
  <worldbody><body name="b"><freejoint/><geom type="mesh" mesh="tetra"/></body></worldbody>
</mujoco>
)";

TEST_F(LimitsTest, MeshVerticesAreReportedAtTheMesh) {
  Write("tetra.obj", Tetrahedron());
  const std::string path = Write("r.xml", kMeshBody);
  Options options;
  options.limits.mesh_vertices = 3;
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  const Diagnostic& d = LimitError(r, "vertices, over the mesh-vertices limit of 3");
  EXPECT_EQ(d.loc.line, 2u);  // the <mesh> asset naming the file
  // 4 triangles have at most 12 corners, however a reader splits them
  options.limits.mesh_vertices = 12;
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
}

TEST_F(LimitsTest, MeshFileSize) {
  const std::string path = Write("r.xml", kMeshBody);
  Write("tetra.obj", Tetrahedron(2 * fs::file_size(path)));
  Options options;
  options.limits.file_size = fs::file_size(path);  // the model fits, the mesh does not
  const Result r = Compile(Input::File(path), options);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(LimitError(r, "mesh file").loc.line, 2u);
  options.limits.file_size = fs::file_size(dir_ / "tetra.obj");
  EXPECT_TRUE(Compile(Input::File(path), options).ok());
}

TEST_F(LimitsTest, AFifoIsNotReadForever) {
  const fs::path fifo = dir_ / "pipe.urdf";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Result r = Compile(Input::File(fifo.string()));
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 1u);
  EXPECT_EQ(r.diagnostics()[0].kind, DiagKind::FileNotFound);
  EXPECT_NE(r.diagnostics()[0].message.find("not a regular file"), std::string::npos);
}

}  // namespace
}  // namespace mdlc
