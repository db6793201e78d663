// Mesh reader workers that each read many files (issue 57,
// passes/mesh/reader_pool.h): one worker reads file after file; a worker
// that crashes, hangs, answers garbage or vanishes loses only the file it
// was reading, and the files after it load; a worker that dies between
// files is replaced without an error; threads reading at once get a worker
// each. The misbehaving worker is tests/unit/mesh/faulty_mesh_reader.cc.
#include "passes/mesh/reader_pool.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/mesh_cache.h"
#include "passes/mesh/reader_location.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

class ReaderPoolTest : public MeshFolderTest {
 protected:
  /// `n` copies of box.obj, ok0.obj ... .
  std::vector<std::string> Boxes(int n, const std::string& stem = "ok") {
    std::vector<std::string> paths;
    for (int i = 0; i < n; ++i) paths.push_back(Copy("box.obj", fmt::format("{}{}.obj", stem, i)));
    return paths;
  }
};

std::string RealReader() {
  const mesh::MeshReaderLocation found = mesh::FindMeshReader();
  EXPECT_FALSE(found.path.empty()) << found.why_none;
  return found.path;
}

/// `m` is the box, as this process reads it.
void ExpectBox(const mesh::MeshOrError& m, const std::string& what) {
  ASSERT_TRUE(m.ok()) << what << ": " << m.error;
  const mesh::MeshOrError here = mesh::LoadMeshInProcess(MeshPath("box.obj"));
  ASSERT_TRUE(here.ok()) << here.error;
  EXPECT_EQ(m.mesh->vertices, here.mesh->vertices) << what;
  EXPECT_EQ(m.mesh->triangles, here.mesh->triangles) << what;
}

/// Waits (up to 10 s) until process `pid` has ended, without reaping it.
bool Ended(pid_t pid) {
  for (int i = 0; i < 1000; ++i) {
    siginfo_t info{};
    if (::waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid) {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST_F(ReaderPoolTest, OneWorkerReadsFileAfterFile) {  // issue 57
  mesh::MeshReaderPool pool(RealReader());
  for (const std::string& path : Boxes(30)) ExpectBox(pool.Read(path, {}), path);
  EXPECT_EQ(pool.workers_started(), 1u);
  EXPECT_EQ(pool.IdleWorkers().size(), 1u);
}

TEST_F(ReaderPoolTest, ACrashAmongManyMeshesLosesOnlyThatMesh) {  // issue 57
  mesh::MeshReaderPool pool(MDLC_FAULTY_MESH_READER);
  std::vector<std::string> paths = Boxes(10, "before");
  const std::string crash = Copy("box.obj", "crash.obj");
  paths.push_back(crash);
  for (const std::string& p : Boxes(10, "after")) paths.push_back(p);
  for (const std::string& path : paths) {
    const mesh::MeshOrError m = pool.Read(path, {});
    if (path != crash) {
      ExpectBox(m, path);
      continue;
    }
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.over_limit);
    EXPECT_EQ(m.error,
              fmt::format("the mesh reader crashed (signal 11, SIGSEGV) reading '{}'", crash));
  }
  EXPECT_EQ(pool.workers_started(), 2u);  // the one that crashed, the one after
}

TEST_F(ReaderPoolTest, EachKindOfFailureEndsOnlyItsWorker) {  // issue 57
  mesh::MeshReaderPool pool(MDLC_FAULTY_MESH_READER);
  Limits limits;
  limits.mesh_seconds = 1;
  const std::vector<std::pair<std::string, std::string>> failures = {
      {"hang.obj",
       "the mesh reader did not finish reading '{}' within 1 s (the mesh-seconds limit; raise "
       "it with --limit mesh-seconds=N)"},
      {"garbage.obj",
       "the mesh reader sent a malformed reply reading '{}': it does not start with the reply "
       "marker"},
      {"vanish.obj", "the mesh reader sent a malformed reply reading '{}': it ended without one"},
  };
  ExpectBox(pool.Read(Copy("box.obj", "first.obj"), limits), "first");
  for (const auto& [name, message] : failures) {
    const std::string path = Copy("box.obj", name);
    const mesh::MeshOrError m = pool.Read(path, limits);
    EXPECT_FALSE(m.ok()) << name;
    EXPECT_EQ(m.over_limit, name == "hang.obj");
    EXPECT_EQ(m.error, fmt::format(fmt::runtime(message), path));
    // named for nothing the faulty reader acts on
    ExpectBox(pool.Read(Copy("box.obj", fmt::format("fine{}.obj", pool.workers_started())), limits),
              "after " + name);
  }
  EXPECT_EQ(pool.workers_started(), 1 + failures.size());
}

TEST_F(ReaderPoolTest, AWorkerThatDiesBetweenMeshesIsReplaced) {  // issue 57
  mesh::MeshReaderPool pool(RealReader());
  const std::vector<std::string> paths = Boxes(2);
  ExpectBox(pool.Read(paths[0], {}), paths[0]);
  ASSERT_EQ(pool.IdleWorkers().size(), 1u);
  const pid_t idle = pool.IdleWorkers().front();
  ASSERT_EQ(::kill(idle, SIGKILL), 0);
  ASSERT_TRUE(Ended(idle));
  // no error for the next mesh: it had nothing to do with the death
  ExpectBox(pool.Read(paths[1], {}), paths[1]);
  EXPECT_EQ(pool.workers_started(), 2u);
  ASSERT_EQ(pool.IdleWorkers().size(), 1u);
  EXPECT_NE(pool.IdleWorkers().front(), idle);
}

TEST_F(ReaderPoolTest, ThreadsReadingAtOnceGetAWorkerEach) {  // issue 57
  mesh::MeshReaderPool pool(RealReader());
  const std::vector<std::string> paths = Boxes(40);
  std::vector<std::thread> threads;
  std::vector<mesh::MeshOrError> results(paths.size());
  std::atomic<size_t> next{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (size_t i = next++; i < paths.size(); i = next++) results[i] = pool.Read(paths[i], {});
    });
  }
  for (std::thread& t : threads) t.join();
  for (size_t i = 0; i < paths.size(); ++i) ExpectBox(results[i], paths[i]);
  EXPECT_GE(pool.workers_started(), 1u);
  EXPECT_LE(pool.workers_started(), 4u);
  EXPECT_EQ(pool.IdleWorkers().size(), pool.workers_started());
}

// The same through a compile's mesh cache, which reads in parallel: the
// crash costs its own file, whichever thread's worker met it.
TEST_F(ReaderPoolTest, ACrashInAParallelReadLosesOnlyThatMesh) {  // issue 57
  ::setenv(mesh::kMeshReaderVariable, MDLC_FAULTY_MESH_READER, 1);
  mesh::MeshCache cache;
  ::unsetenv(mesh::kMeshReaderVariable);
  ASSERT_EQ(cache.reader(), MDLC_FAULTY_MESH_READER);
  std::vector<std::string> paths = Boxes(20);
  const std::string crash = Copy("box.obj", "crash.obj");
  paths.insert(paths.begin() + 10, crash);
  cache.Prefetch(paths);
  for (const std::string& path : paths) {
    const mesh::MeshOrError m = cache.Get(path);
    if (path == crash) {
      EXPECT_NE(m.error.find("crashed (signal 11, SIGSEGV)"), std::string::npos) << m.error;
    } else {
      ExpectBox(m, path);
    }
  }
  EXPECT_EQ(cache.files_read(), paths.size());
  EXPECT_LE(cache.workers_started(), std::max(1u, std::thread::hardware_concurrency()) + 1);
}

}  // namespace
}  // namespace mdlc::testing
