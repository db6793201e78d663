#include "passes/mesh/in_process_reader.h"

#include <dlfcn.h>

#include <fmt/format.h>

#include <atomic>
#include <optional>
#include <vector>

#include "passes/mesh/io/mesh_wire.h"
#include "passes/mesh/reader/import_entry.h"
#include "passes/mesh/reader_location.h"

namespace mdlc::mesh {
namespace {

struct OpenedModule {
  MdlcMeshImportFunction entry = nullptr;
  MeshReaderLocation location;  // the module's path, or why there is none
};

OpenedModule Open() {
  const MeshReaderLocation found = FindMeshImportModule();
  if (found.path.empty()) return {nullptr, found};
  // RTLD_NOW: a module that cannot be bound fails here, not at its first
  // call. RTLD_LOCAL: assimp's symbols, and the module's own copy of mdlc's
  // code, stay out of the process's global scope.
  void* handle = ::dlopen(found.path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    return {nullptr, {{}, fmt::format("cannot open the mesh import module: {}", ::dlerror())}};
  }
  auto entry =
      reinterpret_cast<MdlcMeshImportFunction>(::dlsym(handle, MDLC_MESH_IMPORT_ENTRY_NAME));
  if (!entry) {
    ::dlclose(handle);
    return {nullptr,
            {{}, fmt::format("'{}' is not a mesh import module of this mdlc (it has no {})",
                             found.path, MDLC_MESH_IMPORT_ENTRY_NAME)}};
  }
  // never closed: meshes it read are freed by mdlc, but assimp may keep
  // state of its own, and closing buys nothing in a process that read one
  return {entry, found};
}

std::atomic<bool> module_opened{false};

const OpenedModule& Module() {
  static const OpenedModule module = Open();  // thread-safe, once per process
  module_opened.store(true, std::memory_order_release);
  return module;
}

}  // namespace

MeshReaderLocation ImportModuleLocation() {
  // the module opened, once one is: the search may since have found another
  return module_opened.load(std::memory_order_acquire) ? Module().location
                                                       : FindMeshImportModule();
}

MeshOrError LoadMeshInProcess(const std::string& path, const Limits& limits,
                              const MeshAxes& axes) {
  auto failed = [](std::string what) { return MeshOrError{nullptr, std::move(what)}; };
  const OpenedModule& module = Module();
  if (!module.entry) {
    return failed(
        fmt::format("cannot read '{}' in this process: {}", path, module.location.why_none));
  }
  const std::vector<std::string> request = EncodeMeshRequest(path, limits, axes);
  std::vector<const char*> argv;
  for (const std::string& a : request) argv.push_back(a.c_str());
  std::string answer;
  const int rc = module.entry(
      static_cast<int>(argv.size()), argv.data(),
      [](void* context, const char* bytes, size_t size) {
        static_cast<std::string*>(context)->assign(bytes, size);
      },
      &answer);
  if (rc != 0) {
    return failed(fmt::format("the mesh import module failed reading '{}': {}", path, answer));
  }
  std::string problem;
  std::optional<MeshOrError> result = DecodeMeshReply(answer, &problem);
  if (!result) {
    return failed(fmt::format("the mesh import module sent a malformed reply reading '{}': {}",
                              path, problem));
  }
  return std::move(*result);
}

}  // namespace mdlc::mesh
