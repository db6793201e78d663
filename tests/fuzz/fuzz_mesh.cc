// fuzz_mesh.cc - a libFuzzer harness for the mesh loader (issue 16): the
// first byte picks the file type, the rest is the file; it is loaded as a
// model's mesh would be (assimp, then mdlc's checks and mass properties).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "passes/mesh/mass_properties.h"
#include "passes/mesh/mesh_loader.h"

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
  const mdlc::mesh::MeshOrError loaded = mdlc::mesh::LoadMesh(file);
  if (loaded.ok()) {
    (void)mdlc::mesh::SolidMassProperties(*loaded.mesh);
    (void)mdlc::mesh::ShellMassProperties(*loaded.mesh);
  }
  std::remove(file.c_str());
  return 0;
}
