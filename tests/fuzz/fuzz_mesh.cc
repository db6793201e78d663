// fuzz_mesh.cc - a libFuzzer harness for the mesh loader (issue 16): the
// first byte picks the file type, the rest is the file; it is loaded as a
// model's mesh would be (by a mesh reader worker process, then mdlc's checks
// on its reply and mass properties). One pool of workers serves the whole
// run, as one serves a whole compile (issue 57): an input that crashes a
// worker costs that worker, the next input gets a fresh one.
//
// assimp runs in the child, the reader built with the same sanitizers: its
// memory errors and hangs there become errors here, as they do in a
// compile, so what this harness finds is mdlc's own (the reply's decoding,
// the child's handling, the mass properties). assimp in the child is
// fuzzed too; its crashes show in the log, not as failures.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "passes/mesh/mass_properties.h"
#include "passes/mesh/reader_pool.h"
#include "passes/mesh/reader_location.h"

namespace {

/// The workers, of the reader program; the harness refuses to run without
/// one, rather than fuzz assimp in its own process.
mdlc::mesh::MeshReaderPool& Workers() {
  static mdlc::mesh::MeshReaderPool* pool = [] {
    const mdlc::mesh::MeshReaderLocation found = mdlc::mesh::FindMeshReader();
    if (found.path.empty()) {
      std::fprintf(stderr, "fuzz_mesh: %s\n", found.why_none.c_str());
      std::abort();
    }
    // never destroyed: libFuzzer may end the process from any thread
    return new mdlc::mesh::MeshReaderPool(found.path);
  }();
  return *pool;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".obj", ".stl", ".dae", ".gltf", ".ply"};
  const char* extension = kExtensions[data[0] % 5];
  // assimp reads files: one per process, rewritten for each input
  static const std::string path =
      "/tmp/mdlc_fuzz_mesh_" + std::to_string(::getpid());
  const std::string file = path + extension;
  if (FILE* f = std::fopen(file.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  } else {
    return 0;
  }
  mdlc::Limits limits;
  // a hang in the child is an error long before libFuzzer's -timeout; short,
  // because inputs on which assimp hangs would otherwise take most of a run
  limits.mesh_seconds = 2;
  const mdlc::mesh::MeshOrError loaded = Workers().Read(file, limits);
  if (loaded.ok()) {
    (void)mdlc::mesh::SolidMassProperties(*loaded.mesh);
    (void)mdlc::mesh::ShellMassProperties(*loaded.mesh);
  }
  std::remove(file.c_str());
  return 0;
}
