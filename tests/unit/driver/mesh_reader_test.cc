// Where a compile reads its mesh files (issue 16, Options::meshes.reader): in
// a child process or in this one, the plant is the same; a mesh reader that
// crashes is an error located at the mesh that named the file, and the
// compile survives it; without a reader program the compile reads in this
// process and a note says so.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "mdlc/pass_list.h"

namespace mdlc {
namespace {

namespace fs = std::filesystem;

// MJCF mesh geoms whose bodies' mass properties come from the meshes
const std::string kModel = std::string(MDLC_TEST_MODELS) + "/mjcf/oracle/mesh_geoms.xml";

class MeshReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("mdlc_mesh_reader_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    ::unsetenv("MDLC_MESH_READER");
  }
  void TearDown() override {
    ::unsetenv("MDLC_MESH_READER");
    fs::remove_all(dir_);
  }
  /// MDLC_MESH_READER names a script with `body`.
  void UseStandIn(const std::string& body) {
    const fs::path script = dir_ / "reader.sh";
    std::ofstream(script) << "#!/bin/sh\n" << body << "\n";
    ::chmod(script.c_str(), 0755);
    ::setenv("MDLC_MESH_READER", script.c_str(), 1);
  }
  static Result CompileWith(MeshReader reader) {
    Options options;
    options.meshes.reader = reader;
    options.instrumentation.time_passes = true;
    return Compile(Input::File(kModel), options);
  }
  static std::string PlantJson(const Result& r) {
    return mdlc::PlantJson(r, mdlc::DefaultPositions(r));
  }

  fs::path dir_;
};

TEST_F(MeshReaderTest, BothReadersGiveTheSamePlant) {  // issue 16
  const Result child = CompileWith(MeshReader::Process);
  const Result here = CompileWith(MeshReader::InProcess);
  ASSERT_TRUE(child.ok());
  ASSERT_TRUE(here.ok());
  EXPECT_TRUE(child.diagnostics().empty());
  EXPECT_EQ(PlantJson(child), PlantJson(here));
  EXPECT_NE(TimingReport(child).find("mesh reader: /"), std::string::npos)
      << TimingReport(child);
  EXPECT_NE(TimingReport(here).find("mesh reader: in this process (asked for)"),
            std::string::npos)
      << TimingReport(here);
}

TEST_F(MeshReaderTest, ACrashingReaderIsAnErrorAtTheMesh) {  // issue 16
  UseStandIn("kill -SEGV $$");
  const Result r = CompileWith(MeshReader::Process);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics().empty());
  for (const Diagnostic& d : r.diagnostics()) {
    EXPECT_EQ(d.kind, DiagKind::BadMesh) << d.message;
    EXPECT_TRUE(d.loc.valid()) << d.message;
    EXPECT_NE(d.message.find("the mesh reader crashed (signal 11, SIGSEGV) reading '"),
              std::string::npos)
        << d.message;
    // located at the model's <mesh file="..."> naming the file
    EXPECT_EQ(r.sources().Path(d.loc.file), kModel);
    EXPECT_NE(r.FormatText(d).find("file="), std::string::npos) << r.FormatText(d);
  }
  // asked for, the in-process reader does not use the program at all
  EXPECT_TRUE(CompileWith(MeshReader::InProcess).ok());
}

TEST_F(MeshReaderTest, WithoutAReaderMeshesAreReadHereAndANoteSaysSo) {  // issue 16
  ::setenv("MDLC_MESH_READER", (dir_ / "no_such_reader").c_str(), 1);
  const Result r = CompileWith(MeshReader::Process);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.diagnostics().size(), 1u);
  const Diagnostic& note = r.diagnostics()[0];
  EXPECT_EQ(note.severity, Severity::Note);
  EXPECT_EQ(note.kind, DiagKind::MeshReaderMissing);
  EXPECT_TRUE(note.loc.valid());
  EXPECT_NE(note.message.find("mesh files are read inside mdlc, unprotected: MDLC_MESH_READER "
                              "names '"),
            std::string::npos)
      << note.message;
  EXPECT_NE(TimingReport(r).find("mesh reader: none, meshes read in this process"),
            std::string::npos)
      << TimingReport(r);
  ::unsetenv("MDLC_MESH_READER");
  EXPECT_EQ(PlantJson(r), PlantJson(CompileWith(MeshReader::Process)));
}

}  // namespace
}  // namespace mdlc
