// mdlc-mesh-import.so - the mesh reader as a module that mdlc opens in its
// own process (passes/mesh/in_process_reader.h): the same request and the
// same reply as the program mdlc-mesh-reader (mdlc_mesh_reader.cc), passed
// as strings and bytes through one C function, so that nothing of the
// module's own copy of mdlc's code or of assimp's types crosses into mdlc.
//
// mdlc opens it only when meshes are read in its process. That keeps
// assimp, and the libraries assimp needs, out of every other mdlc process:
// loading them and binding their symbols was most of mdlc's start-up time.
#include <exception>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/import/assimp_loader.h"
#include "passes/mesh/io/mesh_wire.h"
#include "passes/mesh/reader/import_entry.h"

extern "C" __attribute__((visibility("default"))) int MDLC_MESH_IMPORT_ENTRY(
    int argc, const char* const* argv, MdlcMeshImportSink sink, void* context) {
  const std::vector<std::string_view> request(argv, argv + argc);
  mdlc::Limits limits;
  mdlc::mesh::MeshAxes axes;
  std::string path;
  if (auto problem = mdlc::mesh::DecodeMeshRequest(request, &path, &limits, &axes)) {
    sink(context, problem->data(), problem->size());
    return 2;
  }
  // the entry point has a C signature: no exception may leave it
  try {
    const std::string reply = mdlc::mesh::EncodeMeshReply(mdlc::mesh::ImportMesh(path, limits, axes));
    sink(context, reply.data(), reply.size());
    return 0;
  } catch (const std::exception& e) {
    const std::string_view what = e.what();
    sink(context, what.data(), what.size());
    return 3;
  }
}

// the opener calls it through MdlcMeshImportFunction: the two must not drift
static_assert(std::is_same_v<decltype(&MDLC_MESH_IMPORT_ENTRY), MdlcMeshImportFunction>);
