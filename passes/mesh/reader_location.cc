#include "passes/mesh/reader_location.h"

#include <dlfcn.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

// Set by the build: the reader's path below an install prefix, and where
// this build tree puts it.
#ifndef MDLC_MESH_READER_INSTALL_PATH
#define MDLC_MESH_READER_INSTALL_PATH "libexec/mdlc/mdlc-mesh-reader"
#endif
#ifndef MDLC_MESH_READER_BUILD_PATH
#define MDLC_MESH_READER_BUILD_PATH ""
#endif

namespace mdlc::mesh {
namespace {

namespace fs = std::filesystem;

bool IsExecutable(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec) && ::access(file.c_str(), X_OK) == 0;
}

/// The reader of the install prefix above `binary`: the binary may sit in
/// <prefix>/bin, <prefix>/lib, <prefix>/lib/<multiarch>, or (the Python
/// module) <prefix>/lib/python3/dist-packages/mdlc, so a few folders up are
/// tried.
std::string InstalledNextTo(const fs::path& binary) {
  std::error_code ec;
  fs::path dir = fs::weakly_canonical(binary, ec).parent_path();
  if (ec) return {};
  for (int up = 0; up < 5 && !dir.empty(); ++up, dir = dir.parent_path()) {
    const fs::path candidate = dir / MDLC_MESH_READER_INSTALL_PATH;
    if (IsExecutable(candidate)) return candidate.string();
    if (dir == dir.root_path()) break;
  }
  return {};
}

MeshReaderLocation SearchNextToThisCode() {
  // the shared object this code is in (a shared library, the Python
  // module), then the program (mdlc, or a program linking mdlc statically)
  Dl_info info;
  if (::dladdr(reinterpret_cast<void*>(&FindMeshReader), &info) != 0 && info.dli_fname &&
      std::string_view(info.dli_fname).find('/') != std::string_view::npos) {
    if (std::string found = InstalledNextTo(info.dli_fname); !found.empty()) return {found, {}};
  }
  if (std::string found = InstalledNextTo("/proc/self/exe"); !found.empty()) return {found, {}};
  if (const fs::path built = MDLC_MESH_READER_BUILD_PATH; !built.empty() && IsExecutable(built)) {
    return {built.string(), {}};
  }
  return {{}, fmt::format("the mdlc-mesh-reader program was not found (set {} to its path)",
                          kMeshReaderVariable)};
}

}  // namespace

MeshReaderLocation FindMeshReader() {
  if (const char* named = std::getenv(kMeshReaderVariable); named && *named) {
    if (IsExecutable(named)) return {named, {}};
    return {{}, fmt::format("{} names '{}', which is not an executable file", kMeshReaderVariable,
                            named)};
  }
  // where this code and the program are does not change while they run:
  // the folders are searched once per process (a score of system calls),
  // not once per compile
  static const MeshReaderLocation found = SearchNextToThisCode();
  return found;
}

}  // namespace mdlc::mesh
