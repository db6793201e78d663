// Reading meshes in a child process (issue 16, passes/mesh/reader_pool.h):
// the mesh reader program gives exactly what reading in this process gives,
// and whatever goes wrong in the child (a crash, a hang, a failure, a
// malformed reply) is an error about the file. Stand-in readers are small
// shell scripts.
#include "passes/mesh/reader_pool.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/mesh_loader.h"
#include "passes/mesh/reader_location.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

namespace fs = std::filesystem;

class ChildReaderTest : public MeshFolderTest {
 protected:
  /// An executable shell script standing in for the reader.
  std::string StandIn(const std::string& body) {
    const fs::path script = dir_ / "reader.sh";
    std::ofstream(script) << "#!/bin/sh\n" << body << "\n";
    ::chmod(script.c_str(), 0755);
    return script.string();
  }
};

std::string RealReader() {
  const mesh::MeshReaderLocation found = mesh::FindMeshReader();
  EXPECT_FALSE(found.path.empty()) << found.why_none;
  return found.path;
}

/// The two results are the same: the same mesh, or the same error.
void ExpectSame(const mesh::MeshOrError& child, const mesh::MeshOrError& here,
                const std::string& what) {
  ASSERT_EQ(child.ok(), here.ok()) << what << ": " << child.error << " / " << here.error;
  EXPECT_EQ(child.error, here.error) << what;
  EXPECT_EQ(child.over_limit, here.over_limit) << what;
  if (!here.ok()) return;
  EXPECT_EQ(child.mesh->vertices, here.mesh->vertices) << what;
  EXPECT_EQ(child.mesh->triangles, here.mesh->triangles) << what;
}

TEST_F(ChildReaderTest, TheBuildsReaderIsFound) {  // issue 16
  ::unsetenv(mesh::kMeshReaderVariable);
  const std::string reader = RealReader();
  EXPECT_EQ(fs::path(reader).filename(), "mdlc-mesh-reader");
  EXPECT_EQ(::access(reader.c_str(), X_OK), 0) << reader;
}

// The module that reads meshes in this process is found next to the reader,
// and the environment overrides the search (in_process_reader.h).
TEST_F(ChildReaderTest, TheBuildsImportModuleIsFound) {  // issue 16
  ::unsetenv(mesh::kMeshModuleVariable);
  const mesh::MeshReaderLocation built = mesh::FindMeshImportModule();
  EXPECT_EQ(fs::path(built.path).filename(), "mdlc-mesh-import.so") << built.why_none;
  EXPECT_EQ(fs::path(built.path).parent_path(), fs::path(RealReader()).parent_path());
  ::setenv(mesh::kMeshModuleVariable, (dir_ / "nothing.so").c_str(), 1);
  const mesh::MeshReaderLocation none = mesh::FindMeshImportModule();
  EXPECT_TRUE(none.path.empty());
  EXPECT_EQ(none.why_none, fmt::format("MDLC_MESH_MODULE names '{}', which is not a readable file",
                                       (dir_ / "nothing.so").string()));
  ::unsetenv(mesh::kMeshModuleVariable);
  EXPECT_EQ(mesh::FindMeshImportModule().path, built.path);
}

// What --time-passes names is the module meshes were read with, even when
// the environment names another afterwards (in_process_reader.h).
TEST_F(ChildReaderTest, TheOpenedImportModuleIsTheOneReported) {  // issue 16
  ::unsetenv(mesh::kMeshModuleVariable);
  const std::string built = mesh::FindMeshImportModule().path;
  ASSERT_TRUE(mesh::LoadMeshInProcess(MeshPath("box.obj")).ok());
  ::setenv(mesh::kMeshModuleVariable, (dir_ / "nothing.so").c_str(), 1);
  EXPECT_TRUE(mesh::FindMeshImportModule().path.empty());
  EXPECT_EQ(mesh::ImportModuleLocation().path, built);
  ::unsetenv(mesh::kMeshModuleVariable);
}

TEST_F(ChildReaderTest, ChildAndInProcessReadTheTestMeshesAlike) {  // issue 16
  ::unsetenv(mesh::kMeshReaderVariable);
  const std::string reader = RealReader();
  std::vector<std::string> paths{MeshPath("no_such_mesh.obj")};
  for (const auto& e : fs::directory_iterator(MeshPath(""))) {
    if (e.path().extension() != ".py") paths.push_back(e.path().string());
  }
  ASSERT_GT(paths.size(), 10u);
  size_t meshes = 0;
  for (const std::string& path : paths) {
    const mesh::MeshOrError here = mesh::LoadMeshInProcess(path);
    meshes += here.ok();
    ExpectSame(mesh::LoadMeshInChild(reader, path, {}), here, path);
  }
  EXPECT_GT(meshes, 5u);  // most of them are meshes, some are errors
}

TEST_F(ChildReaderTest, TheLimitsReachTheChild) {  // issue 16
  Limits limits;
  limits.mesh_vertices = 3;
  const std::string path = MeshPath("box.obj");
  const mesh::MeshOrError child = mesh::LoadMeshInChild(RealReader(), path, limits);
  EXPECT_TRUE(child.over_limit);
  EXPECT_NE(child.error.find("mesh-vertices limit of 3"), std::string::npos) << child.error;
  ExpectSame(child, mesh::LoadMeshInProcess(path, limits), path);
}

TEST_F(ChildReaderTest, ACrashIsAnError) {  // issue 16
  const mesh::MeshOrError m =
      mesh::LoadMeshInChild(StandIn("kill -SEGV $$"), MeshPath("box.obj"), {});
  EXPECT_FALSE(m.ok());
  EXPECT_FALSE(m.over_limit);
  EXPECT_EQ(m.error, fmt::format("the mesh reader crashed (signal 11, SIGSEGV) reading '{}'",
                                 MeshPath("box.obj")));
}

TEST_F(ChildReaderTest, AHangIsStoppedAtTheMeshSecondsLimit) {  // issue 16
  Limits limits;
  limits.mesh_seconds = 1;
  // one that hangs while its output is open, one after closing it
  for (const char* body : {"exec sleep 60", "exec >&-; exec sleep 60"}) {
    const mesh::MeshOrError m = mesh::LoadMeshInChild(StandIn(body), "x.ply", limits);
    EXPECT_FALSE(m.ok()) << body;
    EXPECT_TRUE(m.over_limit) << body;
    EXPECT_EQ(m.error,
              "the mesh reader did not finish reading 'x.ply' within 1 s (the mesh-seconds "
              "limit; raise it with --limit mesh-seconds=N)")
        << body;
  }
}

TEST_F(ChildReaderTest, AFailureIsAnError) {  // issue 16
  const mesh::MeshOrError m = mesh::LoadMeshInChild(StandIn("exit 7"), "x.ply", {});
  EXPECT_FALSE(m.ok());
  EXPECT_EQ(m.error, "the mesh reader failed (exit status 7) reading 'x.ply'");
}

TEST_F(ChildReaderTest, AMalformedReplyIsRejected) {  // issue 16
  for (const char* body : {"printf MDLCMESH", "echo a mesh, honestly", "true"}) {
    const mesh::MeshOrError m = mesh::LoadMeshInChild(StandIn(body), "x.ply", {});
    EXPECT_FALSE(m.ok()) << body;
    EXPECT_TRUE(m.error.starts_with("the mesh reader sent a malformed reply reading 'x.ply': "))
        << m.error;
  }
}

TEST_F(ChildReaderTest, AMissingProgramIsAnError) {  // issue 16
  const mesh::MeshOrError m =
      mesh::LoadMeshInChild((dir_ / "no_such_reader").string(), "x.ply", {});
  EXPECT_FALSE(m.ok());
  EXPECT_TRUE(m.error.starts_with("cannot run the mesh reader")) << m.error;
}

TEST_F(ChildReaderTest, TheEnvironmentNamesTheReader) {  // issue 16
  const std::string stand_in = StandIn("exit 7");
  ::setenv(mesh::kMeshReaderVariable, stand_in.c_str(), 1);
  EXPECT_EQ(mesh::FindMeshReader().path, stand_in);
  EXPECT_NE(mesh::LoadMesh(MeshPath("box.obj")).error.find("exit status 7"), std::string::npos);
  // a name that is no program: none is found, and the reason says why
  ::setenv(mesh::kMeshReaderVariable, (dir_ / "nothing").c_str(), 1);
  const mesh::MeshReaderLocation none = mesh::FindMeshReader();
  EXPECT_TRUE(none.path.empty());
  EXPECT_NE(none.why_none.find("not an executable file"), std::string::npos) << none.why_none;
  EXPECT_TRUE(mesh::LoadMesh(MeshPath("box.obj")).ok());  // read in this process
  ::unsetenv(mesh::kMeshReaderVariable);
}

}  // namespace
}  // namespace mdlc::testing
